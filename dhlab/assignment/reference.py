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
valid DH frames of each link (``frame_family``, ``is_valid_frame``, ``fit_link`` …) are in
:mod:`dhlab.assignment.valid_frames`, which builds on this module.

The frames of a chain of DH rows, at many configurations at once (:func:`dh_frames`), come
from the package's one forward-kinematics code path, :mod:`dhlab.kinematics`.

>>> ref = reference()
>>> [round(float(v), 5) for v in ref.wrist_centre]
[0.4521, -0.15005, 0.4318]
>>> [relation(ref.axes[i], ref.axes[i + 1]).kind for i in range(5)]
['intersect', 'parallel', 'skew', 'intersect', 'intersect']
"""
from __future__ import annotations

import functools
import math
import weakref
from dataclasses import dataclass, field

import numpy as np

from .. import kinematics
from ..i18n import N_, _
from ..lines import Line, LineRelation
from ..lines import relation as line_relation
from ..robots import puma560

__all__ = ["Line", "relation", "Reference", "reference", "LINK_NAMES",
           "dh_program", "dh_frames", "row_matrix", "cache_of", "TOL_POS", "TOL_DEG"]

TOL_POS = 2e-3        # metres: a student who types 0.15 for 0.15005 is right
TOL_DEG = 0.5         # degrees, for directions

LINK_NAMES = [N_("base (pedestal)"), N_("trunk"), N_("upper arm"), N_("forearm"), N_("wrist yoke"), N_("wrist"),
              N_("gripper")]               # (translated where shown: dhlab.assignment.checks.links)


def relation(l1: Line, l2: Line, tol: float = TOL_POS) -> LineRelation:
    """How axis ``l2`` lies with respect to axis ``l1`` (the three cases for x_i of the DH
    convention): :func:`dhlab.lines.relation` with the grader's tolerances — lines less
    than ``tol`` metres apart meet, directions less than ``TOL_DEG`` degrees apart are
    parallel. ``.acute`` is the angle between the axes, 0…90°."""
    return line_relation(l1, l2, tol=tol, angle_tol=math.radians(TOL_DEG))


_CACHES: dict = {}           # id(robot) -> its cache, dropped with the robot (see cache_of)


def cache_of(robot) -> dict:
    """A dict kept with ``robot`` (the PUMA :class:`Reference` or a student's robot) while it lives:
    for what the checks compute from the robot alone, once (its valid frames, its motion at the
    configurations every chain is compared at)."""
    cache = _CACHES.get(id(robot))
    if cache is None:
        cache = _CACHES[id(robot)] = {}
        weakref.finalize(robot, _CACHES.pop, id(robot), None)
    return cache


def dh_program(rows, kinds: str | None = None) -> kinematics.Program:
    """A chain of ``Tz[θ, d]·Tx[α, a]`` factors, compiled for :func:`dhlab.kinematics.run`.

    ``rows``: per link ``(sign, joint, θ0, d0, a, α)``, radians and metres; ``kinds``: one
    letter per link, 'R' (θ = θ0 + sign·q, the default) or 'P' (d = d0 + sign·q). A link
    whose ``joint`` is None does not move. The program's joint k is link k's: the caller
    hands it the column of ``joint`` (:func:`dh_frames`).
    """
    links = []
    for k, (sign, joint, theta, d, a, alpha) in enumerate(rows):
        slides = kinds is not None and kinds[k] == "P"
        moves = joint is not None
        factors = [("R", 2, theta, moves and not slides, sign), ("T", 2, d, moves and slides, sign),
                   ("T", 0, a, False, 1), ("R", 0, alpha, False, 1)]
        # a constant motion by 0 is the identity: leaving it out changes no number, and compiles faster
        links.append([f for f in factors if f[3] or f[2] != 0])
    return kinematics.compile_chain(links, np.eye(4), np.eye(4))


def dh_frames(rows, kinds: str | None, Q) -> np.ndarray:
    """Frames 0…n of a chain of ``Tz[θ, d]·Tx[α, a]`` factors (:func:`dh_program`), batched.

    ``kinds``: 'R'/'P' per link (None: every joint turns); ``Q``: (N, m) joint values, radians
    or metres; link k reads column ``rows[k][1]``. Returns (N, n+1, 4, 4), frame 0 the identity.

    >>> F = dh_frames([(1, 0, 0.0, 0.5, 0.2, 0.0)], "R", [[math.pi / 2]])
    >>> [round(float(v), 6) + 0.0 for v in F[0, 1, :3, 3]]
    [0.0, 0.2, 0.5]
    """
    Q = np.atleast_2d(np.asarray(Q, float))
    columns = [0 if joint is None else joint for _sign, joint, *_rest in rows]
    return kinematics.run(dh_program(rows, kinds), Q[:, columns], frames=True)


def row_matrix(theta: float, d: float, a: float, alpha: float) -> np.ndarray:
    """One row of a DH table as a matrix, ``Tz[θ, d]·Tx[α, a]`` (radians, metres), from the
    elementary motions of :mod:`dhlab.kinematics`: numbers only, without the argument checks of
    :func:`dhlab.transforms.dh_matrix` (which also takes symbols), because the checks call it
    thousands of times on values they made themselves."""
    step = kinematics.elementary
    return step("R", 2, theta) @ step("T", 2, d) @ step("T", 0, a) @ step("R", 0, alpha)


@dataclass
class Reference:
    """The reference PUMA: its DH rows, its axes and links' points at home, its frames at any q."""
    robot: object                 # dhlab DHRobot
    rows: list                    # (sign, joint, θ0, d, a, α) per link, radians
    axes: list                    # Line per joint 1…n at home (index 0 = joint 1)
    wrist_centre: np.ndarray
    points: list                  # per link k: list of (label, world xyz at home)
    home_frames: np.ndarray       # (n+1, 4, 4) reference DH frames at home
    program: kinematics.Program   # the rows compiled once (joint k moves link k)
    link_names: list = field(default_factory=lambda: list(LINK_NAMES))
    name: str = "PUMA 560"

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
        """The reference DH frames 0…n at configurations Q (N, n): (N, n+1, 4, 4)."""
        return kinematics.run(self.program, np.atleast_2d(np.asarray(Q, float)), frames=True)

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
    robot = puma560()
    rows = []
    for j, link in enumerate(robot.links):
        d, a, alpha, offset = _floats(link)
        rows.append((1, j, offset, d, a, alpha))
    program = dh_program(rows)
    home = kinematics.run(program, np.zeros((1, len(rows))), frames=True)[0]
    axes = [Line(home[i, :3, 3].copy(), home[i, :3, 2].copy()) for i in range(len(rows))]
    W = home[-1, :3, 3].copy()
    floor = float(puma560(floor=True).links[0].d)       # pedestal height, 0.67183 m
    return Reference(robot, rows, axes, W, _link_points(robot, W, floor), home, program)


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
