"""The figures of notebook 5 (the Denavit–Hartenberg convention), drawn by the notebook's own code.

* :func:`cases_figure`: the three cases of x_i (z_(i−1) and z_i intersect, are parallel, are skew);
* :func:`dh_parameters_figure`: the four DH parameters θ_i, d_i, a_i, α_i measured between
  {S_(i−1)} and {S_i}, labelled as in the textbooks' figure (Spong, Craig);
* :func:`exercise_axes_figure`: the joint axes of exercise 5.1, drawn so that nothing looks like an
  intersection that is not one; :func:`common_normals_figure` shows, after the answer, each
  consecutive pair's common normal and a view along y where skew and parallel axes are plain;
* :func:`row_frames_figure`: the two frames of exercise 5.2.
"""
from __future__ import annotations

import numpy as np

from ...i18n import _
from ...lines import Line, relation
from ...views.figures import new_figure
from .figures_common import AXIS_COLORS, fit_box, label, triad

__all__ = ["cases_figure", "dh_parameters_figure", "exercise_axes_figure", "common_normals_figure",
           "common_normals_after", "row_frames_figure"]

NORMAL_COLOR = "black"          # common normals and dimensions: black, as in the textbooks


def _segment(ax, p, q, **style):
    return ax.plot(*np.array([p, q], dtype=float).T, **style)[0]


def _no_ticks(ax):
    ax.set(xticks=[], yticks=[], zticks=[])


# --- the three cases of x_i ---------------------------------------------------------------------
def cases_figure(z_prev, examples):
    """One 3D panel per case: ``z_prev`` = (point, direction) of z_(i−1); ``examples`` =
    {name: (point, direction) of z_i}. Draws z_(i−1) (solid blue), z_i (dashed blue), the common
    normal (black) with its length, x_i (red arrow) and O_i (black dot), all labelled."""
    fig = new_figure((11, 4.0), layout=None)          # 4.0 in tall: with its table, one 1080 p slide
    fig.subplots_adjust(left=0.0, right=1.0, bottom=0.0, top=0.9, wspace=0.0)
    a = Line(*z_prev)
    for k, (name, (p, u)) in enumerate(examples.items(), start=1):
        ax = fig.add_subplot(1, len(examples), k, projection="3d")
        b = Line(p, u)
        rel = relation(a, b)
        O = rel.foot                                   # where x_i meets z_i: the origin O_i
        H = a.nearest_point(O)                         # the other end of the normal, on z_(i-1)
        for line, style, name_i, top in ((a, "-", "$z_{i-1}$", 1.75), (b, "--", "$z_i$", 1.1)):
            _segment(ax, line.point - 1.1 * line.direction, line.point + top * line.direction,
                     ls=style, color=AXIS_COLORS[2], lw=2.2)
            label(ax, line.point + (top + 0.22) * line.direction, name_i, color=AXIS_COLORS[2])
        x = np.cross(a.direction, b.direction) if rel.kind == "intersect" else rel.normal
        _segment(ax, H, O, color=NORMAL_COLOR, lw=2.5)
        _segment(ax, O, O + 0.65 * x, color=AXIS_COLORS[0], lw=2.8)
        label(ax, O + 0.85 * x, "$x_i$", color=AXIS_COLORS[0])
        ax.plot(*O[:, None], "o", color="black", ms=7)
        label(ax, O + (0.1, 0.0, -0.25), "$O_i$")
        note = (_("normal of length 0") if rel.kind == "intersect" else
                _("common normal, length {length:g}").format(length=rel.distance))
        ax.text2D(0.5, 0.02, note, transform=ax.transAxes, ha="center", fontsize=12)
        ax.set(xlim=(-1, 1.5), ylim=(-1.2, 1.2), zlim=(-0.6, 2.1))
        ax.set_title(f"{_(name)}: {_(rel.kind)}", fontsize=14)    # a case named by N_ is translated
        _no_ticks(ax)
        ax.set_box_aspect((2.5, 2.4, 2.7), zoom=1.05)
        ax.view_init(elev=18, azim=-62)
    return fig


# --- the four parameters, textbook style ------------------------------------------------------------
def _arc(ax, centre, start, end, normal, radius, text, text_at=1.45, n=40):
    """An arc (with an arrowhead) from direction ``start`` to ``end`` about ``normal``, and its label."""
    start = start / np.linalg.norm(start)
    other = np.cross(normal, start)
    angle = np.arctan2(end @ other, end @ start)
    t = np.linspace(0, angle, n)
    P = centre + radius * (np.cos(t)[:, None] * start + np.sin(t)[:, None] * other)
    ax.plot(*P.T, color=NORMAL_COLOR, lw=1.6)
    ax.quiver(*P[-4], *(P[-1] - P[-4]), color=NORMAL_COLOR, arrow_length_ratio=2.5, lw=1.6)
    middle = centre + text_at * radius * (np.cos(angle / 2) * start + np.sin(angle / 2) * other)
    label(ax, middle, text, fontsize=15)


def _dimension(ax, p, q, offset, text, text_shift=(0, 0, 0)):
    """A length from ``p`` to ``q`` drawn beside them (moved by ``offset``), arrows at both ends."""
    p, q, offset = (np.asarray(v, dtype=float) for v in (p, q, offset))
    for a, b in ((p, q), (q, p)):
        ax.quiver(*(a + offset), *(0.5 * (b - a)), color=NORMAL_COLOR, lw=1.3, arrow_length_ratio=0)
        ax.quiver(*((a + b) / 2 + offset), *(0.5 * (b - a)), color=NORMAL_COLOR, lw=1.3,
                  arrow_length_ratio=0.12 / (0.5 * np.linalg.norm(b - a)))
    for end in (p, q):                                       # the extension lines
        _segment(ax, end, end + 1.25 * offset, color="0.5", lw=0.8)
    label(ax, (p + q) / 2 + 1.9 * offset + np.asarray(text_shift), text, fontsize=15)


def dh_parameters_figure(theta_deg: float = 50.0, d: float = 1.2, a: float = 1.2, alpha_deg: float = 55.0,
                         camera=(20.0, -60.0)):
    """The four DH parameters between {S_(i−1)} and {S_i} (Spong's and Craig's figure): θ_i about
    z_(i−1) from x_(i−1) to x_i; d_i along z_(i−1) from O_(i−1) to H_i, where x_i crosses z_(i−1);
    a_i along x_i from H_i to O_i; α_i about x_i from z_(i−1) to z_i. Returns the figure."""
    th, al = np.radians(theta_deg), np.radians(alpha_deg)
    x_i = np.array([np.cos(th), np.sin(th), 0.0])
    z_i = np.array([np.sin(al) * np.sin(th), -np.sin(al) * np.cos(th), np.cos(al)])
    H, O_i = np.array([0, 0, d]), np.array([0, 0, d]) + a * x_i
    S_prev, S_i = np.eye(4), np.eye(4)
    S_i[:3, :3] = np.column_stack([x_i, np.cross(z_i, x_i), z_i])
    S_i[:3, 3] = O_i

    fig = new_figure((8, 7), layout=None)
    fig.subplots_adjust(left=0.0, right=1.0, bottom=0.0, top=0.95)
    ax = fig.add_subplot(projection="3d")
    z = np.array([0, 0, 1.0])
    _segment(ax, -0.35 * z, 2.0 * z, color=AXIS_COLORS[2], lw=1.2, ls=(0, (6, 3)))    # the line of z_(i-1)
    _segment(ax, O_i - 0.5 * z_i, O_i + 1.15 * z_i, color=AXIS_COLORS[2], lw=1.2, ls=(0, (6, 3)))
    triad(ax, S_prev, 0.55, sub="i-1", lw=2.8)
    triad(ax, S_i, 0.55, sub="i", lw=2.8)
    _segment(ax, H, O_i, color=AXIS_COLORS[0], lw=1.4, ls=(0, (2, 2)))                 # x_i's line, back to H
    for point, text, shift in ((np.zeros(3), "$O_{i-1}$", (0.0, 0.1, -0.2)), (O_i, "$O_i$", (0.14, 0.05, -0.16)),
                               (H, "$H_i$", (-0.05, 0.18, 0.02))):
        ax.plot(*point[:, None], "o", color="black", ms=6)
        label(ax, point + np.array(shift), text)
    _segment(ax, H, H + 0.95 * np.array([1, 0, 0]), color="0.45", lw=1.2, ls=":")      # x_(i-1), moved to H
    _arc(ax, H, np.array([1.0, 0, 0]), x_i, z, 0.6, r"$\theta_i$", text_at=1.4)
    _segment(ax, O_i, O_i + 0.75 * z, color="0.45", lw=1.2, ls=":")                     # z_(i-1), moved to O_i
    _arc(ax, O_i, z, z_i, x_i, 0.5, r"$\alpha_i$", text_at=1.35)
    _dimension(ax, np.zeros(3), H, (-0.0, -0.2, 0.0), "$d_i$", text_shift=(0, -0.05, 0))
    _dimension(ax, H, O_i, (0, 0, 0.22), "$a_i$")                  # above x_i: the θ arc is below
    label(ax, (0.0, 0.0, 2.15), "joint $i$", color="0.3", fontsize=12)
    label(ax, O_i + 1.3 * z_i, "joint $i+1$", color="0.3", fontsize=12, ha="left")
    points = np.array([-0.35 * z, 2.2 * z, O_i + 1.3 * z_i, O_i - 0.7 * z_i, H + (0, -0.4, 0), (0.7, 0.3, 0)])
    fit_box(ax, points, pad=0.15)
    ax.set_box_aspect(np.ptp(points, axis=0) + 0.3, zoom=1.45)
    _no_ticks(ax)
    ax.set_axis_off()
    ax.view_init(*camera)
    ax.set_title(_("the four DH parameters of link $i$"), fontsize=14)
    return fig


# --- exercise 5.1: the joint axes, and after the answer their common normals --------------------------
# z_1 passes beside z_0, not across it (tests/course/test_course_figures.py)
_EXERCISE_CAMERA = dict(elev=22, azim=-74)


def _name_at(p, u, length):
    """Where an axis's name goes: just past its arrow, lifted off the line when the line is not vertical."""
    lift = np.array([0.0, 0.0, 0.0 if abs(u[2]) > 0.9 else 0.07])
    return p + 1.5 * length * u + lift


def _draw_axes(ax, axes, length, tool):
    """Joint axes as dotted lines with an arrow (positive sense) and the label z_(k−1) at the tip."""
    for k, (p, u, _kind) in enumerate(axes):
        p, u = np.asarray(p, float), np.asarray(u, float) / np.linalg.norm(u)
        _segment(ax, p - 1.2 * length * u, p + 2.0 * length * u, ls=":", color="0.45", lw=1.6)
        ax.quiver(*p, *(length * u), color=AXIS_COLORS[2], arrow_length_ratio=0.3, lw=2.5)
        ax.plot(*p[:, None], "o", color=AXIS_COLORS[2], ms=5)
        label(ax, _name_at(p, u, length), f"$z_{k}$", color=AXIS_COLORS[2], fontsize=15)
    if tool is not None:
        tool = np.asarray(tool, float)
        tool = tool[:3, 3] if tool.shape == (4, 4) else tool
        ax.plot(*tool[:, None], "*", color="darkorange", mec="k", ms=16)


def _axes_box(ax, axes, tool, length):
    points = [np.asarray(p, float) + s * np.asarray(u, float) / np.linalg.norm(u)
              for p, u, _kind in axes for s in (-1.2 * length, 2.3 * length)]
    if tool is not None:
        tool = np.asarray(tool, float)
        points.append(tool[:3, 3] if tool.shape == (4, 4) else tool)
    fit_box(ax, np.array(points), pad=0.05)
    ax.set(xlabel="x [m]", ylabel="y [m]", zlabel="z [m]")
    ax.locator_params(nbins=4)
    for axis, pad in ((ax.xaxis, 10), (ax.yaxis, 10), (ax.zaxis, 15)):
        axis.labelpad = pad                          # clear of the tick labels
    ax.set_box_aspect(np.ptp(np.array(points), axis=0) + 0.1, zoom=0.88)      # room for the axis labels


def exercise_axes_figure(axes, tool=None, length: float = 0.22, title: str | None = None):
    """Exercise 5.1's picture: each joint axis ``(point, direction, kind)`` as a dotted line with an arrow
    (the positive sense), labelled z_0, z_1, … (joint k's axis is z_(k−1)), and the end effector (star).
    The camera is chosen so that no two axes look as if they met unless they do. Returns the figure."""
    fig = new_figure((6.4, 6.0), layout=None)
    fig.subplots_adjust(left=0.02, right=0.9, bottom=0.08, top=0.92)
    ax = fig.add_subplot(projection="3d")
    _draw_axes(ax, axes, length, tool)
    _axes_box(ax, axes, tool, length)
    ax.view_init(**_EXERCISE_CAMERA)
    ax.set_title(_("the 4-axis arm at q = 0: joint axes") if title is None else title, fontsize=13)
    return fig


def common_normals_figure(axes, tool=None, length: float = 0.22):
    """After exercise 5.1 is answered: left, the same axes with the common normal of each consecutive
    pair and its length; right, the view along y, where an axis along y is a point. Returns the figure."""
    fig = new_figure((12, 6.0), layout=None)
    fig.subplots_adjust(left=0.01, right=0.98, bottom=0.1, top=0.92, wspace=0.15)
    ax = fig.add_subplot(1, 2, 1, projection="3d")
    _draw_axes(ax, axes, length, tool)
    lines = [Line(p, u) for p, u, _kind in axes]
    for k, (a, b) in enumerate(zip(lines, lines[1:])):
        rel = relation(a, b)
        end = rel.foot
        start = a.nearest_point(end)
        if rel.kind == "intersect":
            ax.plot(*end[:, None], "o", ms=12, mfc="none", mec=NORMAL_COLOR, mew=2)
            text, at = _("$z_{k}, z_{k1}$ meet").format(k=k, k1=k + 1), end + (-0.06, 0.0, 0.1)
        else:
            _segment(ax, start, end, color=NORMAL_COLOR, lw=3)
            text, at = f"{rel.distance:g} m", (start + end) / 2 + (0.0, 0.0, 0.07)
        label(ax, at, text, fontsize=13, ha="right" if rel.kind == "intersect" else "center")
    _axes_box(ax, axes, tool, length)
    ax.view_init(**_EXERCISE_CAMERA)
    ax.set_title(_("common normals of $z_0 z_1$, $z_1 z_2$, $z_2 z_3$"), fontsize=13)
    side = fig.add_subplot(1, 2, 2)
    _along_y(side, lines, length, tool)
    return fig


def common_normals_after(answer, axes, tool=None):
    """:func:`common_normals_figure`, but only once ``answer`` (the student's answer to 5.1) is given: while
    it is still ``...`` this prints how to go on and returns None, so the stored notebook gives nothing away."""
    if answer is Ellipsis or answer is None:
        print(_("Answer exercise 5.1 first (replace the ... in its cell and run it), then run this cell again."))
        return None
    return common_normals_figure(axes, tool)


def _along_y(ax, lines, length, tool):
    """The axes seen along +y (x to the right, z up): an axis along y is a point (⊗: pointing away)."""
    for k, line in enumerate(lines):                  # the line of the axis z_k
        p2, u2 = line.point[[0, 2]], line.direction[[0, 2]]
        if np.linalg.norm(u2) < 1e-9:
            ax.plot(*p2, ls="", marker="o", ms=16, mfc="white", mec=AXIS_COLORS[2], mew=2)
            ax.plot(*p2, ls="", marker="x", ms=9, color=AXIS_COLORS[2], mew=2)
            label(ax, p2 + (-0.05, 0.07), f"$z_{k}$", color=AXIS_COLORS[2], fontsize=15, ha="right")
        else:
            ends = np.array([p2 - 1.2 * length * u2, p2 + 2.0 * length * u2])
            ax.plot(*ends.T, ":", color="0.45", lw=1.6)
            ax.annotate("", xy=p2 + length * u2, xytext=p2,
                        arrowprops=dict(arrowstyle="-|>", color=AXIS_COLORS[2], lw=2.5, mutation_scale=16))
            lift = (0.0, 0.0) if abs(u2[1]) > 0.9 else (0.0, 0.06)
            label(ax, p2 + 1.5 * length * u2 + lift, f"$z_{k}$", color=AXIS_COLORS[2], fontsize=15,
                  ha="right" if abs(u2[1]) > 0.9 else "center")
    for a, b in zip(lines, lines[1:]):
        rel = relation(a, b)
        if rel.kind != "intersect":
            start, end = a.nearest_point(rel.foot)[[0, 2]], rel.foot[[0, 2]]
            ax.plot(*np.array([start, end]).T, color=NORMAL_COLOR, lw=3)
            across = np.array([-(end - start)[1], (end - start)[0]]) / np.linalg.norm(end - start)
            label(ax, (start + end) / 2 - 0.08 * across, f"{rel.distance:g} m", fontsize=13)
    if tool is not None:
        tool = np.asarray(tool, float)
        tool = tool[:3, 3] if tool.shape == (4, 4) else tool
        ax.plot(tool[0], tool[2], "*", color="darkorange", mec="k", ms=16)
    ax.set(aspect="equal", xlabel="x [m]", ylabel="z [m]", title=_("seen along y (⊗: an axis along y)"))
    ax.title.set_fontsize(13)
    ax.margins(0.15)
    ax.grid(alpha=0.3)


# --- exercise 5.2: two frames -----------------------------------------------------------------------------
def row_frames_figure(S_prev, S_next, length: float = 0.25, name_offsets=((0.16, 0.0, -0.08), (0.03, 0.0, -0.12))):
    """Exercise 5.2's picture: the frames {S_(i−1)} and {S_i} as labelled triads, their names moved from
    the origins by ``name_offsets`` (world units, chosen by eye to sit clear of the axes). Returns the figure."""
    fig = new_figure((6.4, 6.0), layout=None)
    fig.subplots_adjust(left=0.02, right=0.9, bottom=0.08, top=0.92)
    ax = fig.add_subplot(projection="3d")
    S_prev, S_next = (np.asarray(F, dtype=float) for F in (S_prev, S_next))
    for F, offset, sub, name in ((S_prev, name_offsets[0], "i-1", r"$\{S_{i-1}\}$"),
                                 (S_next, name_offsets[1], "i", r"$\{S_i\}$")):
        triad(ax, F, length, sub=sub, lw=3)
        ax.plot(*F[:3, 3, None], "o", color="black", ms=5)
        label(ax, F[:3, 3] + np.asarray(offset, dtype=float), name)
    P = np.array([F[:3, 3] + s * F[:3, k] for F in (S_prev, S_next) for k in range(3)
                  for s in (-0.4 * length, 1.3 * length)])
    fit_box(ax, P, pad=0.05)
    ax.set(xlabel="x [m]", ylabel="y [m]", zlabel="z [m]")
    ax.locator_params(nbins=4)
    for axis, pad in ((ax.xaxis, 10), (ax.yaxis, 10), (ax.zaxis, 15)):
        axis.labelpad = pad
    ax.set_box_aspect(np.ptp(P, axis=0) + 0.1, zoom=0.9)
    ax.set_title(_(r"exercise 5.2: $\{S_{i-1}\}$ and $\{S_i\}$ in the world"), fontsize=13)
    return fig
