"""The PUMA grader on submissions at the edge, one test each: a grader error, a kernel that died or
an answer cell that does not parse is never the student's 0; after a flipped frame the feedback names
only the robot's own rows; zero is printed as 0, never -0; cells are named as a student finds them.

Unit-level: the functions that build a gradebook row, its status and its feedback are called
directly, on answers built here; no kernel runs.
"""
import dataclasses
import json
from pathlib import Path
from types import SimpleNamespace

import pytest

from dhlab import assignment as A
from dhlab.assignment import answers as ans
from dhlab.assignment import checks
from dhlab.assignment.checks.analysis import point_text
from dhlab.grading import cli
from dhlab.grading.book import gradebook
from dhlab.grading.book import submission_row as rows
from dhlab.grading.release.generate import find_source, student_notebook

q1, q2, q3, q4, q5, q6 = A.joint_variables(6)
ROOT = Path(__file__).resolve().parents[2]
SOURCE = find_source()                               # the teacher's notebook, computed (in a temporary folder)
STUDENT = ROOT / "notebooks" / "08_puma_assignment.ipynb"
KERNEL_DIED = "RuntimeError: Kernel died before replying to kernel_info"
SYNTAX = ("closing parenthesis '}' does not match opening parenthesis '[' on line 11 (98695007.py, line 14)")


def _solution_namespace():
    """The source notebook's setup cell and solution code, run here (our own code)."""
    ns = {}
    for cell in json.loads(SOURCE.read_text(encoding="utf-8"))["cells"]:
        meta = cell["metadata"].get("nbgrader", {})
        if meta.get("grade_id") == "setup" or meta.get("solution"):
            exec(compile("".join(cell["source"]), meta["grade_id"], "exec"), ns)
    return ns


def _report(ns):
    ns["chain"] = ns["T1"] @ ns["T2"] @ ns["T3"] @ ns["T4"] @ ns["T5"] @ ns["T6"]
    return checks.check_all(ans.answers_from_namespace(ns))


def _wrong(report):
    return [item for item in report.part("part3").items if item.ok is False]


def _staged(tmp_path, notebook=None):
    """A staged submission whose code-only copy is ``notebook`` (the student notebook by default)."""
    copy = tmp_path / "00000.ipynb"
    copy.write_text(json.dumps(notebook or json.loads(STUDENT.read_text(encoding="utf-8"))), encoding="utf-8")
    return SimpleNamespace(submission="s03_sympy_extras", file="s03_sympy_extras.ipynb", sha256="a" * 64,
                           copy=copy, error="", variant=None)


def _options():
    return SimpleNamespace(timeout=30, total_timeout=120, memory_mb=2048, output_mb=10)


def _not_graded(row):
    assert row["score"] == "" and all(row[c] == "" for c in gradebook.PART_COLUMNS.values()), row
    assert row["status"].startswith("grader error: ")
    assert row["status"].endswith("(not the student's fault: grade again with --resume)"), row["status"]
    text = row["_feedback_text"]
    assert "not graded" in text.lower() and "grader error" in text and "grade it again" in text
    assert "0/10" not in text and "not answered" not in text
    assert gradebook.grade_again(row)


# --- a grader error is not the student's 0 -------------------------------------------------------

def test_a_grader_exception_gives_a_row_that_says_not_graded(tmp_path):
    row = rows.error_row(_staged(tmp_path), RuntimeError("Kernel died before replying to kernel_info"))
    _not_graded(row)
    assert KERNEL_DIED in row["status"]


def test_a_run_the_grader_failed_on_gives_a_row_that_says_not_graded(tmp_path, monkeypatch):
    monkeypatch.setattr(rows, "run_submission", lambda *a, **k: {"grader_error": KERNEL_DIED, "errors": []})
    row = rows.grade_submission(_staged(tmp_path), _options())
    _not_graded(row)
    assert row["status"] == f"grader error: {KERNEL_DIED} (not the student's fault: grade again with --resume)"


@pytest.mark.parametrize("status, again", [
    (f"grader error: {KERNEL_DIED} (not the student's fault: grade again with --resume)", True),
    (f"grader error: {KERNEL_DIED}; not answered", True),               # a gradebook written before the fix
    ("variant tampered: …; grader error: x (not the student's fault: grade again with --resume)", True),
    ("ok", False), ("not answered", False), ("error in cell 7 (NameError: name 'x' is not defined)", False),
])
def test_resume_grades_a_grader_error_again(status, again):
    assert gradebook.grade_again({"status": status, "score": ""}) is again


def test_the_summary_and_the_progress_bar_take_a_row_without_score():
    rows = [{"submission": "a", "score": "", "max_score": 10, "status": "grader error: x (not the student's "
             "fault: grade again with --resume)"},
            {"submission": "b", "score": "8", "max_score": 10, "status": "ok"}]
    summary = cli.summary(rows, 10.0, 1)
    assert "Mean score 8.00/10" in summary and "not graded (grader error): 1" in summary
    stream = SimpleNamespace(isatty=lambda: False, lines=[], write=lambda s: stream.lines.append(s),
                             flush=lambda: None)
    cli.Progress(2, stream=stream).step(rows[0])
    assert "a: not graded" in stream.lines[0]


# --- a kernel that died in a locked cell of the assignment ----------------------------------------

def _numbered(nb):
    """[(number among all cells, source)] of the code cells, as the runner numbers them."""
    return [(k, "".join(c["source"])) for k, c in enumerate(nb["cells"], start=1) if c["cell_type"] == "code"]


def test_a_kernel_that_died_in_a_cell_of_the_assignment_does_not_blame_the_student():
    nb = json.loads(STUDENT.read_text(encoding="utf-8"))
    cells = gradebook.Cells(_numbered(nb))
    figure = next(k for k, c in enumerate(nb["cells"], 1) if "".join(c["source"]) == "my_robot_figure(globals())")
    status = gradebook.status_text({"kernel_died": [figure]}, report_answered=True, cells=cells)
    assert status.startswith("kernel died in cell 12 (a cell of the assignment: \"my_robot_figure(globals())\"")
    assert "run again without it" not in status and status.endswith("grade again with --resume)")
    assert gradebook.grade_again({"status": status})
    answer = next(k for k, c in enumerate(nb["cells"], 1) if "".join(c["source"]).startswith("# Part 2"))
    mine = gradebook.status_text({"kernel_died": [answer]}, report_answered=True, cells=cells)
    assert mine == "kernel died in cell 7 (run again without it)" and not gradebook.grade_again({"status": mine})


def test_the_released_your_robot_cell_is_a_cell_of_the_assignment():
    from dhlab.assignment import variants
    from dhlab.assignment.notebook_cells import SEAM_CELL_ID, release_notebook
    record = {"variant": variants.variant("kr5", "ana").to_dict(), "student_id": "ana"}
    nb, _ = release_notebook(student_notebook(json.loads(SOURCE.read_text(encoding="utf-8"))), record, figures=False)
    cells = gradebook.Cells(_numbered(nb))
    seam = next(k for k, c in enumerate(nb["cells"], 1) if c.get("id") == SEAM_CELL_ID)
    table = next(k for k, c in enumerate(nb["cells"], 1) if "".join(c["source"]) == "my_robot.axes_table()")
    assert cells.of_assignment(seam) and cells.of_assignment(table)
    assert "a cell of the assignment" in gradebook.status_text({"stuck": [seam]}, True, cells=cells)


# --- the rows after a flipped frame are the robot's own ----------------------------------------

@pytest.mark.parametrize("name, T, later", [
    ("T5", lambda: A.Tz(q5, 0) @ A.Tx(90, 0), "your T6 is written for frame 5"),
    ("T4", lambda: A.Tz(q4, 0.4318) @ A.Tx(-90, 0), "your T5 and T6 are written for frame 4"),
    ("T1", lambda: A.Tz(q1, 0) @ A.Tx(-90, 0), "your T2…T6 are written for frame 1"),
])
def test_a_flip_message_names_only_the_rows_the_robot_has(name, T, later):
    ns = _solution_namespace()
    ns[name] = T()
    wrong = _wrong(_report(ns))
    assert [w.label.split(" ")[0] for w in wrong] == [name]
    assert later in wrong[0].message and "T7" not in wrong[0].message, wrong[0].message


# --- zero is printed as 0 -------------------------------------------------------------------------

def test_a_point_near_zero_prints_without_a_minus_sign():
    assert point_text([-0.4318, -1e-17, 0.15005]) == "(-0.4318, 0.0000, 0.1500)"
    assert point_text([-0.0, -4e-5, 1.0]) == "(0.0000, 0.0000, 1.0000)"


def test_a_constant_of_zero_in_theta_prints_as_0_degrees():
    """Other valid frames (z2 and z4 turned over), the +180° of θ3 forgotten; -q3 had
    the constant -0.0 (the answers, as JSON from the student's kernel, can still carry it)."""
    ns = _solution_namespace()
    ns.update(T1=A.Tz(q1 + 180, 0) @ A.Tx(-90, 0), T2=A.Tz(q2 + 180, 0.15005) @ A.Tx(180, 0.4318),
              T3=A.Tz(-q3, 0) @ A.Tx(-90, -0.0203), T4=A.Tz(q4 + 180, 0.4318) @ A.Tx(-90, 0),
              T5=A.Tz(-q5 + 180, 0) @ A.Tx(-90, 0), T6=A.Tz(q6 - 90, 0) @ A.Tx(0, 0))
    ns["chain"] = ns["T1"] @ ns["T2"] @ ns["T3"] @ ns["T4"] @ ns["T5"] @ ns["T6"]
    answers = ans.answers_from_namespace(ns)
    answers.T[2] = dataclasses.replace(answers.T[2], theta=ans.Term(-0.0, 3, -1))
    wrong = _wrong(checks.check_all(answers))
    assert [w.label.split(" ")[0] for w in wrong] == ["T3"]
    assert "(yours: 0°)" in wrong[0].message and "-0°" not in wrong[0].message, wrong[0].message


def test_the_nearest_frames_point_of_a_wrong_link_has_no_minus_zero():
    """Link 2 drawn with its origin at A."""
    ns = _solution_namespace()
    points = ans.answers_from_namespace(ns).link_points
    ns["link_points"] = [list(p) for p in points]
    ns["link_points"][2] = [(0, 0, 0.15005), (0.4318, 0, 0.15005)]
    item = _report(ns).part("part2").items[2]
    assert item.ok is False and "(-0.4318, 0.0000, 0.1500)" in item.message and "-0.0000" not in item.message


# --- an answer cell that does not parse was not read, and cells are named as a student finds them --

def test_a_syntax_error_in_the_part2_answer_cell_says_not_read(tmp_path, monkeypatch):
    ns = _solution_namespace()
    ns["chain"] = ns["T1"] @ ns["T2"] @ ns["T3"] @ ns["T4"] @ ns["T5"] @ ns["T6"]
    raw = {name: ans.to_plain(ns[name]) for name in ans.ANSWER_NAMES if name in ns and name != "link_points"}
    run = {"errors": [[11, "SyntaxError", SYNTAX]], "answers_json": ans.encode_json(raw)}
    monkeypatch.setattr(rows, "run_submission", lambda *a, **k: dict(run))
    row = rows.grade_submission(_staged(tmp_path), _options())
    assert (row["score"], row["part2_links"]) == ("7", "0")
    assert row["status"] == ("error in cell 7 (SyntaxError on line 14: closing parenthesis '}' does not match "
                             "opening parenthesis '[' on line 11)")
    text = row["_feedback_text"]
    assert ("Part 2 (each link in its own frame): 0/3 points, not read: your answer cell (cell 7) has a "
            "SyntaxError on line 14") in text
    assert '- cell 7 ("# Part 2: write link_points below: for each…") raised SyntaxError on line 14' in text
    assert "cells counted from the top, code cells only" in text
    assert ".py" not in text and "cell 11" not in text and "not answered" not in text


def test_an_error_in_a_cell_of_its_own_leaves_the_parts_as_they_are():
    cells = gradebook.Cells([(2, "import numpy as np"), (13, "print(lenghts)")])
    assert cells.answer_parts(13) == [] and cells.number(13) == 2
    assert gradebook.status_text({"errors": [[13, "NameError", "name 'lenghts' is not defined"]]}, True,
                                 cells=cells) == "error in cell 2 (NameError: name 'lenghts' is not defined)"
    assert gradebook.status_text({"tampering": ["cell 13: redefines check_part1"]}, True, cells=cells) == \
        "modifies dhlab, ignored (cell 2: redefines check_part1)"


def test_part1_accepts_either_case_where_a_sliding_axis_may_be_drawn_to_meet_the_other_or_not():
    """A prismatic joint fixes only its axis's direction: drawn through the other axis the pair
    intersects, drawn beside it the pair is skew. Both are valid sketches (between two turning
    joints the case is fixed, and the other one is still wrong)."""
    from dhlab.assignment import reference as puma
    from dhlab.assignment.answers import Answers
    from dhlab.assignment.family import family_names
    from dhlab.assignment.model import build

    checked = 0
    for key in family_names():
        robot = build(key)
        cases = [puma.relation(robot.axes[i - 1], robot.axes[i]).kind for i in range(1, robot.n)]
        for i, case in enumerate(cases, start=1):
            if case not in ("intersect", "skew"):
                continue
            other = "skew" if case == "intersect" else "intersect"
            answers = Answers(n_links=robot.n + 1, n_joints=robot.n, joint_types=list(robot.kinds),
                              x_cases=cases[:i - 1] + [other] + cases[i:])
            item = checks.check_part1(answers, ref=robot).items[2 + i]
            sliding = "P" in robot.kinds[i - 1:i + 1]
            assert item.ok is sliding, (key, i, item)
            checked += sliding
    assert checked >= 1          # the family has such a pair (the Stanford arm's, at least)
