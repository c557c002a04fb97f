"""What the student sees of an assignment robot: its picture and its tables.

:func:`axes_figure` draws the robot at its pictured home pose: the links with their
labelled points, every joint axis (dashed) with the arrow of its positive sense (a
curled arrow for a revolute joint, right-hand rule; a double arrowhead for a sliding
one), the world frame 0 and the plate it is mounted on. No DH frames: placing them
is the exercise. :func:`axes_table` and :func:`points_table` give the same numbers.
"""
from __future__ import annotations

import html

import numpy as np

from ..grading.variants import shown_name
from ..i18n import _

__all__ = ["axes_figure", "axes_table", "points_table", "Table"]


class Table:
    """A small table shown as HTML in Jupyter and as aligned text elsewhere; ``rows`` are
    tuples of strings (what the student reads)."""

    def __init__(self, title, header, rows):
        self.title, self.header, self.rows = title, tuple(header), [tuple(r) for r in rows]

    def __repr__(self):
        table = [self.header, *self.rows]
        widths = [max(len(str(r[c])) for r in table) for c in range(len(self.header))]
        return "\n".join([self.title] + [" | ".join(str(v).ljust(w) for v, w in zip(r, widths)).rstrip()
                                         for r in table])

    def _repr_html_(self):
        head = "".join(f"<th>{html.escape(str(h))}</th>" for h in self.header)
        body = "".join("<tr>" + "".join(f"<td>{html.escape(str(v))}</td>" for v in r) + "</tr>"
                       for r in self.rows)
        return (f"<div><b>{html.escape(self.title)}</b><table><thead><tr>{head}</tr></thead>"
                f"<tbody>{body}</tbody></table></div>")


def _xyz(v) -> str:
    return "(" + ", ".join(f"{round(float(x), 6) + 0.0:.6g}" for x in np.asarray(v, float)) + ")"


def _anchors(robot) -> list:
    """For each joint axis, a named link point on it, the one nearest the axis's own point
    (None when no link point lies on the axis)."""
    out = []
    for axis in robot.axes:
        on = [(float(np.linalg.norm(p - axis.point)), name, p) for link in robot.points for name, p in link
              if axis.distance_to_point(p) < 1e-9]
        out.append(min(on, key=lambda t: t[0])[1:] if on else (None, axis.point))
    return out


def axes_table(robot) -> Table:
    """The joint axes at the home pose, in the world frame 0: a point on each axis and the
    direction of its drawn arrow (positive q_i: right-hand rule, or the sliding sense)."""
    rows = []
    for i, (axis, kind, (name, p)) in enumerate(zip(robot.axes, robot.kinds, _anchors(robot)), start=1):
        where = f"{name} = {_xyz(p)}" if name else _xyz(p)
        rows.append((_("joint {i}").format(i=i), _("revolute") if kind == "R" else _("prismatic"), where,
                     _xyz(axis.direction)))
    rows.append((_("end effector"), "", f"{_end_name(robot)} = {_xyz(robot.end_point)}", ""))
    return Table(_("{robot}: joint axes at the home pose (world frame 0, metres)").format(robot=shown_name(robot.name)),
                 (_("joint"), _("kind"), _("passes through"), _("positive direction")), rows)


def _end_name(robot) -> str:
    for link in reversed(robot.points):
        for name, p in link:
            if np.linalg.norm(p - robot.end_point) < 1e-9:
                return name
    return "E"


def points_table(robot) -> Table:
    """The points that draw each link, in the world frame at the home pose (metres)."""
    rows = [(f"{k} ({_(robot.link_names[k])})", name, _xyz(p))
            for k, link in enumerate(robot.points) for name, p in link]
    return Table(_("{robot}: link points at the home pose (world frame 0, metres): give them, in this "
                   "order, in each link's own DH frame").format(robot=shown_name(robot.name)),
                 (_("link"), _("point"), _("world (x, y, z)")), rows)


# --- the picture ----------------------------------------------------------------------------------

def _new_figure(figsize):
    try:
        from ..views.figures import new_figure
        return new_figure(figsize, layout=None)
    except ImportError:                      # before the course figures exist: a plain Agg figure
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure
        fig = Figure(figsize=figsize)
        FigureCanvasAgg(fig)
        return fig


def _arc(centre, w, radius, start):
    u = start - (start @ w) * w
    if np.linalg.norm(u) < 1e-6:
        u = np.cross(w, [0.3, 0.5, 0.8])
    u = u / np.linalg.norm(u)
    v = np.cross(w, u)
    t = np.radians(np.linspace(0, 300, 40))
    return centre + radius * (np.outer(np.cos(t), u) + np.outer(np.sin(t), v))


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


def _box(robot):
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
    lo, hi, span = _box(robot)
    wrist = _wrist(robot, span)
    fig = _new_figure(figsize or ((13, 7) if wrist else (9, 8)))
    ax = fig.add_subplot(1, 2 if wrist else 1, 1, projection="3d")
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
        close = fig.add_subplot(1, 2, 2, projection="3d")
        _draw(close, robot, links, joints, 0.9 * half, 2 * half, set(), near=robot.end_point)
        _cube(close, robot.end_point - half, robot.end_point + half, elev, azim)
        close.set_title(_("the wrist: axes J{first}…J{n}").format(first=joints[0] + 1, n=robot.n), fontsize=10)
    fig.suptitle(_("{robot}: joint axes J1…J{n} and their positive senses (right-hand rule)").format(
        robot=shown_name(robot.name), n=robot.n), fontsize=11)
    fig.legend(*ax.get_legend_handles_labels(), loc="lower center", ncol=4 if not wrist else 7, fontsize=8,
               frameon=False)
    fig.subplots_adjust(left=0.02, right=0.97, bottom=0.1, top=0.9, wspace=0.05)
    return fig
