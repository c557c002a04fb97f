"""Start an IPython kernel inside resource limits (the grader's kernels run this).

The grader's runner starts each student kernel as::

    python .../dhlab/grading/run/sandbox.py --memory-mb 2048 --cpu-seconds 300 --file-mb 64 --output-mb 10 \\
        -- -f CONNECTION_FILE

Before IPython starts, this process lowers its own limits with
:func:`resource.setrlimit`; the kernel inherits them:

* ``RLIMIT_AS`` (address space; with a control group only a backstop at 4 × ``--memory-mb``):
  an allocation beyond it fails with ``MemoryError``
  in the student's cell instead of eating the machine's memory;
* ``RLIMIT_CPU``: a backstop that ends a kernel still spinning long after the
  grader stopped waiting for it (the runner's wall-clock limit acts first);
* ``RLIMIT_FSIZE``: a file the notebook writes cannot grow past the limit (the write
  fails with an error; ``SIGXFSZ`` is ignored so the kernel is not killed);
* ``RLIMIT_CORE`` 0: a crash leaves no core file.

Soft and hard limits are set equal, so an ordinary user's code cannot raise them
again.

**Isolation** (``--uid``/``--gid``, when the grader runs as root): before the kernel
starts, this process joins the submission's control group (``--group``, made by the runner:
:mod:`dhlab.grading.run.cgroups`: memory and processes limited for the whole submission, children
included), enters private mount, IPC and network namespaces and **a root of its own**
(:func:`enter_sandbox`): a new tmpfs holding only the system's programs and libraries, a few files of ``/etc``,
the Python installation and dhlab's own folder — all read-only — the kernel's own folder
(writable), a private ``/tmp`` and ``/dev/shm`` of ``--tmp-mb`` each (they vanish with the
kernel), a few devices and a ``/proc`` that shows only the kernel user's processes. Then it
becomes the unprivileged user ``--uid`` for good. So the kernel cannot see the submissions, the
release and its secret, the gradebook, the teacher's home or any socket at a file path,
wherever the teacher keeps them — what is not bound in does not exist for it, and a course
installed in a folder other users cannot enter (``/root``, a ``mktemp -d`` folder) is reachable
all the same. It has no network, cannot write dhlab or signal the grader, and every process it
starts belongs to that user and that control group, so the grader can end them all.

It also caps what one cell may print (``--output-mb``): beyond it, the kernel drops the
cell's further ``print`` output and says so once (:data:`OUTPUT_LIMIT_NOTE`). Without
that, a cell printing in a loop makes the kernel buffer output faster than it can send
it, until the buffer exhausts the memory limit.
"""
from __future__ import annotations

import argparse
import contextlib
import ctypes
import ctypes.util
import glob
import importlib.util
import os
import resource
import secrets
import signal
import sys
import tempfile

__all__ = ["apply_limits", "limit_output", "enter_sandbox", "OUTPUT_LIMIT_NOTE", "MAX_PROCESSES", "main"]

MB = 1024 * 1024
OUTPUT_LIMIT_NOTE = "[dhlab grader: output limit reached; the rest of this cell's output is dropped]"
MAX_PROCESSES = 128       # per kernel user (RLIMIT_NPROC): no fork bomb

CLONE_NEWNS = 0x00020000
CLONE_NEWIPC = 0x08000000
CLONE_NEWNET = 0x40000000
MS_RDONLY, MS_NOSUID, MS_NODEV, MS_NOEXEC = 1, 2, 4, 8
MS_REMOUNT, MS_BIND, MS_REC, MS_PRIVATE = 32, 4096, 16384, 1 << 18
MNT_DETACH = 2
PIVOT_ROOT = {"x86_64": 155, "aarch64": 41, "riscv64": 41, "ppc64le": 203, "s390x": 217, "i686": 217}  # syscall numbers
# what every kernel reads, bound read-only into its private root (links such as /bin -> usr/bin copied)
SYSTEM_PATHS = ("/usr", "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32")
# of /etc only what programs, the dynamic linker, Python and matplotlib read: not the whole of it
# (a token in /etc/environment, a password in a service's configuration stays out of sight)
ETC_NAMES = ("passwd", "group", "nsswitch.conf", "ld.so.cache", "ld.so.conf", "ld.so.conf.d", "localtime",
             "timezone", "alternatives", "fonts", "mime.types", "hosts", "host.conf", "os-release",
             "matplotlibrc", "locale.alias", "locale.conf", "default/locale", "python3*", "ipython", "jupyter")
DEVICES = ("/dev/null", "/dev/zero", "/dev/full", "/dev/random", "/dev/urandom")


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
    # lazy: this runs in the kernel's launcher after the limits are lowered; the runner and the
    # grader import this module for its limits and names, and never need ipykernel
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
    _keep_no_output_history()


def _keep_no_output_history() -> None:
    """IPython 9 keeps every string a cell prints in memory (``history_manager.outputs``, through
    ``InteractiveShell._tee``), even past our cap: a cell printing in a loop would fill the memory
    limit with output nobody reads. The grader needs no output history, so none is kept."""
    try:
        from IPython.core.interactiveshell import InteractiveShell  # lazy: as ipykernel above
    except ImportError:
        return
    if hasattr(InteractiveShell, "_tee"):
        @contextlib.contextmanager
        def no_tee(self, channel):
            yield
        InteractiveShell._tee = no_tee


def _libc():
    libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6", use_errno=True)
    libc.mount.argtypes = [ctypes.c_char_p, ctypes.c_char_p, ctypes.c_char_p, ctypes.c_ulong, ctypes.c_char_p]
    return libc


def _mount(libc, source, target, fstype, flags, data=None):
    enc = (lambda x: None if x is None else str(x).encode())
    if libc.mount(enc(source), enc(target), enc(fstype), flags, enc(data)) != 0:
        err = ctypes.get_errno()
        raise OSError(err, f"mount {fstype or 'bind'} on {target}: {os.strerror(err)}")


def mount_tmpfs(target: str, size_mb: float, uid: int, gid: int) -> None:
    """Mount a tmpfs of ``size_mb`` on ``target``, owned by ``uid``/``gid`` (mode 0700): a kernel's
    own folder with a size (what it writes is memory of its control group, and goes with it)."""
    _mount(_libc(), "tmpfs", target, "tmpfs", MS_NOSUID | MS_NODEV,
           f"size={max(1, int(size_mb))}m,mode=0700,uid={int(uid)},gid={int(gid)}")


def unmount(target: str) -> bool:
    """Detach whatever is mounted on ``target`` (lazily: busy files go when closed); False if nothing was."""
    return _libc().umount2(os.fsencode(target), MNT_DETACH) == 0


def unmount_below(folder: str) -> int:
    """Detach every mount at or below ``folder`` (the kernels' folders a killed grader left mounted);
    how many were."""
    folder = os.path.realpath(folder).rstrip("/")
    try:
        with open("/proc/self/mounts", encoding="utf-8", errors="replace") as f:
            points = [line.split()[1].replace("\\040", " ") for line in f if len(line.split()) > 1]
    except OSError:
        return 0
    below = [p for p in points if p == folder or p.startswith(folder + "/")]
    return sum(unmount(p) for p in sorted(below, key=len, reverse=True))


def _covered(path: str, by) -> bool:
    return any(path == q or path.startswith(q.rstrip("/") + "/") for q in by)


def _needed_paths() -> list:
    """What the kernel must read beyond the system: the Python installation, the environment
    (a virtual environment's folder) and dhlab's own folder — never the folder around it (an
    editable install's checkout holds the notebooks and tests, a teacher's may hold more)."""
    # a base installation's programs and libraries, not its whole folder (a conda base holds every
    # environment, its package cache and .condarc); a virtual environment is the course's own: whole
    paths = {os.path.join(prefix, sub) for prefix in {sys.base_prefix, sys.base_exec_prefix}
             for sub in ("bin", "lib", "lib64", "share")}
    paths |= {sys.prefix, sys.exec_prefix} - {sys.base_prefix, sys.base_exec_prefix}
    paths.add(os.path.dirname(os.path.realpath(sys.executable)))
    # the packages' folders on the path, also those a .pth file reaches (a virtual environment
    # built on another one's packages) — never a plain folder on the path (the current folder)
    paths |= {p for p in sys.path if os.path.basename(p.rstrip("/")) in ("site-packages", "dist-packages")}
    spec = importlib.util.find_spec("dhlab")
    if spec and spec.submodule_search_locations:
        paths.add(os.path.realpath(list(spec.submodule_search_locations)[0]))
    paths = sorted(os.path.realpath(p) for p in paths if p and os.path.isdir(p))
    return [p for p in paths if not _covered(p, [q for q in paths if q != p])]


def _mount_flags(path: str) -> int:
    """The flags of the mount ``path`` is on (nosuid, nodev, noexec, …), kept when it is made read-only."""
    keep = 0
    flag = os.statvfs(path).f_flag
    for st, ms in ((os.ST_NOSUID, MS_NOSUID), (os.ST_NODEV, MS_NODEV), (os.ST_NOEXEC, MS_NOEXEC),
                   (getattr(os, "ST_NOATIME", 1024), 1024), (getattr(os, "ST_NODIRATIME", 2048), 2048),
                   (getattr(os, "ST_RELATIME", 4096), 1 << 21)):
        if flag & st:
            keep |= ms
    return keep


def _place(root: str, path: str, like: str) -> str:
    """Make ``path`` inside ``root`` (folders on the way 0755, so the kernel's user can pass) for a
    bind of ``like``: a folder or an empty file. Returns the target."""
    target = os.path.join(root, path.lstrip("/"))
    old = os.umask(0o022)
    try:
        if os.path.isdir(like):
            os.makedirs(target, exist_ok=True)
        else:
            os.makedirs(os.path.dirname(target), exist_ok=True)
            if not os.path.exists(target):
                open(target, "a").close()
    finally:
        os.umask(old)
    return target


def _bind(libc, root: str, path: str, writable: bool = False) -> None:
    """Bind ``path`` at the same place inside ``root``; read-only unless ``writable``. A symbolic
    link (``/bin`` -> ``usr/bin`` on merged-/usr systems, ``/etc/os-release``) is copied as a link."""
    if os.path.islink(path):
        link = os.path.join(root, path.lstrip("/"))
        if not os.path.lexists(link):
            os.makedirs(os.path.dirname(link), mode=0o755, exist_ok=True)
            os.symlink(os.readlink(path), link)
        return
    target = _place(root, path, path)
    _mount(libc, path, target, None, MS_BIND | MS_REC)
    if not writable:
        _mount(libc, None, target, None, MS_BIND | MS_REMOUNT | MS_RDONLY | _mount_flags(path))


def root_folder(workdir: str | None) -> str:
    """Where the private root is mounted (in the kernel's mount namespace only): an empty folder
    beside the kernel's own, ``<workdir>.root``, which the grader removes with it."""
    return os.path.realpath(workdir).rstrip("/") + ".root" if workdir else tempfile.mkdtemp(prefix="dhlab-root-")


def _private_root(libc, workdir: str, tmp_mb: float) -> str:
    """Build the kernel's whole file system in a new tmpfs and return its folder: the system's
    programs and libraries, a few files of /etc, Python and dhlab read-only; the kernel's own folder
    writable; a private /tmp and /dev/shm of ``tmp_mb`` MB each; a few devices; a /proc that
    shows only the kernel user's processes. Nothing else exists in it: not the submissions,
    the release, the secret, the gradebook, the teacher's home, nor sockets at file paths."""
    root = root_folder(workdir)
    os.makedirs(root, mode=0o700, exist_ok=True)       # beside the kernel's folder, removed with it
    _mount(libc, "tmpfs", root, "tmpfs", MS_NOSUID | MS_NODEV, "mode=0755,size=4m")
    for name in ("tmp", "dev/shm"):
        folder = _place(root, "/" + name, "/")
        _mount(libc, "tmpfs", folder, "tmpfs", MS_NOSUID | MS_NODEV,
               f"mode=1777,size={max(1, int(tmp_mb))}m")
    bound = []
    etc = sorted({p for name in ETC_NAMES for p in glob.glob(os.path.join("/etc", name))})
    for path in [*SYSTEM_PATHS, *etc, *_needed_paths()]:
        if os.path.islink(path):
            _bind(libc, root, path)                      # /bin -> usr/bin: the link itself
        elif os.path.exists(path) and not _covered(os.path.realpath(path), bound):
            _bind(libc, root, os.path.realpath(path))
            bound.append(os.path.realpath(path))
    for device in DEVICES:
        if os.path.exists(device):
            _bind(libc, root, device, writable=True)
    for name, target in (("fd", "/proc/self/fd"), ("stdin", "/proc/self/fd/0"), ("stdout", "/proc/self/fd/1"),
                         ("stderr", "/proc/self/fd/2")):
        os.symlink(target, os.path.join(root, "dev", name))
    if workdir:
        _bind(libc, root, os.path.realpath(workdir), writable=True)
    proc = _place(root, "/proc", "/")
    _mount(libc, "proc", proc, "proc", MS_NOSUID | MS_NODEV | MS_NOEXEC, "hidepid=2")
    return root


def _pivot(libc, root: str) -> None:
    """Make ``root`` this process's ``/`` and drop the old one (pivot_root(".", "."), then detach)."""
    os.chdir(root)
    number = PIVOT_ROOT.get(os.uname().machine)
    if number is None or libc.syscall(number, b".", b".") != 0:
        err = ctypes.get_errno()
        raise OSError(err, f"pivot_root: {os.strerror(err)}")
    if libc.umount2(b".", MNT_DETACH) != 0:
        err = ctypes.get_errno()
        raise OSError(err, f"detaching the old root: {os.strerror(err)}")
    os.chdir("/")


def join_group(folders) -> None:
    """Enter the submission's control group(s) (:mod:`dhlab.grading.run.cgroups`): its memory and
    process limits then hold for this kernel and every process it starts, together."""
    for folder in folders:
        with open(os.path.join(folder, "cgroup.procs"), "w", encoding="ascii") as f:
            f.write(str(os.getpid()))


def enter_sandbox(uid: int, gid: int, workdir: str | None = None, tmp_mb: float = 64, groups=(),
                  report: str | None = None) -> list:
    """As root: join the submission's control groups, enter private mount, IPC and network
    namespaces with a private root (:func:`_private_root`), then become ``uid``/``gid`` for good.
    Returns what could not be done (empty when everything held); raises OSError when the
    process could not become the unprivileged user."""
    missing = []
    libc = _libc()
    try:
        join_group(groups)
    except OSError as e:
        missing.append(f"the submission's control group could not be joined ({e.strerror or e})")
    try:
        if libc.unshare(CLONE_NEWNS | CLONE_NEWIPC) != 0:
            raise OSError(ctypes.get_errno(), "unshare(CLONE_NEWNS) refused")
        _mount(libc, None, "/", None, MS_REC | MS_PRIVATE)
        _pivot(libc, _private_root(libc, workdir, tmp_mb))
        os.chdir(os.path.realpath(workdir) if workdir else "/")      # the kernel starts in its own folder
    except OSError as e:
        missing.append(f"no private root ({e.strerror or e}): a kernel can read every file its user may read")
    if libc.unshare(CLONE_NEWNET) != 0:           # no network: only a loopback that is down
        missing.append(f"the kernels have network access (no network namespace: "
                       f"{os.strerror(ctypes.get_errno())})")
    if report:                                    # for the runner: what held (written as root, before any student code)
        try:
            write_new(report, "\n".join(missing).encode("utf-8"))
        except OSError:
            pass                                  # something is in its place: the runner reads nothing
    resource.setrlimit(resource.RLIMIT_NPROC, (MAX_PROCESSES, MAX_PROCESSES))
    os.setgroups([])
    os.setgid(gid)
    os.setuid(uid)
    if os.getuid() != uid or os.geteuid() != uid:
        raise OSError("could not become the sandbox user")
    return missing


def write_new(path: str, data: bytes, uid: int | None = None, gid: int | None = None) -> None:
    """Create ``path`` and write ``data``, never through a link or over a file that is already
    there. Root writes into folders a student's process owns (the kernel's own folder): a link
    planted there by a process of an earlier kernel must not make root write or chown another file."""
    fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW | os.O_CLOEXEC, 0o600)
    try:
        if uid is not None:
            os.fchown(fd, uid, gid)
        os.write(fd, data)
    finally:
        os.close(fd)


def _private_connection_file(rest, workdir, uid, gid) -> list:
    """Copy the kernel's connection file (in the runner's private folder) to the kernel's own,
    under a new name each time (see :func:`write_new`)."""
    rest = list(rest)
    if "-f" in rest and workdir:
        i = rest.index("-f") + 1
        with open(rest[i], "rb") as f:
            data = f.read()
        target = os.path.join(workdir, f"kernel-connection-{secrets.token_hex(8)}.json")
        write_new(target, data, uid, gid)
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
    parser.add_argument("--tmp-mb", type=float, default=64, help="size of the private /tmp and /dev/shm, MB each")
    parser.add_argument("--group", action="append", default=[],
                        help="a control group folder to join (the submission's, dhlab.grading.run.cgroups)")
    parser.add_argument("--report", default=None, help="where to write what did not hold (one line each)")
    parser.add_argument("--probe", action="store_true",
                        help="set up the sandbox, check that dhlab imports and cannot be written, and exit")
    parser.add_argument("kernel_args", nargs=argparse.REMAINDER,
                        help="arguments for ipykernel, after --")
    args = parser.parse_args(argv)
    rest = args.kernel_args[1:] if args.kernel_args[:1] == ["--"] else args.kernel_args
    address_space = args.memory_mb
    if args.uid is not None:
        rest = _private_connection_file(rest, args.workdir, args.uid, args.gid)
        missing = enter_sandbox(args.uid, args.gid, args.workdir, args.tmp_mb, args.group, args.report)
        if args.probe:
            _probe(missing)
            return
        if args.group and args.memory_mb and not any("control group" in m for m in missing):
            # the group holds the whole submission to --memory-mb; the address space, which counts
            # reserved but unused memory (numpy's and BLAS's arenas), is only a backstop that turns
            # an absurd allocation into a MemoryError in the cell instead of an OOM kill
            address_space = max(4 * args.memory_mb, args.memory_mb + 4096)
    apply_limits(address_space, args.cpu_seconds, args.file_mb)
    if args.output_mb:
        limit_output(int(args.output_mb * 1e6))
    # started as a script, this folder is sys.path[0]; a kernel started with -m has '' (its cwd)
    here = os.path.dirname(os.path.abspath(__file__))
    sys.path[:] = [""] + [p for p in sys.path if p and os.path.abspath(p) != here]
    from ipykernel import kernelapp  # lazy: only now, under the limits and with this folder off sys.path
    sys.argv = [sys.argv[0], *rest]
    kernelapp.launch_new_instance()


def _probe(missing) -> None:
    """Exit 0 when the sandbox user can run the kernel and cannot write dhlab; say what is missing."""
    spec = importlib.util.find_spec("dhlab")
    if spec is None:
        sys.exit(f"dhlab does not import in the sandbox (Python {sys.executable}, path {sys.path})")
    import ipykernel  # noqa: F401  (the kernel must import)
    folder = os.path.dirname(spec.origin)
    if os.access(folder, os.W_OK) or os.access(spec.origin, os.W_OK):
        sys.exit(f"the sandbox user can write dhlab's files in {folder}")
    print("\n".join(missing))


if __name__ == "__main__":
    main()
