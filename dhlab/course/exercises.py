"""The exercises of notebooks 1-4, with their right answers and the feedback for each typical mistake.

The checks themselves live in small modules, re-exported here so that one import serves a notebook:

* :mod:`~dhlab.course.feedback`: :class:`Feedback` (what a check returns) and :class:`Exercise`;
* :mod:`~dhlab.course.answers`: reading a student's answer (or refusing it with a reason);
* :mod:`~dhlab.course.matrix_checks`: :func:`check_matrix` (a matrix, symbolic or numeric) and
  :func:`check_function` (a function the student wrote, called on test inputs);
* :mod:`~dhlab.course.value_checks`: :func:`check_value` (a number or a vector) and
  :func:`check_solutions` (several solutions in any order);
* :mod:`~dhlab.course.word_checks`: :func:`check_choice` and :func:`check_terms` (words, a glossary).

A check says *what* is wrong and *where*: which entry of a matrix, which component of a vector, a
sign, a transposed rotation, degrees where radians are expected, or a known slip of the seeds (an
erratum). Any equivalent form of a right answer passes, and an answer right to the decimals the
student typed is accepted (rounding is never blamed). A check never raises on a student's answer.

>>> import sympy as sp
>>> th = sp.Symbol("theta")
>>> R = sp.Matrix([[sp.cos(th), -sp.sin(th)], [sp.sin(th), sp.cos(th)]])
>>> check_matrix(R, R, name="R")
✓ correct: R is right.
>>> check_matrix(R.T, R, name="R")
✗ R is not right yet.
  • your rotation block is the transpose of the right one: that is the rotation the other way (by −θ instead of θ).

The course's exercises are made by :func:`exercise`:

>>> ex = exercise("1.1")
>>> ex.check([45, -90])
✗ Exercise 1.1: your q is not right yet.
  • θ0: you gave 45, which is the angle in degrees: the API takes radians. Write deg2rad(45) (or 45·π/180).
  • θ1: you gave -90, which is the angle in degrees: the API takes radians. Write deg2rad(-90) (or -90·π/180).
  Stuck? Call .hint() on this exercise (2 hints).
>>> ex.check(deg2rad([45, -90]))
✓ Exercise 1.1: correct: your q is right.
"""
from __future__ import annotations

import math

import numpy as np
import sympy as sp

from ..transforms import Rx, Ry, Rz, inv, trans
from ..i18n import N_, _
from ..units import deg2rad
from ..validation import DHLabError, as_angle, as_vector, check_length_size
from .feedback import NOT_ANSWERED, Exercise, Feedback
from .matrix_checks import TRANSPOSED_ROTATION, check_function, check_matrix
from .value_checks import check_solutions, check_value
from .word_checks import check_choice, check_terms

__all__ = ["Feedback", "Exercise", "NOT_ANSWERED", "TRANSPOSED_ROTATION", "check_matrix", "check_value",
           "check_solutions", "check_choice", "check_terms", "check_function", "exercise", "available",
           "seed001_DefinirTHz"]


# ======================================================================================================
# The exercises of notebooks 1-4. The right answers live here, not in the notebooks.
# ======================================================================================================
TH, THETA0, THETA1, L1, L2 = sp.symbols("theta theta0 theta1 l1 l2")


def _ex_1_1():
    return Exercise("1.1", N_("a joint vector for the API"), lambda a: check_value(
        a, [math.radians(45), math.radians(-90)], name=N_("your q"), components=("θ0", "θ1"), unit="rad"),
        [N_("The sliders show degrees; robot.fk takes radians: dhlab.deg2rad converts (it also takes a list)."),
         N_("q lists the joints from the base: [θ0, θ1].")])


def _ex_1_2():
    return Exercise("1.2", "glossary", lambda a: check_terms(a, {
        "eslabón": "link", "articulación": "joint", "efector final": ("end effector", "end-effector"),
        "dextrógiro": ("right-handed", "right handed"), "grados de libertad": ("degrees of freedom", "dof"),
    }, name=N_("the glossary")), [N_("The glossary table above has every term.")])


def _ex_1_3():
    return Exercise("1.3", N_("colour of z"), lambda a: check_choice(
        a, "blue", name=N_("the colour of the z axis"), accepted=("azul",),
        explanations={"red": N_("red is the x axis."), "green": N_("green is the y axis."),
                      "rojo": N_("rojo (red) is the x axis."), "verde": N_("verde (green) is the y axis.")}),
        [N_("x, y, z are drawn in the order of the colours of RGB.")])


def _ex_2_1():
    right = Rz(TH)
    return Exercise("2.1", N_("Rz(θ) by hand"), lambda a: check_matrix(a, right, name=N_("your Rz(θ)"), mistakes=[
        (Rx(TH), N_("that is the rotation about x (it leaves x fixed): Rz leaves z fixed, so its third row "
                    "and column are those of the identity.")),
        (Ry(TH), N_("that is the rotation about y (it leaves y fixed): Rz leaves z fixed."))]),
        [N_("A rotation about z leaves z fixed: the third row and column are 0 0 1 (and the 4th those of the identity)."),
         N_("Its first column is where x goes: (cos θ, sin θ, 0). The second is where y goes: 90° further on.")])


def _ex_2_2():
    right = Rz(math.radians(30)) @ trans(2, 0, 0)
    by_hand_in_degrees = np.array([[math.cos(30), -math.sin(30), 0, 2 * math.cos(30)],
                                   [math.sin(30), math.cos(30), 0, 2 * math.sin(30)],
                                   [0, 0, 1, 0], [0, 0, 0, 1]])
    return Exercise("2.2", N_("compose in the moving frame"), lambda a: check_matrix(
        a, right, name=N_("your ⁰T₁"), mistakes=[
            (trans(2, 0, 0) @ Rz(math.radians(30)),
             N_("that is Tr(2,0,0)·Rz(30°): the move along the FIXED x0 axis (pre-multiplied, fixed-frame order). "
                "Moving along the new x axis means post-multiplying: Rz(30°)·Tr(2,0,0).")),
            (by_hand_in_degrees, N_("cos(30) and sin(30) were computed with 30 radians: "
                                    "use the angle in radians, deg2rad(30) = π/6.")),
            (Rz(math.radians(30)), N_("that is only the rotation: the move of 2 along the new x is missing."))]),
        [N_("Moving frame: multiply on the right, in the order the motions happen."),
         N_("Rz(deg2rad(30)) @ trans(2, 0, 0): the new origin is 2·(cos 30°, sin 30°, 0).")])


def _ex_2_3():
    T = trans(1, 2, 0) @ Rz(math.pi / 2)
    R, p = T[:3, :3], T[:3, 3]
    keep_p = np.eye(4)
    keep_p[:3, :3], keep_p[:3, 3] = R.T, p
    minus_p = keep_p.copy()
    minus_p[:3, 3] = -p
    return Exercise("2.3", N_("the inverse"), lambda a: check_matrix(a, inv(T), name=N_("your T⁻¹"), mistakes=[
        (keep_p, N_("the rotation block (Rᵀ) is right, but the translation of the inverse is −Rᵀ·p, not p.")),
        (minus_p, N_("the rotation block (Rᵀ) is right, but the translation of the inverse is −Rᵀ·p: "
                     "−p alone forgets to turn it into the other frame.")),
        (T, N_("that is T itself: the inverse undoes it, T⁻¹·T = I."))]),
        [N_("T⁻¹ = [[Rᵀ, −Rᵀ·p], [0 0 0 1]]."), N_("Check yours: T⁻¹ @ T must be the identity.")])


def _ex_2_5():
    right = (Rz(math.pi / 2) @ trans(1, 0, 0))[:3, 3]
    return Exercise("2.5", N_("predict: turn 90° about z, then move 1 along the new x"), lambda a: check_value(
        a, right, name=N_("your predicted origin of {S1}"), components=("x", "y", "z"), mistakes=[
            ((trans(1, 0, 0) @ Rz(math.pi / 2))[:3, 3],
             N_("that is the move along the FIXED x0 axis. In the moving frame the move follows the frame's own "
                "x axis, which the turn has already carried somewhere else: where does x point after the turn?")),
            ([0, -1, 0], N_("the turn is +90°, counter-clockwise seen from +z: x goes to where y was, not to −y."))]),
        [N_("After a turn of +90° about z, the frame's x axis points where y0 points."),
         N_("Then move 1 along that new x axis.")])


def seed001_DefinirTHz(dtheta, d):
    """Seed 001's ``DefinirTHz`` listing, transcribed line by line into Python, bugs included.

    ``dtheta`` in radians (the C++ ``AplicarTHz`` converts degrees first), ``d`` = (x, y, z).
    """
    dtheta, d = as_angle(dtheta, "dtheta (radians)"), as_vector(d, "d = (x, y, z)", 3)
    for k, v in enumerate(d):
        check_length_size(abs(v), f"d[{k}]")
    THz = np.zeros((4, 4))
    THz[0][0] = -math.cos(dtheta)
    THz[0][1] = -math.sin(dtheta)
    THz[0][2] = 0
    THz[0][3] = -d[0]
    THz[1][0] = math.sin(dtheta)
    THz[1][1] = math.cos(dtheta)
    THz[1][2] = 0
    THz[1][3] = -d[1]
    THz[2][0] = 0
    THz[2][1] = 0
    THz[2][2] = 1
    THz[2][3] = -d[2]
    THz[3][0] = 0
    THz[3][1] = 0
    THz[3][2] = 0
    THz[3][3] = 1
    return THz


def _seed000_DefinirTHz(dtheta, d):
    """The right listing (seed 000, the author's repository): Tr(d)·Rz(θ)."""
    return trans(*d) @ Rz(dtheta)


def _rz_then_translate(dtheta, d):
    """A plausible wrong fix of the listing: the two factors in the other order."""
    return Rz(dtheta) @ trans(*d)


def _ex_2_4():
    def only_cos_fixed(dtheta, d):
        M = seed001_DefinirTHz(dtheta, d)
        M[0][0] = math.cos(dtheta)
        return M

    def only_d_fixed(dtheta, d):
        M = seed001_DefinirTHz(dtheta, d)
        M[:3, 3] = d
        return M

    cases = [(0.0, (0.0, 0.0, 2.5)), (math.radians(30), (0.0, 0.0, 2.5)),
             (math.radians(45), (1.0, 2.0, 3.0)), (2.0, (0.5, -1.0, 0.0))]
    return Exercise("2.4", N_("spot the bug in DefinirTHz"), lambda f: check_function(
        f, _seed000_DefinirTHz, cases, name=N_("your DefinirTHz"), index_style="cpp",
        describe=lambda a: f"dtheta = {math.degrees(a[0]):g}°, d = {a[1]}",
        mistakes=[(seed001_DefinirTHz, N_("this is still seed 001's listing, unchanged: it has two bugs. "
                                          "Compare each line with Rz(θ) and with a translation by d.")),
                  (only_cos_fixed, N_("aij[0][0] is fixed, but the translation column still has −d.x, −d.y, "
                                      "−d.z: the frame moves to the wrong side (erratum 001-2).")),
                  (only_d_fixed, N_("the translation column is fixed, but aij[0][0] is still −cos(dtheta): "
                                    "det R = −cos 2θ, a mirror at θ = 0 and flat at 45° (erratum 001-1).")),
                  (_rz_then_translate, N_("your function builds Rz(θ)·Tr(d): the frame turns first, so the "
                                          "translation is turned too (its column is Rz(θ)·d, not d). Both agree "
                                          "only when d lies along z. DefinirTHz moves by d, then turns: Tr(d)·Rz(θ)."))]),
        [N_("Compare each line with the matrix Rz(θ) of this notebook: one entry of the rotation block differs."),
         N_("Seed 000 prints the same listing with d.x, d.y, d.z: which sign does a translation by d have?")])


def _robot1_H1_eq3():
    """⁰H₁ as printed in seed 004's eq. (3) (erratum 004-1)."""
    c, s = sp.cos(THETA0), sp.sin(THETA0)
    return sp.Matrix([[c, -s, 0, -L1 * c], [s, c, 0, L1 * s], [0, 0, 1, 0], [0, 0, 0, 1]])


def _ex_3_1():
    right = Rz(THETA0) * trans(0, L1, 0)
    mistakes = [
        (_robot1_H1_eq3(), N_("your translation column is (−l1·cos θ0, l1·sin θ0, 0): that is eq. (3) as printed, "
                              "erratum 004-1. At θ0 = 0 it puts {S1} at (−l1, 0) instead of (0, l1): link 1 lies "
                              "along y0.")),
        (trans(0, L1, 0) * Rz(THETA0), N_("your translation column is (0, l1, 0) for every θ0: that is "
                                          "Tr(0,l1,0)·Rz(θ0), the link does not turn with the joint. The joint turns "
                                          "first, then the link carries {S1} along the NEW y axis: "
                                          "Rz(θ0)·Tr(0,l1,0).")),
    ]
    return Exercise("3.1", N_("⁰H₁ of the first robot"),
                    lambda a: check_matrix(a, right, name=N_("your ⁰H₁"), mistakes=mistakes),
                    [N_("Two motions, in the moving frame: turn by θ0 about z0, then move l1 along the new y axis."),
                     N_("The translation column is Rz(θ0) applied to (0, l1, 0).")])


def _ex_3_2():
    H1, H2 = Rz(THETA0) * trans(L1, 0, 0), Rz(THETA1) * trans(L2, 0, 0)
    right = H1 * H2
    seed_robot = Rz(THETA0) * trans(0, L1, 0) * H2
    c0, s0, c1, s1 = sp.cos(THETA0), sp.sin(THETA0), sp.cos(THETA1), sp.sin(THETA1)
    link2_alone = right.copy()
    link2_alone[0, 3], link2_alone[1, 3] = L1 * c0 + L2 * c1, L1 * s0 + L2 * s1
    return Exercise("3.2", N_("⁰H₂ of the variant with link 1 along x0"), lambda a: check_matrix(
        a, right, name=N_("your ⁰H₂"), mistakes=[
            (seed_robot, N_("that is ⁰H₂ of seed 004's robot, whose link 1 lies along y0; in this variant link 1 "
                            "lies along x0: ⁰H₁ = Rz(θ0)·Tr(l1, 0, 0).")),
            (H2 * H1, N_("that is ¹H₂·⁰H₁, the product in the wrong order: ⁰H₂ = ⁰H₁·¹H₂ (the upper and lower "
                         "indices chain: 0→1, then 1→2).")),
            (link2_alone, N_("the rotation block is right, but link 2 points at θ0 + θ1 from x0, not θ1: its "
                             "terms are l2·cos(θ0+θ1) and l2·sin(θ0+θ1) (angles add along a planar chain)."))]),
        [N_("⁰H₁ = Rz(θ0)·Tr(l1, 0, 0) and ¹H₂ = Rz(θ1)·Tr(l2, 0, 0); multiply them in this order."),
         N_("At θ0 = θ1 = 0 the pen must be at (l1 + l2, 0, 0); the rotation block is Rz(θ0 + θ1).")])


def _robot1_position(t0, t1, l1=0.70, l2=0.30):
    return np.array([l2 * math.cos(t0 + t1) - l1 * math.sin(t0), l2 * math.sin(t0 + t1) + l1 * math.cos(t0), 0.0])


def _variant_position(t0, t1, l1=0.70, l2=0.30):
    """The pen if link 1 lay along x0 at rest (the variant of exercise 3.2)."""
    return np.array([l1 * math.cos(t0) + l2 * math.cos(t0 + t1), l1 * math.sin(t0) + l2 * math.sin(t0 + t1), 0.0])


def _ex_3_3():
    t0, t1 = math.radians(30), math.radians(45)
    eq3 = np.array(_robot1_H1_eq3().subs({THETA0: t0, L1: 0.70}).evalf(), dtype=float) @ (
        Rz(t1) @ trans(0.30, 0, 0))
    return Exercise("3.3", N_("the pen at θ0 = 30°, θ1 = 45°"), lambda a: check_value(
        a, _robot1_position(t0, t1), name=N_("your pen position"), components=("x", "y", "z"), unit="m",
        mistakes=[(_robot1_position(30, 45), N_("those are the values for θ0 = 30 rad and θ1 = 45 rad: "
                                               "convert the angles, deg2rad(30) and deg2rad(45).")),
                  (_robot1_position(t1, t0), N_("you swapped θ0 and θ1: θ0 = 30° is the base joint.")),
                  (eq3[:3, 3], N_("that is the position with ⁰H₁ of eq. (3) as printed (erratum 004-1): "
                                  "use ⁰H₁ = Rz(θ0)·Tr(0, l1, 0).")),
                  (_variant_position(t0, t1),
                   N_("that is the pen of the variant with link 1 along x0 (exercise 3.2). In seed 004's robot "
                      "link 1 lies along y0 at rest: ⁰H₁ = Rz(θ0)·Tr(0, l1, 0), so l1 contributes "
                      "(−l1·sin θ0, l1·cos θ0)."))]),
        [N_("robot.fk(deg2rad([30, 45])) gives the whole pose; its last column is the position."),
         N_("By the formula: x = l2·cos(θ0+θ1) − l1·sin θ0, y = l2·sin(θ0+θ1) + l1·cos θ0.")])


def _ex_3_4():
    l, x, y = 0.70, -0.6, 0.6
    reach = math.hypot(x, y)
    right = [math.radians(45), reach - l]
    return Exercise("3.4", N_("reach (−0.6, 0.6) with the second robot"), lambda a: check_value(
        a, right, name=N_("your (θ, d)"), components=("θ", "d"), unit=("rad", "m"),
        mistakes=[([math.radians(45), reach], N_("d = 0.8485 is the whole distance l + d from the base: the "
                                                 "fixed link l = 0.70 is not part of the joint value d.")),
                  ([45, reach - l], N_("θ = 45 is in degrees: the API takes radians, deg2rad(45).")),
                  ([-math.radians(45), reach - l], N_("with θ = −45° the pen goes to (+0.6, 0.6): x = −(l+d)·sin θ, "
                                                      "so x < 0 needs θ > 0 (counter-clockwise)."))]),
        [N_("The pen is at (−(l+d)·sin θ, (l+d)·cos θ): its distance from the base is l + d."),
         N_("Distance √(0.6² + 0.6²) = l + d, and the direction gives θ.")])


def _robot2_position(theta, d, l=0.70):
    return np.array([-(l + d) * math.sin(theta), (l + d) * math.cos(theta), 0.0])


def _ex_3_5():
    d_max = 0.30
    right = _robot2_position(-math.pi / 2, d_max)
    title = N_("predict: the reader's exercise of seed 004 (θ = −π/2, d = d_max)")
    return Exercise("3.5", title, lambda a: check_value(
        a, right, name=N_("your predicted pen position"), components=("x", "y", "z"), unit="m", mistakes=[
            (_robot2_position(math.pi / 2, d_max), N_("that is θ = +π/2, counter-clockwise: a negative angle turns "
                                                      "clockwise, so the arm leaves +y0 the other way.")),
            (_robot2_position(-math.pi / 2, 0.0), N_("that is d = 0: at d = d_max the prismatic joint is fully "
                                                     "extended, the pen is l + d_max from the base.")),
            (_robot2_position(-math.pi / 2, 0.0, l=d_max), N_("that is d_max alone: the fixed link l = 0.70 is still "
                                                              "there, the pen is l + d from the base.")),
            (_robot2_position(-90.0, d_max), N_("that is θ = −90 rad: the angle is −π/2 rad = −90°.")),
            (_robot2_position(0.0, d_max), N_("that is θ = 0: the arm still points along +y0; turn it by −π/2."))]),
        [N_("At θ = 0 the arm points along +y0, and the pen is at distance l + d from the base."),
         N_("A negative θ turns clockwise (seen from +z): by −90° the +y0 direction goes to +x0.")])


def _pr_fk(q1, q2, l1=1.0, l2=0.5):
    return np.array([q1 + l1 + l2 * math.cos(q2), l2 * math.sin(q2)])


def _ex_4_1():
    q1, q2 = 0.5, math.radians(60)
    return Exercise("4.1", N_("forward kinematics of the P-R mechanism"), lambda a: check_value(
        a, _pr_fk(q1, q2), name=N_("your (x, y)"), components=("x", "y"), mistakes=[
            (_pr_fk(q1, 60), N_("that is q2 = 60 rad: the angle must be in radians, deg2rad(60).")),
            (_pr_fk(q1, q2) - [1.0, 0], N_("x is missing l1 = 1: the arm's joint sits at q1 + l1 along x.")),
            ([q1 + 1.0 + 0.5 * math.sin(q2), 0.5 * math.cos(q2)], N_("cos and sin are swapped: q2 is measured "
                                                                       "from the x axis, so x gets l2·cos q2.")),
            ([_pr_fk(q1, q2)[0], 0.5 * math.sin(math.radians(30))],
             N_("x is right; for y you used sin 30° (the angle from the y axis, or cos 60° by mistake): "
                "y = l2·sin q2 with q2 measured from the x axis, q2 = 60°.")),
            (_pr_fk(q1, math.radians(30)), N_("that is q2 = 30°: the arm is at q2 = 60° from the x axis."))]),
        [N_("x = q1 + l1 + l2·cos q2, y = l2·sin q2, with l1 = 1, l2 = 0.5.")])


def _ex_4_2():
    x, y, l1, l2 = 1.8, 0.3, 1.0, 0.5
    root = l2 * math.sqrt(1 - (y / l2) ** 2)
    q2a = math.asin(y / l2)
    right = [[x - l1 - root, q2a], [x - l1 + root, math.pi - q2a]]
    return Exercise("4.2", N_("both inverse-kinematics solutions"), lambda a: check_solutions(
        a, right, name=N_("your list of solutions"), components=("q1", "q2"), unit=("", "rad"), mistakes=[
            ([x - l1 - root, math.pi - q2a], N_("(q1A, q2B) is not a solution: q2B needs its own slider value "
                                                "q1B = x − l1 + l2·√(1 − (y/l2)²). The slide gives only q1A "
                                                "(erratum 003-1).")),
            ([x - l1 - root, math.degrees(q2a)], N_("q2 = 36.87 is in degrees: give radians.")),
            ([x - l1 + root, math.degrees(math.pi - q2a)], N_("q2 = 143.13 is in degrees: give radians."))]),
        [N_("q2A = arcsin(y/l2) and q2B = π − arcsin(y/l2)."),
         N_("Then q1 = x − l1 − l2·cos q2 for each branch: cos q2B = −cos q2A.")])


TARGETS_4_3 = ((1.5, -0.5), (1.5, 0.7), (2.5, 0.1))


def _count_reason(y, l2=0.5) -> str:
    """Why a target of the P-R mechanism has the solutions it has, without saying how many."""
    if abs(abs(y) - l2) < 1e-12:
        return _("here |y| = l2 = {l2:g}: sin q2 = y/l2 = {sine:+g}. How many angles have that sine? q2A = "
                 "arcsin(y/l2) and q2B = π − q2A are then the same angle, so the two branches meet.").format(
                     l2=l2, sine=y / l2)
    if abs(y) > l2:
        return _("here |y| = {y:g} > l2 = {l2:g}: sin q2 = y/l2 = {sine:g}. Is there an angle with that sine? The "
                 "arm cannot reach that far from the x axis.").format(y=abs(y), l2=l2, sine=y / l2)
    return _("here |y| = {y:g} < l2 = {l2:g}: sin q2 = y/l2 = {sine:g}, and within a turn two angles have that "
             "sine (q2A and π − q2A), each with its own q1.").format(y=abs(y), l2=l2, sine=y / l2)


def _check_4_3(answer):
    right = [1, 0, 2]
    names = [f"({x:g}, {'−' if y < 0 else ''}{abs(y):g})" for x, y in TARGETS_4_3]
    feedback = check_value(answer, right, name=N_("your list of counts"), components=names, tol=1e-9)
    if feedback.status == "wrong":
        values = answer if isinstance(answer, (list, tuple, np.ndarray)) else []
        explained = []
        for item in feedback.items:
            k = next((k for k, n in enumerate(names) if item.startswith(n + ":")), None)
            explained.append(item if k is None else f"{item.rstrip('.')}: {_count_reason(TARGETS_4_3[k][1])}")
        if len(values) == 3 and any(isinstance(v, float) and not float(v).is_integer() for v in values):
            explained.append(_("a count of solutions is a whole number: 0, 1, 2, …"))
        feedback.items = explained
    return feedback


def _ex_4_3():
    return Exercise("4.3", N_("how many solutions"), _check_4_3,
                    [N_("sin q2 = y/l2 must hold: compare |y| with l2 = 0.5 for each target."),
                     N_("|y| < l2: two angles have that sine; |y| = l2: the two branches meet in one; "
                        "|y| > l2: no angle (outside the workspace).")])


def _ex_4_5():
    why_not_a = N_("branch A has the smaller slider value, q1A = x − l1 − l2·√(1 − (y/l2)²): for a target "
                   "this close to the base, is it still ≥ 0?")
    return Exercise("4.5", N_("predict: which branch survives the slider's range"), lambda a: check_choice(
        a, "B", name=N_("your predicted branch"), accepted=("branch B", "the B branch", "rama B", "la rama B"),
        explanations={"A": why_not_a, "branch A": why_not_a, "rama A": why_not_a, "la rama A": why_not_a,
                      **dict.fromkeys(("both", "ambas", "las dos"), N_("compute q1 for each branch: one of them "
                                                                       "is below the slider's range 0 ≤ q1 ≤ 2.")),
                      **dict.fromkeys(("none", "ninguna"), N_("compute q1 for each branch: one of them is within "
                                                             "the slider's range 0 ≤ q1 ≤ 2."))}),
        [N_("q1B − q1A = 2·l2·√(1 − (y/l2)²) ≥ 0: branch A always has the smaller q1."),
         N_("Compute q1A = x − l1 − l2·√(1 − (y/l2)²) for (x, y) = (1.2, 0.25).")])


def _rrr_position(q1, q2, q3, l1=1.0, l2=2.0, l3=1.5):
    r = l2 * math.cos(q2) + l3 * math.cos(q2 + q3)
    return np.array([l1 + l2 * math.sin(q2) + l3 * math.sin(q2 + q3), r * math.cos(q1), r * math.sin(q1)])


def _ex_4_4():
    q = [math.radians(v) for v in (90, 30, 60)]
    return Exercise("4.4", N_("the 3R example by the geometric method"), lambda a: check_value(
        a, _rrr_position(*q), name=N_("your (x, y, z)"), components=("x", "y", "z"), mistakes=[
            (_rrr_position(90, 30, 60), N_("those are the formulas at 90, 30, 60 radians: convert, deg2rad(...).")),
            (_rrr_position(q[0], q[1], q[1] + q[2]), N_("q3 is relative to link 2: the angle of link 3 is "
                                                         "q2 + q3 (use cos(q2 + q3), not cos(q2 + q2 + q3))."))]),
        [N_("r = l2·cos q2 + l3·cos(q2 + q3), then y = r·cos q1, z = r·sin q1."),
         N_("With q3 = 60° and q2 = 30°, link 3 points along x: cos 90° = 0.")])


_COURSE = {f.__name__[4:].replace("_", "."): f for f in (
    _ex_1_1, _ex_1_2, _ex_1_3, _ex_2_1, _ex_2_2, _ex_2_3, _ex_2_4, _ex_2_5,
    _ex_3_1, _ex_3_2, _ex_3_3, _ex_3_4, _ex_3_5, _ex_4_1, _ex_4_2, _ex_4_3, _ex_4_4, _ex_4_5)}


def available() -> list:
    """The keys of the course's exercises, e.g. ['1.1', '1.2', …]."""
    return list(_COURSE)


class UnknownExercise(DHLabError, KeyError):
    """``exercise(key)`` with a key the course does not have."""

    __str__ = DHLabError.__str__


def exercise(key: str) -> Exercise:
    """A fresh :class:`Exercise` of the course by its key, e.g. ``exercise("3.1")``."""
    if not isinstance(key, str) or key not in _COURSE:
        raise UnknownExercise(_("no exercise {key!r} in notebooks 1-4: the keys are {keys} (notebooks 5-7: "
                                "dhlab.course.exercises_dh.exercise).").format(key=key, keys=", ".join(_COURSE)))
    return _COURSE[key]()
