"""What every robot view shares: the robot, its pose, its frames and mechanism, ``update``.

The 3D view is :mod:`~dhlab.views.view3d`, the planar one :mod:`~dhlab.views.view2d`;
:func:`~dhlab.views.view.robot_view` picks one.
"""
from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.colors import is_color_like
from mpl_toolkits.mplot3d import Axes3D

from ..errors import DHLabError
from ..i18n import _
from ..validation import as_choice, as_flag, as_number, as_text, describe
from . import framing
from .live.livefigure import LiveFigure
from .mechanism import Mechanism
from .poses import checked_start, default_q, one_pose
from .triads import axis_colors, letter_points

__all__ = ["RobotView", "checked_robot", "workspace_box", "typical_size",
           "line_in_box", "LINK_COLOR", "EE_COLOR", "JOINT_AXIS_COLOR", "TRIAD_FRACTION", "STYLES", "LETTER_SIZE"]

LINK_COLOR = "0.25"
EE_COLOR = "darkorange"
JOINT_AXIS_COLOR = "0.55"
TRIAD_FRACTION = 0.13       # triad length as a fraction of the robot's typical size
LINK_FRACTION = 0.25        # ... and at least this fraction of its typical link
MAX_LIMIT = 1e6             # a joint limit beyond this cannot be drawn (1e308 is "no limit")
STYLES = ("mechanism", "stick")
LETTER_SIZE = 9             # points: the x, y, z at the tips of the triads


def checked_robot(robot):
    """``robot`` if it is a dhlab robot with finite joint limits a view can sample,
    else a DHLabError saying what is wrong."""
    if not all(hasattr(robot, name) for name in ("links", "frames", "n", "tool")):
        raise DHLabError(_("expected a dhlab robot (dhlab.DHRobot or dhlab.Robot), got {type} {value}.").format(
            type=type(robot).__name__, value=f"{robot!r:.60}"))
    if robot.n < 1:
        raise DHLabError(_("the robot has no joints: nothing to move."))
    for j, link in enumerate(robot.links):
        lo, hi = (float(v) for v in link.qlim)
        if not (np.isfinite(lo) and np.isfinite(hi)) or max(abs(lo), abs(hi)) > MAX_LIMIT:
            raise DHLabError(_("joint {j}'s limits ({lo:g}, {hi:g}) are too wide to draw a slider or a workspace; "
                               "give the robot finite limits, e.g. qlim=(0, 1) for a prismatic joint.").format(
                                   j=j + 1, lo=lo, hi=hi))
    return robot


def workspace_box(robot, samples: int = 500) -> tuple:
    """Axis limits (lo, hi), each of shape (3,), that the robot does not leave.

    The box holds every frame origin seen at ``samples`` random poses within
    the joint limits, plus a margin; no side is shorter than a quarter of the
    longest (a planar robot still gets some depth) and it never extends past
    the guaranteed bound ``robot.reach()`` around the base. A robot whose
    origins all coincide gets a unit box.
    """
    rng = np.random.default_rng(0)                     # the same limits every time
    qlo, qhi = np.array([link.qlim for link in robot.links], dtype=float).T
    poses = qlo + (qhi - qlo) * rng.random((samples, robot.n))
    frames = np.asarray(robot.frames(poses), dtype=float)
    if not np.allclose(np.asarray(robot.tool, dtype=float), np.eye(4)):
        frames = np.concatenate([frames, np.asarray(robot.fk(poses), dtype=float)[:, None]], axis=1)
    points = frames[..., :3, 3].reshape(-1, 3)
    lo, hi = points.min(axis=0), points.max(axis=0)
    longest = float((hi - lo).max())
    if not longest > 1e-9:                              # every origin at one place
        return lo - 1.0, hi + 1.0
    center = (lo + hi) / 2
    half = np.maximum((hi - lo) / 2 + 0.1 * longest, 0.125 * longest)
    base, reach = frames[0, 0, :3, 3], max(float(robot.reach()), longest)
    lo = np.maximum(center - half, base - reach)
    hi = np.minimum(center + half, base + reach)
    return lo, hi


def typical_size(robot, samples: int = 200) -> float:
    """The median, over random poses within the joint limits, of the longest side of
    the box around the robot's frame origins (1.0 for a robot without size)."""
    rng = np.random.default_rng(1)
    qlo, qhi = np.array([link.qlim for link in robot.links], dtype=float).T
    origins = np.asarray(robot.frames(qlo + (qhi - qlo) * rng.random((samples, robot.n))),
                         dtype=float)[..., :3, 3]
    size = float(np.median(np.ptp(origins, axis=1).max(axis=1)))
    return size if size > 1e-9 else 1.0


def triad_length(robot, size: float) -> float:
    """How long a triad is drawn: a fraction of the robot's size, and at least a quarter of its
    typical link, so that a two-link arm's frames read as well as a seven-joint arm's."""
    origins = np.asarray(robot.frames(default_q(robot)), dtype=float)[:, :3, 3]
    links = np.linalg.norm(np.diff(origins, axis=0), axis=1)
    links = links[links > 1e-6 * size]
    return max(TRIAD_FRACTION * size, LINK_FRACTION * float(np.median(links)) if len(links) else 0.0)


def points_along(path, t=(0.25, 0.5, 0.75)) -> np.ndarray:
    """Points at fractions ``t`` of every segment of ``path`` (p, 3); NaN rows break the path."""
    a, b = path[:-1], path[1:]
    whole = np.isfinite(a).all(axis=1) & np.isfinite(b).all(axis=1)
    a, b = a[whole], b[whole]
    return (a[None] + np.asarray(t, dtype=float)[:, None, None] * (b - a)[None]).reshape(-1, 3)


def line_in_box(point, direction, lo, hi) -> np.ndarray:
    """The two ends of the piece of the line ``point + t·direction`` inside the box
    [lo, hi] (matplotlib's 3D axes do not clip lines at their limits)."""
    t_lo, t_hi = -np.inf, np.inf
    for p, v, a, b in zip(point, direction, lo, hi):
        if abs(v) > 1e-12:
            t1, t2 = sorted(((a - p) / v, (b - p) / v))
            t_lo, t_hi = max(t_lo, t1), min(t_hi, t2)
        elif not a <= p <= b:
            return np.full((2, len(point)), np.nan)
    if not t_lo <= t_hi:
        return np.full((2, len(point)), np.nan)
    return np.array([point + t_lo * direction, point + t_hi * direction])


class RobotView:
    """What the 3D and the planar view share: the robot, its frames, ``update``.

    Options: ``style`` ('mechanism': joints as cylinders and sleeves, links along
    their d and a segments, a gripper; 'stick': lines from origin to origin),
    ``triads``, ``labels`` (frame labels and the x/y/z letters at the triads' tips)
    and ``joint_axes`` (what is drawn), ``palette`` ('seed' or 'colorblind'; default
    :func:`dhlab.views.triads.set_palette`'s),
    ``framing`` ('follow': the limits follow the robot; 'fixed': the whole
    workspace), ``camera`` (3D: 'iso', 'front', 'side', 'top'), ``zoom``
    (1 = the robot fills its view), ``title`` (default the robot's name;
    ``False`` for none), ``color``/``alpha`` (a faint "ghost" robot),
    ``figsize``/``backend`` (for the figure the view makes), ``ax``/``live``
    (draw into an existing axes / live figure).
    """

    projection = None          # matplotlib projection of the axes: None (2D) or "3d"

    def __init__(self, robot, q=None, *, ax=None, live: LiveFigure | None = None,
                 triads: bool = True, labels: bool = True, joint_axes: bool = False,
                 color=LINK_COLOR, alpha: float = 1.0, figsize=None, backend: str = "auto",
                 framing: str = "follow", camera: str = "iso", zoom: float = 1.0, title=None,
                 style: str = "mechanism", palette: str | None = None):
        self.robot = checked_robot(robot)
        self.framing = as_choice(framing, ("follow", "fixed"), "framing")
        self.camera = as_choice(camera, ("iso", "front", "side", "top"), "camera")
        self.zoom = self._checked_zoom(zoom)
        self.title = robot.name if title is None else ("" if title is False else as_text(title, "title"))
        color, alpha = _checked_color(color), _checked_alpha(alpha)
        self._check_drawing_place(ax, live)
        self.style = as_choice(style, STYLES, "style")
        self.colors = axis_colors(palette)
        self.box = workspace_box(robot)
        size = typical_size(robot)
        self.triad_length = triad_length(robot, size)
        self.has_tool = not np.allclose(np.asarray(robot.tool, dtype=float), np.eye(4))
        # a robot that is not a chain of elementary motions (no numeric_links) is drawn as a stick figure
        drawable = hasattr(robot, "numeric_links")
        self.mechanism = Mechanism(robot, size) if self.style == "mechanism" and drawable else None
        self.shape = None                     # the mechanism at the current pose
        self.show_triads = as_flag(triads, "triads")
        self._labels_on = as_flag(labels, "labels")
        self._joint_axes_on = as_flag(joint_axes, "joint_axes")
        self.q = checked_start(robot, q)     # within the joint limits, as teach() and its sliders
        self._set_pose(self.q)
        self.limits = None                    # (lo, hi) of the current frame, when framed
        self._reframed = False
        if ax is None:
            live = live or LiveFigure(figsize=self._figsize() if figsize is None else figsize, backend=backend)
            ax = live.figure.add_subplot(projection=self.projection)
            self.ax, self.live = ax, live
            self._fit(live.figure)
            self.setup_axes(ax)
        self.ax, self.live = ax, live
        self.artists = self._make_artists(color, alpha)
        if live is not None:
            live.add_moving(*self.artists)
        self.update(self.q, draw=False)

    # --- the public part --------------------------------------------------------
    def update(self, q, draw: bool = True) -> None:
        """Move the robot to ``q`` (radians / length units). ``draw=False`` only
        moves the artists (a panel updating several views draws once)."""
        if draw is not True and draw is not False:      # the panels pass a bool: no check on their path
            draw = as_flag(draw, "draw")
        self.q = one_pose(self.robot, q)
        self._set_pose(self.q)
        if self.limits is not None and self.framing == "follow" and framing.needs_reframe(
                self.ax, self.framed_points()):
            if self.live is not None and self.live.in_motion() and not (
                    self.live.may_redraw() and framing.leaves_view(self.ax, self.framed_points())):
                # the browser is moving the picture itself (canvas backend): a new frame costs a
                # full redraw, so while it moves only a robot leaving the picture is framed again,
                # and at most every REDRAW_EVERY_S; the rest (a robot grown small, back home)
                # once it stops
                self.live.when_at_rest(self, self._reframe_at_rest)
            else:
                self.reframe()
        self._place(self.frames)
        if draw:
            self.draw()

    def draw(self) -> None:
        """Show the current pose (blitting when the view has a live figure; a full
        redraw when the frame has just changed)."""
        if self.live is not None:
            if self._reframed:
                self._reframed = False
                self.live.redraw()
            else:
                self.live.refresh()
        else:
            self.ax.figure.canvas.draw_idle()

    def _reframe_at_rest(self) -> None:
        if framing.needs_reframe(self.ax, self.framed_points()):
            self.reframe()
            self._place(self.frames)
            self.draw()

    def reframe(self) -> None:
        """Fit the axes to the robot where it is now (the next draw redraws everything)."""
        self.limits = self._frame_limits(self.ax)
        self._reframed = True

    def set_zoom(self, zoom: float, draw: bool = True) -> None:
        """Zoom the view: 1 frames the robot, 2 shows it twice as large."""
        self.zoom = self._checked_zoom(zoom)
        self._refit(draw)

    def set_camera(self, preset: str = "iso", draw: bool = True) -> None:
        """3D only: 'iso' (the view where every triad reads), 'front', 'side' or 'top'."""
        self.camera = as_choice(preset, ("iso", "front", "side", "top"), "camera")
        self._camera_set = None
        self._refit(draw)

    def show_labels(self, on: bool = True, draw: bool = True) -> None:
        """Show or hide the frame labels."""
        self._labels_on = as_flag(on, "on")
        if self.labels is not None:
            self.labels.set_visible(self._labels_on)
        for mark in self.letter_marks:
            mark.set_visible(self._labels_on)
        if draw:
            self.draw()

    def show_joint_axes(self, on: bool = True, draw: bool = True) -> None:
        """Show or hide the joint axes (dashed lines along z_(i-1))."""
        self._joint_axes_on = as_flag(on, "on")
        if self.joint_axes_line is not None:
            self.joint_axes_line.set_visible(self._joint_axes_on)
            self._place(self.frames)
        if draw:
            self.draw()

    @property
    def figure(self):
        """The matplotlib Figure the view draws in."""
        return self.ax.figure

    @property
    def frame_labels(self) -> list:
        """``{S_0} … {S_n}`` (and ``{E}`` for a tool frame), as mathtext."""
        names = [rf"$\{{S_{{{i}}}\}}$" for i in range(self.robot.n + 1)]
        return names + [r"$\{E\}$"] if self.has_tool else names

    def extent_fraction(self) -> float:
        """How much of its axes the robot's frame origins span now (see framing)."""
        return framing.extent_fraction(self.ax, self.framed_points())

    def _repr_mimebundle_(self, **kwargs):
        # A view alone in a cell shows its figure.
        return self.live.widget._repr_mimebundle_(**kwargs)

    # --- helpers ----------------------------------------------------------------
    def _frames_at(self, q) -> np.ndarray:
        frames = np.asarray(self.robot.frames(q), dtype=float)
        if self.has_tool:                 # the end effector is frame n moved by the tool
            frames = np.concatenate([frames, (frames[-1] @ self.robot.tool)[None]])
        return frames

    def _set_pose(self, q) -> None:
        self.frames = self._frames_at(q)
        if self.mechanism is not None:
            self.shape = self.mechanism.shape(self.frames, q)

    def framed_points(self) -> np.ndarray:
        """What must stay in sight, (N, 3) in the world: the origins, and the mechanism's links,
        joints and gripper (what the view frames, see :mod:`dhlab.views.framing`)."""
        return self.shape.points if self.shape is not None else self.frames[:, :3, 3]

    def _refit(self, draw):
        if self.limits is not None:
            self.limits = self._frame_limits(self.ax)
            self._reframed = True
            self._place(self.frames)
        if draw:
            self.draw()

    def _check_drawing_place(self, ax, live) -> None:
        """``live`` a LiveFigure, ``ax`` an Axes of this view's kind (3D or 2D), or None."""
        if live is not None and not isinstance(live, LiveFigure):
            raise DHLabError(_("live must be a dhlab LiveFigure (or None), got {value}.").format(value=describe(live)))
        three_d = self.projection == "3d"
        if ax is not None and (not isinstance(ax, Axes) or isinstance(ax, Axes3D) != three_d):
            kind = ("3D Axes, e.g. figure.add_subplot(projection='3d')" if three_d else
                    "2D Axes, e.g. figure.add_subplot() (or pass planar=False for a 3D view)")
            raise DHLabError(_("ax must be a matplotlib {kind}; got {value}.").format(kind=kind, value=describe(ax)))

    @staticmethod
    def _checked_zoom(zoom):
        zoom = as_number(zoom, "zoom")
        if not 0.2 <= zoom <= 5:
            raise DHLabError(_("zoom must be between 0.2 and 5 (1: the robot fills its view), got {zoom:g}.").format(
                zoom=zoom))
        return zoom

    def _strokes(self, frames) -> np.ndarray:
        """Points along the links (the mechanism's d and a segments, or the stick figure), on the
        joints' solids and the gripper, and along the triads and their letters: what labels keep off."""
        pieces = [points_along(self.shape.path if self.shape is not None else frames[:, :3, 3])]
        if self.shape is not None:
            pieces.append(self.shape.outline)
        if self.show_triads:
            origins, axes = frames[:, None, :3, 3], frames[:, :3, :3].transpose(0, 2, 1)   # axes[m, k] = axis k
            pieces += [(origins + s * self.triad_length * axes).reshape(-1, 3) for s in (0.5, 1.0)]
            if self._labels_on:                       # the letters at the tips
                pieces += letter_points(frames, self.triad_length)
        return np.vstack(pieces)

    def _joint_axis_points(self, lo, hi) -> np.ndarray:
        """Long dashed lines through origin i-1 along z_(i-1), i = 1…n, inside the box."""
        pieces = []
        for frame in self.frames[:self.robot.n]:
            pieces += [*line_in_box(frame[:3, 3], frame[:3, 2], lo, hi), np.full(3, np.nan)]
        return np.array(pieces)

    # --- what subclasses provide ------------------------------------------------
    def _figsize(self):
        return (5.6, 5.6)

    def _fit(self, figure) -> None:
        """Fill a figure that holds only this view."""

    def setup_axes(self, ax) -> None:
        """Limits, labels, title, camera and aspect of the axes (called for axes the
        view makes; call it yourself for axes you give it)."""
        raise NotImplementedError

    def _frame_limits(self, ax):
        raise NotImplementedError

    def _make_artists(self, color, alpha) -> list:
        raise NotImplementedError

    def _place(self, frames) -> None:
        raise NotImplementedError

    def _axis_label(self, name: str) -> str:
        unit = getattr(self.robot, "unit", "")
        return f"${name}_0$" + (f" [{unit}]" if unit else "")


def _checked_color(color):
    if not is_color_like(color):
        raise DHLabError(_("color must be a matplotlib colour, e.g. 'tab:blue', '0.25' (grey) or (0.2, 0.4, 0.6); "
                           "got {value}.").format(value=describe(color)))
    return color


def _checked_alpha(alpha) -> float:
    alpha = as_number(alpha, "alpha")
    if not 0 <= alpha <= 1:
        raise DHLabError(_("alpha must be from 0 (invisible) to 1 (opaque), e.g. 0.45 for a faint robot; got "
                           "{alpha:g}.").format(alpha=alpha))
    return alpha
