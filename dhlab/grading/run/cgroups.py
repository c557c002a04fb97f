"""One control group per submission: its memory and its number of processes are limited together.

A resource limit of a process (``setrlimit``) holds for that process alone: ten forked
children of 500 MB each stay inside a 2 GB address-space limit each, and reach 6 GB together.
The kernel's control groups (cgroups) limit a *group* of processes, children included, so
the grader puts each submission's kernel — and everything it starts — into a group of its own
(:class:`SubmissionGroup`), created by the runner (root) before the kernel starts and removed
after the submission:

* memory (``memory.max`` in cgroup v2, ``memory.limit_in_bytes`` in v1, swap forbidden):
  the limit the teacher chose with ``--memory-mb``, for the whole submission; files it writes
  to its private ``/tmp`` and ``/dev/shm`` (tmpfs) count too. A group that runs out has its
  largest process killed by the kernel's OOM killer; :meth:`SubmissionGroup.oom_kills` counts
  those kills, so the grader can say "the memory limit was reached" instead of scoring a dead
  kernel as a student's fault;
* processes (``pids.max``): no fork bomb, however many users or sessions it uses.

Both cgroup versions are handled: v2 (the unified hierarchy of current distributions) and
v1 (separate ``memory`` and ``pids`` hierarchies, as on older hosts and some containers). The
groups are made under the grader's own group, so the limits of the container or service the
grader runs in still apply above them. Where no group can be made (not root, no cgroup
file system, no delegation) :func:`create` returns None and the grader falls back to the
per-process limits of :mod:`dhlab.grading.run.sandbox`; the gradebook says which held.

Plain standard library only: :mod:`dhlab.grading.run.runner` imports this file as a script.
"""
from __future__ import annotations

import os
import signal
import time

__all__ = ["SubmissionGroup", "create", "version", "leftovers", "remove_leftovers", "GROUP_PARENT", "CGROUP_ROOT"]

CGROUP_ROOT = "/sys/fs/cgroup"
GROUP_PARENT = "dhlab-grade"                 # our groups: <own group>/dhlab-grade/<name>
MB = 1024 * 1024


def version() -> str:
    """'v2' (unified hierarchy with the memory and pids controllers), 'v1', or '' (none usable)."""
    controllers = _read(os.path.join(CGROUP_ROOT, "cgroup.controllers"))
    if controllers is not None and {"memory", "pids"} <= set(controllers.split()):
        return "v2"
    if os.path.isdir(os.path.join(CGROUP_ROOT, "memory")) and os.path.isdir(os.path.join(CGROUP_ROOT, "pids")):
        return "v1"
    return ""


def _read(path: str):
    try:
        with open(path, encoding="ascii") as f:
            return f.read()
    except (OSError, UnicodeDecodeError):
        return None


def _write(path: str, value) -> None:
    with open(path, "w", encoding="ascii") as f:
        f.write(str(value))


def _own_group(controller: str) -> str:
    """This process's group in ``controller``'s hierarchy ('' for v2), as /proc/self/cgroup says."""
    for line in (_read("/proc/self/cgroup") or "").splitlines():
        number, names, path = (line.split(":", 2) + ["", ""])[:3]
        if controller in names.split(",") or (controller == "" and number == "0"):
            return path.strip()
    return "/"


def _parent_dir(mount: str, controller: str) -> str:
    """Where our groups go: under the grader's own group when it is visible, else the mount's root."""
    own = os.path.join(mount, _own_group(controller).lstrip("/"))
    return os.path.join(own if os.path.isdir(own) else mount, GROUP_PARENT)


class SubmissionGroup:
    """The control group(s) of one submission: join, count OOM kills, end every process, remove."""

    def __init__(self, kind: str, dirs: list, memory_mb: float, max_pids: int):
        self.kind, self.dirs, self.memory_mb, self.max_pids = kind, dirs, memory_mb, max_pids

    def describe(self) -> str:
        """E.g. 'cgroup v1: 2048 MB, 128 processes' (for the whole submission)."""
        return f"cgroup {self.kind}: {self.memory_mb:.0f} MB, {self.max_pids} processes"

    def join(self, pid: int | None = None) -> None:
        """Move ``pid`` (default: this process) into every directory of the group."""
        for folder in self.dirs:
            _write(os.path.join(folder, "cgroup.procs"), pid or os.getpid())

    def pids(self) -> list:
        out = set()
        for folder in self.dirs:
            for line in (_read(os.path.join(folder, "cgroup.procs")) or "").split():
                if line.isdigit():
                    out.add(int(line))
        return sorted(out)

    def oom_kills(self) -> int:
        """How many processes of the group the OOM killer ended (the memory limit was reached)."""
        memory = self.dirs[0]
        name = "memory.events" if self.kind == "v2" else "memory.oom_control"
        for line in (_read(os.path.join(memory, name)) or "").splitlines():
            key, _, value = line.partition(" ")
            if key == "oom_kill" and value.strip().isdigit():
                return int(value)
        if self.kind == "v1":            # kernels before 4.13 have no oom_kill count: the limit was hit
            failcnt = (_read(os.path.join(memory, "memory.memsw.failcnt"))
                       or _read(os.path.join(memory, "memory.failcnt")))
            return 1 if failcnt and failcnt.strip() not in ("", "0") else 0
        return 0

    def kill_all(self, tries: int = 50) -> bool:
        """SIGKILL every process in the group until none is left (a fork in between is caught next round)."""
        kill_file = os.path.join(self.dirs[0], "cgroup.kill")
        for _ in range(tries):
            pids = self.pids()
            if not pids:
                return True
            if self.kind == "v2" and os.path.exists(kill_file):
                try:
                    _write(kill_file, 1)
                except OSError:
                    pass
            for pid in pids:
                try:
                    os.kill(pid, signal.SIGKILL)
                except (ProcessLookupError, PermissionError):
                    pass
            time.sleep(0.02)
        return not self.pids()

    def remove(self) -> None:
        """End the group's processes and remove its directories (an empty group can be removed)."""
        self.kill_all()
        for folder in self.dirs:
            for _ in range(250):
                try:
                    os.rmdir(folder)
                    break
                except FileNotFoundError:
                    break
                except OSError:
                    time.sleep(0.02)      # a killed process stays in its group until it is reaped


def _make(folder: str) -> None:
    os.makedirs(folder, mode=0o755, exist_ok=False)


def _create_v2(name: str, memory_mb: float, max_pids: int) -> SubmissionGroup:
    parent = _parent_dir(CGROUP_ROOT, "")
    if not os.path.isdir(parent):
        os.makedirs(parent, mode=0o755, exist_ok=True)
        _write(os.path.join(os.path.dirname(parent), "cgroup.subtree_control"), "+memory +pids")
    _write(os.path.join(parent, "cgroup.subtree_control"), "+memory +pids")
    folder = os.path.join(parent, name)
    _make(folder)
    group = SubmissionGroup("v2", [folder], memory_mb, max_pids)
    try:
        _write(os.path.join(folder, "memory.max"), int(memory_mb * MB))
        if os.path.exists(os.path.join(folder, "memory.swap.max")):
            _write(os.path.join(folder, "memory.swap.max"), 0)
        _write(os.path.join(folder, "pids.max"), max_pids)
    except OSError:
        group.remove()
        raise
    return group


def _create_v1(name: str, memory_mb: float, max_pids: int) -> SubmissionGroup:
    memory = os.path.join(_parent_dir(os.path.join(CGROUP_ROOT, "memory"), "memory"), name)
    pids = os.path.join(_parent_dir(os.path.join(CGROUP_ROOT, "pids"), "pids"), name)
    for folder in (memory, pids):
        os.makedirs(os.path.dirname(folder), mode=0o755, exist_ok=True)
    _make(memory)
    group = SubmissionGroup("v1", [memory], memory_mb, max_pids)
    try:
        _make(pids)
        group.dirs.append(pids)
        _write(os.path.join(memory, "memory.limit_in_bytes"), int(memory_mb * MB))
        if os.path.exists(os.path.join(memory, "memory.memsw.limit_in_bytes")):   # no swap either
            _write(os.path.join(memory, "memory.memsw.limit_in_bytes"), int(memory_mb * MB))
        _write(os.path.join(pids, "pids.max"), max_pids)
    except OSError:
        group.remove()
        raise
    return group


def create(name: str, memory_mb: float, max_pids: int):
    """A new :class:`SubmissionGroup` called ``name`` with these limits, or None when this machine
    (or this user) cannot make one — the reason is then in :data:`last_refusal`."""
    global last_refusal
    kind = version()
    if os.geteuid() != 0 or not kind:
        last_refusal = "not root" if os.geteuid() != 0 else "no cgroup file system with the memory and pids controllers"
        return None
    try:
        return (_create_v2 if kind == "v2" else _create_v1)(name, memory_mb, max_pids)
    except OSError as e:
        last_refusal = f"cgroup {kind} refused ({e.strerror or e})"
        return None


def _parents() -> list:
    """The folders our groups are made in, one per hierarchy we use."""
    mounts = {"v2": [(CGROUP_ROOT, "")], "v1": [(os.path.join(CGROUP_ROOT, c), c) for c in ("memory", "pids")]}
    return [_parent_dir(mount, controller) for mount, controller in mounts.get(version(), [])]


def leftovers(name: str = "") -> list:
    """The submission groups a killed grader or runner left: those called ``name``, or every
    ``dhlab-grade/sub-*`` when no name is given."""
    found = []
    for parent in _parents():
        try:
            found += [os.path.join(parent, n) for n in sorted(os.listdir(parent))
                      if (n == name if name else n.startswith("sub-"))]
        except OSError:
            pass
    return found


def remove_leftovers(name: str = "") -> list:
    """End the processes of the groups a killed grader (or runner) left and remove the groups:
    ``name`` after each submission, all of them for ``dhlab-grade --clean`` (when no grader runs);
    the folders removed."""
    removed = []
    for folder in leftovers(name):
        group = SubmissionGroup(version(), [folder], 0, 0)
        group.remove()
        if not os.path.exists(folder):
            removed.append(folder)
    return removed


last_refusal = ""
