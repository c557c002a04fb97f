"""Bad input into the exercise checks of notebooks 1-7 and the public helpers of dhlab.course.exercises.
A check never raises on a student's answer and never marks a wrong one correct (symbolic answers are
compared over a whole turn, exercise 5.1 reads one case per answer, an answer that cannot be printed
still gets feedback); the helpers refuse a teacher's bad arguments with a DHLabError."""
import functools

import numpy as np
import pytest
import sympy as sp

import dhlab
from dhlab import DHLabError
from dhlab.course.exercises import exercise

TH, T0, T1, L1, L2 = sp.symbols("theta theta0 theta1 l1 l2")
C2, S2 = sp.symbols("C2 S2")
RIGHT_61 = sp.Matrix([[-S2, 0, -C2, 0], [C2, 0, -S2, 0], [0, -1, 0, L2], [0, 0, 0, 1]])
RIGHT_32 = dhlab.Rz(T0) * dhlab.trans(L1, 0, 0) * dhlab.Rz(T1) * dhlab.trans(L2, 0, 0)


def check(key, answer):
    return exercise(key).check(answer)


def half_cos(M, th):
    """cos θ written as √(1 − sin²θ): right only for |θ| ≤ 90°."""
    return M.subs(sp.cos(th), sp.sqrt(1 - sp.sin(th) ** 2))


# --- symbolic answers are compared over a whole turn ------------------------------------------
@pytest.mark.parametrize("key, answer", [
    ("2.1", half_cos(dhlab.Rz(TH), TH)),
    ("2.1", dhlab.Rz(sp.asin(sp.sin(TH)))),
    ("2.1", sp.Matrix(dhlab.Rz(TH)).applyfunc(lambda e: sp.Piecewise((e, TH < 2), (0, True)))),
    ("3.1", half_cos(dhlab.Rz(T0) * dhlab.trans(0, L1, 0), T0)),
    ("3.2", half_cos(RIGHT_32, T0)),
    ("3.2", half_cos(RIGHT_32, T1)),
    ("6.1", RIGHT_61.subs(C2, sp.sqrt(1 - S2 ** 2))),
], ids=["2.1-sqrt", "2.1-asin", "2.1-piecewise", "3.1-sqrt", "3.2-sqrt-theta0", "3.2-sqrt-theta1", "6.1-sqrt"])
def test_an_answer_wrong_beyond_90_degrees_is_wrong(key, answer):
    feedback = check(key, answer)
    assert feedback.status == "wrong", str(feedback)


@pytest.mark.parametrize("key, answer", [
    ("2.1", dhlab.Rz(TH)), ("3.1", dhlab.Rz(T0) * dhlab.trans(0, L1, 0)), ("3.2", RIGHT_32),
    ("3.2", RIGHT_32.applyfunc(sp.expand_trig)), ("6.1", RIGHT_61),
    ("6.1", RIGHT_61.subs({C2: sp.cos(sp.Symbol("q2")), S2: sp.sin(sp.Symbol("q2"))})),
])
def test_right_answers_still_pass(key, answer):
    assert check(key, answer).ok


# --- exercise 5.1 reads one case per answer ------------------------------------------------------
@pytest.mark.parametrize("answer, said", [
    ({1: "skew", 2: "parallel", 3: "they do not intersect"}, "says what does not hold"),
    ({1: "skew", 2: "parallel", 3: "no se cortan"}, "says what does not hold"),
    ({1: "skew", 2: "skew, not parallel", 3: "intersect"}, "names two cases (parallel and skew)"),
    ({1: "case 3: skew", 2: "case 1, parallel", 3: "intersect"}, "names two cases (intersect and parallel)"),
])
def test_a_negated_or_double_case_is_not_read_as_right(answer, said):
    feedback = check("5.1", answer)
    assert feedback.status == "wrong" and len(feedback.items) == 1 and said in feedback.items[0], str(feedback)


def test_coincident_for_intersecting_axes_does_not_contradict_itself():
    item, = check("5.1", {1: "skew", 2: "parallel", 3: "coincident"}).items
    assert item.startswith("x3: you said z2 and z3 are the same line, but") and "0, not 0" not in item


# --- the last frame's z axis is compared -------------------------------------------------------------
ARM = [("q1", 0.5, 0.2, -90), ("q2 - 90", 0, 0.5, 0), ("q3", 0, 0, -90)]


@pytest.mark.parametrize("key, rows", [
    ("5.3", ARM + [("q4", 0.5, 0, 90)]), ("5.3", ARM + [("q4", 0.5, 0, -45)]), ("5.3", ARM + [("q4", 0.5, 0, 123)]),
    ("5.3", ARM + [("q4", 0.5, 0, 180)]),
    ("6.3", [("q1", "l1", 0, 0), (90, "d2", 0, 90), (0, "d3", 0, 0), ("q4", "l4", 0, 45)]),
])
def test_a_wrong_last_alpha_is_wrong(key, rows):
    item, = check(key, rows).items
    assert "your α4 =" in item and "rule 9 puts z4 along z3" in item


# --- an answer whose repr fails still gets feedback ------------------------------------------------
class BadRepr(float):
    def __repr__(self):
        raise RuntimeError("no repr")


DEEP = functools.reduce(lambda a, _: [a], range(3000), [])


@pytest.mark.parametrize("key, answer", [
    ("1.3", DEEP), ("1.1", DEEP), ("2.1", DEEP), ("3.3", DEEP), ("4.5", DEEP), ("5.2", DEEP), ("6.1", DEEP),
    ("7.3", DEEP), ("4.5", BadRepr(1.0)), ("1.3", BadRepr(1.0)), ("4.5", [BadRepr(1.0)]),
    ("5.3", [BadRepr(1.0)] * 4), ("6.3", [BadRepr(1.0)] * 4),
], ids=lambda v: v if isinstance(v, str) else type(v).__name__)
def test_an_answer_that_cannot_be_printed_gets_feedback(key, answer):
    feedback = check(key, answer)
    assert feedback.status == "wrong" and feedback.items


# --- the public helpers of dhlab.course.exercises refuse bad teacher arguments -------------------------
X = dhlab.course.exercises


@pytest.mark.parametrize("call", [
    lambda: X.thlist_slot("1"), lambda: X.thlist_slot(None), lambda: X.thlist_slot(True),
    lambda: X.printed_key_position("a"), lambda: X.printed_key_position(None), lambda: X.printed_key_position(99),
    lambda: X.printed_key_position(2.7), lambda: X.printed_key_position("1"), lambda: X.printed_key_position(True),
    lambda: X.printed_key_position(1e308),
    lambda: X.parallel_pairs(robot=5), lambda: X.parallel_pairs(samples=0), lambda: X.parallel_pairs(samples=-1),
    lambda: X.parallel_pairs(samples="a"), lambda: X.parallel_pairs(samples=1.5),
    lambda: X.check_link_matrix(sp.eye(4), i=99), lambda: X.check_link_matrix(sp.eye(4), i="2"),
    lambda: X.check_link_matrix(sp.eye(4), i=None),
    lambda: X.check_dh_row([0, 0, 0, 0], frames=5),
    lambda: X.check_wrist_centre([0, 0, 0], q_deg="abc"),
    lambda: X.check_x_cases({1: "skew"}, robot=5), lambda: X.check_parallel_pairs({(1, 2)}, robot=5),
    lambda: X.check_wrist_centre([0, 0, 0], robot=5), lambda: X.check_link_matrix(sp.eye(4), robot=5),
    lambda: X.check_key_jump((0, 0, 0), joints=[2, "5"]), lambda: X.compare_robots(5, X.four_axis_arm()),
    lambda: X.check_table([], params=5),
], ids=["thlist-text", "thlist-None", "thlist-True", "key-text", "key-None", "key-99", "key-2.7", "key-'1'",
        "key-True", "key-1e308", "pairs-robot", "pairs-0", "pairs-neg", "pairs-text", "pairs-1.5", "link-99",
        "link-'2'", "link-None", "row-frames", "wrist-q_deg", "cases-robot", "check-pairs-robot", "wrist-robot",
        "link-robot", "jump-joints", "compare-student", "table-params"])
def test_helpers_refuse_bad_arguments_with_DHLabError(call):
    with pytest.raises(DHLabError):
        call()


def test_helpers_still_give_the_seed_answers():
    assert X.thlist_slot(1) == 2 and X.thlist_slot(np.int64(7)) == 14
    assert X.printed_key_position(1).round(6).tolist() == [24.0, 0.0, -13.0]
    assert np.allclose(X.printed_key_position([2, 5]), (24, -6, -4.5))
    assert X.parallel_pairs(samples=1) >= X.parallel_pairs() == {(3, 4), (3, 5), (4, 5)}
