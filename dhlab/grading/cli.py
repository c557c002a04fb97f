"""Grade a folder of submitted PUMA notebooks: ``dhlab-grade puma SUBMISSIONS_DIR -o gradebook.csv``.

    dhlab-grade puma SUBMISSIONS_DIR -o gradebook.csv [-j N] [--timeout S] [--resume]
                [--secret-file KEY --release RELEASE_DIR [--fallback roster|none]] [--language en|es]
    dhlab-grade export gradescope|try-gradescope|canvas|moodle ...   (dhlab.grading.export)
    dhlab-grade --clean                    (remove what a killed grader left: dhlab.grading.cleanup)
    python -m dhlab.grading.cli puma SUBMISSIONS_DIR ...          (the same)

Every ``*.ipynb`` under SUBMISSIONS_DIR (any depth, e.g. nbgrader's
``submitted/<student>/<assignment>/``) is one submission. What happens:

1. **Every submission is copied first**, without its outputs (:mod:`dhlab.grading.staging`),
   into a folder only the grader can enter; nothing runs before all are copied.
2. **The grader checks itself** (:mod:`dhlab.grading.selfcheck`): one kernel is started exactly
   as the submissions' will be and must import dhlab and answer; if it cannot, the grader
   stops with one message (which user cannot enter which folder, what to do), exit code 5,
   and grades nothing.
3. Each copy is run by its own runner process (:mod:`dhlab.grading.runner`) in a fresh
   kernel with a time limit per cell (``--timeout``), a limit for the whole notebook, a
   memory limit and an output limit; ``-j N`` runs N at a time. As root, each kernel
   runs as an unprivileged user of its own, in its own folder
   (:mod:`dhlab.grading.isolation`), and every process of that user is killed afterwards.
4. The runner only returns the student's answers as plain data; they are scored
   **here**, in the grader's process, by :mod:`dhlab.grading.checks`.
5. Before and after each submission the whole installed ``dhlab`` is checked
   unchanged; if it changed, the grader stops with a message (the rows it can
   trust are kept).
6. The gradebook CSV is rewritten atomically after every submission (submission,
   score, max_score, status, one column per part, seconds, feedback file, the file
   and its SHA-256), so a grader killed mid-batch keeps every finished row, and
   ``--resume`` grades only what is missing (or changed). One feedback file per
   submission goes to a folder beside it (``gradebook_feedback/``). Exit codes: 0 done,
   2 usage, 3 stopped (dhlab changed), 4 cannot isolate, 5 the self-check failed.

A submission that raises, hangs, floods its output, runs out of memory, is not a
notebook, or tampers with dhlab gets the marks its real answers earn and a reason in
``status``; it never stops the batch.

**Personal variants** (notebooks released with ``dhlab-assign release``): with
``--secret-file`` each submission is graded against its student's own robot. While the
submissions are staged (step 1, before any runs) the grader works out whose each one is,
verifies the variant signed in it, rewrites the copy's "Your robot" cell from the variant
it will be graded against, and the checks score against that robot; ``--release`` (the
release folder) gives the roster and every student's released variant, the fallback for a
missing, tampered or classmate's record (``--fallback roster``, the default with
``--release``; ``none``: no marks). The rules, and the gradebook's five variant columns:
:mod:`dhlab.grading.grade_variants`. Without ``--secret-file`` every submission is
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
import sys
import threading
import time
from pathlib import Path

from .language import _
from .launch import run_submission
from .progress import Progress, _summary
from .rows import _error_row, grade_submission
from .staging import find_submissions

__all__ = ["main", "grade_submission", "find_submissions", "run_submission"]

ASSIGNMENTS = ("puma",)


class _Batch:
    """The rows of one batch, the gradebook rewritten after each, and the package watch."""

    def __init__(self, options, feedback_dir, rows, fingerprint_now):
        self.options, self.feedback_dir = options, feedback_dir
        self.rows = {r["submission"]: r for r in rows}
        self.lock = threading.Lock()
        self.fingerprint = fingerprint_now
        self.expected = fingerprint_now()
        self.checked_ok = time.monotonic()          # when the package was last seen unchanged
        self.stop = threading.Event()
        self.refusal = ""
        self.discarded = []

    def package_unchanged(self) -> bool:
        from .isolation import changed_files
        with self.lock:
            if self.stop.is_set():
                return False
            now = self.fingerprint()
            if now == self.expected:
                self.checked_ok = time.monotonic()
                return True
            self.stop.set()
            changed = changed_files(self.expected, now)
            self.refusal = (f"dhlab's installed files changed during the batch ({', '.join(changed[:5])}"
                            f"{', …' if len(changed) > 5 else ''}: did a submission write to them?). "
                            "The grader stopped: reinstall dhlab (pip install --force-reinstall, or git checkout "
                            "of the package), then run the same command with --resume.")
            # every row that ran since the package was last seen unchanged cannot be trusted
            for name, row in list(self.rows.items()):
                if row.get("_started", -1) >= 0 and row["_ended"] > self.checked_ok:
                    self.discarded.append(name)
                    del self.rows[name]
            self._write()
            return False

    def add(self, row, started, ended) -> None:
        from .gradebook import write_atomic
        with self.lock:
            text = row.pop("_feedback_text")
            row.pop("_part_text", None)
            if self.stop.is_set():
                self.discarded.append(row["submission"])
                return
            row["_started"], row["_ended"] = started, ended
            write_atomic(self.feedback_dir / row["feedback"], text)
            self.rows[row["submission"]] = row
            self._write()

    def _write(self) -> None:
        from .gradebook import write_csv
        write_csv(self.options.output, self.rows.values(), self.options.columns)


def _grade_one(batch, staged, iso, hide):
    """One task of the pool: check the package, grade, check again, keep the row."""
    if not batch.package_unchanged():
        return None
    started = time.monotonic()
    try:
        row = grade_submission(staged, batch.options, iso, hide)
    except Exception as exc:                      # never stop the batch
        row = _error_row(staged, exc)
    ended = time.monotonic()
    if not batch.package_unchanged():
        batch.discarded.append(staged.submission)
        return None
    batch.add(row, started, ended)
    return row


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else list(argv)
    if argv[:1] == ["--clean"]:                   # what a killed grader left behind (cleanup.py)
        from .cleanup import main as clean
        return clean()
    if argv[:1] == ["export"]:                    # Gradescope's autograder.zip, LMS gradebooks
        from .export import main as export
        return export(argv[1:])
    return grade(argv)


def grade(argv) -> int:
    """``dhlab-grade puma SUBMISSIONS -o gradebook.csv …`` (see the module), in the teacher's language
    (``--language``, else ``DHLAB_LANGUAGE``, else English): its help, messages, statuses and summary;
    each feedback file is in its student's language (:mod:`dhlab.grading.rows`)."""
    from .language import as_teacher
    return as_teacher("dhlab-grade", argv, _grade)


def _grade(argv) -> int:
    parser = argparse.ArgumentParser(prog="dhlab-grade", description=__doc__.splitlines()[0],
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
    parser.add_argument("--secret-file", type=Path, default=None,
                        help=_("personal variants: the teacher's secret the notebooks were released with; each "
                               "submission is graded against its student's own robot (without it: the PUMA 560)"))
    parser.add_argument("--release", type=Path, default=None,
                        help=_("the folder 'dhlab-assign release' wrote (its _teacher/ holds the roster's variants)"))
    parser.add_argument("--fallback", choices=("roster", "none"), default=None,
                        help=_("a missing, tampered or classmate's variant: grade against the roster's variant for "
                               "the student (roster, the default with --release) or give no marks (none)"))
    parser.add_argument("--language", default=None,
                        help=_("the teacher's language, en or es: this command's messages, the gradebook's statuses "
                               "(default: DHLAB_LANGUAGE, else en); each feedback file is in its student's language"))
    options = parser.parse_args(argv)
    if options.jobs < 1 or options.timeout <= 0 or options.memory_mb < 256:
        parser.error(_("-j must be ≥ 1, --timeout > 0 and --memory-mb ≥ 256"))
    options.total_timeout = options.total_timeout or 4 * options.timeout
    if options.secret_file is None and (options.release is not None or options.fallback is not None):
        parser.error("--release and --fallback grade personal variants: give --secret-file too (the secret "
                     "the notebooks were released with)")
    resolve = None
    if options.secret_file is not None:
        from . import grade_variants as GV
        from ..validation import DHLabError
        try:
            variant_setup = GV.setup(options.secret_file, options.release, options.fallback)
        except DHLabError as exc:
            print(f"dhlab-grade: error: {exc}", file=sys.stderr)
            return 2
        resolve = functools.partial(GV.resolve, variant_setup)
    from .gradebook import COLUMNS, VARIANT_COLUMNS
    options.columns = VARIANT_COLUMNS if resolve is not None else COLUMNS
    folder = options.submissions
    if not folder.is_dir():
        parser.error(_("{folder} is not a folder").format(folder=folder))
    paths = find_submissions(folder)
    if not paths:
        print(_("no notebooks (*.ipynb) found under {folder}").format(folder=folder), file=sys.stderr)
        return 2
    feedback_dir = options.feedback_dir or options.output.with_name(options.output.stem + "_feedback")

    from . import checks, grade_variants  # noqa: F401  (imported before any student code runs)
    from .gradebook import assignment_cells, grade_again, read_csv
    from .isolation import file_digests, setup
    from . import cleanup, selfcheck
    from .staging import stage_all
    held = cleanup.hold()                         # dhlab-grade --clean leaves this grader's folders alone  # noqa: F841
    checks.check_all(checks.Answers())            # build the reference before any student code runs
    assignment_cells()                            # and read the assignment's own cells

    copies, staged = stage_all(folder, paths, resolve)   # every submission copied (and its variant checked)
    for robot in {id(s.variant.robot): s.variant.robot for s in staged if s.variant and s.variant.variant}.values():
        checks.check_all(checks.Answers(), ref=robot)   # each student's robot built before any code runs
    try:
        try:
            iso = setup(options.jobs, options.isolation)
        except OSError as e:
            print(f"dhlab-grade: cannot isolate the submissions: {e}", file=sys.stderr)
            return 4
        if iso.why:
            print(f"Note: {iso.note()}", file=sys.stderr)
        try:
            selfcheck.check(iso, options, [folder.resolve()])   # one kernel, as the submissions' will run
        except selfcheck.SelfCheckError as e:
            print(f"dhlab-grade: {e}", file=sys.stderr)
            return 5
        feedback_dir.mkdir(parents=True, exist_ok=True)
        old = read_csv(options.output, options.columns) if options.resume else []
        current = {(s.submission, s.sha256) for s in staged}
        keep = [r for r in old if (r["submission"], r["sha256"]) in current     # unchanged since graded,
                and not grade_again(r)]                                          # and not a grader error
        done = {(r["submission"], r["sha256"]) for r in keep}
        todo = [s for s in staged if (s.submission, s.sha256) not in done]
        batch = _Batch(options, feedback_dir, keep, file_digests)
        batch._write()
        hide = [folder.resolve()]
        started = time.monotonic()
        progress = Progress(len(todo), quiet=options.quiet)
        graded = []
        with concurrent.futures.ThreadPoolExecutor(max_workers=iso.jobs) as pool:
            futures = [pool.submit(_grade_one, batch, s, iso, hide) for s in todo]
            for future in concurrent.futures.as_completed(futures):
                row = future.result()
                if row is not None:
                    graded.append(row)
                    progress.step(row)
        elapsed = time.monotonic() - started
    finally:
        import shutil
        shutil.rmtree(copies, ignore_errors=True)
        if "iso" in locals():
            iso.close()                           # our grading users, free for other graders again
            if iso.base is not None:
                shutil.rmtree(iso.base, ignore_errors=True)
    if graded:
        print(_summary(graded, elapsed, iso.jobs), file=sys.stderr)
    if keep:
        print(_("Resumed: {count} rows kept from {gradebook}.").format(count=len(keep), gradebook=options.output),
              file=sys.stderr)
    print(_("Gradebook: {gradebook}  Feedback: {folder}/").format(gradebook=options.output, folder=feedback_dir),
          file=sys.stderr)
    if batch.refusal:
        left = sorted(set(batch.discarded) | {s.submission for s in todo if s.submission not in batch.rows})
        print(_("STOPPED: {why}").format(why=batch.refusal), file=sys.stderr)
        print(_("Not graded ({count}): {names}").format(count=len(left), names=", ".join(left[:20])), file=sys.stderr)
        return 3
    return 0


if __name__ == "__main__":
    sys.exit(main())
