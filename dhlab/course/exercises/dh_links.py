"""Exercises of notebook 6: a link matrix by hand (6.1) and the wrist centre (6.2)."""
from __future__ import annotations

import math

import numpy as np
import sympy as sp

from ... import robots
from ...dh import DHRobot
from ...errors import DHLabError
from ...i18n import N_, _
from ...mdh import mdh_matrix
from ...transforms import dh_matrix
from ...validation import as_index, as_vector, has_angle_mark
from ..checks.feedback import Exercise, Feedback, unanswered
from ..checks.matrix import check_matrix
from ..checks.reading import is_unanswered
from ..checks.values import check_value
from .dh_common import as_robot, number_text

__all__ = ["link_exercise_robot", "check_link_matrix", "WRIST_Q_DEG", "check_wrist_centre"]


# --- 6.1: one link matrix by hand ---------------------------------------------------------------------
_SUP = str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹")
_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def _to_robot_symbols(M, robot):
    """C4 / S4 written as symbols become cos(q4) / sin(q4) of ``robot``'s joint 4."""
    swap = {}
    for s in M.free_symbols:
        text = str(s)
        if text[:1] in "CS" and text[1:].isdigit() and 1 <= int(text[1:]) <= robot.n:
            q = robot.q_symbols[int(text[1:]) - 1]
            swap[s] = sp.cos(q) if text[0] == "C" else sp.sin(q)
    return M.xreplace(swap)


def link_exercise_robot() -> DHRobot:
    """Exercise 6.1's two-link table: its row 2, (q2 + 90°, l2, 0, −90°), has an offset and
    a negative twist."""
    return DHRobot.from_table([("q1", "l1", 0, 90), ("q2 + 90", "l2", 0, -90)], name=_("exercise 6.1 table"),
                              params={"l1": 1.0, "l2": 0.5})


def check_link_matrix(M, i: int = 2, robot=None) -> Feedback:
    """Check a hand-written ^{i−1}A_i (4x4; C2 / S2 as symbols or cos(q2) / sin(q2)) against
    link ``i`` of ``robot`` (default: :func:`link_exercise_robot`)."""
    robot = link_exercise_robot() if robot is None else as_robot(robot, kind=DHRobot)
    i = as_index(i, "i", 1, robot.n)
    name = _("your {matrix}").format(matrix=f"{str(i - 1).translate(_SUP)}A{str(i).translate(_SUB)}")
    if is_unanswered(M):
        return unanswered(name)
    if isinstance(M, sp.MatrixBase):
        M = _to_robot_symbols(sp.Matrix(M), robot)
    link, q = robot.links[i - 1], robot.q_symbols[i - 1]
    mistakes = []
    if link.is_revolute:
        theta, d = q + link.offset, link.d
        if link.offset != 0:
            degrees = math.degrees(float(link.offset))
            mistakes.append((dh_matrix(q, d, link.a, link.alpha),
                             _("you left out the offset: θ{i} = {q} {sign} {degrees}°, so the entries hold cos "
                               "and sin of the whole θ{i}.").format(i=i, q=q, sign="+" if degrees > 0 else "−",
                                                                    degrees=number_text(abs(degrees)))))
    else:
        theta, d = link.theta, q + link.offset
    mistakes.append((dh_matrix(theta, d, link.a, -link.alpha),
                     _("the sign of α{i} is flipped: it is {alpha}°.").format(
                         i=i, alpha=number_text(math.degrees(float(link.alpha))))))
    mistakes.append((dh_matrix(theta, d, link.a, link.alpha).T,
                     _("you wrote the rows as columns: the whole matrix is transposed.")))
    mistakes.append((mdh_matrix(theta, d, link.a, link.alpha),
                     _("this is the modified DH (Craig) product Rx(α)·Tx(a)·Rz(θ)·Tz(d) of row {i}. The course "
                       "uses standard DH: A{i} = Rz(θ{i})·Tz(d{i})·Tx(a{i})·Rx(α{i}), the same four motions with "
                       "the ones along z_(i−1) first.").format(i=i)))
    return check_matrix(M, robot.A(i), name=name, mistakes=mistakes, index_style="math")


# --- 6.2: the wrist centre ----------------------------------------------------------------------------
WRIST_Q_DEG = (30, -45, 60, 90, -30, 45)


def _degrees(q_deg, n: int) -> np.ndarray:
    """``q_deg``: n joint angles in degrees, as plain numbers of at most a full turn."""
    if has_angle_mark(q_deg):
        raise DHLabError(_("q_deg is in degrees already: give plain numbers (30, not deg2rad(30))."))
    values = as_vector(q_deg, "q_deg", n)
    if np.any(np.abs(values) > 360):
        raise DHLabError(_("q_deg holds joint angles in degrees, each at most 360 in size; got {values}.").format(
            values=values.tolist()))
    return values


def _spherical_wrist(F, centre, tol: float) -> bool:
    """True when the axes of joints 4, 5, 6 (z3 through O3, z4 through O4, z5 through O5) all pass
    through ``centre``."""
    for k in (3, 4, 5):
        offset = centre - F[k, :3, 3]
        if np.linalg.norm(offset - (offset @ F[k, :3, 2]) * F[k, :3, 2]) > tol:
            return False
    return True


def check_wrist_centre(p, q_deg=WRIST_Q_DEG, robot=None) -> Feedback:
    """Check the wrist centre (x, y, z) of a 6-DOF arm with a spherical wrist (the axes of
    joints 4, 5, 6 meet in O4 = O5) at joint angles ``q_deg`` (degrees).
    Default robot: seed 002's 6-DOF arm."""
    robot = robots.seed002_6dof() if robot is None else as_robot(robot, joints=6)
    if robot.n != 6:
        raise DHLabError(_("robot must be a 6-DOF arm with a spherical wrist; it has {n} joints.").format(n=robot.n))
    q = np.radians(_degrees(q_deg, robot.n))
    F = np.asarray(robot.frames(q), dtype=float)
    T = np.asarray(robot.fk(q), dtype=float)
    centre, p_end, a = F[4, :3, 3], T[:3, 3], T[:3, 2]
    if not _spherical_wrist(F, centre, 1e-9 * max(1.0, robot.reach())):
        raise DHLabError(_("{name!r} has no spherical wrist: the axes of joints 4, 5 and 6 do not meet in one point "
                           "(O4 = O5), so it has no wrist centre to check.").format(name=robot.name))
    l4 = float(np.linalg.norm(p_end - centre))
    mistakes = [(p_end, _("that is the end effector p: the wrist centre is l4 = {l4} back from p along the "
                          "approach vector a (the third column of T): p_w = p − l4·a.").format(l4=number_text(l4))),
                (p_end + l4 * a, _("you went the wrong way along a: p_w = p − l4·a, not p + l4·a."))]
    for k in (1, 2, 3, 6):
        if np.linalg.norm(F[k, :3, 3] - centre) > 1e-6:
            mistakes.append((F[k, :3, 3], _("that is the origin of frame {k}: the wrist centre is where the axes "
                                            "of joints 4, 5 and 6 meet (O4 = O5).").format(k=k)))
    return check_value(p, centre, name=_("your wrist centre"), components=("x", "y", "z"), mistakes=mistakes)


# --- the exercises of this module, by key: dhlab.course.exercises.exercise(key) makes them -------------
EXERCISES = {
    "6.1": lambda: Exercise("6.1", N_("¹A₂ by hand"), lambda M: check_link_matrix(M, 2), [
        N_("Put θ2 = q2 + 90° and α2 = −90° into the general A of rule 14."),
        N_("cos(q2 + 90°) = −S2, sin(q2 + 90°) = C2, cos(−90°) = 0, sin(−90°) = −1.")]),
    "6.2": lambda: Exercise("6.2", N_("the wrist centre"), check_wrist_centre, [
        N_("The axes of joints 4, 5 and 6 meet in one point, O4 = O5: the wrist centre."),
        N_("From T = robot.fk(q): p_w = p − l4·a, with a = T[:3, 2] and l4 = 4.")]),
}
