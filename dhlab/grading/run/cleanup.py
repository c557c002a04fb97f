"""``dhlab-grade --clean``: remove what a killed grader left behind.

A grader ended with ``SIGKILL`` (the machine's out-of-memory killer, ``kill -9``, a closed
cloud shell) cannot tidy up: its private copies of the submissions
(``dhlab-grade-copies-*``), its kernels' folders (``dhlab-grade-kernels-*``), its runners'
folders (``dhlab-grade-run-*``, ``dhlab-runner-*``), its runners and kernels still running from
those folders and, as root, every process of its users ``dhlab-grade-K`` and the submissions'
control groups (``dhlab-grade/sub-*``). (A kernel's private ``/tmp`` and ``/dev/shm`` vanish with
it: nothing of them is left to clean.)
``--resume`` grades the missing rows again but leaves those; ``--clean`` removes them.

It never touches a grader that is still running: every grader holds a shared lock on
``dhlab-grade.lock`` in each temporary folder it uses (:func:`hold`); ``--clean`` takes it
exclusively first, and when it cannot, says so and removes nothing there.
"""
from __future__ import annotations

import fcntl
import os
import pwd
import shutil
import signal
import sys
import tempfile
from pathlib import Path

from .cgroups import remove_leftovers
from .isolation import MAX_USERS, USER_PREFIX, claim, kernels_parent, kill_user, pids_of
from .sandbox import unmount_below

__all__ = ["hold", "clean", "main", "LEFTOVERS", "LOCK_NAME"]

LEFTOVERS = ("dhlab-grade-copies-", "dhlab-grade-kernels-", "dhlab-grade-run-", "dhlab-runner-", "dhlab-hold-")
LOCK_NAME = "dhlab-grade.lock"


def _folders() -> list:
    """The temporary folders a grader uses: ``TMPDIR`` and where the kernels' folders go."""
    out = []
    for folder in (Path(tempfile.gettempdir()), kernels_parent() if os.geteuid() == 0 else None):
        if folder is not None and folder.is_dir() and folder.resolve() not in [f.resolve() for f in out]:
            out.append(folder)
    return out


def _lock(folder: Path, how: int):
    """An open descriptor holding ``how`` (LOCK_SH / LOCK_EX) on the folder's lock, or None when
    another process holds it the other way (or the folder cannot hold a lock)."""
    try:
        fd = os.open(folder / LOCK_NAME, os.O_RDWR | os.O_CREAT | os.O_CLOEXEC | os.O_NOFOLLOW, 0o644)
    except OSError:
        return None
    try:
        fcntl.flock(fd, how | fcntl.LOCK_NB)
    except OSError:
        os.close(fd)
        return None
    return fd


def hold() -> list:
    """The running grader's shared locks (kept open until it ends: the kernel drops them even
    after SIGKILL), so that ``--clean`` leaves this grader's folders alone."""
    return [fd for fd in (_lock(folder, fcntl.LOCK_SH) for folder in _folders()) if fd is not None]


def _leftovers(folder: Path) -> list:
    mine = os.geteuid()
    return sorted(p for p in folder.iterdir()
                  if p.name.startswith(LEFTOVERS) and p.is_dir() and not p.is_symlink()
                  and (mine == 0 or p.lstat().st_uid == mine))


def _end_kernels() -> list:
    """As root: end the processes of grading users no running grader holds (their grader was killed)."""
    ended = []
    for k in range(1, MAX_USERS + 1):
        try:
            entry = pwd.getpwnam(f"{USER_PREFIX}{k}")
        except KeyError:
            continue
        fd = claim(entry.pw_name)
        if fd is None:
            continue                                     # a running grader holds it
        try:
            if pids_of(entry.pw_uid):
                kill_user(entry.pw_uid)
                ended.append(entry.pw_name)
        finally:
            os.close(fd)
    return ended


def _end_processes(folders) -> int:
    """End the processes still running from the leftover ``folders`` (a killed grader's runners and
    kernels: their command lines name their copy, their result file or their kernel's folder)."""
    marks = [str(f).encode() for f in folders]
    ended = 0
    for entry in os.scandir("/proc"):
        if not entry.name.isdigit() or int(entry.name) == os.getpid():
            continue
        try:
            cmdline = Path(entry.path, "cmdline").read_bytes()
        except OSError:
            continue
        if any(mark in cmdline for mark in marks):
            try:
                os.kill(int(entry.name), signal.SIGKILL)
                ended += 1
            except OSError:
                pass
    return ended


def clean() -> tuple:
    """Remove the leftovers of killed graders: (removed folders, busy folders skipped, users whose
    processes were ended)."""
    removed, busy = [], []
    for folder in _folders():
        fd = _lock(folder, fcntl.LOCK_EX)
        if fd is None:
            busy.append(folder)
            continue
        try:
            _end_processes(_leftovers(folder))
            for path in _leftovers(folder):
                if os.geteuid() == 0:             # a kernel's folder is a tmpfs while it runs
                    unmount_below(str(path))
                shutil.rmtree(path, ignore_errors=True)
                if not path.exists():
                    removed.append(path)
        finally:
            os.close(fd)
    ended = _end_kernels() if os.geteuid() == 0 and not busy else []
    if os.geteuid() == 0 and not busy:            # the control groups of killed runners (dhlab.grading.run.cgroups)
        removed += [Path(folder) for folder in remove_leftovers()]
    return removed, busy, ended


def main() -> int:
    """``dhlab-grade --clean`` (see the module); 0 when done, 1 when a running grader kept a folder busy."""
    removed, busy, ended = clean()
    for path in removed:
        print(f"removed {path}", file=sys.stderr)
    if ended:
        print(f"ended the processes of {', '.join(ended)} (left by a killed grader)", file=sys.stderr)
    for folder in busy:
        print(f"{folder}: a grader is running there now; nothing of it was removed (run --clean when it ends)",
              file=sys.stderr)
    print(f"dhlab-grade --clean: {len(removed)} folder{'s' if len(removed) != 1 else ''} removed.", file=sys.stderr)
    return 1 if busy else 0
