"""Figures of notebook 06 (worked DH examples): the table read one frame pair at a time."""
from __future__ import annotations

import math

import numpy as np

from ...errors import DHLabError
from ...i18n import _
from ...validation import as_length, as_text, describe
from ...views.figures import new_figure
from ...views.triads import draw_triad, free_direction, letter_points
from ...views.viewbase import checked_robot, one_pose

__all__ = ["frame_pairs_figure", "row_title", "clip_segment"]


def clip_segment(a, b, lo, hi):
    """The part of the segment a→b inside the box [lo, hi] (two points), or None
    (matplotlib's 3D axes do not clip what they draw at their limits)."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    t0, t1 = 0.0, 1.0
    for p, v, l, h in zip(a, b - a, lo, hi):
        if abs(v) < 1e-12:
            if not l <= p <= h:
                return None
            continue
        s0, s1 = sorted(((l - p) / v, (h - p) / v))
        t0, t1 = max(t0, s0), min(t1, s1)
    return None if t0 > t1 else np.array([a + t0 * (b - a), a + t1 * (b - a)])


def frame_pairs_figure(robot, q=None, length: float | None = None, titles=None):
    """One picture per row of the DH table: frame {S_(i-1)} faint, {S_i} bold (x, y, z
    lettered), the arm in grey, each box fitted around its two frames so nothing is cut;
    three pictures a row (up to four rows of the table: all in one row).

    ``titles`` (one text per row) replaces the default "row i".
    """
    robot = checked_robot(robot)
    q = one_pose(robot, q)
    F = np.asarray(robot.frames(q), dtype=float)
    origins = F[:, :3, 3]
    length = _checked_length(length) if length is not None else 0.22 * max(float(np.ptp(origins, axis=0).max()), 1e-9)
    titles = _checked_titles(titles, robot.n)
    cols = robot.n if robot.n <= 4 else 3          # up to four pictures in one row (one screen of a deck)
    rows = math.ceil(robot.n / cols)
    height = 4.3 * rows * 3 / cols
    fig = new_figure((12, height), layout=None)
    fig.subplots_adjust(left=0.01, right=0.99, bottom=0.01, top=1 - 0.5 / height, wspace=0.02, hspace=0.14)
    for i in range(1, robot.n + 1):
        ax = fig.add_subplot(rows, cols, i, projection="3d", proj_type="ortho")
        pair = F[i - 1:i + 1]
        seen = np.vstack([pair[:, :3, 3], *letter_points(pair, length, gap=0.35)])
        centre = (seen.min(axis=0) + seen.max(axis=0)) / 2
        half = 0.62 * float(np.ptp(seen, axis=0).max())
        lo, hi = centre - half, centre + half
        for a, b in zip(origins[:-1], origins[1:]):               # the arm, cut at the box
            piece = clip_segment(a, b, lo, hi)
            if piece is not None:
                ax.plot(*piece.T, "-", color="0.6", lw=4, solid_capstyle="round")
        inside = origins[np.all((origins >= lo) & (origins <= hi), axis=1)]
        ax.plot(*inside.T, "o", color="0.45", ms=6)
        ax.set(xlim=(lo[0], hi[0]), ylim=(lo[1], hi[1]), zlim=(lo[2], hi[2]), xticks=[], yticks=[], zticks=[])
        ax.set_box_aspect((1, 1, 1), zoom=1.05)
        ax.view_init(elev=18, azim=-60)                         # before the labels: they read the view
        arm = [origins[k + 1] - origins[k] for k in range(robot.n)]
        together = np.linalg.norm(pair[1][:3, 3] - pair[0][:3, 3]) < 1e-9 * length
        taken = []                 # frames at one origin: the second label keeps off the first
        for k, (T, style) in enumerate(((pair[0], dict(lw=2.5, alpha=0.45, fontsize=14)),
                                        (pair[1], dict(lw=4, fontsize=15)))):
            busy = [v for v in arm[max(i - 2 + k, 0):i + k] if np.linalg.norm(v) > 1e-9]
            busy += [-v for v in busy] + [pair[1 - k][:3, 3] - T[:3, 3]]       # the arm and the other frame
            busy += [pair[1 - k][:3, j] for j in range(3)] if together else []
            draw_triad(ax, T, length, label=rf"$\{{S_{{{i - 1 + k}}}\}}$", avoid=busy + taken, **style)
            taken.append(free_direction(ax, T, busy + taken))
        ax.set_title(titles[i - 1] if titles else row_title(robot, i), fontsize=15)
    return fig


def _checked_length(length) -> float:
    length = as_length(length, _("length (of the triads)"))
    if not length > 0:
        raise DHLabError(_("length (of the triads) must be positive, got {length:g}.").format(length=length))
    return length


def _checked_titles(titles, n: int):
    if titles is None:
        return None
    if isinstance(titles, (str, bytes)) or not hasattr(titles, "__len__") or len(titles) != n:
        raise DHLabError(_("titles must be a list of {n} texts, one per row of the table; got {value}.").format(
            n=n, value=describe(titles)))
    return [as_text(t, f"titles[{k}]") for k, t in enumerate(titles)]


def row_title(robot, i: int) -> str:
    """"row i:  θi = qi − 90°": the row's θ with its offset, for a DH link (else "row i")."""
    link = robot.links[i - 1]
    if not hasattr(link, "offset") or not link.is_revolute:
        return _("row {i}").format(i=i)
    offset = np.degrees(float(link.offset))
    sign = "+" if offset > 0 else "−"
    return _("row {i}").format(i=i) + f":  θ{i} = q{i}" + (f" {sign} {abs(offset):g}°" if abs(offset) > 1e-9 else "")

