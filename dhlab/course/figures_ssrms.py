"""The figures of notebook 7 (the SSRMS), drawn by the notebook's own code.

* :func:`links_figure`: each link of the SSRMS in its own frame, as seed 000 designs its pieces;
* :func:`rot_x_figure`: Rot_x(−90°) seen from the tip of +x (erratum 000-1: it is clockwise);
* :func:`seed001_figure`: the arm at zero built with seed 000's THz and with seed 001's faulty one.
"""
from __future__ import annotations

import numpy as np
from matplotlib.lines import Line2D

from ..transforms import Rx
from ..units import deg
from ..views.figures import new_figure
from .figures_common import AXIS_COLORS, fit_box, label, triad

__all__ = ["links_figure", "rot_x_figure", "seed001_figure"]

SKELETON = dict(color="0.62", lw=9, solid_capstyle="round")     # wide and light: the triad stays visible on it
PREVIOUS_AXIS = dict(ls="--", color="0.35", lw=1.5)             # joint i's axis, z_(i-1)
NEXT_AXIS = dict(ls="--", color=AXIS_COLORS[2], lw=1.5)         # joint i+1's axis, the local z


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
    _link_panel(fig.add_subplot(rows, 4, 1, projection="3d"), None, None, "link 0 (base) in $B_0$")
    for link in range(1, robot.n + 1):
        B_prev = np.linalg.inv(np.asarray(robot.A(link, 0.0), dtype=float))
        name = f"link {link} in $B_{link}$" + (" (gripper)" if link == robot.n else "")
        _link_panel(fig.add_subplot(rows, 4, link + 1, projection="3d"), link_skeleton(robot, link),
                    B_prev[:3, 2], name)
    handles = [Line2D([], [], label="the link: d along $z_{i-1}$, then a along $x_i$", **SKELETON),
               Line2D([], [], label="axis of joint $i$ (it turns the link)", **PREVIOUS_AXIS),
               Line2D([], [], label="axis of joint $i+1$: the local $z$", **NEXT_AXIS)]
    fig.legend(handles=handles, loc="lower center", ncols=3, fontsize=12, frameon=False)
    return fig


# --- erratum 000-1 --------------------------------------------------------------------------------------
def rot_x_figure():
    """y and z before and after Rot_x(−90°), seen from the tip of +x (x points at the reader):
    y turns clockwise onto −z, z onto +y. Returns the figure."""
    R = np.asarray(Rx(deg(-90)), dtype=float)[:3, :3]
    fig = new_figure((5.6, 5.6))
    ax = fig.add_subplot()
    for k, (color, name) in ((1, (AXIS_COLORS[1], "y")), (2, (AXIS_COLORS[2], "z"))):
        before, after = np.eye(3)[k][1:], 0.8 * (R @ np.eye(3)[k])[1:]     # shorter: "y before" shows past "z after"
        ax.annotate("", xy=before, xytext=(0, 0), arrowprops=dict(arrowstyle="-|>", color=color, lw=1.5, alpha=0.4,
                                                                  mutation_scale=16))
        ax.annotate("", xy=after, xytext=(0, 0), arrowprops=dict(arrowstyle="-|>", color=color, lw=3,
                                                                 mutation_scale=18))
        side = np.array([-before[1], before[0]]) * 0.14          # "before" and "after" labels apart
        label(ax, 1.13 * before + side, f"{name} before", color=color, alpha=0.65)
        label(ax, 1.16 * after - np.array([-after[1], after[0]]) * 0.17, f"{name} after", color=color)
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
    ax.set_title("Rot$_x$(−90°) seen from +x: clockwise", fontsize=13)
    return fig


# --- the arm built with seed 001's THz ------------------------------------------------------------------
WRONG_COLOR = "tab:red"


def seed001_figure(robot, wrong_frames, camera=(12.0, -78.0)):
    """The SSRMS at zero as seed 000 builds it (the robot's own view, with triads) and the chain of
    frames ``wrong_frames`` (n+1, 4, 4) built with seed 001's THz (red, dashed), both ends marked, in one
    box that holds both; seen nearly from the front (x to the right, z up). Returns the figure."""
    from ..views.view import robot_view

    wrong = np.asarray(wrong_frames, dtype=float)[:, :3, 3]
    right = np.asarray(robot.frames(robot.qz), dtype=float)[:, :3, 3]
    fig = new_figure((9.6, 6.4), layout=None)
    fig.subplots_adjust(left=0.0, right=0.95, bottom=0.1, top=0.93)
    ax = fig.add_subplot(projection="3d")
    view = robot_view(robot, robot.qz, ax=ax, labels=False)
    view.setup_axes(ax)
    ax.plot(*wrong.T, "--o", color=WRONG_COLOR, lw=2.5, ms=6)
    ax.plot(*wrong[-1:].T, "*", color=WRONG_COLOR, mec="k", ms=18)
    label(ax, wrong[-1] + (1.5, 0, 1.8), f"seed 001: end at ({_short(wrong[-1])})", color=WRONG_COLOR,
          ha="left", fontsize=13)
    label(ax, right[-1] + (-2.0, 0, 0), f"seed 000: end at ({_short(right[-1])})", color="0.2", fontsize=13,
          ha="right")
    fit_box(ax, np.vstack([wrong, right]), pad=2.5)
    ax.set_box_aspect(np.ptp(np.vstack([wrong, right]), axis=0) + 5, zoom=1.1)
    ax.view_init(*camera)
    ax.set_title("SSRMS at zero: seed 000's THz reaches out, seed 001's folds up", fontsize=13)
    handles = [Line2D([], [], color="0.25", lw=3, label="with seed 000's THz (correct)"),
               Line2D([], [], color=WRONG_COLOR, lw=2.5, ls="--", marker="o", label="with seed 001's THz")]
    fig.legend(handles=handles, loc="lower center", ncols=2, fontsize=12, frameon=False)
    return fig


def _short(p) -> str:
    return ", ".join(f"{round(float(v), 3) + 0.0:g}" for v in p)
