"""Rules 10–13 of the DH frame placement: the row (θ, d, a, α) between consecutive
frames, the link it makes (angles within the tolerance of a whole degree made exact,
rounding noise removed), and the check of the robot built against the given axes.

Part of :mod:`dhlab.dh_frames` (import from there).

>>> import numpy as np
>>> F1 = np.eye(4); F1[:3, 3] = (1.0, 0.0, 0.5)
>>> [round(v, 6) for v in dh_row(np.eye(4), F1)]
[0.0, 0.5, 1.0, 0.0]
"""
from __future__ import annotations

import math

import numpy as np

from ..dh import PrismaticDH, RevoluteDH
from .frames import cross

__all__: list = []

def dh_row(F_prev, F):
    """θ, d, a, α that take frame i−1 to frame i (floats; radians)."""
    x0, z0, o0 = F_prev[:3, 0], F_prev[:3, 2], F_prev[:3, 3]
    x1, z1, o1 = F[:3, 0], F[:3, 2], F[:3, 3]
    theta = math.atan2(float(cross(x0, x1) @ z0), float(x0 @ x1))
    alpha = math.atan2(float(cross(z0, z1) @ x1), float(z0 @ z1))
    return theta, float((o1 - o0) @ z0), float((o1 - o0) @ x1), alpha


def make_link(kind, row, tol, angle_tol, qlim):
    """The DH link of joint ``kind`` ('R' or 'P') with the table ``row`` (θ, d, a, α), near-whole
    degrees made exact and lengths below ``tol`` made 0."""
    theta, d, a, alpha = row
    theta, alpha = _snap_angle(theta, angle_tol), _snap_angle(alpha, angle_tol)
    d, a = _snap_length(d, tol), _snap_length(a, tol)
    if kind == "R":
        return RevoluteDH(d=d, a=a, alpha=alpha, offset=theta, qlim=qlim)
    return PrismaticDH(theta=theta, a=a, alpha=alpha, offset=d, qlim=qlim)


def _snap_angle(value: float, angle_tol: float):
    """Within ``angle_tol`` of a whole number of degrees: exact (π/2, not 1.5707963…); in (−π, π]."""
    degrees = math.degrees(value)
    whole = round(degrees)
    if abs(degrees - whole) <= max(math.degrees(angle_tol), 1e-9):
        whole = 180 if whole == -180 else whole
        from ..symbolic import exact_angle  # (sympy: imported when the first frames are placed)
        return exact_angle(math.radians(whole)) if whole else 0
    return value


def _snap_length(value: float, tol: float) -> float:
    return 0.0 if abs(value) <= tol else float(f"{value:.12g}")


def without_noise(T, tol) -> np.ndarray:
    """A fixed transform with rounding noise removed (rotation entries near 0, ±1 made exact)."""
    T = np.array(T, dtype=float)
    R = T[:3, :3]
    near = np.round(R)
    snap = np.abs(R - near) < 1e-12
    R[snap] = near[snap]
    T[:3, 3][np.abs(T[:3, 3]) <= tol] = 0.0
    T[3] = [0, 0, 0, 1]
    return T + 0.0                                   # no -0.0


def finish_steps(steps, robot, tool_pose, tol):
    """Give each step its table row, and the frame as the robot built has it (rounding noise removed)."""
    frames = robot.frames(robot.qz)
    for step, F in zip(steps, frames):
        F = without_noise(F, tol)
        step.origin, step.x, step.z = F[:3, 3], F[:3, 0], F[:3, 2]
    for step, row in zip(steps[1:], robot.table().rows):
        step.row = tuple(row[1:5])
    if tool_pose is not None:
        if np.allclose(robot.tool, np.eye(4), atol=1e-12):
            steps[-1].notes.append("the given tool pose is this frame: the robot's tool transform is the identity")
        else:
            steps[-1].notes.append("the given tool pose is not this frame: the pose seen from it becomes the "
                                   "robot's tool transform (robot.tool)")


def check_rebuilt(robot, lines, tool_pose, tool_point, scale):
    """Measured on the robot built, at q = 0: (how far each z_{i−1} is from joint i's line —
    the distance of O_{i−1} from it, or the direction error times the robot's size —,
    the end effector's deviation from the given pose or point)."""
    F = robot.frames(robot.qz)
    worst = 0.0
    for i, line in enumerate(lines):
        o, z = F[i][:3, 3], F[i][:3, 2]
        worst = max(worst, line.distance_to_point(o), float(np.linalg.norm(z - line.direction)) * scale)
    end = robot.fk(robot.qz)
    tool_dev = float(np.abs(end - tool_pose).max()) if tool_pose is not None \
        else float(np.linalg.norm(end[:3, 3] - tool_point))
    return worst, tool_dev
