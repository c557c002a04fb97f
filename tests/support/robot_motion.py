"""Two robots move alike: random configurations inside the joint limits, and the comparison of two
chains of frames (the same joint axes as lines, the same end point); used by the assignment's tests."""
import math

import numpy as np


def random_q(robot, rng, n=20):
    """Configurations inside the robot's joint limits (as q from home)."""
    lo = np.array([max(a, -math.pi) for a, _ in robot.qlim])
    hi = np.array([min(b, math.pi) for _, b in robot.qlim])
    return lo + (hi - lo) * rng.random((n, robot.n))


def assert_same_motion(robot, frames_a, frames_b, kinds, signs_a=None, signs_b=None):
    """Two chains of frames (N, n+1, 4, 4) move the same robot: every revolute axis z_{i-1} on the
    same line, every prismatic axis the same direction (up to sense), the same end point."""
    for i, kind in enumerate(kinds):
        za, zb = frames_a[:, i, :3, 2], frames_b[:, i, :3, 2]
        np.testing.assert_allclose(np.abs(np.sum(za * zb, axis=1)), 1.0, atol=1e-9)
        if kind == "R":
            d = frames_b[:, i, :3, 3] - frames_a[:, i, :3, 3]
            off_line = d - np.sum(d * za, axis=1)[:, None] * za
            np.testing.assert_allclose(off_line, 0.0, atol=1e-9)
    np.testing.assert_allclose(frames_a[:, -1, :3, 3], frames_b[:, -1, :3, 3], atol=1e-9)
