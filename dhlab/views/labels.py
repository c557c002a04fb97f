"""Frame labels ``{S_0} … {S_n}`` that never pile up.

Two rules, applied on every draw (so they hold at any pose and after the 3D
view is turned with the mouse):

1. **Frames at one place get one label.** The origins of a spherical wrist
   coincide, so its frames are labelled together: ``{S_4,S_5,S_6}``.
2. **Labels keep out of each other's way.** Each label is placed in *screen*
   space, next to its origin, on the side away from its neighbours (along the
   bisector of the directions to them). Where that spot is taken, it moves
   further out, with a thin leader line back to its origin. No two labels
   overlap and none leaves the figure.

Why one artist for all labels: Agg renders a ``Text`` glyph by glyph on every
draw (about 0.8 ms each); one collection of ready-made outlines draws all the
labels in about 0.3 ms, which keeps the sliders fast.

>>> groups = group_points([[0, 0, 0], [1, 0, 0], [1, 0, 0]])
>>> groups
[[0], [1, 2]]
>>> merged_name(["$\\\\{S_{1}\\\\}$", "$\\\\{S_{2}\\\\}$"])
'$\\\\{S_{1},S_{2}\\\\}$'
"""
from __future__ import annotations

import re

import numpy as np
from matplotlib.collections import LineCollection, PathCollection
from matplotlib.textpath import TextPath
from matplotlib.transforms import Affine2D, IdentityTransform
from mpl_toolkits.mplot3d import proj3d

__all__ = ["FrameLabels", "FrameLabels3D", "group_points", "merged_name", "place_boxes",
           "overlap_cost", "outside_cost", "cover_cost", "GAP", "RADII", "LABEL_FONTSIZE"]

LABEL_FONTSIZE = 10.0            # points: 13.9 px at 100 dpi
GAP = 3.0                       # pixels between an origin and its label (at least)
RADII = (0.0, 8.0, 18.0, 32.0, 50.0, 75.0, 105.0)      # extra distances tried, pixels
_DIRECTIONS = 16


def group_points(points, tol: float = 1e-9) -> list:
    """Indices of ``points`` grouped by place (points closer than ``tol`` share a group),
    in order of first appearance."""
    points = np.asarray(points, dtype=float)
    groups, where = [], []
    for i, p in enumerate(points):
        for g, q in zip(groups, where):
            if np.linalg.norm(p - q) <= tol:
                g.append(i)
                break
        else:
            groups.append([i])
            where.append(p)
    return groups


_BRACED = re.compile(r"^\$\\\{(.*)\\\}\$$")


def merged_name(names) -> str:
    r"""One mathtext label for several frames: ``$\{S_4\}$, $\{S_5\}$`` -> ``$\{S_4,S_5\}$``."""
    names = list(names)
    if len(names) == 1:
        return names[0]
    inner = [(_BRACED.match(n).group(1) if _BRACED.match(n) else n.strip("$")) for n in names]
    return r"$\{" + ",".join(inner) + r"\}$"


def place_boxes(anchors, sizes, bounds, obstacles=(), gap: float = GAP) -> tuple:
    """Screen positions for labels that do not overlap.

    ``anchors`` (k, 2): the pixel each label belongs to; ``sizes`` (k, 2): label
    width and height in pixels; ``bounds`` (x0, y0, x1, y1): where labels must
    stay; ``obstacles`` (m, 2): points labels should rather not cover (the origins).
    Returns (lower-left corners (k, 2), extra distances from the anchors (k,)).

    Each label tries the directions around its anchor, the one pointing away
    from the other anchors first, at growing distances, and takes the first
    free spot (the most crowded labels choose first).

    >>> corners, _ = place_boxes([[100, 100], [101, 100]], [[40, 14], [40, 14]], (0, 0, 400, 400))
    >>> bool(abs(corners[0, 0] - corners[1, 0]) >= 40 or abs(corners[0, 1] - corners[1, 1]) >= 14)
    True
    """
    anchors = np.asarray(anchors, dtype=float).reshape(-1, 2)
    sizes = np.asarray(sizes, dtype=float).reshape(-1, 2)
    obstacles = np.asarray(obstacles, dtype=float).reshape(-1, 2)
    angles = 2 * np.pi * np.arange(_DIRECTIONS) / _DIRECTIONS
    unit = np.column_stack([np.cos(angles), np.sin(angles)])
    radii = np.asarray(RADII)
    placed = np.zeros((0, 4))                     # boxes taken: x0, y0, x1, y1
    corners, distances = np.zeros_like(anchors), np.zeros(len(anchors))
    gaps = anchors[:, None, :] - anchors[None, :, :]
    crowd = np.sum(1 / (1 + np.linalg.norm(gaps, axis=2)), axis=1)
    for k in np.argsort(-crowd, kind="stable"):
        a, (w, h) = anchors[k], sizes[k]
        d = gaps[k]
        away = np.sum(d / np.maximum(np.sum(d * d, axis=1), 1.0)[:, None], axis=0)
        if np.linalg.norm(away) < 1e-9:
            away = np.array([0.6, 0.8])           # alone: up and to the right, as in the seeds
        u = unit[np.argsort(-(unit @ away), kind="stable")]           # (D, 2), best first
        half_extent = 0.5 * (np.abs(u[:, 0]) * w + np.abs(u[:, 1]) * h)
        best_cost, best_box = np.inf, None
        for ring, radius in enumerate(radii):
            if best_cost <= 1e-3 * ring:      # costs are >= 0: no farther spot can do better
                break
            # candidate centres: the box touches a circle of radius GAP + r around the anchor
            centres = a + u * (gap + radius + half_extent)[:, None]
            boxes = np.concatenate([centres - [w / 2, h / 2], centres + [w / 2, h / 2]], axis=-1)
            cost = overlap_cost(boxes, placed) + outside_cost(boxes, bounds) \
                + cover_cost(boxes, obstacles, a) + 1e-3 * ring           # nearer is better
            j = int(np.argmin(cost))
            if cost[j] < best_cost:
                best_cost, best_box, distances[k] = cost[j], boxes[j], radius
        corners[k] = best_box[:2]
        placed = np.vstack([placed, best_box])
    return corners, distances


def overlap_cost(boxes, placed):
    """Per candidate box (x0, y0, x1, y1), a large cost for touching a box already placed."""
    if not len(placed):
        return np.zeros(len(boxes))
    dx = np.minimum(boxes[:, None, 2], placed[None, :, 2]) - np.maximum(boxes[:, None, 0], placed[None, :, 0])
    dy = np.minimum(boxes[:, None, 3], placed[None, :, 3]) - np.maximum(boxes[:, None, 1], placed[None, :, 1])
    hit = (dx > -1) & (dy > -1)                  # one pixel apart at least
    return np.sum(np.where(hit, 1000 + np.maximum(dx, 0) * np.maximum(dy, 0), 0), axis=1)


def outside_cost(boxes, bounds):
    """Per candidate box, a large cost for sticking out of ``bounds`` (the axes), growing with how far."""
    x0, y0, x1, y1 = bounds
    out = (np.maximum(x0 - boxes[:, 0], 0) + np.maximum(boxes[:, 2] - x1, 0)
           + np.maximum(y0 - boxes[:, 1], 0) + np.maximum(boxes[:, 3] - y1, 0))
    return np.where(out > 0, 1000 + 100 * out, 0)


def cover_cost(boxes, points, own):
    """A small cost for covering another origin's dot (not a hard rule)."""
    # only the points near some candidate can be covered: the same cost, far fewer comparisons
    lo, hi = boxes[:, :2].min(axis=0) - 3, boxes[:, 2:].max(axis=0) + 3
    near = (points > lo).all(axis=1) & (points < hi).all(axis=1)
    points = points[near & (np.linalg.norm(points - own, axis=1) > 1.0)]
    if not len(points):
        return np.zeros(len(boxes))
    inside = ((points[None, :, 0] > boxes[:, None, 0] - 3) & (points[None, :, 0] < boxes[:, None, 2] + 3)
              & (points[None, :, 1] > boxes[:, None, 1] - 3) & (points[None, :, 1] < boxes[:, None, 3] + 3))
    return 5.0 * np.sum(inside, axis=1)


def _three_columns(points) -> np.ndarray:
    points = np.asarray(points, dtype=float).reshape(len(points), -1)
    if points.shape[1] == 2:
        points = np.column_stack([points, np.zeros(len(points))])
    return points


_outline_cache: dict = {}


def _outline(name, fontsize):
    key = (name, fontsize)
    if key not in _outline_cache:
        path = TextPath((0, 0), name, size=fontsize)
        (bx0, by0), (bx1, by1) = path.get_extents().get_points()
        # origin at the lower-left corner of the ink, size in points
        _outline_cache[key] = (path.transformed(Affine2D().translate(-bx0, -by0)), (bx1 - bx0, by1 - by0))
    return _outline_cache[key]


class FrameLabels(PathCollection):
    """All frame labels of a view in one artist, placed afresh at every draw.

    ``set_points(points)`` gives the origins (data coordinates); the labels of
    origins closer than ``tol`` are merged. ``boxes()`` returns where the labels
    were last drawn (pixels), ``texts`` their texts.
    """

    def __init__(self, ax, names, fontsize: float = LABEL_FONTSIZE, color="k", alpha: float = 1.0,
                 gap: float = 8.0):
        self.names, self.fontsize, self.gap = list(names), fontsize, gap    # gap: points
        self._points = np.zeros((len(self.names), 3))
        self._avoid = np.zeros((0, 3))
        self._tol = 1e-9
        self.texts, self._boxes = [], np.zeros((0, 4))
        super().__init__([], offsets=np.zeros((0, 2)), offset_transform=IdentityTransform(),
                         facecolors=color, edgecolors="none", alpha=alpha)
        self.set_zorder(4)                        # above the robot in a still figure too
        self.leaders = LineCollection([], colors="0.45", linewidths=0.8, alpha=alpha)
        ax.add_collection(self, autolim=False)
        self.leaders.set_figure(ax.figure)
        self.leaders.set_transform(IdentityTransform())

    # --- data --------------------------------------------------------------------
    def set_points(self, points, tol: float = 1e-9, avoid=None) -> None:
        """Label i goes with ``points[i]`` (data coordinates, 2 or 3 columns); labels
        also keep off the points ``avoid`` (e.g. along the triads and links) where
        they can."""
        self._points, self._tol = _three_columns(points), tol
        self._avoid = _three_columns(avoid) if avoid is not None else np.zeros((0, 3))
        self.stale = True

    def get_points(self) -> np.ndarray:
        """The origins labelled, in data coordinates (2 or 3 columns, as the axes)."""
        return self._points[:, :self._dims]

    def groups(self) -> list:
        """The origins that share one label: lists of indices (see :func:`group_points`)."""
        return group_points(self._points, self._tol)

    _dims = 2

    def to_pixels(self, points) -> np.ndarray:
        """Data points (N, 2 or 3) as display pixels (N, 2) of this label's axes."""
        return self.axes.transData.transform(points[:, :2])

    # --- drawing -------------------------------------------------------------------
    def layout(self):
        """Place the labels for the axes as they are now (each draw does; see :func:`place_boxes`)."""
        points = self._points
        groups = group_points(points, self._tol)
        self.texts = [merged_name([self.names[i] for i in g]) for g in groups]
        anchors_all = self.to_pixels(points)
        anchors = anchors_all[[g[0] for g in groups]]
        scale = self.figure.dpi / 72.0
        outlines = [_outline(t, self.fontsize) for t in self.texts]
        sizes = np.array([[w * scale, h * scale] for _, (w, h) in outlines]).reshape(-1, 2)
        box = self.axes.bbox                      # labels stay inside their axes
        bounds = (box.x0 + 2, box.y0 + 2, box.x1 - 2, box.y1 - 2)
        avoid = self._avoid[~np.isnan(self._avoid).any(axis=1)]
        obstacles = np.vstack([anchors_all, self.to_pixels(avoid)]) if len(avoid) else anchors_all
        corners, distances = place_boxes(anchors, sizes, bounds, obstacles=obstacles,
                                         gap=self.gap * scale)      # clear of the origin's marker
        self._boxes = np.column_stack([corners, corners + sizes]) if len(corners) else np.zeros((0, 4))
        to_pixels = Affine2D().scale(scale)
        self.set_paths([path.transformed(to_pixels) for path, _ in outlines])
        self.set_offsets(corners)
        self.set_transform(IdentityTransform())
        far = distances > RADII[1]
        segments = []
        for a, c, s in zip(anchors[far], corners[far], sizes[far]):
            end = np.clip(a, c, c + s)                  # the nearest point of the label's box
            segments.append([a, end])
        self.leaders.set_segments(segments)

    def draw(self, renderer):
        if not self.get_visible():
            return
        self.layout()
        self.leaders.draw(renderer)
        super().draw(renderer)

    def boxes(self) -> np.ndarray:
        """Where the labels were last drawn: one (x0, y0, x1, y1) row per label, pixels."""
        return self._boxes.copy()


class FrameLabels3D(FrameLabels):
    """:class:`FrameLabels` at 3D points, projected with the axes' current view."""

    _dims = 3

    def to_pixels(self, points):
        """Data points (N, 3) projected by the 3D axes' current view, as display pixels (N, 2)."""
        x, y, _ = proj3d.proj_transform(*points.T, self.axes.M)
        return self.axes.transData.transform(np.column_stack([x, y]))

    def do_3d_projection(self):
        # matplotlib's 3D axes call this to sort artists by depth: labels on top
        return -np.inf
