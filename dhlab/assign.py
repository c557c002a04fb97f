"""Placing the Denavit-Hartenberg frames from the joint axes (rules 1–9 of seeds 002/003).

Describe a robot the way one sees it on a drawing, in one known pose: for each
joint (*articulación*) a point on its axis, the axis direction (which fixes the
positive sense of the joint variable: right-hand rule for a revolute joint, the
sliding sense for a prismatic one) and its kind, ``'R'`` or ``'P'``; and the end
effector's pose (4×4) or point in that same pose. :func:`dh_from_axes` then

1. puts z_{i−1} on joint i's axis, with the given direction (rule 4);
2. places frame 0 on z0 (rule 5), each frame i = 1 … n−1 by the relation of
   z_{i−1} and z_i (rules 6–8, the three cases of seed 000):

   * **case 1**, the axes intersect: x_i = ±(z_{i−1} × z_i), origin at the intersection;
   * **case 2**, the axes are parallel: their common normal is not unique, one is chosen;
     x_i runs along it from z_{i−1} towards z_i (so a_i > 0);
   * **case 3**, the axes are skew: x_i on their unique common normal, from z_{i−1}
     towards z_i, origin where it meets z_i;

3. places frame n at the end effector with z_n along z_{n−1} (rule 9);
4. reads each row θ_i, d_i, a_i, α_i between consecutive frames (rules 10–13),

and returns a :class:`~dhlab.DHRobot` whose q = 0 is the given pose, whose base
puts frame 0 where it was placed in the world, and whose forward kinematics is
the original robot's for every q. The report of every choice travels with it
as ``robot.assignment`` (a :class:`DHAssignment`: text with ``print``, a table
in Jupyter); :func:`dh_assignment` returns the report itself.

>>> import numpy as np
>>> import dhlab
>>> ssrms = dhlab.robots.ssrms()
>>> axes, tool = joint_axes(ssrms)            # z_{i-1} of each frame, at q = 0
>>> rebuilt = dh_from_axes(axes, tool, case1="z x z_prev")   # seed 000's sign for case 1
>>> print(rebuilt.table())
 i | θ  | d   | a  | α    | joint
 1 | q1 | 2.5 | 0  | -90° | R
 2 | q2 | 6   | 0  | -90° | R
 3 | q3 | 6   | 12 | 0°   | R
 4 | q4 | 1   | 12 | 0°   | R
 5 | q5 | 6   | 0  | -90° | R
 6 | q6 | 6   | 0  | -90° | R
 7 | q7 | 0   | 0  | 0°   | R
>>> [step.case for step in rebuilt.assignment.steps[1:-1]]      # x1 … x6
[1, 1, 2, 2, 1, 1]
>>> q = np.radians([10, 20, 30, 40, 50, 60, 70])
>>> bool(np.allclose(rebuilt.fk(q), ssrms.fk(q)))
True

The free choices (the seeds list them: O_0 and x_0; x_i's sign when the axes
intersect; which common normal when they are parallel; where a prismatic axis
lies) are keyword options, and every one taken is written in the report.
"""
from __future__ import annotations

import html
import math
from dataclasses import dataclass, field

import numpy as np

from .dh import DHRobot, PrismaticDH, RevoluteDH
from .kinematics import elementary
from .lines import Line, relation
from .symbolic import exact_angle
from .table import format_angle, format_length
from .transforms import inv
from .validation import FULL_TURN, DHLabError, as_float_array, check_joint_values, rigid_problem

__all__ = ["dh_from_axes", "dh_assignment", "joint_axes", "DHAssignment", "FrameStep"]

CASE1_RULES = {"z_prev x z": +1, "z x z_prev": -1, "nearest": 0}
PARALLEL_RULES = ("at_joint", "zero_d")
PRISMATIC_RULES = ("given", "through_origin")
NEARLY = 1e-4          # relations this close to the tolerance get a warning note


# --------------------------------------------------------------------------------------
# The report
# --------------------------------------------------------------------------------------
@dataclass
class FrameStep:
    """How frame ``i`` was placed: the rule, the case and why, the choices, the DH row.

    ``case`` is 1 (z_{i−1}, z_i intersect), 2 (parallel; also when they are the same
    line) or 3 (skew) for frames 1 … n−1, and None for frame 0 (rule 5) and frame n
    (rule 9). ``relation`` names what the axes do: 'intersecting', 'parallel',
    'coincident' or 'skew' (None for frame 0). ``origin``, ``x`` and ``z`` are the
    frame's origin and axes in the world, at q = 0; ``row`` is the table row
    (θ, d, a, α) as printed (None for frame 0).
    """
    i: int
    rule: str
    case: int | None
    relation: str | None
    why: str
    origin_choice: str
    x_choice: str
    origin: np.ndarray
    x: np.ndarray
    z: np.ndarray
    row: tuple | None = None
    notes: list = field(default_factory=list)

    @property
    def title(self) -> str:
        if self.i == 0:
            return "frame 0 (rule 5)"
        if self.case is None:
            return f"frame {self.i} (rule 9, end effector)"
        return f"frame {self.i}: case {self.case}"

    def lines(self) -> list:
        """The step as text lines (what ``print(report)`` shows for it)."""
        out = [f"{self.title} — {self.why}",
               f"    origin O{self.i} = {_vec(self.origin)}: {self.origin_choice}",
               f"    x{self.i} = {_vec(self.x)}: {self.x_choice}"]
        if self.row is not None:
            theta, d, a, alpha = self.row
            out.append(f"    row {self.i}: θ = {theta}, d = {d}, a = {a}, α = {alpha}")
        out += [f"    note: {note}" for note in self.notes]
        return out


class DHAssignment:
    """The report of :func:`dh_assignment`: one :class:`FrameStep` per frame 0 … n.

    ``print(report)`` gives the text; in Jupyter it shows as a table. Attributes:
    ``robot`` (the DHRobot built), ``steps``, ``frames`` (the DH frames in the world at
    q = 0, (n+1, 4, 4)), ``tol`` (lengths below it count as zero), ``options`` (the
    choices used), and ``check`` (the largest distance from a z_{i−1} to joint i's given
    axis and the end-effector deviation, measured on the robot built).
    """

    def __init__(self, robot, steps, tol, scale, options, check):
        self.robot = robot
        self.steps = steps
        self.tol = tol
        self.scale = scale
        self.options = options
        self.check = check

    @property
    def frames(self) -> np.ndarray:
        return self.robot.frames(self.robot.qz)

    @property
    def cases(self) -> list:
        """The case (1, 2 or 3) of x1 … x_{n−1}, as in seed 000's Paso 2."""
        return [step.case for step in self.steps[1:-1]]

    def table(self):
        """The DH table of the robot built (``robot.table()``)."""
        return self.robot.table()

    def _header(self) -> str:
        kinds = " ".join("R" if link.is_revolute else "P" for link in self.robot.links)
        return (f"DH frames of {self.robot.name!r}: {self.robot.n} joints ({kinds}); "
                f"lengths below {self.tol:.2g} count as 0")

    def _footer(self) -> str:
        rounding = 1e-12 * self.scale                 # differences below this are rounding: shown as 0
        axis_dev, tool_dev = (f"{v:.1g}" if v > rounding else "0" for v in self.check)
        return (f"check at q = 0: every z_(i-1) lies on joint i's axis with its direction (off by {axis_dev}), "
                f"the end effector is as given (off by {tool_dev}); rounding below {rounding:.1g} shows as 0")

    def __str__(self) -> str:
        lines = [self._header()]
        for step in self.steps:
            lines += step.lines()
        lines.append(self._footer())
        return "\n".join(lines)

    def __repr__(self) -> str:
        return str(self)

    def _repr_html_(self) -> str:
        head = "".join(f"<th>{h}</th>" for h in
                       ("frame", "case", "why", "origin", "x", "θ", "d", "a", "α"))
        body = []
        for s in self.steps:
            case = "rule 5" if s.i == 0 else ("rule 9" if s.case is None else str(s.case))
            why = html.escape(s.why)
            choice = html.escape(f"origin: {s.origin_choice}; x{s.i}: {s.x_choice}")
            notes = "".join(f"<br><em>note: {html.escape(n)}</em>" for n in s.notes)
            row = s.row or ("", "", "", "")
            cells = [str(s.i), case, f"{why}<br><small>{choice}</small>{notes}",
                     html.escape(_vec(s.origin)), html.escape(_vec(s.x))] + [html.escape(c) for c in row]
            body.append("<tr>" + "".join(f"<td>{c}</td>" for c in cells) + "</tr>")
        caption = html.escape(self._header())
        foot = html.escape(self._footer())
        return (f"<table><caption>{caption}</caption><thead><tr>{head}</tr></thead>"
                f"<tbody>{''.join(body)}</tbody></table><p><small>{foot}</small></p>")


# --------------------------------------------------------------------------------------
# Public functions
# --------------------------------------------------------------------------------------
def dh_from_axes(axes, tool=None, *, case1: str = "nearest", parallel: str = "at_joint",
                 prismatic: str = "given", tol: float = 1e-9, qlim=None,
                 name: str = "robot from axes", joint_symbols=None, unit: str = "") -> DHRobot:
    """A DH robot from its joint axes in one pose; the report is ``robot.assignment``.

    ``axes``: one ``(point, direction, kind)`` per joint — a point on the axis, the
    axis direction (any length; it fixes the positive sense of the joint variable)
    and ``'R'`` or ``'P'``. ``tool``: the end effector's pose (4×4) or point (x, y, z),
    in the same pose and world frame as the axes. See :func:`dh_assignment` for the
    options. The robot's q = 0 is the given pose and its ``fk`` equals the original
    robot's (in the world frame of the input) for every q.

    >>> import dhlab
    >>> arm = dh_from_axes([((0, 0, 0), (0, 0, 1), "R"), ((1, 0, 0), (0, 0, 1), "R")], tool=(1.5, 0, 0))
    >>> print(arm.table())
     i | θ  | d | a   | α  | joint
     1 | q1 | 0 | 1   | 0° | R
     2 | q2 | 0 | 0.5 | 0° | R
    >>> arm.assignment.cases
    [2]
    """
    return dh_assignment(axes, tool, case1=case1, parallel=parallel, prismatic=prismatic, tol=tol,
                         qlim=qlim, name=name, joint_symbols=joint_symbols, unit=unit).robot


def dh_assignment(axes, tool=None, *, case1: str = "nearest", parallel: str = "at_joint",
                  prismatic: str = "given", tol: float = 1e-9, qlim=None,
                  name: str = "robot from axes", joint_symbols=None, unit: str = "") -> DHAssignment:
    """Place the DH frames for ``axes`` and ``tool`` (see :func:`dh_from_axes`) and report why.

    Options (each choice the rules leave free; the report names the one taken):

    * ``case1``: the sign of x_i when z_{i−1} and z_i intersect. ``"nearest"``
      (default): the sign that keeps x_i closest to x_{i−1}, for the smallest θ
      offset (z_{i−1} × z_i on a tie) — it gives back the published SSRMS and PUMA
      tables row for row; ``"z_prev x z"``: x_i = z_{i−1} × z_i, so 0° < α_i < 180°;
      ``"z x z_prev"``: seed 000's x_i = z_i × z_{i−1} (−180° < α_i < 0°).
    * ``parallel``: which common normal when z_{i−1} ∥ z_i. ``"at_joint"`` (default,
      seeds' rule 6: "si son paralelos, el origen se sitúa en la articulación i+1"):
      the normal through joint i+1's given point, which becomes O_i; ``"zero_d"``:
      the normal through O_{i−1}, so d_i = 0. When the axes are the same line, O_i
      goes to that point too, and x_i = x_{i−1}.
    * ``prismatic``: only a prismatic axis's direction matters, not where the line
      lies (seed 002 note, ERRATA 002-n2). ``"given"`` (default): the line through the
      given point; ``"through_origin"``: the line through the previous origin O_{i−2}
      (the world origin for joint 1), which makes z_{i−2} and z_{i−1} meet there.
    * ``tol``: relative tolerance. Lengths below ``tol`` × (the robot's size) count
      as zero, axes less than ``tol`` radians apart as parallel, angles within
      ``tol`` of a whole degree are made exact. Raise it (e.g. 1e-4) for axes typed
      with few digits.
    * ``qlim``: one (low, high) per joint for the robot built (radians or lengths).
      ``name``, ``joint_symbols``, ``unit``: passed to :class:`~dhlab.DHRobot`.

    Frame 0 (rule 5) sits at the point of z0 nearest the world origin, with x0 the
    world x axis made perpendicular to z0 (world y when z0 is along world x): if
    the world frame already is a valid frame 0, the base is the identity. Frame n
    (rule 9) sits at the tool point, with z_n along z_{n−1}; x_n points from z_{n−1}
    to the tool point, or, when the point is on z_{n−1}, along the tool's x axis
    (made perpendicular to z_n) or else along x_{n−1}. A 4×4 tool pose that is not
    frame n becomes the robot's ``tool`` transform.
    """
    lines = _read_axes(axes)
    tool_pose, tool_point = _read_tool(tool)
    sign_rule = _read_choice(case1, CASE1_RULES, "case1")
    _read_choice(parallel, PARALLEL_RULES, "parallel")
    _read_choice(prismatic, PRISMATIC_RULES, "prismatic")
    rel = _read_tol(tol)
    limits = _read_qlim(qlim, [kind for _, _, kind in lines])
    scale = _scale([p for p, _, _ in lines] + [tool_point])
    placer = _Placer(lines, tool_pose, tool_point, rel, rel * scale, sign_rule, case1, parallel, prismatic)
    frames, steps = placer.place()

    rows = [_dh_row(frames[i - 1], frames[i]) for i in range(1, len(lines) + 1)]
    links = [_link(kind, row, rel * scale, rel, lim)
             for (_, _, kind), row, lim in zip(lines, rows, limits)]
    robot = DHRobot(links, name=name, base=_clean(frames[0], rel * scale),
                    joint_symbols=joint_symbols, unit=unit)
    if tool_pose is not None:
        robot.tool = _clean(inv(robot.frames(robot.qz)[-1]) @ tool_pose, rel * scale)
    check = _check(robot, placer.lines, tool_pose, tool_point, scale)
    if max(check) > 1e3 * rel * scale + 1e-9 * scale:
        raise DHLabError(
            f"could not place consistent DH frames: the robot built misses the given axes by "
            f"{check[0]:.3g} and the end effector by {check[1]:.3g}. Some axes are probably parallel "
            "or intersecting only up to rounding: pass a larger tol (e.g. tol=1e-6)."
        )
    _finish_steps(steps, robot, tool_pose, rel * scale)
    report = DHAssignment(robot, steps, rel * scale, scale,
                          dict(case1=case1, parallel=parallel, prismatic=prismatic, tol=rel), check)
    robot.assignment = report
    return report


def joint_axes(robot, q=None):
    """The joint axes of any ``robot`` (DH or not) at ``q`` (default q = 0), and its end pose.

    Returns ``(axes, tool)`` ready for :func:`dh_from_axes`: ``axes[i]`` is
    ``(point, direction, kind)`` of joint i+1 in the world (for a DH robot, the origin
    and z axis of frame i), ``tool`` is ``robot.fk(q)``. The robot rebuilt from them
    has its q = 0 at this ``q``.

    >>> import dhlab
    >>> axes, tool = joint_axes(dhlab.robots.robot_no_tan_elemental_1())
    >>> [(p.tolist(), d.tolist(), kind) for p, d, kind in axes]
    [([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], 'R'), ([0.0, 0.7, 0.0], [0.0, 0.0, 1.0], 'R')]
    """
    if not (hasattr(robot, "_numeric") and hasattr(robot, "frames")):
        raise DHLabError(f"joint_axes needs a dhlab robot (DHRobot or Robot), e.g. joint_axes(dhlab.robots.ssrms()); "
                         f"got {_short(robot)}.")
    q = robot.qz if q is None else check_joint_values(q, robot.links, single=True)
    frames = robot.frames(q)
    axes = []
    for i, factors in enumerate(robot._numeric):
        T = frames[i]
        for kind, axis, const, is_joint, sign in factors:
            if is_joint:
                axes.append((T[:3, 3].copy(), sign * T[:3, axis].copy(), "R" if kind == "R" else "P"))
                break
            T = T @ elementary(kind, axis, const)
    return axes, robot.fk(q)


# --------------------------------------------------------------------------------------
# Reading and checking the input
# --------------------------------------------------------------------------------------
def _read_axes(axes) -> list:
    """[(point, unit direction, kind)] or a DHLabError naming the bad entry."""
    example = "[((0, 0, 0), (0, 0, 1), 'R'), ((0, 0, 1), (0, 1, 0), 'P')]"
    if isinstance(axes, (str, bytes)) or not hasattr(axes, "__len__") or len(axes) == 0:
        raise DHLabError(f"axes must be a list with one (point, direction, kind) per joint, e.g. {example}; "
                         f"got {_short(axes)}.")
    lines = []
    for j, entry in enumerate(axes):
        where = f"axes[{j}] (joint {j + 1})"
        if isinstance(entry, (str, bytes)) or not hasattr(entry, "__len__") or len(entry) != 3:
            raise DHLabError(f"{where} must be (point, direction, kind), e.g. ((0, 0, 0), (0, 0, 1), 'R'); "
                             f"got {_short(entry)}.")
        point, direction, kind = entry
        p = _vector3(point, f"{where} point")
        u = _vector3(direction, f"{where} direction")
        length = float(np.linalg.norm(u))
        if length < 1e-12:
            raise DHLabError(
                f"{where} direction is {_vec(u)}: a joint axis needs a non-zero direction vector. "
                f"Its sense is the positive sense of q{j + 1} (right-hand rule for 'R', sliding sense for 'P')."
            )
        if not isinstance(kind, str) or kind not in ("R", "P"):
            hint = f" Write it in capitals: {kind.upper()!r}." if isinstance(kind, str) and kind in ("r", "p") \
                else " 'R' is a revolute joint (it turns about the axis), 'P' a prismatic one (it slides along it)."
            raise DHLabError(f"{where} kind must be 'R' or 'P', got {_short(kind)}.{hint}")
        lines.append((p, u / length, kind))
    return lines


def _vector3(value, name: str) -> np.ndarray:
    arr = as_float_array(value, name)
    if arr.shape != (3,):
        raise DHLabError(f"{name} must be 3 numbers (x, y, z), got shape {arr.shape}: {_short(value)}.")
    if not np.isfinite(arr).all():
        raise DHLabError(f"{name} is {arr.tolist()}: every coordinate must be a finite number.")
    return arr


def _read_tool(tool):
    """(pose or None, point) from a 4x4 pose or a 3-point."""
    if tool is None:
        raise DHLabError(
            "tool is missing: rule 9 puts frame n at the end effector, so give its pose (4x4) or its point "
            "(x, y, z), in the same pose and world frame as the axes. If the end effector is on the last "
            "joint's axis, a point on that axis will do, e.g. tool=axes[-1][0]."
        )
    arr = as_float_array(tool, "tool")
    if arr.shape == (3,):
        if not np.isfinite(arr).all():
            raise DHLabError(f"tool is {arr.tolist()}: every coordinate must be a finite number.")
        return None, arr
    if arr.shape != (4, 4):
        raise DHLabError(f"tool must be the end effector's pose (4x4) or point (x, y, z), got shape {arr.shape}.")
    if not np.isfinite(arr).all():
        raise DHLabError("tool has a value that is not a finite number (nan or inf): check the pose.")
    problem = rigid_problem(arr)
    if problem:
        raise DHLabError(f"tool is not a proper rigid transform: {problem}.")
    return arr, arr[:3, 3].copy()


def _read_choice(value, allowed, name: str):
    key = value.replace("×", "x") if isinstance(value, str) else value
    if isinstance(key, str):
        key = " ".join(key.split())
    if key not in allowed:
        options = ", ".join(repr(a) for a in allowed)
        raise DHLabError(f"{name} must be one of {options}, got {_short(value)}.")
    return allowed[key] if isinstance(allowed, dict) else key


def _read_tol(tol) -> float:
    try:
        value = float(tol)
    except (TypeError, ValueError):
        value = float("nan")
    if not (0 < value <= 1e-2):
        raise DHLabError(f"tol must be a small positive number (relative tolerance, e.g. 1e-9; at most 1e-2), "
                         f"got {_short(tol)}.")
    return value


def _read_qlim(qlim, kinds) -> list:
    if qlim is None:
        return [None] * len(kinds)
    if not hasattr(qlim, "__len__") or len(qlim) != len(kinds):
        raise DHLabError(f"qlim must give one (low, high) per joint ({len(kinds)}), got {_short(qlim)}.")
    out = []
    for j, (limits, kind) in enumerate(zip(qlim, kinds)):
        arr = as_float_array(limits, f"qlim[{j}]")
        if arr.shape != (2,) or not np.isfinite(arr).all() or not arr[0] < arr[1]:
            raise DHLabError(f"qlim[{j}] (joint {j + 1}) must be (low, high) with low < high, got {_short(limits)}.")
        if kind == "R" and np.abs(arr).max() > FULL_TURN + 1e-9:
            raise DHLabError(
                f"qlim[{j}] (joint {j + 1}, revolute) is {arr.tolist()}: more than one full turn. Limits are "
                f"radians: for degrees write dhlab.deg({arr[0]:g}), dhlab.deg({arr[1]:g})."
            )
        out.append((float(arr[0]), float(arr[1])))
    return out


def _scale(points) -> float:
    """The robot's size: the spread of the given points (not less than 1e-3 of their distance
    from the world origin, which sets the rounding error of their coordinates)."""
    P = np.array(points)
    spread = float(np.linalg.norm(P - P[0], axis=1).max())
    size = max(spread, 1e-3 * float(np.linalg.norm(P, axis=1).max()))
    return size if size > 0 else 1.0


# --------------------------------------------------------------------------------------
# Placing the frames (rules 4–9)
# --------------------------------------------------------------------------------------
class _Placer:
    """Frames 0 … n at the given pose, one after the other, with the report of each."""

    def __init__(self, lines, tool_pose, tool_point, rel, tol, sign_rule, case1, parallel, prismatic):
        self.given = lines
        self.lines = [None] * len(lines)          # the axis lines actually used (dhlab.lines.Line)
        self.tool_pose, self.tool_point = tool_pose, tool_point
        self.rel, self.tol, self.scale = rel, tol, tol / rel
        self.sign_rule, self.case1 = sign_rule, case1
        self.parallel, self.prismatic = parallel, prismatic

    def place(self):
        n = len(self.given)
        self._fix_line(0, np.zeros(3))
        frames, steps = [], []
        F, step = self._frame0()
        frames.append(F), steps.append(step)
        for i in range(1, n):
            self._fix_line(i, frames[i - 1][:3, 3])
            F, step = self._frame(i, frames[i - 1])
            frames.append(F), steps.append(step)
        F, step = self._frame_n(n, frames[n - 1])
        frames.append(F), steps.append(step)
        for j, (_, _, kind) in enumerate(self.given):
            if kind == "P":
                steps[j].notes.append(self._prismatic_note(j))
        return frames, steps

    # --- the axis lines: prismatic ones may be moved (only their direction matters) ---
    def _fix_line(self, j, previous_origin):
        """Line of joint j+1 (= z_j): as given, or for a prismatic joint through ``previous_origin``."""
        p, u, kind = self.given[j]
        if kind == "P" and self.prismatic == "through_origin":
            p = previous_origin
        self.lines[j] = Line(p, u)

    def _prismatic_note(self, j) -> str:
        where = ("the previous origin" if j else "the world origin") + " (prismatic='through_origin')"
        if self.prismatic == "given":
            where = "the given point (prismatic='given')"
        return (f"joint {j + 1} is prismatic: its direction is fixed (the sliding sense), but the line "
                f"z{j} may lie anywhere (seed 002 note 002-n2); it was put through {where}")

    # --- rule 5 -------------------------------------------------------------------
    def _frame0(self):
        z = self.lines[0].direction
        origin = self.lines[0].nearest_point(np.zeros(3))
        world_x = np.array([1.0, 0.0, 0.0])
        x = world_x - (world_x @ z) * z
        x_choice = "the world x axis, made perpendicular to z0"
        if np.linalg.norm(x) < 1e-6:                  # z0 along world x
            world_y = np.array([0.0, 1.0, 0.0])
            x = world_y - (world_y @ z) * z
            x_choice = "z0 is along the world x axis, so the world y axis, made perpendicular to z0"
        x = _unit(x)
        why = "z0 on joint 1's axis (rule 4); origin and x0 are free (rule 5)"
        step = FrameStep(0, "5", None, None, why, "the point of z0 nearest the world origin",
                         x_choice + " (y0 = z0 × x0)", origin, x, z)
        return _frame(origin, x, z), step

    # --- rules 6–8 --------------------------------------------------------------------
    def _frame(self, i, F_prev):
        """Frame i from z_{i−1} (joint i's line) and z_i (joint i+1's line)."""
        a, b = self.lines[i - 1], self.lines[i]
        O_prev, x_prev = F_prev[:3, 3], F_prev[:3, 0]
        rel = relation(a, b, tol=self.tol, angle_tol=self.rel)
        kind = "intersecting" if rel.kind == "intersect" else rel.kind     # the report's word
        dist, angle = rel.distance, math.radians(rel.acute)                # lines have no sense here
        za, zb = f"z{i - 1}", f"z{i}"
        notes = []
        if kind in ("intersecting", "skew"):
            origin = rel.foot                         # the point of z_i nearest z_{i-1}
            if kind == "intersecting":
                case = 1
                x, x_choice = self._case1_x(i, rel.normal, x_prev)
                why = f"{za} and {zb} intersect (at {_deg(angle)}): x{i} is perpendicular to both"
                origin_choice = "the intersection (rule 6)"
            else:
                case = 3
                x = rel.normal                        # from z_{i-1} towards z_i
                why = (f"{za} and {zb} are skew ({_deg(angle)} apart, distance {_num(dist)}): "
                       "they have one common normal")
                origin_choice = f"where the common normal meets {zb} (rule 6)"
                x_choice = f"along the common normal, from {za} towards {zb} (a{i} > 0)"
                if dist < NEARLY * self.scale:
                    notes.append(f"the axes nearly intersect (distance {dist:.2g}): if they should, pass a larger tol")
            if angle < NEARLY:
                notes.append(f"the axes are nearly parallel ({angle:.2g} rad): the common normal lies far away; "
                             "if they should be parallel, pass a larger tol")
        else:
            case = 2
            origin, origin_choice = self._parallel_origin(i, b, O_prev)
            antiparallel = rel.angle > 90
            sense = " (opposite directions, so α = 180°)" if antiparallel else ""
            if kind == "parallel":
                x = _unit(origin - a.nearest_point(origin))
                why = (f"{za} ∥ {zb}{sense}, {_num(dist)} apart: "
                       "infinitely many common normals, one is chosen")
                x_choice = f"along that common normal, from {za} towards {zb} (a{i} > 0)"
            else:
                x = x_prev
                why = (f"{za} and {zb} are the same line{sense}: a{i} = 0, "
                       f"and x{i} and O{i} are free")
                x_choice = f"x{i} = x{i - 1} (no turn about {za}: θ{i} offset 0)"
        step = FrameStep(i, "6-8", case, kind, why, origin_choice, x_choice, origin, x, b.direction, notes=notes)
        return _frame(origin, x, b.direction), step

    def _case1_x(self, i, cross, x_prev):
        """x_i for intersecting axes, from the unit ``cross`` = z_{i−1} × z_i / |…|."""
        if self.sign_rule > 0:
            return cross, f"x{i} = z{i - 1} × z{i} (case1='z_prev x z': 0° < α{i} < 180°)"
        if self.sign_rule < 0:
            return -cross, f"x{i} = z{i} × z{i - 1} (case1='z x z_prev', seed 000: -180° < α{i} < 0°)"
        if cross @ x_prev < -1e-9:
            return -cross, f"x{i} = z{i} × z{i - 1}, the sign nearest x{i - 1} (case1='nearest')"
        return cross, f"x{i} = z{i - 1} × z{i}, the sign nearest x{i - 1} (case1='nearest')"

    def _parallel_origin(self, i, b, O_prev):
        if self.parallel == "at_joint":
            origin = b.nearest_point(self.given[i][0])
            return origin, f"joint {i + 1}'s given point (parallel='at_joint', seed rule 6)"
        origin = b.nearest_point(O_prev)
        return origin, f"the foot of the normal from O{i - 1} (parallel='zero_d': d{i} = 0)"

    # --- rule 9 ---------------------------------------------------------------------------
    def _frame_n(self, n, F_prev):
        line, point = self.lines[n - 1], self.tool_point
        z, foot = line.direction, line.nearest_point(point)
        dist = line.distance_to_point(point)
        za = f"z{n - 1}"
        if dist > self.tol:
            kind, origin, x = "parallel", point, _unit(point - foot)
            why = f"z{n} along {za} (rule 9), through the end effector, {_num(dist)} from {za}"
            x_choice = f"from {za} towards the end effector (a{n} > 0)"
        else:
            kind, origin = "coincident", foot
            why = f"z{n} along {za} (rule 9); the end effector is on {za}, so x{n} is free"
            x, x_choice = F_prev[:3, 0], f"x{n} = x{n - 1} (θ{n} offset 0)"
            if self.tool_pose is not None:
                xt = self.tool_pose[:3, 0] - (self.tool_pose[:3, 0] @ z) * z
                if np.linalg.norm(xt) > 1e-6:
                    x, x_choice = _unit(xt), f"the tool's x axis (made perpendicular to z{n})"
        origin_choice = "the end effector's point (rule 9)"
        step = FrameStep(n, "9", None, kind, why, origin_choice, x_choice, origin, x, z)
        return _frame(origin, x, z), step


def _frame(origin, x, z) -> np.ndarray:
    """The 4x4 frame with this origin, z, and x made exactly perpendicular to z."""
    x = _unit(x - (x @ z) * z)
    F = np.eye(4)
    F[:3, 0], F[:3, 1], F[:3, 2], F[:3, 3] = x, _cross(z, x), z, origin
    return F


# --------------------------------------------------------------------------------------
# Rules 10–13: the DH row between consecutive frames, and the robot
# --------------------------------------------------------------------------------------
def _dh_row(F_prev, F):
    """θ, d, a, α that take frame i−1 to frame i (floats; radians)."""
    x0, z0, o0 = F_prev[:3, 0], F_prev[:3, 2], F_prev[:3, 3]
    x1, z1, o1 = F[:3, 0], F[:3, 2], F[:3, 3]
    theta = math.atan2(float(_cross(x0, x1) @ z0), float(x0 @ x1))
    alpha = math.atan2(float(_cross(z0, z1) @ x1), float(z0 @ z1))
    return theta, float((o1 - o0) @ z0), float((o1 - o0) @ x1), alpha


def _link(kind, row, tol, angle_tol, qlim):
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
        return exact_angle(math.radians(whole)) if whole else 0
    return value


def _snap_length(value: float, tol: float) -> float:
    return 0.0 if abs(value) <= tol else float(f"{value:.12g}")


def _clean(T, tol) -> np.ndarray:
    """A fixed transform with rounding noise removed (rotation entries near 0, ±1 made exact)."""
    T = np.array(T, dtype=float)
    R = T[:3, :3]
    near = np.round(R)
    snap = np.abs(R - near) < 1e-12
    R[snap] = near[snap]
    T[:3, 3][np.abs(T[:3, 3]) <= tol] = 0.0
    T[3] = [0, 0, 0, 1]
    return T + 0.0                                   # no -0.0


def _finish_steps(steps, robot, tool_pose, tol):
    """Give each step its table row, and the frame as the robot built has it (rounding noise removed)."""
    frames = robot.frames(robot.qz)
    for step, F in zip(steps, frames):
        F = _clean(F, tol)
        step.origin, step.x, step.z = F[:3, 3], F[:3, 0], F[:3, 2]
    for step, row in zip(steps[1:], robot.table().rows):
        step.row = tuple(row[1:5])
    if tool_pose is not None:
        if np.allclose(robot.tool, np.eye(4), atol=1e-12):
            steps[-1].notes.append("the given tool pose is this frame: the robot's tool transform is the identity")
        else:
            steps[-1].notes.append("the given tool pose is not this frame: the pose seen from it becomes the "
                                   "robot's tool transform (robot.tool)")


def _check(robot, lines, tool_pose, tool_point, scale):
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


# --------------------------------------------------------------------------------------
# Small helpers
# --------------------------------------------------------------------------------------
def _cross(a, b) -> np.ndarray:
    """a × b for 3-vectors (numpy's general cross is slow on single vectors)."""
    return np.array([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]])


def _unit(v) -> np.ndarray:
    return v / np.linalg.norm(v)


def _num(v: float) -> str:
    return format_length(float(v))


def _vec(v) -> str:
    return "(" + ", ".join(_num(c) for c in np.asarray(v, dtype=float)) + ")"


def _deg(angle: float) -> str:
    return format_angle(angle)


def _short(x) -> str:
    text = repr(x)
    return text if len(text) <= 60 else text[:57] + "..."

