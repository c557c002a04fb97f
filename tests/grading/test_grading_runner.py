"""The grader on whole notebooks: each one runs alone, in a fresh, limited kernel; answers are scored here.

One batch (`dhlab-grade puma DIR -o gradebook.csv -j 2`) grades every submission of
tests/data/submissions — valid answers, one mistake or one slip each, numbers of every
numeric type, odd file names, and hostile notebooks that raise, hang, ignore interrupts,
flood their output, exhaust memory, fork without end, kill their kernel, kill the grader,
tamper with the installed package, edit their classmates' files, leave a `setsid`
process behind, are not JSON, are not notebooks, or hold odd values — plus the course's
source notebook, its student version, and a correct notebook with 25 MB of saved outputs.

The grader imports dhlab from a private copy of the package (PYTHONPATH), so that a
submission that tampers with "the installed dhlab" can only touch that copy, and so that
the check "dhlab is unchanged" is not disturbed by anyone editing this working tree.
"""
import csv
import hashlib
import json
import os
import pwd
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import nbformat
import pytest

from dhlab import grade
from dhlab.grading.run import isolation, runner
from support.grader import SOURCE, package_copy, run_grader, write_notebook

ROOT = Path(__file__).resolve().parents[2]
SUBMISSIONS = ROOT / "tests" / "data" / "submissions"
AS_ROOT = os.geteuid() == 0




def _sha(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def _read(csv_path):
    with open(csv_path, newline="", encoding="utf-8") as f:
        return {row["submission"]: row for row in csv.DictReader(f)}


def _with_big_outputs(src: Path, dst: Path, mb: int) -> None:
    nb = nbformat.read(src, 4)
    cell = next(c for c in nb.cells if c.cell_type == "code")
    cell.outputs = [nbformat.v4.new_output("stream", name="stdout", text="x" * 1_000_000) for _ in range(mb)]
    nbformat.write(nb, dst)


@pytest.fixture(scope="module")
def batch(tmp_path_factory, one_batch_at_a_time):
    package = package_copy()
    folder = tmp_path_factory.mktemp("submitted")
    for path in SUBMISSIONS.glob("*.ipynb"):
        shutil.copy(path, folder / path.name)
    shutil.copy(SOURCE, folder / "source_solutions.ipynb")
    shutil.copy(ROOT / "notebooks" / "08_puma_assignment.ipynb", folder / "student_blank.ipynb")
    _with_big_outputs(SUBMISSIONS / "valid_alternative.ipynb", folder / "big_saved_outputs.ipynb", 25)
    nested = folder / "alice" / "ps8"                        # nbgrader's submitted/<student>/<assignment>/
    nested.mkdir(parents=True)
    shutil.copy(SUBMISSIONS / "valid_alternative.ipynb", nested / "puma.ipynb")
    (folder / ".ipynb_checkpoints").mkdir()
    shutil.copy(SUBMISSIONS / "hostile_hangs.ipynb", folder / ".ipynb_checkpoints" / "skipped.ipynb")
    originals = {p: _sha(p) for p in folder.rglob("*.ipynb")}
    out = tmp_path_factory.mktemp("out") / "gradebook.csv"
    out.write_text("an old gradebook\n")
    before = isolation.fingerprint(package / "dhlab")
    # a generous time per cell: on a busy machine the first cell (imports) can take many seconds
    argv = ["puma", str(folder), "-o", str(out), "-j", "2", "--timeout", "40", "--total-timeout", "150"]
    holds = set(Path(tempfile.gettempdir()).glob("dhlab-hold-*"))
    started = time.monotonic()
    proc = run_grader(argv, package, timeout=1800)
    yield {"rows": _read(out), "proc": proc, "feedback": out.with_name("gradebook_feedback"), "csv": out,
           "folder": folder, "originals": originals, "package": package, "before": before,
           "seconds": time.monotonic() - started,
           "holds_left": set(Path(tempfile.gettempdir()).glob("dhlab-hold-*")) - holds}
    shutil.rmtree(package, ignore_errors=True)


def _parts(row):
    return [float(row[c]) for c in ("part1_sketch", "part2_links", "part3_transforms")]


def _expected_names():
    return ({p.stem for p in SUBMISSIONS.glob("*.ipynb")}
            | {"source_solutions", "student_blank", "alice/ps8/puma", "big_saved_outputs"})


def test_every_submission_is_in_the_gradebook_and_the_batch_ends_normally(batch):
    proc, rows = batch["proc"], batch["rows"]
    assert proc.returncode == 0, proc.stderr[-3000:]
    assert set(rows) == _expected_names()
    n = len(rows)
    assert f"Graded {n} submissions" in proc.stderr and "s per submission" in proc.stderr
    assert f"{n}/{n}" in proc.stderr                          # the progress bar reached the end
    for row in rows.values():
        assert float(row["score"]) == pytest.approx(sum(_parts(row)), abs=0.02)
        assert row["max_score"] == "10"
        assert (batch["feedback"] / row["feedback"]).is_file()
        assert row["file"] == row["submission"] + ".ipynb" and len(row["sha256"]) == 64


FULL = [2, 3, 5]


@pytest.mark.parametrize("name, parts, status", [
    ("source_solutions", FULL, "ok"),
    ("valid_alternative", FULL, "ok"),
    ("alice/ps8/puma", FULL, "ok"),
    ("student_blank", [0, 0, 0], "not answered"),
    ("mistake_part1", [1.5, 3, 5], "ok"),
    ("mistake_part2", [2, 3 * 5 / 7, 5], "ok"),   # link 3 in frame 2; link 5 in a valid frame, not the one T1…T5 build
    ("mistake_part3", [2, 3, 5 * 5 / 7], "ok"),
    ("slip_alpha1", [2, 3, 5 * 6 / 7], "ok"),
    ("slip_alpha3", [2, 3, 5 * 6 / 7], "ok"),
    ("slip_theta4_offset", [2, 3, 5 * 6 / 7], "ok"),
    ("mixed_valid_frames", [2, 3 * 3 / 7, 5], "ok"),    # links 1, 2, 4, 6 not in the frames its T_k build
    ("numeric_types", FULL, "ok"),
    ("big_saved_outputs", FULL, "ok"),
    ("Ana María", [2, 3, 5 * 5 / 7], "ok"),
    ("Ana_María", FULL, "ok"),
])
def test_scores_of_right_and_wrong_answers(batch, name, parts, status):
    row = batch["rows"][name]
    assert _parts(row) == pytest.approx(parts, abs=0.01), row
    assert row["status"] == status


@pytest.mark.parametrize("name, parts, words", [
    ("hostile_raises", [2, 0, 5], ["error in cells", "RuntimeError"]),
    ("hostile_hangs", FULL, ["timeout: cell"]),
    ("hostile_ignores_interrupt", FULL, ["could not be interrupted", "run again without it"]),
    ("hostile_prints", FULL, ["output limit: printed"]),
    # a MemoryError in the cell (address-space limit), or the submission's control group full (cgroups)
    ("hostile_memory", FULL, ["memory limit reached"]),
    ("hostile_kills_kernel", FULL, ["kernel died in cell"]),
    ("hostile_kills_grader", FULL, ["PermissionError"] if AS_ROOT else ["runner was killed in cell"]),
    ("hostile_invalid_json", [0, 0, 0], ["invalid notebook", "not valid JSON"]),
    ("hostile_not_a_notebook", [0, 0, 0], ["invalid notebook", "no list of cells"]),
    ("hostile_huge_code", [0, 0, 0], ["invalid notebook", "code too large", "outputs do not count"]),
    ("hostile_monkeypatch", [2, 0, 5 * 5 / 7], ["modifies dhlab, ignored"]),
    ("hostile_weird_values", [0, 0, 0], ["unreadable answers: n_links"]),
    # as root the package is bound read-only into the kernel's private root
    ("hostile_tampers_package", FULL, ["Read-only file system"] if AS_ROOT else []),
    ("hostile_setsid_escapee", FULL, []),
    ("hostile_edits_classmates", FULL, []),
    ("hostile_kills_everything", FULL, []),
    ("hostile_fork_bomb", FULL, []),
])
def test_hostile_submissions_get_what_their_real_answers_earn_and_a_reason(batch, name, parts, words):
    row = batch["rows"][name]
    assert _parts(row) == pytest.approx(parts, abs=0.01), row
    for word in words:
        assert word in row["status"], row["status"]


def _feedback(batch, name):
    return (batch["feedback"] / batch["rows"][name]["feedback"]).read_text(encoding="utf-8")


def test_feedback_files_name_the_joint_and_the_parameter(batch):
    text = _feedback(batch, "mistake_part3")
    assert "joint 3: z2 should be parallel to z1; your α2 = -90° turns it" in text
    assert "end effector" in text and "d6 = 0.056" in text
    assert "α1: your T1 builds a valid frame 1" in _feedback(batch, "slip_alpha1")
    assert "α3 = -90° instead of 90°" in _feedback(batch, "slip_alpha3")
    slip = _feedback(batch, "slip_theta4_offset")
    assert "θ4's offset 180° instead of 0°" in slip and slip.count("✗") == 1
    blank = _feedback(batch, "student_blank")
    assert blank.count("not answered") >= 3 and "0/10 points" in blank
    raised = _feedback(batch, "hostile_raises")
    assert "raised RuntimeError: I give up on this cell" in raised and "NameError" in raised
    monkey = _feedback(batch, "hostile_monkeypatch")
    assert "no effect" in monkey and "10/10" not in monkey.splitlines()[3]
    assert "not in the one your T1…T6 build" in _feedback(batch, "mixed_valid_frames")


def test_every_student_gets_their_own_feedback_file(batch):
    rows = batch["rows"]
    files = [row["feedback"] for row in rows.values()]
    assert len(set(f.lower() for f in files)) == len(files)           # unique, even case-insensitively
    ana, ana_ = _feedback(batch, "Ana María"), _feedback(batch, "Ana_María")
    assert "Submission: Ana María\nFile: Ana María.ipynb" in ana and "5/5" not in ana
    assert "Submission: Ana_María\n" in ana_ and "10/10 points" in ana_


def test_the_old_gradebook_was_replaced_whole(batch):
    text = batch["csv"].read_text(encoding="utf-8")
    assert "an old gradebook" not in text
    assert text.splitlines()[0] == ("submission,score,max_score,status,part1_sketch,part2_links,part3_transforms,"
                                    "seconds,feedback,file,sha256,isolation")
    assert not [p for p in batch["csv"].parent.iterdir() if p.name.endswith(".tmp")]


def test_no_submission_changed_the_package_a_classmate_or_the_gradebook(batch):
    assert isolation.fingerprint(batch["package"] / "dhlab") == batch["before"]
    assert not (batch["package"] / "dhlab" / "course" / "sneaky.py").exists()
    for path, digest in batch["originals"].items():
        assert _sha(path) == digest, f"{path} was changed"
    assert "overwritten" not in batch["csv"].read_text(encoding="utf-8")
    # the honest classmates of the tamperers got exactly what their answers earn (above), and:
    assert batch["rows"]["mistake_part3"]["score"] == "8.57"


def _free_grading_users() -> set:
    """The uids of the kernel users no grader holds now (another grader on the machine, e.g. the
    other pytest worker's, holds its own users: their processes are not this batch's)."""
    free = set()
    for entry in pwd.getpwall():
        if entry.pw_name.startswith(isolation.USER_PREFIX):
            fd = isolation.claim(entry.pw_name) if AS_ROOT else None
            if fd is not None or not AS_ROOT:
                free.add(entry.pw_uid)
            if fd is not None:
                os.close(fd)
    return free


def _grading_processes(package: Path) -> list:
    """Processes still alive of this batch: running this batch's copy of dhlab (runners, kernels),
    running as a kernel user no grader holds (escapees), or, as an ordinary user, carrying a token."""
    uids, mark = _free_grading_users(), str(package).encode()
    found = []
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                if (entry.stat().st_uid in uids or mark in (entry / "cmdline").read_bytes()
                        or not AS_ROOT and b"DHLAB_GRADE_TOKEN=" in (entry / "environ").read_bytes()):
                    found.append(int(entry.name))
            except OSError:
                pass
    return found


def test_no_process_is_left_running(batch):
    """After the batch (hung, forking, killed, setsid-escaping notebooks included) nothing is left."""
    deadline = time.monotonic() + 15
    while _grading_processes(batch["package"]) and time.monotonic() < deadline:
        time.sleep(0.5)
    assert _grading_processes(batch["package"]) == []


def test_no_folder_is_left_in_tmp(batch):
    """The sandbox's temporary mount points (as root: the Python under /root made reachable)
    are removed once the kernel's paths are mounted: a class of 30 leaves no 30 folders in /tmp."""
    assert batch["holds_left"] == set()


@pytest.mark.skipif(not AS_ROOT, reason="the kernels run as their own users only when the grader is root")
def test_every_row_says_how_its_kernel_was_isolated(batch):
    ran = [row for row in batch["rows"].values() if row["seconds"] not in ("0", "0.0")]
    assert ran and all("own user, private root" in row["isolation"] for row in ran), \
        [(row["submission"], row["isolation"]) for row in ran if "private root" not in row["isolation"]]


@pytest.mark.skipif(not AS_ROOT, reason="the kernels run as their own users only when the grader is root")
def test_the_kernels_ran_as_unprivileged_users(batch):
    assert "not isolated" not in batch["proc"].stderr
    assert all("not isolated" not in row["status"] for row in batch["rows"].values())
    assert pwd.getpwnam(isolation.USER_PREFIX + "1").pw_uid != 0


def test_the_notebook_shows_the_score_of_the_gradebook(batch):
    """One checking path: for every fixture a student can run, the three check cells show
    the scores the gradebook gives (run here, in this process, as the student's kernel would)."""
    for name in ["source_solutions", "valid_alternative", "mistake_part1", "mistake_part2", "mistake_part3",
                 "slip_alpha1", "slip_alpha3", "slip_theta4_offset", "mixed_valid_frames", "numeric_types",
                 "Ana María", "student_blank"]:
        path = batch["folder"] / f"{name}.ipynb"
        ns = {"display": lambda *a, **k: None}
        for cell in nbformat.read(path, 4).cells:
            code = cell.source
            if cell.cell_type != "code" or any(f in code for f in ("_figure(", "teach(", "_table()")):
                continue
            exec(compile(code, name, "exec"), ns)
        shown = [ns[f"feedback_{k}"].score for k in (1, 2, 3)]
        assert shown == pytest.approx(_parts(batch["rows"][name]), abs=1e-9), name


def test_the_batch_of_about_thirty_is_timed(batch):
    """Not a speed check (benchmarks/bench_grade.py is): the batch's time is reported."""
    print(f"\n{len(batch['rows'])} submissions with -j 2 in {batch['seconds']:.0f} s")


# --- a grader killed mid-batch, --resume, and a package that changes -----------------------------

def test_a_killed_grader_keeps_its_rows_and_resume_continues(tmp_path):
    package = package_copy()
    try:
        folder = tmp_path / "class"
        folder.mkdir()
        for k, name in enumerate(["valid_alternative", "mistake_part3", "mistake_part1", "slip_alpha1"]):
            shutil.copy(SUBMISSIONS / f"{name}.ipynb", folder / f"s{k}_{name}.ipynb")
        out = tmp_path / "gradebook.csv"
        env = dict(os.environ, PYTHONPATH=str(package))
        proc = subprocess.Popen([sys.executable, "-m", "dhlab.grading.cli", "puma", str(folder), "-o", str(out),
                                 "-j", "1", "--timeout", "40", "-q"], env=env, start_new_session=True,
                                stderr=subprocess.DEVNULL, cwd=package)
        deadline = time.monotonic() + 300
        while time.monotonic() < deadline and (not out.exists() or len(_read(out)) < 2):
            time.sleep(0.2)
        os.killpg(proc.pid, signal.SIGKILL)                 # the grader, mid-batch
        proc.wait()
        kept = _read(out)
        assert 2 <= len(kept) < 4, kept
        done = run_grader(["puma", str(folder), "-o", str(out), "-j", "1", "--timeout", "40", "--resume", "-q"],
                      package, timeout=600)
        assert done.returncode == 0, done.stderr[-2000:]
        assert f"Resumed: {len(kept)} rows kept" in done.stderr
        rows = _read(out)
        assert len(rows) == 4
        for name, row in kept.items():
            assert rows[name] == row                           # the finished rows were not graded again
        assert {n: r["score"] for n, r in rows.items()} == {
            "s0_valid_alternative": "10", "s1_mistake_part3": "8.57", "s2_mistake_part1": "9.5",
            "s3_slip_alpha1": "9.29"}
    finally:
        shutil.rmtree(package, ignore_errors=True)


def test_the_grader_refuses_to_go_on_when_the_package_changed(tmp_path):
    """With the protections off (--isolation none) a submission can write the package: the
    grader notices before the next submission, stops, and keeps no row it cannot trust."""
    package = package_copy()
    try:
        folder = tmp_path / "class"
        folder.mkdir()
        for name in ["hostile_tampers_package", "mistake_part3", "valid_alternative"]:
            shutil.copy(SUBMISSIONS / f"{name}.ipynb", folder / f"{name}.ipynb")
        out = tmp_path / "gradebook.csv"
        proc = run_grader(["puma", str(folder), "-o", str(out), "-j", "1", "--timeout", "40", "--isolation", "none",
                       "-q"], package, timeout=600)
        assert proc.returncode == 3, proc.stderr[-2000:]
        assert "STOPPED: dhlab's installed files changed" in proc.stderr and "--resume" in proc.stderr
        assert "not isolated: isolation turned off" in proc.stderr
        assert _read(out) == {}                               # the tamperer's row is not trusted either
    finally:
        shutil.rmtree(package, ignore_errors=True)


# --- the runner alone ----------------------------------------------------------------------------


def test_the_memory_limit_really_applies_in_the_kernel(tmp_path):
    nb = write_notebook(tmp_path / "m.ipynb",
                   "import resource\nn_links = resource.getrlimit(resource.RLIMIT_AS)[0] // 2**20",
                   "too_much = bytearray(3 * 1024**3)",
                   "n_joints = 6")
    result = runner.run_notebook(nb, timeout=30, total_timeout=90, memory_mb=1024)
    assert json.loads(result.answers_json) == {"n_links": 1024, "n_joints": 6}
    assert [e[:2] for e in result.errors] == [[2, "MemoryError"]]


def test_cells_time_out_one_by_one_and_the_rest_still_run(tmp_path):
    nb = write_notebook(tmp_path / "t.ipynb", "import time\ntime.sleep(30)", "n_links = 7")
    result = runner.run_notebook(nb, timeout=2, total_timeout=40)
    assert result.timeouts == [1] and json.loads(result.answers_json) == {"n_links": 7}
    assert result.seconds < 30


def test_floods_of_printed_or_displayed_output_are_stopped(tmp_path):
    """Printed output past the cap is dropped by the kernel itself: the cell goes on (this one until
    its time limit). Displayed output is not capped in the kernel: far past the cap, the notebook is
    run again without that cell."""
    nb = write_notebook(tmp_path / "f.ipynb", "n_links = 7",
                   "while True:\n    print('x' * 10_000)",
                   "from IPython.display import HTML, display\nwhile True:\n    display(HTML('y' * 10_000))",
                   "n_joints = 6")
    result = runner.run_notebook(nb, timeout=8, total_timeout=90, output_mb=1)
    assert [c for c, _ in result.output_capped] == [2, 3]
    printed, displayed = (size for _, size in result.output_capped)
    assert 0.9e6 <= printed < 1.5e6                                   # about the 1 MB cap
    assert displayed > runner.FLOOD_FACTOR * 1e6 and result.skipped == [3]
    assert result.timeouts == [2]
    assert json.loads(result.answers_json) == {"n_links": 7, "n_joints": 6}


def test_printed_output_is_never_read_as_answers_and_numpy_values_are(tmp_path):
    nb = write_notebook(tmp_path / "p.ipynb", 'print(\'{"n_links": 7}\')\nn_joints = 5', "input('your grade?')",
                   "import numpy as np\nlink_points = [[tuple(np.array([1.0, 2.0, 3.0]))]]")
    result = runner.run_notebook(nb, timeout=20, total_timeout=40)
    assert json.loads(result.answers_json) == {"n_joints": 5, "link_points": [[[1.0, 2.0, 3.0]]]}
    assert result.errors and result.errors[0][1] == "StdinNotImplementedError"


def test_outputs_do_not_count_but_code_does(tmp_path):
    nb = tmp_path / "o.ipynb"
    _with_big_outputs(SUBMISSIONS / "valid_alternative.ipynb", nb, 3)
    assert len(runner.read_code_cells(nb)) > 5
    big = write_notebook(tmp_path / "c.ipynb", "x = '" + "y" * (runner.MAX_CODE_BYTES + 10) + "'")
    with pytest.raises(runner.NotebookError, match="code too large"):
        runner.read_code_cells(big)


def test_usage_errors(tmp_path):
    assert grade.main(["puma", str(tmp_path), "-o", str(tmp_path / "g.csv"), "-q"]) == 2   # no notebooks
    with pytest.raises(SystemExit):
        grade.main(["puma", str(tmp_path / "missing")])
    with pytest.raises(SystemExit):
        grade.main(["other", str(tmp_path)])
    proc = subprocess.run([sys.executable, "-m", "dhlab.grading.cli", "--help"], capture_output=True, text=True)
    assert proc.returncode == 0 and "SUBMISSIONS" in proc.stdout.upper() and "--resume" in proc.stdout


def _kernels_with(token) -> list:
    mark = f"DHLAB_GRADE_TOKEN={token}".encode()
    found = []
    for proc in Path("/proc").iterdir():
        if proc.name.isdigit():
            try:
                if mark in (proc / "environ").read_bytes():
                    found.append(int(proc.name))
            except OSError:
                pass
    return found


def test_a_kernel_can_be_found_while_it_runs_and_names_no_file(tmp_path):
    """The checks above can fail: a running kernel is found by its token, and its
    environment names no file of the grader (no path of a submission)."""
    nb = write_notebook(tmp_path / "slow.ipynb", "import time\ntime.sleep(60)")
    token = "test" + os.urandom(6).hex()
    proc = subprocess.Popen([sys.executable, str(runner.RUNNER), str(nb), str(tmp_path / "r.json"),
                             "--timeout", "60", "--token", token], env=dict(os.environ, TMPDIR=str(tmp_path)))
    try:
        deadline = time.monotonic() + 60
        while not _kernels_with(token) and time.monotonic() < deadline:
            time.sleep(0.3)
        pids = _kernels_with(token)
        assert pids
        environ = Path(f"/proc/{pids[0]}/environ").read_bytes()
        assert b"slow.ipynb" not in environ and b"DHLAB_GRADE_SUBMISSION" not in environ
    finally:
        proc.kill()
        proc.wait()
    isolation.kill_token(token)
    assert _kernels_with(token) == []
