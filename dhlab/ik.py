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

from .validation import DHLabError

__all__ = ["pr_mechanism_ik", "pr_mechanism_ik_explained", "IKSolutions"]


class IKSolutions(list):
    """A list of joint vectors (possibly empty) with ``.message`` saying why there are that many."""

    def __init__(self, solutions, message: str):
        super().__init__(solutions)
        self.message = message


def _lengths(robot_or_params):
    params = getattr(robot_or_params, "params", robot_or_params)
    try:
        l1, l2 = float(params["l1"]), float(params["l2"])
    except (KeyError, TypeError, ValueError):
        raise DHLabError("pass the P-R mechanism (dhlab.robots.pr_mechanism()) or a dict "
                         "{'l1': ..., 'l2': ...} with its two lengths.") from None
    if l2 <= 0:
        raise DHLabError(f"l2 = {l2} must be a positive length (the rotating arm).")
    return l1, l2


def pr_mechanism_ik(robot_or_params, x: float, y: float, tol: float = 1e-12) -> IKSolutions:
    """All solutions (q1, q2) reaching (x, y): 2, 1 (|y| = l2) or 0 (|y| > l2), branch A first."""
    l1, l2 = _lengths(robot_or_params)
    for name, v in (("x", x), ("y", y)):
        if not math.isfinite(float(v)):
            raise DHLabError(f"target {name} = {v} must be a finite number.")
    ratio = float(y) / l2
    if abs(ratio) > 1 + tol:
        return IKSolutions([], f"no solution: |y| = {abs(y):g} > l2 = {l2:g}, the arm cannot reach "
                               f"that height (the point is outside the workspace, |y| ≤ l2).")
    ratio = max(-1.0, min(1.0, ratio))
    q2a = math.asin(ratio)
    root = l2 * math.sqrt(max(0.0, 1 - ratio * ratio))
    a = np.array([x - l1 - root, q2a])
    if root <= tol * l2:
        return IKSolutions([a], f"one solution: |y| = l2, the two branches meet (q2 = {math.degrees(q2a):g}°).")
    b = np.array([x - l1 + root, math.pi - q2a])
    return IKSolutions([a, b], "two solutions: branch A (elbow toward −x) and branch B (toward +x).")


def pr_mechanism_ik_explained(robot_or_params, x: float, y: float) -> str:
    """The solutions as text for a notebook (angles in degrees)."""
    sols = pr_mechanism_ik(robot_or_params, x, y)
    lines = [sols.message]
    for name, q in zip("AB", sols):
        lines.append(f"  {name}: q1 = {q[0]:.6g}, q2 = {math.degrees(q[1]):.6g}°")
    return "\n".join(lines)
