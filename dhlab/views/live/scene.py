"""The moving artists of a figure as plain numbers, for the browser to draw (the canvas backend).

Why: rendering the whole figure with Agg and encoding a PNG costs ~17 ms of kernel time per
slider step; the few lines, polygons and labels that move are a few hundred numbers. Here each
moving matplotlib artist becomes a small description (colours, widths, markers as outlines) plus
its points in *data* coordinates, and each axes becomes a 4x4 matrix ``P`` that maps a data point
``(x, y, z, 1)`` to ``(px, py, depth, w)``: the canvas pixel is ``(px/w, py/w)`` (y down, device
pixels), exactly as matplotlib maps it (for a 3D axes: its projection ``ax.M``, then the axes'
``transData``). The browser (canvas.js) projects, depth-sorts the polygons as mplot3d does and
paints. For a 3D axes it also gets the view's parameters, so it can turn the view itself while
the mouse drags.

An artist this module does not know raises :class:`Unsupported`: the figure then falls back to
a full matplotlib frame (never a wrong picture).

>>> from matplotlib.figure import Figure
>>> from matplotlib.backends.backend_agg import FigureCanvasAgg
>>> fig = Figure()
>>> _ = FigureCanvasAgg(fig)
>>> ax = fig.add_subplot()
>>> line, = ax.plot([0, 1], [0, 1], "-o")
>>> fig.canvas.draw()
>>> content, numbers = describe_scene(fig, [line])
>>> content["items"][0]["kind"], len(numbers) > 0
('line', True)
"""
from __future__ import annotations

import numpy as np
from matplotlib import colors as mcolors
from matplotlib import patheffects
from matplotlib.collections import PathCollection, PolyCollection
from matplotlib.lines import Line2D
from matplotlib.path import Path
from matplotlib.text import Text
from matplotlib.textpath import TextPath
from matplotlib.transforms import Affine2D
from mpl_toolkits.mplot3d import art3d

from ..labels import FrameLabels

__all__ = ["describe_scene", "describe_artist", "Numbers", "axes_camera", "css_color", "faces3d", "Unsupported"]


class Unsupported(Exception):
    """An artist the browser layer cannot draw exactly enough: fall back to a matplotlib frame."""


class Numbers:
    """All the numbers of one scene in one float32 buffer; items keep (offset, count)."""

    def __init__(self):
        self.parts, self.size = [], 0

    def add(self, array) -> int:
        array = np.ascontiguousarray(array, dtype=np.float32).ravel()
        self.parts.append(array)
        self.size += len(array)
        return self.size - len(array)

    def buffer(self) -> np.ndarray:
        return np.concatenate(self.parts) if self.parts else np.zeros(0, np.float32)


def css_color(rgba) -> str:
    """A matplotlib RGBA colour (0-1 floats) as a CSS colour."""
    r, g, b, a = (float(v) for v in rgba)
    return f"rgba({round(255 * r)},{round(255 * g)},{round(255 * b)},{a:.4g})"


def _css(rgba) -> str | None:
    return None if float(rgba[3]) == 0 else css_color(rgba)


def _flip(figure) -> np.ndarray:
    """matplotlib's display pixels (y up) -> canvas pixels (y down), as a 3x3 affine."""
    return np.array([[1.0, 0, 0], [0, -1.0, figure.bbox.height], [0, 0, 1.0]])


def axes_camera(ax) -> dict:
    """How the browser maps the data of ``ax`` to canvas pixels: ``P`` (4x4, row-major) and,
    for a 3D axes, what it needs to recompute ``ax.M`` for another (elev, azim)."""
    flip = _flip(ax.figure)
    A = flip @ ax.transData.get_affine().get_matrix()          # 2D -> canvas pixels
    bbox = (flip @ [[ax.bbox.x0, ax.bbox.x1], [ax.bbox.y1, ax.bbox.y0], [1, 1]])[:2].T.ravel()
    if getattr(ax, "name", "") != "3d":
        P = np.array([[A[0, 0], A[0, 1], 0, A[0, 2]], [A[1, 0], A[1, 1], 0, A[1, 2]],
                      [0, 0, 0, 0], [0, 0, 0, 1.0]])
        return {"P": P.ravel().tolist(), "bbox": bbox.tolist(), "three_d": False}
    M = ax.M if getattr(ax, "M", None) is not None else ax.get_proj()
    camera = {"P": _compose(A, M).ravel().tolist(), "bbox": bbox.tolist(), "three_d": True,
              "A": A[:2].ravel().tolist(), "elev": float(ax.elev), "azim": float(ax.azim),
              "roll": float(ax.roll), "dist": float(ax._dist),
              "focal": None if np.isinf(ax._focal_length) else float(ax._focal_length),
              "aspect": np.asarray(ax._box_aspect, dtype=float).tolist(),
              "limits": _limits(ax),
              # the browser turns a view only in the usual case: z up, linear scales
              "turnable": bool(ax._vertical_axis == 2 and all(
                  axis.get_scale() == "linear" for axis in (ax.xaxis, ax.yaxis, ax.zaxis)))}
    return camera


def _limits(ax) -> list:
    """[x0, x1, y0, y1, z0, z1] as get_proj uses them (through the axis scales: matplotlib >= 3.9;
    3.8 has linear 3D axes only and uses the limits themselves)."""
    if hasattr(ax, "_get_scaled_limits"):
        return np.asarray(ax._get_scaled_limits(), dtype=float).tolist()
    return np.asarray([*ax.get_xlim3d(), *ax.get_ylim3d(), *ax.get_zlim3d()], dtype=float).tolist()


def _compose(A, M) -> np.ndarray:
    """(x, y, z, 1) -> (px, py, depth, w): rows 0, 1 are transData applied to M's x/w, y/w."""
    P = np.empty((4, 4))
    P[0] = A[0, 0] * M[0] + A[0, 1] * M[1] + A[0, 2] * M[3]
    P[1] = A[1, 0] * M[0] + A[1, 1] * M[1] + A[1, 2] * M[3]
    P[2], P[3] = M[2], M[3]
    return P


def describe_scene(figure, moving, quick: bool = False) -> tuple:
    """(content, numbers): a JSON-able description of the visible moving artists of ``figure``
    in drawing order, and the float32 array their points live in. Raises Unsupported.

    ``quick`` (while a slider is dragged): frame labels keep where they sat, beside their
    origins, at the last full layout (placing them afresh is half the cost of a step); the
    picture at rest lays them out again."""
    axes = [ax for ax in figure.axes]
    numbers = Numbers()
    scale = figure.dpi / 72.0                                  # points -> pixels
    items = []
    for index, artist in enumerate(moving):
        if not artist.get_visible():
            continue
        space = axes.index(artist.axes) if artist.axes in axes else -1
        item = describe_artist(artist, space, numbers, scale, quick)
        item["clip"] = _clip(artist)
        item["artist"] = index               # which moving artist (a rig names them so: rig.py)
        items.append(item)
    content = {"items": items, "spaces": [axes_camera(ax) for ax in axes],
               "size": [figure.bbox.width, figure.bbox.height]}
    return content, numbers.buffer()


def describe_artist(artist, space, numbers, scale, quick=False) -> dict:
    """One moving artist as the browser paints it (its numbers appended to ``numbers``), or
    :class:`Unsupported` for an artist ``canvas.js`` cannot paint."""
    if isinstance(artist, FrameLabels):
        return _labels(artist, space, numbers, quick)
    if isinstance(artist, Line2D):
        return _line(artist, space, numbers, scale)
    if isinstance(artist, art3d.Poly3DCollection):
        return _polys3d(artist, space, numbers, scale)
    if isinstance(artist, PolyCollection) and not isinstance(artist, PathCollection):
        return _polys2d(artist, space, numbers, scale)
    if isinstance(artist, Text):
        return _text(artist, space, numbers, scale)
    raise Unsupported(type(artist).__name__)


def _clip(artist):
    """The clip rectangle in canvas pixels (x0, y0, x1, y1), or None."""
    if not artist.get_clip_on():
        return None
    box = artist.get_clip_box()
    path = artist.get_clip_path()
    extents = []
    if box is not None:
        extents.append(box.extents)
    if path is not None:
        extents.append(path.get_fully_transformed_path().get_extents().extents)
    if not extents:
        return None
    x0, y0 = np.max([e[:2] for e in extents], axis=0)
    x1, y1 = np.min([e[2:] for e in extents], axis=0)
    h = artist.figure.bbox.height
    return [float(x0), float(h - y1), float(x1), float(h - y0)]


def _points(artist) -> np.ndarray:
    """The artist's points as it holds them (data coordinates, z = 0 in 2D; or pixels, for an artist drawn in them)."""
    if isinstance(artist, art3d.Line3D):
        return np.column_stack(artist.get_data_3d()).astype(float)
    xy = np.column_stack(artist.get_data()).astype(float) if len(artist.get_xdata()) else np.zeros((0, 2))
    return np.column_stack([xy, np.zeros(len(xy))])


def _in_data_space(artist, space) -> bool:
    return space >= 0 and (isinstance(artist, art3d.Line3D) or artist.get_transform() == artist.axes.transData)


def _line(line, space, numbers, scale) -> dict:
    if line.get_drawstyle() != "default" or line.get_markevery() is not None:
        raise Unsupported("Line2D drawstyle/markevery")
    points = _points(line)
    if not _in_data_space(line, space):
        if isinstance(line, art3d.Line3D):
            raise Unsupported("Line3D with its own transform")
        flip = _flip(line.figure)
        xy = line.get_transform().transform(points[:, :2])
        points = np.column_stack([xy[:, 0], flip[1, 2] - xy[:, 1], np.zeros(len(xy))])
        space = -1
    item = {"kind": "line", "space": space, "points": [numbers.add(points), len(points)]}
    alpha = line.get_alpha()
    if line.get_linestyle() not in ("None", "", " ") and line.get_linewidth() > 0:
        offset, dashes = line._dash_pattern
        item.update(color=_css(mcolors.to_rgba(line.get_color(), alpha)), width=line.get_linewidth() * scale,
                    dash=None if dashes is None else [d * scale for d in dashes], dash_offset=(offset or 0) * scale,
                    cap=_cap(line.get_solid_capstyle() if dashes is None else line.get_dash_capstyle()),
                    join=_join(line.get_solid_joinstyle() if dashes is None else line.get_dash_joinstyle()))
    marker = line._marker
    if marker.get_marker() not in ("None", None, "", " ") and line.get_markersize() > 0:
        if marker.get_fillstyle() not in ("full", "none") or marker.get_marker() == ",":
            raise Unsupported("half-filled or pixel marker")
        size = line.get_markersize() * scale
        transform = marker.get_transform() + Affine2D().scale(size, -size)     # y down
        filled = marker.is_filled() and marker.get_fillstyle() != "none"
        fc = mcolors.to_rgba(line._get_markerfacecolor(), alpha) if filled else (0, 0, 0, 0)
        ec = mcolors.to_rgba(line.get_markeredgecolor(), alpha)
        item["marker"] = dict(_path(marker.get_path(), transform, numbers), fill=_css(fc), edge=_css(ec),
                              edge_width=line.get_markeredgewidth() * scale, join=_join(marker.get_joinstyle()))
    return item


def _path(path: Path, transform, numbers) -> dict:
    """A path's vertices (transformed) and codes, for the browser's Path2D."""
    vertices = transform.transform(path.vertices) if len(path.vertices) else np.zeros((0, 2))
    codes = path.codes.tolist() if path.codes is not None else None
    return {"vertices": [numbers.add(vertices), len(vertices)], "codes": codes}


def _cap(style) -> str:
    return {"butt": "butt", "round": "round", "projecting": "square"}[str(style)]


def _join(style) -> str:
    return {"miter": "miter", "round": "round", "bevel": "bevel"}[str(style)]


def _colors(rgba, count) -> np.ndarray:
    rgba = np.asarray(rgba, dtype=float).reshape(-1, 4)
    if len(rgba) == 0:
        return np.zeros((count, 4))
    return np.resize(rgba, (count, 4))


def _polys3d(polys, space, numbers, scale) -> dict:
    if polys._codes3d is not None or polys._A is not None or getattr(polys, "_axlim_clip", False):
        raise Unsupported("Poly3DCollection with codes, a colormap or axlim_clip")
    sort = {np.average: "average", np.min: "min", np.max: "max"}.get(polys._zsortfunc)
    if sort is None:
        raise Unsupported("Poly3DCollection zsort")
    faces = faces3d(polys)
    count = len(faces)
    return {"kind": "polys", "space": space, "sort": sort,
            "faces": [numbers.add(faces), count, faces.shape[1] if count else 0],
            "fill": numbers.add(_colors(polys._facecolor3d, count)),
            "edge": numbers.add(_colors(polys._edgecolor3d if len(polys._edgecolor3d) else polys._facecolor3d,
                                        count)),
            "width": float(np.ravel(polys.get_linewidth())[0]) * scale}


def faces3d(polys) -> np.ndarray:
    """The data corners of a Poly3DCollection's faces, shape (faces, corners, 3); the unused
    corners of a face shorter than the longest are NaN (the browser skips them).

    mplot3d has no public getter for them and keeps them differently by version: one padded
    array ``_faces`` with a mask ``_invalid_vertices`` (matplotlib >= 3.9), or one (4, n)
    array of homogeneous points ``_vec`` cut into faces by ``_segslices`` (3.8, the version
    of the browser edition's Pyodide)."""
    if hasattr(polys, "_faces"):
        faces = np.array(polys._faces, dtype=float)
        if faces.ndim != 3:
            raise Unsupported(f"Poly3DCollection faces of shape {faces.shape}")
        faces[np.broadcast_to(np.asarray(polys._invalid_vertices), faces.shape[:2])] = np.nan
        return faces
    if not hasattr(polys, "_vec"):
        raise Unsupported("Poly3DCollection of an unknown matplotlib version")
    points = np.asarray(polys._vec, dtype=float)[:3].T
    spans = [(s.start, s.stop) for s in polys._segslices]
    faces = np.full((len(spans), max((b - a for a, b in spans), default=0), 3), np.nan)
    for face, (a, b) in zip(faces, spans):
        face[:b - a] = points[a:b]
    return faces


def _polys2d(polys, space, numbers, scale) -> dict:
    if polys._A is not None or polys.get_transform() != polys.axes.transData or np.any(polys.get_offsets()):
        raise Unsupported("PolyCollection with a colormap, offsets or its own transform")
    paths = polys.get_paths()
    if any(p.codes is not None and not np.isin(p.codes, (Path.MOVETO, Path.LINETO, Path.CLOSEPOLY)).all()
           for p in paths):
        raise Unsupported("PolyCollection with curves")
    corners = max((len(p.vertices) for p in paths), default=0)
    faces = np.full((len(paths), corners, 3), np.nan)      # ragged faces: NaN corners are skipped
    for face, p in zip(faces, paths):
        face[:len(p.vertices), :2], face[:len(p.vertices), 2] = p.vertices, 0.0
    count = len(faces)
    return {"kind": "polys", "space": space, "sort": None,
            "faces": [numbers.add(faces), count, faces.shape[1] if count else 0],
            "fill": numbers.add(_colors(polys.get_facecolor(), count)),
            "edge": numbers.add(_colors(polys.get_edgecolor(), count)),
            "width": float(np.ravel(polys.get_linewidth())[0]) * scale}


def _labels(labels, space, numbers, quick=False) -> dict:
    """Frame labels: their outlines (pixels, y down) relative to their origin's pixel, which the
    browser projects, so that while it turns the view the labels travel with their origins."""
    points = labels.get_points()
    groups = [g[0] for g in labels.groups()]
    last = getattr(labels, "_dhlab_placed", None)
    if not (quick and last is not None and last[0] == groups):
        labels.layout()                              # where matplotlib would put them now
        anchors = labels.to_pixels(points)[groups]
        leaders = np.array([seg for seg in labels.leaders.get_segments()], dtype=float).reshape(-1, 2, 2)
        anchor_of = [int(np.argmin(np.linalg.norm(anchors - seg[0], axis=1))) for seg in leaders]
        last = labels._dhlab_placed = (groups, labels.get_offsets() - anchors, anchor_of,
                                       [(seg - anchors[k]) * [1, -1] for seg, k in zip(leaders, anchor_of)])
    _, offsets, anchor_of, leader_deltas = last
    pieces = [_path(path, Affine2D().translate(*offset).scale(1, -1), numbers)
              for path, offset in zip(labels.get_paths(), offsets)]
    anchor_points = np.column_stack([points[groups], np.zeros((len(groups), 3 - points.shape[1]))])
    return {"kind": "glyphs", "space": space, "anchors": [numbers.add(anchor_points), len(groups)],
            "pieces": pieces, "fill": _css(_colors(labels.get_facecolor(), 1)[0]),
            "leaders": {"of": anchor_of, "deltas": numbers.add(np.array(leader_deltas).reshape(-1, 2)),
                        "color": _css(_colors(labels.leaders.get_edgecolor(), 1)[0]),
                        "width": float(np.ravel(labels.leaders.get_linewidth())[0]) * labels.figure.dpi / 72}}




def _text(text, space, numbers, scale) -> dict:
    """A Text as its outline, aligned on its ink (close to matplotlib's layout; the rest frame is exact)."""
    if text.get_rotation() % 360 or not text.get_text().strip():
        if text.get_text().strip():
            raise Unsupported("rotated Text")
        return {"kind": "glyphs", "space": -1, "anchors": [numbers.add(np.zeros((0, 3))), 0], "pieces": []}
    path = TextPath((0, 0), text.get_text(), prop=text.get_fontproperties())
    (x0, y0), (x1, y1) = path.get_extents().get_points() if len(path.vertices) else ((0, 0), (0, 0))
    dx = {"left": -x0, "center": -(x0 + x1) / 2, "right": -x1}[text.get_horizontalalignment()]
    dy = {"bottom": -y0, "baseline": 0.0, "center": -(y0 + y1) / 2, "center_baseline": -(y0 + y1) / 2,
          "top": -y1}[text.get_verticalalignment()]
    move = Affine2D().translate(dx, dy).scale(scale, -scale)
    if isinstance(text, art3d.Text3D):
        anchor = np.asarray(text.get_position_3d(), dtype=float)[None]
    elif space >= 0 and text.get_transform() == text.axes.transData:
        anchor = np.array([[*text.get_unitless_position(), 0.0]])
    else:                                             # any other transform: its pixel, fixed
        x, y = text.get_transform().transform(text.get_unitless_position())
        anchor, space = np.array([[x, text.figure.bbox.height - y, 0.0]]), -1
    return {"kind": "glyphs", "space": space, "anchors": [numbers.add(anchor), 1],
            "pieces": [_path(path, move, numbers)], "halo": _halo(text, scale),
            "fill": _css(mcolors.to_rgba(text.get_color(), text.get_alpha()))}


def _halo(text, scale):
    """A ``withStroke`` path effect (the course's white halo) as {color, width}; None without one."""
    halo = None
    for effect in text.get_path_effects():
        if isinstance(effect, patheffects.withStroke):
            style = effect._gc
            halo = {"color": _css(mcolors.to_rgba(style.get("foreground", "w"), text.get_alpha())),
                    "width": float(style.get("linewidth", 2)) * scale}
        elif type(effect) is not patheffects.Normal:
            raise Unsupported(type(effect).__name__)
    return halo
