"""Framing: the robot fills its view, and the view does not jump while it moves.

A fixed box holding the whole workspace leaves the robot a few centimetres
wide on a projector (the PUMA used 11 % of its axes). Instead, the view is
*framed* around the robot's current configuration:

* the axis limits are the box around the frame origins, padded by the triad
  length (triads stay inside) and a little slack, with equal scaling (a cube
  looks like a cube);
* in 3D the box is zoomed (``set_box_aspect(..., zoom=)``) until its picture
  fills the axes;
* a robot seen end-on fills little of its box: then the box is cut down about
  its centre and the view zoomed in (:func:`zoom_in_on`), so that the robot
  spans at least :data:`TARGET` of its axes;
* while the robot moves, the frame is kept (**hysteresis**) until an origin
  comes near the border of the axes or the robot spans less than
  :data:`REFRAME_BELOW` of the axes; only then is it framed again, and only
  then is the cached background redrawn;
* the hysteresis **returns**: the view remembers the poses its frames were made
  at, and when the robot comes back to one of them it is framed again, as it was
  there. A joint swept to its limit (the view zooms out to follow it) and back
  leaves the view as it was at the start, not zoomed out (:func:`needs_reframe`).

>>> import numpy as np
>>> lo, hi = frame_box(np.array([[0, 0, 0], [1, 0, 0]]), pad=0.1)
>>> lo.round(2).tolist(), hi.round(2).tolist()
([-0.15, -0.23, -0.23], [1.15, 0.23, 0.23])
"""
from __future__ import annotations

import itertools

import matplotlib
import numpy as np
from mpl_toolkits.mplot3d import proj3d

__all__ = ["frame_box", "projected", "extent_fraction", "fit_zoom", "needs_reframe", "leaves_view", "back_home",
           "axes_limits",
           "zoom_in_on",
           "center_on", "box_corners", "PANE_MARGIN",
           "REFRAME_BELOW", "TARGET", "MIN_SIDE", "SLACK"]

REFRAME_BELOW = 0.42      # re-frame when the robot spans less of its axes than this
MIN_SIDE = 0.3            # no side of the box shorter than this fraction of the longest
SLACK = 0.04              # extra room on each side, as a fraction of the longest side
BOX_FILL = 0.98           # how much of the axes the zoomed 3D box fills
TARGET = 0.62             # a fresh frame makes the robot span at least this much of its axes
EDGE = 0.03               # re-frame when an origin comes this close to the axes' border
HOME = 0.01               # back at a framed pose: every point within this fraction of the box's size
HOMES_KEPT = 64           # how many framed poses a view remembers (a sweep makes ~15)
# matplotlib before 3.9 (the browser edition's 3.8) draws the 3D box's panes 1/48 of each
# range beyond the limits, on every side; from 3.9 on, exactly at the limits
PANE_MARGIN = 1 / 48 if tuple(int(v) for v in matplotlib.__version__.split(".")[:2]) < (3, 9) else 0.0


def frame_box(points, pad: float, slack: float = SLACK, min_side: float = MIN_SIDE) -> tuple:
    """(lo, hi), each (3,): the box around ``points`` (m, 3) with ``pad`` on every
    side, plus ``slack`` times its longest side, no side shorter than ``min_side``
    times the longest (so the panes of a flat robot keep some depth)."""
    points = np.asarray(points, dtype=float)
    lo, hi = points.min(axis=0) - pad, points.max(axis=0) + pad
    longest = max(float((hi - lo).max()), 1e-9)
    center = (lo + hi) / 2
    half = np.maximum((hi - lo) / 2, min_side * longest / 2) + slack * longest
    return center - half, center + half


def projected(ax, points, M=None) -> np.ndarray:
    """Pixel positions of data ``points`` (m, 3) (or (m, 2) in a 2D axes)."""
    points = np.asarray(points, dtype=float)
    if getattr(ax, "name", "") == "3d":
        M = ax.get_proj() if M is None else M
        x, y, _ = proj3d.proj_transform(*points[:, :3].T, M)
        return ax.transData.transform(np.column_stack([x, y]))
    return ax.transData.transform(points[:, :2])


def extent_fraction(ax, points, M=None) -> float:
    """How much of its axes the ``points`` span: the larger of (their width / the
    axes' width) and (their height / the axes' height), in pixels."""
    pixels = projected(ax, points, M)
    span = pixels.max(axis=0) - pixels.min(axis=0)
    box = ax.bbox
    return float(max(span[0] / box.width, span[1] / box.height))


def box_corners(ax):
    """The 8 corners of the 3D box as matplotlib draws it (data coordinates)."""
    limits = [ax.get_xlim(), ax.get_ylim(), ax.get_zlim()]
    limits = [(lo - PANE_MARGIN * (hi - lo), hi + PANE_MARGIN * (hi - lo)) for lo, hi in limits]
    return np.array(list(itertools.product(*limits)))


def fit_zoom(ax, zoom: float = 1.0, fill: float = BOX_FILL) -> float:
    """Zoom the 3D box of ``ax`` (limits and box aspect already set) until its
    picture fills ``fill`` of the axes in its tighter direction, times ``zoom``.
    Returns the zoom set."""
    aspect = np.array([np.ptp(ax.get_xlim()), np.ptp(ax.get_ylim()), np.ptp(ax.get_zlim())])
    ax.set_box_aspect(aspect, zoom=1.0)
    ax.apply_aspect()
    pixels = projected(ax, box_corners(ax))
    span = pixels.max(axis=0) - pixels.min(axis=0)
    box = ax.bbox
    best = fill * min(box.width / max(span[0], 1e-9), box.height / max(span[1], 1e-9)) * zoom
    ax.set_box_aspect(aspect, zoom=best)
    return best


def needs_reframe(ax, points, M=None, below: float = REFRAME_BELOW, edge: float = EDGE) -> bool:
    """True when a point is drawn within ``edge`` (a fraction of the axes' size) of the
    axes' border or beyond (:func:`leaves_view`), or the points span less than ``below`` of
    the axes, or the points are back at a pose a frame was made at while the current frame
    was made elsewhere (:func:`back_home`)."""
    pixels = projected(ax, points, M)
    box = ax.bbox
    span = pixels.max(axis=0) - pixels.min(axis=0)
    home = back_home(ax, points)           # always called: it also notes the frames made
    return _near_edge(box, pixels, edge) or max(span[0] / box.width, span[1] / box.height) < below or home


def leaves_view(ax, points, M=None, edge: float = EDGE) -> bool:
    """True when a point is drawn within ``edge`` (a fraction of the axes' size) of the
    axes' border or beyond: the robot is leaving the picture (the one reason to frame it
    again while a slider is still being dragged)."""
    return _near_edge(ax.bbox, projected(ax, points, M), edge)


def _near_edge(box, pixels, edge) -> bool:
    mx, my = edge * box.width, edge * box.height
    return bool(np.any(pixels[:, 0] < box.x0 + mx) or np.any(pixels[:, 0] > box.x1 - mx)
                or np.any(pixels[:, 1] < box.y0 + my) or np.any(pixels[:, 1] > box.y1 - my))


def back_home(ax, points) -> bool:
    """True when ``points`` are (within :data:`HOME` of the box's size) where they were
    when one of the axes' earlier frames was made, and the current frame was made
    elsewhere: framing again puts the view back as it was at that pose.

    Called with the points of every update (by :func:`needs_reframe`), it notes the
    frames made: when the axes' limits differ from those of the previous call, a new
    frame was made, from the points of that call (or, the first time, from these).
    What it remembers is kept on the axes (``ax._dhlab_homes``)."""
    points = np.array(points, dtype=float)
    limits = axes_limits(ax)
    memory = ax.__dict__.setdefault("_dhlab_homes", {"homes": [], "limits": None, "last": None})
    if memory["limits"] != limits:            # a frame was made since the last call
        made_from = points if memory["last"] is None else memory["last"]
        memory["homes"] = [made_from, *memory["homes"]][:HOMES_KEPT]    # the current frame's first
        memory["limits"] = limits
    memory["last"] = points
    size = max(float(np.ptp(np.asarray(limits).reshape(-1, 2), axis=1).max()), 1e-12)

    def near(home):
        return home.shape == points.shape and float(np.abs(home - points).max()) <= HOME * size
    current, *earlier = memory["homes"]
    return not near(current) and any(near(home) for home in earlier)


def axes_limits(ax) -> tuple:
    """The axes' limits as one flat tuple: (x0, x1, y0, y1[, z0, z1])."""
    limits = [ax.get_xlim(), ax.get_ylim()] + ([ax.get_zlim()] if getattr(ax, "name", "") == "3d" else [])
    return tuple(float(v) for pair in limits for v in pair)


def center_on(ax, points, lo, hi):
    """3D: slide the box [lo, hi] across the screen (along the camera's right and up
    directions) so that the picture of ``points`` sits in the middle of the box's
    picture. Returns the new (lo, hi)."""
    center = (lo + hi) / 2
    elev, azim = np.radians(ax.elev), np.radians(ax.azim)
    right = np.array([-np.sin(azim), np.cos(azim), 0.0])
    up = np.array([-np.sin(elev) * np.cos(azim), -np.sin(elev) * np.sin(azim), np.cos(elev)])
    pixels = projected(ax, np.vstack([points, center, center + right, center + up]))   # one projection
    pixels, (base, at_right, at_up) = pixels[:-3], pixels[-3:]
    middle = (pixels.max(axis=0) + pixels.min(axis=0)) / 2
    per_unit = [np.linalg.norm(at_right - base), np.linalg.norm(at_up - base)]
    if min(per_unit) < 1e-9:
        return lo, hi
    shift = (middle - base) / per_unit
    move = shift[0] * right + shift[1] * up
    lo, hi = lo + move, hi + move
    ax.set(xlim=(lo[0], hi[0]), ylim=(lo[1], hi[1]), zlim=(lo[2], hi[2]))
    return lo, hi


def zoom_in_on(ax, points, lo, hi, target: float = TARGET, zoom: float = 1.0, most: float = 4.0):
    """3D: when the ``points`` span less than ``target`` of the axes in the box [lo, hi]
    (a robot seen end-on fills little of its box), shrink the box about the points
    and zoom in by the same factor (at most ``most``, and never so far that the
    points' picture leaves the box's picture, where the tick labels are): the box's
    picture keeps its size, the robot grows (and may stand out of the box towards
    the eye). Returns the new (lo, hi)."""
    lo, hi = center_on(ax, points, lo, hi)
    fraction = extent_fraction(ax, points)
    if fraction >= target or fraction <= 0:
        return lo, hi
    robot = np.ptp(projected(ax, points), axis=0)
    box = np.ptp(projected(ax, box_corners(ax)), axis=0)
    room = 0.85 * float(np.min(box / np.maximum(robot, 1e-9)))
    grow = min(target / fraction, most, room)
    if grow <= 1:
        return lo, hi
    center, half = (lo + hi) / 2, (hi - lo) / 2 / grow
    lo, hi = center - half, center + half
    ax.set(xlim=(lo[0], hi[0]), ylim=(lo[1], hi[1]), zlim=(lo[2], hi[2]))
    fit_zoom(ax, zoom)
    return center_on(ax, points, lo, hi)
