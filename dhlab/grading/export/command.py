"""``dhlab-grade export …``: the grading where the teacher's university already grades.

    dhlab-grade export gradescope -o autograder.zip [--secret-file KEY --release DIR] [--timeout S ...]
    dhlab-grade export try-gradescope autograder.zip NOTEBOOK [--email E] [--sid S]
    dhlab-grade export canvas GRADEBOOK.csv --roster ROSTER.csv -o canvas.csv [--assignment TITLE]
    dhlab-grade export moodle GRADEBOOK.csv --roster ROSTER.csv -o moodle.csv [--id-column COLUMN]

The zip: :mod:`dhlab.grading.export.gradescope`; trying it here: :mod:`dhlab.grading.export.gradescope_local`;
the LMS files: :mod:`dhlab.grading.export.lms`.
"""
from __future__ import annotations

import argparse
import csv
import json
import sys
import tempfile
from pathlib import Path

from ...errors import DHLabError
from ...i18n import N_, _, as_teacher, error_line
from ..book.grade_variants import release_files
from ..book.gradebook import read_csv
from ..csvsafe import neutralised
from ..options import shared
from . import lms
from .gradescope import export
from .gradescope_local import Harness, metadata, problems

__all__ = ["main"]

# the docstring's first line, in the teacher's language in --help
DESCRIPTION = N_("``dhlab-grade export …``: the grading where the teacher's university already grades.")


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="dhlab-grade export", description=_(DESCRIPTION),
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="target", required=True)
    gs = sub.add_parser("gradescope", help=_("Gradescope's autograder.zip (otter-grader runs it too)"),
                        parents=[shared(secret=_("personal variants: the teacher's secret"), source=True,
                                        language=False)])
    gs.add_argument("-o", "--output", type=Path, default=Path("autograder.zip"))
    gs.add_argument("--release", type=Path, default=None, help=_("personal variants: the folder dhlab-assign wrote"))
    gs.add_argument("--fallback", choices=("roster", "none"), default=None)
    gs.add_argument("--timeout", type=float, default=30, help=_("seconds per cell (default 30)"))
    gs.add_argument("--total-timeout", type=float, default=None,
                    help=_("seconds per notebook (default 4 × --timeout)"))
    gs.add_argument("--memory-mb", type=float, default=2048)
    gs.add_argument("--isolation", choices=("auto", "user", "none"), default="auto")
    tr = sub.add_parser("try-gradescope", help=_("run an autograder.zip here, as Gradescope would"))
    tr.add_argument("zip", type=Path)
    tr.add_argument("notebook", type=Path)
    tr.add_argument("--email", default="student@example.edu", help=_("the submitter's email in the metadata"))
    tr.add_argument("--sid", default="", help=_("the submitter's SID in the metadata"))
    for name in ("canvas", "moodle"):
        lms = sub.add_parser(name, help=_("a CSV file {lms} imports").format(lms=name.capitalize()))
        lms.add_argument("gradebook", type=Path, help=_("the gradebook dhlab-grade wrote"))
        lms.add_argument("--roster", type=Path, required=True, help=_("the class list (CSV with a header)"))
        lms.add_argument("-o", "--output", type=Path, required=True)
        lms.add_argument("--id-column", default=None, help=_("the roster's id column (default: id, student_id, …)"))
        lms.add_argument("--release", type=Path, default=None,
                         help=_("the release folder: its file names count as their students' ids"))
        if name == "canvas":
            lms.add_argument("--assignment", default="PUMA assignment",
                             help=_("the assignment's column title in Canvas"))
        else:
            lms.add_argument("--feedback-dir", type=Path, default=None,
                             help=_("the feedback files (default: beside the gradebook, <name>_feedback)"))
    return parser


def _lms(args) -> int:
    """The Canvas or Moodle file (see :mod:`dhlab.grading.export.lms`). Only graded rows become grades;
    the rows left out are listed, and an export that matches no student is an error (exit 2)."""
    rows = _gradebook_rows(args.gradebook)
    id_column, roster = lms.read_roster_rows(args.roster, args.id_column)
    files = {}
    if args.release is not None:
        files = release_files(args.release, roster)
    by_id, unmatched, missing = lms.match(rows, roster, files)
    skipped = lms.not_graded(rows)
    if not by_id:
        raise DHLabError(_("no graded row of {gradebook} is from a student of the roster {roster} (its id column "
                           "is {column!r}; {count} rows, {skipped} not graded): nothing to import, no file written. "
                           "Check --id-column, or pass --release when the files have the release's names.").format(
            gradebook=args.gradebook, roster=args.roster, column=id_column, count=len(rows), skipped=len(skipped)))
    if args.target == "canvas":
        table = lms.canvas_rows(by_id, roster, args.assignment, rows[0]["max_score"])
    else:
        feedback = args.feedback_dir or args.gradebook.with_name(args.gradebook.stem + "_feedback")
        table = lms.moodle_rows(by_id, id_column, feedback)
    lms.write(args.output, table, lms.GRADE_COLUMNS[args.target])
    _report(args, by_id, unmatched, missing, skipped)
    return 0


def _gradebook_rows(path) -> list:
    """The rows of the gradebook dhlab-grade wrote (with or without a BOM, cells unescaped), or a
    clear error."""
    try:
        with open(path, newline="", encoding="utf-8-sig") as f:
            columns = csv.DictReader(f).fieldnames or []
    except (OSError, UnicodeDecodeError, csv.Error) as exc:
        raise DHLabError(_("cannot read the gradebook {file}: {why}").format(
            file=path, why=getattr(exc, "strerror", None) or exc)) from None
    rows = read_csv(path, columns)
    if "score" not in columns or "submission" not in columns or not rows:
        raise DHLabError(_("{file} is not a gradebook dhlab-grade wrote (no rows with a score column).").format(
            file=path))
    return rows


def _report(args, by_id, unmatched, missing, skipped) -> None:
    """What was exported, and every row or student left out, and why."""
    print(_("dhlab-grade export {target}: {count} grades in {file}.").format(
        target=args.target, count=len(by_id), file=args.output), file=sys.stderr)
    if skipped:
        print(_("Not exported, not graded ({count}: no grade, not a 0; grade them by hand, or again with "
                "--resume): {names}").format(count=len(skipped), names=", ".join(skipped[:10])), file=sys.stderr)
    if unmatched:
        print(_("Not exported, no student of the roster ({count}): {names}").format(
            count=len(unmatched), names=", ".join(unmatched[:10])), file=sys.stderr)
    if missing:
        print(_("No graded submission ({count}, left as they are in the LMS): {names}").format(
            count=len(missing), names=", ".join(missing[:10])), file=sys.stderr)
    formulas = [sid for sid in by_id if neutralised(sid) != sid]
    if formulas:
        print(_("Written with a leading ' so that no spreadsheet runs them as formulas ({count}): {names}; "
                "the LMS may not match these ids: check their grades after the import.").format(
            count=len(formulas), names=", ".join(formulas[:10])), file=sys.stderr)


def _try(args) -> int:
    with tempfile.TemporaryDirectory(prefix="dhlab-try-gradescope-") as tmp:
        harness = Harness(args.zip, tmp)
        outcome = harness.run([args.notebook], metadata(args.email, sid=args.sid))
    print(outcome.log, file=sys.stderr)
    if outcome.results is None:
        print(_("No results.json: Gradescope shows an autograder failure (the log above says why)."), file=sys.stderr)
        return 1
    print(json.dumps(outcome.results, indent=1, ensure_ascii=False))
    wrong = problems(outcome.results)
    for p in wrong:
        print(_("results.json does not follow Gradescope's schema: {problem}").format(problem=p), file=sys.stderr)
    return 1 if wrong else 0


def main(argv=None) -> int:
    """``dhlab-grade export …`` in the teacher's language (``--language``, else ``DHLAB_LANGUAGE``)."""
    argv = sys.argv[1:] if argv is None else list(argv)
    return as_teacher("dhlab-grade export", argv, _main, strip=True)


def _main(argv) -> int:
    args = _parser().parse_args(argv)
    try:
        if args.target == "gradescope":
            out = export(args.output, args.secret_file, args.release, args.fallback, args.timeout,
                         args.total_timeout, args.memory_mb, isolation=args.isolation, source=args.source)
            print(_("dhlab-grade export: {file} (upload it to Gradescope as the autograder; never to students)").format(
                file=out), file=sys.stderr)
            return 0
        if args.target == "try-gradescope":
            return _try(args)
        return _lms(args)
    except DHLabError as exc:
        print(error_line("dhlab-grade export", exc), file=sys.stderr, end="")
        return 2
