"""The grader on whole notebooks: each one runs in a fresh, limited kernel; answers are scored here.

One batch (`dhlab-grade puma DIR -o gradebook.csv -j 2`) grades every submission of
tests/data/submissions (a valid alternative DH assignment, a mistake per part, and hostile
notebooks that raise, hang, ignore interrupts, flood their output, exhaust memory, kill
their kernel, kill the grader's runner, are not JSON, are not notebooks, monkeypatch
dhlab, or hold odd values), plus the course's source notebook and its student version.
The tests below read that batch's gradebook and feedback files.
"""
import csv
import json
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest

from dhlab import grade
from dhlab.grading import runner

ROOT = Path(__file__).resolve().parents[1]
SUBMISSIONS = ROOT / "tests" / "data" / "submissions"


@pytest.fixture(scope="module")
def batch(tmp_path_factory):
    folder = tmp_path_factory.mktemp("submitted")
    for path in SUBMISSIONS.glob("*.ipynb"):
        shutil.copy(path, folder / path.name)
    shutil.copy(ROOT / "notebooks" / "source" / "08_puma_assignment.ipynb", folder / "source_solutions.ipynb")
    shutil.copy(ROOT / "notebooks" / "08_puma_assignment.ipynb", folder / "student_blank.ipynb")
    nested = folder / "alice" / "ps8"                        # nbgrader's submitted/<student>/<assignment>/
    nested.mkdir(parents=True)
    shutil.copy(SUBMISSIONS / "valid_alternative.ipynb", nested / "puma.ipynb")
    (folder / ".ipynb_checkpoints").mkdir()
    shutil.copy(SUBMISSIONS / "hostile_hangs.ipynb", folder / ".ipynb_checkpoints" / "skipped.ipynb")
    out = tmp_path_factory.mktemp("out") / "gradebook.csv"
    out.write_text("an old gradebook\n")
    # a generous time per cell: on a busy machine the first cell (imports) can take seconds
    argv = ["puma", str(folder), "-o", str(out), "-j", "2", "--timeout", "20", "--total-timeout", "90"]
    proc = subprocess.run([sys.executable, "-m", "dhlab.grading.cli", *argv], capture_output=True, text=True, timeout=600)
    with open(out, newline="", encoding="utf-8") as f:
        rows = {row["submission"]: row for row in csv.DictReader(f)}
    return {"rows": rows, "proc": proc, "feedback": out.with_name("gradebook_feedback"), "csv": out,
            "folder": folder}


def _parts(row):
    return [float(row[c]) for c in ("part1_sketch", "part2_links", "part3_transforms")]


def test_every_submission_is_in_the_gradebook_and_the_batch_ends_normally(batch):
    proc, rows = batch["proc"], batch["rows"]
    assert proc.returncode == 0, proc.stderr[-2000:]
    expected = {p.stem for p in SUBMISSIONS.glob("*.ipynb")} | {"source_solutions", "student_blank", "alice/ps8/puma"}
    assert set(rows) == expected
    assert "Graded 18 submissions" in proc.stderr and "s per submission" in proc.stderr
    assert "18/18" in proc.stderr                                # the progress bar reached the end
    for row in rows.values():
        assert float(row["score"]) == pytest.approx(sum(_parts(row)), abs=0.02)
        assert row["max_score"] == "10"
        assert (batch["feedback"] / row["feedback"]).is_file()


@pytest.mark.parametrize("name, parts, status", [
    ("source_solutions", [2, 3, 5], "ok"),
    ("valid_alternative", [2, 3, 5], "ok"),
    ("alice/ps8/puma", [2, 3, 5], "ok"),
    ("student_blank", [0, 0, 0], "not answered"),
    ("mistake_part1", [1.5, 3, 5], "ok"),
    ("mistake_part2", [2, 3 * 5 / 7, 5], "ok"),
    ("mistake_part3", [2, 3, 5 * 5 / 7], "ok"),
])
def test_scores_of_right_and_wrong_answers(batch, name, parts, status):
    row = batch["rows"][name]
    assert _parts(row) == pytest.approx(parts, abs=0.01)
    assert row["status"] == status


@pytest.mark.parametrize("name, parts, words", [
    ("hostile_raises", [2, 0, 5], ["error in cells", "RuntimeError"]),
    ("hostile_hangs", [2, 3, 5], ["timeout: cell"]),
    ("hostile_ignores_interrupt", [2, 3, 5], ["could not be interrupted", "run again without it"]),
    ("hostile_prints", [2, 3, 5], ["output limit: printed"]),
    ("hostile_memory", [2, 3, 5], ["memory limit reached", "MemoryError"]),
    ("hostile_kills_kernel", [2, 3, 5], ["kernel died in cell"]),
    ("hostile_kills_grader", [2, 3, 5], ["runner was killed in cell"]),
    ("hostile_invalid_json", [0, 0, 0], ["invalid notebook", "not valid JSON"]),
    ("hostile_not_a_notebook", [0, 0, 0], ["invalid notebook", "no list of cells"]),
    ("hostile_monkeypatch", [2, 0, 5 * 5 / 7], ["modifies dhlab, ignored"]),
    ("hostile_weird_values", [0, 0, 0], ["unreadable answers: n_links"]),
])
def test_hostile_submissions_get_what_their_real_answers_earn_and_a_reason(batch, name, parts, words):
    row = batch["rows"][name]
    assert _parts(row) == pytest.approx(parts, abs=0.01), row
    for word in words:
        assert word in row["status"], row["status"]


def test_feedback_files_name_the_joint_and_the_quantity(batch):
    text = (batch["feedback"] / "mistake_part3.txt").read_text()
    assert "joint 3: z2 should be parallel to z1; your α2 = -90° turns it" in text
    assert "end effector" in text and "d6 = 0.056" in text
    blank = (batch["feedback"] / "student_blank.txt").read_text()
    assert blank.count("not answered") >= 3 and "0/10 points" in blank
    raised = (batch["feedback"] / "hostile_raises.txt").read_text()
    assert "raised RuntimeError: I give up on this cell" in raised and "NameError" in raised
    monkey = (batch["feedback"] / "hostile_monkeypatch.txt").read_text()
    assert "no effect" in monkey and "10/10" not in monkey.splitlines()[2]


def test_the_old_gradebook_was_replaced_whole(batch):
    text = batch["csv"].read_text(encoding="utf-8")
    assert "an old gradebook" not in text
    assert text.splitlines()[0].startswith("submission,score,max_score,status,part1_sketch,part2_links,part3_transforms")
    assert not [p for p in batch["csv"].parent.iterdir() if p.name.endswith(".tmp")]


def _notebook(path, *cells):
    nb = {"nbformat": 4, "nbformat_minor": 5, "metadata": {},
          "cells": [{"cell_type": "code", "metadata": {}, "source": c, "outputs": [], "execution_count": None}
                    for c in cells]}
    path.write_text(json.dumps(nb), encoding="utf-8")
    return path


def test_the_memory_limit_really_applies_in_the_kernel(tmp_path):
    nb = _notebook(tmp_path / "m.ipynb",
                   "import resource\nn_links = resource.getrlimit(resource.RLIMIT_AS)[0] // 2**20",
                   "too_much = bytearray(3 * 1024**3)",
                   "n_joints = 6")
    result = runner.run_notebook(nb, timeout=20, total_timeout=60, memory_mb=1024)
    assert json.loads(result.answers_json) == {"n_links": 1024, "n_joints": 6}
    assert [e[:2] for e in result.errors] == [[2, "MemoryError"]]


def test_cells_time_out_one_by_one_and_the_rest_still_run(tmp_path):
    nb = _notebook(tmp_path / "t.ipynb", "import time\ntime.sleep(30)", "n_links = 7")
    result = runner.run_notebook(nb, timeout=2, total_timeout=30)
    assert result.timeouts == [1] and json.loads(result.answers_json) == {"n_links": 7}
    assert result.seconds < 20


def test_floods_of_printed_or_displayed_output_are_stopped(tmp_path):
    nb = _notebook(tmp_path / "f.ipynb", "n_links = 7",
                   "while True:\n    print('x' * 10_000)",
                   "from IPython.display import HTML, display\nwhile True:\n    display(HTML('y' * 10_000))",
                   "n_joints = 6")
    result = runner.run_notebook(nb, timeout=20, total_timeout=60, output_mb=1)
    assert [c for c, _ in result.output_capped] == [2, 3]
    assert all(0.9e6 <= size < 3e6 for _, size in result.output_capped)     # about the 1 MB cap
    assert json.loads(result.answers_json) == {"n_links": 7, "n_joints": 6}


def test_printed_output_is_never_read_as_answers(tmp_path):
    nb = _notebook(tmp_path / "p.ipynb", 'print(\'{"n_links": 7}\')\nn_joints = 5', "input('your grade?')")
    result = runner.run_notebook(nb, timeout=10, total_timeout=30)
    assert json.loads(result.answers_json) == {"n_joints": 5}
    assert result.errors and result.errors[0][1] == "StdinNotImplementedError"


def test_usage_errors(tmp_path):
    assert grade.main(["puma", str(tmp_path), "-o", str(tmp_path / "g.csv"), "-q"]) == 2   # no notebooks
    with pytest.raises(SystemExit):
        grade.main(["puma", str(tmp_path / "missing")])
    with pytest.raises(SystemExit):
        grade.main(["other", str(tmp_path)])
    proc = subprocess.run([sys.executable, "-m", "dhlab.grading.cli", "--help"], capture_output=True, text=True)
    assert proc.returncode == 0 and "SUBMISSIONS" in proc.stdout.upper()


def _kernels_of(folder) -> list:
    """Process ids of running kernels that grade a notebook under ``folder`` (the runner
    names the submission in the kernel's environment)."""
    mark = f"DHLAB_GRADE_SUBMISSION={Path(folder).resolve()}".encode()
    found = []
    for proc in Path("/proc").iterdir():
        if proc.name.isdigit():
            try:
                if mark in (proc / "environ").read_bytes():
                    found.append(int(proc.name))
            except OSError:
                pass
    return found


def test_no_kernel_is_left_running(batch):
    """After the batch (hung, killed and flooding notebooks included) every kernel has ended."""
    deadline = time.monotonic() + 15
    while _kernels_of(batch["folder"]) and time.monotonic() < deadline:
        time.sleep(0.5)
    assert _kernels_of(batch["folder"]) == []


def test_a_kernel_can_be_found_while_it_runs(tmp_path):
    """The check above can fail: a running kernel is found by its submission."""
    nb = _notebook(tmp_path / "slow.ipynb", "import time\ntime.sleep(60)")
    proc = subprocess.Popen([sys.executable, str(runner.RUNNER), str(nb), str(tmp_path / "r.json"),
                             "--timeout", "60"], env=dict(os.environ, TMPDIR=str(tmp_path)))
    try:
        deadline = time.monotonic() + 60
        while not _kernels_of(tmp_path) and time.monotonic() < deadline:
            time.sleep(0.3)
        assert _kernels_of(tmp_path)
    finally:
        proc.kill()
        proc.wait()
    deadline = time.monotonic() + 15          # its kernel notices that its parent is gone
    while _kernels_of(tmp_path) and time.monotonic() < deadline:
        time.sleep(0.5)
    assert _kernels_of(tmp_path) == []
