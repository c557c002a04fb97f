"""The teach panel: one slider per joint, the robot moving beside them, and the
end-effector pose and matrix read live.

>>> import dhlab
>>> from dhlab.views.panels.teach import teach   # also dhlab.teach, dhlab.views.teach
>>> panel = teach(dhlab.robots.ssrms())           # display it: last line of a cell
>>> panel.sliders[1].value = 30                   # degrees, exactly like dragging it
>>> round(float(panel.q[1]), 6)                   # the maths gets radians
0.523599

It works with ``%matplotlib widget`` (ipympl: the figure is interactive and
updates in place; you can rotate the 3D view) and with the default inline
backend (the figure is an image that is replaced on every move).
"""
from __future__ import annotations

import ipywidgets as widgets
import numpy as np

from ...errors import DHLabError
from ...i18n import _
from ...transforms import rpy
from ...validation import as_flag
from ..poses import checked_start, default_q, q_to_slider, slider_to_q
from ..view import robot_view
from ..viewbase import checked_robot
from .panel import Panel, follow_sliders, joint_sliders, view_controls

__all__ = ["teach", "TeachPanel", "pose_text", "matrix_html"]


def pose_text(T, unit: str = "") -> str:
    """The end-effector position and roll-pitch-yaw (degrees) of pose ``T``, as HTML.

    The numbers sit in cells of a fixed width (``x = …`` under its heading): a longer
    number never widens or re-wraps the readout, so the panel keeps its size while a
    slider moves.

    >>> import numpy as np
    >>> import re
    >>> print(" ".join(re.sub("<[^>]+>", " ", pose_text(np.eye(4), "m")).split()))  # doctest: +NORMALIZE_WHITESPACE
    End effector ( efector final ) position [m], roll-pitch-yaw [°]:
    x = 0.000 y = 0.000 z = 0.000 roll = 0.00 pitch = 0.00 yaw = 0.00
    """
    x, y, z = np.round(np.asarray(T, dtype=float)[:3, 3], 3) + 0.0    # + 0.0: no "-0.000"
    roll, pitch, yaw = np.round(np.degrees(rpy(T)), 2) + 0.0

    def row(cells):
        return "<tr>" + "".join(f'<td style="{_CELL}">{c}</td>' for c in cells) + "</tr>"
    return (_("<b>End effector</b> (<i>efector final</i>)<br>position [{unit}], roll-pitch-yaw [°]:").format(
                unit=unit or _("length"))
            + '<table style="border-collapse:collapse;table-layout:fixed">'
            + row([f"x = {x:.3f}", f"y = {y:.3f}", f"z = {z:.3f}"])
            + row([f"roll = {roll:.2f}", f"pitch = {pitch:.2f}", f"yaw = {yaw:.2f}"]) + "</table>")


MATRIX_CHARS = 8         # "-10.0000": a matrix cell's width; a robot in mm asks for more (TeachPanel)


_CELL = "width:7.6em;padding:0 .6em 0 0;white-space:nowrap;font-variant-numeric:tabular-nums"


def matrix_html(T, title: str = "<sup>0</sup>T<sub>n</sub>", chars: int = MATRIX_CHARS) -> str:
    """A 4x4 matrix as a small HTML table, rotation and translation parts visible.

    Every cell is ``chars`` characters wide (monospace, fixed table layout): the table keeps its
    size whatever the numbers, so the panel does not move while a slider does."""
    rows = []
    for i, row in enumerate(np.round(np.asarray(T, dtype=float), 4) + 0.0):   # no "-0.0000"
        cells = "".join(
            f'<td style="width:{chars}ch;padding:0 .5em;text-align:right;white-space:nowrap;'
            f'{"border-left:1px solid #999;" if j == 3 else ""}">'
            f"{v:.4f}</td>" for j, v in enumerate(row))
        rows.append(f'<tr style="{"border-top:1px solid #999;" if i == 3 else ""}">{cells}</tr>')
    # the title is one line whatever its length (a step-through's names the motions done so far)
    return (f'<div style="white-space:nowrap">{title} =</div>'
            f'<table style="font-family:monospace;border-collapse:collapse;'
            f'table-layout:fixed">{"".join(rows)}</table>')


def matrix_chars(robot) -> int:
    """How many characters the widest number of ``robot``'s end-effector matrix takes
    (its reach, negative, with 4 decimals; at least :data:`MATRIX_CHARS`)."""
    reach = getattr(robot, "reach", None)
    if not callable(reach):
        return MATRIX_CHARS
    return max(MATRIX_CHARS, len(f"{-float(reach()):.4f}"))


class TeachPanel(Panel):
    """The widget returned by :func:`teach`.

    Attributes: ``sliders`` (one per joint, display units), ``figure`` (the
    matplotlib Figure), ``view`` (the :class:`~dhlab.views.view.RobotView`),
    ``readout`` and ``matrix`` (HTML widgets), ``q`` (radians / length units).
    """

    def __init__(self, robot, q=None, *, on_change=None, planar=None, figsize=None,
                 backend: str = "auto", controls: bool = True, **view_options):
        self.robot = checked_robot(robot)
        if on_change is not None and not callable(on_change):
            raise DHLabError(_("on_change must be a function of q (or None), got {value}.").format(
                value=f"{on_change!r:.60}"))
        self.on_change = on_change
        controls = as_flag(controls, "controls")
        q = default_q(robot) if q is None else checked_start(robot, q)
        rows, self.sliders = joint_sliders(robot, q)
        self._chars = matrix_chars(self.robot)
        self.view = robot_view(robot, q, planar=planar, figsize=figsize, backend=backend,
                               **view_options)
        live = self.view.live
        self.readout = widgets.HTML()
        self.matrix = widgets.HTML()
        extra = view_controls(self.view, run=lambda action, value: self.run(action, value)) \
            if controls else []
        title = widgets.HTML(_("<b>{name}</b>: joints (<i>articulaciones</i>)").format(name=robot.name))
        super().__init__(live, [title, *rows, self.readout, self.matrix, *extra])
        self._refresh()
        self.observe_values(self.sliders, self._refresh)
        follow_sliders(self.view, self.sliders)

    @property
    def q(self) -> np.ndarray:
        """The joint vector the sliders show (radians / length units)."""
        return slider_to_q(self.robot, self.sliders)

    def set_q(self, q) -> None:
        """Move every slider (q in radians / length units, one value per joint,
        within the limits) and redraw once."""
        q = checked_start(self.robot, q)
        self._quiet = True
        try:
            for link, slider, value in zip(self.robot.links, self.sliders, q):
                slider.value = q_to_slider(link, value)
        finally:
            self._quiet = False
        self.run(self._refresh)

    _quiet = False

    def _refresh(self) -> None:
        if self._quiet:
            return
        q = self.q
        self.view.update(q, draw=False)
        T = self.view.frames[-1]          # the end effector: the view has just computed it
        self.readout.value = pose_text(T, getattr(self.robot, "unit", ""))
        self.matrix.value = matrix_html(T, f"<sup>0</sup>T<sub>{self.robot.n}</sub>", self._chars)
        if self.on_change is not None:
            self.on_change(q)             # before the draw: a callback may move its own artists
        self.view.draw()                  # one draw per update

    def __repr__(self):
        return _("<dhlab teach panel: {name}, {n} joints>").format(name=self.robot.name, n=self.robot.n)


def teach(robot, q=None, *, on_change=None, planar=None, figsize=None,
          backend: str = "auto", controls: bool = True, **view_options) -> TeachPanel:
    """A teach panel for ``robot``: sliders (revolute in degrees, prismatic in
    length units, within the joint limits), the robot view, and the live
    end-effector pose and 4x4 matrix.

    ``q``: the starting pose (radians / length units; default zero, clipped to
    the limits). ``on_change(q)``: called after every move, just before the
    figure is drawn, e.g. to check an exercise (its errors are shown in the
    panel) or to move artists of your own (add them with
    ``panel.view.live.add_moving``; no extra draw is needed). ``planar``: force the 2D
    (True) or 3D (False) view. ``figsize``: inches (default from the
    workspace's shape; at least 4.5 in at 100 dpi, see
    :func:`dhlab.views.figures.new_figure`). ``backend``: 'auto', 'ipympl' or
    'image'. ``controls``: show the camera presets, zoom and label toggles.
    Other keyword options go to the view (:func:`~dhlab.views.view.robot_view`):
    ``labels``, ``joint_axes``, ``camera``, ``zoom``, ``title``, ``framing``,
    ``color``, ``alpha``.
    """
    return TeachPanel(robot, q, on_change=on_change, planar=planar, figsize=figsize,
                      backend=backend, controls=controls, **view_options)
