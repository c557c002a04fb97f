"""Grade a folder of submitted PUMA notebooks: ``dhlab-grade puma SUBMISSIONS_DIR -o gradebook.csv``.

    dhlab-grade puma SUBMISSIONS_DIR -o gradebook.csv [-j N] [--timeout S]
    python -m dhlab.grading.cli puma SUBMISSIONS_DIR ...          (the same)

Every ``*.ipynb`` under SUBMISSIONS_DIR (any depth, e.g. nbgrader's
``submitted/<student>/<assignment>/``) is one submission. Each one is run by its
own runner process (:mod:`dhlab.grading.runner`) in a fresh kernel with a time
limit per cell (``--timeout``), a limit for the whole notebook, a memory limit and
an output limit; ``-j N`` runs N at a time. The runner only returns the student's
answers as plain data; they are scored **here**, in the grader's process, by
:mod:`dhlab.grading.checks`.

Written: the gradebook CSV (submission, score, max_score, status, one column per
part, seconds, feedback), and one feedback file per submission in a folder beside
it (``gradebook_feedback/`` for ``gradebook.csv``). A submission that raises,
hangs, floods its output, runs out of memory, is not a notebook, or tampers with
dhlab gets the marks its real answers earn and a reason in ``status``; it never
stops the batch. The gradebook is written atomically, at the end.
"""
from __future__ import annotations

import argparse
import concurrent.futures
import hashlib
import json
import os
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

__all__ = ["main", "grade_submission", "find_submissions"]

ASSIGNMENTS = ("puma",)


def find_submissions(folder: Path) -> list:
    """Every notebook under ``folder``, skipping checkpoints and hidden folders."""
    out = []
    for path in sorted(folder.rglob("*.ipynb")):
        parts = path.relative_to(folder).parts
        if any(p.startswith(".") for p in parts) or path.is_symlink() or not path.is_file():
            continue
        out.append(path)
    return out


def _dhlab_fingerprint() -> str:
    """A hash of the files the grading reads from disk while it runs (the runner, the
    kernel's launcher, the answers' reader): a submission must not be able to change them.
    The checks themselves are loaded into this process before any submission runs."""
    from . import runner
    h = hashlib.sha256()
    for path in sorted(runner.RUNNER.parent.glob("*.py")):
        h.update(path.name.encode())
        h.update(path.read_bytes())
    return h.hexdigest()


def _kill_kernel(pid_file: Path) -> None:
    """Kill the kernel a runner started (its own process group), if it is still there."""
    try:
        pid = int(pid_file.read_text().strip())
        cmdline = Path(f"/proc/{pid}/cmdline").read_bytes()
    except (OSError, ValueError):
        return
    if b"sandbox.py" in cmdline:
        try:
            os.killpg(pid, signal.SIGKILL)
        except (ProcessLookupError, PermissionError):
            pass


def run_submission(path: Path, options, retries: int = 2) -> dict:
    """Run one notebook in a runner process; the runner's result (a dict).

    If the runner process itself dies (a notebook can kill its kernel's parent), the
    notebook is run again without the cell that was running, at most ``retries`` times.
    """
    killed = []
    for attempt in range(retries + 1):
        run, cell = _run_once(path, options, skip=killed)
        if not run.get("grader_error") or cell is None or cell in killed or attempt == retries:
            break
        killed.append(cell)
    if killed and not run.get("grader_error"):
        run["runner_killed"] = killed
    elif killed:
        run["grader_error"] += f" (also in a run without cell {', '.join(map(str, killed))})"
    return run


def _run_once(path: Path, options, skip) -> tuple:
    """(result dict, the cell that was running when the runner stopped or None)."""
    from .runner import RUNNER
    with tempfile.TemporaryDirectory(prefix="dhlab-grade-") as tmp:
        tmp = Path(tmp)
        result, pid_file, log = tmp / "result.json", tmp / "kernel.pid", tmp / "runner.log"
        progress = tmp / "progress"
        cmd = [sys.executable, str(RUNNER), str(path), str(result),
               "--timeout", str(options.timeout), "--total-timeout", str(options.total_timeout),
               "--memory-mb", str(options.memory_mb), "--output-mb", str(options.output_mb),
               "--pid-file", str(pid_file), "--progress-file", str(progress)]
        for cell in skip:
            cmd += ["--skip", str(cell)]
        hard_limit = options.total_timeout + 150          # kernel starts and the answers' read
        with open(log, "wb") as err:
            # TMPDIR: the runner's working folder, the kernel's connection file and the notebook's
            # own temporary files all land in this folder, which goes away even if the runner is killed
            proc = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=err,
                                    start_new_session=True, env=dict(os.environ, TMPDIR=str(tmp)))
            try:
                proc.wait(timeout=hard_limit)
            except subprocess.TimeoutExpired:
                os.killpg(proc.pid, signal.SIGKILL)
                proc.wait()
            finally:
                _kill_kernel(pid_file)
        if result.exists():
            try:
                return json.loads(result.read_text(encoding="utf-8")), None
            except ValueError:
                pass
        try:
            cell = int(progress.read_text())
        except (OSError, ValueError):
            cell = None
        tail = log.read_bytes()[-300:].decode("utf-8", "replace").strip().splitlines()[-1:] if log.exists() else []
        why = (f"the runner did not finish in {hard_limit:.0f} s" if proc.returncode in (-9, None)
               else f"the runner stopped (exit code {proc.returncode})")
        if cell is not None:
            why += f" while running cell {cell}"
        return {"grader_error": why + (f": {tail[0][:150]}" if tail else "")}, cell


def grade_submission(path: Path, folder: Path, options) -> dict:
    """Run, read the answers, score in this process: one gradebook row (+ feedback text)."""
    from . import checks
    from .answers import Answers, Unreadable, parse_json
    from .gradebook import PART_COLUMNS, feedback_filename, feedback_text, status_text

    started = time.monotonic()
    submission = path.relative_to(folder).with_suffix("").as_posix()
    run = run_submission(path, options)
    answers, problem = Answers(), ""
    if run.get("answers_json"):
        try:
            answers = parse_json(run["answers_json"])
        except ValueError as e:
            problem = f"answers not read: {e}"
    report = checks.check_all(answers)
    unreadable = [name for name, value in answers.items() if isinstance(value, Unreadable)]
    if unreadable and not problem:
        problem = f"unreadable answers: {', '.join(unreadable)}"
    status = status_text(run, report_answered=answers.answered(), answers_problem=problem)
    row = {"submission": submission, "score": f"{report.score:g}", "max_score": report.max_score,
           "status": status, "seconds": f"{time.monotonic() - started:.1f}",
           "feedback": feedback_filename(submission)}
    for part in report.parts:
        row[PART_COLUMNS[part.key]] = f"{part.score:g}"
    row["_feedback_text"] = feedback_text(submission, run, report, status)
    return row


def _error_row(path, folder, exc) -> dict:
    """The row of a submission the grader itself failed on (it keeps the batch going)."""
    from .checks import POINTS
    from .gradebook import PART_COLUMNS, feedback_filename
    submission = path.relative_to(folder).with_suffix("").as_posix()
    status = f"grader error: {type(exc).__name__}: {str(exc)[:150]}"
    row = {"submission": submission, "score": "0", "max_score": sum(POINTS.values()), "status": status, "seconds": "0",
           "feedback": feedback_filename(submission),
           "_feedback_text": f"Submission: {submission}\nStatus: {status}\n"}
    row.update({c: "0" for c in PART_COLUMNS.values()})
    return row


class Progress:
    """A one-line progress bar on a terminal; one line per submission otherwise."""

    def __init__(self, total: int, stream=sys.stderr, quiet: bool = False):
        self.total, self.done, self.stream, self.quiet = total, 0, stream, quiet
        self.tty = stream.isatty()
        self.started = time.monotonic()

    def step(self, row) -> None:
        self.done += 1
        if self.quiet:
            return
        width = 30
        filled = int(width * self.done / max(self.total, 1))
        bar = "#" * filled + "-" * (width - filled)
        line = (f"[{bar}] {self.done}/{self.total}  {row['submission']}: {row['score']}/{row['max_score']}"
                f"  {row['status'][:60]}")
        if self.tty:
            self.stream.write("\r" + line[:120].ljust(120))
            if self.done == self.total:
                self.stream.write("\n")
        else:
            self.stream.write(line + "\n")
        self.stream.flush()


STATUS_KINDS = [("ok", "ok"), ("not answered", "not answered"), ("invalid notebook", "invalid notebook"),
                ("error in cell", "errors"), ("memory limit", "memory limit"), ("timeout", "timeout"),
                ("output limit", "output limit"), ("kernel died", "kernel died"),
                ("could not be interrupted", "hung"), ("runner was killed", "runner killed"),
                ("time limit for the whole", "notebook time limit"), ("answers not read", "answers not read"),
                ("modifies dhlab", "modifies dhlab"), ("grader error", "grader error")]


def _summary(rows, seconds, jobs) -> str:
    """A few lines for the end of the run: time, scores, how many had each kind of status."""
    n = len(rows)
    scores = [float(r["score"]) for r in rows]
    counts = {label: sum(1 for r in rows if (r["status"] == key if key in ("ok", "not answered") else key in r["status"]))
              for key, label in STATUS_KINDS}
    per = seconds / n if n else 0.0
    full = sum(1 for r in rows if float(r["score"]) == float(r["max_score"]))
    return "\n".join([
        f"Graded {n} submission{'s' if n != 1 else ''} in {seconds:.1f} s with -j {jobs} ({per:.2f} s per submission).",
        f"Mean score {sum(scores) / n:.2f}/{rows[0]['max_score']}; full marks: {full}.",
        "Status: " + ", ".join(f"{label} {c}" for label, c in counts.items() if c)])


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="dhlab-grade", description=__doc__.splitlines()[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("assignment", choices=ASSIGNMENTS, help="the assignment to grade (puma)")
    parser.add_argument("submissions", type=Path, help="folder of submitted notebooks (*.ipynb, any depth)")
    parser.add_argument("-o", "--output", type=Path, default=Path("gradebook.csv"), help="the gradebook CSV")
    parser.add_argument("-j", "--jobs", type=int, default=1, help="submissions graded at the same time")
    parser.add_argument("--timeout", type=float, default=30, help="seconds per cell (default 30)")
    parser.add_argument("--total-timeout", type=float, default=None,
                        help="seconds for a whole notebook (default 4 × --timeout)")
    parser.add_argument("--memory-mb", type=float, default=2048, help="memory (address space) per kernel, MB")
    parser.add_argument("--output-mb", type=float, default=10, help="output per cell before it is stopped, MB")
    parser.add_argument("--feedback-dir", type=Path, default=None,
                        help="folder for the feedback files (default: beside the CSV, <name>_feedback)")
    parser.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    options = parser.parse_args(argv)
    if options.jobs < 1 or options.timeout <= 0 or options.memory_mb < 256:
        parser.error("-j must be ≥ 1, --timeout > 0 and --memory-mb ≥ 256")
    options.total_timeout = options.total_timeout or 4 * options.timeout
    folder = options.submissions
    if not folder.is_dir():
        parser.error(f"{folder} is not a folder")
    paths = find_submissions(folder)
    if not paths:
        print(f"no notebooks (*.ipynb) found under {folder}", file=sys.stderr)
        return 2
    feedback_dir = options.feedback_dir or options.output.with_name(options.output.stem + "_feedback")

    from . import checks
    from .gradebook import write_atomic, write_csv
    checks.check_all(checks.Answers())            # build the reference before any student code runs

    fingerprint = _dhlab_fingerprint()
    started = time.monotonic()
    progress = Progress(len(paths), quiet=options.quiet)
    rows = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=options.jobs) as pool:
        futures = {pool.submit(grade_submission, p, folder, options): p for p in paths}
        for future in concurrent.futures.as_completed(futures):
            try:
                row = future.result()
            except Exception as exc:              # never stop the batch
                row = _error_row(futures[future], folder, exc)
            write_atomic(feedback_dir / row["feedback"], row.pop("_feedback_text"))
            rows.append(row)
            progress.step(row)
    write_csv(options.output, rows)
    elapsed = time.monotonic() - started
    print(_summary(rows, elapsed, options.jobs), file=sys.stderr)
    print(f"Gradebook: {options.output}  Feedback: {feedback_dir}/", file=sys.stderr)
    if _dhlab_fingerprint() != fingerprint:
        print("WARNING: dhlab's own files changed while grading (did a submission write to them?). "
              "Reinstall dhlab and grade again.", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
