"""A grader fault is never a score; Ctrl-C and re-runs lose nothing.

Unit-level first (a row, a status, the self-check's message, the plan of a --resume run: no
kernel runs, the runner's result is made here), then the grader itself, as a teacher runs it:
``python -m dhlab.grading.cli puma …`` in a subprocess, on notebooks that sleep, stopped with
one Ctrl-C (the running submission finishes, nothing new starts) and with two (it is stopped,
its row not written); both exit with 130, leave no copy, kernel's folder or process behind, say
the command that grades the rest, and ``--resume`` then grades every correct notebook 10/10.
"""
import csv
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from types import SimpleNamespace

import pytest

from dhlab.assignment import encode
from dhlab.grading import batch as grading_batch
from dhlab.grading import cli
from dhlab.grading.book import gradebook
from dhlab.grading.book import submission_row as rows
from dhlab.grading.release.generate import find_source
from dhlab.grading.run import cleanup, selfcheck

ROOT = Path(__file__).resolve().parents[2]
SOURCE = find_source()                               # the teacher's notebook, computed (in a temporary folder)
STUDENT = ROOT / "notebooks" / "08_puma_assignment.ipynb"
SUBMISSIONS = ROOT / "tests" / "data" / "submissions"
AGAIN = "(not the student's fault: grade again with --resume)"


# --- the runner's result, made here ------------------------------------------------------------------

def _solution_json() -> str:
    """The answers JSON a kernel writes for the teacher's solution (run here: our own code)."""
    ns = {}
    for cell in json.loads(SOURCE.read_text(encoding="utf-8"))["cells"]:
        meta = cell["metadata"].get("nbgrader", {})
        if meta.get("grade_id") == "setup" or meta.get("solution"):
            exec(compile("".join(cell["source"]), meta["grade_id"], "exec"), ns)
    ns["chain"] = ns["T1"] @ ns["T2"] @ ns["T3"] @ ns["T4"] @ ns["T5"] @ ns["T6"]
    return encode.encode_json({name: encode.to_plain(ns[name]) for name in encode.ANSWER_NAMES if name in ns})


FULL = _solution_json()


def _staged(tmp_path, copy=True):
    """A staged submission whose code-only copy is the handed-out notebook."""
    path = None
    if copy:
        path = tmp_path / "00000.ipynb"
        path.write_text(STUDENT.read_text(encoding="utf-8"), encoding="utf-8")
    return SimpleNamespace(submission="ana/puma", file="ana/puma.ipynb", sha256="a" * 64, copy=path, error="",
                           variant=None)


def _options(**kw):
    return SimpleNamespace(**{"timeout": 30, "total_timeout": 120, "memory_mb": 1024, "output_mb": 10, **kw})


def _row(tmp_path, monkeypatch, run, staged=None, **options):
    monkeypatch.setattr(rows, "run_submission", lambda *a, **k: dict(run))
    return rows.grade_submission(staged or _staged(tmp_path), _options(**options))


def _grader_error(row) -> str:
    assert row["score"] == "" and all(row[c] == "" for c in gradebook.PART_COLUMNS.values()), row
    assert row["status"].startswith("grader error: ") and AGAIN in row["status"], row["status"]
    assert gradebook.grade_again(row) and "0/10" not in row["_feedback_text"]
    return row["status"]


def _cell(source_start: str) -> int:
    """The runner's number (among all cells) of the handed-out notebook's cell starting so."""
    nb = json.loads(STUDENT.read_text(encoding="utf-8"))
    return next(k for k, c in enumerate(nb["cells"], 1) if "".join(c["source"]).startswith(source_start))


# --- item 3: a grader fault is never a score ----------------------------------------------------------

def test_a_kernel_out_of_the_teachers_memory_is_a_grader_error_that_says_what_to_change(tmp_path, monkeypatch):
    """Before: 'answers not read: the kernel did not write the answers; not answered', 0/10, kept by --resume."""
    run = {"limit": "memory", "answers_error": "the kernel did not write the answers", "errors": []}
    status = _grader_error(_row(tmp_path, monkeypatch, run, memory_mb=1024))
    assert "ran out of the 1024 MB set with --memory-mb" in status and "larger --memory-mb" in status


def test_a_memory_hog_whose_answers_were_read_keeps_its_marks(tmp_path, monkeypatch):
    run = {"limit": "memory", "errors": [[7, "MemoryError", ""]], "answers_json": FULL}
    row = _row(tmp_path, monkeypatch, run)
    assert row["score"] == "10" and "memory limit reached" in row["status"], row


@pytest.mark.parametrize("run, score, words", [
    ({"errors": [[4, "NameError", "name 'x' is not defined"]], "answers_json": "{}"}, "0", "error in cell"),
    ({"errors": [], "answers_json": "{}"}, "0", "not answered"),
    ({"errors": [[4, "RuntimeError", "mine"]], "answers_json": FULL}, "10", "RuntimeError: mine"),
])
def test_the_students_own_faults_still_score_what_they_earn(tmp_path, monkeypatch, run, score, words):
    row = _row(tmp_path, monkeypatch, run)
    assert row["score"] == score and words in row["status"] and "grader error" not in row["status"], row


def test_a_copy_removed_before_it_ran_is_a_grader_error_naming_the_file(tmp_path, monkeypatch):
    """Before: 'invalid notebook: [Errno 2] No such file …', 0/10 (after a second Ctrl-C)."""
    staged = _staged(tmp_path)
    staged.copy.unlink()
    monkeypatch.setattr(rows, "run_submission", lambda *a, **k: pytest.fail("a missing copy was run"))
    status = _grader_error(rows.grade_submission(staged, _options()))
    assert "ana/puma.ipynb" in status and "removed before it ran" in status


def test_a_copy_the_runner_cannot_read_is_a_grader_error(tmp_path, monkeypatch):
    run = {"notebook_error": "[Errno 2] No such file or directory: '/tmp/x/00003.ipynb'"}
    status = _grader_error(_row(tmp_path, monkeypatch, run))
    assert "ana/puma.ipynb" in status and "No such file" in status and "invalid notebook" not in status


def test_a_file_that_vanished_while_it_was_read_is_a_grader_error(tmp_path, monkeypatch):
    staged = _staged(tmp_path, copy=False)
    staged.sha256, staged.error = "", "cannot read the file (No such file or directory)"
    status = _grader_error(_row(tmp_path, monkeypatch, {}, staged, submissions=tmp_path))
    assert "ana/puma.ipynb could not be read" in status and str(tmp_path) in status


def test_a_file_too_large_to_grade_is_still_the_students_invalid_notebook(tmp_path, monkeypatch):
    (tmp_path / "ana").mkdir()
    (tmp_path / "ana" / "puma.ipynb").write_text("{}")
    staged = _staged(tmp_path, copy=False)
    staged.sha256, staged.error = "", "the file is 198 MB, more than 50 MB"
    row = _row(tmp_path, monkeypatch, {}, staged, submissions=tmp_path)
    assert row["score"] == "0" and row["status"].startswith("invalid notebook: the file is 198 MB"), row


def test_a_kernel_that_died_in_the_assignments_setup_cell_is_a_grader_error(tmp_path, monkeypatch):
    """The imports' cell is the assignment's: without it every answer is a NameError, a 0 that is not the
    student's. Out of memory there: the message names the limit."""
    setup = _cell("import numpy as np")
    run = {"kernel_died": [setup], "errors": [[9, "NameError", "name 'Tz' is not defined"]], "answers_json": "{}"}
    status = _grader_error(_row(tmp_path, monkeypatch, run))
    assert "cell 1 of the assignment" in status and "stopped the kernel" in status
    status = _grader_error(_row(tmp_path, monkeypatch, {**run, "limit": "memory"}, memory_mb=512))
    assert "ran out of the 512 MB set with --memory-mb" in status


def test_a_kernel_that_died_in_a_figure_after_full_answers_keeps_the_marks(tmp_path, monkeypatch):
    figure = _cell("my_robot_figure(globals())")
    row = _row(tmp_path, monkeypatch, {"kernel_died": [figure], "answers_json": FULL})
    assert row["score"] == "10" and "a cell of the assignment" in row["status"], row


def test_floods_until_no_answer_was_read_are_a_grader_error_naming_the_output_limit(tmp_path, monkeypatch):
    """Three cells that flood output once gave 0/10 for correct answers."""
    run = {"output_capped": [[4, 31_000_000], [7, 30_500_000], [9, 30_200_000]],
           "answers_error": "the kernel died or hung, and there was no time left to run the notebook again"}
    status = _grader_error(_row(tmp_path, monkeypatch, run))
    assert "larger --output-mb (now 10 MB)" in status


def test_the_output_limit_is_said_in_megabytes_of_the_limit_not_what_the_runner_received():
    """Before: an 11 MB print read 'printed 0.0 MB' (the kernel stops it; the runner counts characters)."""
    status = gradebook.status_text({"output_capped": [[5, 1200]], "output_mb": 10}, report_answered=True)
    assert status == "output limit: printed more than 10 MB in cell 5 (stopped, run again without it)"


# --- item 3: the self-check tries the teacher's memory limit with a correct notebook -------------------

def _fake_runs(monkeypatch, enough_mb):
    """The runner, faked: a correct notebook runs out of memory below ``enough_mb``."""
    seen = []

    def run(staged, limits, iso, retries=2):
        seen.append((json.loads(Path(staged.copy).read_text()), limits.memory_mb))
        if limits.memory_mb < enough_mb:
            return {"limit": "memory", "errors": [], "answers_error": "the kernel did not write the answers"}
        return {"errors": [], "answers_json": FULL}
    monkeypatch.setattr("dhlab.grading.run.selfcheck.run_submission", run)      # as selfcheck imported it
    return seen


def test_the_self_check_runs_the_teachers_solution_under_the_teachers_memory_limit(monkeypatch):
    seen = _fake_runs(monkeypatch, enough_mb=0)
    iso = SimpleNamespace(users=[], base=None)
    selfcheck.check(iso, _options(memory_mb=1536))
    (notebook, memory_mb), = seen
    assert memory_mb == 1536
    code = [c["source"] for c in notebook["cells"] if c["cell_type"] == "code"]
    assert any("import dhlab" in c for c in code) and any("\nT1 = " in c for c in code)


@pytest.mark.parametrize("memory_mb", [256, 1024])
def test_a_memory_limit_too_small_for_a_correct_notebook_stops_the_grader_naming_it(monkeypatch, memory_mb):
    """Before: --memory-mb 1024 passed the self-check (a one-line probe), and 256-896 failed it with
    advice that blamed the installation."""
    seen = _fake_runs(monkeypatch, enough_mb=1500)
    with pytest.raises(selfcheck.SelfCheckError) as failed:
        selfcheck.check(SimpleNamespace(users=[], base=None), _options(memory_mb=memory_mb))
    message = str(failed.value)
    assert f"--memory-mb {memory_mb}" in message and "With --memory-mb 2048 it earned full marks" in message
    assert "ipykernel" not in message and "install" not in message
    assert [m for _, m in seen] == [memory_mb, 2048]


# --- item 4: a re-run keeps the old rows; a removed submission is reported -----------------------------

def _old_row(name, status="ok", score="10", sha="1"):
    return {"submission": name, "score": score, "max_score": 10, "status": status, "sha256": sha}


def test_resume_keeps_a_removed_submissions_row_marked_and_grades_the_rest():
    old = [_old_row("ana"), _old_row("bob"), _old_row("eve", "grader error: x " + AGAIN, ""),
           _old_row("carl", sha="0")]
    staged = [SimpleNamespace(submission=n, sha256="1") for n in ("ana", "eve", "carl")]
    keep, removed, todo = cli._plan(old, staged, resume=True)
    assert [r["submission"] for r in keep] == ["ana"] and [s.submission for s in todo] == ["eve", "carl"]
    assert [(r["submission"], r["status"], r["score"]) for r in removed] == [("bob", "removed since the last run; ok",
                                                                               "10")]
    keep, removed, todo = cli._plan(removed, staged, resume=True)        # the next --resume: marked once
    assert removed[0]["status"] == "removed since the last run; ok"
    back = [SimpleNamespace(submission="bob", sha256="1")]                # the file is back: graded again
    assert cli._plan(removed, back, resume=True) == ([], [], back)
    assert "Removed since the last run (1): bob" in cli._removed_text(removed, resume=True)


def test_a_plain_rerun_grades_everything_and_reports_the_removed():
    staged = [SimpleNamespace(submission="ana", sha256="1")]
    keep, removed, todo = cli._plan([_old_row("ana"), _old_row("bob")], staged, resume=False)
    assert keep == [] and todo == staged and [r["submission"] for r in removed] == ["bob"]
    assert "not in the new gradebook" in cli._removed_text(removed, resume=False)


def test_a_gradebook_that_cannot_be_written_stops_the_batch_with_a_message(tmp_path, monkeypatch):
    """Item 5: the disk, not a submission: before, an OSError in a worker ended the grader with a traceback."""
    feedback = tmp_path / "feedback"
    feedback.write_text("a file where the feedback folder should be")
    batch = grading_batch.Batch(SimpleNamespace(output=tmp_path / "gradebook.csv", columns=gradebook.COLUMNS),
                                feedback, [], lambda: "unchanged")
    row = {"submission": "ana", "feedback": "ana.txt", "_feedback_text": "…", "score": "10", "status": "ok"}
    monkeypatch.setattr(grading_batch, "grade_submission", lambda *a, **k: dict(row))
    assert grading_batch.grade_one(batch, SimpleNamespace(submission="ana"), None) is None
    assert batch.refusal.startswith("cannot write ") and "--resume" in batch.refusal
    assert batch.discarded == ["ana"] and not batch.package_unchanged()        # nothing else starts
    assert cli._cannot_write(tmp_path) == "it is a folder" and cli._cannot_write(tmp_path / "new" / "gb.csv") == ""


# --- items 3 and 4: the grader, stopped with Ctrl-C --------------------------------------------------

AS_ROOT = os.geteuid() == 0


@pytest.fixture
def place():
    """A folder every user may pass through, with a TMPDIR of its own (for the leftovers' check)."""
    base = Path(tempfile.mkdtemp(prefix="dhlab-test-interrupts-"))
    base.chmod(0o711)
    (base / "tmp").mkdir(mode=0o1777)
    (base / "tmp").chmod(0o1777)
    yield base
    for pid in _running(str(base / "tmp")):
        os.kill(pid, signal.SIGKILL)
    shutil.rmtree(base, ignore_errors=True)


def _slow_submissions(folder: Path, count: int, seconds: float) -> Path:
    """``count`` correct notebooks whose first cell sleeps ``seconds``."""
    folder.mkdir()
    nb = json.loads((SUBMISSIONS / "valid_alternative.ipynb").read_text(encoding="utf-8"))
    for k in range(count):
        sleep = {"cell_type": "code", "metadata": {}, "execution_count": None, "outputs": [],
                 "source": f"import time\ntime.sleep({seconds})  # student {k}"}
        (folder / f"s{k}.ipynb").write_text(json.dumps({**nb, "cells": [sleep, *nb["cells"]]}), encoding="utf-8")
    return folder


def _grader(argv, package, place):
    env = dict(os.environ, PYTHONPATH=str(package), TMPDIR=str(place / "tmp"),
               DHLAB_GRADE_KERNELS_DIR=str(place / "tmp"))
    return subprocess.Popen([sys.executable, "-m", "dhlab.grading.cli", *argv], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, env=env, cwd=package,
                            preexec_fn=_ctrl_c_as_in_a_terminal)


def _ctrl_c_as_in_a_terminal():
    """In the grader's process: SIGINT as a terminal's foreground command gets it (a background job
    of a shell, as this test may be, ignores it, and so would the grader, like any program)."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def _running(*marks: str) -> list:
    found = []
    for entry in os.scandir("/proc"):
        if entry.name.isdigit():
            try:
                if all(m.encode() in Path(entry.path, "cmdline").read_bytes() for m in marks):
                    found.append(int(entry.name))
            except OSError:
                pass
    return found


def _wait_for_the_batch(proc, feedback: Path, seconds: float = 300) -> None:
    """Until the batch runs (the feedback folder is made after the self-check), and a kernel sleeps."""
    deadline = time.monotonic() + seconds
    while not feedback.is_dir() and time.monotonic() < deadline and proc.poll() is None:
        time.sleep(0.2)
    assert proc.poll() is None and feedback.is_dir(), proc.communicate()[1][-2000:]
    time.sleep(4)


def _rows(path: Path) -> dict:
    with open(path, newline="", encoding="utf-8-sig") as f:
        return {r["submission"]: r for r in csv.DictReader(f)}


def _no_leftovers(place: Path) -> None:
    left = [p.name for p in (place / "tmp").iterdir() if p.name.startswith(cleanup.LEFTOVERS)]
    assert left == [], left                      # copies, kernels' and runners' folders all removed
    time.sleep(0.5)
    assert _running(str(place / "tmp")) == []    # no runner or kernel still running


def test_one_ctrl_c_lets_the_running_submission_finish_and_starts_no_other(package, place):
    subs = _slow_submissions(place / "subs", 3, 10)
    out = place / "gradebook.csv"
    argv = ["puma", str(subs), "-o", str(out), "-j", "1"]
    proc = _grader(argv, package, place)
    _wait_for_the_batch(proc, place / "gradebook_feedback")
    proc.send_signal(signal.SIGINT)
    _, err = proc.communicate(timeout=240)
    assert proc.returncode == 130, err[-3000:]
    assert "Traceback" not in err and "no new submission starts" in err
    assert f"dhlab-grade puma {subs} -o {out} -j 1 --resume" in err, err[-2000:]
    graded = _rows(out)
    assert [(r["submission"], r["score"], r["status"]) for r in graded.values()] == [("s0", "10", "ok")]
    _no_leftovers(place)
    (subs / "s0.ipynb").unlink()                  # removed since the last run: reported, its row kept
    proc = _grader([*argv, "--resume", "-q"], package, place)
    _, err = proc.communicate(timeout=600)
    assert proc.returncode == 0, err[-3000:]
    graded = _rows(out)
    assert {n: (r["score"], r["status"]) for n, r in graded.items()} == {
        "s0": ("10", "removed since the last run; ok"), "s1": ("10", "ok"), "s2": ("10", "ok")}
    assert "Removed since the last run (1): s0" in err
    _no_leftovers(place)


def test_two_ctrl_c_stop_the_running_submissions_without_writing_their_rows(package, place):
    """Before: the grader ended while its workers ran, and the rest became 0/10 'invalid notebook: [Errno 2]
    No such file' rows that --resume kept. A plain re-run stopped early keeps the old gradebook as it was."""
    subs = _slow_submissions(place / "subs", 3, 60)
    out = place / "gradebook.csv"
    out.write_text("the teacher's old gradebook\n", encoding="utf-8")
    proc = _grader(["puma", str(subs), "-o", str(out), "-j", "2"], package, place)
    _wait_for_the_batch(proc, place / "gradebook_feedback")
    assert len(_running(str(place / "tmp"), "runner.py")) == 2
    started = time.monotonic()
    proc.send_signal(signal.SIGINT)
    time.sleep(1)
    proc.send_signal(signal.SIGINT)
    _, err = proc.communicate(timeout=120)
    assert proc.returncode == 130 and time.monotonic() - started < 40, err[-3000:]
    assert "Traceback" not in err and "Stopping" in err
    assert out.read_text(encoding="utf-8") == "the teacher's old gradebook\n"      # untouched
    assert f"To grade: dhlab-grade puma {subs} -o {out} -j 2" in err
    _no_leftovers(place)
    assert not list((place / "gradebook_feedback").iterdir())                       # no feedback either
