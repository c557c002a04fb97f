"""A hostile battery, graded as a teacher grades a class: one ``dhlab-grade`` batch with ``-j 2``, as root,
with the teacher's token in the environment, a secret, a release and an ``autograder.zip`` beside the
submissions, and a Unix socket, an abstract socket and a TCP port of the host listening.

Every hostile notebook also holds the correct answers, so each must keep 10/10; the attacks report what
they saw through the one channel a student has — the error message of their own last cell, which the
gradebook and the feedback show. After the batch: no canary in the gradebook, the feedback or the grader's
output, no connection reached the host, and nothing of the batch is left (processes, mounts, folders,
control groups).

Without root the kernels are not isolated (the gradebook says so) and the battery is skipped.
"""
import copy
import csv
import json
import os
import re
import secrets
import shutil
import socket
import subprocess
import sys
import tempfile
import threading
import time
import zipfile
from pathlib import Path

import pytest

from support.grader import package_copy

ROOT = Path(__file__).resolve().parents[2]
VALID = ROOT / "tests" / "data" / "submissions" / "valid_alternative.ipynb"
pytestmark = pytest.mark.skipif(os.geteuid() != 0,
                                reason="the kernels run as their own users only when the grader is root")

CANARY = "dhlab-canary-" + secrets.token_hex(6)
NEEDLE = CANARY[::-1]                 # the notebooks search for the canary without holding it
ABSTRACT = "dhlab-battery-" + secrets.token_hex(4)

RECON = r'''
import os, socket
needle = NEEDLE[::-1]
flags, blob = {}, []
flags["env"] = sum(needle in v for v in os.environ.values())
pids = [p for p in os.listdir("/proc") if p.isdigit()]
flags["pids"] = len(pids)
leak = 0
for p in pids:
    for f in ("environ", "cmdline"):
        try:
            leak += needle.encode() in open(f"/proc/{p}/{f}", "rb").read()
        except OSError:
            pass
flags["procleak"] = leak
try:
    open("/proc/1/environ", "rb").read(); flags["p1"] = 1
except OSError:
    flags["p1"] = 0
hits = 0
for top in ("/tmp", "/dev/shm", "/home", "/root", "/srv", "/opt", "/mnt", "/var", "/run", os.getcwd(), "/etc"):
    for d, ds, fs in os.walk(top):
        for f in fs:
            try:
                with open(os.path.join(d, f), "rb") as fh:
                    hits += needle.encode() in fh.read(1 << 20)
            except OSError:
                pass
flags["filehits"] = hits
def tryc(fam, addr):
    s = socket.socket(fam, socket.SOCK_STREAM); s.settimeout(1)
    try:
        s.connect(addr); s.sendall(b"kernel"); return 1
    except OSError:
        return 0
    finally:
        s.close()
flags["unix"] = tryc(socket.AF_UNIX, UNIX_PATH)
flags["abstract"] = tryc(socket.AF_UNIX, "\0" + ABSTRACT)
flags["tcp"] = tryc(socket.AF_INET, ("127.0.0.1", TCP_PORT))
import dhlab
try:
    open(os.path.join(os.path.dirname(dhlab.__file__), "planted.py"), "w"); flags["dhlabw"] = 1
except OSError:
    flags["dhlabw"] = 0
try:
    os.setuid(0); flags["setuid"] = 1
except OSError:
    flags["setuid"] = 0
try:
    os.listdir("/sys/fs/cgroup"); flags["cg"] = 1
except OSError:
    flags["cg"] = 0
try:
    os.kill(os.getppid(), 9); flags["killppid"] = 1
except OSError:
    flags["killppid"] = 0
try:
    os.kill(1, 0); flags["init"] = 1
except OSError:
    flags["init"] = 0
leaked = [v[:40] for v in os.environ.values() if needle in v]       # echoed: the student's own channel
raise RuntimeError("RECON " + " ".join(f"{k}={v}" for k, v in flags.items())
                   + " token=" + os.environ.get("DHLAB_GRADE_TOKEN", "") + " " + " ".join(leaked[:1]))
'''

FORK_MEMORY = r'''
import os, signal, time
kids = []
for i in range(8):                     # 8 x 500 MB: each fits its own address-space limit, not the group
    pid = os.fork()
    if pid == 0:
        try:
            b = bytearray(500 * 1024 * 1024)
            for j in range(0, len(b), 4096):
                b[j] = 1
            time.sleep(3)
        finally:
            os._exit(0)
    kids.append(pid)
killed = 0
for k in kids:
    _, status = os.waitpid(k, 0)
    killed += os.WIFSIGNALED(status) and os.WTERMSIG(status) == signal.SIGKILL
'''

THREADS = r'''
import threading, time
ts = []
try:
    for i in range(2000):
        t = threading.Thread(target=time.sleep, args=(2,)); t.start(); ts.append(t)
except RuntimeError:
    pass
for t in ts:
    t.join()
n_threads = len(ts)
'''

LATE_WRITER = r'''
import os, time
if os.fork() == 0:
    os.setsid()
    if os.fork() == 0:
        end = time.time() + 90
        while time.time() < end:       # outlive the submission and rewrite the teacher's files
            for p in (GRADEBOOK, SENTINEL):
                try:
                    open(p, "w").write("LATE-WRITTEN")
                except OSError:
                    pass
            time.sleep(0.5)
        os._exit(0)
    os._exit(0)
'''

MONKEYPATCH = r'''
import builtins, json
real_import = builtins.__import__
class Fake:
    def __getattr__(self, k):
        return getattr(builtins, k)
    def exec(self, src, g):
        builtins.exec(src, g)
        w = g["write"]
        def forged(path, names, ns):
            ns = dict(ns); ns["x_cases"] = ["skew"] * 5
            w(path, names, ns)
        g["write"] = forged
def imp(name, *a, **k):
    return Fake() if name == "builtins" else real_import(name, *a, **k)
builtins.__import__ = imp
builtins.list = lambda *a: ["skew"]
json.dumps = lambda *a, **k: "{}"
'''

NEIGHBOUR = r'''
import os, time
seen = set()
end = time.time() + 6
while time.time() < end:                # both run at -j 2: look for the other kernel's folder
    for d, ds, fs in os.walk("/tmp"):
        seen |= {os.path.join(d, x) for x in ds if x.startswith("kernel-")}
    for p in os.listdir("/proc"):
        try:
            seen.add(os.readlink(f"/proc/{p}/cwd"))
        except OSError:
            pass
    time.sleep(0.3)
others = sorted(s for s in seen if s.rstrip("/") != os.getcwd().rstrip("/") and "kernel-" in s)
raise RuntimeError("NEIGHBOUR n=%d %s" % (len(others), ";".join(others)[:120]))
'''


# a daemon plants links to a file of the host in its own folder, where root writes at the next
# kernel's start, then kills its kernel so that a next kernel starts
PLANT_LINKS = r'''
import os, time
victim = VICTIM
if os.fork() == 0:
    os.setsid()
    if os.fork() == 0:
        for fd in (0, 1, 2):
            os.dup2(os.open(os.devnull, os.O_RDWR), fd)
        for _ in range(300):
            for name in ["kernel-connection.json", *os.listdir(".")]:
                if name.startswith(("kernel-connection", ".sandbox-")):
                    try:
                        os.unlink(name)
                    except OSError:
                        pass
                    try:
                        os.symlink(victim, name)
                    except OSError:
                        pass
            time.sleep(0.02)
        os._exit(0)
    os._exit(0)
time.sleep(0.5)
os._exit(1)
'''

# the kernel's own folder has a size: 40 files of 60 MB do not fit
DISK_FILL = r'''
written = 0
try:
    for i in range(40):
        with open(f"fill-{i}", "wb") as f:
            f.write(b"x" * (60 * 2**20))
        written += 1
except OSError:
    pass                                  # the folder is full
finally:
    import os
    for i in range(written + 1):
        try:
            os.unlink(f"fill-{i}")
        except OSError:
            pass
'''


def _notebook(path: Path, before=(), after=()):
    nb = json.loads(VALID.read_text(encoding="utf-8"))
    cell = lambda s: {"cell_type": "code", "metadata": {}, "execution_count": None, "outputs": [], "source": s}
    nb = copy.deepcopy(nb)
    nb["cells"] = [cell(s) for s in before] + nb["cells"] + [cell(s) for s in after]
    path.write_text(json.dumps(nb), encoding="utf-8")


class _Listeners:
    """A Unix socket at a path, an abstract socket and a TCP port on 127.0.0.1: each connection is counted."""

    def __init__(self, folder: Path):
        self.hits, self.socks = [], []
        self.path = str(folder / "host.sock")
        for fam, addr in ((socket.AF_UNIX, self.path), (socket.AF_UNIX, "\0" + ABSTRACT),
                          (socket.AF_INET, ("127.0.0.1", 0))):
            s = socket.socket(fam, socket.SOCK_STREAM)
            s.bind(addr)
            s.listen(8)
            s.settimeout(0.5)
            self.socks.append(s)
            threading.Thread(target=self._serve, args=(s, str(addr)), daemon=True).start()
        os.chmod(self.path, 0o777)
        self.port = self.socks[2].getsockname()[1]
        self.stop = False

    def _serve(self, s, name):
        while not getattr(self, "stop", False):
            try:
                c, _ = s.accept()
            except (TimeoutError, OSError):
                continue
            self.hits.append(name)
            c.close()

    def close(self):
        self.stop = True
        for s in self.socks:
            s.close()


@pytest.fixture(scope="module")
def battery():
    base = Path(tempfile.mkdtemp(prefix="dhlab-battery-"))
    os.chmod(base, 0o755)
    package = package_copy(base / "pkg")
    course = base / "course"              # where the teacher keeps everything
    subs = course / "submissions"
    subs.mkdir(parents=True)
    (course / "secret.key").write_text(CANARY, encoding="utf-8")
    (subs / "secret.key").write_text(CANARY, encoding="utf-8")
    (course / "release" / "_teacher").mkdir(parents=True)
    (course / "release" / "_teacher" / "variants.json").write_text(json.dumps({"ana": CANARY}), encoding="utf-8")
    with zipfile.ZipFile(course / "autograder.zip", "w") as z:
        z.writestr("secret.key", CANARY)
    for path in [course, *course.rglob("*")]:
        path.chmod(0o755 if path.is_dir() else 0o644)      # readable by everybody: only the sandbox hides them
    listeners = _Listeners(course)
    gradebook, sentinel = course / "gb.csv", course / "sentinel.txt"
    victim = course / "victim.txt"
    victim.write_text("ORIGINAL", encoding="utf-8")
    victim.chmod(0o644)
    fill = lambda s: (s.replace("NEEDLE", repr(NEEDLE)).replace("UNIX_PATH", repr(listeners.path))
                      .replace("ABSTRACT", repr(ABSTRACT)).replace("TCP_PORT", str(listeners.port))
                      .replace("GRADEBOOK", repr(str(gradebook))).replace("SENTINEL", repr(str(sentinel)))
                      .replace("VICTIM", repr(str(victim))))
    shutil.copy(VALID, subs / "control.ipynb")
    _notebook(subs / "recon.ipynb", after=[fill(RECON)])
    _notebook(subs / "fork_memory.ipynb", before=[FORK_MEMORY],
              after=['raise RuntimeError("FORK killed=%d" % killed)'])
    _notebook(subs / "threads.ipynb", before=[THREADS], after=['raise RuntimeError("THREADS n=%d" % n_threads)'])
    _notebook(subs / "display_huge.ipynb", before=[
        'from IPython.display import display, HTML\n'
        'for i in range(6):\n    display(HTML("<b>" + "x" * 10_000_000 + "</b>"))'])
    _notebook(subs / "print_flood.ipynb", before=["for i in range(3_000_000):\n    print('flood', i)"])
    _notebook(subs / "late_writer.ipynb", before=[fill(LATE_WRITER)])
    _notebook(subs / "monkeypatch.ipynb", after=[MONKEYPATCH])
    _notebook(subs / "neighbour_a.ipynb", before=[NEIGHBOUR.replace("raise", "neighbour_a =")])
    _notebook(subs / "neighbour_b.ipynb", after=[NEIGHBOUR])
    _notebook(subs / "plant_links.ipynb", after=[fill(PLANT_LINKS)])
    _notebook(subs / "disk_fill.ipynb", after=[DISK_FILL, 'raise RuntimeError("DISK written=%d" % written)'])
    tmp = base / "tmp"                    # the grader's temporary folders (kernels' folders included)
    tmp.mkdir(mode=0o755)
    env = dict(os.environ, PYTHONPATH=str(package), TMPDIR=str(tmp), CANVAS_API_TOKEN=CANARY,
               AWS_SECRET_ACCESS_KEY=CANARY)
    started = time.monotonic()
    try:
        proc = subprocess.run([sys.executable, "-m", "dhlab.grading.cli", "puma", str(subs), "-o", str(gradebook),
                               "-j", "2", "-q", "--timeout", "30"], capture_output=True, text=True, env=env,
                              cwd=package, timeout=600)
    finally:
        listeners.close()
    seconds = time.monotonic() - started
    with open(gradebook, newline="", encoding="utf-8-sig") as f:
        rows = {row["submission"]: row for row in csv.DictReader(f)}
    yield {"proc": proc, "rows": rows, "course": course, "gradebook": gradebook, "sentinel": sentinel, "victim": victim,
           "listeners": listeners, "tmp": tmp, "seconds": seconds, "base": base}
    shutil.rmtree(base, ignore_errors=True)


def _flags(status: str, marker: str) -> dict:
    found = re.search(marker + r" (.*?)\)?$", status)
    assert found, status
    return dict(kv.split("=", 1) for kv in found[1].split() if "=" in kv)


def test_every_hostile_notebook_keeps_its_correct_answers(battery):
    proc, rows = battery["proc"], battery["rows"]
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert len(rows) == 12, sorted(rows)
    for name, row in rows.items():
        assert row["score"] == "10", (name, row["status"])
        assert "grader error" not in row["status"], (name, row["status"])
    assert rows["control"]["status"] == "ok"


def test_no_canary_reaches_the_gradebook_the_feedback_or_the_output(battery):
    texts = [battery["gradebook"].read_text(encoding="utf-8-sig"), battery["proc"].stdout, battery["proc"].stderr]
    texts += [p.read_text(encoding="utf-8", errors="replace")
              for p in (battery["course"] / "gb_feedback").rglob("*") if p.is_file()]
    assert len(texts) > 3
    assert not [t[:200] for t in texts if CANARY in t]


def test_the_kernel_sees_nothing_of_the_teacher_or_the_host(battery):
    flags = _flags(battery["rows"]["recon"]["status"], "RECON")
    for name in ("env", "procleak", "p1", "filehits", "unix", "abstract", "tcp", "dhlabw", "setuid", "cg",
                 "killppid", "init"):
        assert flags[name] == "0", (name, flags)
    assert int(flags["pids"]) <= 4, flags          # hidepid: its own processes only
    assert battery["listeners"].hits == []


def test_memory_and_processes_are_limited_for_the_whole_submission(battery):
    rows = battery["rows"]
    assert int(_flags(rows["fork_memory"]["status"], "FORK")["killed"]) >= 1, rows["fork_memory"]["status"]
    threads = rows["threads"]["status"]
    if "THREADS" in threads:                 # the thread that could not start raised in the cell
        assert int(_flags(threads, "THREADS")["n"]) < 200, threads
    else:                                    # or the limit took the kernel down (and the row kept its marks)
        assert "kernel died in cell" in threads and rows["threads"]["score"] == "10", threads


def test_floods_are_cut_and_said(battery):
    rows = battery["rows"]
    assert "output limit" in rows["display_huge"]["status"]
    assert "output limit" in rows["print_flood"]["status"]


def test_two_kernels_at_once_do_not_see_each_other(battery):
    rows = battery["rows"]
    assert _flags(rows["neighbour_b"]["status"], "NEIGHBOUR")["n"] == "0", rows["neighbour_b"]["status"]


def test_a_process_that_outlives_its_kernel_touches_nothing_and_nothing_is_left(battery):
    tmp, base = battery["tmp"], str(battery["base"])
    assert not battery["sentinel"].exists()
    assert "LATE-WRITTEN" not in battery["gradebook"].read_text(encoding="utf-8-sig")
    token = _flags(battery["rows"]["recon"]["status"], "RECON")["token"]
    assert token
    from dhlab.grading.run import cgroups
    assert cgroups.leftovers(f"sub-{token}") == []
    with open("/proc/mounts", encoding="utf-8") as f:
        assert not [line for line in f if base in line]
    left = []
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            if base in os.readlink(f"/proc/{pid}/cwd") or token.encode() in open(f"/proc/{pid}/environ", "rb").read():
                left.append(pid)
        except OSError:
            pass
    assert left == []
    assert [p.name for p in tmp.iterdir() if p.name != "dhlab-grade.lock"] == []   # the users' lock stays


def test_the_battery_is_fast(battery):
    assert battery["seconds"] < 180, battery["seconds"]


def test_links_planted_in_the_kernels_folder_make_root_write_nothing(battery):
    """A daemon that replaces every file root writes at a kernel's start with a link to a host file,
    then kills its kernel: the next kernel starts with nothing of the last one alive, and root
    creates its files afresh, never through a link (the victim keeps its owner, mode and text)."""
    victim = battery["victim"]
    info = victim.stat()
    assert victim.read_text(encoding="utf-8") == "ORIGINAL"
    assert (info.st_uid, oct(info.st_mode & 0o777)) == (0, "0o644")
    assert battery["rows"]["plant_links"]["score"] == "10", battery["rows"]["plant_links"]["status"]


def test_the_kernels_own_folder_has_a_size(battery):
    status = battery["rows"]["disk_fill"]["status"]
    assert int(_flags(status, "DISK")["written"]) * 60 <= 256, status
