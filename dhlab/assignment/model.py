"""An assignment robot: what the student is given, and what every valid answer shares.

:func:`build` places a robot of the family (:mod:`dhlab.assignment.family`) in the
pictured world: its DH lengths (scaled in a variant), the pictured home pose, the
drawn positive sense of each joint, and how it is mounted. What comes out, an
:class:`AssignmentRobot`, has the same fields as the PUMA reference of
:mod:`dhlab.assignment.reference` (``axes``, ``points``, ``rows``, ``home_frames``,
``frames(Q)`` …), so the fair checks can take either:

* ``axes``: joint i's axis at home as a directed :class:`~dhlab.lines.Line` — the
  drawn arrow is the positive sense of q_i (right-hand rule, or the sliding sense);
* ``end_point``: the end effector's point at home, on the last joint's axis
  (``wrist_centre`` is the same point, the PUMA's name for it);
* ``points``: per link 0…n, its labelled points in the world at home (part 2);
* ``rows`` / ``home_frames``: one reference solution, frame 0 the pictured world
  frame, the rest placed by the DH rules from the drawn axes; ``robot``: the solution
  of :func:`dhlab.dh_frames.dh_from_axes` as a :class:`dhlab.DHRobot` (frame 0 on the
  drawn axis 1, so its base may turn the world frame).

The joint variables q_i are measured from the pictured home pose, positive as drawn.
Every pose is computed by the one forward-kinematics path, :mod:`dhlab.kinematics`
(the rows compiled once by :func:`dhlab.assignment.reference.dh_program`). The robot's
picture and tables are drawn by :mod:`~dhlab.assignment.pictures` and
:mod:`~dhlab.assignment.tables`, loaded on first use: the grader never draws.

>>> kr5 = build("kr5")
>>> kr5.kinds, kr5.n, len(kr5.points)
('RRRRRR', 6, 7)
>>> [round(float(v), 4) + 0.0 for v in kr5.end_point]          # wrist centre at home, metres
[1.4, 0.0, 0.52]
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .. import kinematics
from ..errors import DHLabError
from ..i18n import _
from ..lines import Line
from ..lines import relation as line_relation
from .family import spec as family_spec
from .reference import dh_program, row_matrix

__all__ = ["AssignmentRobot", "build", "physical_frames", "rows_from_frames",
           "random_frames_from_axes", "GRIPPER"]

GRIPPER = (0.03, 0.04)       # finger half-gap and finger length, metres (the drawing only)


def _base(mount: str, plate: float, yaw_deg: float, floor: float) -> np.ndarray:
    """World → the published frame 0: the plate at height ``plate`` on the world z axis,
    turned ``yaw_deg`` about it; on the ceiling the robot hangs (its frame 0 points down)."""
    c, s = math.cos(math.radians(yaw_deg)), math.sin(math.radians(yaw_deg))
    B = np.array([[c, -s, 0, 0], [s, c, 0, 0], [0, 0, 1, plate], [0, 0, 0, 1.0]])
    if mount == "ceiling":
        B = B @ np.diag([1.0, -1.0, -1.0, 1.0])         # Rx(180°): hang from the plate
    B[:3, 3] += floor * B[:3, 2]                          # up to frame 0 from the plate
    return _tidy(B)


def _tidy(T) -> np.ndarray:
    T = np.array(T, float)
    near = np.round(T[:3, :3])
    snap = np.abs(T[:3, :3] - near) < 1e-12
    T[:3, :3][snap] = near[snap]
    return T + 0.0


@dataclass
class _Geometry:
    """The variant's published model placed in the world (what the physics is)."""
    kinds: str
    rows: list              # published rows, scaled: (sign=1, joint, θ0, d0, a, α) radians/metres
    base: np.ndarray
    home: np.ndarray        # published q at the pictured pose
    senses: np.ndarray      # +1/−1: the drawn arrow against the published z
    program: kinematics.Program = field(init=False, repr=False)

    def __post_init__(self):
        self.program = dh_program(self.rows, self.kinds)        # compiled once: joint k moves link k

    def frames(self, Q) -> np.ndarray:
        """The published DH frames in the world at the student's q (from home, as drawn)."""
        Q = np.atleast_2d(np.asarray(Q, float))
        return self.base @ kinematics.run(self.program, self.home + Q * self.senses, frames=True)


def physical_frames(robot, Q) -> np.ndarray:
    """The published model's frames in the world at the student's joint values ``Q`` (N, n):
    the ground truth every valid DH answer must reproduce (origins may differ, the motion not)."""
    return robot._geometry.frames(Q)


@dataclass
class AssignmentRobot:
    """A robot to assign (see the module): drawn axes, link points, one reference solution."""
    key: str
    name: str
    kinds: str
    axes: list                     # Line per joint 1…n at home (index 0 = joint 1)
    end_point: np.ndarray
    points: list                   # per link k: [(label, world xyz at home)]
    rows: list                     # reference solution: (sign, joint, θ0, d0, a, α), radians/metres
    home_frames: np.ndarray        # (n+1, 4, 4) its frames at home, frame 0 = world
    qlim: list                     # per joint (low, high) of q from home: radians or metres
    link_names: list
    mount: dict                    # {"mount": "floor"|"ceiling", "plate": z of the plate}
    _geometry: _Geometry = field(repr=False, default=None)
    program: kinematics.Program = field(repr=False, default=None)     # rows compiled (joint k moves link k)
    _robot: object = field(repr=False, default=None)
    _families: dict = field(repr=False, default_factory=dict)     # the grader's cache of valid frames

    @property
    def n(self) -> int:
        return len(self.rows)

    @property
    def wrist_centre(self) -> np.ndarray:
        """The PUMA's name for :attr:`end_point` (frame n's origin)."""
        return self.end_point

    @property
    def end_name(self) -> str:
        """The label of the link point at the end point (frame n's origin), as the tables show it."""
        for link in reversed(self.points):
            for name, p in link:
                if np.linalg.norm(p - self.end_point) < 1e-9:
                    return name
        return "E"

    @property
    def end_text(self) -> str:
        """How the feedback names frame n's origin: the end point of the axes table."""
        return _("the end point {name} of the axes table").format(name=self.end_name)

    def frames(self, Q) -> np.ndarray:
        """The reference solution's frames 0…n at configurations Q (N, n)."""
        return kinematics.run(self.program, np.atleast_2d(np.asarray(Q, float)), frames=True)

    def axes_at(self, Q):
        """Joint axes at configurations Q (N, n): points (N, n, 3) and drawn directions (N, n, 3)."""
        F = self.frames(Q)
        signs = np.array([row[0] for row in self.rows], float)
        return F[:, :-1, :3, 3], F[:, :-1, :3, 2] * signs[None, :, None]

    def world_points(self, k: int) -> np.ndarray:
        return np.array([p for _name, p in self.points[k]])

    def local_points(self, k: int) -> np.ndarray:
        """Link k's points in the reference DH frame k (one valid answer of part 2)."""
        F = self.home_frames[k]
        return (self.world_points(k) - F[:3, 3]) @ F[:3, :3]

    @property
    def robot(self):
        """The reference solution as a :class:`dhlab.DHRobot` (``dh_from_axes`` on the axes;
        its q is the student's q, its base puts its frame 0 on joint 1's drawn axis)."""
        if self._robot is None:
            from ..dh_frames import dh_from_axes  # (sympy: only when a notebook asks for the robot)
            axes = [(ax.point, ax.direction, kind) for ax, kind in zip(self.axes, self.kinds)]
            qlim = [(lo, hi) if kind == "P" else (max(lo, -2 * math.pi), min(hi, 2 * math.pi))
                    for (lo, hi), kind in zip(self.qlim, self.kinds)]
            self._robot = dh_from_axes(axes, self.end_point, qlim=qlim, name=self.name, unit="m")
        return self._robot

    # The released notebook shows my_robot.figure() and its tables. Drawing is loaded on first
    # use (matplotlib's 3D toolkit comes with it): the grader builds robots by the hundred, never draws.

    def figure(self, **options):
        """The robot at home with its joint axes: see :func:`dhlab.assignment.pictures.axes_figure`."""
        from .pictures import axes_figure  # lazy: loaded on first use (see above)
        return axes_figure(self, **options)

    def axes_table(self):
        """The table the student is given: a point and the drawn direction of each axis."""
        from .tables import axes_table  # lazy: loaded on first use (see above)
        return axes_table(self)

    def points_table(self):
        """The link points at home, in the world frame (part 2)."""
        from .tables import points_table  # lazy: loaded on first use (see above)
        return points_table(self)


# --- building ------------------------------------------------------------------------------------

def build(key: str, *, lengths=None, home=None, senses=None, base=None, name=None) -> AssignmentRobot:
    """The robot ``key`` of the family, as published, or changed as a variant gives it.

    ``lengths``: {"d1": …, "a2": …} replacing published DH lengths (metres);
    ``home``: the pictured pose as published joint values (degrees / metres);
    ``senses``: per joint +1 or −1, the drawn arrow along or against the published z;
    ``base``: {"mount": "floor" | "ceiling", "plate": metres, "yaw": degrees}, where
    the world frame 0 is: on joint 1's axis, ``plate`` below the mounting plate,
    its x axis ``yaw`` degrees from the published x0. Defaults: as published, on the
    floor, plate at the world origin (the PUMA: world origin at the shoulder, as in
    the seed's exercise).
    """
    s = family_spec(key)
    lengths = dict(lengths or {})
    rows, qlim_pub = [], []
    for j, (kind, theta, d, a, alpha) in enumerate(s.rows):
        d, a = lengths.get(f"d{j + 1}", d), lengths.get(f"a{j + 1}", a)
        rows.append((1, j, math.radians(theta), float(d), float(a), math.radians(alpha)))
        lo, hi = s.qlim[j]
        qlim_pub.append((math.radians(lo), math.radians(hi)) if kind == "R" else (lo, hi))
    scale = lengths.get("stroke", 1.0)
    qlim_pub = [(lo * scale, hi * scale) if kind == "P" else (lo, hi) for (lo, hi), kind in zip(qlim_pub, s.kinds)]
    home = list(s.home if home is None else home)
    home_q = np.array([math.radians(v) if k == "R" else float(v) for v, k in zip(home, s.kinds)])
    senses = np.array([1] * s.n if senses is None else senses, float)
    if base is None:
        base = {"mount": "floor", "plate": -s.floor if key == "puma560" else 0.0, "yaw": 0}
    floor = lengths.get("floor", s.floor)
    B = _base(base["mount"], float(base["plate"]), float(base["yaw"]), floor)
    geometry = _Geometry(s.kinds, rows, B, home_q, senses)

    F = geometry.frames(np.zeros((1, s.n)))[0]
    axes = [Line(F[i, :3, 3], senses[i] * F[i, :3, 2]) for i in range(s.n)]
    end_point = F[-1, :3, 3].copy()
    points = _link_points(s, F, floor, [hi - lo for lo, hi in qlim_pub])
    qlim = []
    for (lo, hi), h, sense in zip(qlim_pub, home_q, senses):
        ends = sorted(((lo - h) * sense, (hi - h) * sense))
        qlim.append((float(ends[0]), float(ends[1])))
    robot = AssignmentRobot(key, name or s.name, s.kinds, axes, end_point, points, [], None, qlim,
                            list(s.link_names), {"mount": base["mount"], "plate": float(base["plate"])},
                            geometry)
    _reference_solution(robot)
    return robot


def _reference_solution(robot: AssignmentRobot) -> None:
    """The DH rules applied to the drawn axes, as :func:`dhlab.dh_frames.dh_from_axes` applies them
    (z_i along the drawn arrow of joint i+1, x_i along the common normal, origins at its feet,
    frame n at the end point), with frame 0 the pictured world frame (z0 lies on joint 1's axis,
    either sense, so frame 1 still follows it by one Tz·Tx). Plain numpy: a class of 300 is
    released in seconds; the tests check it against dh_from_axes and the published table."""
    lines = list(robot.axes)
    frames = [np.eye(4)]
    scale = max(1.0, float(np.abs(robot.end_point).max()))
    for k in range(1, len(lines)):                        # (robot.n counts rows: none yet)
        rel = line_relation(lines[k - 1], lines[k], tol=1e-9 * scale, angle_tol=1e-9)
        z = lines[k].direction
        if rel.kind == "coincident":                      # the same line: x_k = x_{k-1}, no offset
            origin, x = lines[k].nearest_point(frames[-1][:3, 3]), frames[-1][:3, 0]
        else:
            origin, x = np.asarray(rel.foot, float), np.asarray(rel.normal, float)
        frames.append(_frame(origin, x, z))
    z, x = lines[-1].direction, frames[-1][:3, 0]
    if np.linalg.norm(x - (x @ z) * z) < 1e-9:
        x = frames[-1][:3, 1]
    frames.append(_frame(robot.end_point, x, z))
    frames = np.array([_tidy(F) for F in frames])
    robot.rows = rows_from_frames(robot, frames)
    robot.home_frames = frames
    robot.program = dh_program(robot.rows, robot.kinds)


def rows_from_frames(robot, frames) -> list:
    """The DH rows ``(sign, joint, θ0, d0, a, α)`` that carry ``frames`` (at home) into
    each other; sign = −1 where z_{i−1} points against joint i's drawn arrow. A clear
    error when two frames are not related by one Tz·Tx (not DH frames)."""
    rows = []
    for k in range(1, len(frames)):
        A = np.linalg.inv(frames[k - 1]) @ frames[k]
        theta = math.atan2(A[1, 0], A[0, 0])
        alpha = math.atan2(A[2, 1], A[2, 2])
        d = float(A[2, 3])
        a = float(A[0, 3] * math.cos(theta) + A[1, 3] * math.sin(theta))
        if not np.allclose(row_matrix(theta, d, a, alpha), A, atol=1e-9):
            raise DHLabError(_("frames {j} and {k} are not related by Tz[θ, d]·Tx[α, a]: not DH frames.").format(
                j=k - 1, k=k))
        sign = 1 if frames[k - 1][:3, 2] @ robot.axes[k - 1].direction > 0 else -1
        rows.append((sign, k - 1, theta, d, a, alpha))
    return rows


# --- the link points of part 2 -------------------------------------------------------------------

def _link_points(s, F, floor: float, strokes) -> list:
    """Labelled points of links 0…n in the world at home.

    Each link k carries its published DH frame k; its points are where the link meets
    its two joint axes, along the DH path O_{k−1} → O_{k−1} + d_k z_{k−1} → O_k (a
    sliding link: from its tail, ``stroke`` behind). A link whose two axes meet in one
    point gets a knuckle: a point on each axis near it. Link 0 is the base, from the
    plate up joint 1's axis; link n ends in a two-finger gripper. Same place, same label.
    """
    plate = F[0, :3, 3] - floor * F[0, :3, 2]
    size = max(float(np.linalg.norm(F[-1, :3, 3] - plate)), 0.3)
    knuckle = max(round(0.08 * size, 2), 0.03)          # drawing only: a round number
    links = [[plate, _base_top(F, plate, floor)]]
    for k in range(1, s.n + 1):
        O_prev, z_prev, O = F[k - 1, :3, 3], F[k - 1, :3, 2], F[k, :3, 3]
        d = (O - O_prev) @ z_prev
        corner = O_prev + d * z_prev
        start = links[0][1] if k == 1 else O_prev
        if s.kinds[k - 1] == "P":
            stroke = strokes[k - 1]
            path = [corner - stroke * z_prev, corner, O]
        else:
            path = [start, corner, O]
        path = _dedupe(path)
        if len(path) == 1 and k < s.n:                       # axes meet in one point: a knuckle
            path = [O - knuckle * z_prev, O, O + knuckle * F[k, :3, 2]]
        links.append(path)
    g, t = GRIPPER
    x, z, E = F[-1, :3, 0], F[-1, :3, 2], F[-1, :3, 3]
    links[-1] = _dedupe(links[-1]) + [E - g * x + t * z, E - g * x, E + g * x, E + g * x + t * z]
    return _label(links)


def _base_top(F, plate, floor) -> np.ndarray:
    """Top of the base on joint 1's axis: below the pedestal's top (the PUMA), or a short
    plinth under the first joint's link."""
    z = F[0, :3, 2]
    rise = (F[1, :3, 3] - plate) @ z
    if floor > 0:
        return F[0, :3, 3] - round(0.37 * floor, 2) * z
    return plate + round(0.25 * rise, 2) * z


def _dedupe(path) -> list:
    out = []
    for p in path:
        if not out or np.linalg.norm(p - out[-1]) > 1e-6:
            out.append(np.array(p, float))
    return out


_LETTERS = "OBSACDEHJKLMNPRTUVWXYZ"


def _label(links) -> list:
    """Name every distinct point once (O, B, S, A, C, …; the gripper's G1…G4)."""
    names, seen, out = iter(_LETTERS), [], []
    for k, path in enumerate(links):
        labelled = []
        body = path[:-4] if k == len(links) - 1 else path
        for p in body:
            match = next((nm for nm, q in seen if np.linalg.norm(p - q) < 1e-6), None)
            if match is None:
                match = next(names, None) or f"P{len(seen)}"
                seen.append((match, p))
            labelled.append((match, _clean(p)))
        if k == len(links) - 1:
            labelled += [(f"G{i}", _clean(p)) for i, p in enumerate(path[-4:], start=1)]
        out.append(labelled)
    return out


def _clean(p) -> np.ndarray:
    p = np.round(np.asarray(p, float), 12) + 0.0
    return p


# --- every valid answer: random valid DH frames ---------------------------------------------------

def _unit(v):
    return v / np.linalg.norm(v)


def _frame(origin, x, z) -> np.ndarray:
    F = np.eye(4)
    x = _unit(x - (x @ z) * z)
    F[:3, 0], F[:3, 1], F[:3, 2], F[:3, 3] = x, np.cross(z, x), z, origin
    return F


def _perpendicular(z, rng) -> np.ndarray:
    v = rng.normal(size=3)
    return _unit(v - (v @ z) * z)


def random_frames_from_axes(robot: AssignmentRobot, rng, slide: float = 0.3) -> list:
    """A random valid set of DH frames 0…n at home, frame 0 the world frame, built from the
    robot's drawn axis lines by the convention's rules alone: independent of the frame families
    the checks accept (:func:`~dhlab.assignment.valid_frames.random_family_frames`), so the
    tests can hold the checks against the convention, and the only one that moves a prismatic
    axis' line.

    Every free choice of the convention is drawn: the sense of each z_i, the sense of
    x_i, the origin slid along z_i when consecutive axes are parallel (and x_i turned
    when they coincide), the line of a prismatic axis moved anywhere parallel to it, and
    frame n's x turned about the last axis. ``rng``: a numpy Generator.
    """
    n = robot.n
    lines = []
    for i, (axis, kind) in enumerate(zip(robot.axes, robot.kinds)):
        point = axis.point
        if kind == "P" and i > 0:                 # only the direction of a sliding axis matters
            point = point + slide * rng.uniform(-1, 1) * _perpendicular(axis.direction, rng)
        sense = 1.0 if i == 0 else float(rng.choice([-1.0, 1.0]))
        lines.append(Line(point, sense * axis.direction))
    frames = [np.eye(4)]
    scale = max(1.0, float(np.abs(robot.end_point).max()))
    for k in range(1, n):
        a, b = lines[k - 1], lines[k]
        rel = line_relation(a, b, tol=1e-9 * scale, angle_tol=1e-9)
        z = b.direction
        sx = float(rng.choice([-1.0, 1.0]))
        if rel.kind == "coincident":
            origin = b.point + slide * rng.uniform(-1, 1) * z
            x = _perpendicular(z, rng)
        else:
            origin = np.asarray(rel.foot, float)
            if rel.kind == "parallel":
                origin = origin + slide * rng.uniform(-1, 1) * z
            x = sx * np.asarray(rel.normal, float)
        frames.append(_frame(origin, x, z))
    z = float(rng.choice([-1.0, 1.0])) * lines[-1].direction
    frames.append(_frame(robot.end_point, _perpendicular(z, rng), z))
    return frames
