"""Stick-figure views of a robot that move in place.

A view draws, for a joint vector ``q``:

* the links (*eslabones*) as lines from frame origin to frame origin, with a
  dot at each origin;
* a right-handed (*dextrógiro*) triad at every frame: **x red, y green, z blue**
  (seed 000, figure 10), labelled ``{S_0} … {S_n}``;
* the end effector (*efector final*) as an orange star (and its own triad,
  labelled ``{E}``, when the robot has a tool transform).

``view.update(q)`` only moves these artists: it never clears the axes or makes
a new figure, and the axis limits are fixed from the robot's workspace (see
:func:`workspace_box`), so the picture does not jump while the robot moves.
Only the moving artists are redrawn, over a cached picture of the axes
(:mod:`dhlab.livefigure`): a few milliseconds per update.

>>> import dhlab
>>> robot = dhlab.robots.ssrms()
>>> view = robot_view(robot)                 # 3D; a planar robot gets a 2D view
>>> view.update(dhlab.deg([0, 30, 0, 0, 0, 0, 0]))
>>> view.frames.shape                        # the frames drawn last (n+1, 4, 4)
(8, 4, 4)
"""
from __future__ import annotations

import numpy as np
from matplotlib.collections import PathCollection
from matplotlib.textpath import TextPath
from matplotlib.transforms import Affine2D
from mpl_toolkits.mplot3d import proj3d

from .livefigure import LiveFigure

__all__ = ["RobotView", "RobotView3D", "RobotView2D", "robot_view", "triad_segments",
           "FrameLabels", "FrameLabels3D", "AXIS_COLORS", "default_q", "workspace_box"]

AXIS_COLORS = ("tab:red", "tab:green", "tab:blue")    # x, y, z
LINK_COLOR = "0.25"
EE_COLOR = "darkorange"
TRIAD_FRACTION = 0.06       # triad length as a fraction of the workspace's longest side


def default_q(robot) -> np.ndarray:
    """The zero pose, moved inside the joint limits where zero is outside them."""
    lo, hi = np.array([link.qlim for link in robot.links], dtype=float).T
    return np.clip(np.zeros(robot.n), lo, hi)


def workspace_box(robot, samples: int = 500) -> tuple:
    """Fixed axis limits (lo, hi), each of shape (3,), that the robot does not leave.

    The box holds every frame origin seen at ``samples`` random poses within
    the joint limits, plus a margin; no side is shorter than a quarter of the
    longest (a planar robot still gets some depth) and it never extends past
    the guaranteed bound ``robot.reach()`` around the base.
    """
    rng = np.random.default_rng(0)                     # the same limits every time
    qlo, qhi = np.array([link.qlim for link in robot.links], dtype=float).T
    poses = qlo + (qhi - qlo) * rng.random((samples, robot.n))
    frames = np.asarray(robot.frames(poses), dtype=float)
    if not np.allclose(np.asarray(robot.tool, dtype=float), np.eye(4)):
        frames = np.concatenate([frames, np.asarray(robot.fk(poses), dtype=float)[:, None]], axis=1)
    points = frames[..., :3, 3].reshape(-1, 3)
    lo, hi = points.min(axis=0), points.max(axis=0)
    longest = max(float((hi - lo).max()), 1e-9)
    center = (lo + hi) / 2
    half = np.maximum((hi - lo) / 2 + 0.1 * longest, 0.125 * longest)
    base, reach = frames[0, 0, :3, 3], float(robot.reach())
    lo = np.maximum(center - half, base - reach)
    hi = np.minimum(center + half, base + reach)
    return lo, hi


def triad_segments(frames: np.ndarray, length: float) -> list:
    """Line data for the triads of ``frames`` (m, 4, 4): one array per axis (x, y, z).

    Each array has shape (3m, 3): for every frame its origin, the tip of the
    axis (origin + length · axis) and a NaN row that breaks the line, so that
    one matplotlib line draws the same axis of every frame.

    >>> x, y, z = triad_segments(np.eye(4)[None], 2.0)
    >>> z[:2].tolist()
    [[0.0, 0.0, 0.0], [0.0, 0.0, 2.0]]
    """
    origins = frames[:, :3, 3]
    out = []
    for k in range(3):
        points = np.full((len(frames), 3, 3), np.nan)
        points[:, 0] = origins
        points[:, 1] = origins + length * frames[:, :3, k]
        out.append(points.reshape(-1, 3))
    return out


class FrameLabels(PathCollection):
    """All frame labels in one artist: the outlines of the texts, placed at points.

    Why not one ``Text`` per frame: Agg renders a ``Text`` glyph by glyph on
    every draw (about 0.8 ms each, 6 ms for the SSRMS's 8 frames); one
    collection of ready-made outlines draws all of them in about 0.3 ms.
    Labels of frames that share an origin (a spherical wrist) are stacked
    one under the other instead of printed on top of each other.
    """

    def __init__(self, ax, names, fontsize: float = 9, color="k", alpha: float = 1.0):
        self.names, self.fontsize = list(names), fontsize
        super().__init__(self._outlines([0] * len(names)), offsets=np.zeros((len(names), 2)),
                         offset_transform=ax.transData, facecolors=color, edgecolors="none",
                         alpha=alpha)
        # outlines are in points: 1/72 inch, then the figure's inches -> pixels
        self.set_transform(Affine2D().scale(1 / 72) + ax.figure.dpi_scale_trans)
        ax.add_collection(self, autolim=False)

    def _outlines(self, rows):
        # up-right of the point, row k lines lower
        return [_text_outline(name, self.fontsize, row) for name, row in zip(self.names, rows)]

    def set_points(self, points, tol: float = 1e-9) -> None:
        """Place label i at ``points[i]`` (data coordinates)."""
        points = np.asarray(points, dtype=float)
        self._place_offsets(points)
        self.set_paths(self._outlines(_rows_of_shared_points(points, tol)))

    def _place_offsets(self, points):
        self.set_offsets(points)

    def get_points(self) -> np.ndarray:
        return np.asarray(self.get_offsets(), dtype=float)


def _rows_of_shared_points(points, tol):
    """For each point, how many earlier points are at the same place."""
    rows = []
    for i, p in enumerate(points):
        rows.append(int(np.sum(np.linalg.norm(points[:i] - p, axis=1) <= tol)))
    return rows


_outline_cache: dict = {}


def _text_outline(name, fontsize, row):
    key = (name, fontsize, row)
    if key not in _outline_cache:
        _outline_cache[key] = TextPath((4, 3 - 1.25 * fontsize * row), name, size=fontsize)
    return _outline_cache[key]


class FrameLabels3D(FrameLabels):
    """:class:`FrameLabels` at 3D points, projected with the axes' current view."""

    def __init__(self, ax, names, **style):
        self._points3d = np.zeros((len(names), 3))
        super().__init__(ax, names, **style)

    def _place_offsets(self, points):
        self._points3d = points

    def get_points(self) -> np.ndarray:
        return self._points3d

    def do_3d_projection(self):
        # matplotlib's 3D axes call this before drawing, and so does draw()
        x, y, z = proj3d.proj_transform(*self._points3d.T, self.axes.M)
        self.set_offsets(np.column_stack([x, y]))
        return np.min(z) if len(z) else np.nan

    def draw(self, renderer):
        self.do_3d_projection()
        super().draw(renderer)


class RobotView:
    """What the 3D and the planar view share: the robot, its frames, ``update``.

    Subclasses make the artists (``_make_artists``) and move them (``_place``).
    """

    projection = None          # matplotlib projection of the axes: None (2D) or "3d"

    def __init__(self, robot, q=None, *, ax=None, live: LiveFigure | None = None,
                 triads: bool = True, labels: bool = True, color=LINK_COLOR,
                 alpha: float = 1.0, figsize=None, backend: str = "auto"):
        self.robot = robot
        self.box = workspace_box(robot)
        self.triad_length = TRIAD_FRACTION * float((self.box[1] - self.box[0]).max())
        self.has_tool = not np.allclose(np.asarray(robot.tool, dtype=float), np.eye(4))
        if ax is None:
            live = live or LiveFigure(figsize=figsize or self._figsize(), backend=backend)
            ax = live.figure.add_subplot(projection=self.projection)
            self.setup_axes(ax)
            self._fit(live.figure)
        self.ax, self.live = ax, live
        self.show_triads, self.show_labels = triads, labels
        self.artists = self._make_artists(color, alpha)
        if live is not None:
            live.add_moving(*self.artists)
        self.update(default_q(robot) if q is None else q, draw=False)

    # --- the public part --------------------------------------------------------
    def update(self, q, draw: bool = True) -> None:
        """Move the robot to ``q`` (radians / length units). ``draw=False`` only
        moves the artists (a panel updating several views draws once)."""
        frames = np.asarray(self.robot.frames(q), dtype=float)
        if self.has_tool:                 # the end effector is frame n moved by the tool
            frames = np.concatenate([frames, (frames[-1] @ self.robot.tool)[None]])
        self.q = np.array(q, dtype=float)
        self.frames = frames
        self._place(frames)
        if draw:
            self.draw()

    def draw(self) -> None:
        """Show the current pose (blitting when the view has a live figure)."""
        if self.live is not None:
            self.live.refresh()
        else:
            self.ax.figure.canvas.draw_idle()

    @property
    def figure(self):
        """The matplotlib Figure the view draws in."""
        return self.ax.figure

    @property
    def frame_labels(self) -> list:
        """``{S_0} … {S_n}`` (and ``{E}`` for a tool frame), as mathtext."""
        names = [rf"$\{{S_{{{i}}}\}}$" for i in range(self.robot.n + 1)]
        return names + [r"$\{E\}$"] if self.has_tool else names

    def _repr_mimebundle_(self, **kwargs):
        # A view alone in a cell shows its figure.
        return self.live.widget._repr_mimebundle_(**kwargs)

    # --- what subclasses provide ------------------------------------------------
    def _figsize(self):
        return (6, 6)

    def _fit(self, figure) -> None:
        """Fill a figure that holds only this view."""

    def setup_axes(self, ax) -> None:
        """Limits, labels and aspect of the axes (called for axes the view makes;
        call it yourself for axes you give it)."""
        raise NotImplementedError

    def _make_artists(self, color, alpha) -> list:
        raise NotImplementedError

    def _place(self, frames) -> None:
        raise NotImplementedError

    def _axis_label(self, name: str) -> str:
        unit = getattr(self.robot, "unit", "")
        return f"${name}_0$" + (f" [{unit}]" if unit else "")


class RobotView3D(RobotView):
    """The robot in a 3D axes with equal scaling, in a fixed box it cannot leave."""

    projection = "3d"

    def setup_axes(self, ax):
        (x0, y0, z0), (x1, y1, z1) = self.box
        ax.set(xlim=(x0, x1), ylim=(y0, y1), zlim=(z0, z1), xlabel=self._axis_label("x"),
               ylabel=self._axis_label("y"), zlabel=self._axis_label("z"))
        # equal scaling: a cube looks like a cube
        ax.set_box_aspect(self.box[1] - self.box[0])
        ax.figure.suptitle(self.robot.name, y=0.985, fontsize="medium")   # a 3D title can be clipped

    def _fit(self, figure):
        figure.subplots_adjust(left=0, right=0.92, bottom=0.02, top=0.97)

    def _make_artists(self, color, alpha):
        ax = self.ax
        self.link_line, = ax.plot([], [], [], "-o", color=color, lw=3, ms=4, alpha=alpha)
        self.axis_lines = [ax.plot([], [], [], "-", color=c, lw=2, alpha=alpha)[0]
                           for c in AXIS_COLORS] if self.show_triads else []
        self.ee_marker, = ax.plot([], [], [], "*", color=EE_COLOR, mec="k", ms=15, alpha=alpha)
        self.labels = FrameLabels3D(ax, self.frame_labels, alpha=alpha) if self.show_labels else None
        return [a for a in (self.link_line, *self.axis_lines, self.ee_marker, self.labels) if a]

    def _place(self, frames):
        origins = frames[:, :3, 3]
        self.link_line.set_data_3d(*origins.T)
        for line, points in zip(self.axis_lines, triad_segments(frames, self.triad_length)):
            line.set_data_3d(*points.T)
        self.ee_marker.set_data_3d(*origins[-1:].T)
        if self.labels:
            self.labels.set_points(origins, tol=1e-3 * self.triad_length)


class RobotView2D(RobotView):
    """The robot seen from above (+z towards you), for robots that stay in the xy plane.

    An axis that points out of the page is drawn as ⊙, into the page as ⊗,
    in its colour (so z is a blue ⊙ for the usual planar robot).
    """

    def _figsize(self):
        # a wide workspace (e.g. the P-R mechanism) gets a wide, short figure
        width, height = (self.box[1] - self.box[0])[:2]
        return (6, float(np.clip(6 * height / width + 0.8, 2.5, 6)))

    def setup_axes(self, ax):
        (x0, y0, _), (x1, y1, _) = self.box
        ax.set(xlim=(x0, x1), ylim=(y0, y1), xlabel=self._axis_label("x"),
               ylabel=self._axis_label("y"), aspect="equal", title=self.robot.name)
        ax.grid(True, alpha=0.3)

    def _fit(self, figure):
        figure.set_layout_engine("tight")

    def _make_artists(self, color, alpha):
        ax = self.ax
        self.link_line, = ax.plot([], [], "-o", color=color, lw=3, ms=5, alpha=alpha)
        self.axis_lines, self.out_marks, self.in_marks = [], [], []
        if self.show_triads:
            for c in AXIS_COLORS:
                self.axis_lines.append(ax.plot([], [], "-", color=c, lw=2, alpha=alpha)[0])
                self.out_marks.append(ax.plot([], [], ls="", marker=r"$\odot$", ms=13, color=c)[0])
                self.in_marks.append(ax.plot([], [], ls="", marker=r"$\otimes$", ms=13, color=c)[0])
        self.ee_marker, = ax.plot([], [], "*", color=EE_COLOR, mec="k", ms=15, alpha=alpha)
        self.labels = FrameLabels(ax, self.frame_labels, alpha=alpha) if self.show_labels else None
        return [a for a in (self.link_line, *self.axis_lines, *self.out_marks, *self.in_marks,
                            self.ee_marker, self.labels) if a]

    def _place(self, frames):
        origins = frames[:, :2, 3]
        self.link_line.set_data(*origins.T)
        segments = triad_segments(frames, self.triad_length)
        for k, line in enumerate(self.axis_lines):
            line.set_data(*segments[k][:, :2].T)
            out_of_page = frames[:, 2, k]                 # z component of axis k
            self.out_marks[k].set_data(*origins[out_of_page > 0.7].T)
            self.in_marks[k].set_data(*origins[out_of_page < -0.7].T)
        self.ee_marker.set_data(*origins[-1:].T)
        if self.labels:
            self.labels.set_points(origins, tol=1e-3 * self.triad_length)


def robot_view(robot, q=None, *, planar: bool | None = None, **options) -> RobotView:
    """A view of ``robot`` at ``q`` (default: zero, inside the joint limits).

    ``planar=None`` picks the 2D view for robots that stay in the xy plane
    (``robot.is_planar``) and the 3D view otherwise. Other options: ``ax`` and
    ``live`` (draw into an existing axes / live figure), ``triads``,
    ``labels``, ``color``, ``alpha``, ``figsize``, ``backend``.
    """
    if planar is None:
        planar = bool(getattr(robot, "is_planar", False))
    return (RobotView2D if planar else RobotView3D)(robot, q, **options)
