"""The exercises of notebook 4 (the P-R mechanism): its forward and inverse kinematics, how many solutions."""
from __future__ import annotations

import math

import numpy as np

from ...i18n import N_, _
from ..checks.feedback import Exercise
from ..checks.values import check_solutions, check_value
from ..checks.words import check_choice


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


# The exercises of this notebook, by key: dhlab.course.exercises.exercise(key) makes them.
EXERCISES = {"4.1": _ex_4_1, "4.2": _ex_4_2, "4.3": _ex_4_3, "4.4": _ex_4_4, "4.5": _ex_4_5}
