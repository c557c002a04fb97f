"""The PUMA 560 that the assignment is checked against, with the grader's tolerances.

The reference is :func:`dhlab.robots.puma560` (P. Corke's ``mdl_puma560``, metres),
with **frame 0 at the shoulder**: the world frame of the assignment's picture, origin
where the axes of joints 1 and 2 meet, z0 up along joint 1, x0 forward (towards the
arm in the home pose). The joint variables are the physical joint angles measured
from the pictured home pose (q = 0), positive by the right-hand rule about the drawn
arrow of each joint axis. Frame 6 (the end effector, *efector final*) has its origin
at the wrist centre W, where the axes of joints 4, 5 and 6 meet.

What every valid DH answer shares (DH frames are not unique) is computed here from
the reference robot, never typed: the **joint axes** as directed lines, the wrist
centre, and the **links' points** in the world at the home pose. How two axes
lie is :func:`dhlab.lines.relation`, with the grader's tolerances (:func:`relation`). The
valid DH frames of each link (:func:`frame_family`, :func:`is_valid_frame`, :func:`fit_link`
…) are in :mod:`dhlab.grading.frames`, and importable from here.

>>> ref = reference()
>>> [round(float(v), 5) for v in ref.wrist_centre]
[0.4521, -0.15005, 0.4318]
>>> [relation(ref.axes[i], ref.axes[i + 1]).kind for i in range(5)]
['intersect', 'parallel', 'skew', 'intersect', 'intersect']
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field

import numpy as np

from ..lines import Line, LineRelation
from ..lines import relation as line_relation
from .frames import (FrameFamily, dh_rows_from_frames, fit_link, frame_family, is_valid_frame,  # noqa: F401
                     nearest_valid_frame, random_valid_frames, rotation_angle, valid_frames_near)
from .language import N_, _

__all__ = ["Line", "relation", "Reference", "reference", "LINK_NAMES",
           "dh_frames", "TOL_POS", "TOL_DEG"]

TOL_POS = 2e-3        # metres: a student who types 0.15 for 0.15005 is right
TOL_DEG = 0.5         # degrees, for directions

LINK_NAMES = [N_("base (pedestal)"), N_("trunk"), N_("upper arm"), N_("forearm"), N_("wrist yoke"), N_("wrist"),
              N_("gripper")]               # (translated where shown: dhlab.grading.part2)


def relation(l1: Line, l2: Line, tol: float = TOL_POS) -> LineRelation:
    """How axis ``l2`` lies with respect to axis ``l1`` (the three cases for x_i of the DH
    convention): :func:`dhlab.lines.relation` with the grader's tolerances — lines less
    than ``tol`` metres apart meet, directions less than ``TOL_DEG`` degrees apart are
    parallel. ``.acute`` is the angle between the axes, 0…90°."""
    return line_relation(l1, l2, tol=tol, angle_tol=math.radians(TOL_DEG))


def dh_frames(rows, Q) -> np.ndarray:
    """Frames 0…n of a chain of ``Tz[θ, d]·Tx[α, a]`` factors, batched.

    ``rows``: per link ``(sign, joint, theta_const, d, a, alpha)`` with angles in
    radians; θ = sign·q[joint] + theta_const (``joint`` None: θ constant).
    ``Q``: (N, n) radians. Returns (N, n+1, 4, 4), frame 0 = identity.
    """
    Q = np.atleast_2d(np.asarray(Q, float))
    N = len(Q)
    out = np.zeros((N, len(rows) + 1, 4, 4))
    T = np.broadcast_to(np.eye(4), (N, 4, 4)).copy()
    out[:, 0] = T
    for k, (sign, joint, th0, d, a, al) in enumerate(rows):
        th = th0 + (sign * Q[:, joint] if joint is not None else 0.0)
        ct, st, ca, sa = np.cos(th), np.sin(th), math.cos(al), math.sin(al)
        A = np.zeros((N, 4, 4))
        A[:, 0, 0], A[:, 0, 1], A[:, 0, 2], A[:, 0, 3] = ct, -st * ca, st * sa, a * ct
        A[:, 1, 0], A[:, 1, 1], A[:, 1, 2], A[:, 1, 3] = st, ct * ca, -ct * sa, a * st
        A[:, 2, 1], A[:, 2, 2], A[:, 2, 3], A[:, 3, 3] = sa, ca, d, 1.0
        T = T @ A
        out[:, k + 1] = T
    return out


@dataclass
class Reference:
    """The reference PUMA: its DH rows, home-pose axes and points, and the valid frames."""
    robot: object                 # dhlab DHRobot
    rows: list                    # (sign, joint, θ0, d, a, α) per link, radians
    axes: list                    # Line per joint 1…n at home (index 0 = joint 1)
    wrist_centre: np.ndarray
    points: list                  # per link k: list of (label, world xyz at home)
    home_frames: np.ndarray       # (n+1, 4, 4) reference DH frames at home
    link_names: list = field(default_factory=lambda: list(LINK_NAMES))
    name: str = "PUMA 560"
    _families: dict = field(default_factory=dict, repr=False, compare=False)

    @property
    def n(self) -> int:
        return len(self.rows)

    @property
    def kinds(self) -> str:
        """One letter per joint: the PUMA's six turn ('RRRRRR')."""
        return "R" * self.n

    @property
    def qlim(self) -> list:
        """Per joint (low, high) of q, radians: the PUMA's joint limits."""
        return [tuple(float(v) for v in link.qlim) for link in self.robot.links]

    @property
    def end_point(self) -> np.ndarray:
        """Frame n's origin at home (the name every assignment robot shares)."""
        return self.wrist_centre

    @property
    def end_text(self) -> str:
        """How the feedback names frame n's origin."""
        return _("the wrist centre W, where the axes of joints 4, 5 and 6 meet")

    def frames(self, Q) -> np.ndarray:
        return dh_frames(self.rows, Q)

    def axes_at(self, Q):
        """Joint axes at configurations Q (N, n): points (N, n, 3) and directions (N, n, 3)."""
        F = self.frames(Q)
        return F[:, :-1, :3, 3], F[:, :-1, :3, 2]

    def world_points(self, k: int) -> np.ndarray:
        return np.array([p for _name, p in self.points[k]])

    def local_points(self, k: int) -> np.ndarray:
        """Link k's points in the reference DH frame k (one valid answer of part 2)."""
        F = self.home_frames[k]
        return (self.world_points(k) - F[:3, 3]) @ F[:3, :3]


def _floats(link):
    return float(link.d), float(link.a), float(link.alpha), float(link.offset)


@functools.lru_cache(maxsize=1)
def reference() -> Reference:
    """The reference PUMA 560 (built once)."""
    from ..robots import puma560

    robot = puma560()
    rows = []
    for j, link in enumerate(robot.links):
        d, a, alpha, offset = _floats(link)
        rows.append((1, j, offset, d, a, alpha))
    home = dh_frames(rows, np.zeros((1, len(rows))))[0]
    axes = [Line(home[i, :3, 3].copy(), home[i, :3, 2].copy()) for i in range(len(rows))]
    W = home[-1, :3, 3].copy()
    floor = float(puma560(floor=True).links[0].d)       # pedestal height, 0.67183 m
    return Reference(robot, rows, axes, W, _link_points(robot, W, floor), home)


def _link_points(robot, W, floor) -> list:
    """The labelled points that draw each link (world, home pose, metres).

    Built from the DH lengths (a2, a3, d3, d4) and the pedestal height, so nothing
    is typed twice; the few other numbers only shape the drawing (the pedestal's
    top, the yoke, the gripper) and are not part of the DH model.
    """
    a2, a3 = float(robot.links[1].a), float(robot.links[2].a)
    d3 = float(robot.links[2].d)
    side = np.array([0.0, -1.0, 0.0])             # joints 2, 3, 5 point this way at home
    up = np.array([0.0, 0.0, 1.0])
    S = np.zeros(3)                               # shoulder: axes 1 and 2 meet (frame 0)
    A = S + d3 * side                             # where the upper arm sits on axis 2
    E = A + np.array([a2, 0.0, 0.0])              # elbow, on axis 3
    K = E + np.array([a3, 0.0, 0.0])              # on the forearm axis (joint 4)
    M = W - 0.08 * up                             # top of the forearm
    Y = M + 0.05 * side                           # the yoke's arm ...
    N = W + 0.05 * side                           # ... reaching axis 5
    F = W + 0.056 * up                            # flange, on axis 6
    g = 0.03 * side
    return [
        [("O", S - floor * up), ("B", S - 0.25 * up)],
        [("B", S - 0.25 * up), ("S", S), ("A", A)],
        [("A", A), ("E", E)],
        [("E", E), ("K", K), ("M", M)],
        [("M", M), ("Y", Y), ("N", N)],
        [("N", N), ("W", W.copy()), ("F", F)],
        [("G1", F - g + 0.04 * up), ("G2", F - g), ("G3", F + g), ("G4", F + g + 0.04 * up)],
    ]
