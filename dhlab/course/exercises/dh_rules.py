"""Exercises of notebook 5 on single rules: the case of each x_i (rule 7, exercise 5.1) and a DH row
read from two frames (rules 10-13, exercise 5.2).

A case is read as one case: an answer that names none, several, or says what does not hold
("they do not intersect") gets feedback, never a guess.
"""
from __future__ import annotations

import math

import numpy as np

from ...errors import DHLabError
from ...i18n import N_, _
from ...mdh import mdh_matrix
from ...transforms import Rx, Rz, dh_matrix, trans
from ...validation import as_matrix4, describe, rigid_problem
from ..checks.case_words import CASE_NUMBERS as _CASE_NUMBERS
from ..checks.case_words import read_case_words
from ..checks.feedback import Exercise, Feedback, unanswered
from ..checks.reading import is_unanswered
from .dh_common import (
    ANGLE_TOL,
    Relation,
    as_robot,
    axes_of,
    axis_relation,
    number_text,
    quoted,
    read_numbers,
    right_answer,
    whole_number,
    wrong_answer,
)
from .dh_tables import four_axis_arm

__all__ = ["check_x_cases", "ROW_EXERCISE", "row_exercise_frames", "check_dh_row"]


# --- 5.1: the case of each x_i ------------------------------------------------------------------
_SAID = {"intersect": N_("z{p} and z{i} intersect"), "parallel": N_("z{p} and z{i} are parallel"),
         "skew": N_("z{p} and z{i} are skew"), "coincident": N_("z{p} and z{i} are the same line")}
_ASK = N_("say which one case holds: 'intersect', 'parallel' or 'skew' (or 'case 1', 'case 2', 'case 3').")
_CASE_NAMES = {"intersect": N_("intersect"), "parallel": N_("parallel"), "skew": N_("skew"),
               "coincident": N_("coincident")}


def read_case(value):
    """The case an answer names, read as one case: ('skew', '') from 'skew', 'se cruzan', 'case 3'
    or 3; (None, why) when it names none, several, or says what the case is not.

    >>> read_case("se cruzan")
    ('skew', '')
    >>> read_case("they do not intersect")[0] is None
    True
    """
    number = whole_number(value)
    if number is not None:
        if number not in _CASE_NUMBERS:
            return None, _("there is no case {number}: {ask}").format(number=number, ask=_(_ASK))
        return _CASE_NUMBERS[number], ""
    if not isinstance(value, str):
        return None, _("cannot read {value}: {ask}").format(value=quoted(value), ask=_(_ASK))
    shown = repr(value.strip()[:40])
    reading = read_case_words(value)             # the grader reads x_cases with the same function
    if reading.case is not None:
        return reading.case, ""
    named = reading.named
    if len(named) > 1:
        message = (_("your answer {shown} names two cases ({cases}): {ask}") if len(named) == 2 else
                   _("your answer {shown} names {count} cases ({cases}): {ask}"))
        return None, message.format(shown=shown, count=len(named), ask=_(_ASK), cases=_(" and ").join(
            _(_CASE_NAMES[k]) for k in sorted(named)))
    if reading.negated:
        return None, _("your answer {shown} says what does not hold: {ask}").format(shown=shown, ask=_(_ASK))
    return None, _("cannot read {value}: {ask}").format(value=quoted(value), ask=_(_ASK))


def refutation(said: str, rel: Relation) -> str:
    """Why the relation the student said is not the one of z_(i-1) and z_i, without naming the
    right one (that is the exercise): the test their claim fails."""
    if said == "coincident" and rel.kind == "intersect":
        return _("one line has a single direction, and their directions are {angle}° apart.").format(
            angle=number_text(min(rel.angle, 180 - rel.angle), 1))
    if said in ("intersect", "coincident"):
        return _("they do not meet: the shortest distance between the two lines is {distance}, not 0.").format(
            distance=number_text(rel.distance))
    if said == "parallel":
        return _("they do not point the same way: their directions are {angle}° apart.").format(
            angle=number_text(min(rel.angle, 180 - rel.angle), 1))
    return _("they lie in one plane, and skew lines never do (look at their directions, then at whether they "
             "meet).")


def _case_key(key):
    """A key of the answer dict as the number i of x_i: 1, '1', 'x1' -> 1; None otherwise."""
    number = whole_number(key)
    if number is not None:
        return number
    if isinstance(key, str):
        text = key.strip().lower().lstrip("x").strip("_ ")
        return int(text) if text.isdigit() else None
    return None


def check_x_cases(answer, robot=None) -> Feedback:
    """Check which case places x_i, i = 1 … n−1: ``{i: 'intersect' | 'parallel' | 'skew'}``
    (or 'case 1' …, or a list in the order x1, x2, …). Default robot: :func:`four_axis_arm`.

    A wrong case is refuted (the test the claimed relation fails), not corrected: the
    feedback never states the right case.
    """
    robot = four_axis_arm() if robot is None else as_robot(robot, joints=2)
    count = robot.n - 1
    name = _("the cases of x1 … x{count}").format(count=count)
    if is_unanswered(answer):
        return unanswered(name)
    if isinstance(answer, (list, tuple)):
        answer = dict(enumerate(answer, start=1))
    if not isinstance(answer, dict):
        return wrong_answer(name, [_("give a dict {{i: case}} for i = 1 … {count}, e.g. {{1: 'parallel', …}}, not a "
                                     "{type}.").format(count=count, type=type(answer).__name__)], plural=True)
    given = {}
    for key, value in answer.items():
        i = _case_key(key)
        if i is None or not 1 <= i <= count:
            return wrong_answer(name, [_("{key} is not one of the x_i asked: the keys are 1 … {count}.").format(
                key=quoted(key), count=count)], plural=True)
        given[i] = value
    missing = [i for i in range(1, count + 1) if i not in given]
    if missing:
        return wrong_answer(name, [_("say the case of every x_i, i = 1 … {count}: x{i} is missing.").format(
            count=count, i=missing[0])], plural=True)
    points, dirs = axes_of(robot, robot.qz)
    items = []
    for i in range(1, count + 1):
        said, unreadable = read_case(given[i])
        if said is None:
            items.append(f"x{i}: {unreadable}")
            continue
        rel = axis_relation(points[i - 1], dirs[i - 1], points[i], dirs[i])
        if rel.kind == "coincident" and said in ("coincident", "parallel", "intersect"):
            continue
        if said != rel.kind:
            items.append(_("x{i}: you said {said}, but {why}").format(
                i=i, said=_(_SAID[said]).format(p=i - 1, i=i), why=refutation(said, rel)))
    return wrong_answer(name, items, plural=True) if items else right_answer(name, plural=True)


# --- 5.2: one DH row from two frames ---------------------------------------------------------------
ROW_EXERCISE = (120.0, 0.3, 0.4, -90.0)       # θ, d, a, α of the hidden link (degrees, metres)


def row_exercise_frames():
    """The two frames of exercise 5.2: ({S_(i-1)}, {S_i}) in the world, 4x4 each."""
    theta, d, a, alpha = ROW_EXERCISE
    before = Rz(math.radians(30)) @ trans(0.2, -0.1, 0.3) @ Rx(math.radians(90))
    return before, before @ dh_matrix(math.radians(theta), d, a, math.radians(alpha))


def _angle_diff(a: float, b: float) -> float:
    """a − b in degrees, wrapped into (−180, 180]."""
    d = (a - b) % 360.0
    return d - 360.0 if d > 180.0 else d


def _true_row(before, after):
    A = np.linalg.solve(before, after)
    theta = math.atan2(A[1, 0], A[0, 0])
    alpha = math.atan2(A[2, 1], A[2, 2])
    a = A[0, 3] * math.cos(theta) + A[1, 3] * math.sin(theta)
    if not np.allclose(dh_matrix(theta, A[2, 3], a, alpha), A, atol=1e-9):
        raise DHLabError(_("these two frames are not related by a DH link: x_i must cross z_(i-1) at a right "
                           "angle."))
    return math.degrees(theta), float(A[2, 3]), float(a), math.degrees(alpha)


def _modified_reading(values, before, after) -> str:
    """Why ``values`` are the row in modified DH (Craig) but not in standard DH, or ''."""
    theta, d, a, alpha = values
    if max(abs(theta), abs(alpha)) > 720 or max(abs(d), abs(a)) > 1e6:
        return ""                           # not a row of these frames in any convention
    A = np.linalg.solve(before, after)
    angles = math.radians(theta), math.radians(alpha)
    scale = max(1.0, float(np.abs(A[:3, 3]).max()))
    standard = dh_matrix(angles[0], d, a, angles[1])
    craig = mdh_matrix(angles[0], d, a, angles[1])
    if np.allclose(standard, A, atol=1e-3 * scale) or not np.allclose(craig, A, atol=1e-3 * scale):
        return ""
    return _("this row is in modified DH (Craig): Rx(α)·Tx(a)·Rz(θ)·Tz(d) with your numbers carries {S_(i−1)} "
             "onto {S_i}. The course uses standard DH, A = Rz(θ)·Tz(d)·Tx(a)·Rx(α): the same four motions, "
             "the turn and slide along z_(i−1) first (θ, d), then along x_i (a, α).")


def _frame_pair(frames):
    """``frames`` = ({S_(i-1)}, {S_i}): two rigid 4x4 poses."""
    if not isinstance(frames, (list, tuple)) or len(frames) != 2:
        got = _("{n} items").format(n=len(frames)) if isinstance(frames, (list, tuple)) else describe(frames)
        raise DHLabError(_("frames must be a pair (S_prev, S_next) of 4x4 poses, got {got}.").format(got=got))
    pair = []
    for k, T in enumerate(frames):
        T = as_matrix4(T, f"frames[{k}]")
        problem = rigid_problem(T, 1e-6)
        if problem:
            raise DHLabError(_("frames[{k}] is not a pose: {problem}.").format(k=k, problem=problem))
        pair.append(T)
    return pair


def check_dh_row(answer, frames=None) -> Feedback:
    """Check a DH row ``(θ, d, a, α)`` (angles in **degrees**) that carries ``frames[0]`` =
    {S_(i-1)} onto ``frames[1]`` = {S_i} (default: :func:`row_exercise_frames`)."""
    name = _("your row (θ, d, a, α)")
    before, after = row_exercise_frames() if frames is None else _frame_pair(frames)
    if is_unanswered(answer):
        return unanswered(name)
    values, problem = read_numbers(answer, 4, _("(θ, d, a, α), angles in degrees"))
    if problem:
        return wrong_answer(name, [problem])
    theta, d, a, alpha = values
    t_theta, t_d, t_a, t_alpha = _true_row(before, after)
    modified = _modified_reading(values, before, after)
    if modified:
        return wrong_answer(name, [modified])
    scale = max(1.0, abs(t_d), abs(t_a))
    near = lambda x, y: abs(x - y) <= 1e-3 * scale
    same_angle = lambda x, y: abs(_angle_diff(x, y)) <= ANGLE_TOL
    if not (near(d, t_d) and near(a, t_a)) and near(d, t_a) and near(a, t_d):
        return wrong_answer(name, [_("d and a are swapped: the columns are θ, d, a, α; d is measured along z_(i−1), "
                                     "a along x_i.")])
    items = []
    if not same_angle(theta, t_theta):
        hint = ""
        if same_angle(theta, -t_theta):
            hint = _(" Check the sense: positive is counter-clockwise seen from the tip of z_(i−1).")
        elif same_angle(theta + 180, t_theta):
            hint = _(" It is 180° off: your x_i points the other way.")
        items.append(_("θ: turning x_(i−1) by your θ = {theta}° about z_(i−1) does not make it parallel to x_i "
                       "(rule 10).").format(theta=number_text(theta)) + hint)
    if not near(d, t_d):
        hint = _(" The sign: d is positive towards +z_(i−1).") if near(d, -t_d) else ""
        items.append(_("d: your d = {d} is not the distance along z_(i−1) from O_(i−1) to the point where x_i "
                       "crosses z_(i−1) (rule 11).").format(d=number_text(d)) + hint)
    if not near(a, t_a):
        hint = (_(" The sign: a is measured along +x_i, from z_(i−1) to O_i (a negative a means x_i points "
                  "from O_i back towards z_(i−1), note 002-n1).") if near(a, -t_a) else "")
        items.append(_("a: your a = {a} is not the distance along x_i from z_(i−1) to O_i (rule 12).").format(
            a=number_text(a)) + hint)
    if not same_angle(alpha, t_alpha):
        if same_angle(t_alpha, 0) or same_angle(t_alpha, 180):
            items.append(_("α: your α is {alpha}°, but z_(i−1) and z_i are parallel: α is 0° or 180° (0° when "
                           "they point the same way).").format(alpha=number_text(alpha)))
        elif same_angle(alpha, 0) or same_angle(alpha, 180):
            items.append(_("α: your α is {alpha}°, which keeps z_i parallel to z_(i−1), but they are at "
                           "{angle}° to each other.").format(alpha=number_text(alpha),
                                                              angle=number_text(abs(t_alpha), 1)))
        elif same_angle(alpha, -t_alpha):
            items.append(_("α: the size is right but not the sign: turning z_(i−1) by α about x_i (right-hand "
                           "rule: counter-clockwise seen from the tip of x_i) must bring it onto z_i (rule 13)."))
        else:
            items.append(_("α: turning z_(i−1) by your α = {alpha}° about x_i does not bring it onto z_i "
                           "(rule 13).").format(alpha=number_text(alpha)))
    if items:
        return wrong_answer(name, items)
    return right_answer(name, [_("Rz(θ)·Tz(d)·Tx(a)·Rx(α) carries {S_(i−1)} exactly onto {S_i}.")])


# --- the exercises of this module, by key: dhlab.course.exercises.exercise(key) makes them -------------
EXERCISES = {
    "5.1": lambda: Exercise("5.1", N_("the case of each x_i"), check_x_cases, [
        N_("Look at z_(i−1) and z_i (the axes of joints i and i+1): do they meet, are they parallel, or neither?"),
        N_("Skew lines are not parallel and never meet: their common normal is unique (case 3).")]),
    "5.2": lambda: Exercise("5.2", N_("a DH row from two frames"), check_dh_row, [
        N_("Read the figure, one motion at a time: θ turns about z_(i−1) until x_(i−1) points along x_i; "
           "d is how far along z_(i−1) the foot of x_i (where x_i crosses z_(i−1)) is from O_(i−1)."),
        N_("a is how far O_i is from that foot, measured along x_i; α turns about x_i until z_(i−1) "
           "points along z_i (right-hand rule for the signs)."),
        N_("Give the angles in degrees.")]),
}
