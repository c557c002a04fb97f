"""The assignment's pictures: the robot to work on, and the student's robot assembled.

* :func:`axes_figure` draws a robot of the family (:class:`~dhlab.assignment.model.AssignmentRobot`)
  at its pictured home pose: the links with their labelled points, every joint axis (dashed)
  with the arrow of its positive sense (a curled arrow for a revolute joint, right-hand rule;
  a double arrowhead for a sliding one), the world frame 0 and the plate it is mounted on;
* :func:`puma_picture` draws the PUMA 560 of the seed (:func:`dhlab.assignment.reference.reference`),
  whole and its wrist;
* :func:`assembled_figure` draws the student's links placed by the student's frames over the
  robot of the assignment in grey, at the home pose and at a test pose;
* :class:`Note` stands in for a figure that cannot be drawn yet, with the reason.

No DH frames are drawn on the robot to work on: placing them is the exercise. What the
notebook calls (``puma_figure()``, ``my_robot_figure(globals())``, ``teach(globals())``) picks
the robot and reads the answers, then draws here: :mod:`dhlab.assignment.notebook` and
:mod:`dhlab.assignment.student_robot`. Everything here takes the robot it draws as an argument.
matplotlib is imported when a figure is made, never at import.
"""
from __future__ import annotations

import html
import math

import numpy as np

from ..i18n import _
from .family import shown_name

__all__ = ["axes_figure", "puma_picture", "assembled_figure", "link_lines", "box", "Note", "PUMA_BOX"]

PUMA_BOX = ((-0.35, -0.45, -0.7), (0.65, 0.25, 0.6))     # the PUMA's figures: the box its reach needs


class Note:
    """A short message shown in place of a figure or a panel that cannot be made yet."""

    def __init__(self, text: str):
        self.text = text

    def __repr__(self):
        return self.text

    def _repr_html_(self):
        return f'<div style="color:#8a5300"><b>{html.escape(self.text)}</b></div>'


def _new_axes(figsize=(7.5, 6.5), ncols: int = 1):
    """A course figure (a picture on a first Run All, inline or with ipympl) with 3D axes."""
    from ..views.figures import new_figure  # lazy: the views (matplotlib) on first picture

    fig = new_figure(figsize=figsize, layout=None)       # the layout is set by hand (3D axes)
    axes = [fig.add_subplot(1, ncols, c + 1, projection="3d") for c in range(ncols)]
    return fig, axes


def _arc(centre, w, radius, start):
    """Points of a 300° arc around direction ``w`` at ``centre``, turning by the right-hand rule."""
    u = start - (start @ w) * w
    if np.linalg.norm(u) < 1e-6:
        u = np.cross(w, [0.3, 0.5, 0.8])
    u = u / np.linalg.norm(u)
    v = np.cross(w, u)
    t = np.radians(np.linspace(0, 300, 40))
    return centre + radius * (np.outer(np.cos(t), u) + np.outer(np.sin(t), v))


# --- the PUMA 560 of the seed ------------------------------------------------------------------

def _square(ax, lo=PUMA_BOX[0], hi=PUMA_BOX[1]):
    ax.set(xlim=(lo[0], hi[0]), ylim=(lo[1], hi[1]), zlim=(lo[2], hi[2]),
           xlabel="$x_0$ [m]", ylabel="$y_0$ [m]", zlabel="$z_0$ [m]")
    ax.set_box_aspect(np.array(hi) - np.array(lo))
    ax.view_init(elev=18, azim=-65)
    from matplotlib.ticker import MaxNLocator  # lazy: matplotlib on first picture
    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):          # a few ticks: no labels piled up
        axis.set_major_locator(MaxNLocator(4))


def _draw_links(ax, ref, links, label_points, fontsize=10):
    """The links ``links``, their points labelled for the links in ``label_points`` (True: all)."""
    seen = set()
    for k in links:
        P = ref.world_points(k)
        ax.plot(*P.T, "-o", color=f"C{k}", lw=4, ms=4,
                label=_("link {k}: {name}").format(k=k, name=_(ref.link_names[k])))
        labelled = label_points is True or k in (label_points or ())
        for name, p in ref.points[k]:
            if labelled and name not in seen:
                seen.add(name)
                ax.text(*(p + np.array([0.006, 0.0, 0.006])), name, fontsize=fontsize, color="0.15")


def _draw_puma_axis(ax, ref, i: int, anchor, size: float):
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


def puma_picture(ref):
    """The PUMA 560 ``ref`` at its home pose: whole (left) and its wrist (right), the links,
    the labelled points, each joint axis (dashed) with its positive direction (arrow) and
    positive sense of turning (curled arrow, right-hand rule), and the world frame 0 at the
    shoulder."""
    fig, (whole, wrist) = _new_axes(figsize=(12, 6.2), ncols=2)
    points = {name: p for link in ref.points for name, p in link}
    _draw_links(whole, ref, range(ref.n + 1), label_points=range(4))   # the wrist's points: on the right
    for i, anchor in zip((1, 2, 3, 4), ("B", "A", "E", "K")):
        _draw_puma_axis(whole, ref, i, points[anchor], 0.25)
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
        _draw_puma_axis(wrist, ref, i, points[anchor], 0.09)
    W = ref.wrist_centre
    _square(wrist, lo=W - np.array([0.1, 0.12, 0.13]), hi=W + np.array([0.1, 0.08, 0.15]))
    wrist.set_title(_("the wrist: axes 4, 5, 6 meet at W"), fontsize=10)
    fig.legend(*whole.get_legend_handles_labels(), loc="lower center", ncol=4, fontsize=10, frameon=False)
    fig.suptitle(_("PUMA 560: joint axes J1…J6, their positive directions and senses (right-hand rule)"))
    fig.subplots_adjust(left=0.0, right=0.97, bottom=0.11, top=0.92, wspace=0.05)
    return fig


# --- any robot of the family -------------------------------------------------------------------

def _centres(robot, joints, size, near=None) -> dict:
    """Where each joint's axis is drawn: its point (nearest to ``near``), moved along its line,
    past the earlier one, when two joints share a line (a SCARA's quill and its tool: J3 and J4),
    so their arrows and labels do not lie on top of each other."""
    out = {}
    for i in joints:
        axis = robot.axes[i]
        c = axis.point if near is None else axis.nearest_point(near)
        for j, cj in out.items():
            w, wj = axis.direction, robot.axes[j].direction
            if abs(float(w @ wj)) < 0.999 or np.linalg.norm(np.cross(c - cj, wj)) > 0.05 * size:
                continue                                 # not the same line
            # along this axis, in sizes: each drawing runs from 0.45 behind its centre to its label 1.07 ahead
            u = float((cj - c) @ w) / size
            lo, hi = (u - 0.45, u + 1.07) if float(w @ wj) > 0 else (u - 1.07, u + 0.45)
            if lo < 1.07 and hi > -0.45:                 # the two drawings overlap: start past the other's
                c = c + (hi + 0.55) * size * w
        out[i] = c
    return out


def _draw_axis(ax, robot, i, size, near=None, centre=None):
    axis, kind = robot.axes[i], robot.kinds[i]
    w = axis.direction
    c = centre if centre is not None else axis.point if near is None else axis.nearest_point(near)
    a, b = c - 0.45 * size * w, c + 0.75 * size * w
    ax.plot(*np.array([a, b]).T, "--", color="0.1", lw=1.2)
    ax.quiver(*b, *(0.25 * size * w), color="0.1", arrow_length_ratio=0.45, lw=1.6)
    if kind == "R":
        arc = _arc(c + 0.55 * size * w, w, 0.13 * size, np.array([1.0, 0.35, 0.25]))
        ax.plot(*arc.T, "-", color="purple", lw=1.5)
        ax.quiver(*arc[-2], *((arc[-1] - arc[-2]) * 5), color="purple", arrow_length_ratio=1.0, lw=1.5)
    else:
        ax.quiver(*(b - 0.1 * size * w), *(0.3 * size * w), color="purple", arrow_length_ratio=0.5, lw=2.5)
    ax.text(*(b + 0.32 * size * w), f"J{i + 1}", fontsize=11, color="purple", weight="bold")


def box(robot):
    """The cube a figure of ``robot`` shows: (low corner, high corner, span of its points)."""
    pts = np.vstack([robot.world_points(k) for k in range(robot.n + 1)] + [np.zeros((1, 3))])
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    span = max(float((hi - lo).max()), 0.3)
    centre = (lo + hi) / 2
    half = np.full(3, 0.62 * span)               # a cube: lengths look the same along every axis
    return centre - half, centre + half, span


def _draw(ax, robot, links, joints, size, span, labelled, near=None):
    """Links ``links`` with their labelled points, and the axes of ``joints`` (indices)."""
    for k in links:
        P = robot.world_points(k)
        name = _(robot.link_names[k]) if k < len(robot.link_names) else _("link {k}").format(k=k)
        if k == robot.n:                                # the gripper: flange path, then the fingers
            body, fingers = P[:-4], P[-4:]
            if len(body):
                ax.plot(*np.vstack([body, fingers[[1, 2]].mean(axis=0)]).T, "-o", color=f"C{k}", lw=4, ms=4,
                        label=_("link {k}: {name}").format(k=k, name=name))
            ax.plot(*fingers.T, "-", color=f"C{k}", lw=3)
        else:
            ax.plot(*P.T, "-o", color=f"C{k}", lw=4, ms=4, label=_("link {k}: {name}").format(k=k, name=name))
        for label, p in robot.points[k]:
            if label not in labelled:
                labelled.add(label)
                ax.text(*(p + 0.012 * span), label, fontsize=8, color="0.15")
    centres = _centres(robot, joints, size, near)
    for i in joints:
        _draw_axis(ax, robot, i, size, near, centres[i])


def _cube(ax, lo, hi, elev, azim):
    ax.set(xlim=(lo[0], hi[0]), ylim=(lo[1], hi[1]), zlim=(lo[2], hi[2]),
           xlabel="$x_0$ [m]", ylabel="$y_0$ [m]", zlabel="$z_0$ [m]")
    ax.set_box_aspect(hi - lo)
    ax.view_init(elev=elev, azim=azim)


def _wrist(robot, span):
    """The last three joints when they sit close together (a wrist): their indices and the
    half-size of a close-up around the end point, else None."""
    if robot.n < 5:
        return None
    joints = list(range(robot.n - 3, robot.n))
    links = [robot.n - 1, robot.n]
    pts = np.vstack([robot.world_points(k) for k in links])
    reach = float(np.linalg.norm(pts - robot.end_point, axis=1).max())
    return (links, joints, max(1.4 * reach, 0.08)) if reach < 0.2 * span else None


def axes_figure(robot, elev: float = 22, azim: float = -58, figsize=None):
    """The robot at its home pose: links, labelled points, joint axes with their positive
    senses, the world frame 0 and the mounting plate; beside it a close-up of the wrist when
    the last joints sit close together. Returns a figure (shown as a picture)."""
    lo, hi, span = box(robot)
    wrist = _wrist(robot, span)
    fig, axs = _new_axes(figsize or ((13, 7) if wrist else (9, 8)), ncols=2 if wrist else 1)
    ax = axs[0]
    size = 0.22 * span
    plate = robot.world_points(0)[0]
    sq = 0.18 * span * np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0], [-1, -1, 0]])
    ax.plot(*(plate + sq).T, "-", color="0.55", lw=1)
    if np.linalg.norm(plate) > 1e-9:                     # what holds the plate: a pedestal, a ceiling
        ax.plot(*np.array([np.zeros(3), plate]).T, ":", color="0.55", lw=1)
    mount = robot.mount["mount"]                      # "floor" or "ceiling": marked N_ in family.py
    ax.text(*(plate + sq[1]), _(mount), fontsize=8, color="0.4")
    _draw(ax, robot, range(robot.n + 1), range(robot.n), size, span, set())
    for j, color in enumerate(("tab:red", "tab:green", "tab:blue")):
        e = np.eye(3)[j] * 0.14 * span
        ax.quiver(0, 0, 0, *e, color=color, lw=2.5, arrow_length_ratio=0.3)
        ax.text(*(1.15 * e), f"${'xyz'[j]}_0$", color=color, fontsize=11)
    _cube(ax, lo, hi, elev, azim)
    ax.set_title(_("home pose (q = 0), world frame 0"), fontsize=10)
    if wrist:
        links, joints, half = wrist
        close = axs[1]
        _draw(close, robot, links, joints, 0.9 * half, 2 * half, set(), near=robot.end_point)
        _cube(close, robot.end_point - half, robot.end_point + half, elev, azim)
        close.set_title(_("the wrist: axes J{first}…J{n}").format(first=joints[0] + 1, n=robot.n), fontsize=10)
    fig.suptitle(_("{robot}: joint axes J1…J{n} and their positive senses (right-hand rule)").format(
        robot=shown_name(robot.name), n=robot.n), fontsize=11)
    fig.legend(*ax.get_legend_handles_labels(), loc="lower center", ncol=4 if not wrist else 7, fontsize=8,
               frameon=False)
    fig.subplots_adjust(left=0.02, right=0.97, bottom=0.1, top=0.9, wspace=0.05)
    return fig


# --- the student's robot, assembled from their answers ---------------------------------------------

def link_lines(frames, points) -> np.ndarray:
    """Link points placed by frames: one polyline per link k (``points[k]``, in frame k), NaN rows between."""
    chunks = []
    for k, P in enumerate(points):
        if k < len(frames) and isinstance(P, list) and P:
            P = np.array(P, float)
            chunks += [P @ frames[k][:3, :3].T + frames[k][:3, 3], np.full((1, 3), np.nan)]
    return np.vstack(chunks) if chunks else np.zeros((0, 3))


def _pose_text(q, kinds) -> str:
    """'(30, 20, -40)°', or with each unit when a joint slides: '(30°, 20°, 0.05 m, 0°)'."""
    values = [round(math.degrees(v), 9) if kind == "R" else round(float(v), 9) for v, kind in zip(q, kinds)]
    if "P" not in kinds:
        return "(" + ", ".join(f"{v + 0.0:.5g}" for v in values) + ")°"
    return "(" + ", ".join(f"{v + 0.0:.5g}{'°' if kind == 'R' else ' m'}" for v, kind in zip(values, kinds)) + ")"


def assembled_figure(robot, points, ref, q, limits):
    """``points`` (the student's part 2: per link, its points in its own frame) placed by
    ``robot`` (a :class:`dhlab.Robot` built from the student's T1…Tn), over the robot of the
    assignment ``ref`` in grey, at the home pose and at ``q``; ``limits``: the (low, high)
    corners of the box shown."""
    fig, axs = _new_axes(figsize=(11, 5.5), ncols=2)
    lo, hi = limits
    for ax, pose, title in zip(axs, (np.zeros(ref.n), q), (_("home pose"), "q = " + _pose_text(q, ref.kinds))):
        R = ref.frames(pose[None])[0]
        ghost = link_lines(R, [ref.local_points(k).tolist() for k in range(ref.n + 1)])
        ax.plot(*ghost.T, "-", color="0.75", lw=6, label=_("the {robot}").format(robot=shown_name(ref.name)))
        F = robot.frames(pose)
        mine = link_lines(F, points)
        if len(mine):
            ax.plot(*mine.T, "-o", color="C3", lw=2, ms=3,
                    label=_("your links, assembled by your T1…T{n}").format(n=ref.n))
        ax.plot(*F[:, :3, 3].T, ":", color="C0", lw=1, label=_("your frame origins"))
        _square(ax, lo, hi)
        ax.set_title(title)
    fig.legend(*axs[0].get_legend_handles_labels(), loc="lower center", ncol=3, fontsize=9, frameon=False)
    fig.subplots_adjust(left=0.0, right=0.97, bottom=0.1, top=0.93, wspace=0.05)
    return fig
