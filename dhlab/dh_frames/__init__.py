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

The work is split by concept: :mod:`dhlab.dh_frames.reading` reads and checks the
input, :mod:`dhlab.dh_frames.frames` places the frames (rules 4–9),
:mod:`dhlab.dh_frames.rows` reads the rows and builds the links (rules 10–13) and
:mod:`dhlab.dh_frames.report` is the report; everything is imported from here.
"""
from __future__ import annotations

from ..dh import DHRobot
from ..errors import DHLabError
from ..i18n import _
from ..kinematics import elementary
from ..transforms import inv
from ..validation import check_joint_values
from .frames import Placer
from .reading import (
    CASE1_RULES,
    PARALLEL_RULES,
    PRISMATIC_RULES,
    read_axes,
    read_choice,
    read_qlim,
    read_tol,
    read_tool,
    robot_size,
    short_repr,
)
from .report import DHAssignment, FrameStep
from .rows import check_rebuilt, dh_row, finish_steps, make_link, without_noise

__all__ = ["dh_from_axes", "dh_assignment", "joint_axes", "DHAssignment", "FrameStep"]


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
    lines = read_axes(axes)
    tool_pose, tool_point = read_tool(tool)
    sign_rule = read_choice(case1, CASE1_RULES, "case1")
    read_choice(parallel, PARALLEL_RULES, "parallel")
    read_choice(prismatic, PRISMATIC_RULES, "prismatic")
    rel = read_tol(tol)
    limits = read_qlim(qlim, [kind for _point, _direction, kind in lines])
    scale = robot_size([p for p, _direction, _kind in lines] + [tool_point])
    placer = Placer(lines, tool_pose, tool_point, rel, rel * scale, sign_rule, case1, parallel, prismatic)
    frames, steps = placer.place()

    rows = [dh_row(frames[i - 1], frames[i]) for i in range(1, len(lines) + 1)]
    links = [make_link(kind, row, rel * scale, rel, lim)
             for (_point, _direction, kind), row, lim in zip(lines, rows, limits)]
    robot = DHRobot(links, name=name, base=without_noise(frames[0], rel * scale),
                    joint_symbols=joint_symbols, unit=unit)
    if tool_pose is not None:
        robot.tool = without_noise(inv(robot.frames(robot.qz)[-1]) @ tool_pose, rel * scale)
    check = check_rebuilt(robot, placer.lines, tool_pose, tool_point, scale)
    if max(check) > 1e3 * rel * scale + 1e-9 * scale:
        raise DHLabError(_(
            "could not place consistent DH frames: the robot built misses the given axes by {axes} and the end "
            "effector by {tool}. Some axes are probably parallel or intersecting only up to rounding: pass a larger "
            "tol (e.g. tol=1e-6).").format(axes=f"{check[0]:.3g}", tool=f"{check[1]:.3g}"))
    finish_steps(steps, robot, tool_pose, rel * scale)
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
    if not (hasattr(robot, "numeric_links") and hasattr(robot, "frames")):
        raise DHLabError(_("joint_axes needs a dhlab robot (DHRobot or Robot), e.g. joint_axes(dhlab.robots.ssrms()); "
                           "got {value}.").format(value=short_repr(robot)))
    q = robot.qz if q is None else check_joint_values(q, robot.links, single=True)
    frames = robot.frames(q)
    axes = []
    for i, factors in enumerate(robot.numeric_links):
        T = frames[i]
        for kind, axis, const, is_joint, sign in factors:
            if is_joint:
                axes.append((T[:3, 3].copy(), sign * T[:3, axis].copy(), "R" if kind == "R" else "P"))
                break
            T = T @ elementary(kind, axis, const)
    return axes, robot.fk(q)
