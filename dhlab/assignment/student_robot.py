"""The student's robot, built from their answers: a :class:`dhlab.Robot`, its figure, a teach panel.

Part 4 of notebook 8 (not scored) shows the student what their answers make:
:func:`robot_of` turns part 3's ``T1 … Tn`` into a :class:`dhlab.Robot` whose joint i is
their q_i; :func:`my_robot_figure` places their part-2 links with it, over the robot of
the assignment in grey (:func:`dhlab.assignment.pictures.assembled_figure`), and
:func:`teach` puts it in a teach panel. The answers are read exactly as the grader reads
them (:func:`dhlab.assignment.answers.answers_from_namespace`); before part 3 is answered
each shows a :class:`~dhlab.assignment.pictures.Note` saying so, never a traceback.
"""
from __future__ import annotations

import math

import numpy as np

from ..chain import Robot
from ..errors import DHLabError
from ..i18n import _
from ..links import Link, Move, Rot
from .answers import Row, answers_from_namespace
from .checks.analysis import rows_of
from .family import shown_name
from .notebook_cells import current_robot
from .pictures import PUMA_BOX, Note, assembled_figure, box, link_lines
from .reference import reference

__all__ = ["robot_of", "my_robot_figure", "teach", "second_pose"]


def _rows_from(namespace, ref):
    """Part 3's rows (each a :class:`~dhlab.assignment.answers.Row`) and part 2's link points,
    read from the notebook's variables; a clear error while a T_i is not a Tz(...) @ Tx(...)."""
    answers = answers_from_namespace(namespace, ref.n)
    rows = rows_of(answers, ref.n)
    missing = [f"T{i}" for i, row in enumerate(rows, start=1) if not isinstance(row, Row)]
    if missing:
        raise DHLabError((_("answer part 3 first: {names} is not a transformation Tz(...) @ Tx(...) yet.")
                          if len(missing) == 1 else
                          _("answer part 3 first: {names} are not transformations Tz(...) @ Tx(...) yet.")).format(
            names=", ".join(missing)))
    points = answers.link_points if isinstance(answers.link_points, list) else []
    return rows, points


def robot_of(namespace):
    """Your robot, from T1…Tn (or chain) in ``namespace``, as a :class:`dhlab.Robot`
    whose joint i is your q_i (limits: those of the robot of the assignment, where your
    joint i is of the same kind)."""
    ref = current_robot()
    rows, _points = _rows_from(namespace, ref)
    links = []
    for i, row in enumerate(rows, start=1):
        _joint, sign, where = row.joint
        theta = math.radians((row.theta.const + 180) % 360 - 180)
        alpha = math.radians((row.alpha + 180) % 360 - 180)
        kind = ref.kinds[i - 1] if i <= ref.n else None
        if where == "theta":
            first = [Rot("z", theta, joint=True, sign=sign), Move("z", row.d.const)]
            qlim = _within_a_turn(ref.qlim[i - 1]) if kind == "R" else None
        elif where == "d":
            first = [Rot("z", theta), Move("z", row.d.const, joint=True, sign=sign)]
            qlim = tuple(ref.qlim[i - 1]) if kind == "P" else None
        else:
            raise DHLabError(_("T{i} has no joint variable: write θ{i} = q{i} + (constant).").format(i=i))
        links.append(Link(first + [Move("x", row.a), Rot("x", alpha)], name=f"T{i}", qlim=qlim))
    return Robot(links, name=_("your {robot}").format(robot=shown_name(ref.name)), unit="m")


def _within_a_turn(qlim) -> tuple:
    """A revolute joint's limits cut to one turn either way (a slider of ±720° helps nobody)."""
    lo, hi = qlim
    return max(float(lo), -2 * math.pi), min(float(hi), 2 * math.pi)


def second_pose(ref) -> np.ndarray:
    """The second pose of :func:`my_robot_figure`: the PUMA's, or each joint a third of the way
    to a limit (a prismatic joint a quarter of its stroke)."""
    if ref is reference():
        return np.radians([30, 20, -40, 45, 60, 90])
    q = []
    for i, ((lo, hi), kind) in enumerate(zip(ref.qlim, ref.kinds)):
        end = hi if i % 2 == 0 else lo
        q.append(0.25 * end if kind == "P" else max(-0.6, min(0.6, end / 3)))
    return np.array(q)


def _limits(ref) -> tuple:
    """The box a figure of ``ref`` shows: the PUMA's own, or a cube around the robot's reach."""
    if ref is reference():
        return PUMA_BOX
    lo, hi, span = box(ref)
    grow = 0.35 * span                                   # room for the arm at another pose
    return tuple(lo - grow), tuple(hi + grow)


def my_robot_figure(namespace, q=None):
    """Your links (part 2) assembled by your transformations (part 3), over the robot of the
    assignment in grey, at the home pose and at ``q`` (radians / metres; default a test
    configuration). Before part 3 is answered: a :class:`~dhlab.assignment.pictures.Note` saying so."""
    try:
        ref = current_robot()
        _rows, points = _rows_from(namespace, ref)
        robot = robot_of(namespace)
        q = second_pose(ref) if q is None else np.asarray(q, float)
        return assembled_figure(robot, points, ref, q, _limits(ref))
    except DHLabError as e:
        return Note(str(e))
    except (ValueError, ArithmeticError, IndexError, TypeError) as e:   # an answer matplotlib cannot draw
        return Note(_("your robot cannot be drawn ({kind}: {error}); check your answers first").format(
            kind=type(e).__name__, error=e))


def teach(namespace, **options):
    """A teach panel (sliders in degrees, or metres for a sliding joint) for your robot: your
    links assembled by your transformations, with your DH frames (x red, y green, z blue).
    Not scored. Before part 3 is answered: a :class:`~dhlab.assignment.pictures.Note` saying so."""
    from ..views.panels.teach import teach as teach_panel  # ipywidgets: only when a panel is asked for

    ref = current_robot()
    try:
        _rows, points = _rows_from(namespace, ref)
        robot = robot_of(namespace)
    except DHLabError as e:
        return Note(str(e))
    state = {}

    def draw_links(q):          # runs before the panel draws: only move the line
        line = state.get("line")
        if line is not None:
            line.set_data_3d(*link_lines(robot.frames(q), points).T)

    options.setdefault("planar", False)          # the robot is drawn in 3D, even when your answer is planar
    try:
        panel = teach_panel(robot, on_change=draw_links, **options)
        state["line"], = panel.view.ax.plot([], [], [], "-", color="C3", lw=3, alpha=0.8)
        panel.view.live.add_moving(state["line"])
        panel.set_q(panel.q)
    except DHLabError as e:
        return Note(_("your robot cannot be shown in a teach panel: {error}").format(error=e))
    except (ValueError, ArithmeticError, IndexError, TypeError) as e:   # an answer the views cannot draw
        return Note(_("your robot cannot be shown in a teach panel ({kind}: {error}); "
                      "check your T1…T{n} with check_part3 first").format(kind=type(e).__name__, error=e, n=ref.n))

    return panel
