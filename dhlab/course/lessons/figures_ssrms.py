"""The figures of notebook 7 (the SSRMS), drawn by the notebook's own code.

* :func:`paso1_figure`, :func:`paso2_figure`, :func:`paso3_figure`: seed 000's method on the SSRMS, one
  figure per step (its figures 7, 8–9 and 14): each z_i on joint A_(i+1)'s axis; the case of each x_i with
  its common normal; the origins B_i and y_i = z_i × x_i;
* :func:`links_figure`: each link of the SSRMS in its own frame, as seed 000 designs its pieces;
* :func:`rot_x_figure`: Rot_x(−90°) seen from the tip of +x (erratum 000-1: it is clockwise);
* :func:`seed001_figure`: the arm at zero built with seed 000's THz and with seed 001's faulty one.
"""
from __future__ import annotations

import numpy as np
from matplotlib.lines import Line2D

from ... import robots
from ...i18n import _
from ...transforms import Rx
from ...units import deg2rad
from ...views.figures import new_figure
from ...views.triads import free_direction
from .figures_common import AXIS_COLORS, fit_box, label, triad
from .ssrms_steps import frames_b, x_steps, z_axes

__all__ = ["paso1_figure", "paso2_figure", "paso3_figure", "links_figure", "rot_x_figure", "seed001_figure"]

SKELETON = dict(color="0.62", lw=9, solid_capstyle="round")     # wide and light: the triad stays visible on it
PREVIOUS_AXIS = dict(ls="--", color="0.35", lw=1.5)             # joint i's axis, z_(i-1)
NEXT_AXIS = dict(ls="--", color=AXIS_COLORS[2], lw=1.5)         # joint i+1's axis, the local z


# --- seed 000's Paso 1 … 3 on the arm at zero -------------------------------------------------------------
AXIS_LINE = dict(ls="--", color="0.45", lw=1.2)                 # a joint's axis A_i, as a long line
NORMAL = dict(color="tab:purple", lw=4, solid_capstyle="butt")   # a common normal (case 2)
CAMERA = (20.0, -38.0)                                          # elevation, azimuth: every joint in sight


def _arm_axes(fig, robot, title, rect=(0.0, 0.09, 1.0, 0.84)):
    """A 3D axes with ``robot`` drawn faintly at θ = 0 (no triads): the steps are drawn over it."""
    from ...views.view import robot_view  # lazy: the live views load ipywidgets and mplot3d

    ax = fig.add_axes(rect, projection="3d")
    robot_view(robot, robot.qz, ax=ax, triads=False, labels=False, alpha=0.35)
    ax.computed_zorder = False
    ax._robot_lines = len(ax.lines)             # what the steps draw next goes on top (_on_top)
    points = np.asarray(robot.frames(robot.qz), dtype=float)[:, :3, 3]
    fit_box(ax, points, pad=3.5)
    ax.set_proj_type("ortho")
    ax.view_init(*CAMERA)
    ax.set_axis_off()                           # no box, no ticks: the steps are about the arm's lines
    ax.set_box_aspect(np.ptp(points, axis=0) + 7, zoom=1.25)
    fig.suptitle(title, fontsize=14, y=0.985)
    return ax


def _on_top(ax):
    """Put what a step drew (the lines after the robot's own) over the joints' solids."""
    for line in ax.lines[ax._robot_lines:]:
        line.set_zorder(4)
    for text in ax.texts:
        text.set_zorder(5)


def _arrow(ax, start, direction, length, color, lw=3.0):
    end = np.asarray(start, dtype=float) + length * np.asarray(direction, dtype=float)
    ax.plot(*np.array([start, end]).T, color=color, lw=lw, solid_capstyle="round")
    ax.plot(*end[:, None], marker="o", ms=5, color=color)
    return end


# where each z_i's label goes, off the lines (in data units, added to the arrow's tip): seen from CAMERA
Z_LABEL_SHIFT = {0: (-1.5, 0, 0.4), 1: (0, 0.8, 1.2), 2: (-1.6, 0, 0.6), 3: (-1.6, 0, 0.6), 4: (1.6, 0, 0.6),
                 5: (0, -0.6, 1.3), 6: (1.6, 0, 0.4)}


def paso1_figure(robot=None, length: float = 3.5):
    """Paso 0 and 1 (seed 000, figure 7): the joints A_1 … A_n on their axes (dashed) and each z_i on the
    axis of A_(i+1), from its origin. Returns the figure."""

    robot = robots.ssrms() if robot is None else robot
    fig = new_figure((9.6, 7.0), layout=None)
    ax = _arm_axes(fig, robot, _("Paso 1: each $z_i$ on the axis of joint $A_{i+1}$"))
    for i, line in enumerate(z_axes(robot)):
        ax.plot(*np.array([line.point - 4 * line.direction, line.point + 4.5 * line.direction]).T, **AXIS_LINE)
        label(ax, line.point - 4.9 * line.direction, f"$A_{i + 1}$", color="0.3")
        tip = _arrow(ax, line.point, line.direction, length, AXIS_COLORS[2])
        label(ax, tip + np.array(Z_LABEL_SHIFT.get(i, (1.2, 0, 0.5))), f"$z_{i}$", color=AXIS_COLORS[2])
    handles = [Line2D([], [], label=_("axis of joint $A_i$ (articulación)"), **AXIS_LINE),
               Line2D([], [], color=AXIS_COLORS[2], lw=3, label=_("$z_{i-1}$, on the axis of $A_i$"))]
    _on_top(ax)
    fig.legend(handles=handles, loc="lower center", ncols=2, fontsize=12, frameon=False)
    return fig


def paso2_figure(robot=None, length: float = 3.5):
    """Paso 2 (seed 000, figures 8 and 9): each x_i (red) with its case; for parallel axes (case 2) the
    common normal chosen (purple) from z_(i−1) to z_i, where B_i is placed. Returns the figure."""

    robot = robots.ssrms() if robot is None else robot
    fig = new_figure((9.6, 7.0), layout=None)
    ax = _arm_axes(fig, robot, _("Paso 2: the case of each $x_i$"))
    for line in z_axes(robot):
        ax.plot(*np.array([line.point - 4 * line.direction, line.point + 4 * line.direction]).T,
                color=AXIS_COLORS[2], lw=1.2, alpha=0.6)
    for step in x_steps(robot):
        if step.case == 1:
            ax.plot(*step.origin[:, None], marker="o", ms=9, mfc="white", mec="k", mew=1.5)
        else:
            ax.plot(*np.array([step.foot, step.origin]).T, **NORMAL)
        tip = _arrow(ax, step.origin, step.x, length, AXIS_COLORS[0])
        label(ax, tip + (0.7, 0, 0), _("$x_{i}$: case {case}").format(i=step.i, case=step.case),
              color=AXIS_COLORS[0], ha="left")
    handles = [Line2D([], [], color=AXIS_COLORS[2], lw=1.2, label=_("$z_i$ lines")),
               Line2D([], [], ls="", marker="o", ms=9, mfc="white", mec="k", label=_("case 1: where they meet")),
               Line2D([], [], label=_("case 2: a common normal"), **NORMAL)]
    _on_top(ax)
    fig.legend(handles=handles, loc="lower center", ncols=3, fontsize=12, frameon=False)
    return fig


def paso3_figure(robot=None, length: float = 3.0):
    """Paso 3 (seed 000, figure 14): every frame B_0 … B_n at its origin, y_i = z_i × x_i drawn thick.
    Frames at one point share one label. Returns the figure."""

    robot = robots.ssrms() if robot is None else robot
    fig = new_figure((9.6, 7.0), layout=None)
    ax = _arm_axes(fig, robot, _("Paso 3: $y_i = z_i \\times x_i$ completes each $B_i$"))
    frames = frames_b(robot)
    names = {}
    for i, F in enumerate(frames):
        names.setdefault(tuple(F[:3, 3].round(9)), []).append(i)
    for F in frames:
        triad(ax, F, length, letters=False, lw=2.0)
        ax.plot(*np.array([F[:3, 3], F[:3, 3] + length * F[:3, 1]]).T, color=AXIS_COLORS[1], lw=4.5)
    for point, ids in names.items():                     # beside the origin, away from every axis drawn there
        others = [frames[k][:3, j] for k in ids[1:] for j in range(3)]
        away = free_direction(ax, frames[ids[0]], avoid=others)
        label(ax, np.array(point) + 0.75 * length * away, "$B_{" + ",".join(map(str, ids)) + "}$")
    handles = [Line2D([], [], color=c, lw=w, label=t) for c, w, t in
               ((AXIS_COLORS[0], 2, "$x_i$"), (AXIS_COLORS[1], 4.5, "$y_i = z_i \\times x_i$"),
                (AXIS_COLORS[2], 2, "$z_i$"))]
    _on_top(ax)
    fig.legend(handles=handles, loc="lower center", ncols=3, fontsize=12, frameon=False)
    return fig


# --- each link in its own frame ------------------------------------------------------------------
def link_skeleton(robot, link: int) -> np.ndarray:
    """The skeleton of ``link`` (1 … n) in its own frame B_link, at θ = 0: from the previous origin
    O_(link−1) along z_(link−1) by d, then along x_link by a, to the origin (3 points)."""
    B_prev = np.linalg.inv(np.asarray(robot.A(link, 0.0), dtype=float))    # B_(link-1) seen from B_link
    hang, axis_prev = B_prev[:3, 3], B_prev[:3, 2]
    d = float(robot.links[link - 1].d)
    return np.array([hang, hang + d * axis_prev, np.zeros(3)])


def _link_panel(ax, skeleton, axis_prev, title, triad_length=2.0):
    """One link: the next joint's axis (local z, dashed blue), the axis it hangs on (dashed grey), its
    skeleton (wide grey) and, on top, its local triad with letters. No ticks: the shape is the point."""
    ax.computed_zorder = False                  # draw in this order: the triad on top of the skeleton
    ax.plot([0, 0], [0, 0], [-5, 5], **NEXT_AXIS)
    if skeleton is not None:
        hang = skeleton[0]
        ax.plot(*np.array([hang - 4 * axis_prev, hang + 4 * axis_prev]).T, **PREVIOUS_AXIS)
        ax.plot(*skeleton.T, **SKELETON)
        ax.plot(*hang[:, None], "o", color="0.35", ms=6)
    triad(ax, np.eye(4), triad_length, lw=3)
    points = np.vstack([np.zeros((1, 3)) if skeleton is None else skeleton, [[-3, -3, -3], [3, 3, 3]]])
    centre = (points.min(axis=0) + points.max(axis=0)) / 2
    half = (points.max(axis=0) - points.min(axis=0)).max() / 2 + 1
    ax.set(xlim=(centre[0] - half, centre[0] + half), ylim=(centre[1] - half, centre[1] + half),
           zlim=(centre[2] - half, centre[2] + half), xticks=[], yticks=[], zticks=[])
    ax.set_box_aspect((1, 1, 1), zoom=1.1)
    ax.view_init(elev=20, azim=-55)
    ax.set_title(title, fontsize=13)


def links_figure(robot):
    """Link 0 (the base) … link n of ``robot``, each drawn in its own frame B_i at θ = 0. Returns the figure."""
    fig = new_figure((12, 7.2), layout=None)
    fig.subplots_adjust(left=0.0, right=1.0, bottom=0.09, top=0.94, wspace=0.0, hspace=0.12)
    rows = int(np.ceil((robot.n + 1) / 4))
    _link_panel(fig.add_subplot(rows, 4, 1, projection="3d"), None, None, _("link 0 (base) in $B_0$"))
    for link in range(1, robot.n + 1):
        B_prev = np.linalg.inv(np.asarray(robot.A(link, 0.0), dtype=float))
        name = (_("link {k} in $B_{k}$ (gripper)") if link == robot.n else _("link {k} in $B_{k}$")).format(k=link)
        _link_panel(fig.add_subplot(rows, 4, link + 1, projection="3d"), link_skeleton(robot, link),
                    B_prev[:3, 2], name)
    handles = [Line2D([], [], label=_("the link: d along $z_{i-1}$, then a along $x_i$"), **SKELETON),
               Line2D([], [], label=_("axis of joint $i$ (it turns the link)"), **PREVIOUS_AXIS),
               Line2D([], [], label=_("axis of joint $i+1$: the local $z$"), **NEXT_AXIS)]
    fig.legend(handles=handles, loc="lower center", ncols=3, fontsize=12, frameon=False)
    return fig


# --- erratum 000-1 --------------------------------------------------------------------------------------
def rot_x_figure():
    """y and z before and after Rot_x(−90°), seen from the tip of +x (x points at the reader):
    y turns clockwise onto −z, z onto +y. Returns the figure."""
    R = np.asarray(Rx(deg2rad(-90)), dtype=float)[:3, :3]
    fig = new_figure((5.6, 5.6))
    ax = fig.add_subplot()
    for k, (color, name) in ((1, (AXIS_COLORS[1], "y")), (2, (AXIS_COLORS[2], "z"))):
        before, after = np.eye(3)[k][1:], 0.8 * (R @ np.eye(3)[k])[1:]     # shorter: "y before" shows past "z after"
        ax.annotate("", xy=before, xytext=(0, 0), arrowprops=dict(arrowstyle="-|>", color=color, lw=1.5, alpha=0.4,
                                                                  mutation_scale=16))
        ax.annotate("", xy=after, xytext=(0, 0), arrowprops=dict(arrowstyle="-|>", color=color, lw=3,
                                                                 mutation_scale=18))
        side = np.array([-before[1], before[0]]) * 0.14          # "before" and "after" labels apart
        label(ax, 1.13 * before + side, _("{name} before").format(name=name), color=color, alpha=0.65)
        label(ax, 1.16 * after - np.array([-after[1], after[0]]) * 0.17, _("{name} after").format(name=name),
              color=color)
    arc = np.radians(np.linspace(-5, -82, 30))
    ax.plot(0.55 * np.cos(arc), 0.55 * np.sin(arc), "k", lw=1.2)
    ax.annotate("", xy=(0.55 * np.cos(np.radians(-88)), 0.55 * np.sin(np.radians(-88))),
                xytext=(0.55 * np.cos(arc[-1]), 0.55 * np.sin(arc[-1])),
                arrowprops=dict(arrowstyle="-|>", color="k", mutation_scale=14))
    label(ax, (0.5, -0.5), "−90°", ha="left", va="top")
    ax.plot(0, 0, "o", ms=16, mfc="white", mec=AXIS_COLORS[0], mew=2, zorder=5)   # x, towards the reader: ⊙
    ax.plot(0, 0, ".", ms=8, color=AXIS_COLORS[0], zorder=6)
    label(ax, (-0.1, 0.1), "x (towards you)", color=AXIS_COLORS[0], ha="right", va="bottom")
    ax.set(xlim=(-1.35, 1.35), ylim=(-1.35, 1.35), aspect="equal", xticks=[], yticks=[])
    ax.set_title(_("Rot$_x$(−90°) seen from +x: clockwise"), fontsize=13)
    return fig


# --- the arm built with seed 001's THz ------------------------------------------------------------------
WRONG_COLOR = "tab:red"


def seed001_figure(robot, wrong_frames, camera=(12.0, -78.0)):
    """The SSRMS at zero as seed 000 builds it (the robot's own view, with triads) and the chain of
    frames ``wrong_frames`` (n+1, 4, 4) built with seed 001's THz (red, dashed), both ends marked, in one
    box that holds both; seen nearly from the front (x to the right, z up). Returns the figure."""
    from ...views.view import robot_view  # lazy: the live views load ipywidgets and mplot3d

    wrong = np.asarray(wrong_frames, dtype=float)[:, :3, 3]
    right = np.asarray(robot.frames(robot.qz), dtype=float)[:, :3, 3]
    fig = new_figure((9.6, 6.4), layout=None)
    fig.subplots_adjust(left=0.0, right=0.95, bottom=0.1, top=0.93)
    ax = fig.add_subplot(projection="3d")
    view = robot_view(robot, robot.qz, ax=ax, labels=False)
    view.setup_axes(ax)
    ax.plot(*wrong.T, "--o", color=WRONG_COLOR, lw=2.5, ms=6)
    ax.plot(*wrong[-1:].T, "*", color=WRONG_COLOR, mec="k", ms=18)
    label(ax, wrong[-1] + (1.5, 0, 1.8), _("seed 001: end at ({point})").format(point=_short(wrong[-1])),
          color=WRONG_COLOR, ha="left", fontsize=13)
    label(ax, right[-1] + (-2.0, 0, 0), _("seed 000: end at ({point})").format(point=_short(right[-1])),
          color="0.2", fontsize=13, ha="right")
    fit_box(ax, np.vstack([wrong, right]), pad=2.5)
    ax.set_box_aspect(np.ptp(np.vstack([wrong, right]), axis=0) + 5, zoom=1.1)
    ax.view_init(*camera)
    ax.set_title(_("SSRMS at zero: seed 000's THz reaches out, seed 001's folds up"), fontsize=13)
    handles = [Line2D([], [], color="0.25", lw=3, label=_("with seed 000's THz (correct)")),
               Line2D([], [], color=WRONG_COLOR, lw=2.5, ls="--", marker="o", label=_("with seed 001's THz"))]
    fig.legend(handles=handles, loc="lower center", ncols=2, fontsize=12, frameon=False)
    return fig


def _short(p) -> str:
    return ", ".join(f"{round(float(v), 3) + 0.0:g}" for v in p)
