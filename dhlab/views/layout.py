"""Figure layout for the course's 3D axes: tick labels that do not collide, and
nothing clipped at the figure's edge.

* :func:`space_ticks` gives each 3D axis as many ticks as its drawn length
  holds (a foreshortened axis gets two), so tick labels do not run into each other;
* :func:`keep_texts_inside` watches the full draws of a figure and, when a
  title, axis label or tick label of the axes sticks out of the figure, moves
  (or shrinks) the axes and draws again. matplotlib's own layout engines do
  not see the labels of a 3D axes where they are really drawn.
"""
from __future__ import annotations

import numpy as np
from matplotlib.ticker import MaxNLocator, NullLocator

from . import framing

__all__ = ["space_ticks", "keep_texts_inside", "drawn_texts"]


def space_ticks(ax, per_tick_px: float = 90.0) -> None:
    """3D: as many ticks on each axis as its drawn length holds, one per
    ``per_tick_px`` pixels (2 to 5): a short, foreshortened axis gets few ticks,
    so that its tick labels do not collide; an axis seen end-on gets none."""
    lo = np.array([ax.get_xlim()[0], ax.get_ylim()[0], ax.get_zlim()[0]])
    hi = np.array([ax.get_xlim()[1], ax.get_ylim()[1], ax.get_zlim()[1]])
    scale = ax.figure.dpi / 100
    ends = np.array([lo] + [np.where(np.arange(3) == k, hi, lo) for k in range(3)])
    pixels = framing.projected(ax, ends)                  # the box's corner and its three edges' ends
    for k, axis in enumerate((ax.xaxis, ax.yaxis, ax.zaxis)):
        drawn = float(np.linalg.norm(pixels[k + 1] - pixels[0]))
        if drawn < 0.4 * per_tick_px * scale:     # seen end-on (a top view's z): no tick labels
            axis.set_major_locator(NullLocator())
            continue
        bins = int(np.clip(drawn / (per_tick_px * scale), 1, 4))
        axis.set_major_locator(MaxNLocator(nbins=bins, min_n_ticks=2))


def keep_texts_inside(ax) -> None:
    """After every full draw of ``ax``'s figure: if a title, axis label or tick label
    of ``ax`` sticks out of the figure, move (or shrink) the axes and draw again.
    Full draws are rare in a panel (a new frame, a turn of the camera), so this
    costs nothing while the sliders move.

    The place is always worked out from where the axes were put first (``home``),
    not from where an earlier frame moved them: the layout is a function of what
    is drawn, so a robot swept to a joint limit and back is drawn where it was at
    the start (an axes moved for one frame goes back for the next if it can)."""
    busy, home = [], ax.get_position().frozen()

    def on_draw(event):
        figure = ax.figure
        if busy or figure.canvas.is_saving():
            return
        for _ in range(3):
            position = _placement(ax, event.renderer, home)
            if position is None:
                return
            ax.set_position(position)
            busy.append(True)
            try:
                figure.canvas.draw()
            finally:
                busy.clear()

    ax.figure.canvas.mpl_connect("draw_event", on_draw)


def _placement(ax, renderer, home):
    """Where ``ax`` should be, given the texts it has just drawn, or None if it is there.

    When the axes have their home size, they were only shifted: their texts, drawn
    at home, would be where they are now less that shift, so the place is worked
    out from home without drawing there. A shrunk axes is placed from where it is."""
    fig, now = ax.figure.bbox, ax.get_position()
    if np.allclose([now.width, now.height], [home.width, home.height], atol=1e-9):
        shift = ((home.x0 - now.x0) * fig.width, (home.y0 - now.y0) * fig.height)
        position = _overflow(ax, renderer, shift=shift, start=home)
        position = list(home.bounds) if position is None else position
    else:
        position = _overflow(ax, renderer)
    if position is None:
        return None
    if np.allclose(position, now.bounds, atol=0.25 / max(fig.width, fig.height)):   # within a pixel
        return None
    return position


def drawn_texts(ax) -> list:
    """The texts an axes drew: title, axis labels and the tick labels within the limits."""
    texts = [t for t in (ax.title, ax._left_title, ax._right_title) if t.get_text()]
    for axis in ax._axis_map.values():
        texts.append(axis.label)
        lo, hi = sorted(axis.get_view_interval())
        for tick in axis.majorTicks[:len(axis.get_majorticklocs())]:
            if lo <= tick.get_loc() <= hi and tick.label1.get_visible():
                texts.append(tick.label1)
    return [t for t in texts if t.get_visible() and t.get_text()]


def _overflow(ax, renderer, pad: float = 4.0, shift=(0.0, 0.0), start=None):
    """A new position (figure fraction) for ``ax`` that brings the texts it drew
    inside the figure (shifted, or shrunk about its centre when they cannot fit),
    or None when they are inside already. ``shift`` (px) moves the drawn texts
    first, as if the axes had been drawn at ``start`` (a position; default: where
    the axes are)."""
    boxes = [t.get_window_extent(renderer) for t in drawn_texts(ax)]
    if not boxes:
        return None
    fig = ax.figure.bbox
    lows = (min(b.x0 for b in boxes) + shift[0], min(b.y0 for b in boxes) + shift[1])
    highs = (max(b.x1 for b in boxes) + shift[0], max(b.y1 for b in boxes) + shift[1])
    sizes = (fig.width, fig.height)
    if all(lo >= pad - 0.5 and hi <= size - pad + 0.5 for lo, hi, size in zip(lows, highs, sizes)):
        return None
    p = ax.get_position() if start is None else start
    px = [p.x0 * fig.width, p.y0 * fig.height, p.width * fig.width, p.height * fig.height]
    for k, (lo, hi, size) in enumerate(zip(lows, highs, sizes)):
        if hi - lo > size - 2 * pad:             # cannot fit: shrink (the next pass shifts)
            center = px[k] + px[2 + k] / 2
            px[2 + k] *= 0.97 * (size - 2 * pad) / (hi - lo)
            px[k] = center - px[2 + k] / 2
        else:
            px[k] += max(pad - lo, 0) - max(hi - (size - pad), 0)
    return [px[0] / fig.width, px[1] / fig.height, px[2] / fig.width, px[3] / fig.height]
