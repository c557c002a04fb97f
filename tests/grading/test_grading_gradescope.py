"""The Gradescope autograder, run as Gradescope runs it (dhlab.grading.export.gradescope_local).

``dhlab-grade export gradescope`` writes autograder.zip; the harness runs its setup.sh once
(dhlab from the zip's wheel, offline) and then every submission in a fresh /autograder tree
in a temporary folder. Each results.json is checked against Gradescope's documented schema
and against the scores ``dhlab-grade puma`` gives the same notebooks (tests/grading/test_grading_runner.py):
a valid notebook, a wrong one, hostile ones (an endless loop, a raise), no notebook at all,
a grader that cannot run kernels (an autograder failure: no results.json, never a zero), and
personal variants, whose student is named by submission_metadata.json.
"""
import json
import os
import shutil
import zipfile
from pathlib import Path

import pytest

from dhlab.grading.export import gradescope
from dhlab.grading.export import gradescope_local as GL
from dhlab.grading.export.command import main as export

ROOT = Path(__file__).resolve().parents[2]
SUBMISSIONS = ROOT / "tests" / "data" / "submissions"
SECRET = b"gradescope-test-secret-0123456789"
LIMITS = ["--timeout", "8", "--total-timeout", "90"]


def _parts(results):
    return [t["score"] for t in results["tests"]]


def _valid(results):
    assert GL.problems(results) == [], GL.problems(results)
    assert [t["max_score"] for t in results["tests"]] == [2, 3, 5]
    assert results["score"] == pytest.approx(sum(_parts(results)), abs=0.011)
    assert all(t["visibility"] == "visible" and t["output"].startswith(f"Part {k}") for k, t in
               enumerate(results["tests"], start=1))


@pytest.fixture(scope="module")
def puma(tmp_path_factory, one_batch_at_a_time):
    tmp = tmp_path_factory.mktemp("gradescope")
    assert export(["gradescope", "-o", str(tmp / "autograder.zip"), *LIMITS]) == 0
    return GL.Harness(tmp / "autograder.zip", tmp)


def test_the_zip_holds_what_gradescope_runs(puma):
    with zipfile.ZipFile(puma.zip) as z:
        names = set(z.namelist())
        modes = {i.filename: i.external_attr >> 16 for i in z.infolist()}
        config = json.loads(z.read(gradescope.CONFIG))
    assert {"setup.sh", "run_autograder", gradescope.CONFIG} <= names
    assert any(n.startswith("dhlab-") and n.endswith(".whl") for n in names)
    assert modes["setup.sh"] & 0o111 and modes["run_autograder"] & 0o111
    assert gradescope.SECRET not in names and not config["variants"]
    # the harness installed dhlab from the wheel, not from this checkout
    where = puma.python.parent.parent
    assert list(where.glob("lib/python*/site-packages/dhlab/grading/export/gradescope.py"))


def test_a_valid_notebook_gets_full_marks(puma):
    out = puma.run([SUBMISSIONS / "valid_alternative.ipynb"])
    assert out.returncode == 0, out.log[-2000:]
    _valid(out.results)
    assert out.results["score"] == 10 and _parts(out.results) == [2, 3, 5]


def test_a_wrong_notebook_gets_its_marks_and_the_feedback_per_part(puma):
    out = puma.run([SUBMISSIONS / "mistake_part3.ipynb"])
    _valid(out.results)
    part1, part2, part3 = out.results["tests"]
    assert (part1["score"], part2["score"]) == (2, 3) and 0 < part3["score"] < 5
    assert "✗ T2" in part3["output"] and "✗" not in part1["output"]


@pytest.mark.parametrize("name, parts, status", [("hostile_hangs", [2, 3, 5], "timeout"),
                                                 ("hostile_raises", [2, 0, 5], "RuntimeError")])
def test_hostile_notebooks_are_scored_on_their_answers(puma, name, parts, status):
    out = puma.run([SUBMISSIONS / f"{name}.ipynb"])
    _valid(out.results)
    assert _parts(out.results) == parts
    assert status in out.results["output"]


def test_no_notebook_is_the_students_to_fix(puma, tmp_path):
    (tmp_path / "notes.txt").write_text("my answers are in my head")
    out = puma.run([tmp_path / "notes.txt"])
    assert GL.problems(out.results) == [] and out.results["score"] == 0
    assert "No notebook" in out.results["output"]


def test_a_grader_that_cannot_run_kernels_writes_no_results(puma, tmp_path):
    """An autograder failure (Gradescope: 'The autograder failed to execute correctly'), never a
    zero, and the log says why: here a memory limit too small for any kernel, set at export."""
    if os.geteuid() != 0:
        pytest.skip("kernels run as another user only when the grader is root")
    import copy
    assert export(["gradescope", "-o", str(tmp_path / "tiny.zip"), "--memory-mb", "40", *LIMITS]) == 0
    tiny = copy.copy(puma)
    tiny.zip = tmp_path / "tiny.zip"     # the same installed wheel, the options of this zip
    out = tiny.run([SUBMISSIONS / "valid_alternative.ipynb"])
    assert out.results is None and out.returncode != 0
    assert "self-check failed" in out.log and "--memory-mb 40" in out.log, out.log[-3000:]
    assert "not the student's fault" in out.log


def test_results_of_a_row_follow_the_schema():
    row = {"score": "7.5", "status": "ok", "part1_sketch": "2", "part2_links": "0.5", "part3_transforms": "5",
           "_part_text": {"part1": "Part 1 (the sketch): 2/2 points", "part2": "Part 2 (…): 0.5/3 points",
                          "part3": "Part 3 (…): 5/5 points"},
           "_feedback_text": "Submission: x\nFile: x.ipynb\nStatus: ok\n\nPUMA 560 assignment: 7.5/10 points\n\n"
                             "Part 1 (the sketch): 2/2 points\n\nPart 2 (…): 0.5/3 points\n\nPart 3 (…): 5/5 points\n"}
    results = gradescope.results(row)
    assert GL.problems(results) == [] and results["score"] == 7.5 and _parts(results) == [2, 0.5, 5]
    assert results["output"] == "Status: ok\n"                  # the parts are the tests' outputs, not repeated
    # inside Gradescope's container the container is the boundary: no "not isolated" for the student to read
    not_isolated = "ok (not isolated: no private mount namespace)"
    row.update(status=not_isolated,
               _feedback_text=row["_feedback_text"].replace("Status: ok", f"Status: {not_isolated}"))
    assert gradescope.results(row)["output"] == "Status: ok\n"
    assert "not isolated" in gradescope.results(row)["extra_data"]["status"]
    assert GL.problems({"score": "10", "tests": [{"score": 6, "max_score": 5, "visibility": "public"}]}) == [
        "score is not a number", "tests[0] scores more than its max_score",
        f"tests[0].visibility 'public' is not one of {gradescope.VISIBILITIES}"]


# --- personal variants: the student named by submission_metadata.json ------------------------------------

@pytest.fixture(scope="module")
def variants(tmp_path_factory, one_batch_at_a_time):
    from dhlab.grading.release import notebooks as R
    tmp = tmp_path_factory.mktemp("gradescope-variants")
    (tmp / "roster.csv").write_text("email,name\nana@uni.edu,Ana\nbruno@uni.edu,Bruno\n", encoding="utf-8")
    secret = tmp / "secret.key"
    secret.write_bytes(SECRET + b"\n")
    assert R.main(["release", str(tmp / "roster.csv"), "-o", str(tmp / "release"), "--secret-file", str(secret),
                   "--family", "all", "--id-column", "email"]) == 0
    assert export(["gradescope", "-o", str(tmp / "autograder.zip"), "--secret-file", str(secret),
                   "--release", str(tmp / "release"), *LIMITS]) == 0
    return tmp, GL.Harness(tmp / "autograder.zip", tmp / "harness")


def _solved(tmp, student, folder):
    from support.solved_notebooks import released_robot, solved
    files = {r["student_id"]: r["file"] for r in _manifest(tmp)}
    nb = json.loads((tmp / "release" / files[student]).read_text(encoding="utf-8"))
    path = folder / "my_work.ipynb"                      # Gradescope keeps any file name
    path.write_text(json.dumps(solved(nb, released_robot(nb))), encoding="utf-8")
    return path


def _manifest(tmp):
    import csv
    with open(tmp / "release" / "_teacher" / "manifest.csv", newline="", encoding="utf-8-sig") as f:
        return list(csv.DictReader(f))


def test_the_variants_zip_carries_the_secret_and_the_roster(variants):
    tmp, harness = variants
    with zipfile.ZipFile(harness.zip) as z:
        names = set(z.namelist())
    assert {gradescope.SECRET, "release/_teacher/variants.json", "release/_teacher/manifest.csv"} <= names
    # no student's notebook: the one notebook is the teacher's solution, for the self-check
    assert [n for n in names if n.endswith(".ipynb")] == [gradescope.SOLUTION]


def test_a_variant_is_graded_against_the_submitters_robot(variants, tmp_path):
    tmp, harness = variants
    ana = _solved(tmp, "ana@uni.edu", tmp_path)
    out = harness.run([ana], GL.metadata("ana@uni.edu", "Ana"))
    assert out.returncode == 0, out.log[-2000:]
    _valid(out.results)
    assert out.results["score"] == 10 and out.results["extra_data"]["variant_status"] == "ok"
    # Bruno hands in Ana's notebook: graded against Bruno's own robot, and the output says so
    out = harness.run([ana], GL.metadata("Bruno@uni.edu", "Bruno"))
    _valid(out.results)
    assert out.results["extra_data"]["variant_status"] == "other_student"
    assert "other_student" in out.results["output"] and out.results["score"] < 10


def test_a_submitter_not_in_the_roster_is_an_autograder_failure(variants, tmp_path):
    tmp, harness = variants
    out = harness.run([_solved(tmp, "ana@uni.edu", tmp_path)], GL.metadata("eve@elsewhere.org", "Eve"))
    assert out.results is None and out.returncode != 0
    assert "eve@elsewhere.org" in out.log and "matches no student of the roster" in out.log


def test_export_refuses_variants_without_the_release(tmp_path, capsys):
    secret = tmp_path / "secret.key"
    secret.write_bytes(SECRET + b"\n")
    assert export(["gradescope", "-o", str(tmp_path / "a.zip"), "--secret-file", str(secret)]) == 2
    assert "--release" in capsys.readouterr().err and not (tmp_path / "a.zip").exists()
    shutil.rmtree(tmp_path, ignore_errors=True)


DAEMON = r'''import os, sys
MARK, RESULTS = {mark!r}, {results!r}
LOOP = ("import glob, sys, time\n"
        "for _ in range(600):  # a minute: rewrite any results.json it can reach\n"
        "    for path in glob.glob(sys.argv[2]):\n"
        "        try: open(path, 'w').write('{{\"score\": 100, \"output\": \"forged\", \"tests\": []}}')\n"
        "        except OSError: pass\n"
        "    time.sleep(0.1)\n")
started, proof = os.pipe()                # close-on-exec: the daemon's exec closes its copy
if os.fork() == 0:                       # a daemon: out of the kernel's group and parent, it waits
    os.close(started)
    os.setsid()
    if os.fork() == 0:
        null = os.open(os.devnull, os.O_RDWR)
        for fd in (0, 1, 2):
            os.dup2(null, fd)
        os.execv(sys.executable, [sys.executable, "-c", LOOP, MARK, RESULTS])   # MARK: seen in ps
    os._exit(0)
os.close(proof)
os.read(started, 1)                      # end of file: the daemon runs its loop (on a loaded machine
os.close(started)                        # the notebook could otherwise end before the exec)
print("daemon started")'''


def _processes_with(mark: str) -> list:
    """The pids whose command line holds ``mark``."""
    found = []
    for entry in os.scandir("/proc"):
        if entry.name.isdigit():
            try:
                if mark.encode() in Path(entry.path, "cmdline").read_bytes():
                    found.append(int(entry.name))
            except OSError:
                pass
    return found


def _with_cell(source: Path, out: Path, code: str) -> Path:
    nb = json.loads(source.read_text(encoding="utf-8"))
    nb["cells"].append({"cell_type": "code", "execution_count": None, "id": "daemon", "metadata": {},
                        "outputs": [], "source": code})
    out.write_text(json.dumps(nb), encoding="utf-8")
    return out


def test_a_daemon_the_notebook_forks_cannot_rewrite_the_result(puma, tmp_path):
    """A daemon (setsid, double fork) that tries to rewrite results.json for a minute: the score
    stays the notebook's, and the daemon is seen while the grader runs, gone once it has finished."""
    import threading
    import time
    mark = f"dhlab-daemon-{os.getpid()}-{time.monotonic_ns()}"
    seen, done = [], threading.Event()

    def watch():                         # the daemon's proof of life: its command line, in /proc
        while not done.is_set():
            seen.extend(_processes_with(mark))
            time.sleep(0.05)

    watcher = threading.Thread(target=watch)
    watcher.start()
    try:
        code = DAEMON.format(mark=mark, results=str(puma.folder / "autograder-*" / "results" / "results.json"))
        out = puma.run([_with_cell(SUBMISSIONS / "valid_alternative.ipynb", tmp_path / "daemon.ipynb", code)])
    finally:
        done.set()
        watcher.join()
    _valid(out.results)
    assert out.results["score"] == 10 and "forged" not in json.dumps(out.results)
    assert seen, "the daemon never ran: the test proves nothing"
    assert _processes_with(mark) == [], "the daemon outlived the grading"


def test_a_kernel_that_would_run_as_root_is_refused(puma, tmp_path):
    """As root with no sandbox user (here: exported with --isolation none) the autograder grades
    nothing: no results.json (an autograder failure), never a score the notebook could forge."""
    if os.geteuid() != 0:
        pytest.skip("Gradescope's case: the autograder runs as root")
    import copy
    assert export(["gradescope", "-o", str(tmp_path / "none.zip"), "--isolation", "none", *LIMITS]) == 0
    unsafe = copy.copy(puma)
    unsafe.zip = tmp_path / "none.zip"   # the same installed wheel, the options of this zip
    out = unsafe.run([SUBMISSIONS / "valid_alternative.ipynb"])
    assert out.results is None and out.returncode != 0, out.log[-2000:]
    assert "refused to run the student's notebook as root" in out.log and "not the student's fault" in out.log
