"""The grader checks itself before it grades anyone, and `dhlab-grade --clean` tidies up after a killed one.

The bug this first reproduced: run as root with TMPDIR pointing into a 0700 folder (as `mktemp -d`
makes), every submission came back "grader error: RuntimeError: Kernel died before replying
to kernel_info" — the kernels' users could not enter their own folders. Each kernel now has a
private root that recreates the paths it needs, so such a folder grades; a kernel that still
cannot work (here: a dhlab that fails to import in kernels) makes the self-check stop the grader
with one message, and nothing is graded.
"""
import csv
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pytest

from dhlab.grading.run import cleanup

ROOT = Path(__file__).resolve().parents[2]
SUBMISSIONS = ROOT / "tests" / "data" / "submissions"
AS_ROOT = os.geteuid() == 0
root_only = pytest.mark.skipif(not AS_ROOT, reason="kernels run as other users only when the grader is root")


@pytest.fixture
def tmp_open():
    """A folder every user may pass through (0711), for this test's TMPDIR and its private folders."""
    base = Path(tempfile.mkdtemp(prefix="dhlab-test-selfcheck-"))
    base.chmod(0o711)
    yield base
    shutil.rmtree(base, ignore_errors=True)


def _grader(argv, package, env=(), **kw):
    environment = dict(os.environ, PYTHONPATH=str(package), **dict(env))
    return subprocess.Popen([sys.executable, "-m", "dhlab.grading.cli", *argv], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, env=environment, cwd=package, **kw)


def _submissions(folder: Path, *names) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    for name in names:
        shutil.copy(SUBMISSIONS / f"{name}.ipynb", folder / f"{name}.ipynb")
    return folder


@root_only
def test_a_private_tmpdir_no_longer_kills_every_kernel(package, tmp_open):
    private = tmp_open / "mktemp"
    private.mkdir(mode=0o700)                               # TMPDIR=$(mktemp -d)
    subs = _submissions(tmp_open / "subs", "valid_alternative")
    out = tmp_open / "gradebook.csv"
    proc = _grader(["puma", str(subs), "-o", str(out), "-q"], package, env={"TMPDIR": str(private)})
    _, err = proc.communicate(timeout=600)
    assert proc.returncode == 0, err[-2000:]
    with open(out, newline="", encoding="utf-8") as f:
        row = next(csv.DictReader(f))
    assert (row["score"], row["status"]) == ("10", "ok"), row


@root_only
def test_a_kernels_folder_others_cannot_enter_still_grades(package, tmp_open):
    """The kernels' folders under a 0700 folder: each kernel's private root recreates the path it
    needs, so the class is graded (before the private root, every kernel died at its start)."""
    blocked = tmp_open / "private"
    blocked.mkdir(mode=0o700)
    (blocked / "kernels").mkdir()
    subs = _submissions(tmp_open / "subs", "valid_alternative")
    out = tmp_open / "gradebook.csv"
    proc = _grader(["puma", str(subs), "-o", str(out), "-q"], package,
                   env={"DHLAB_GRADE_KERNELS_DIR": str(blocked / "kernels")})
    _, err = proc.communicate(timeout=600)
    assert proc.returncode == 0, err[-2000:]
    rows = list(csv.DictReader(open(out, encoding="utf-8-sig")))
    assert [(r["submission"], r["score"]) for r in rows] == [("valid_alternative", "10")]


@pytest.fixture
def broken_package(tmp_open):
    """dhlab whose import fails in a grading kernel (its environment names a submission's token),
    while the grader itself imports it: an installation a kernel cannot use."""
    from support.grader import package_copy
    folder = package_copy()
    init = folder / "dhlab" / "__init__.py"
    init.write_text("import os\nif os.environ.get('DHLAB_GRADE_TOKEN'):\n"
                    "    raise ImportError('this dhlab is broken for kernels')\n" + init.read_text())
    yield folder
    shutil.rmtree(folder, ignore_errors=True)


def test_the_self_check_stops_the_grader_with_one_message_and_grades_nothing(broken_package, tmp_open):
    subs = _submissions(tmp_open / "subs", "valid_alternative", "mistake_part1")
    out = tmp_open / "gradebook.csv"
    proc = _grader(["puma", str(subs), "-o", str(out), "-q"], broken_package)
    _, err = proc.communicate(timeout=600)
    assert proc.returncode == 5, err[-2000:]
    lines = [line for line in err.splitlines() if "self-check" in line]
    assert len(lines) == 1, err
    assert "user dhlab-grade-" in lines[0] and "this dhlab is broken for kernels" in lines[0]
    assert "What to do" in lines[0] and "grader error" not in err
    assert not out.exists()                                 # nothing graded, not even an empty gradebook


def _leftovers(folder: Path) -> list:
    return sorted(p.name for p in folder.iterdir() if p.name.startswith(cleanup.LEFTOVERS))


def _running(*marks: str) -> list:
    """The processes whose command line holds every one of ``marks``."""
    found = []
    for entry in os.scandir("/proc"):
        if entry.name.isdigit():
            try:
                cmdline = Path(entry.path, "cmdline").read_bytes()
                if all(mark.encode() in cmdline for mark in marks):
                    found.append(int(entry.name))
            except OSError:
                pass
    return found


def _clean(package, tmp):
    return subprocess.run([sys.executable, "-m", "dhlab.grading.cli", "--clean"], capture_output=True, text=True,
                          env=dict(os.environ, PYTHONPATH=str(package), TMPDIR=str(tmp)), cwd=package, timeout=120)


def test_clean_removes_what_a_killed_grader_left_and_ends_its_processes(package, tmp_open):
    tmp = tmp_open / "tmp"
    tmp.mkdir(mode=0o1777)
    subs = _submissions(tmp_open / "subs", "hostile_hangs")
    env = {"TMPDIR": str(tmp), "DHLAB_GRADE_KERNELS_DIR": str(tmp)}
    proc = _grader(["puma", str(subs), "-o", str(tmp_open / "gradebook.csv"), "-q", "--timeout", "300"], package, env)
    try:
        deadline = time.monotonic() + 180
        # until the submission's kernel runs (a process of its folder besides the runner): the runner dies
        # with its grader, the kernel is what a killed grader leaves behind (a fixed wait raced a slow start).
        # The grader's self-check runs a kernel first, in a copies folder of its own that goes when it ends:
        # the submission's kernel is the one that runs once that first folder is gone.
        first = None
        while time.monotonic() < deadline:
            kernels = set(_running(str(tmp))) - set(_running(str(tmp), "00000.ipynb"))
            copies = sorted(n for n in _leftovers(tmp) if n.startswith("dhlab-grade-copies-"))
            first = first or (copies[0] if kernels and copies else None)
            if kernels and first is not None and first not in copies:
                break
            time.sleep(0.5)
        time.sleep(3)                                       # and hangs in the endless cell
        assert proc.poll() is None, proc.communicate()[1][-2000:]
        proc.send_signal(signal.SIGKILL)                    # the grader, killed: it cannot tidy up
        proc.communicate(timeout=30)
        left = _leftovers(tmp)
        assert any(n.startswith("dhlab-grade-copies-") for n in left), left
        assert any(n.startswith("dhlab-grade-kernels-") for n in left) and _running(str(tmp))
        done = _clean(package, tmp)
        assert done.returncode == 0, done.stderr
        assert _leftovers(tmp) == [] and "removed" in done.stderr
        time.sleep(0.5)
        assert _running(str(tmp)) == []                     # its runner and kernel ended too
    finally:
        for pid in _running(str(tmp)):
            os.kill(pid, signal.SIGKILL)


def test_clean_leaves_a_running_grader_alone(package, tmp_open, monkeypatch):
    tmp = tmp_open / "tmp"
    tmp.mkdir(mode=0o1777)
    (tmp / "dhlab-grade-copies-abc").mkdir()               # a running grader's copies
    monkeypatch.setenv("TMPDIR", str(tmp))
    monkeypatch.setenv("DHLAB_GRADE_KERNELS_DIR", str(tmp))
    monkeypatch.setattr(tempfile, "tempdir", None)          # gettempdir() reads TMPDIR again
    held = cleanup.hold()                                   # what the grader holds while it runs
    try:
        assert held
        done = _clean(package, tmp)
        assert done.returncode == 1 and "a grader is running there now" in done.stderr
        assert _leftovers(tmp) == ["dhlab-grade-copies-abc"]
    finally:
        for fd in held:
            os.close(fd)
    done = _clean(package, tmp)
    assert done.returncode == 0 and _leftovers(tmp) == []


@root_only
def test_a_kernel_has_no_network(package, tmp_open):
    """Item 6: the kernel runs in a network namespace of its own (it talks to its runner over Unix
    sockets), so it cannot even reach a server on this machine's loopback."""
    import json
    import socket
    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    server.listen(5)
    port = server.getsockname()[1]
    code = (f"import socket\ntry:\n    socket.create_connection(('127.0.0.1', {port}), timeout=3)\n"
            "    n_links = 0\nexcept OSError:\n    n_links = 7\n")
    subs = tmp_open / "subs"
    subs.mkdir()
    (subs / "net.ipynb").write_text(json.dumps({"nbformat": 4, "nbformat_minor": 5, "metadata": {}, "cells": [
        {"cell_type": "code", "metadata": {}, "execution_count": None, "outputs": [], "source": code}]}))
    try:
        for isolation, reached in (("auto", False), ("none", True)):
            out = tmp_open / f"gradebook-{isolation}.csv"
            proc = _grader(["puma", str(subs), "-o", str(out), "-q", "--isolation", isolation], package)
            _, err = proc.communicate(timeout=600)
            assert proc.returncode == 0, err[-2000:]
            feedback = next((tmp_open / f"gradebook-{isolation}_feedback").glob("*.txt")).read_text()
            assert ("✓ n_links = 7" not in feedback) is reached, feedback[:600]
            assert "network access" not in err                    # the namespace held: the status would say
    finally:
        server.close()
