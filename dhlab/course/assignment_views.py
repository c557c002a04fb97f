"""The assignment's pictures: the robot to work on, the student's robot assembled, a teach panel.

:func:`puma_figure` draws the robot of the assignment with its joint axes (the PUMA 560,
or the student's own robot when the notebook's "Your robot" cell set one);
:func:`my_robot_figure` and :func:`teach` build the student's robot from their answers
(:func:`robot_of`: part 3's ``T1 … Tn`` as a :class:`dhlab.Robot`) and show it over the
robot of the assignment. Before part 3 is answered they show a :class:`Note` instead.
:mod:`dhlab.course.assignment` imports every name of this module: the notebook uses them
from there.
"""
from __future__ import annotations

import math

import numpy as np

from ..grading import answers as _answers
from ..grading import checks as _checks
from ..grading import puma as _puma
from ..grading.variants import shown_name
from ..i18n import N_, _
from ..validation import DHLabError

__all__ = ["current_robot", "puma_figure", "robot_of", "my_robot_figure", "teach", "Note"]

# The PUMA's link names (dhlab.grading.puma.LINK_NAMES), marked here for the message catalog:
# the figures and tables of this notebook show them translated.
_LINK_NAMES = (N_("base (pedestal)"), N_("trunk"), N_("upper arm"), N_("forearm"), N_("wrist yoke"),
               N_("wrist"), N_("gripper"))


def current_robot():
    """The robot of this notebook's assignment: the student's own robot when the notebook's
    "Your robot" cell set one (:func:`dhlab.course.family_notebook.use_variant`), else the
    PUMA 560 (:func:`dhlab.grading.puma.reference`)."""
    from .family_notebook import active_robot
    return active_robot() or _puma.reference()


def _is_puma(ref) -> bool:
    return ref is _puma.reference()


# --- the PUMA's picture ----------------------------------------------------------------------

def _new_axes(figsize=(7.5, 6.5), ncols: int = 1):
    """A course figure (a picture on a first Run All, inline or with ipympl) with 3D axes."""
    from ..views.figures import new_figure

    fig = new_figure(figsize=figsize, layout=None)       # the layout is set by hand (3D axes)
    axes = [fig.add_subplot(1, ncols, c + 1, projection="3d") for c in range(ncols)]
    return fig, axes


def _square(ax, lo=(-0.35, -0.45, -0.7), hi=(0.65, 0.25, 0.6)):
    ax.set(xlim=(lo[0], hi[0]), ylim=(lo[1], hi[1]), zlim=(lo[2], hi[2]),
           xlabel="$x_0$ [m]", ylabel="$y_0$ [m]", zlabel="$z_0$ [m]")
    ax.set_box_aspect(np.array(hi) - np.array(lo))
    ax.view_init(elev=18, azim=-65)
    from matplotlib.ticker import MaxNLocator
    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):          # a few ticks: no labels piled up
        axis.set_major_locator(MaxNLocator(4))


def _limits(ref) -> tuple:
    """The box a figure of ``ref`` shows: the PUMA's own, or a cube around the robot's reach."""
    if _is_puma(ref):
        return (-0.35, -0.45, -0.7), (0.65, 0.25, 0.6)
    from .family_views import _box
    lo, hi, span = _box(ref)
    grow = 0.35 * span                                   # room for the arm at another pose
    return tuple(lo - grow), tuple(hi + grow)


def _arc(axis_point, w, radius, start_dir):
    """Points of a 300° arc around direction ``w`` at ``axis_point``, turning by the right-hand rule."""
    u = start_dir - (start_dir @ w) * w
    u = u / np.linalg.norm(u)
    v = np.cross(w, u)
    t = np.radians(np.linspace(0, 300, 40))
    return axis_point + radius * (np.outer(np.cos(t), u) + np.outer(np.sin(t), v))


def _draw_links(ax, ref, links, label_points, fontsize=10):
    """The links ``links``, their points labelled for the links in ``label_points`` (True: all)."""
    seen = set()
    for k in links:
        P = ref.world_points(k)
        ax.plot(*P.T, "-o", color=f"C{k}", lw=4, ms=4,
                label=_("link {k}: {name}").format(k=k, name=_(_puma.LINK_NAMES[k])))
        labelled = label_points is True or k in (label_points or ())
        for name, p in ref.points[k]:
            if labelled and name not in seen:
                seen.add(name)
                ax.text(*(p + np.array([0.006, 0.0, 0.006])), name, fontsize=fontsize, color="0.15")


def _draw_axis(ax, ref, i: int, anchor, size: float):
    """Joint i's axis: a dashed line, an arrow for its positive direction, a curled
    arrow for its positive sense of turning (right-hand rule), and its name."""
    axis = ref.axes[i - 1]
    w = axis.direction
    c = axis.point + ((anchor - axis.point) @ w) * w
    a, b = c - 0.5 * size * w, c + 0.8 * size * w
    ax.plot(*np.array([a, b]).T, "--", color="0.1", lw=1.2)
    ax.quiver(*b, *(0.25 * size * w), color="0.1", arrow_length_ratio=0.45, lw=1.5)
    arc = _arc(c + 0.6 * size * w, w, 0.14 * size, np.array([1.0, 0.35, 0.25]))
    ax.plot(*arc.T, "-", color="purple", lw=1.5)
    ax.quiver(*arc[-2], *((arc[-1] - arc[-2]) * 5), color="purple", arrow_length_ratio=1.0, lw=1.5)
    ax.text(*(b + 0.3 * size * w), f"J{i}", fontsize=11, color="purple", weight="bold")


def puma_figure():
    """The robot of the assignment at its home pose. For the PUMA 560: whole (left) and its
    wrist (right), the links, the labelled points, each joint axis (dashed) with its positive
    direction (arrow) and positive sense of turning (curled arrow, right-hand rule), and the
    world frame 0 at the shoulder. For a student's own robot: its own figure
    (:meth:`~dhlab.course.family_model.AssignmentRobot.figure`). No DH frames: placing
    them is the exercise."""
    ref = current_robot()
    if not _is_puma(ref):
        return ref.figure()
    fig, (whole, wrist) = _new_axes(figsize=(12, 6.2), ncols=2)
    points = {name: p for link in ref.points for name, p in link}
    _draw_links(whole, ref, range(ref.n + 1), label_points=range(4))   # the wrist's points: on the right
    for i, anchor in zip((1, 2, 3, 4), ("B", "A", "E", "K")):
        _draw_axis(whole, ref, i, points[anchor], 0.25)
    for k, color in enumerate(("tab:red", "tab:green", "tab:blue")):
        e = np.eye(3)[k]
        whole.quiver(0, 0, 0, *(0.1 * e), color=color, lw=2.5, arrow_length_ratio=0.3)
        whole.text(*(0.13 * e), f"${'xyz'[k]}_0$", color=color, fontsize=11)
    _square(whole)
    whole.set_title(_("home pose (q = 0), world frame 0 at the shoulder S"), fontsize=10)
    _draw_links(wrist, ref, (4, 5, 6), label_points=True, fontsize=11)
    M = points["M"]
    wrist.plot(*np.array([M - [0, 0, 0.1], M]).T, "-", color="C3", lw=4)       # the forearm's top
    for i, anchor in zip((4, 5, 6), ("M", "N", "F")):
        _draw_axis(wrist, ref, i, points[anchor], 0.09)
    W = ref.wrist_centre
    _square(wrist, lo=W - np.array([0.1, 0.12, 0.13]), hi=W + np.array([0.1, 0.08, 0.15]))
    wrist.set_title(_("the wrist: axes 4, 5, 6 meet at W"), fontsize=10)
    fig.legend(*whole.get_legend_handles_labels(), loc="lower center", ncol=4, fontsize=10, frameon=False)
    fig.suptitle(_("PUMA 560: joint axes J1…J6, their positive directions and senses (right-hand rule)"))
    fig.subplots_adjust(left=0.0, right=0.97, bottom=0.11, top=0.92, wspace=0.05)
    return fig


# --- the student's robot: a dhlab Robot, a figure, a teach panel ------------------------------

def _rows_from(namespace, ref):
    answers = _answers.answers_from_namespace(namespace, ref.n)
    rows = _checks._rows(answers, ref.n)
    missing = [f"T{i}" for i, row in enumerate(rows, start=1) if not isinstance(row, _answers.Row)]
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
    from ..chain import Link, Move, Robot, Rot

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


def _link_lines(frames, points) -> np.ndarray:
    """Your link points placed by your frames: one polyline per link, NaN rows between."""
    chunks = []
    for k, P in enumerate(points):
        if k < len(frames) and isinstance(P, list) and P:
            P = np.array(P, float)
            chunks += [P @ frames[k][:3, :3].T + frames[k][:3, 3], np.full((1, 3), np.nan)]
    return np.vstack(chunks) if chunks else np.zeros((0, 3))


class Note:
    """A short message shown in place of a figure or a panel that cannot be made yet."""

    def __init__(self, text: str):
        self.text = text

    def __repr__(self):
        return self.text

    def _repr_html_(self):
        import html
        return f'<div style="color:#8a5300"><b>{html.escape(self.text)}</b></div>'


def _test_pose(ref) -> np.ndarray:
    """The second pose of :func:`my_robot_figure`: the PUMA's, or each joint a third of the way
    to a limit (a prismatic joint a quarter of its stroke)."""
    if _is_puma(ref):
        return np.radians([30, 20, -40, 45, 60, 90])
    q = []
    for i, ((lo, hi), kind) in enumerate(zip(ref.qlim, ref.kinds)):
        end = hi if i % 2 == 0 else lo
        q.append(0.25 * end if kind == "P" else max(-0.6, min(0.6, end / 3)))
    return np.array(q)


def my_robot_figure(namespace, q=None):
    """Your links (part 2) assembled by your transformations (part 3), over the robot of the
    assignment in grey, at the home pose and at ``q`` (radians / metres; default a test
    configuration). Before part 3 is answered: a :class:`Note` saying so."""
    try:
        ref = current_robot()
        rows, points = _rows_from(namespace, ref)
        robot = robot_of(namespace)
        q = _test_pose(ref) if q is None else np.asarray(q, float)
        return _my_robot_figure(robot, points, ref, q)
    except DHLabError as e:
        return Note(str(e))
    except (ValueError, ArithmeticError, IndexError, TypeError) as e:   # an answer matplotlib cannot draw
        return Note(_("your robot cannot be drawn ({kind}: {error}); check your answers first").format(
            kind=type(e).__name__, error=e))


def _pose_text(q, kinds) -> str:
    """'(30, 20, -40)°', or with each unit when a joint slides: '(30°, 20°, 0.05 m, 0°)'."""
    values = [round(math.degrees(v), 9) if kind == "R" else round(float(v), 9) for v, kind in zip(q, kinds)]
    if "P" not in kinds:
        return "(" + ", ".join(f"{v + 0.0:.5g}" for v in values) + ")°"
    return "(" + ", ".join(f"{v + 0.0:.5g}{'°' if kind == 'R' else ' m'}" for v, kind in zip(values, kinds)) + ")"


def _my_robot_figure(robot, points, ref, q):
    fig, axs = _new_axes(figsize=(11, 5.5), ncols=2)
    lo, hi = _limits(ref)
    for ax, pose, title in zip(axs, (np.zeros(ref.n), q), (_("home pose"), "q = " + _pose_text(q, ref.kinds))):
        R = ref.frames(pose[None])[0]
        ghost = _link_lines(R, [ref.local_points(k).tolist() for k in range(ref.n + 1)])
        ax.plot(*ghost.T, "-", color="0.75", lw=6, label=_("the {robot}").format(robot=shown_name(ref.name)))
        F = robot.frames(pose)
        mine = _link_lines(F, points)
        if len(mine):
            ax.plot(*mine.T, "-o", color="C3", lw=2, ms=3,
                    label=_("your links, assembled by your T1…T{n}").format(n=ref.n))
        ax.plot(*F[:, :3, 3].T, ":", color="C0", lw=1, label=_("your frame origins"))
        _square(ax, lo, hi)
        ax.set_title(title)
    fig.legend(*axs[0].get_legend_handles_labels(), loc="lower center", ncol=3, fontsize=9, frameon=False)
    fig.subplots_adjust(left=0.0, right=0.97, bottom=0.1, top=0.93, wspace=0.05)
    return fig


def teach(namespace, **options):
    """A teach panel (sliders in degrees, or metres for a sliding joint) for your robot: your
    links assembled by your transformations, with your DH frames (x red, y green, z blue).
    Not scored. Before part 3 is answered: a :class:`Note` saying so."""
    from ..views.teach import teach as _teach

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
            line.set_data_3d(*_link_lines(robot.frames(q), points).T)

    options.setdefault("planar", False)          # the robot is drawn in 3D, even when your answer is planar
    try:
        panel = _teach(robot, on_change=draw_links, **options)
        state["line"], = panel.view.ax.plot([], [], [], "-", color="C3", lw=3, alpha=0.8)
        panel.view.live.add_moving(state["line"])
        panel.set_q(panel.q)
    except DHLabError as e:
        return Note(_("your robot cannot be shown in a teach panel: {error}").format(error=e))
    except (ValueError, ArithmeticError, IndexError, TypeError) as e:   # an answer the views cannot draw
        return Note(_("your robot cannot be shown in a teach panel ({kind}: {error}); "
                      "check your T1…T{n} with check_part3 first").format(kind=type(e).__name__, error=e, n=ref.n))

    return panel
