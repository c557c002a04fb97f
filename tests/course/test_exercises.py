"""The exercise checks: right answers in any form pass, and each typical mistake gets its own message."""
import math

import numpy as np
import pytest
import sympy as sp

import dhlab
from dhlab import deg2rad
from dhlab.course.exercises import (
    Exercise,
    Feedback,
    available,
    check_choice,
    check_function,
    check_matrix,
    check_solutions,
    check_terms,
    check_value,
    exercise,
    seed001_DefinirTHz,
)
from dhlab.course.exercises.homogeneous import seed000_DefinirTHz
from dhlab.transforms import Rx, Rz, trans

TH = sp.Symbol("theta")


def text(feedback):
    return str(feedback)


# --- Feedback ------------------------------------------------------------------------------------
def test_feedback_truth_text_and_html():
    right, wrong = Feedback("correct", "fine"), Feedback("wrong", "no <b>", ["a < b"], tip="try")
    assert right and not wrong and right.ok and not wrong.ok
    assert str(wrong) == "✗ no <b>\n  • a < b\n  try"
    assert "&lt;b&gt;" in wrong._repr_html_() and "a &lt; b" in wrong._repr_html_()
    with pytest.raises(ValueError):
        Feedback("maybe", "x")


# --- check_matrix: right answers in any form -----------------------------------------------------
def test_symbolic_right_in_any_equivalent_form_and_symbol_spelling():
    a, b = sp.symbols("a b", real=True)
    expected = Rz(a + b)
    expanded = expected.applyfunc(lambda e: sp.expand_trig(e))
    assert check_matrix(expanded, expected).ok
    # θ0, theta_0 and theta0 (with or without assumptions) are the same symbol
    th0_real, th0_greek, th0_sub = sp.Symbol("theta0", real=True), sp.Symbol("θ0"), sp.Symbol("theta_0")
    assert check_matrix(Rz(th0_greek), Rz(th0_real)).ok
    assert check_matrix(Rz(th0_sub), Rz(th0_real)).ok


def test_numeric_right_when_rounded_or_as_lists():
    T = Rz(math.radians(30)) @ trans(2, 0, 0)
    assert check_matrix(np.round(T, 3), T).ok
    assert check_matrix(np.round(T, 3).tolist(), T).ok
    assert check_matrix(sp.Matrix(T), T).ok
    assert not check_matrix(np.round(T, 1), T).ok


def test_unanswered_and_refused_inputs():
    assert check_matrix(..., Rz(TH)).status == "unanswered"
    assert check_matrix(None, Rz(TH)).status == "unanswered"
    assert check_matrix([[1, ...], [0, 1]], sp.eye(2)).status == "unanswered"
    assert "is text" in text(check_matrix("cos(theta)", Rz(TH)))
    assert "must be a matrix" in text(check_matrix([[1, 2], [3]], sp.eye(2)))


# --- check_matrix: each typical mistake, its message -----------------------------------------------
def test_wrong_sign_of_one_entry_is_located():
    M = Rz(TH)
    M[0, 1] = sp.sin(TH)
    fb = check_matrix(M, Rz(TH), name="R")
    assert not fb.ok
    assert "row 1, column 2 ([0, 1]), rotation block: you have sin(theta): the sign is wrong." in text(fb)
    assert "det R = cos(2*theta)" in text(fb)           # and it is not a rotation any more


def test_transposed_rotation_and_inverse():
    assert "the transpose of the right one" in text(check_matrix(Rz(-TH), Rz(TH)))
    assert "the transpose of the right one" in text(check_matrix(Rz(TH)[:3, :3].T, Rz(TH)[:3, :3]))
    T = Rz(TH) * sp.Matrix(trans(1, 2, 0))
    assert "the inverse of the right matrix" in text(check_matrix(sp.simplify(T.inv()), T))
    assert "rows as columns" in text(check_matrix(sp.Matrix([[1, 2], [3, 4]]).T, sp.Matrix([[1, 2], [3, 4]])))


def test_cos_sin_swap_and_wrong_symbol():
    th0, l1, l2 = sp.symbols("theta0 l1 l2")
    expected = sp.Matrix([[l1 * sp.cos(th0) + l2]])
    assert "cos and sin are swapped" in text(check_matrix(sp.Matrix([[l1 * sp.sin(th0) + l2]]), expected))
    fb = check_matrix(sp.Matrix([[l1 * sp.cos(th0) + l1]]), expected)
    assert "l1 is the wrong symbol in the term l1: it should be l2." in text(fb)


def test_degrees_inside_sympy_trig():
    M = sp.Matrix([[sp.cos(90), -sp.sin(90)], [sp.sin(90), sp.cos(90)]])
    fb = check_matrix(M, Rz(TH)[:2, :2])
    assert "cos(90) takes radians" in text(fb) and "sp.pi*90/180" in text(fb)


def test_symbolic_versus_numeric_and_foreign_symbols():
    assert "has only numbers, but the answer is symbolic" in text(check_matrix(Rz(0.5), Rz(TH)))
    assert "still has the symbols theta" in text(check_matrix(Rz(TH), Rz(0.5)))
    fb = check_matrix(Rz(sp.Symbol("phi")), Rz(TH), name="R")
    assert "R uses phi, which is not a symbol of this exercise: use theta." in text(fb)
    l1 = sp.Symbol("l1")
    fb = check_matrix(Rz(TH) * trans(0, 0.7, 0), Rz(TH) * trans(0, l1, 0), name="H")
    assert "H does not use l1, but the right matrix does: keep the parameters as symbols" in text(fb)
    fb = check_matrix(Rz(TH), Rz(TH) * trans(0, l1, 0), name="H")
    assert "H does not use l1, but the right matrix does." in text(fb)
    assert "translation column (y): you have 0" in text(fb)


def test_shapes_last_row_and_translation_sign():
    T = Rz(math.radians(30)) @ trans(1, 2, 3)
    assert "is 3×3, but a homogeneous transformation matrix is 4×4" in text(check_matrix(T[:3, :3], T))
    assert "must be 2×2" in text(check_matrix(np.eye(3), np.eye(2)))
    bad_row = T.copy()
    bad_row[3] = [0, 0, 1, 1]
    assert "the last row must be 0 0 0 1; yours is 0 0 1 1." in text(check_matrix(bad_row, T))
    neg = T.copy()
    neg[:3, 3] *= -1
    assert "the whole translation column has the wrong sign." in text(check_matrix(neg, T))


def test_not_a_rotation_numeric_says_det():
    bad = seed001_DefinirTHz(0.0, (0, 0, 0))            # the seed-001 listing at θ = 0: a mirror
    fb = check_matrix(bad, np.eye(4))
    assert "det R = -1" in text(fb) and "mirror" in text(fb)


def test_known_mistake_message_comes_first_and_index_styles():
    right = Rz(math.radians(30)) @ trans(2, 0, 0)
    wrong = trans(2, 0, 0) @ Rz(math.radians(30))
    fb = check_matrix(wrong, right, mistakes=[(wrong, "fixed-frame order")])
    assert fb.items == ["fixed-frame order"]
    off = right.copy()
    off[0, 3] = 5
    assert "(aij[0][3])" in text(check_matrix(off, right, index_style="cpp"))
    assert "([0, 3])" not in text(check_matrix(off, right, index_style="math"))


def test_many_wrong_entries_are_summarised():
    fb = check_matrix(np.arange(16.0).reshape(4, 4) + 7, np.eye(4))
    assert "more entries are not right" in text(fb)


# --- check_value -----------------------------------------------------------------------------------
def test_value_right_rounded_and_symbolic():
    assert check_value(0.5236, math.pi / 6, unit="rad").ok
    assert check_value(deg2rad(30), math.pi / 6, unit="rad").ok
    assert check_value(sp.pi / 6, math.pi / 6).ok
    l, d = sp.symbols("l d")
    assert check_value([l + d, 0], [d + l, 0]).ok
    assert "cos and sin are swapped" in text(check_value([sp.sin(TH)], [sp.cos(TH)], components=["x"]))


def test_value_mistakes():
    fb = check_value(30, math.pi / 6, name="θ", unit="rad")
    assert "which is the angle in degrees: the API takes radians. Write deg2rad(30)" in text(fb)
    fb = check_value(math.pi / 6, 30, name="θ", unit="°")
    assert "which is the angle in radians: here it is asked in degrees." in text(fb)
    assert "the sign is wrong" in text(check_value(-0.5, 0.5))
    assert "every component has the wrong sign" in text(check_value([-1, -2], [1, 2]))
    assert "in the wrong order: the order is (x, y)" in text(check_value([2, 1], [1, 2], components="xy"))
    assert "close, but not right to the 2 decimals you typed" in text(check_value(0.86, math.sqrt(3) / 2))
    assert "must be 3 numbers; you gave 2" in text(check_value([1, 2], [1, 2, 3]))
    assert "within one turn" in text(check_value(0.5 + 2 * math.pi, 0.5, unit="rad"))
    assert "you gave 1, which is not right." in text(check_value([1, 0.3], [0, 0.3]))   # not "it is 0"
    assert check_value(..., 1).status == "unanswered"
    fb = check_value([1, 1], [1, 2], mistakes=[([1, 1], "known")])
    assert fb.items == ["known"]


# --- check_solutions -------------------------------------------------------------------------------
def test_solutions_any_order_modulo_a_turn():
    expected = [[0.4, 0.6435], [1.2, 2.4981]]
    opts = dict(components=("q1", "q2"), unit=("", "rad"))
    assert check_solutions(expected[::-1], expected, **opts).ok
    assert check_solutions([[0.4, 0.6435], [1.2, 2.4981 - 2 * math.pi]], expected, **opts).ok
    fb = check_solutions([[0.4, 0.6435]], expected, **opts)
    assert "there are 2 solutions; you gave 1." in text(fb) and "missing: 1 more solution" in text(fb)
    assert "2.498" not in text(fb)                         # the missing solution is not given away
    fb = check_solutions([[0.4, 0.6435], [0.4, 0.6435]], expected, **opts)
    assert "is given twice" in text(fb)
    fb = check_solutions([[0.4, 0.6435], [1.25, 2.4981]], expected, **opts)
    assert "(q1, q2) = (1.25, 2.4981 rad) is not a solution: q1: you gave 1.25, which is not right." in text(fb)
    fb = check_solutions([[0.4, 0.6435], [0.4, 2.4981]], expected, mistakes=[([0.4, 2.4981], "q1B!")], **opts)
    assert "q1B!" in fb.items
    assert "must be a list of solutions" in text(check_solutions(5, expected, **opts))


# --- words ---------------------------------------------------------------------------------------------
def test_choice_and_terms():
    assert check_choice("  The End-Effector ", "end effector").ok
    assert check_choice(2, 2).ok and not check_choice(3, 2).ok
    assert check_choice("Red", "blue", explanations={"red": "red is x"}).items == ["red is x"]
    fb = check_terms({"eslabon": "joint", "articulación": "joint"}, {"eslabón": "link", "articulación": "joint"})
    assert "eslabón: you wrote 'joint', which is the English for articulación." in text(fb)
    assert check_terms({"a": ..., "b": ...}, {"a": "x", "b": "y"}).status == "unanswered"
    assert "1 term is still empty" in text(check_terms({"a": "x", "b": ...}, {"a": "x", "b": "y"}))


# --- functions -------------------------------------------------------------------------------------------
def test_function_errors_and_best_failing_case():
    cases = [(0.0,), (0.5,)]
    assert check_function(lambda t: Rz(t), lambda t: Rz(t), cases).ok
    fb = check_function(lambda t: 1 / 0, lambda t: Rz(t), cases, describe=lambda a: f"t = {a[0]}")
    assert "calling it with t = 0.0 raised ZeroDivisionError" in text(fb)
    fb = check_function(lambda t: Rz(-t), lambda t: Rz(t), cases, describe=lambda a: f"t = {a[0]}")
    assert "for t = 0.5:" in text(fb)              # at t = 0 the slip is invisible
    assert "not a function" not in text(fb)
    assert "must be a function" in text(check_function(3, lambda t: Rz(t), cases))


# --- Exercise and hints ------------------------------------------------------------------------------------
def test_exercise_hints_in_turn():
    ex = Exercise("9.9", "demo", lambda a: check_value(a, 1), hints=["first", "second"])
    assert ex.check(2).tip == "Stuck? Call .hint() on this exercise (2 hints)."
    assert ex.check(1).tip == "" and str(ex.check(1)).startswith("✓ Exercise 9.9: correct")
    assert ex.hint().items == ["first"] and ex.hint().items == ["second"] and ex.hint().items == ["second"]
    assert ex.hint(1).items == ["first"]
    with pytest.raises(ValueError):
        ex.hint(3)
    assert "has no hints" in text(Exercise("9.8", "x", lambda a: check_value(a, 1)).hint())
    with pytest.raises(KeyError):
        exercise("0.0")


# --- the course's exercises: right answers (computed independently) pass, mistakes named ---------------
TH0, TH1, L1, L2 = sp.symbols("θ0 θ1 l1 l2")


def right_answers(cases):
    robot1 = dhlab.robots.robot_no_tan_elemental_1()
    pr = dhlab.robots.pr_mechanism()
    extra = cases["004_robot1_extra"]

    def fixed_DefinirTHz(dtheta, d):
        M = seed001_DefinirTHz(dtheta, d)
        M[0][0] = math.cos(dtheta)
        M[:3, 3] = d
        return M

    return {
        "1.1": deg2rad([45, -90]),
        "1.2": {"eslabón": "link", "articulación": "joint", "efector final": "end effector",
                "dextrógiro": "right-handed", "grados de libertad": "degrees of freedom"},
        "1.3": "blue",
        "2.1": sp.Matrix([[sp.cos(TH), -sp.sin(TH), 0, 0], [sp.sin(TH), sp.cos(TH), 0, 0],
                          [0, 0, 1, 0], [0, 0, 0, 1]]),
        "2.2": dhlab.Tz(deg2rad(30), 0) @ dhlab.Tx(0, 2),
        "2.3": np.linalg.inv(trans(1, 2, 0) @ Rz(math.pi / 2)),
        "2.4": fixed_DefinirTHz,
        "3.1": robot1.A(1),
        "3.2": dhlab.Robot([dhlab.Link([dhlab.Rot("z", joint=True), dhlab.Move("x", L1)]),
                            dhlab.Link([dhlab.Rot("z", joint=True), dhlab.Move("x", L2)])],
                           params={"l1": 0.7, "l2": 0.3}, joint_symbols=("theta0", "theta1")).fk_sym(),
        "3.3": extra["expected_position"],
        "3.4": [deg2rad(45), 0.6 * math.sqrt(2) - 0.70],
        "4.1": pr.fk([0.5, deg2rad(60)])[:2, 3],
        "4.2": list(dhlab.ik.pr_mechanism_ik(pr, 1.8, 0.3)),
        "4.3": [len(dhlab.ik.pr_mechanism_ik(pr, x, y)) for x, y in ((1.5, -0.5), (1.5, 0.7), (2.5, 0.1))],
        "4.4": dhlab.robots.rrr_example().fk(deg2rad([90, 30, 60]))[:3, 3],
        "3.5": dhlab.robots.robot_no_tan_elemental_2().fk([-math.pi / 2, 0.30])[:3, 3],
        "2.5": (dhlab.Rz(deg2rad(90)) @ dhlab.trans(1, 0, 0))[:3, 3],
        "4.5": "branch " + "AB"[int(pr.qlim[0][0] <= dhlab.ik.pr_mechanism_ik(pr, 1.2, 0.25)[1][0] <= pr.qlim[0][1])],
    }


def test_every_course_exercise_accepts_its_right_answer_and_waits_for_one(cases):
    answers = right_answers(cases)
    assert sorted(answers) == [key for key in available() if int(key.split(".")[0]) <= 4]
    for key, answer in answers.items():
        ex = exercise(key)
        assert ex.check(answer).ok, (key, str(ex.check(answer)))
        assert ex.check(...).status == "unanswered", key
        assert ex.hints, key


def eq3_H1():
    c, s = sp.cos(TH0), sp.sin(TH0)
    return sp.Matrix([[c, -s, 0, -L1 * c], [s, c, 0, L1 * s], [0, 0, 1, 0], [0, 0, 0, 1]])


def robot1_xy(t0, t1, l1=0.7, l2=0.3):
    return [l2 * math.cos(t0 + t1) - l1 * math.sin(t0), l2 * math.sin(t0 + t1) + l1 * math.cos(t0), 0]


def only_cos_fixed(dtheta, d):
    M = seed001_DefinirTHz(dtheta, d)
    M[0][0] = math.cos(dtheta)
    return M


def only_d_fixed(dtheta, d):
    M = seed001_DefinirTHz(dtheta, d)
    M[:3, 3] = d
    return M


MISTAKES = [
    ("1.1", [45, -90], "θ1: you gave -90, which is the angle in degrees"),
    ("1.1", deg2rad([-90, 45]), "in the wrong order"),
    ("1.3", "green", "green is the y axis."),
    ("2.1", Rz(-TH), "the transpose of the right one"),
    ("2.1", Rx(TH), "that is the rotation about x"),
    ("2.2", trans(2, 0, 0) @ Rz(math.radians(30)), "fixed-frame order"),
    ("2.2", [[math.cos(30), -math.sin(30), 0, 2 * math.cos(30)], [math.sin(30), math.cos(30), 0, 2 * math.sin(30)],
             [0, 0, 1, 0], [0, 0, 0, 1]], "computed with 30 radians"),
    ("2.3", np.block([[Rz(math.pi / 2)[:3, :3].T, np.array([[1], [2], [0]])], [np.array([[0, 0, 0, 1]])]]),
     "the translation of the inverse is −Rᵀ·p, not p."),
    ("2.4", seed001_DefinirTHz, "still seed 001's listing, unchanged: it has two bugs"),
    ("2.5", [1, 0, 0], "the move along the FIXED x0 axis"),
    ("2.5", [0, -1, 0], "counter-clockwise"),
    ("2.4", only_cos_fixed, "erratum 001-2"),
    ("2.4", only_d_fixed, "erratum 001-1"),
    ("3.1", eq3_H1(), "erratum 004-1"),
    ("3.1", trans(0, L1, 0) * Rz(TH0), "the link does not turn with the joint"),
    ("3.2", (Rz(TH1) * trans(L2, 0, 0)) * (Rz(TH0) * trans(L1, 0, 0)), "the product in the wrong order"),
    ("3.2", Rz(TH0) * trans(0, L1, 0) * Rz(TH1) * trans(L2, 0, 0), "seed 004's robot, whose link 1 lies along y0"),
    ("3.2", sp.Matrix([[sp.cos(TH0 + TH1), -sp.sin(TH0 + TH1), 0, L1 * sp.cos(TH0) + L2 * sp.cos(TH1)],
                       [sp.sin(TH0 + TH1), sp.cos(TH0 + TH1), 0, L1 * sp.sin(TH0) + L2 * sp.sin(TH1)],
                       [0, 0, 1, 0], [0, 0, 0, 1]]), "link 2 points at θ0 + θ1"),
    ("3.3", robot1_xy(30, 45), "θ0 = 30 rad"),
    ("3.3", robot1_xy(math.radians(45), math.radians(30)), "you swapped θ0 and θ1"),
    ("3.4", [math.radians(45), 0.6 * math.sqrt(2)], "the fixed link l = 0.70 is not part of the joint value d"),
    ("3.4", [-math.radians(45), 0.6 * math.sqrt(2) - 0.7], "x < 0 needs θ > 0"),
    ("4.1", [1.5 + 0.5 * math.cos(60), 0.5 * math.sin(60)], "q2 = 60 rad"),
    ("4.1", [0.75, 0.5 * math.sin(math.radians(60))], "x is missing l1 = 1"),
    ("4.2", [[0.4, math.asin(0.6)], [0.4, math.pi - math.asin(0.6)]], "erratum 003-1"),
    ("4.2", [[0.4, math.degrees(math.asin(0.6))], [1.2, 180 - math.degrees(math.asin(0.6))]], "in degrees"),
    ("4.2", [[0.4, math.asin(0.6)]], "missing: 1 more solution"),
    ("4.3", [2, 0, 2], "(1.5, −0.5): you gave 2"),
    ("4.4", [1 + 2 * math.sin(30) + 1.5 * math.sin(90), 0, 0], "90, 30, 60 radians"),
    ("4.5", "A", "is it still ≥ 0?"),
    ("4.5", "both", "one of them is below the slider's range"),
]


@pytest.mark.parametrize("key, answer, message", MISTAKES, ids=[f"{m[0]}-{i}" for i, m in enumerate(MISTAKES)])
def test_each_typical_mistake_gets_its_message(key, answer, message):
    if key == "4.4":                                   # the formulas evaluated at 90, 30, 60 radians
        q1, q2, q3 = 90, 30, 60
        r = 2 * math.cos(q2) + 1.5 * math.cos(q2 + q3)
        answer = [1 + 2 * math.sin(q2) + 1.5 * math.sin(q2 + q3), r * math.cos(q1), r * math.sin(q1)]
    feedback = exercise(key).check(answer)
    assert feedback.status == "wrong"
    assert message in str(feedback), str(feedback)


def test_definirthz_transcription_is_seed_001(cases):
    """The listing given to fix in notebook 2 really is seed 001's (its output and det R)."""
    for deg_value in (0, 30, 45):
        case = cases[f"001_DefinirTHz_{deg_value}"]
        got = seed001_DefinirTHz(case["joint_values"]["dtheta"], case["parameters"]["d"])
        np.testing.assert_allclose(got, case["listing_001_output"], atol=1e-12)
        assert np.linalg.det(got[:3, :3]) == pytest.approx(case["listing_001_det_R"], abs=1e-12)
        # and the reference the check compares with is the correct pose (seed 000's listing)
        np.testing.assert_allclose(seed000_DefinirTHz(case["joint_values"]["dtheta"], case["parameters"]["d"]),
                                   case["expected_pose"], atol=1e-12)
