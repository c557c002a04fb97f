"""Start an IPython kernel inside resource limits (the grader's kernels run this).

The grader's runner starts each student kernel as::

    python .../dhlab/grading/sandbox.py --memory-mb 2048 --cpu-seconds 300 --file-mb 64 --output-mb 10 \\
        -- -f CONNECTION_FILE

Before IPython starts, this process lowers its own limits with
:func:`resource.setrlimit`; the kernel inherits them:

* ``RLIMIT_AS`` (address space): an allocation beyond it fails with ``MemoryError``
  in the student's cell instead of eating the machine's memory;
* ``RLIMIT_CPU``: a backstop that ends a kernel still spinning long after the
  grader stopped waiting for it (the runner's wall-clock limit acts first);
* ``RLIMIT_FSIZE``: a file the notebook writes cannot grow past the limit (the write
  fails with an error; ``SIGXFSZ`` is ignored so the kernel is not killed);
* ``RLIMIT_CORE`` 0: a crash leaves no core file.

Soft and hard limits are set equal, so an ordinary user's code cannot raise them
again.

**Isolation** (``--uid``/``--gid``, when the grader runs as root): before the kernel
starts, this process enters a private network namespace (no network: the kernel talks to
its runner over Unix sockets in its own folder) and a private mount namespace, empties the folders it is told
to hide (``--hide``: the submissions), makes the Python installation and dhlab
reachable even when they sit under a folder other users cannot enter (``/root``),
mounts a ``/proc`` that shows only the kernel user's own processes, caps that user's
number of processes (``RLIMIT_NPROC``), and then becomes the unprivileged user
``--uid`` for good. The kernel then cannot write dhlab, read the other submissions or
the gradebook, or signal the grader; every process it starts belongs to that user, so
the grader can end them all, including those that left the process group.

It also caps what one cell may print (``--output-mb``): beyond it, the kernel drops the
cell's further ``print`` output and says so once (:data:`OUTPUT_LIMIT_NOTE`). Without
that, a cell printing in a loop makes the kernel buffer output faster than it can send
it, until the buffer exhausts the memory limit.
"""
from __future__ import annotations

import argparse
import ctypes
import ctypes.util
import os
import resource
import shutil
import signal
import sys
import tempfile

__all__ = ["apply_limits", "limit_output", "enter_sandbox", "OUTPUT_LIMIT_NOTE", "MAX_PROCESSES", "main"]

MB = 1024 * 1024
OUTPUT_LIMIT_NOTE = "[dhlab grader: output limit reached; the rest of this cell's output is dropped]"
MAX_PROCESSES = 128       # per kernel user (RLIMIT_NPROC): no fork bomb

CLONE_NEWNS = 0x00020000
CLONE_NEWNET = 0x40000000
MS_RDONLY, MS_NOSUID, MS_NODEV, MS_NOEXEC = 1, 2, 4, 8
MS_BIND, MS_REC, MS_PRIVATE = 4096, 16384, 1 << 18
MNT_DETACH = 2


def apply_limits(memory_mb: float | None, cpu_seconds: float | None, file_mb: float | None) -> None:
    """Lower this process's resource limits (None leaves a limit as it is)."""
    def lower(kind, value):
        soft, hard = resource.getrlimit(kind)
        value = int(value)
        if hard != resource.RLIM_INFINITY:
            value = min(value, hard)
        resource.setrlimit(kind, (value, value))

    if memory_mb:
        lower(resource.RLIMIT_AS, memory_mb * MB)
    if cpu_seconds:
        lower(resource.RLIMIT_CPU, cpu_seconds)
    if file_mb:
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        lower(resource.RLIMIT_FSIZE, file_mb * MB)
    lower(resource.RLIMIT_CORE, 0)


def limit_output(max_bytes: int) -> None:
    """Make the kernel's stdout/stderr drop a cell's output beyond ``max_bytes`` characters."""
    from ipykernel import iostream

    write = iostream.OutStream.write
    counts = {}                                   # characters written, for the running cell only

    def limited_write(self, string):
        if not isinstance(string, str):
            return write(self, string)            # ipykernel's own error for a wrong type
        try:
            cell = (self.parent_header or {}).get("msg_id")
        except Exception:
            cell = None
        if cell not in counts:
            counts.clear()
            counts[cell] = 0
        before = counts[cell]
        counts[cell] = before + len(string)
        if before > max_bytes:
            return len(string)
        if counts[cell] > max_bytes:
            write(self, "\n" + OUTPUT_LIMIT_NOTE + "\n")
            return len(string)
        return write(self, string)

    iostream.OutStream.write = limited_write


def _libc():
    libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6", use_errno=True)
    libc.mount.argtypes = [ctypes.c_char_p, ctypes.c_char_p, ctypes.c_char_p, ctypes.c_ulong, ctypes.c_char_p]
    return libc


def _mount(libc, source, target, fstype, flags, data=None):
    enc = (lambda x: None if x is None else str(x).encode())
    if libc.mount(enc(source), enc(target), enc(fstype), flags, enc(data)) != 0:
        err = ctypes.get_errno()
        raise OSError(err, f"mount {fstype or 'bind'} on {target}: {os.strerror(err)}")


def _remove_hold(libc, hold: str, held) -> None:
    """The paths are mounted in their places now: detach the temporary spots and remove their
    folder, so no kernel leaves a folder behind in /tmp (the mounts in place stay)."""
    try:
        for _, spot in held:
            if libc.umount2(spot.encode(), MNT_DETACH) != 0:
                return                            # still mounted: leave the (empty) folder
            os.rmdir(spot)
        os.rmdir(hold)
    except OSError:
        pass                                      # an empty folder left in /tmp is harmless


def _needed_paths() -> list:
    """What the kernel must reach: the Python installation, the environment, dhlab's folder."""
    import importlib.util
    paths = {sys.base_prefix, sys.prefix}
    spec = importlib.util.find_spec("dhlab")
    if spec and spec.submodule_search_locations:
        paths.add(os.path.dirname(os.path.realpath(list(spec.submodule_search_locations)[0])))
    paths = sorted(os.path.realpath(p) for p in paths if os.path.isdir(p))
    outer = [p for p in paths if not any(p != q and p.startswith(q.rstrip("/") + "/") for q in paths)]
    return outer


def _blocked_ancestor(path: str):
    """The first folder on the way to ``path`` that other users cannot enter, or None."""
    current = "/"
    for part in path.strip("/").split("/"):
        if not os.stat(current).st_mode & 0o001:
            return current
        current = os.path.join(current, part)
    return None


def enter_sandbox(uid: int, gid: int, hide=()) -> list:
    """As root: a private mount namespace (see the module doc), then become ``uid``/``gid``.
    Returns what could not be done (empty when everything held); raises OSError when
    the process could not become the unprivileged user."""
    missing = []
    libc = _libc()
    try:
        if libc.unshare(CLONE_NEWNS) != 0:
            raise OSError(ctypes.get_errno(), "unshare(CLONE_NEWNS) refused")
        _mount(libc, None, "/", None, MS_REC | MS_PRIVATE)
        blocked = {}
        for path in _needed_paths():
            ancestor = _blocked_ancestor(path)
            if ancestor:
                blocked.setdefault(ancestor, []).append(path)
        for ancestor, paths in blocked.items():          # e.g. /root (0700) holding pyenv's Python
            hold = tempfile.mkdtemp(prefix="dhlab-hold-")
            held = []
            for i, path in enumerate(paths):
                spot = os.path.join(hold, str(i))
                os.mkdir(spot)
                _mount(libc, path, spot, None, MS_BIND | MS_REC)
                held.append((path, spot))
            _mount(libc, "tmpfs", ancestor, "tmpfs", MS_NOSUID | MS_NODEV, "mode=0755,size=1m")
            old = os.umask(0o022)
            for path, spot in held:
                os.makedirs(path, exist_ok=True)
                _mount(libc, spot, path, None, MS_BIND | MS_REC)
            os.umask(old)
            _remove_hold(libc, hold, held)
        needed = _needed_paths()
        for folder in hide:                                # the other submissions
            folder = os.path.realpath(folder)
            if any(p == folder or p.startswith(folder.rstrip("/") + "/") for p in needed):
                missing.append(f"{folder} holds dhlab or Python itself, so it cannot be hidden")
            elif os.path.isdir(folder):
                _mount(libc, "tmpfs", folder, "tmpfs", MS_NOSUID | MS_NODEV | MS_NOEXEC, "mode=0755,size=64k")
        try:
            _mount(libc, "proc", "/proc", "proc", MS_NOSUID | MS_NODEV | MS_NOEXEC, "hidepid=2")
        except OSError:
            missing.append("/proc shows other users' processes (hidepid not available)")
    except OSError as e:
        missing.append(f"no private mount namespace ({e.strerror or e}): the submissions folder is not hidden")
    if libc.unshare(CLONE_NEWNET) != 0:           # no network: only a loopback that is down
        missing.append(f"the kernels have network access (no network namespace: "
                       f"{os.strerror(ctypes.get_errno())})")
    resource.setrlimit(resource.RLIMIT_NPROC, (MAX_PROCESSES, MAX_PROCESSES))
    os.setgroups([])
    os.setgid(gid)
    os.setuid(uid)
    if os.getuid() != uid or os.geteuid() != uid:
        raise OSError("could not become the sandbox user")
    return missing


def _private_connection_file(rest, workdir, uid, gid) -> list:
    """Copy the kernel's connection file (in the runner's private folder) to the kernel's own."""
    rest = list(rest)
    if "-f" in rest and workdir:
        i = rest.index("-f") + 1
        target = os.path.join(workdir, "kernel-connection.json")
        shutil.copyfile(rest[i], target)
        os.chmod(target, 0o600)
        os.chown(target, uid, gid)
        rest[i] = target
    return rest


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--memory-mb", type=float, default=None)
    parser.add_argument("--cpu-seconds", type=float, default=None)
    parser.add_argument("--file-mb", type=float, default=None)
    parser.add_argument("--output-mb", type=float, default=None)
    parser.add_argument("--uid", type=int, default=None, help="become this user (the grader runs as root)")
    parser.add_argument("--gid", type=int, default=None)
    parser.add_argument("--workdir", default=None, help="the kernel's own folder (owned by --uid)")
    parser.add_argument("--hide", action="append", default=[], help="a folder the kernel must not see")
    parser.add_argument("--probe", action="store_true",
                        help="set up the sandbox, check that dhlab imports and cannot be written, and exit")
    parser.add_argument("kernel_args", nargs=argparse.REMAINDER,
                        help="arguments for ipykernel, after --")
    args = parser.parse_args(argv)
    rest = args.kernel_args[1:] if args.kernel_args[:1] == ["--"] else args.kernel_args
    if args.uid is not None:
        rest = _private_connection_file(rest, args.workdir, args.uid, args.gid)
        missing = enter_sandbox(args.uid, args.gid, args.hide)
        if args.probe:
            _probe(missing, args.hide)
            return
    apply_limits(args.memory_mb, args.cpu_seconds, args.file_mb)
    if args.output_mb:
        limit_output(int(args.output_mb * 1e6))
    # started as a script, this folder is sys.path[0]; a kernel started with -m has '' (its cwd)
    here = os.path.dirname(os.path.abspath(__file__))
    sys.path[:] = [""] + [p for p in sys.path if p and os.path.abspath(p) != here]
    from ipykernel import kernelapp
    sys.argv = [sys.argv[0], *rest]
    kernelapp.launch_new_instance()


def _probe(missing, hide) -> None:
    """Exit 0 when the sandbox user can run the kernel and cannot write dhlab; say what is missing."""
    import importlib.util
    spec = importlib.util.find_spec("dhlab")
    import ipykernel  # noqa: F401  (the kernel must import)
    folder = os.path.dirname(spec.origin)
    if os.access(folder, os.W_OK) or os.access(spec.origin, os.W_OK):
        sys.exit(f"the sandbox user can write dhlab's files in {folder}")
    for folder in hide:
        if os.path.isdir(folder) and os.listdir(folder):
            missing.append(f"the sandbox user can see {folder}")
    print("\n".join(missing))


if __name__ == "__main__":
    main()
