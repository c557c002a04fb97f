"""What a teacher sees while ``dhlab-grade`` runs and at its end: a progress line, a summary.

:class:`Progress` is a one-line bar on a terminal (one line per submission otherwise);
:func:`summary` counts the run's scores and statuses (:data:`STATUS_KINDS`) in a few lines.
"""
from __future__ import annotations

import sys
import time

from ...i18n import N_, _

__all__ = ["Progress", "STATUS_KINDS", "summary"]


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
        score = f"{row['score']}/{row['max_score']}" if row["score"] != "" else _("not graded")
        line = f"[{bar}] {self.done}/{self.total}  {row['submission']}: {score}  {row['status'][:60]}"
        if self.tty:
            self.stream.write("\r" + line[:120].ljust(120))
            if self.done == self.total:
                self.stream.write("\n")
        else:
            self.stream.write(line + "\n")
        self.stream.flush()

    def end(self) -> None:
        """End the bar's line when the batch stopped short of the total (Ctrl-C, a refusal), so that
        what is printed next starts on a line of its own."""
        if self.tty and not self.quiet and 0 < self.done < self.total:
            self.stream.write("\n")
            self.stream.flush()


# (the start of a status, as dhlab.grading.book.gradebook writes it in the teacher's language; its label)
STATUS_KINDS = [("ok", "ok"), (N_("not answered"), N_("not answered")),
                (N_("invalid notebook"), N_("invalid notebook")),
                (N_("error in cell"), N_("errors")), (N_("memory limit"), N_("memory limit")),
                (N_("timeout"), N_("timeout")), (N_("output limit"), N_("output limit")),
                (N_("kernel died"), N_("kernel died")), (N_("could not be interrupted"), N_("hung")),
                (N_("runner was killed"), N_("runner killed")),
                (N_("time limit for the whole"), N_("notebook time limit")),
                (N_("answers not read"), N_("answers not read")), (N_("modifies dhlab"), N_("modifies dhlab")),
                ("grader error", "grader error"), (N_("variant missing"), N_("variant missing")),
                (N_("variant tampered"), N_("variant tampered")),
                (N_("variant other_student"), N_("a classmate's variant")),
                (N_("student not identified"), N_("student unknown"))]


def summary(rows, seconds, jobs) -> str:
    """A few lines for the end of the run: time, scores, how many had each kind of status."""
    n = len(rows)
    scored = [r for r in rows if r["score"] != ""]          # a grader error has no score
    scores = [float(r["score"]) for r in scored]
    counts = {}
    for key, label in STATUS_KINDS:
        key = _(key)
        counts[_(label)] = sum(1 for r in rows if (r["status"] == key if key in ("ok", _("not answered"))
                                                   else key in r["status"]))
    per = seconds / n if n else 0.0
    full = sum(1 for r in scored if float(r["score"]) == float(r["max_score"]))
    mean = (_("Mean score {mean}/{max}").format(mean=f"{sum(scores) / len(scores):.2f}", max=rows[0]["max_score"])
            if scores else _("No score"))
    left = n - len(scored)
    again = (_("; not graded (grader error): {left}, run the same command with --resume").format(left=left)
             if left else "")
    graded = (_("Graded {n} submission in {seconds} s with -j {jobs} ({per} s per submission).") if n == 1 else
              _("Graded {n} submissions in {seconds} s with -j {jobs} ({per} s per submission)."))
    return "\n".join([
        graded.format(n=n, seconds=f"{seconds:.1f}", jobs=jobs, per=f"{per:.2f}"),
        _("{mean}; full marks: {full}{again}.").format(mean=mean, full=full, again=again),
        _("Status: {counts}").format(counts=", ".join(f"{label} {c}" for label, c in counts.items() if c))])
