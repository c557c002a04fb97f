"""Views of a robot that move in place.

A view draws, for a joint vector ``q``:

* the mechanism (:mod:`~dhlab.views.mechanism`): the links (*eslabones*) along their
  translations — d along z_(i-1), then a along x_i, so offsets and common normals
  show — revolute joints (*articulaciones*) as cylinders on their axes, prismatic
  ones as sleeves whose length is the joint's value, and a gripper at the end
  effector (*efector final*), marked by an orange star; ``style='stick'`` draws
  the plain stick figure instead (lines from origin to origin, a dot at each);
* a right-handed (*dextrógiro*) triad at every frame: **x red, y green, z blue**
  (seed 000, figure 10) with the letters x, y, z at the tips
  (:mod:`~dhlab.views.triads`; ``palette='colorblind'`` for a red and green that
  differ in lightness too), labelled ``{S_0} … {S_n}``; frames at one place share
  one label (``{S_4,S_5,S_6}``) and labels never overlap (:mod:`~dhlab.views.labels`);
* a tool frame, when the robot has one, with its own triad labelled ``{E}``;
* optionally (``joint_axes=True``) the joint axes as long dashed lines through
  each origin along z_(i-1), as the seeds draw them: parallel axes show at once.

The robot fills its view (:mod:`~dhlab.views.framing`): the limits follow the
robot's configuration, with hysteresis so that the axes do not jump on every
step. ``view.update(q)`` only moves the artists; the cached picture of the
axes (:mod:`~dhlab.views.live.livefigure`) is redrawn only when the frame changes.

>>> import dhlab
>>> robot = dhlab.robots.ssrms()
>>> view = robot_view(robot)                 # 3D; a planar robot gets a 2D view
>>> view.update(dhlab.deg2rad([0, 30, 0, 0, 0, 0, 0]))
>>> view.frames.shape                        # the frames drawn last (n+1, 4, 4)
(8, 4, 4)
>>> view.set_camera("top"); view.set_zoom(1.5); view.show_labels(False)
"""
from __future__ import annotations

from ..validation import as_flag
from .labels import FrameLabels, FrameLabels3D
from .poses import default_q, one_pose
from .triads import AXIS_COLORS, triad_segments
from .view2d import RobotView2D
from .view3d import RobotView3D
from .viewbase import STYLES, RobotView, checked_robot, line_in_box, workspace_box

# robot_view() and the names a script once found beside it: the old path ``dhlab.view`` (see
# dhlab.moved) offered them all from one module, so they stay importable from here. Code in the
# package imports each from where it lives (viewbase, labels, triads, poses).
__all__ = ["RobotView", "RobotView3D", "RobotView2D", "robot_view", "triad_segments",
           "FrameLabels", "FrameLabels3D", "AXIS_COLORS", "default_q", "workspace_box",
           "checked_robot", "one_pose", "line_in_box", "STYLES"]


def robot_view(robot, q=None, *, planar: bool | None = None, **options) -> RobotView:
    """A view of ``robot`` at ``q`` (default: zero, inside the joint limits; a ``q``
    outside them is refused, as by :func:`~dhlab.views.panels.teach.teach`).

    ``planar=None`` picks the 2D view for robots that stay in the xy plane
    (``robot.is_planar``) and the 3D view otherwise. Other options (keyword
    only): ``ax`` and ``live`` (draw into an existing axes / live figure; call
    ``view.setup_axes(ax)`` to let the view set limits, labels and title),
    ``triads``, ``labels``, ``joint_axes``, ``framing``, ``camera``, ``zoom``,
    ``title`` (text, or False for none), ``color`` (a matplotlib colour),
    ``alpha`` (0 … 1), ``figsize``, ``backend``.
    """
    checked_robot(robot)
    if planar is None:
        planar = bool(getattr(robot, "is_planar", False))
    return (RobotView2D if as_flag(planar, "planar") else RobotView3D)(robot, q, **options)
