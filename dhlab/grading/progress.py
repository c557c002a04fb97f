"""What a teacher sees while ``dhlab-grade`` runs and at its end: a progress line, a summary.

:class:`Progress` is a one-line bar on a terminal (one line per submission otherwise);
:func:`_summary` counts the run's scores and statuses (:data:`STATUS_KINDS`) in a few lines.
"""
from __future__ import annotations

import sys
import time

__all__ = ["Progress", "STATUS_KINDS"]


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
        score = f"{row['score']}/{row['max_score']}" if row["score"] != "" else "not graded"
        line = f"[{bar}] {self.done}/{self.total}  {row['submission']}: {score}  {row['status'][:60]}"
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
                ("modifies dhlab", "modifies dhlab"), ("grader error", "grader error"),
                ("variant missing", "variant missing"), ("variant tampered", "variant tampered"),
                ("variant other_student", "a classmate's variant"), ("student not identified", "student unknown")]


def _summary(rows, seconds, jobs) -> str:
    """A few lines for the end of the run: time, scores, how many had each kind of status."""
    n = len(rows)
    scored = [r for r in rows if r["score"] != ""]          # a grader error has no score
    scores = [float(r["score"]) for r in scored]
    counts = {label: sum(1 for r in rows if (r["status"] == key if key in ("ok", "not answered") else key in r["status"]))
              for key, label in STATUS_KINDS}
    per = seconds / n if n else 0.0
    full = sum(1 for r in scored if float(r["score"]) == float(r["max_score"]))
    mean = f"Mean score {sum(scores) / len(scores):.2f}/{rows[0]['max_score']}" if scores else "No score"
    left = n - len(scored)
    again = f"; not graded (grader error): {left}, run the same command with --resume" if left else ""
    return "\n".join([
        f"Graded {n} submission{'s' if n != 1 else ''} in {seconds:.1f} s with -j {jobs} ({per:.2f} s per submission).",
        f"{mean}; full marks: {full}{again}.",
        "Status: " + ", ".join(f"{label} {c}" for label, c in counts.items() if c)])
