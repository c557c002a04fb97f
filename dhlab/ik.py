"""Inverse kinematics of seed 003's prismatic-rotational (P-R) mechanism.

Forward: x = q1 + l1 + l2·cos q2, y = l2·sin q2. Inverse, for a target (x, y):

* q2A = arcsin(y / l2),      q1A = x − l1 − l2·√(1 − (y/l2)²)
* q2B = π − arcsin(y / l2),  q1B = x − l1 + l2·√(1 − (y/l2)²)

The slide prints only q1A (erratum 003-1). When |y| = l2 the two branches are
the same point (the workspace boundary); when |y| > l2 there is no solution.

>>> sols = pr_mechanism_ik({"l1": 1.0, "l2": 0.5}, 2.0, 0.25)
>>> [s.round(6).tolist() for s in sols]
[[0.566987, 0.523599], [1.433013, 2.617994]]
"""
from __future__ import annotations

import math

import numpy as np

from .errors import DHLabError
from .i18n import _
from .validation import as_length, as_tolerance, describe

__all__ = ["pr_mechanism_ik", "pr_mechanism_ik_explained", "IKSolutions"]


class IKSolutions(list):
    """A list of joint vectors (possibly empty) with ``.message`` saying why there are that many."""

    def __init__(self, solutions, message: str):
        super().__init__(solutions)
        self.message = message


def _lengths(robot_or_params):
    """(l1, l2) of the P-R mechanism, from the robot itself or a dict of its two lengths."""
    if isinstance(robot_or_params, dict):
        if set(robot_or_params) != {"l1", "l2"}:
            raise DHLabError(_("pass the P-R mechanism (dhlab.robots.pr_mechanism()) or a dict "
                               "{{'l1': ..., 'l2': ...}} with its two lengths; got {got}.").format(
                                   got=describe(robot_or_params)))
        l1, l2 = (as_length(robot_or_params[k], k) for k in ("l1", "l2"))
    elif _is_pr_mechanism(robot_or_params):
        l1, l2 = robot_or_params.params["l1"], robot_or_params.params["l2"]
    else:
        raise DHLabError(_("pr_mechanism_ik solves seed 003's P-R mechanism only: pass "
                           "dhlab.robots.pr_mechanism() (any lengths) or a dict {{'l1': ..., 'l2': ...}}; "
                           "got {got}.").format(got=describe(robot_or_params)))
    if l2 <= 0:
        raise DHLabError(_("l2 = {l2} must be a positive length (the rotating arm).").format(l2=l2))
    return l1, l2


def _is_pr_mechanism(robot) -> bool:
    """True for a robot with exactly the P-R structure Tr(q1 + l1, 0, 0)·Rz(q2)·Tr(l2, 0, 0), no base or tool."""
    numeric = getattr(robot, "_numeric", None)
    params = getattr(robot, "params", None)
    if numeric is None or not isinstance(params, dict) or not {"l1", "l2"} <= set(params):
        return False
    shape = [[(kind, axis, joint, sign) for kind, axis, _const, joint, sign in link] for link in numeric]
    return (shape == [[("T", 0, True, 1)], [("R", 2, True, 1), ("T", 0, False, 1)]]
            and numeric[0][0][2] == params["l1"] and numeric[1][0][2] == 0 and numeric[1][1][2] == params["l2"]
            and np.array_equal(robot.base, np.eye(4)) and np.array_equal(robot.tool, np.eye(4)))


def pr_mechanism_ik(robot_or_params, x: float, y: float, tol: float = 1e-12) -> IKSolutions:
    """All solutions (q1, q2) reaching (x, y): 2, 1 (|y| = l2) or 0 (|y| > l2), branch A first.

    ``tol`` (relative, 0 ≤ tol ≤ 1e-2) decides when |y| = l2 counts as the boundary.
    """
    l1, l2 = _lengths(robot_or_params)
    x, y = as_length(x, "target x"), as_length(y, "target y")
    tol = as_tolerance(tol, "tol", upper=1e-2, zero=True)
    ratio = y / l2
    if abs(ratio) > 1 + tol:
        return IKSolutions([], _("no solution: |y| = {y:g} > l2 = {l2:g}, the arm cannot reach that height (the "
                                 "point is outside the workspace, |y| ≤ l2).").format(y=abs(y), l2=l2))
    ratio = max(-1.0, min(1.0, ratio))
    q2a = math.asin(ratio)
    root = l2 * math.sqrt(max(0.0, 1 - ratio * ratio))
    a = np.array([x - l1 - root, q2a])
    if root <= tol * l2:
        return IKSolutions([a], _("one solution: |y| = l2, the two branches meet (q2 = {q2:g}°).").format(
            q2=math.degrees(q2a)))
    b = np.array([x - l1 + root, math.pi - q2a])
    return IKSolutions([a, b], _("two solutions: branch A (arm pointing forward, +x) and B (arm pointing back, "
                                 "−x)."))


def pr_mechanism_ik_explained(robot_or_params, x: float, y: float) -> str:
    """The solutions as text for a notebook (angles in degrees)."""
    sols = pr_mechanism_ik(robot_or_params, x, y)
    lines = [sols.message]
    for name, q in zip("AB", sols):
        lines.append(f"  {name}: q1 = {q[0]:.6g}, q2 = {math.degrees(q[1]):.6g}°")
    return "\n".join(lines)
