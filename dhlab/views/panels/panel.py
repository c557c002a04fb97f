"""What every interactive panel shares: joint sliders in display units, errors
shown to the user, and cleaning up when its notebook cell runs again.

Units (one rule everywhere): a revolute joint's slider is in **degrees**, a
prismatic joint's slider in the robot's **length unit**; the maths gets
radians (:mod:`dhlab.views.poses` converts).

>>> import dhlab
>>> robot = dhlab.robots.pr_mechanism()
>>> rows, sliders = joint_sliders(robot, [0.25, dhlab.deg2rad(30)])
>>> [s.description for s in sliders], [round(s.value, 6) for s in sliders]
(['q1', 'q2'], [0.25, 30.0])
>>> slider_to_q(robot, sliders).round(6).tolist()
[0.25, 0.523599]
"""
from __future__ import annotations

import html
import traceback

import ipywidgets as widgets
import numpy as np

from ...i18n import _
from ..figures import projector_scale
from ..live.keys import FIGURE_CLASS, slider_keys
from ..live.livefigure import LiveFigure, forget_previous_run
from ..live.rig import Rig
from ..poses import checked_start, q_to_slider, slider_to_q, unit_of
from ..projector import widgets_scale

__all__ = ["Panel", "joint_sliders", "slider_to_q", "q_to_slider", "unit_of", "checked_start", "follow_sliders",
           "view_controls", "SliderEchoes"]

REVOLUTE_STEP_DEG = 0.5
PRISMATIC_STEPS = 1000         # a prismatic slider's range is cut into this many steps
SLIDER_PX, SIDE_PX, ERROR_PX = 330, 370, 520   # widths at normal size: a slider, the controls, an error


def control_width(px: float) -> str:
    """A control's width: ``px`` at normal size, wider under :func:`dhlab.projector` (as its
    widgets' text), so that a panel made afterwards never squeezes a slider or a readout."""
    return f"{px * widgets_scale(projector_scale()):g}px"


def follow_sliders(view, sliders) -> None:
    """With the canvas backend, let the browser move ``view``'s robot as soon as one of the
    joint ``sliders`` moves, before the kernel's picture arrives (see :mod:`dhlab.views.live.rig`;
    the browser converts the slider's display units with the same rule as :func:`slider_to_q`)."""
    live = view.live
    if live is None or live.backend != "canvas":
        return
    live.rig = Rig(view, sliders, [np.pi / 180 if link.is_revolute else 1.0 for link in view.robot.links])


def joint_sliders(robot, q, labels=None):
    """One slider per joint, within the joint limits, labelled as the DH table numbers
    the joints (``robot.joint_labels``). Returns (rows to display, sliders):
    each row is the slider followed by its unit."""
    labels = labels or list(getattr(robot, "joint_labels", [f"q{i + 1}" for i in range(robot.n)]))
    rows, sliders = [], []
    for link, label, value in zip(robot.links, labels, q):
        lo, hi = (q_to_slider(link, v) for v in link.qlim)
        step = REVOLUTE_STEP_DEG if link.is_revolute else (hi - lo) / PRISMATIC_STEPS
        slider = widgets.FloatSlider(
            value=float(np.clip(q_to_slider(link, value), lo, hi)), min=lo, max=hi, step=step,
            description=label, continuous_update=True,
            readout_format=".1f" if link.is_revolute else ".3f",
            tooltip="{}: {}".format(label, _("revolute, degrees") if link.is_revolute else _("prismatic, length")),
            style={"description_width": "3em"}, layout=widgets.Layout(width=control_width(SLIDER_PX)))
        sliders.append(slider)
        rows.append(widgets.HBox([slider, widgets.Label(unit_of(robot, link))]))
    return rows, sliders


def view_controls(view, run=None) -> list:
    """The controls of a robot view, as widgets: camera presets (3D: iso, front,
    side, top) and zoom, labels on/off, joint axes on/off (3D). Each change
    redraws the view; ``run(action, value)`` (e.g. a panel's :meth:`Panel.run`,
    which shows errors) calls the view's method."""
    def changed(action):
        def observer(change):
            (run or (lambda f, *args: f(*args)))(action, change["new"])
        return observer

    rows = []
    if view.projection == "3d":
        camera = widgets.ToggleButtons(options=["iso", "front", "side", "top"], value=view.camera,
                                       description=_("view"), tooltips=[
                                           _("oblique: every triad reads"), _("looking along +y"),
                                           _("looking along -x"), _("looking down -z")],
                                       style={"description_width": "3em", "button_width": "4.2em"})
        camera.observe(changed(view.set_camera), names="value")
        rows.append(camera)
    zoom = widgets.FloatSlider(value=view.zoom, min=0.5, max=3.0, step=0.05, description=_("zoom"),
                               readout_format=".2f", continuous_update=False,
                               style={"description_width": "3em"},
                               layout=widgets.Layout(width=control_width(SLIDER_PX)))
    zoom.observe(changed(view.set_zoom), names="value")
    rows.append(zoom)
    toggles = []
    if view.labels is not None:
        labels = widgets.Checkbox(value=view.labels.get_visible(), description=_("frame labels"),
                                  indent=False, layout=widgets.Layout(width="auto"))
        labels.observe(changed(view.show_labels), names="value")
        toggles.append(labels)
    if getattr(view, "joint_axes_line", None) is not None:
        axes = widgets.Checkbox(value=view.joint_axes_line.get_visible(), indent=False,
                                description=_("joint axes (z of each joint)"),
                                layout=widgets.Layout(width="auto"))
        axes.observe(changed(view.show_joint_axes), names="value")
        toggles.append(axes)
    if toggles:
        rows.append(widgets.HBox(toggles))
    return rows


class SliderEchoes:
    """Tells a student's slider move from the browser's echo of a value the panel set.

    When the kernel sets a slider to a value between two of its steps, the browser
    rounds it to a step and sends the rounded value back. That echo may arrive late:
    during Run All, after a later cell has moved the panel again. A panel whose
    sliders are coupled (the joints and the target of :func:`~dhlab.views.panels.spaces.spaces`)
    that took a late echo for a student's move would move the robot back, set the
    other sliders, get *their* echoes, and so on: the panel drifted on its own.

    :meth:`set` sets a slider and remembers the value; :meth:`classify` says what a
    new value of the slider is: ``"echo"`` (the browser's rounding of the value the
    panel set last: nothing to do), ``"late"`` (the rounding of an older value: the
    panel's own value is sent again, so the browser shows it) or ``"student"``.

    >>> import ipywidgets as widgets
    >>> slider, echoes = widgets.FloatSlider(min=0, max=1, step=0.01), SliderEchoes()
    >>> echoes.set(slider, 0.3333); echoes.set(slider, 0.5)
    >>> slider.value = 0.33                   # the browser's rounding of 0.3333, after 0.5 was set
    >>> echoes.classify(slider), slider.value
    ('late', 0.5)
    >>> slider.value = 0.8
    >>> echoes.classify(slider)
    'student'
    """

    def __init__(self):
        self._expected = {}          # id(slider) -> values the panel set, oldest first
        self.setting = False         # True while the panel sets a slider (its observers ignore it)

    def set(self, slider, value) -> None:
        """Set ``slider`` to ``value`` (clipped to its range) as the panel, not the student."""
        value = float(np.clip(value, slider.min, slider.max))
        if value == slider.value:
            return                                    # no message to the browser, no echo
        expected = self._expected.setdefault(id(slider), [])
        if not expected or expected[-1] != value:
            expected.append(value)
        del expected[:-8]                             # echoes older than 8 settings never come
        self.setting = True
        try:
            slider.value = value
        finally:
            self.setting = False

    def expect(self, slider) -> None:
        """The slider's current value was set by the panel (e.g. when it was made)."""
        self._expected[id(slider)] = [float(slider.value)]

    def classify(self, slider) -> str:
        value, expected = float(slider.value), self._expected.get(id(slider), [])
        half_step = float(slider.step) / 2 * (1 + 1e-9) + 1e-12
        for k, mine in enumerate(expected):
            if abs(value - mine) <= half_step:
                current = expected[-1]
                del expected[:k + 1]                  # this echo, and the older ones, will not come
                if not expected:                      # it was the last value set: a plain echo
                    return "echo"
                self.set(slider, current)             # a late echo: show the panel's value again
                return "late"
        expected.clear()
        return "student"


class Panel(widgets.HBox):
    """A figure on the left, controls on the right (or under it: ``below=True``);
    the base of the course's panels.

    ``run(action, *args)`` calls ``action`` and, if it raises, shows the error
    in red under the controls (and keeps it in ``panel.error``) before raising
    it again: from a slider drag it would otherwise only reach the browser's
    log, where nobody sees it.
    """

    def __init__(self, live: LiveFigure, controls: list, *, below: bool = False):
        self.live = live
        self.figure = live.figure
        self.error = None
        self.error_box = widgets.HTML(layout=widgets.Layout(max_width=control_width(ERROR_PX)))
        # beside the figure (wrapped under it in a narrow column), or always under it (``below``:
        # a wide figure, e.g. two subplots side by side)
        # beside the figure the controls have a fixed width, so the row wraps (or not) by the
        # column's width alone, never because a readout grew while a slider moves
        # an invisible widget that gives a focused slider its keys (not the notebook's shortcuts)
        keys = slider_keys()
        side = widgets.VBox([*controls, self.error_box, *([keys] if keys is not None else [])],
                            layout=widgets.Layout(margin="0.5em 0 0 0" if below else "0 0 0 1em",
                                                  width=None if below else control_width(SIDE_PX),
                                                  flex=None if below else "0 0 auto"))
        self._side, self._keys = side, keys
        _as_figure(live.widget)
        super().__init__([live.widget, side],
                         layout=widgets.Layout(flex_flow="column" if below else "row wrap",
                                               align_items="flex-start"))
        live.on_new_widget(self._figure_replaced)
        forget_previous_run(self)

    @property
    def keys_widget(self):
        """The invisible widget that gives a focused slider its arrow keys (:mod:`dhlab.views.live.keys`),
        or None: anywidget is missing, or the page cannot run its module (the figure fell back to PNG)."""
        return self._keys

    def _figure_replaced(self, old, new) -> None:
        # the page cannot run the canvas backend's module (LiveFigure.fall_back_to_image): the PNG
        # figure takes its place, and the keys widget (the same front end) leaves the controls
        _as_figure(new)
        self.children = tuple(new if child is old else child for child in self.children)
        if self._keys is not None:
            self._side.children = tuple(c for c in self._side.children if c is not self._keys)
            self._keys.close()
            self._keys = None

    def run(self, action, *args):
        """``action(*args)``, with any error shown in the panel (then raised)."""
        try:
            result = action(*args)
        except Exception as exc:
            self.error = exc
            text = "".join(traceback.format_exception(type(exc), exc, exc.__traceback__, limit=-3))
            self.error_box.value = (
                '<div style="color:#b00020"><b>Error while updating:</b>'
                f'<pre style="white-space:pre-wrap;font-size:85%">{html.escape(text)}</pre></div>')
            raise
        if self.error is not None:
            self.error, self.error_box.value = None, ""
        return result

    def observe_values(self, sliders, callback) -> None:
        """Call ``callback()`` (through :meth:`run`) whenever one of the sliders moves,
        from a drag in the browser or from ``slider.value = ...`` in code."""
        for slider in sliders:
            slider.observe(lambda change: self.run(callback), names="value")

    def __repr__(self):
        # short and free of memory addresses: it is the text/plain of the cell's output
        return f"<dhlab {type(self).__name__}>"

    def close(self):
        """Close the panel's widgets (with their layouts and styles) and release its figure."""
        live = getattr(self, "live", None)     # None if the constructor failed half-way
        if live is not None:
            live.close()
        for widget in [*_descendants(self), self]:
            for part in (getattr(widget, "layout", None), getattr(widget, "style", None)):
                if isinstance(part, widgets.Widget):
                    part.close()
            widgets.Widget.close(widget)

    def _repr_mimebundle_(self, **kwargs):
        # Beside the live widget, a PNG of the figure for viewers without a
        # widget manager (nbconvert to HTML, GitHub): they show the picture.
        bundle = super()._repr_mimebundle_(**kwargs)
        if isinstance(bundle, dict) and "image/png" not in bundle:
            import base64  # here: only the PNG fallback encodes

            bundle["image/png"] = base64.b64encode(self.live.png()).decode("ascii")
        return bundle


def _as_figure(widget) -> None:
    # the figure keeps its size: a flex row may otherwise shrink the canvas, which then shows
    # only part of the picture (its left side cut, as seen in a narrow browser column)
    widget.layout.flex = "0 0 auto"
    widget.add_class(FIGURE_CLASS)      # its picture is not dragged away (keys.py)


def _descendants(widget):
    for child in getattr(widget, "children", ()):
        yield from _descendants(child)
        yield child
    toolbar = getattr(widget, "toolbar", None)      # ipympl's canvas has one
    if isinstance(toolbar, widgets.Widget):
        yield toolbar
