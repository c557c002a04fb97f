"""Each kernel in a root of its own: nothing of the teacher reaches it, its limits hold for the whole
submission, and it leaves nothing behind: a grader a university can trust.

These tests run a kernel as the grader runs it as root — its own user, a private root, a control
group — through :func:`dhlab.grading.run.runner.run_notebook`, and ask the kernel what it can see:
the teacher's environment, a secret beside the submissions, a Unix socket at a file path, the
files it wrote to /tmp and /dev/shm. Without root they are skipped (the kernel then runs as the
grader's own user, and the gradebook says so).
"""
import json
import os
import shutil
import socket
import stat
import subprocess
import sys
import tempfile
import zipfile
from pathlib import Path

import pytest

from dhlab.grading.export import gradescope
from dhlab.grading.run import cgroups, isolation, runner, sandbox
from dhlab.grading.run.kernel import PASSED_ENV, Kernel, kernel_environment
from support.grader import write_notebook

ROOT = Path(__file__).resolve().parents[2]
AS_ROOT = os.geteuid() == 0
needs_root = pytest.mark.skipif(not AS_ROOT, reason="a private root and a grading user need root")


@pytest.fixture()
def user():
    """A grading user of this test's own (locked, as a grader holds it), and its kernel folder."""
    iso = isolation.setup(1, "user")
    who = iso.acquire()
    workdir = iso.workdir(who)
    yield who, workdir
    iso.cleanup(who, workdir, "")
    iso.close()
    shutil.rmtree(iso.base, ignore_errors=True)


def _run(nb, user, **kw):
    who, workdir = user
    kw.setdefault("timeout", 60)
    kw.setdefault("total_timeout", 150)
    return runner.run_notebook(nb, user=(who[1], who[2]), workdir=workdir, **kw)


def _answers(result):
    assert not result.grader_error, result.grader_error
    return json.loads(result.answers_json)


def test_the_kernel_environment_is_an_allow_list():
    env = kernel_environment(Path("/k"), "tok", environ={
        "CANVAS_API_TOKEN": "xyz", "AWS_SECRET_ACCESS_KEY": "s", "LANG": "es_ES.UTF-8", "LC_ALL": "$(rm -rf /)",
        "PYTHONPATH": "/teacher/private", "HOME": "/root", "DHLAB_LANGUAGE": "es"})
    assert "CANVAS_API_TOKEN" not in env and "AWS_SECRET_ACCESS_KEY" not in env
    assert env["LANG"] == "es_ES.UTF-8" and env["DHLAB_LANGUAGE"] == "es"
    assert "LC_ALL" not in env                       # not a locale's name: not passed
    assert "PYTHONPATH" not in env                   # dhlab is not found through it here
    assert env["HOME"] == env["TMPDIR"] == "/k" and env["DHLAB_GRADE_TOKEN"] == "tok"
    assert set(env) <= set(PASSED_ENV) | {
        "PATH", "PYTHONDONTWRITEBYTECODE", "PYTHONNOUSERSITE", "PYTHONHASHSEED", "OPENBLAS_NUM_THREADS",
        "OMP_NUM_THREADS", "MKL_NUM_THREADS", "MPLBACKEND", "HOME", "TMPDIR", "IPYTHONDIR", "MPLCONFIGDIR",
        "JUPYTER_RUNTIME_DIR", "DHLAB_GRADE_TOKEN", "PYTHONPATH"}


@needs_root
def test_nothing_of_the_teacher_reaches_the_kernel(tmp_path, user, monkeypatch):
    """The teacher's token, a secret file readable by everyone, a Unix socket at a file path, the
    teacher's home: none exists for the kernel. Only its own folder is writable."""
    teacher = Path(tempfile.mkdtemp(prefix="dhlab-test-teacher-"))     # outside the kernel's folder
    os.chmod(teacher, 0o755)
    (teacher / "secret.key").write_text("s3cr3t")
    os.chmod(teacher / "secret.key", 0o644)
    server = socket.socket(socket.AF_UNIX)
    server.bind(str(teacher / "grader.sock"))
    server.listen(1)
    os.chmod(teacher / "grader.sock", 0o777)
    monkeypatch.setenv("CANVAS_API_TOKEN", "canary-7f3a")
    try:
        nb = write_notebook(
            tmp_path / "look.ipynb",
            "import os, socket\n"
            f"teacher = {str(teacher)!r}\n"
            "n_links = int(os.path.exists(teacher + '/secret.key'))\n"
            "s = socket.socket(socket.AF_UNIX)\n"
            "try:\n    s.connect(teacher + '/grader.sock'); n_joints = 1\nexcept OSError:\n    n_joints = 0\n"
            "joint_types = ' '.join(sorted(os.listdir('/')))\n"
            "x_cases = [os.environ.get('CANVAS_API_TOKEN', 'none'), str(os.path.exists('/home')),"
            " str(os.access('/usr/bin', os.W_OK)), str(os.access(os.getcwd(), os.W_OK)), os.getcwd()]\n")
        result = _run(nb, user)
    finally:
        server.close()
        shutil.rmtree(teacher, ignore_errors=True)
    answers = _answers(result)
    assert answers["n_links"] == 0 and answers["n_joints"] == 0
    assert set(answers["joint_types"].split()) <= {"bin", "dev", "etc", "lib", "lib32", "lib64", "libx32", "proc",
                                                   "sbin", "tmp", "usr", *Path(sys.prefix).parts[1:2],
                                                   *Path(sys.base_prefix).parts[1:2], *ROOT.parts[1:2]}
    assert answers["x_cases"][:4] == ["none", "False", "False", "True"]
    assert "private root" in result.isolation and "NOT:" not in result.isolation
    assert "canary-7f3a" not in json.dumps(answers)


@needs_root
def test_tmp_and_shm_are_the_submissions_own_and_go_with_it(tmp_path, user):
    marker = f"dhlab-test-{os.getpid()}"
    nb = write_notebook(tmp_path / "w.ipynb",
                   f"open('/tmp/{marker}', 'w').write('x')\nopen('/dev/shm/{marker}', 'w').write('x')\n"
                   "import os\nn_links = len(os.listdir('/tmp')) + len(os.listdir('/dev/shm'))\n"
                   # a private /tmp has a size: filling it fails in the cell, not on the machine
                   "try:\n    open('/tmp/big', 'wb').write(b'x' * (200 * 2**20)); n_joints = 0\n"
                   "except OSError:\n    n_joints = 1\n")
    answers = _answers(_run(nb, user, memory_mb=1024))
    assert answers["n_joints"] == 1
    assert not Path(f"/tmp/{marker}").exists() and not Path(f"/dev/shm/{marker}").exists()
    assert not Path(f"{user[1]}.root").exists() or not os.listdir(f"{user[1]}.root")


@needs_root
@pytest.mark.skipif(not cgroups.version(), reason="no cgroup file system with memory and pids controllers")
def test_the_memory_limit_holds_for_the_whole_submission(tmp_path, user):
    """Six forked children of 300 MB each: under a 1024 MB limit for the submission, not each."""
    nb = write_notebook(tmp_path / "fork.ipynb",
                   "import os, time\nkids = []\n"
                   "for i in range(6):\n    pid = os.fork()\n"
                   "    if pid == 0:\n        b = bytearray(300 * 2**20)\n        time.sleep(30)\n        os._exit(0)\n"
                   "    kids.append(pid)\n"
                   "time.sleep(4)\n"
                   "n_links = sum(os.waitpid(k, os.WNOHANG)[0] == k for k in kids)\n"
                   "for k in kids:\n    try: os.kill(k, 9)\n    except OSError: pass\n",
                   "n_joints = 6")
    result = _run(nb, user, memory_mb=1024)
    answers = _answers(result)
    assert answers["n_joints"] == 6                  # the kernel itself lived on
    assert answers["n_links"] >= 3                   # at least three children were killed for memory
    assert result.limit == "memory" and "cgroup" in result.isolation


@needs_root
def test_a_correct_notebook_fits_a_small_memory_limit(tmp_path, user):
    """The limit counts memory used, not address space reserved: numpy, matplotlib and dhlab at 512 MB."""
    nb = write_notebook(tmp_path / "imports.ipynb",
                   "import numpy, sympy, matplotlib.pyplot as plt, dhlab\nfrom dhlab.robots import puma560\n"
                   "fig = plt.figure(); plt.plot([0, 1]); fig.savefig('a.png')\nn_links = 7")
    result = _run(nb, user, memory_mb=512)
    assert _answers(result) == {"n_links": 7} and not result.errors and result.limit == ""


@needs_root
def test_a_course_in_a_private_folder_still_grades(tmp_path):
    """dhlab in a 0700 folder (a fresh container's /root, a mktemp -d): the kernel reaches it all the same."""
    private = Path(tempfile.mkdtemp(prefix="dhlab-test-private-"))          # mode 0700
    try:
        shutil.copytree(ROOT / "dhlab", private / "dhlab", ignore=shutil.ignore_patterns("__pycache__"))
        nb = write_notebook(tmp_path / "p.ipynb", "import dhlab\nn_links = 7\njoint_types = dhlab.__file__")
        out = tmp_path / "result.json"
        env = dict(os.environ, PYTHONPATH=str(private))
        iso_code = (
            "import sys, json; from dhlab.grading.run import isolation, runner\n"
            "iso = isolation.setup(1, 'user'); who = iso.acquire(); w = iso.workdir(who)\n"
            f"r = runner.run_notebook({str(nb)!r}, timeout=60, total_timeout=150, user=(who[1], who[2]), workdir=w)\n"
            "iso.cleanup(who, w, ''); iso.close()\n"
            f"open({str(out)!r}, 'w').write(json.dumps({{'answers': r.answers_json, 'error': r.grader_error, "
            "'why': iso.why}))\n")
        subprocess.run([sys.executable, "-c", iso_code], env=env, cwd=private, check=True, timeout=300)
        got = json.loads(out.read_text())
    finally:
        shutil.rmtree(private, ignore_errors=True)
    assert got["error"] == "" and "sandbox does not hold" not in got["why"]
    answers = json.loads(got["answers"])
    assert answers["n_links"] == 7 and answers["joint_types"].startswith(str(private))


def test_flooding_cells_keep_their_answers(tmp_path):
    """Three cells that print without end-of-line discipline: their output past the cap is dropped,
    they finish, and the answers count (no restart, no 'no time left')."""
    nb = write_notebook(tmp_path / "flood.ipynb", *["for i in range(200_000):\n    print(i)"] * 3, "n_links = 7")
    result = runner.run_notebook(nb, timeout=60, total_timeout=150, output_mb=0.2)
    assert json.loads(result.answers_json) == {"n_links": 7}
    assert result.restarts == 0 and not result.skipped and not result.out_of_time
    assert [c for c, _ in result.output_capped] == [1, 2, 3]


def test_a_cell_waiting_for_a_cpu_is_not_charged_for_it():
    """The cell's limit counts the time it ran or slept, not the time it waited for a CPU."""
    class Fake(Kernel):
        def __init__(self):
            self.clock = 0.0

        def waited(self):
            return self.clock * 0.75              # a machine so loaded that 3/4 of the time is waiting

    kernel = Fake()
    kernel.kc = type("KC", (), {"execute": lambda *a, **k: "m"})()
    seen = []

    def next_message(msg_id, wait, result):
        kernel.clock += 1.0
        seen.append(kernel.clock)
        return "idle" if kernel.clock >= 8 else None

    kernel._next = next_message
    kernel._stop = lambda msg_id, result, why: setattr(result, "status", why) or result
    real = runner.time.monotonic
    runner.time.monotonic = lambda: kernel.clock
    try:
        cell = kernel.execute("x", limit=5, cap_bytes=10**6)
    finally:
        runner.time.monotonic = real
    assert cell.status == "ok" and seen[-1] == 8     # 8 s of wall clock, 2 s of its own: not a timeout


def test_the_secret_inside_the_autograder_zip_unpacks_for_its_owner_only(tmp_path):
    out = tmp_path / "autograder.zip"
    with zipfile.ZipFile(out, "w") as z:
        gradescope._add(z, gradescope.SECRET, b"k" * 32, private=True)
        gradescope._add(z, "setup.sh", "#!/bin/sh\n", executable=True)
        gradescope._add(z, "dhlab_autograder.json", "{}")
    modes = {i.filename: i.external_attr >> 16 for i in zipfile.ZipFile(out).infolist()}
    assert modes == {"secret.key": 0o600, "setup.sh": 0o755, "dhlab_autograder.json": 0o644}


def test_export_writes_the_zip_0600(tmp_path):
    out = gradescope.export(tmp_path / "autograder.zip")
    assert stat.S_IMODE(out.stat().st_mode) == 0o600


def test_the_sandbox_binds_only_what_the_kernel_needs():
    paths = sandbox._needed_paths()
    assert all(Path(p).is_dir() for p in paths)
    # an editable install's checkout is not bound whole: only its dhlab folder
    assert str(ROOT) not in paths or (ROOT / "dhlab").resolve() == ROOT.resolve()


def test_a_loaded_machine_does_not_turn_a_correct_cell_into_a_timeout(tmp_path):
    """Two graders on one machine: a cell that needs 2 s of CPU, a 3-s limit, and three
    busy processes beside it on this 2-core machine, so the cell takes about 5 s of wall-clock time.
    The limit counts the time the cell had the CPU (or slept), not the time it waited for one."""
    if not Path("/proc/self/schedstat").exists():
        pytest.skip("the scheduler does not say how long a process waited (no /proc/PID/schedstat)")
    nb = write_notebook(tmp_path / "busy.ipynb",
                   "import time\nstart = time.process_time()\n"
                   "while time.process_time() - start < 2.0:\n    pass\n"
                   "n_links = 7")
    hogs = [subprocess.Popen([sys.executable, "-c", "while True: pass"], start_new_session=True)  # own sessions:
            for _ in range(3)]                       # each its own share of the CPU (autogroup)
    try:
        result = runner.run_notebook(nb, timeout=3, total_timeout=120)
    finally:
        for hog in hogs:
            hog.kill()
            hog.wait()
    assert result.timeouts == [], result
    assert json.loads(result.answers_json) == {"n_links": 7}
