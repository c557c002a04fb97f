"""The exercise checks of notebooks 5-7 (dhlab.exercises_dh): right answers pass in every
valid form, wrong ones get feedback that names the joint and the quantity, and no input
makes a check raise."""
import math
import re
from pathlib import Path

import nbformat
import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import dhlab
from dhlab import robots
from dhlab.course.exercises import (
    WRIST_Q_DEG,
    Feedback,
    available,
    axis_relation,
    check_dh_row,
    check_key_jump,
    check_link_matrix,
    check_parallel_pairs,
    check_table,
    check_thlist_slots,
    check_wrist_centre,
    check_x_cases,
    compare_robots,
    exercise,
    four_axis_arm,
    link_exercise_robot,
    parallel_pairs,
    printed_key_position,
    row_exercise_frames,
)
from dhlab.dh_frames import dh_from_axes, joint_axes
from dhlab.transforms import Rz, dh_matrix, trans
from support.nbmarks import checks_output, ignores_output

NOTEBOOKS = Path(__file__).resolve().parents[2] / "notebooks"
ARM_TABLE = [("q1", 0.5, 0.2, -90), ("q2 - 90", 0, 0.5, 0), ("q3", 0, 0, -90), ("q4", 0.5, 0, 0)]
RPPR_TABLE = [("q1", "l1", 0, 0), (90, "d2", 0, 90), (0, "d3", 0, 0), ("q4", "l4", 0, 0)]
GARBAGE = ["abc", 42, 3.5, [1, 2], {"a": 1}, (np.nan, 0, 0, 0), [[1, 2], [3]], {(1, 2, 3)}, True, object()]


def only_item(feedback) -> str:
    assert feedback.status == "wrong", str(feedback)
    assert len(feedback.items) == 1, str(feedback)
    return feedback.items[0]


# --- geometry ---------------------------------------------------------------------------------
def test_axis_relation_classifies_the_three_cases_and_coincident_lines():
    z = [0, 0, 1]
    assert axis_relation([0, 0, 0], z, [0, 0, 1], [0, 1, 0]).kind == "intersect"
    par = axis_relation([0, 0, 0], z, [1, 0, 0.5], [0, 0, 2])
    assert (par.kind, par.distance, par.angle) == ("parallel", 1.0, 0.0)
    skew = axis_relation([0, 0, 0], z, [1, 0, 0.5], [0, 1, 0])
    assert skew.kind == "skew" and math.isclose(skew.distance, 1.0) and math.isclose(skew.angle, 90.0)
    assert axis_relation([0, 0, 0], z, [0, 0, 7], [0, 0, -1]).kind == "coincident"


# --- 5.1 -----------------------------------------------------------------------------------------
def test_x_cases_right_answer_in_several_spellings():
    for answer in ({1: "skew", 2: "parallel", 3: "intersect"}, ["case 3", "case 2", "case 1"], [3, 2, 1],
                   {1: "Skew lines", 2: "they are parallel", 3: "intersecting"}):
        assert check_x_cases(answer).ok, answer


def test_x_cases_wrong_answer_refutes_without_giving_the_answer_away():
    fb = check_x_cases({1: "intersect", 2: "parallel", 3: "intersect"})
    item = only_item(fb)
    assert item.startswith("x1: you said z0 and z1 intersect, but they do not meet")
    assert "0.2" in item
    for answer in ({1: "intersect", 2: "parallel", 3: "intersect"}, {1: "parallel", 2: "skew", 3: "skew"},
                   {1: "skew", 2: "intersect", 3: "parallel"}, {1: 2, 2: 3, 3: 2}):
        for item in check_x_cases(answer).items:
            said = item.split(", but", 1)[0]
            why = item.split(", but", 1)[1]
            # the refutation names no case and no relation: the student still has to find it
            assert not re.search(r"case \d|skew|parallel|intersect", why.replace("skew lines never", "")), item
            assert said.startswith("x")


def test_x_cases_accept_spanish_words_and_string_keys():
    assert check_x_cases({"x1": "se cruzan", "x2": "paralelos", "x3": "se cortan"}).ok
    assert check_x_cases({"1": "caso 3", "2": "caso 2", "3": "caso 1"}).ok


def test_x_cases_reproduce_the_seed_claims_for_the_ssrms():
    ssrms = robots.ssrms()
    assert check_x_cases([1, 1, 2, 2, 1, 1], robot=ssrms).ok
    fb = check_x_cases([1, 1, 1, 2, 1, 1], robot=ssrms)
    assert "x3" in only_item(fb) and "do not meet" in only_item(fb) and "is 12, not 0" in only_item(fb)


def test_x_cases_coincident_axes_accept_either_word():
    rppr = robots.seed002_4dof()         # z0, z1 the same line; z1, z2 intersect; z2, z3 the same line
    assert check_x_cases(["parallel", "intersect", "coincident"], robot=rppr).ok


# --- 5.2 -----------------------------------------------------------------------------------------
def test_dh_row_right_and_wrapped_angles():
    assert check_dh_row((120, 0.3, 0.4, -90)).ok
    assert check_dh_row((120 - 360, 0.3, 0.4, 270)).ok


@pytest.mark.parametrize("answer, expected", [
    ((120, 0.3, 0.4, 90), "α: the size is right but not the sign"),
    ((-120, 0.3, 0.4, -90), "θ: turning x_(i−1) by your θ = -120°"),
    ((300, 0.3, -0.4, 90), "It is 180° off"),
    ((120, -0.3, 0.4, -90), "d: your d = -0.3"),
    ((120, 0.3, -0.4, -90), "a is measured along +x_i"),
    ((120, 0.3, 0.4, 0), "which keeps z_i parallel to z_(i−1)"),
])
def test_dh_row_wrong_parameter_is_named(answer, expected):
    fb = check_dh_row(answer)
    assert fb.status == "wrong" and any(expected in item for item in fb.items), str(fb)


def test_dh_row_swapped_d_and_a():
    assert "d and a are swapped" in only_item(check_dh_row((120, 0.4, 0.3, -90)))


def test_dh_row_alpha_on_parallel_axes_gets_the_course_message():
    before = trans(1, 2, 3) @ Rz(0.4)
    frames = (before, before @ dh_matrix(math.radians(30), 0.5, 1.2, 0.0))   # α = 0: z axes parallel
    assert check_dh_row((30, 0.5, 1.2, 0), frames).ok
    item = only_item(check_dh_row((30, 0.5, 1.2, -90), frames))
    assert item.startswith("α: your α is -90°, but z_(i−1) and z_i are parallel")


# --- 5.3 and 6.3: fair table checks ------------------------------------------------------------------
ARM_VALID = [
    ARM_TABLE,
    [("q1 + 180", 0.5, -0.2, 90), ("q2 + 90", 0, 0.5, 0), ("q3", 0, 0, -90), ("q4", 0.5, 0, 0)],   # x1 flipped
    [("q1", 0.5, 0.2, -90), ("q2 - 90", 0, 0.5, 0), ("q3 + 180", 0, 0, 90), ("q4", 0.5, 0, 0)],   # x3 flipped
    [("q1", 0.5, 0.2, -90), ("q2 - 90", 0.1, 0.5, 0), ("q3", -0.1, 0, -90), ("q4", 0.5, 0, 0)],  # other normal
    [("q1", 0.5, 0.2, -90), ("q2 - 90", 0, 0.5, 0), ("q3", 0, 0, -90), ("q4 + 90", 0.5, 0, 0)],  # x4 turned
]


@pytest.mark.parametrize("rows", ARM_VALID)
def test_table_every_valid_assignment_scores(rows):
    assert check_table(rows).ok


@pytest.mark.parametrize("case1", ["z_prev x z", "z x z_prev", "nearest"])
@pytest.mark.parametrize("parallel", ["at_joint", "zero_d"])
def test_table_tables_placed_by_dh_from_axes_are_accepted(case1, parallel):
    for reference in (four_axis_arm(), robots.seed002_4dof(), robots.ssrms(), robots.seed002_6dof()):
        axes, tool = joint_axes(reference)
        rebuilt = dh_from_axes(axes, tool[:3, 3], case1=case1, parallel=parallel)
        assert compare_robots(rebuilt, reference) == [], (reference.name, case1, parallel)


@pytest.mark.parametrize("rows, expected", [
    ([("q1", 0.5, 0.2, -90), ("q2 - 90", 0, 0.5, -90), ("q3", 0, 0, -90), ("q4", 0.5, 0, 0)],
     "joint 3: your α2 is -90°, but z1 and z2 (the axes of joints 2 and 3) are parallel: α2 must be 0° or 180°."),
    ([("q1", 0.5, 0.2, 0), ("q2 - 90", 0, 0.5, 0), ("q3", 0, 0, -90), ("q4", 0.5, 0, 0)],
     "joint 2: your α1 is 0°, which keeps z1 parallel to z0, "
     "but z0 and z1 (the axes of joints 1 and 2) are at 90° to each other."),
    ([("q1", 0.5, 0.2, 90), ("q2 - 90", 0, 0.5, 0), ("q3", 0, 0, -90), ("q4", 0.5, 0, 0)],
     "joint 2: z1 points against joint 2's positive sense"),
    ([("q1", 0.5, 0.2, -90), ("q2 - 90", 0, 0.5, 0), ("q3", 0, 0.1, -90), ("q4", 0.5, 0, 0)],
     "joint 4: your a3 = 0.1 puts z2 and z3 (the axes of joints 3 and 4) 0.1 apart, but they intersect, so a3 = 0."),
    ([("q1", 0.4, 0.2, -90), ("q2 - 90", 0, 0.5, 0), ("q3", 0, 0, -90), ("q4", 0.5, 0, 0)],
     "joint 2: the axis has the right direction and distance from joint 1's axis, "
     "but sits at the wrong place along z0 at q = 0: check d1."),
    ([("q1", 0.5, 0.2, -90), ("q2", 0, 0.5, 0), ("q3", 0, 0, -90), ("q4", 0.5, 0, 0)],
     "joint 3: the axis has the right direction and distance from joint 2's axis, "
     "but is turned about z1 at q = 0: check θ2"),
    ([("q1", 0.5, 0.2, -90), ("q2 - 90", 0.1, 0.5, 0), ("q3", 0, 0, -90), ("q4", 0.5, 0, 0)],
     "check d3 (or d2: z1 ∥ z2"),
    ([("q1", 0.5, 0.2, -90), ("q2 - 90", 0, 0.5, 0), ("q3", 0, 0, -90), ("q4", 0.4, 0, 0)],
     "every joint axis is right, but the end effector is at (0.6, 0, 1) at q = 0, not at (0.7, 0, 1)"),
    ([("q1", 0.5, 0.2, -90), ("q2 - 90", 0, 0.5, 0), (0, "d3", 0, -90), ("q4", 0.5, 0, 0)],
     "joint 3 is revolute (R): its variable belongs in θ3, but your row 3 makes d3 the variable."),
    (ARM_TABLE[:3], "your table has 3 rows, but the robot has 4 joints"),
])
def test_table_first_mistake_is_named_with_joint_and_quantity(rows, expected):
    assert only_item(check_table(rows)).startswith(expected) or expected in only_item(check_table(rows))


def test_table_prismatic_axis_is_a_direction_only():
    moved_line = [("q1", "l1", 0, 0), (90, "d2", 0.3, 90), (0, "d3", -0.3, 0), ("q4", "l4", 0, 0)]   # note 002-n2
    assert check_table(moved_line, "seed002_4dof").ok
    reversed_z2 = [("q1", "l1", 0, 0), (90, "d2", 0, -90), (0, "d3", 0, 0), ("q4", "l4", 0, 0)]
    assert "z2 points against joint 3's positive sense" in only_item(check_table(reversed_z2, "seed002_4dof"))


def test_table_exercise_6_3_wants_another_table_than_the_slide():
    ex = exercise("6.3")
    assert "this is the slide's own table" in only_item(ex.check(RPPR_TABLE))
    assert ex.check([("q1", "l1", 0, 0), (-90, "d2", 0, -90), (180, "d3", 0, 0), ("q4", "l4", 0, 0)]).ok


def test_table_random_perturbations_of_a_valid_table_are_caught():
    """Any change of d, a or α moves a joint axis or the end effector (the last row's α turns the
    end effector's z away from z_{n-1}, where rule 9 puts it)."""
    rng = np.random.default_rng(0)
    reference = four_axis_arm()
    for _ in range(30):
        rows = [list(r) for r in ARM_TABLE]
        i, col = int(rng.integers(0, 4)), int(rng.integers(1, 4))
        rows[i][col] = float(rows[i][col]) + (float(rng.choice([-1, 1])) * (0.15 if col < 3 else 45))
        student = dhlab.DHRobot.from_table(rows)
        assert compare_robots(student, reference), rows


# --- 6.1 -----------------------------------------------------------------------------------------
C2, S2, L2 = sp.symbols("C2 S2 l2")
RIGHT_12 = sp.Matrix([[-S2, 0, -C2, 0], [C2, 0, -S2, 0], [0, -1, 0, L2], [0, 0, 0, 1]])


def test_link_matrix_right_with_names_or_functions():
    q2 = sp.Symbol("q2")
    assert check_link_matrix(RIGHT_12).ok
    assert check_link_matrix(RIGHT_12.subs({C2: sp.cos(q2), S2: sp.sin(q2)})).ok
    assert check_link_matrix(sp.Matrix(link_exercise_robot().A(2))).ok


@pytest.mark.parametrize("matrix, expected", [
    (sp.Matrix([[C2, 0, -S2, 0], [S2, 0, C2, 0], [0, -1, 0, L2], [0, 0, 0, 1]]), "you left out the offset"),
    (sp.Matrix([[-S2, 0, C2, 0], [C2, 0, S2, 0], [0, 1, 0, L2], [0, 0, 0, 1]]), "the sign of α2 is flipped"),
    (RIGHT_12.T, "transposed"),
])
def test_link_matrix_known_mistakes(matrix, expected):
    assert expected in only_item(check_link_matrix(matrix))


def test_link_matrix_single_entry_is_located():
    wrong = RIGHT_12.copy()
    wrong[2, 3] = 0
    fb = check_link_matrix(wrong)
    assert any("row 3, column 4" in item for item in fb.items), str(fb)


def test_link_matrix_of_the_slides_robots():
    C4, S4, l3 = sp.symbols("C4 S4 l3")
    seed003_A4 = sp.Matrix([[S4, 0, C4, 0], [-C4, 0, S4, 0], [0, -1, 0, l3], [0, 0, 0, 1]])   # VERIFIED_MATH §6.1
    assert check_link_matrix(seed003_A4, 4, robots.seed003_6dof()).ok


# --- 6.2 -----------------------------------------------------------------------------------------
def test_wrist_centre_right_and_the_usual_slips():
    arm6 = robots.seed002_6dof()
    q = np.radians(WRIST_Q_DEG)
    F, T = arm6.frames(q), arm6.fk(q)
    assert check_wrist_centre(F[4, :3, 3]).ok
    assert check_wrist_centre(T[:3, 3] - 4 * T[:3, 2]).ok
    assert "that is the end effector p" in only_item(check_wrist_centre(T[:3, 3]))
    assert "wrong way along a" in only_item(check_wrist_centre(T[:3, 3] + 4 * T[:3, 2]))
    assert "origin of frame 3" in only_item(check_wrist_centre(F[3, :3, 3]))


# --- 7.1-7.3 -------------------------------------------------------------------------------------
def test_thlist_slots():
    assert check_thlist_slots({k: 2 * k for k in range(1, 8)}).ok
    fb = check_thlist_slots({k: 2 * k + (1 if k == 3 else 0) for k in range(1, 8)})
    assert only_item(fb).startswith("joint 3: not THList[7]: THList[7] is link 3's Tx[α, a] factor")
    assert "THList[6]" not in only_item(fb) and "just before" not in only_item(fb)      # not the answer
    fb = check_thlist_slots({k: 2 * k - (2 if k == 1 else 0) for k in range(1, 8)})
    assert "the Tz factor of the base" in only_item(fb)


def test_parallel_pairs_of_the_ssrms():
    assert parallel_pairs() == {(3, 4), (3, 5), (4, 5)}
    assert check_parallel_pairs({(3, 4), (4, 5), (5, 3)}).ok
    fb = check_parallel_pairs({(3, 4), (4, 5), (3, 5), (1, 3)})
    assert only_item(fb) == ("joints 1 and 3: parallel at θ = 0, but not at every configuration: "
                             "at θ = (0, 30, 0, 0, 0, 0, 0)° they are not.")
    item = only_item(check_parallel_pairs({(3, 4), (4, 5)}))
    assert item.startswith("1 pair of joints") and "missing" in item and "(3, 5)" not in item and "3 and 5" not in item


def test_printed_key_positions_match_verified_math_5_5():
    verified = {1: (24, 0, -13), 2: (24, -6, -10.5), 3: (24, 0, -4.5), 4: (24, 0, -9.5), 5: (24, 0, -4.5),
                6: (24, 6, -10.5), 7: (24, 0, -10.5)}          # VERIFIED_MATH.md §5.5, typed
    for joint, position in verified.items():
        assert np.allclose(printed_key_position(joint), position, atol=1e-9), joint


def test_key_jump_two_keys():
    assert np.allclose(printed_key_position((2, 5)), (24, -6, -4.5))
    assert check_key_jump((24, -6, -4.5)).ok
    assert "correct code (THz)" in only_item(check_key_jump((24, 0, -10.5)))
    assert "joint 5's key alone" in only_item(check_key_jump((24, 0, -4.5)))


# --- every exercise: unanswered, garbage, hints ----------------------------------------------------
RIGHT = {"5.1": {1: "skew", 2: "parallel", 3: "intersect"}, "5.2": (120, 0.3, 0.4, -90), "5.3": ARM_TABLE,
         "6.1": RIGHT_12, "6.2": None, "6.3": [("q1", "l1", 0, 0), (-90, "d2", 0, -90), (0, "d3", 0, 0),
                                                ("q4", "l4", 0, 0)],
         "7.1": {k: 2 * k for k in range(1, 8)}, "7.2": {(3, 4), (3, 5), (4, 5)}, "7.3": (24, -6, -4.5)}


DH_KEYS = [key for key in available() if int(key.split(".")[0]) >= 5]      # the exercises of notebooks 5-7


def test_one_registry_serves_every_notebook():
    assert DH_KEYS == list(RIGHT) and available()[0] == "1.1"
    from dhlab.course import exercises_dh  # the old name, kept for one release
    assert exercises_dh.exercise is exercise
    with pytest.raises(KeyError, match=r"did you mean '5\.3'"):
        exercise("5.4")


@pytest.mark.parametrize("key", DH_KEYS)
def test_every_exercise_right_unanswered_and_hints(key):
    ex = exercise(key)
    right = RIGHT[key]
    if key == "6.2":
        right = robots.seed002_6dof().frames(np.radians(WRIST_Q_DEG))[4, :3, 3]
    assert ex.check(right).ok
    assert ex.check(...).status == "unanswered"
    assert ex.check(None).status == "unanswered"
    assert ex.hint().status == "hint" and ex.hints


@pytest.mark.parametrize("key", DH_KEYS)
def test_no_input_makes_a_check_raise(key):
    ex = exercise(key)
    for answer in GARBAGE:
        fb = ex.check(answer)
        assert fb.status == "wrong" and fb.items, (key, answer, str(fb))


# --- the checks themselves never raise (not only through Exercise.check, which would hide it) ----------
DIRECT = {"5.1": check_x_cases, "5.2": check_dh_row, "5.3": lambda rows: check_table(rows, "arm"),
          "6.1": lambda M: check_link_matrix(M, 2), "6.2": check_wrist_centre,
          "6.3": lambda rows: check_table(rows, "seed002_4dof", different=True),
          "7.1": check_thlist_slots, "7.2": check_parallel_pairs, "7.3": check_key_jump}
JUNK = [np.nan, math.inf, -math.inf, 1 + 2j, sp.zoo, sp.nan, sp.oo, sp.Integral(sp.Symbol("x"), sp.Symbol("x")),
        sp.Function("f")(sp.Symbol("q2")), None, True, 10 ** 400, -10 ** 30, "", "q1", b"bytes", 2.5, -7,
        np.array([1.0, np.nan]), np.zeros((4, 4)), sp.eye(4), sp.zeros(3, 1), [np.nan] * 4, [1, 2, 3, 4, 5],
        [None, 0, 0, 0], [True, 0, 0, 0], [[1, 2], [3]], ["q1", "l1", 0], [("q1", np.inf, 0, 0)] * 4,
        [("q1", 0, 0, 1e300)] * 4, [(1 + 1j, 0, 0, 0)] * 4, [("q1", None, 0, 0)] * 4, [{"a": 1}] * 4,
        {1: np.nan, 2: None, 3: "x"}, {(1, 2), ("a", "b")}, {(1, np.inf)}, {(1, 2, 3)}, "1234",
        {k: math.inf for k in range(1, 8)}, {k: 2.5 for k in range(1, 8)}, {k: True for k in range(1, 8)},
        {"x1": "skew", "x9": "skew"}, object(), sp.Matrix([[sp.zoo, 0], [0, 1]]), slice(1, 2), range(4)]


def test_five_two_refuses_a_dict_whose_keys_are_the_right_row():
    # iterating a dict gives its keys: this answer was once marked correct
    fb = exercise("5.2").check({120: "a", 0.3: "b", 0.4: "c", -90: "d"})
    assert fb.status == "wrong" and "dict" in fb.items[0], str(fb)
    assert exercise("5.2").check((120, 0.3, 0.4, -90)).ok


@pytest.mark.parametrize("key", sorted(DIRECT))
@pytest.mark.parametrize("answer", JUNK, ids=[type(j).__name__ + str(i) for i, j in enumerate(JUNK)])
def test_checks_give_feedback_for_junk(key, answer):
    fb = DIRECT[key](answer)
    assert fb.status in ("wrong", "unanswered"), (key, answer, str(fb))
    assert fb.status == "unanswered" or fb.items, str(fb)
    assert "Error" not in str(fb), str(fb)          # a reason in the student's terms, not an exception's name


def _junk():
    leaves = st.one_of(st.none(), st.booleans(), st.integers(), st.floats(allow_nan=True, allow_infinity=True),
                       st.complex_numbers(), st.text(max_size=8),
                       st.sampled_from([sp.zoo, sp.nan, sp.oo, sp.pi, sp.Symbol("q2"), sp.Symbol("l1"),
                                        sp.Integral(sp.Symbol("x"), sp.Symbol("x")), sp.I]),
                       st.sampled_from(["q1", "q2 - 90", "l1", "d2", "skew", "parallel", "intersect", "caso 2"]))
    return st.recursive(leaves, lambda kids: st.one_of(
        st.lists(kids, max_size=8), st.tuples(kids, kids, kids, kids),
        st.dictionaries(st.integers(-2, 9), kids, max_size=8),
        st.frozensets(st.tuples(st.integers(-2, 9), st.integers(-2, 9)), max_size=5),
        st.lists(st.tuples(kids, kids, kids, kids), min_size=4, max_size=4)), max_leaves=24)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(answer=_junk(), key=st.sampled_from(sorted(DIRECT)))
def test_random_answers_in_feedback_out(answer, key):
    fb = DIRECT[key](answer)
    assert isinstance(fb, Feedback)
    assert fb.status in ("correct", "wrong", "unanswered")
    assert fb.status != "wrong" or fb.items
    str(fb), fb._repr_html_()
    via_exercise = exercise(key).check(answer)
    assert via_exercise.status == fb.status


def test_exercise_keys_used_in_the_notebooks_exist():
    for name in ("05_dh_convention", "06_dh_examples", "07_ssrms"):
        path = NOTEBOOKS / f"{name}.ipynb"
        if not path.exists():
            pytest.skip(f"{path.name} not present")
        source = "\n".join(c.source for c in nbformat.read(path, as_version=4).cells)
        keys = re.findall(r'exercise\("(\d\.\d)"\)', source)
        assert keys and set(keys) <= set(available()), (name, keys)
        assert all(k.startswith(name[1]) for k in keys), (name, keys)


def test_row_exercise_frames_are_related_by_a_dh_link():
    before, after = row_exercise_frames()
    A = np.linalg.solve(before, after)
    assert np.allclose(A, dh_matrix(math.radians(120), 0.3, 0.4, math.radians(-90)))
    assert dhlab.is_rigid(before) and dhlab.is_rigid(after)


# --- notebooks 5-7: stated numbers come from the code, seed cases are checked, errata stated ---------------
NOTEBOOK_NAMES = ["05_dh_convention", "06_dh_examples", "07_ssrms"]
NUMBER = re.compile(r"(?<![\w.])-?\d+(?:\.\d+)?")
DECIMAL = re.compile(r"(?<![\w.{,])[-−]?\d+\.\d+(?![\w])")


def _notebook(name):
    path = NOTEBOOKS / f"{name}.ipynb"
    if not path.exists():
        pytest.skip(f"{path.name} not present")
    return nbformat.read(path, as_version=4)


def _outputs(cells) -> str:
    parts = []
    for cell in cells:
        for out in cell.get("outputs", []):
            if out.output_type == "stream":
                parts.append(out.text)
            elif out.output_type in ("execute_result", "display_data"):
                parts.append(out.data.get("text/plain", ""))
    return "\n".join(parts)


def _checked_numbers(nb):
    cells = [c for c in nb.cells if checks_output(c)]
    return [float(m) for m in NUMBER.findall(_outputs(cells))]


def _contains(values, expected, tol=1e-6) -> bool:
    expected = [float(v) for v in expected]
    return any(all(abs(values[i + k] - e) <= tol for k, e in enumerate(expected))
               for i in range(len(values) - len(expected) + 1))


@pytest.mark.parametrize("name", NOTEBOOK_NAMES)
def test_notebook_stored_executed_without_errors(name):
    for cell in _notebook(name).cells:
        if cell.cell_type == "code":
            assert cell.execution_count is not None, f"{name}: not executed:\n{cell.source[:80]}"
            assert all(o.output_type != "error" for o in cell.outputs), f"{name}: raised:\n{cell.source[:80]}"


@pytest.mark.parametrize("name", NOTEBOOK_NAMES)
def test_notebook_numbers_in_the_text_are_printed_by_the_code(name):
    nb = _notebook(name)
    printed = [float(m) for m in NUMBER.findall(_outputs(c for c in nb.cells if c.cell_type == "code"))]
    missing = []
    for cell in nb.cells:
        if cell.cell_type != "markdown":
            continue
        if cell.source.lstrip().startswith("## Exercises"):
            break
        text = re.sub(r"§\s*[\d.–-]+|`[^`]*`", " ", cell.source)
        for match in DECIMAL.findall(text):
            value, digits = float(match.replace("−", "-")), len(match.split(".")[1])
            if not any(abs(p - value) <= 0.5 * 10 ** -digits + 1e-12 for p in printed):
                missing.append(match)
    assert not missing, f"{name}: the text states numbers no output prints: {missing}"


SEED_CASES_PRINTED = {
    "05_dh_convention": ["002_6dof_30_-45_60_90_-30_45"],
    "06_dh_examples": ["002_4dof_0_0.0_0.0_0", "002_4dof_30_0.5_0.4_45", "002_4dof_90_1.0_1.0_90",
                       "002_6dof_0_0_0_0_0_0", "002_6dof_90_0_0_0_0_0", "002_6dof_0_90_0_0_0_0",
                       "002_6dof_0_0_90_0_0_0", "002_6dof_30_-45_60_90_-30_45", "003_6dof_0_0_0_0_0_0",
                       "003_6dof_0_90_0_0_0_0", "003_6dof_0_0_90_0_0_0", "003_6dof_0_0_0_0_90_0",
                       "003_6dof_30_-45_60_90_-30_45"],
    "07_ssrms": [f"000_SSRMS_{q}" for q in ("0_0_0_0_0_0_0", "90_0_0_0_0_0_0", "0_90_0_0_0_0_0", "0_0_90_0_0_0_0",
                                            "0_0_0_90_0_0_0", "0_0_0_0_90_0_0", "0_0_0_0_0_90_0", "0_0_0_0_0_0_90",
                                            "10_20_30_40_50_60_70", "-30_45_-60_90_-45_30_180")],
}


@pytest.mark.parametrize("name, case_id", [(n, c) for n, ids in SEED_CASES_PRINTED.items() for c in ids])
def test_notebook_prints_the_seed_cases_in_checked_cells(name, case_id):
    from support.seeddata import load_cases
    case = {c["id"]: c for c in load_cases()}[case_id]
    assert _contains(_checked_numbers(_notebook(name)), case["expected_position"]), case_id


def test_notebook_7_prints_the_verified_ssrms_frames_001_and_key_jumps():
    from support.seeddata import load_cases
    cases = {c["id"]: c for c in load_cases()}
    values = _checked_numbers(_notebook("07_ssrms"))
    for origin in cases["000_SSRMS_0_0_0_0_0_0_0"]["frame_origins"]:
        assert _contains(values, origin), origin
    for angle in (0, 30, 45):
        det = round(cases[f"001_DefinirTHz_{angle}"]["listing_001_det_R"], 4) + 0.0
        assert _contains(values, [angle, det]), angle
    for position in ((24, 0, -13), (24, -6, -10.5), (24, 0, -4.5), (24, 0, -9.5), (24, 6, -10.5)):
        assert _contains(values, position), position               # VERIFIED_MATH §5.5
    assert _contains(values, [0, 0, 10.5, -1]) and _contains(values, [-0.5, 0.5, 12.692, 0])   # 001 on the SSRMS


ERRATA_STATED = {
    "05_dh_convention": ["002-n1", "002-n2", "003-n1"],
    "06_dh_examples": ["002-n1", "003-n2"],
    "07_ssrms": ["000-1", "000-2", "000-3", "000-4", "000-5", "000-6", "000-7", "000-8",
                 "001-1", "001-2", "001-3", "001-4"],
}


@pytest.mark.parametrize("name", NOTEBOOK_NAMES)
def test_notebook_states_the_errata_where_they_arise(name):
    text = "\n".join(c.source for c in _notebook(name).cells if c.cell_type == "markdown")
    missing = [e for e in ERRATA_STATED[name] if e not in set(re.findall(r"\b(\d{3}-n?\d+)\b", text))]
    assert not missing, f"{name}: errata not stated: {missing}"


@pytest.mark.parametrize("name", NOTEBOOK_NAMES)
def test_notebook_panels_are_not_compared_and_exercises_are_asked_before_answered(name):
    nb = _notebook(name)
    for cell in nb.cells:
        if cell.cell_type == "code" and any("<dhlab" in o.get("data", {}).get("text/plain", "") for o in cell.outputs):
            assert ignores_output(cell), f"{name}: a panel cell is compared:\n{cell.source[:80]}"
    checks = [i for i, c in enumerate(nb.cells) if c.cell_type == "code" and re.search(r"ex\d+\.check\(", c.source)]
    assert 2 <= len(checks) <= 4, f"{name}: {len(checks)} exercises"
    start = next(i for i, c in enumerate(nb.cells) if c.cell_type == "markdown" and c.source.startswith("## Exercises"))
    for i in checks:        # at the end, or in the text as predict-then-check: the worked answer comes after it
        assert i > start or any(c.cell_type == "markdown" and c.source.startswith("**Check your prediction.**")
                                for c in nb.cells[i + 1:i + 4]), f"{name}: exercise cell {i} is not predict-then-check"
    assert nb.cells[-1].source.startswith("## Recap")


def test_notebook_7_asks_exercise_7_1_before_printing_its_answer():
    nb = _notebook("07_ssrms")
    ask = next(i for i, c in enumerate(nb.cells) if 'exercise("7.1")' in c.source)
    answers = [i for i, c in enumerate(nb.cells) if c.cell_type == "code" and "writes THList[" in _outputs([c])]
    tables = [i for i, c in enumerate(nb.cells) if c.cell_type == "markdown" and "| index in `THList`" in c.source]
    assert answers and tables and min(answers + tables) > ask


@pytest.mark.parametrize("module", ["exercises", "exercises.dh_common", "exercises.dh_tables",
                                    "exercises.dh_links", "exercises.ssrms", "exercises.dh_rules"])
def test_docstring_examples(module):
    import doctest
    import importlib
    result = doctest.testmod(importlib.import_module(f"dhlab.course.{module}"),
                             optionflags=doctest.NORMALIZE_WHITESPACE)
    assert result.failed == 0
