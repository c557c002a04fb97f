"""Grade a folder of submitted PUMA notebooks: ``dhlab-grade puma SUBMISSIONS_DIR -o gradebook.csv``.

    dhlab-grade puma SUBMISSIONS_DIR -o gradebook.csv [-j N] [--timeout S] [--resume]
                [--secret-file KEY --release RELEASE_DIR [--fallback roster|none]] [--language en|es]
    dhlab-grade export gradescope|try-gradescope|canvas|moodle ...   (dhlab.grading.export.command)
    dhlab-grade --clean                    (remove what a killed grader left: dhlab.grading.run.cleanup)
    python -m dhlab.grading.cli puma SUBMISSIONS_DIR ...          (the same)

Every ``*.ipynb`` under SUBMISSIONS_DIR (any depth, e.g. nbgrader's
``submitted/<student>/<assignment>/``) is one submission. What happens:

1. **Every submission is copied first**, without its outputs (:mod:`dhlab.grading.run.staging`),
   into a folder only the grader can enter; nothing runs before all are copied.
2. **The grader checks itself** (:mod:`dhlab.grading.run.selfcheck`): the teacher's solution
   (computed for the PUMA 560, :mod:`dhlab.assignment.solution`; or the teacher's own, ``--source``) is
   run exactly as the submissions' will be, under the same limits (``--memory-mb`` included),
   and must earn full marks; if it cannot, the grader stops with one message (which user
   cannot enter which folder, or which memory limit is too small and one that worked, what
   to do), exit code 5, and grades nothing.
3. Each copy is run by its own runner process (:mod:`dhlab.grading.run.runner`) in a fresh
   kernel with a time limit per cell (``--timeout``), a limit for the whole notebook, a
   memory limit and an output limit; ``-j N`` runs N at a time. As root, each kernel
   runs as an unprivileged user of its own, in its own folder
   (:mod:`dhlab.grading.run.isolation`), and every process of that user is killed afterwards.
4. The runner only returns the student's answers as plain data; they are scored
   **here**, in the grader's process, by :mod:`dhlab.assignment.checks`.
5. Before and after each submission the whole installed ``dhlab`` is checked
   unchanged; if it changed, the grader stops with a message (the rows it can
   trust are kept).
6. The gradebook CSV is rewritten atomically after every submission (submission,
   score, max_score, status, one column per part, seconds, feedback file, the file
   and its SHA-256), so a grader killed mid-batch keeps every finished row, and
   ``--resume`` grades only what is missing (or changed), and every grader error again.
   A plain re-run leaves the old gradebook as it is until its first new row. A row whose
   file was removed since the last run is reported (and, with ``--resume``, kept, its status
   starting "removed since the last run"). One feedback file per submission goes to a
   folder beside it (``gradebook_feedback/``).
7. **Ctrl-C** (:class:`dhlab.grading.batch.Interrupts`): the first starts no new submission and lets the running
   ones finish; a second (or SIGTERM) stops them too, and their rows are not written.
   Then the copies and kernels' folders are removed and the grader prints the command that
   grades the rest (``… --resume``). Exit codes: 0 done, 2 usage, 3 stopped (dhlab changed),
   4 cannot isolate, 5 the self-check failed, 130 interrupted.

A submission that raises, hangs, floods its output, runs out of memory, is not a
notebook, or tampers with dhlab gets the marks its real answers earn and a reason in
``status``; it never stops the batch. A fault of the grader's is never a score: a kernel
that ran out of the memory the teacher set before any answer was read, a copy removed
before it ran, a cell of the assignment stopped (:func:`dhlab.grading.book.submission_row.grade_submission`)
give a row with no score, "grader error: <cause and what to change>", graded again by
``--resume``.

**Personal variants** (notebooks released with ``dhlab-assign release``): with
``--secret-file`` each submission is graded against its student's own robot. While the
submissions are staged (step 1, before any runs) the grader works out whose each one is,
verifies the variant signed in it, rewrites the copy's "Your robot" cell from the variant
it will be graded against, and the checks score against that robot; ``--release`` (the
release folder) gives the roster and every student's released variant, the fallback for a
missing, tampered or classmate's record (``--fallback roster``, the default with
``--release``; ``none``: no marks). The rules, and the gradebook's five variant columns:
:mod:`dhlab.grading.book.grade_variants`. Without ``--secret-file`` every submission is
graded against the PUMA 560, as before.

**Languages.** A class may mix English and Spanish notebooks (``dhlab-assign release --language``,
or the roster's ``language``/``idioma`` column): each feedback file is written in its student's
language (the notebook's ``metadata["dhlab"]["language"]``, else its ``dhlab.set_language`` call,
else the grader's), while ``--language`` (else ``DHLAB_LANGUAGE``, else English) is the teacher's:
this command's help and messages, the summary and the gradebook's ``status`` column. The
gradebook's column names, and the status keys ``ok`` and ``grader error: … grade again with
--resume``, stay English (LMS imports and ``--resume`` read them).
"""
from __future__ import annotations

import argparse
import concurrent.futures
import functools
import shlex
import shutil
import sys
import tempfile
import time
from pathlib import Path

# the whole grader is imported before any student code runs (the self-check, the assignment's checks
# included): what a submission does to sys.modules cannot change the code that grades it
from ..assignment import checks
from ..errors import DHLabError
from ..i18n import N_, _, as_teacher, error_line
from .batch import Batch, Interrupts, grade_one
from .book import grade_variants as GV
from .book.gradebook import (
    COLUMNS,
    REMOVED,
    VARIANT_COLUMNS,
    assignment_cells,
    grade_again,
    read_csv,
)
from .book.progress import Progress, summary
from .book.submission_row import grade_submission
from .export.command import main as export
from .options import shared
from .run import cleanup, selfcheck
from .run.cleanup import main as clean
from .run.isolation import file_digests, setup
from .run.launch import Stopped, allow_runs, run_submission
from .run.staging import find_submissions, stage_all

__all__ = ["main", "grade_submission", "find_submissions", "run_submission"]

ASSIGNMENTS = ("puma",)

# the docstring's first line, in the teacher's language in --help
DESCRIPTION = N_("Grade a folder of submitted PUMA notebooks: ``dhlab-grade puma SUBMISSIONS_DIR -o gradebook.csv``.")


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else list(argv)
    if argv[:1] == ["--clean"]:                   # what a killed grader left behind (cleanup.py)
        return clean()
    if argv[:1] == ["export"]:                    # Gradescope's autograder.zip, LMS gradebooks
        return export(argv[1:])
    return grade(argv)


def grade(argv) -> int:
    """``dhlab-grade puma SUBMISSIONS -o gradebook.csv …`` (see the module), in the teacher's language
    (``--language``, else ``DHLAB_LANGUAGE``, else English): its help, messages, statuses and summary;
    each feedback file is in its student's language (:mod:`dhlab.grading.book.submission_row`)."""
    return as_teacher("dhlab-grade", argv, _grade)


def _grade(argv) -> int:
    interrupts = Interrupts()                    # Ctrl-C from now on: see batch.Interrupts
    allow_runs()
    interrupts.install()
    try:
        return _parse_and_grade(argv, interrupts)
    finally:
        interrupts.uninstall()


def _parse_and_grade(argv, interrupts) -> int:
    shared_options = shared(
        secret=_("personal variants: the teacher's secret the notebooks were released with; each "
                 "submission is graded against its student's own robot (without it: the PUMA 560)"),
        source=True,
        language=_("the teacher's language, en or es: this command's messages, the gradebook's statuses "
                   "(default: DHLAB_LANGUAGE, else en); each feedback file is in its student's language"))
    parser = argparse.ArgumentParser(prog="dhlab-grade", description=_(DESCRIPTION), parents=[shared_options],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("assignment", choices=ASSIGNMENTS, help=_("the assignment to grade (puma)"))
    parser.add_argument("submissions", type=Path, help=_("folder of submitted notebooks (*.ipynb, any depth)"))
    parser.add_argument("-o", "--output", type=Path, default=Path("gradebook.csv"), help=_("the gradebook CSV"))
    parser.add_argument("-j", "--jobs", type=int, default=1, help=_("submissions graded at the same time"))
    parser.add_argument("--timeout", type=float, default=30, help=_("seconds per cell (default 30)"))
    parser.add_argument("--total-timeout", type=float, default=None,
                        help=_("seconds for a whole notebook (default 4 × --timeout)"))
    parser.add_argument("--memory-mb", type=float, default=2048, help=_("memory (address space) per kernel, MB"))
    parser.add_argument("--output-mb", type=float, default=10, help=_("output per cell before it is stopped, MB"))
    parser.add_argument("--feedback-dir", type=Path, default=None,
                        help=_("folder for the feedback files (default: beside the CSV, <name>_feedback)"))
    parser.add_argument("--resume", action="store_true",
                        help=_("keep the rows of an existing gradebook and grade only the missing or changed files"))
    parser.add_argument("--isolation", choices=("auto", "user", "none"), default="auto",
                        help=_("auto (default): a user per job when run as root, else none; user: refuse to "
                               "grade without it; none: kernels run as the grader's user"))
    parser.add_argument("-q", "--quiet", action="store_true", help=_("no progress bar"))
    parser.add_argument("--release", type=Path, default=None,
                        help=_("the folder 'dhlab-assign release' wrote (its _teacher/ holds the roster's variants)"))
    parser.add_argument("--fallback", choices=("roster", "none"), default=None,
                        help=_("a missing, tampered or classmate's variant: grade against the roster's variant for "
                               "the student (roster, the default with --release) or give no marks (none)"))
    options = parser.parse_args(argv)
    if options.jobs < 1 or options.timeout <= 0 or options.memory_mb < 256:
        parser.error(_("-j must be ≥ 1, --timeout > 0 and --memory-mb ≥ 256"))
    options.total_timeout = options.total_timeout or 4 * options.timeout
    if options.secret_file is None and (options.release is not None or options.fallback is not None):
        parser.error("--release and --fallback grade personal variants: give --secret-file too (the secret "
                     "the notebooks were released with)")
    resolve = None
    if options.secret_file is not None:
        try:
            variant_setup = GV.setup(options.secret_file, options.release, options.fallback)
        except DHLabError as exc:
            print(error_line("dhlab-grade", exc), file=sys.stderr, end="")
            return 2
        resolve = functools.partial(GV.resolve, variant_setup)
    options.columns = VARIANT_COLUMNS if resolve is not None else COLUMNS
    folder = options.submissions
    if not folder.is_dir():
        parser.error(_("{folder} is not a folder").format(folder=folder))
    paths = find_submissions(folder)
    if not paths:
        print(_("no notebooks (*.ipynb) found under {folder}").format(folder=folder), file=sys.stderr)
        return 2
    feedback_dir = options.feedback_dir or options.output.with_name(options.output.stem + "_feedback")
    unwritable = _cannot_write(options.output)
    if unwritable:
        print(_("dhlab-grade: error: cannot write the gradebook {gradebook} ({why}): choose another -o").format(
            gradebook=options.output, why=unwritable), file=sys.stderr)
        return 2
    return _run_batch(argv, options, folder, paths, feedback_dir, resolve, interrupts)


def _cannot_write(output: Path) -> str:
    """Why the gradebook cannot be written at ``output`` ('' when it can): found before anything
    is graded, not after the first submission."""
    if output.is_dir():
        return _("it is a folder")
    parent = output.parent if str(output.parent) else Path(".")
    try:
        parent.mkdir(parents=True, exist_ok=True)
        with tempfile.TemporaryFile(dir=parent):
            pass
    except OSError as e:
        return e.strerror or str(e)
    return ""


def _run_batch(argv, options, folder, paths, feedback_dir, resolve, interrupts) -> int:
    """Stage, check the grader, grade every submission, and say what happened (exit code)."""
    held = cleanup.hold()                         # dhlab-grade --clean leaves this grader's folders alone  # noqa: F841
    checks.check_all(checks.Answers())            # build the reference before any student code runs
    assignment_cells()                            # and read the assignment's own cells
    copies, iso, batch = None, None, None
    try:
        copies, staged = stage_all(folder, paths, resolve)   # every submission copied (and its variant checked)
        for robot in {id(s.variant.robot): s.variant.robot for s in staged if s.variant and s.variant.variant}.values():
            checks.check_all(checks.Answers(), ref=robot)   # each student's robot built before any code runs
        if interrupts.count:
            return _interrupted(argv, options, None, [], 0)
        try:
            iso = setup(options.jobs, options.isolation)
        except OSError as e:
            print(f"dhlab-grade: cannot isolate the submissions: {e}", file=sys.stderr)
            return 4
        if iso.why:
            print(f"Note: {iso.note()}", file=sys.stderr)
        try:
            selfcheck.check(iso, options)   # a correct notebook, as the submissions' will run
        except selfcheck.SelfCheckError as e:
            if interrupts.count:
                return _interrupted(argv, options, None, [], 0)
            print(f"dhlab-grade: {e}", file=sys.stderr)
            return 5
        except Stopped:
            return _interrupted(argv, options, None, [], 0)
        if interrupts.count:
            return _interrupted(argv, options, None, [], 0)
        feedback_dir.mkdir(parents=True, exist_ok=True)
        old = read_csv(options.output, options.columns)
        keep, removed, todo = _plan(old, staged, options.resume)
        # the old gradebook stays as it is until the first new row (a re-run stopped early loses nothing)
        batch = Batch(options, feedback_dir, keep + (removed if options.resume else []), file_digests, interrupts)
        graded, elapsed = _grade_all(batch, todo, iso)
        if not interrupts.count and not batch.written:
            batch.write()                        # nothing new graded: the kept rows (and the removed ones)
    finally:
        if copies is not None:
            shutil.rmtree(copies, ignore_errors=True)
        if iso is not None:
            iso.close()                           # our grading users, free for other graders again
            if iso.base is not None:
                shutil.rmtree(iso.base, ignore_errors=True)
    return _report(argv, options, feedback_dir, batch, todo, graded, elapsed, iso.jobs, keep, removed)


def _grade_all(batch, todo, iso) -> tuple:
    """Grade ``todo``, ``iso.jobs`` at a time: (the rows graded, in the order they ended; seconds)."""
    started = time.monotonic()
    progress = Progress(len(todo), quiet=batch.options.quiet)
    graded = []
    batch.interrupts.batch_running = True
    with concurrent.futures.ThreadPoolExecutor(max_workers=iso.jobs) as pool:
        futures = [pool.submit(grade_one, batch, s, iso) for s in todo]
        for future in concurrent.futures.as_completed(futures):
            row = future.result()
            if row is not None:
                graded.append(row)
                progress.step(row)
    batch.interrupts.batch_running = False
    progress.end()
    return graded, time.monotonic() - started


def _report(argv, options, feedback_dir, batch, todo, graded, elapsed, jobs, keep, removed) -> int:
    """The summary at the end of a batch, and its exit code (0, 3 stopped, 130 interrupted)."""
    if graded:
        print(summary(graded, elapsed, jobs), file=sys.stderr)
    if keep:
        print(_("Resumed: {count} rows kept from {gradebook}.").format(count=len(keep), gradebook=options.output),
              file=sys.stderr)
    if removed:
        print(_removed_text(removed, options.resume), file=sys.stderr)
    print(_("Gradebook: {gradebook}  Feedback: {folder}/").format(gradebook=options.output, folder=feedback_dir),
          file=sys.stderr)
    if batch.refusal:
        left = sorted(set(batch.discarded) | {s.submission for s in todo if s.submission not in batch.rows})
        print(_("STOPPED: {why}").format(why=batch.refusal), file=sys.stderr)
        print(_("Not graded ({count}): {names}").format(count=len(left), names=", ".join(left[:20])), file=sys.stderr)
        return 3
    if batch.interrupts.count:
        return _interrupted(argv, options, batch, todo, len(graded))
    return 0


def _plan(old, staged, resume) -> tuple:
    """(rows kept, rows of submissions removed since the last run, submissions to grade).

    With ``--resume`` a row is kept when its file is unchanged and it is not a grader error; a row
    whose file is gone from the folder is kept too, its status marked :data:`REMOVED` (its feedback
    file is still there; dropping it silently lost a grade). Without ``--resume`` every submission is
    graded again and the removed ones are only reported."""
    present = {s.submission for s in staged}
    removed = [r for r in old if r["submission"] not in present]
    if not resume:
        return [], removed, list(staged)
    current = {(s.submission, s.sha256) for s in staged}
    keep = [r for r in old if (r["submission"], r["sha256"]) in current     # unchanged since graded,
            and not grade_again(r) and not r["status"].startswith(REMOVED)]  # and not a grader error
    for row in removed:
        if not row["status"].startswith(REMOVED):
            row["status"] = f"{REMOVED}; {row['status']}"
    done = {(r["submission"], r["sha256"]) for r in keep}
    return keep, removed, [s for s in staged if (s.submission, s.sha256) not in done]


def _removed_text(removed, resume) -> str:
    """The summary's line on the submissions removed since the last run (none is dropped silently)."""
    names = ", ".join(r["submission"] for r in removed[:20]) + (", …" if len(removed) > 20 else "")
    if resume:
        return _("Removed since the last run ({count}): {names}. Their rows are kept, their status starting "
                 "'{mark}'; delete those rows if they should go.").format(count=len(removed), names=names,
                                                                          mark=REMOVED)
    return _("Removed since the last run ({count}): {names}. They are not in the new gradebook (their "
             "feedback files are still there).").format(count=len(removed), names=names)


def _interrupted(argv, options, batch, todo, graded: int) -> int:
    """After Ctrl-C: what was graded, and the exact command that grades the rest; exit code 130."""
    again = list(argv) if "--resume" in argv or batch is None or not batch.written else [*argv, "--resume"]
    command = "dhlab-grade " + shlex.join(again)
    if batch is None or not batch.written:
        print(_("Interrupted before any submission was graded: the gradebook {gradebook} is unchanged. "
                "To grade: {command}").format(gradebook=options.output, command=command), file=sys.stderr)
        return 130
    missing = len([s for s in todo if s.submission not in batch.rows])
    print(_("Interrupted: graded in this run {graded}, left {missing} ({stopped} stopped while running: their rows "
            "are not written). The gradebook keeps every finished row. To grade the rest: {command}").format(
        graded=graded, missing=missing, stopped=len(batch.stopped), command=command), file=sys.stderr)
    return 130


if __name__ == "__main__":
    sys.exit(main())
