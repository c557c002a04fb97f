"""Nothing a submission started outlives its grading (the Gradescope autograder uses this).

A notebook's kernel can start a process that leaves its process group and its parent (a
double fork, ``setsid``): a *daemon*. Left alive, it could wait until the grader has written
its result and then rewrite it. Two steps close that:

* :func:`become_subreaper` (``prctl(PR_SET_CHILD_SUBREAPER)``): an orphan anywhere below the
  grader is re-parented to the grader, not to the system's first process, so it stays one of
  the grader's descendants whatever it does;
* :func:`end_descendants`: after grading, before the result is written, every descendant is
  killed (``SIGKILL``) and reaped, until none is left.
"""
from __future__ import annotations

import ctypes
import ctypes.util
import os
import signal
import time

__all__ = ["become_subreaper", "descendants", "end_descendants"]

PR_SET_CHILD_SUBREAPER = 36


def become_subreaper() -> bool:
    """Make this process the reaper of its orphaned descendants (Linux); False when refused."""
    try:
        libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6", use_errno=True)
        return libc.prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0) == 0
    except (OSError, AttributeError):
        return False


def _parents() -> dict:
    """{pid: parent pid} of every process /proc shows."""
    out = {}
    for entry in os.scandir("/proc"):
        if entry.name.isdigit():
            try:
                stat = open(f"/proc/{entry.name}/stat", "rb").read()
                # the command's name (in parentheses) may hold spaces: the fields follow its last ')'
                out[int(entry.name)] = int(stat[stat.rindex(b")") + 2:].split()[1])
            except (OSError, ValueError, IndexError):
                pass
    return out


def descendants(pid: int | None = None) -> list:
    """The pids of every living descendant of ``pid`` (default: this process)."""
    pid = os.getpid() if pid is None else pid
    children = {}
    for child, parent in _parents().items():
        children.setdefault(parent, []).append(child)
    found, todo = [], [pid]
    while todo:
        for child in children.get(todo.pop(), []):
            found.append(child)
            todo.append(child)
    return found


def _reap() -> None:
    """Collect the exit status of this process's dead children (zombies hold no power but show in /proc)."""
    while True:
        try:
            pid, _ = os.waitpid(-1, os.WNOHANG)
        except ChildProcessError:
            return
        if pid == 0:
            return


def end_descendants(tries: int = 50) -> list:
    """Kill every descendant of this process and reap them; the pids that were still alive
    (empty when the grader had left nothing running)."""
    killed = []
    for _ in range(tries):
        _reap()
        alive = [pid for pid in descendants() if not _zombie(pid)]
        if not alive:
            return killed
        for pid in alive:
            try:
                os.kill(pid, signal.SIGKILL)
                killed.append(pid)
            except (ProcessLookupError, PermissionError):
                pass
        time.sleep(0.02)
    raise RuntimeError(f"processes {sorted(set(descendants()))} survived SIGKILL")


def _zombie(pid: int) -> bool:
    try:
        stat = open(f"/proc/{pid}/stat", "rb").read()
        return stat[stat.rindex(b")") + 2:][:1] == b"Z"
    except (OSError, ValueError):
        return True                                # gone already
