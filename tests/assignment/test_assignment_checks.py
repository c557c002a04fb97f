"""The PUMA assignment's fair checks, its answers as plain data, and the student notebook.

Fast tests, no kernels: the checks are run on namespaces built here, as the notebook's
check cells and the grader build them (same plain-data path). The grader's runs of
whole notebooks are in tests/grading/test_grading_runner.py.
"""
import doctest
import importlib
import json
import math
import re
from pathlib import Path

import numpy as np
import pytest

import dhlab
from dhlab import assignment as A
from dhlab.assignment import answers as ans
from dhlab.assignment import checks, encode
from dhlab.assignment import reference as R
from dhlab.assignment import valid_frames as VF
from dhlab.errors import DHLabError
from dhlab.grading import atomic_file
from dhlab.grading.book import gradebook
from dhlab.grading.release import generate

ROOT = Path(__file__).resolve().parents[2]
SOURCE = generate.find_source()                         # the teacher's notebook: computed, in a temporary folder
STUDENT = ROOT / "notebooks" / "08_puma_assignment.ipynb"
q1, q2, q3, q4, q5, q6 = A.joint_variables(6)
QS = (q1, q2, q3, q4, q5, q6)


@pytest.mark.parametrize("name", ["assignment.reference", "assignment.valid_frames", "assignment.encode",
                                  "assignment.answers", "assignment.checks", "assignment.checks.analysis",
                                  "assignment.checks.links", "assignment.checks.transforms",
                                  "grading.book.gradebook", "grading.release.generate", "grading.run.runner",
                                  "grading.run.kernel", "grading.run.read_answers",
                                  "grading.run.notebook_code", "grading.run.sandbox", "grading.run.isolation",
                                  "grading.run.staging", "grading.cli"])
def test_docstring_examples_of_the_grading_modules(name):
    module = importlib.import_module(f"dhlab.{name}")
    result = doctest.testmod(module, optionflags=doctest.NORMALIZE_WHITESPACE)
    assert result.failed == 0


# --- helpers: answers as a student's notebook would hold them ---------------------------------

def _solution_namespace():
    """The source notebook's setup cell and solution code, run here (our own code)."""
    nb = json.loads(SOURCE.read_text(encoding="utf-8"))
    ns = {}
    for cell in nb["cells"]:
        meta = cell["metadata"].get("nbgrader", {})
        source = "".join(cell["source"])
        if meta.get("grade_id") == "setup" or meta.get("solution"):
            exec(compile(source, meta["grade_id"], "exec"), ns)
    return ns


def _namespace_from_frames(frames):
    """A valid answer built from any valid set of DH frames (home pose)."""
    ns = _solution_namespace()
    ref = R.reference()
    rows = VF.dh_rows_from_frames(frames)
    for i, (sign, theta, d, a, alpha) in enumerate(rows, start=1):
        ns[f"T{i}"] = A.Tz(sign * QS[i - 1] + theta, d) @ A.Tx(alpha, a)
    ns["chain"] = _chain(ns)
    ns["link_points"] = {k: ((ref.world_points(k) - F[:3, 3]) @ F[:3, :3]).tolist() for k, F in enumerate(frames)}
    return ns


def _chain(ns):
    return ns["T1"] @ ns["T2"] @ ns["T3"] @ ns["T4"] @ ns["T5"] @ ns["T6"]


def _report(ns):
    return checks.check_all(ans.answers_from_namespace(ns))


def _scores(report):
    return [p.score for p in report.parts]


def _wrong(part):
    return [item for item in part.items if item.ok is False]


# --- full marks: the solution and every other valid DH assignment ------------------------------

def test_the_source_notebooks_solution_scores_full_marks():
    report = _report(_solution_namespace())
    assert report.score == report.max_score == sum(checks.POINTS.values())
    assert "all 6 joint axes" in report.part("part3").text()
    assert "move like the PUMA 560" in report.part("part3").text()


def test_random_valid_dh_assignments_score_full_marks():
    """Signs of every z and x, origins slid along parallel axes, x6 turned: all valid."""
    rng = np.random.default_rng(2024)
    for _ in range(60):
        report = _report(_namespace_from_frames(VF.random_family_frames(rng)))
        assert report.score == report.max_score, report.text()


def test_the_hand_written_alternative_scores_full_marks():
    ns = _solution_namespace()
    ns["T1"] = A.Tz(q1, 0) @ A.Tx(-90, 0)
    ns["T2"] = A.Tz(-q2, -0.15005) @ A.Tx(0, 0.4318)
    ns["T3"] = A.Tz(-q3, 0) @ A.Tx(90, 0.0203)
    ns["T4"] = A.Tz(q4 + 180, 0.4318) @ A.Tx(90, 0)
    ns["T5"] = A.Tz(-q5 + 180, 0) @ A.Tx(90, 0)
    ns["T6"] = A.Tz(q6 + 90, 0) @ A.Tx(0, 0)
    ns["chain"] = _chain(ns)
    frames = ns["chain"].frames(np.zeros(6))
    ref = R.reference()
    ns["link_points"] = [np.round((ref.world_points(k) - F[:3, 3]) @ F[:3, :3], 4).tolist()
                         for k, F in enumerate(frames)]          # typed with 4 decimals
    assert _report(ns).score == 10


def test_a_valid_chain_matches_the_puma_at_random_configurations():
    rng = np.random.default_rng(7)
    rows = ans.answers_from_namespace(_namespace_from_frames(VF.random_family_frames(rng)))
    match = checks.chain_matches(checks.rows_of(rows))
    assert all(match["axes"]) and match["end_effector"] and match["configurations"] == 51


# --- one mistake costs its own item and names the quantity -------------------------------------

def test_the_reference_moves_by_the_one_forward_kinematics_path():
    """The reference's frames, and any chain of rows the checks build (a sliding joint too, a joint
    turned against its z), are the numbers of dhlab.DHRobot, which tests/maths/test_against_rtb.py compares
    with the Robotics Toolbox."""
    ref = R.reference()
    rng = np.random.default_rng(3)
    lo, hi = ref.robot.qlim.T
    Q = lo + (hi - lo) * rng.random((50, 6))
    np.testing.assert_allclose(ref.frames(Q), ref.robot.frames(Q), atol=1e-12)
    robot = dhlab.DHRobot([dhlab.RevoluteDH(d=0.2, a=0.1, alpha=0.5, offset=0.3),
                           dhlab.PrismaticDH(theta=0.7, a=0.3, alpha=-1.2, offset=0.05, qlim=[-1, 1])])
    Q = rng.uniform(-1, 1, (20, 2))
    rows = [(1, 0, 0.3, 0.2, 0.1, 0.5), (-1, 1, 0.7, 0.05, 0.3, -1.2)]
    np.testing.assert_allclose(R.dh_frames(rows, "RP", Q), robot.frames(Q * [1, -1]), atol=1e-12)
    np.testing.assert_allclose(R.row_matrix(0.3, 0.2, 0.1, 0.5), robot.A(1, 0.0), atol=1e-12)


def test_the_issues_example_feedback():
    ns = _solution_namespace()
    ns["T2"] = A.Tz(q2, 0) @ A.Tx(-90, 0.4318)
    ns["chain"] = _chain(ns)
    report = _report(ns)
    wrong = _wrong(report.part("part3"))
    assert [w.label.split(" ")[0] for w in wrong] == ["T2"]
    assert "joint 3: z2 should be parallel to z1" in wrong[0].message
    assert "your α2 = -90° turns it" in wrong[0].message
    assert _scores(report)[:2] == [2, 3]                     # parts 1 and 2 keep their marks
    assert report.score == pytest.approx(10 - 5 / 7, abs=0.01)


@pytest.mark.parametrize("i", range(1, 7))
def test_a_wrong_twist_costs_only_its_own_transformation(i):
    ns = _solution_namespace()
    row = ans.answers_from_namespace(ns).T[i - 1]
    ns[f"T{i}"] = A.Tz(QS[i - 1] + row.theta.const, row.d.const) @ A.Tx(row.alpha + 45, row.a)
    ns["chain"] = _chain(ns)
    report = _report(ns)
    wrong = _wrong(report.part("part3"))
    assert [w.label.split(" ")[0] for w in wrong] == [f"T{i}"]
    assert f"α{i}" in wrong[0].message
    assert _scores(report)[:2] == [2, 3]
    match = checks.chain_matches(checks.rows_of(ans.answers_from_namespace(ns)))
    if i < 6:        # α6 only turns frame 6 about x6: no joint axis, and not the end effector's position
        assert not (all(match["axes"]) and match["end_effector"])     # the chain really is wrong


@pytest.mark.parametrize("change, words", [
    (("T3", lambda: A.Tz(q3, 0.15005) @ A.Tx(-90, 0)), ["z3 should be 0.0203 m from z2", "a3 = 0"]),
    (("T3", lambda: A.Tz(q3, 0.15005) @ A.Tx(-90, -0.0203)), ["wrong side", "sign of a3"]),
    (("T4", lambda: A.Tz(q4, 0.3) @ A.Tx(90, 0)), ["check d4", "0.1318 m short"]),
    (("T4", lambda: A.Tz(-q4, 0.4318) @ A.Tx(90, 0)), ["joint 4: a positive q4 turns the arm the wrong way"]),
    (("T1", lambda: A.Tz(q1 + 90, 0) @ A.Tx(90, 0)), ["points the wrong way", "constant in θ1"]),
    (("T5", lambda: A.Tz(q5, 0) @ A.Tx(-1.5708, 0)), ["looks like radians"]),
    (("T6", lambda: A.Tz(q6, 0.056) @ A.Tx(0, 0)), ["end effector", "wrist centre W", "d6 = 0.056"]),
    (("T3", lambda: A.Tz(q2, 0.15005) @ A.Tx(-90, 0.0203)), ["θ3 uses q2"]),
    (("T2", lambda: A.Tz(0, 0) @ A.Tx(0, 0.4318)), ["θ2 has no joint variable"]),
    (("T2", lambda: A.Tz(90, q2) @ A.Tx(0, 0.4318)), ["slide (prismatic)"]),
])
def test_feedback_names_the_joint_and_the_quantity(change, words):
    name, make = change
    ns = _solution_namespace()
    ns[name] = make()
    ns["chain"] = _chain(ns)
    report = _report(ns)
    wrong = _wrong(report.part("part3"))
    assert len(wrong) == 1 and wrong[0].label.startswith(name)
    for w in words:
        assert w in wrong[0].message, wrong[0].message
    assert _scores(report)[:2] == [2, 3]


def test_the_chain_is_its_own_item():
    ns = _solution_namespace()
    ns["chain"] = ns["T2"] @ ns["T1"] @ ns["T3"] @ ns["T4"] @ ns["T5"] @ ns["T6"]
    part = _report(ns).part("part3")
    assert [w.label for w in _wrong(part)] == ["chain"]
    assert "factor 1 is your T2" in _wrong(part)[0].message
    ns["chain"] = ...
    part = _report(ns).part("part3")
    assert part.items[-1].ok is None and "not answered" in part.items[-1].message
    ns = _solution_namespace()
    del ns["T4"]                                    # the chain's factor stands for a missing T4
    assert _report(ns).score == 10


def test_part1_mistakes_and_the_ways_students_write_answers():
    ns = _solution_namespace()
    ns.update(n_links=6, joint_types="RRRRR", x_cases=["intersect", "parallel", "intersect", "intersect", "intersect"])
    part = _report(ns).part("part1")
    messages = {w.label: w.message for w in _wrong(part)}
    assert set(messages) == {"n_links", "joint_types", "x3"}
    assert "link 0" in messages["n_links"] and "n + 1" not in messages["n_links"]    # a hint, not the answer
    assert "7" not in messages["n_links"].replace("you wrote 6", "")
    assert "joints 3 and 4" in messages["x3"] and "skew" not in messages["x3"]
    assert "joint 6" in messages["joint_types"] and "revolute" not in messages["joint_types"]
    ns.update(n_links=7.0, joint_types=["revolute"] * 6,
              x_cases={1: "case 1", 2: "Paralelos", 3: "ni paralelos ni se intersecan", 4: 1, 5: "intersecting"})
    assert _report(ns).part("part1").full_marks


def test_part2_mistakes_cost_only_those_links():
    ns = _solution_namespace()
    ref = R.reference()
    lp = ns["link_points"]
    F2 = ref.home_frames[2]
    lp[3] = ((ref.world_points(3) - F2[:3, 3]) @ F2[:3, :3]).tolist()        # drawn in frame 2
    lp[4] = [(x, y, z) for (y, x, z) in lp[4]]                              # x and y swapped
    lp[6] = lp[6][:3]                                                        # a point missing
    report = _report(ns)
    wrong = {w.label.split(" ")[1]: w.message for w in _wrong(report.part("part2"))}
    assert set(wrong) == {"3", "4", "6"}
    assert "axis of joint 4 must be the z axis" in wrong["3"]
    assert "x4 must lie along the common normal" in wrong["4"]
    assert "give the 4 points G1, G2, G3, G4" in wrong["6"]
    assert _scores(report)[0] == 2 and _scores(report)[2] == 5
    assert report.part("part2").score == pytest.approx(3 * 4 / 7, abs=0.01)


def test_part2_is_scored_in_the_frames_the_students_own_transformations_build():
    """Links drawn in valid DH frames that are not the ones T1…Tk build lose their item, one per
    link (assembled with the student's T_k they land elsewhere: seed 000, figures 10–13); a slip
    that part 3 charges is not charged again in part 2; the notebook says the same."""
    rng = np.random.default_rng(3)
    frames = VF.random_family_frames(rng)
    ns = _namespace_from_frames(frames)
    assert _report(ns).score == 10                                  # links and rows in the same frames
    ns["link_points"] = _solution_namespace()["link_points"]        # valid, but other frames
    ref = R.reference()
    placed = {k: np.array(P) @ frames[k][:3, :3].T + frames[k][:3, 3] for k, P in ns["link_points"].items()}
    differ = [k for k in range(7) if np.abs(placed[k] - ref.world_points(k)).max() > 1e-6]   # the ground truth
    report = _report(ns)
    wrong = _wrong(report.part("part2"))
    assert [w.label.split(" ")[1] for w in wrong] == [str(k) for k in differ] and len(differ) >= 3
    assert all("not in the one your T1" in w.message and "lands at" in w.message for w in wrong)
    assert report.part("part2").score == pytest.approx(3 * (7 - len(differ)) / 7, abs=0.01)
    assert report.part("part3").score == 5 and report.part("part1").score == 2
    assert A.check_part2(ns).score == report.part("part2").score                # notebook == gradebook
    assert "part 2 again" in A.check_part3(ns).text()
    # one link moved to another valid frame: exactly that link
    ns = _namespace_from_frames(frames)
    F = frames[3] @ np.diag([-1.0, -1, 1, 1])                      # x3 the other way: still a valid frame 3
    ns["link_points"] = dict(ns["link_points"])
    ns["link_points"][3] = ((ref.world_points(3) - F[:3, 3]) @ F[:3, :3]).tolist()
    assert [w.label.split(" ")[1] for w in _wrong(_report(ns).part("part2"))] == ["3"]
    # a slip in part 3 costs its row only: the links after it may sit in the frames the student meant
    ns = _namespace_from_frames(frames)
    ns["T5"] = A.Tz(q5, 0) @ A.Tx(0, 0)
    ns["chain"] = _chain(ns)
    report = _report(ns)
    assert report.part("part2").score == 3
    assert report.part("part3").score == pytest.approx(5 * 6 / 7, abs=0.01)
    # no transformations yet: the DH rules alone, and a note says part 3's frames will be checked
    ns = {"link_points": _solution_namespace()["link_points"]}
    part2 = _report(ns).part("part2")
    assert part2.score == 3 and "checked again" in part2.notes[-1]


def test_nothing_answered_gives_zero_with_not_answered():
    ns = {"n_links": ..., "link_points": {k: ... for k in range(7)}, "T1": ..., "chain": ...}
    report = _report(ns)
    assert report.score == 0
    assert all(not p.answered and "not answered" in p.text() for p in report.parts)


# --- answers as plain data ------------------------------------------------------------------------

def test_to_plain_caps_sizes_and_survives_odd_values():
    cyclic = []
    cyclic.append(cyclic)
    plain = encode.to_plain({"big": list(range(10_000)), "cyclic": cyclic, "arr": np.arange(3.0),
                          "nan": float("nan"), "dots": ..., 3: "int key"})
    json.dumps(plain)                                          # JSON, whatever came in
    text = json.dumps(plain)
    assert "too big" in text and "nan" in text


def test_answers_from_dhlab_objects_read_fields_not_methods(monkeypatch):
    T = A.Tz(q3 - 90, 0.15) @ A.Tx(-90, 0.02)
    monkeypatch.setattr(A.DHTransform, "__repr__", lambda self: "perfect")
    row = ans.parse_answers(json.loads(json.dumps({"T3": encode.to_plain(T)}))).T[2]
    assert (row.theta.joint, row.theta.sign, row.theta.const) == (3, 1, -90)
    assert (row.d.const, row.alpha, row.a) == (0.15, -90, 0.02)


def test_parse_json_refuses_big_or_broken_text():
    with pytest.raises(ValueError, match="not valid JSON"):
        ans.parse_json('{"n_links": ')
    with pytest.raises(ValueError, match="more than"):
        ans.parse_json(" " * (ans.MAX_JSON_BYTES + 1))
    with pytest.raises(ValueError, match="not a JSON object"):
        ans.parse_json("[1, 2]")


def test_unreadable_answers_say_why():
    a = ans.parse_answers({"n_links": "seven", "joint_types": 6, "T1": [[1, 0], [0, 1]],
                           "x_cases": {"first": "skew"}, "link_points": [[(0, 0)]]})
    assert "must be a number" in a.n_links.why
    assert "one letter per joint" in a.joint_types.why
    assert "Tz(θ, d) @ Tx(α, a)" in a.T[0].why
    assert "keys of x_cases" in a.x_cases.why
    assert "must be a point" in a.link_points[0].why


# --- the student's tools ----------------------------------------------------------------------------

def test_only_the_seeds_form_of_transformation_is_allowed():
    with pytest.raises(DHLabError, match="Tz first"):
        A.Tx(90, 0) @ A.Tz(q1, 0)
    with pytest.raises(DHLabError, match="constants"):
        A.Tx(q1, 0)
    with pytest.raises(DHLabError, match="one joint variable"):
        A.Tz(q1 + q2, 0)
    with pytest.raises(DHLabError, match="cannot be multiplied"):
        A.Tz(2 * q1, 0)
    with pytest.raises(DHLabError, match="length"):
        A.Tz(q1, dhlab.deg2rad(90))
    T = A.Tz(q2 + dhlab.deg2rad(90), 0) @ A.Tx(dhlab.deg2rad(-90), 0.1)      # deg2rad() values are read as degrees
    assert repr(T) == "Tz[q2 + 90, 0]·Tx[-90°, 0.1]"
    sym = T.matrix()
    assert sym.free_symbols and str(sym[2, 3]) == "0"


def test_the_check_functions_and_the_figures_in_a_notebook_namespace():
    ns = _solution_namespace()
    feedback = A.check_part3(ns)
    assert feedback.score == checks.POINTS["part3"] and feedback.full_marks
    assert "checked again" not in feedback.text() and "move like the PUMA 560" in feedback.text()
    assert "<b>" in feedback._repr_html_()
    assert A.check_part(2, {"link_points": ns["link_points"]}).full_marks
    with pytest.raises(DHLabError):
        A.check_part(4, ns)
    assert isinstance(A.my_robot_figure({}), A.Note)                 # before part 3 is answered
    assert isinstance(A.teach({}), A.Note)
    panel = A.teach(ns)
    panel.sliders[2].value = 30
    assert panel.q[2] == pytest.approx(math.radians(30))
    assert A.my_robot_figure(ns).axes
    assert "joint 6" in repr(A.axes_table()) and "G4" in repr(A.points_table())


# --- the notebooks: source, student version, points ------------------------------------------------

def test_the_student_notebook_is_up_to_date_with_the_source():
    assert generate.generate(SOURCE, STUDENT, check=True), "run: python -m dhlab.grading.release.generate"


def test_the_student_notebook_has_stubs_and_no_solutions():
    student = json.loads(STUDENT.read_text(encoding="utf-8"))
    text = json.dumps(student)
    for secret in ("BEGIN SOLUTION", "HIDDEN TESTS", "Tz(q4, 0.4318)", "feedback_1.score", "\"RRRRRR\""):
        assert secret not in text
    answers_cells = [c for c in student["cells"] if c["metadata"].get("nbgrader", {}).get("solution")]
    assert len(answers_cells) == 3
    assert all("# YOUR CODE HERE" in "".join(c["source"]) for c in answers_cells)
    # outputs only where a read-only cell shows the robot (figure, axes, points): nothing answered
    shown = {c["metadata"].get("nbgrader", {}).get("grade_id") for c in student["cells"]
             if c["cell_type"] == "code" and c.get("outputs")}
    assert shown == {"robot_figure", "axes_table", "points_table"}


def test_the_student_notebook_is_clean():
    """No teacher-only text, no answer in a comment, one place to type each answer, no file
    a clone lacks; the solutions live outside notebooks/ (make lab never shows them)."""
    student = json.loads(STUDENT.read_text(encoding="utf-8"))
    text = "\n".join("".join(c["source"]) for c in student["cells"])
    for teacher in ("For teachers", "nbgrader", "dhlab-grade", "generate", "ERRATA", "VERIFIED_MATH", "shared/seeds",
                    "seeds/"):
        assert teacher not in text, teacher
    answer = ["intersect", "parallel", "skew", "intersect", "intersect"]
    assert json.dumps(answer) not in text and str(answer) not in text
    for cell in student["cells"]:
        if cell["metadata"].get("nbgrader", {}).get("solution"):
            code = "".join(cell["source"]).splitlines()
            assert code.count("# YOUR CODE HERE") == 1 and code[-1] == "# YOUR CODE HERE"
            assert all(line.startswith("#") for line in code)          # nothing to delete or overwrite
        if "%matplotlib widget" in "".join(cell["source"]):
            assert "import ipympl" in "".join(cell["source"])
    assert "09_sources_and_errata.ipynb" in text
    assert not (ROOT / "notebooks" / "source").exists()
    assert not (ROOT / "tools" / "teacher").exists()                  # no file of the course holds the solutions
    assert sorted(p.name for p in (ROOT / "notebooks").glob("*08*")) == ["08_puma_assignment.ipynb"]


def test_points_in_the_notebook_are_the_checks_points():
    nb = json.loads(SOURCE.read_text(encoding="utf-8"))
    grade = {c["metadata"]["nbgrader"]["grade_id"]: c["metadata"]["nbgrader"]["points"]
             for c in nb["cells"] if c["metadata"].get("nbgrader", {}).get("grade")}
    assert grade == {f"{key}_check": points for key, points in checks.POINTS.items()}
    text = "".join("".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "markdown")
    for n, points in enumerate(checks.POINTS.values(), start=1):
        assert re.search(rf"## Part {n} · .*\({points} points\)", text)
        assert re.search(rf"\| {n}\. .*\| {points} \|", text)


def test_the_generator_follows_nbgraders_rules():
    def cell(source, **meta):
        base = {"grade": False, "solution": False, "locked": False, "schema_version": 3}
        base.update(meta)
        return {"cell_type": "code", "source": source, "outputs": [], "execution_count": 3,
                "metadata": {"nbgrader": base}}

    out = generate.student_cell(cell("def f():\n    ### BEGIN SOLUTION\n    return 1\n    ### END SOLUTION",
                                     solution=True, grade_id="f"))
    assert out["source"] == "def f():\n    # YOUR CODE HERE" and out["metadata"]["deletable"] is False
    assert "editable" not in out["metadata"] and out["execution_count"] is None
    out = generate.student_cell(cell("x = 1", solution=True, grade_id="g"))
    assert out["source"] == "# YOUR CODE HERE"
    md = dict(cell("an answer", solution=True, grade=True, points=1, grade_id="m"), cell_type="markdown")
    assert generate.student_cell(md)["source"] == "YOUR ANSWER HERE"
    out = generate.student_cell(cell("a\n### BEGIN HIDDEN TESTS\nassert x\n### END HIDDEN TESTS\nb",
                                     grade=True, locked=True, points=1, grade_id="t"))
    assert out["source"] == "a\nb" and out["metadata"]["editable"] is False
    with pytest.raises(generate.GenerateError, match="not a solution cell"):
        generate.student_cell({"cell_type": "code", "source": "### BEGIN SOLUTION\n### END SOLUTION",
                               "metadata": {}, "outputs": []})
    with pytest.raises(generate.GenerateError, match="not a grade cell"):
        generate.student_cell(cell("### BEGIN HIDDEN TESTS\n### END HIDDEN TESTS", locked=True, grade_id="h"))
    with pytest.raises(generate.GenerateError, match="without END"):
        generate.student_cell(cell("### BEGIN SOLUTION\nx = 1", solution=True, grade_id="i"))
    with pytest.raises(generate.GenerateError, match="used twice"):
        generate.check_metadata([cell("", locked=True, grade_id="a"), cell("", locked=True, grade_id="a")])
    with pytest.raises(generate.GenerateError, match="needs points"):
        generate.check_metadata([cell("", grade=True, grade_id="b")])
    with pytest.raises(generate.GenerateError, match="unknown keys"):
        generate.check_metadata([cell("", grade_id="c", weight=2)])


def test_generate_check_reports_an_outdated_student_notebook(tmp_path):
    student = tmp_path / "student.ipynb"
    assert generate.main([str(SOURCE), "-o", str(student)]) == 0
    assert generate.main([str(SOURCE), "-o", str(student), "--check"]) == 0
    student.write_text(student.read_text().replace("# YOUR CODE HERE", "# mine"))
    assert generate.main([str(SOURCE), "-o", str(student), "--check"]) == 1


# --- the gradebook's files ----------------------------------------------------------------------

def test_gradebook_writes_are_atomic(tmp_path, monkeypatch):
    path = tmp_path / "gradebook.csv"
    gradebook.write_csv(path, [{"submission": "b", "score": "1"}, {"submission": "a", "score": "2"}])
    text = path.read_text()
    assert text.splitlines()[0].split(",")[:4] == ["submission", "score", "max_score", "status"]
    assert [line.split(",")[0] for line in text.splitlines()[1:]] == ["a", "b"]

    def broken_replace(src, dst):
        raise OSError("disk full")

    monkeypatch.setattr(atomic_file.os, "replace", broken_replace)
    with pytest.raises(OSError):
        gradebook.write_csv(path, [{"submission": "c", "score": "3"}])
    assert path.read_text() == text                                   # the old gradebook, whole
    assert [p.name for p in tmp_path.iterdir()] == ["gradebook.csv"]  # no temporary file left


def test_feedback_file_names_are_safe_and_unique():
    assert gradebook.feedback_filename("alice/ps1/puma").startswith("alice__ps1__puma-")
    assert "/" not in gradebook.feedback_filename("../../etc/passwd")
    assert gradebook.feedback_filename("..").endswith(".txt")
    names = ["Ana María", "Ana_María", "Ana_Maria", "ana_maria", "Ana  María", "a/b", "a__b", "ANA MARÍA"]
    files = [gradebook.feedback_filename(n) for n in names]
    assert len({f.lower() for f in files}) == len(names)              # unique even on case-insensitive disks
    assert all(f.isascii() and len(f) < 200 for f in files)


def test_answers_written_the_ways_students_write_them():
    ns = _solution_namespace()
    ns["T2"] = A.Tz("q2", 0) * A.Tx(0, 0.4318)                # text θ and the seed's * for the product
    ns["T3"] = A.Tz("q3", 0.15005) * A.Tx(-90, 0.0203)
    ns["chain"] = ns["T1"] * ns["T2"] * ns["T3"] * ns["T4"] * ns["T5"] * ns["T6"]
    ns["n_links"], ns["joint_types"] = "7", "R R R R R R"
    ns["x_cases"] = "intersect, parallel, skew, intersect, intersect"
    ns["link_points"] = [np.array(p) for p in ns["link_points"].values()]
    assert _report(ns).score == 10
    with pytest.raises(DHLabError, match="±q_i"):
        A.Tz("2*q1", 0)


def test_the_runner_reads_notebook_formats_3_and_4(tmp_path):
    from dhlab.grading.run import runner
    v3 = {"nbformat": 3, "worksheets": [{"cells": [{"cell_type": "code", "input": "n_links = 7"},
                                                   {"cell_type": "markdown", "source": "hi"}]}]}
    (tmp_path / "v3.ipynb").write_text(json.dumps(v3))
    assert runner.read_code_cells(tmp_path / "v3.ipynb") == [(1, "n_links = 7")]
    (tmp_path / "v4.ipynb").write_text(json.dumps({"cells": [{"cell_type": "markdown", "source": "x"},
                                                             {"cell_type": "code", "source": ["a = 1\n", "b = 2"]}]}))
    assert runner.read_code_cells(tmp_path / "v4.ipynb") == [(2, "a = 1\nb = 2")]
    (tmp_path / "bad.ipynb").write_bytes(b"\xff\xfe not text")
    with pytest.raises(runner.NotebookError, match="UTF-8"):
        runner.read_code_cells(tmp_path / "bad.ipynb")


# --- one slip, one item ---------------------------------------------------------------------------

def _rows_to_namespace(ns, rows):
    for i, (sign, theta, d, a, alpha) in enumerate(rows, start=1):
        ns[f"T{i}"] = A.Tz(sign * QS[i - 1] + round(theta, 9), round(d, 9)) @ A.Tx(round(alpha, 9), round(a, 9))
    ns["chain"] = _chain(ns)
    return ns


SLIPS = {"α+180": lambda r: (r[0], r[1], r[2], r[3], r[4] + 180), "-α": lambda r: (r[0], r[1], r[2], r[3], -r[4]),
         "θ+180": lambda r: (r[0], r[1] + 180, r[2], r[3], r[4]), "-a": lambda r: (r[0], r[1], r[2], -r[3], r[4])}


@pytest.mark.parametrize("seed", range(5))
@pytest.mark.parametrize("k", range(1, 7))
@pytest.mark.parametrize("slip", list(SLIPS))
def test_a_single_slip_costs_at_most_its_own_row(seed, k, slip):
    """One parameter of T_k typed wrong, in any valid assignment: at most T_k is charged
    (nothing when the slip leaves a valid answer, e.g. x6 turned over), never a later row,
    and a charged frame flip names the parameter of T_k."""
    frames = VF.random_family_frames(np.random.default_rng(seed))
    rows = VF.dh_rows_from_frames(frames)
    if SLIPS[slip](rows[k - 1]) == rows[k - 1]:
        return                                                     # -α with α = 0: no slip at all
    rows[k - 1] = SLIPS[slip](rows[k - 1])
    ns = _rows_to_namespace(_namespace_from_frames(frames), rows)     # the links stay in ``frames``
    report = _report(ns)
    wrong = _wrong(report.part("part3"))
    labels = [w.label.split(" ")[0] for w in wrong]
    if not labels:                                                 # then the answer really is valid
        match = checks.chain_matches(checks.rows_of(ans.answers_from_namespace(ns)))
        assert all(match["axes"]) and match["end_effector"] and match["last_z"]
        # ... but frame k may have turned (x6 the other way): link k, drawn in the old one, pays
        mine = R.dh_frames([(1, None, math.radians(th) + 0, d, a, math.radians(al))
                            for _, th, d, a, al in rows], None, np.zeros((1, 6)))[0]
        moved = [f"{j}" for j in range(7) if not np.allclose(mine[j], frames[j], atol=1e-6)]
        assert [w.label.split(" ")[1] for w in _wrong(report.part("part2"))] == moved and len(moved) <= 1
    else:
        assert not _wrong(report.part("part2")), report.part("part2").text()
        assert labels == [f"T{k}"], report.part("part3").text()
        if "builds a valid frame" in wrong[0].message:
            assert f"α{k}" in wrong[0].message or f"θ{k}'s offset" in wrong[0].message
    assert report.score >= 10 - 5 / 7 - 0.01


def test_the_issues_slips_cost_one_item_each_and_name_the_parameter():
    for name, T, words in [("T1", A.Tz(q1, 0) @ A.Tx(-90, 0), "α1 = 90° instead of -90°"),
                           ("T3", A.Tz(q3, 0.15005) @ A.Tx(90, 0.0203), "α3 = -90° instead of 90°")]:
        ns = _solution_namespace()
        ns[name] = T
        ns["chain"] = _chain(ns)
        report = _report(ns)
        wrong = _wrong(report.part("part3"))
        assert [w.label.split(" ")[0] for w in wrong] == [name] and words in wrong[0].message
        assert _scores(report) == pytest.approx([2, 3, 5 * 6 / 7], abs=0.01)
    # frames with x1 backwards (a valid choice), and the +180° of θ1 forgotten
    frames = list(R.reference().home_frames)
    frames[1] = frames[1] @ np.diag([-1.0, -1, 1, 1])
    rows = VF.dh_rows_from_frames(frames)
    assert round(rows[0][1]) == 180
    rows[0] = (rows[0][0], 0.0, *rows[0][2:])
    report = _report(_rows_to_namespace(_solution_namespace(), rows))
    wrong = _wrong(report.part("part3"))
    assert [w.label.split(" ")[0] for w in wrong] == ["T1"] and "θ1's offset 180° instead of 0°" in wrong[0].message


def test_a_sign_slip_in_one_row_is_charged_to_that_row_not_to_the_one_before():
    ns = _solution_namespace()
    ns["T2"] = A.Tz(-q2, 0) @ A.Tx(0, 0.4318)
    ns["chain"] = _chain(ns)
    wrong = _wrong(_report(ns).part("part3"))
    assert [w.label.split(" ")[0] for w in wrong] == ["T2"] and "turns the arm the wrong way" in wrong[0].message


def _mutations(ns):
    """Single-item mutations of a namespace: (what, new namespace)."""
    out = []
    for name, value in [("n_links", 5), ("n_joints", 7), ("joint_types", "RRPRRR"),
                        ("x_cases", ["parallel", "parallel", "skew", "intersect", "intersect"])]:
        out.append((name, {**ns, name: value}))
    lp = ns["link_points"]
    lp = dict(lp) if isinstance(lp, dict) else dict(enumerate(lp))
    for k in range(7):
        for shift in ((0.05, 0, 0), (0, 0, -0.1)):
            moved = dict(lp)
            moved[k] = [tuple(np.add(p, shift)) for p in lp[k]]
            out.append((f"link {k}", {**ns, "link_points": moved}))
    rows = ans.answers_from_namespace(ns).T
    for i, row in enumerate(rows, start=1):
        q = QS[i - 1] if row.theta.sign > 0 else -QS[i - 1]
        for what, (theta, d, alpha, a) in {
            "α+90": (row.theta.const, row.d.const, row.alpha + 90, row.a),
            "-α": (row.theta.const, row.d.const, -row.alpha, row.a),
            "θ+180": (row.theta.const + 180, row.d.const, row.alpha, row.a),
            "θ+90": (row.theta.const + 90, row.d.const, row.alpha, row.a),
            "d+0.1": (row.theta.const, row.d.const + 0.1, row.alpha, row.a),
            "a+0.1": (row.theta.const, row.d.const, row.alpha, row.a + 0.1),
        }.items():
            new = {**ns, f"T{i}": A.Tz(q + theta, d) @ A.Tx(alpha, a)}
            new["chain"] = _chain(new)
            out.append((f"T{i} {what}", new))
        new = {**ns, f"T{i}": A.Tz(-q + row.theta.const, row.d.const) @ A.Tx(row.alpha, row.a)}
        new["chain"] = _chain(new)
        out.append((f"T{i} -q", new))
    out.append(("chain", {**ns, "chain": ns["T2"] @ ns["T1"] @ ns["T3"] @ ns["T4"] @ ns["T5"] @ ns["T6"]}))
    return out


def _fixture_namespaces():
    """The solution, valid alternatives, and answers with one slip (the slip fixtures)."""
    out = {"solution": _solution_namespace()}
    for seed in (1, 2):
        out[f"random valid {seed}"] = _namespace_from_frames(VF.random_family_frames(np.random.default_rng(seed)))
    slip = _solution_namespace()
    slip["T1"] = A.Tz(q1, 0) @ A.Tx(-90, 0)
    slip["chain"] = _chain(slip)
    out["slip α1"] = slip
    mixed = _namespace_from_frames(VF.random_family_frames(np.random.default_rng(5)))
    mixed["link_points"] = _solution_namespace()["link_points"]
    out["mixed frames"] = mixed
    return out


@pytest.mark.parametrize("fixture", list(_fixture_namespaces()))
def test_a_wrong_answer_never_scores_more_than_the_right_one(fixture):
    """score(mutated) ≤ score(original) for every single-item mutation, part by part; and a
    report never carries contradictory notes."""
    ns = _fixture_namespaces()[fixture]
    base = _report(ns)
    credited = {item.label.split(" ")[0] for part in base.parts for item in part.items if item.ok}
    credited |= {f"link {k}" for k in range(7) if base.part("part2").items[k].ok}
    for what, mutated in _mutations(ns):
        if what.split(" ")[0] not in credited and " ".join(what.split(" ")[:2]) not in credited:
            continue                                             # only mutate what was right
        report = _report(mutated)
        assert report.score <= base.score + 1e-9, (fixture, what, report.text())
        for mine, theirs in zip(report.parts, base.parts):
            if fixture == "mixed frames" and mine.key == "part2":
                # parts 2 and 3 disagree there: a mutated row that part 3 reads as a flip of the frame
                # before may make one link agree with it (never more than the row costs in part 3)
                assert mine.score <= theirs.score + 3 / 7 + 0.011, (fixture, what, mine.text())
                continue
            assert mine.score <= theirs.score + 1e-9, (fixture, what, mine.text())
        part3 = report.part("part3")
        if any("move like" in n for n in part3.notes):
            assert all(item.ok for item in part3.items[:-1])
        assert not any("internal check failed" in n for n in part3.notes), (fixture, what)
        notes2 = report.part("part2").notes
        if notes2 and notes2[0].startswith("(not scored)"):
            assert all(item.ok for item in part3.items[:-1])


# --- one checking path: the notebook's and the grader's----------------------------------------------

def test_numbers_of_every_type_are_read_the_same_way():
    import sympy as sp
    ns = _solution_namespace()
    plain = ans.answers_from_namespace(ns)
    odd = dict(ns)
    odd["n_links"], odd["n_joints"] = np.int64(7), sp.Integer(6)
    odd["joint_types"] = np.array(list("RRRRRR"))
    lp = ns["link_points"]
    odd["link_points"] = {k: [tuple(np.asarray(p, dtype=np.float64)) for p in pts] for k, pts in lp.items()}
    odd["link_points"][2] = np.array(lp[2])
    odd["link_points"][3] = [sp.Matrix(p) for p in lp[3]]
    odd["link_points"][4] = [tuple(sp.Float(v) for v in p) for p in lp[4]]
    odd["T1"] = A.Tz(q1, 0) @ A.Tx(dhlab.deg2rad(90), 0)
    odd["T2"] = A.Tz(q2 + dhlab.deg2rad(0), 0) @ A.Tx(0, np.float64(0.4318))
    odd["T4"] = A.Tz(q4, np.float32(0.4318)) @ A.Tx(sp.Integer(90), 0)
    odd["chain"] = _chain(odd)
    read = ans.answers_from_namespace(odd)
    assert read.n_links == plain.n_links and read.n_joints == plain.n_joints
    assert read.joint_types == plain.joint_types
    for a, b in zip(read.link_points, plain.link_points):
        assert np.allclose(a, b)
    assert read.T[0] == plain.T[0] and read.T[1] == plain.T[1]
    assert checks.check_all(read).score == 10


def test_the_notebook_and_the_grader_read_through_the_same_functions():
    """The grader's kernel-side writer is built from answers.to_plain and answers.encode_json
    themselves, and the notebook's check reads through parse_json(encode_json(to_plain(...)))."""
    from dhlab.grading.run import read_answers
    code = read_answers.answer_code(Path("/tmp/x.json"))
    assert "def to_plain(" in code and "def encode_json(" in code
    ns = {"link_points": [[(np.float64(1.0), np.float64(2.0), np.float64(3.0))]]}
    raw = encode.encode_json({k: encode.to_plain(v) for k, v in ns.items()})
    assert json.loads(raw) == {"link_points": [[[1.0, 2.0, 3.0]]]}
    assert ans.answers_from_namespace(ns).link_points == [[(1.0, 2.0, 3.0)]]


def test_any_answer_gets_feedback_never_an_exception():
    import sympy as sp
    junk = [float("nan"), float("inf"), 1e308, -1e308, complex(1, 2), sp.zoo, sp.nan, None, True, "",
            [None, True], {"a": object()}, np.array([[1, 2], [3, 4]]), np.zeros((0, 3)), sp.Symbol("x"),
            [[1, 2, 3, 1]], [(1e300, 0, 0)], 10 ** 400, lambda q: q, type, ...]
    for value in junk:
        for name in encode.ANSWER_NAMES:
            ns = {**_solution_namespace(), name: value}
            for part in (1, 2, 3):
                feedback = A.check_part(part, ns)
                assert isinstance(feedback.text(), str)
    assert "drop the trailing 1" in A.check_part(2, {"link_points": {0: [[0, 0, -0.67183, 1]]}}).text()


def test_the_computed_solution_earns_full_marks_in_the_notebook():
    """The solved notebook is computed (dhlab.assignment.solution), never stored: run here, its
    answers earn every point of the three check cells, as the notebook's checks say them."""
    nb = json.loads(SOURCE.read_text(encoding="utf-8"))
    ns = _solution_namespace()
    parts = [int(c["metadata"]["nbgrader"]["grade_id"][4]) for c in nb["cells"]
             if c["metadata"].get("nbgrader", {}).get("grade_id", "").endswith("_check")]
    assert sorted(parts) == [1, 2, 3]
    for part in parts:
        assert A.check_part(part, ns).full_marks, A.check_part(part, ns).text()


# --- runs of three or more parallel axes -------------------------------------------------------

@pytest.mark.parametrize("key", ["ur5", "cobra600"])
def test_a_slip_before_a_run_of_parallel_axes_costs_one_item(key):
    """UR5 joints 2–4 and the Cobra's column are parallel: a wrong T_j (a_j and d_j swapped, a
    length off) used to carry its wrong offset along the run, and the row where the run ends paid
    too ("T4 … crosses it 0.51 m short … check d4"). Every single slip that changes how the chain
    moves costs exactly one item of part 3 (ground truth: the robot's motion, not the grader)."""
    from dhlab.assignment import variants as V
    from dhlab.assignment.model import random_frames_from_axes
    from support import written_answers as W
    rng = np.random.default_rng(22)
    counted = 0
    for seed in range(3):
        robot = V.robot_of_variant(V.variant(key, seed))
        Q = np.vstack([np.zeros(robot.n)] + [[rng.uniform(max(lo, -3.0), min(hi, 3.0)) for lo, hi in robot.qlim]
                                             for _ in range(6)])
        for frames in [robot.home_frames, random_frames_from_axes(robot, rng, slide=0.3)]:
            rows = W.rows_in_degrees(robot, frames)
            for i, (s, j, th, d, a, al) in enumerate(rows):
                for what, row in {"a and d swapped": (s, j, th, a, d, al), "d + 10 cm": (s, j, th, d + 0.1, a, al),
                                  "a + 10 cm": (s, j, th, d, a + 0.1, al)}.items():
                    changed = rows[:i] + [row] + rows[i + 1:]
                    if (what == "a and d swapped" and abs(a - d) < 2e-3) or W.moves_like(robot, changed, Q):
                        continue                  # no slip, or one below the grader's tolerance of 1 mm
                    counted += 1
                    lost = W.lost(W.report(W.namespace_from_rows(robot, changed, frames), robot))
                    assert len(lost) == 1 and lost[0][0] == "part3", (key, seed, f"T{i + 1}: {what}", lost)
    assert counted > 40


@pytest.mark.parametrize("key", ["puma560", "irb140", "lrmate200ic"])
def test_a_dropped_theta_offset_on_parallel_axes_names_theta_not_a_tiny_distance(key):
    """Joints 2 and 3 parallel, the −90° (or +90°) of θ2 forgotten: x2 is turned about z1. The
    feedback used to say "x2 must cross z1 … 3.307e-18 m past that point … check d2" (the wrong
    parameter, a meaningless distance, and a correct d2 to change when the origin was slid)."""
    from dhlab.assignment import variants as V
    from dhlab.assignment.model import random_frames_from_axes
    from support import written_answers as W
    rng = np.random.default_rng(9)
    seen = 0
    for seed in range(3):
        robot = V.robot_of_variant(V.variant(key, seed))
        for frames in [robot.home_frames] + [random_frames_from_axes(robot, rng, slide=0.3) for _ in range(3)]:
            rows = W.rows_in_degrees(robot, frames)
            s, j, th, d, a, al = rows[1]
            if abs(abs(th) - 90) > 1e-6:
                continue
            report = W.report(W.namespace_from_rows(robot, [rows[0], (s, j, 0.0, d, a, al)] + rows[2:], frames), robot)
            seen += 1
            assert [label for _, label in W.lost(report)] == [report.part("part3").items[1].label]
            message = report.part("part3").items[1].message
            assert "θ2" in message and "check d2" not in message, message
            for number in re.findall(r"(\d[\d.e+-]*) m\b", message):
                assert float(number) >= R.TOL_POS, message            # no distance below the tolerance
    assert seen >= 3


@pytest.mark.parametrize("key", ["ur5", "cobra600"])
def test_a_second_slip_never_raises_the_score_on_runs_of_parallel_axes(key):
    """Monotonicity where three or more axes are parallel (UR5 joints 2–4, the Cobra's column):
    from an answer with one slip, a second slip in another row never raises any part's score. Two
    independent slips in one run may be charged as one item (the frames there may slide: the
    trade-off documented in docs/grading/assignment.md); they are never charged as less than one."""
    from dhlab.assignment import variants as V
    from dhlab.assignment.model import random_frames_from_axes
    from support import written_answers as W
    rng = np.random.default_rng(23)
    robot = V.robot_of_variant(V.variant(key, 4))
    Q = np.vstack([np.zeros(robot.n)] + [[rng.uniform(max(lo, -3.0), min(hi, 3.0)) for lo, hi in robot.qlim]
                                         for _ in range(6)])
    frames = random_frames_from_axes(robot, rng, slide=0.3)
    rows = W.rows_in_degrees(robot, frames)
    slips = [(i, what, row) for i, what, row in W.row_mistakes(robot, rows)
             if row != rows[i] and not W.moves_like(robot, rows[:i] + [row] + rows[i + 1:], Q)]
    pairs = 0
    for a in rng.choice(len(slips), size=10, replace=False):
        i, what, row = slips[a]
        one = rows[:i] + [row] + rows[i + 1:]
        base = W.report(W.namespace_from_rows(robot, one, frames), robot)
        for b in rng.choice(len(slips), size=6, replace=False):
            j, what2, row2 = slips[b]
            if j == i:
                continue
            two = list(one)
            two[j] = row2
            if W.moves_like(robot, two, Q):
                continue                       # the second slip undoes the first (d1 + 5 cm, d4 + 5 cm on a SCARA)
            report = W.report(W.namespace_from_rows(robot, two, frames), robot)
            pairs += 1
            for mine, theirs in zip(report.parts, base.parts):
                assert mine.score <= theirs.score + 1e-9, (key, f"T{i + 1} {what}", f"T{j + 1} {what2}", mine.text())
            assert len(W.lost(report)) >= 1
    assert pairs > 30


def test_part2_is_scored_after_part3_in_the_notebook_so_nbgrader_agrees_with_the_gradebook():
    """Part 2 is checked in the frames of the student's T_k: its scored cell (nbgrader runs the notebook
    from the top) must come after part 3's answers; in its old place a first check is not scored."""
    for path in (SOURCE, STUDENT):
        cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
        ids = [c["metadata"].get("nbgrader", {}).get("grade_id") for c in cells]
        assert ids.index("part2_answers") < ids.index("part2_preview") < ids.index("part3_answers") \
            < ids.index("part3_check") < ids.index("part2_check")
        preview = cells[ids.index("part2_preview")]["metadata"]["nbgrader"]
        assert not preview["grade"] and preview["locked"] and "points" not in preview
