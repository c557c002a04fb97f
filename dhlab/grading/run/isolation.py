"""Each submission runs alone: its own user, its own folder, and nothing left behind.

The grader (:mod:`dhlab.grading.cli`) decides once per batch how far it can isolate
the submissions (:func:`setup`):

* **as root** (the usual way to grade untrusted work): one unprivileged user per
  parallel job, ``dhlab-grade-1`` … ``dhlab-grade-N``, created on demand (``useradd``;
  ``nobody`` when users cannot be created, then one job at a time). A grader holds a
  lock on each of its users (:func:`claim`) until it ends, so two graders running at
  once (two classes, two terminals) never share a user, and neither kills the
  other's kernels. Each kernel runs
  as its job's user in a private root of its own (:mod:`dhlab.grading.run.sandbox`: only the
  system, Python and dhlab, read-only, and its own folder exist for it) with no network, and
  each submission in a control group of its own (:mod:`dhlab.grading.run.cgroups`: memory and
  processes limited for the whole submission). It cannot write dhlab, see any submission
  but its own code, read the gradebook, the release or the secret, or signal the grader. After each
  submission, **every process of that user** is killed (:func:`kill_user`), so a
  process that left its process group (``setsid``, a double fork) dies too.
* **not as root**: the kernels run as the grader's own user. The limits still
  apply, the gradebook is still written row by row, but a submission could read
  the others, and a process that leaves its process group *and* clears its
  environment can outlive its submission. :func:`setup` says so, and the
  gradebook's status column repeats it.

:func:`fingerprint` hashes the **whole** installed ``dhlab`` package (every file,
compiled modules in ``__pycache__`` included; runners and kernels write none); the
grader compares it before and after every submission and refuses to go on when it
changed.

The kernels' folders go where every user can enter (:func:`kernels_parent`): a ``TMPDIR``
pointing to a private folder (``mktemp -d``) would otherwise kill every kernel at its start.
"""
from __future__ import annotations

import fcntl
import hashlib
import os
import pwd
import queue
import shutil
import signal
import stat
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

from .cgroups import remove_leftovers
from .sandbox import mount_tmpfs, unmount

__all__ = ["Isolation", "setup", "claim", "kill_user", "kill_token", "fingerprint", "file_digests", "changed_files",
           "package_dir", "pids_of", "USER_PREFIX", "kernels_parent", "blocked_on_the_way", "KERNELS_DIR_ENV"]

USER_PREFIX = "dhlab-grade-"
MAX_USERS = 64                                  # dhlab-grade-1 … -64: room for many graders at once
SANDBOX = Path(__file__).resolve().with_name("sandbox.py")
KERNELS_DIR_ENV = "DHLAB_GRADE_KERNELS_DIR"     # where the kernels' own folders go (see kernels_parent)
DISK_MB = 256                                   # a kernel's own folder (tmpfs, as root): see Isolation.workdir
NOBODY_UID = 65534                              # root can become this uid even with no passwd entry for it


def package_dir() -> Path:
    """The folder of the installed dhlab package."""
    return Path(__file__).resolve().parents[2]


def file_digests(folder: Path | None = None) -> dict:
    """{path relative to the package: SHA-256} of every file of the installed dhlab."""
    folder = Path(folder or package_dir())
    out = {}
    for root, dirs, files in os.walk(folder):
        dirs.sort()
        for name in sorted(files):
            path = Path(root, name)
            rel = str(path.relative_to(folder))
            try:
                data = path.read_bytes() if not path.is_symlink() else b"->" + os.readlink(path).encode()
                out[rel] = hashlib.sha256(data).hexdigest()
            except OSError as e:
                out[rel] = f"unreadable {e.errno}"
    return out


def changed_files(before: dict, after: dict) -> list:
    """The files added, removed or changed between two :func:`file_digests`."""
    return sorted(k for k in set(before) | set(after) if before.get(k) != after.get(k))


def fingerprint(folder: Path | None = None) -> str:
    """A hash of every file of the installed dhlab (names and contents, compiled modules included)."""
    h = hashlib.sha256()
    for rel, digest in file_digests(folder).items():
        h.update(rel.encode("utf-8", "surrogateescape") + b"\0" + digest.encode() + b"\0")
    return h.hexdigest()


@dataclass
class Isolation:
    """How the submissions of one batch are kept apart."""
    mode: str                                   # "user" or "none"
    why: str = ""                               # what is not protected, for the status and the report
    users: list = field(default_factory=list)   # (name, uid, gid) per job
    jobs: int = 1
    base: Path | None = None                    # root of the kernels' own folders
    locks: list = field(default_factory=list, repr=False)   # open descriptors: this grader's claim on its users
    _free: queue.Queue = field(default_factory=queue.Queue, repr=False)

    def note(self) -> str:
        """The words the gradebook's status carries when the submissions are not fully apart."""
        return f"not isolated: {self.why}" if self.why else ""

    def acquire(self):
        return self._free.get()

    def close(self) -> None:
        """Give the users back to other graders (the end of the process does it too)."""
        for fd in self.locks:
            os.close(fd)
        self.locks.clear()

    def release(self, user) -> None:
        self._free.put(user)

    def workdir(self, user) -> Path:
        """A fresh folder for one submission's kernel, owned by its user (mode 0700). As root it is
        a tmpfs of :data:`DISK_MB`: a submission cannot fill the machine's disk, and what it writes
        counts as its memory (its control group's) and vanishes with it."""
        folder = Path(tempfile.mkdtemp(prefix="kernel-", dir=self.base))
        if user is not None:
            os.chown(folder, user[1], user[2])
            if os.geteuid() == 0:
                try:
                    mount_tmpfs(str(folder), DISK_MB, user[1], user[2])
                except OSError:
                    pass                             # no tmpfs here: the folder stays on disk (runner says so)
        return folder

    def cleanup(self, user, workdir: Path, token: str) -> None:
        """End every process the submission started, then remove its folder."""
        if user is not None:
            kill_user(user[1])
        kill_token(token)
        if token and os.geteuid() == 0:           # the runner removes its group; a killed runner cannot
            remove_leftovers(f"sub-{token}")
        if os.geteuid() == 0:                     # its tmpfs (Isolation.workdir), if it has one
            unmount(str(workdir))
        shutil.rmtree(workdir, ignore_errors=True)
        shutil.rmtree(f"{workdir}.root", ignore_errors=True)    # where its private root was mounted


def _ensure_user(name: str):
    try:
        entry = pwd.getpwnam(name)
    except KeyError:
        useradd = shutil.which("useradd") or "/usr/sbin/useradd"
        proc = subprocess.run([useradd, "--system", "--no-create-home", "--home-dir", "/nonexistent",
                               "--shell", "/usr/sbin/nologin", "--user-group", name],
                              capture_output=True, text=True)
        if proc.returncode != 0:
            raise OSError(proc.stderr.strip() or f"useradd exit {proc.returncode}") from None
        entry = pwd.getpwnam(name)
    if entry.pw_uid == 0:
        raise OSError(f"user {name} is root")
    return name, entry.pw_uid, entry.pw_gid


def _lock_folder() -> Path:
    """Root's own folder for the users' locks: only root can create, take or remove a lock."""
    if os.access("/run", os.W_OK):
        folder = Path("/run/dhlab-grade")
    else:
        folder = Path(tempfile.gettempdir(), "dhlab-grade-locks")
    folder.mkdir(mode=0o700, exist_ok=True)
    info = folder.lstat()
    if not stat.S_ISDIR(info.st_mode) or info.st_uid != 0 or info.st_mode & 0o077:
        raise OSError(f"the lock folder {folder} is not root's own (a folder of mode 0700): remove it and grade again")
    return folder


def claim(name: str, wait: bool = False):
    """Lock user ``name`` for this grader: an open descriptor (held until closed or the process
    ends), or None when another grader holds it and ``wait`` is False."""
    fd = os.open(_lock_folder() / f"{name}.lock", os.O_RDWR | os.O_CREAT | os.O_CLOEXEC | os.O_NOFOLLOW, 0o600)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | (0 if wait else fcntl.LOCK_NB))
    except BlockingIOError:
        os.close(fd)
        return None
    return fd


def _claim_users(iso: Isolation, jobs: int) -> list:
    """The first ``jobs`` users ``dhlab-grade-K`` no other grader holds, locked and created."""
    users = []
    for k in range(1, MAX_USERS + 1):
        fd = claim(f"{USER_PREFIX}{k}")
        if fd is not None:
            iso.locks.append(fd)
            users.append(_ensure_user(f"{USER_PREFIX}{k}"))
            if len(users) == jobs:
                return users
    raise OSError(f"other graders hold all {MAX_USERS} grading users; wait for one to finish")


def _probe(user, base: Path) -> tuple:
    """Run the sandbox's self-test as ``user``: (why it fails or '', what it does not protect or '')."""
    workdir = Path(tempfile.mkdtemp(prefix="probe-", dir=base))
    os.chown(workdir, user[1], user[2])
    try:
        proc = subprocess.run([sys.executable, "-B", str(SANDBOX), "--uid", str(user[1]), "--gid", str(user[2]),
                               "--workdir", str(workdir), "--probe"], capture_output=True, text=True, timeout=60,
                              cwd=workdir, env=dict(os.environ, PYTHONDONTWRITEBYTECODE="1"))
    except (OSError, subprocess.TimeoutExpired) as e:
        return f"the sandbox could not start ({e})", ""
    finally:
        kill_user(user[1])
        shutil.rmtree(workdir, ignore_errors=True)
        shutil.rmtree(f"{workdir}.root", ignore_errors=True)
    if proc.returncode != 0:
        return (proc.stderr.strip().splitlines() or ["the sandbox's self-test failed"])[-1][:200], ""
    return "", "; ".join(proc.stdout.strip().splitlines())


def blocked_on_the_way(path, uid: int, gids=()) -> str:
    """The first folder on the way to ``path`` that user ``uid`` (groups ``gids``) cannot enter,
    described ('/tmp/tmp.x1 (mode 0700, owner root)'), or '' when every folder lets it through."""
    current = Path("/")
    for part in [*Path(path).parts[1:], None]:
        try:
            info = current.stat()
        except OSError:
            return ""                            # not there (yet): nothing to say
        bit = 0o100 if info.st_uid == uid else 0o010 if info.st_gid in gids else 0o001
        if uid != 0 and not info.st_mode & bit:
            try:
                owner = pwd.getpwuid(info.st_uid).pw_name
            except KeyError:
                owner = str(info.st_uid)
            return f"{current} (mode {stat.S_IMODE(info.st_mode):04o}, owner {owner})"
        if part is None:
            return ""
        current = current / part


def kernels_parent() -> Path:
    """Where the kernels' own folders go: ``$DHLAB_GRADE_KERNELS_DIR`` when set, else the temporary
    folder, unless another user cannot enter it (``TMPDIR`` set to a private ``mktemp -d`` folder):
    then ``/tmp`` or ``/var/tmp`` (why: a kernel that cannot enter its own folder dies at its start)."""
    chosen = os.environ.get(KERNELS_DIR_ENV)
    if chosen:
        return Path(chosen)
    nobody = pwd.getpwnam("nobody").pw_uid if _has_user("nobody") else NOBODY_UID
    for folder in (tempfile.gettempdir(), "/tmp", "/var/tmp", "/dev/shm"):
        if os.path.isdir(folder) and not blocked_on_the_way(folder, nobody):
            return Path(folder)
    return Path(tempfile.gettempdir())           # the self-check will say what is wrong


def _kernels_dir():
    """As root (kernels run as other users) or when told: :func:`kernels_parent`; else the temporary folder."""
    return kernels_parent() if os.geteuid() == 0 or os.environ.get(KERNELS_DIR_ENV) else None


def _has_user(name: str) -> bool:
    try:
        pwd.getpwnam(name)
        return True
    except KeyError:
        return False


def setup(jobs: int, mode: str = "auto") -> Isolation:
    """Decide how to isolate a batch of ``jobs`` parallel submissions (see the module doc)."""
    base = Path(tempfile.mkdtemp(prefix="dhlab-grade-kernels-", dir=_kernels_dir()))
    os.chmod(base, 0o711)                      # users can enter their own folder, not list the others
    iso = Isolation("none", jobs=jobs, base=base)
    if mode == "none":
        iso.why = "isolation turned off (--isolation none)"
    elif os.geteuid() != 0:
        iso.why = ("the grader does not run as root, so every kernel runs as the grader's own user: a submission "
                   "could read the other submissions and leave processes behind (grade as root or in a container)")
        if mode == "user":
            raise OSError(iso.why)
    else:
        try:
            iso.users = _claim_users(iso, jobs)
        except OSError as e:
            iso.close()
            try:
                nobody = pwd.getpwnam("nobody")
                iso.locks.append(claim("nobody", wait=True))     # another grader using nobody: wait for it
                iso.users = [("nobody", nobody.pw_uid, nobody.pw_gid)]
                iso.jobs = 1
                iso.why = f"no user could be created ({e}), so all kernels run as nobody, one at a time"
            except KeyError:                   # no nobody either: root can still become a bare uid
                try:
                    iso.locks.append(claim(f"uid-{NOBODY_UID}", wait=True))
                    iso.users = [(f"uid-{NOBODY_UID}", NOBODY_UID, NOBODY_UID)]
                    iso.jobs = 1
                    iso.why = f"no user could be created ({e}), so all kernels run as uid {NOBODY_UID}, one at a time"
                except OSError:
                    iso.why = f"no unprivileged user could be created ({e})"
            except OSError:
                iso.why = f"no unprivileged user could be created ({e})"
        for user in iso.users:                 # a clean slate: nothing left from an earlier, killed batch of ours
            kill_user(user[1])
        if iso.users:
            fatal, limits = _probe(iso.users[0], base)
            if fatal:
                iso.users, iso.jobs = [], jobs
                iso.close()
                iso.why = f"the sandbox does not hold on this machine: {fatal}"
            else:
                iso.mode = "user"
                iso.why = "; ".join(w for w in (iso.why, limits) if w)
        if mode == "user" and iso.mode != "user":
            raise OSError(iso.why)
    for user in iso.users or [None] * iso.jobs:
        iso.release(user)
    return iso


def kill_user(uid: int, tries: int = 50) -> bool:
    """Kill every process of ``uid`` (not root): a child becomes that user and sends
    SIGKILL to every process it may signal (``kill(-1)``), until none is left."""
    if uid == 0:
        raise ValueError("never kill root's processes")
    for _ in range(tries):
        if not pids_of(uid):
            return True
        pid = os.fork()
        if pid == 0:                                   # the child: become the user, kill them all
            try:
                os.setgroups([])
                os.setgid(_gid_of(uid))
                os.setuid(uid)
                os.kill(-1, signal.SIGKILL)
            finally:
                os._exit(0)
        os.waitpid(pid, 0)
        time.sleep(0.02)
    return not pids_of(uid)


def _gid_of(uid: int) -> int:
    """The group of ``uid``: its passwd entry's, or the same number for a bare uid (no entry)."""
    try:
        return pwd.getpwuid(uid).pw_gid
    except KeyError:
        return uid


def pids_of(uid: int) -> list:
    pids = []
    for entry in os.scandir("/proc"):
        if entry.name.isdigit():
            try:
                if entry.stat().st_uid == uid:
                    pids.append(int(entry.name))
            except OSError:
                pass
    return pids


def kill_token(token: str) -> None:
    """Kill the processes whose environment carries ``DHLAB_GRADE_TOKEN=token`` (what can
    be found of a submission's processes when they run as the grader's own user)."""
    if not token:
        return
    mark = f"DHLAB_GRADE_TOKEN={token}".encode()
    for _ in range(5):
        found = False
        for entry in os.scandir("/proc"):
            if entry.name.isdigit() and int(entry.name) != os.getpid():
                try:
                    if mark in Path(entry.path, "environ").read_bytes():
                        os.kill(int(entry.name), signal.SIGKILL)
                        found = True
                except (OSError, ValueError):
                    pass
        if not found:
            return
        time.sleep(0.05)
