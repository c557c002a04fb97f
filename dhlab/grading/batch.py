"""One grading run's state, shared by the pool of workers (:mod:`dhlab.grading.cli` starts them):
the rows of the batch and the gradebook rewritten after each (:class:`Batch`, which also watches that
nothing changes dhlab's installed files while submissions run), what Ctrl-C does (:class:`Interrupts`),
and one submission graded as a task of the pool (:func:`grade_one`)."""
from __future__ import annotations

import os
import signal
import threading
import time

from ..i18n import _
from .atomic_file import write_atomic
from .book.gradebook import write_csv
from .book.submission_row import error_row, grade_submission
from .run.isolation import changed_files
from .run.launch import Stopped, stop_all

__all__ = ["Batch", "Interrupts", "grade_one"]


class Batch:
    """The rows of one batch, the gradebook rewritten after each, and the package watch."""

    def __init__(self, options, feedback_dir, rows, fingerprint_now, interrupts=None):
        self.options, self.feedback_dir = options, feedback_dir
        self.rows = {r["submission"]: r for r in rows}
        self.lock = threading.Lock()
        self.fingerprint = fingerprint_now
        self.expected = fingerprint_now()
        self.checked_ok = time.monotonic()          # when the package was last seen unchanged
        self.stop = threading.Event()
        self.refusal = ""
        self.discarded = []
        self.stopped = []                           # stopped by a second Ctrl-C: no row
        self.interrupts = interrupts or Interrupts()
        self.written = False                        # the gradebook rewritten by this run yet

    def package_unchanged(self) -> bool:
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
            self.write()
            return False

    def add(self, row, started, ended) -> None:
        with self.lock:
            text = row.pop("_feedback_text")
            row.pop("_part_text", None)
            if self.stop.is_set():
                self.discarded.append(row["submission"])
                return
            row["_started"], row["_ended"] = started, ended
            write_atomic(self.feedback_dir / row["feedback"], text)
            self.rows[row["submission"]] = row
            self.write()

    def cannot_write(self, submission: str, exc: OSError) -> None:
        """The gradebook or a feedback file could not be written (a full disk, a folder removed): the
        grader stops as when dhlab changed (exit code 3); the rows written so far stay."""
        with self.lock:
            self.discarded.append(submission)
            if not self.stop.is_set():
                self.stop.set()
                self.refusal = _("cannot write {file} ({why}). Free some space or fix the folder, then run the "
                                 "same command with --resume.").format(file=exc.filename or self.options.output,
                                                                        why=exc.strerror or exc)

    def write(self) -> None:
        """The gradebook, written again (atomically) from the rows kept so far."""
        write_csv(self.options.output, self.rows.values(), self.options.columns)
        self.written = True


class Interrupts:
    """What Ctrl-C (SIGINT) does while the grader runs. The first: no new submission starts and the
    running ones finish (before the batch: it stops at once); the second (or SIGTERM): the running
    ones are stopped too (:func:`dhlab.grading.run.launch.stop_all`), and their rows are not written.
    Either way the grader then removes its copies and kernels' folders, says how to resume, and
    exits with 130. Before, one Ctrl-C graded to the end and a second turned correct notebooks
    into zeros that ``--resume`` kept."""

    SIGNALS = (signal.SIGINT, signal.SIGTERM)

    def __init__(self):
        self.count = 0
        self.batch_running = False
        self.previous = {}

    def install(self) -> None:
        """Handle the signals here, except one the grader was started ignoring (``nohup``, ``… &``)."""
        if threading.current_thread() is threading.main_thread():     # (signals go to the main thread)
            self.previous = {s: signal.signal(s, self.on_signal) for s in self.SIGNALS
                             if signal.getsignal(s) != signal.SIG_IGN}

    def uninstall(self) -> None:
        for signum, handler in self.previous.items():
            signal.signal(signum, handler if handler is not None else signal.SIG_DFL)
        self.previous = {}

    def on_signal(self, signum, frame) -> None:
        self.count += 1
        if self.count == 1 and signum == signal.SIGINT and self.batch_running:
            self._say(_("Ctrl-C: no new submission starts; the running ones finish (Ctrl-C again to stop "
                        "them now: they are then left for --resume)."))
            return
        stop_all()
        self._say(_("Stopping: the running submissions are stopped; their rows are not written."))

    @staticmethod
    def _say(text: str) -> None:
        """Write from a signal handler: os.write, since print may be in the middle of a line."""
        try:
            os.write(2, ("\n" + text + "\n").encode("utf-8", "replace"))
        except OSError:
            pass


def grade_one(batch, staged, iso):
    """One task of the pool: check the package, grade, check again, keep the row. After a Ctrl-C
    it starts nothing; a submission stopped by a second one has no row (``--resume`` grades it)."""
    if batch.interrupts.count or not batch.package_unchanged():
        return None
    started = time.monotonic()
    try:
        row = grade_submission(staged, batch.options, iso)
    except Stopped:
        batch.stopped.append(staged.submission)
        return None
    except Exception as exc:                      # never stop the batch
        row = error_row(staged, exc)
    ended = time.monotonic()
    if not batch.package_unchanged():
        batch.discarded.append(staged.submission)
        return None
    try:
        batch.add(row, started, ended)
    except OSError as exc:                        # the disk, not the submission: stop, keep what is written
        batch.cannot_write(row["submission"], exc)
        return None
    return row
