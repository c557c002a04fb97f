"""The DH step-through: one link's matrix, one elementary motion at a time.

Rules 10-13 of the DH convention carry frame {S_(i-1)} onto frame {S_i} by four
motions, always in this order (seeds 002 and 003)::

    A_i = Rz(θ_i) · Tz(d_i) · Tx(a_i) · Rx(α_i)

A slider ``step`` from 0 to 4 applies them one after the other: at step 1.5
the frame has turned by θ and moved half of d along z_(i-1). Between two whole
steps the current motion is applied in part, so the frame glides.

>>> import numpy as np
>>> T = dh_partial(np.pi / 2, 1.0, 2.0, 0.0, 4)    # all four motions: the DH matrix
>>> np.allclose(T, dh_partial(np.pi / 2, 1.0, 2.0, 0.0, 3))   # α = 0: the last one does nothing
True
>>> dh_partial(np.pi / 2, 1.0, 2.0, 0.0, 1.5)[:3, 3].round(6).tolist()   # turned, half-way up
[0.0, 0.0, 0.5]
"""
from __future__ import annotations

import math

import ipywidgets as widgets
import numpy as np

from ...errors import DHLabError
from ...i18n import N_, _
from ...transforms import Rx, Rz, trans
from ...validation import as_angle, as_index, as_length, as_matrix4, as_number, as_text, describe, has_angle_mark
from ..camera import set_camera
from ..labels import FrameLabels3D
from ..layout import keep_texts_inside, space_ticks
from ..live.livefigure import LiveFigure
from ..poses import checked_start
from ..triads import LETTER_MARKERS, axis_colors, letter_points, triad_segments
from ..viewbase import checked_robot, line_in_box
from .panel import Panel
from .teach import matrix_html

__all__ = ["dh_partial", "dh_params", "motion_text", "stepthrough", "stepthrough_link",
           "StepThroughPanel", "MOTIONS"]

# (name, parameter, what it does) for the four motions, in the DH order
MOTIONS = (
    ("Rz(θ)", "θ", N_("rotate by θ about z<sub>i−1</sub>")),
    ("Tz(d)", "d", N_("translate by d along z<sub>i−1</sub>")),
    ("Tx(a)", "a", N_("translate by a along the new x axis, which is x<sub>i</sub> (the common normal, "
                      "<i>normal común</i>)")),
    ("Rx(α)", "α", N_("rotate by α about x<sub>i</sub>, bringing z onto z<sub>i</sub>")),
)
_MAKERS = (Rz, lambda d: trans(0, 0, d), lambda a: trans(a, 0, 0), Rx)


def dh_partial(theta: float, d: float, a: float, alpha: float, step: float) -> np.ndarray:
    """The frame reached after ``step`` (0…4) of the four DH motions, relative to {S_(i-1)}.

    Angles in radians. A fractional step applies that part of the next motion.
    """
    step = _checked_step(step)
    T = np.eye(4)
    for k, (make, amount) in enumerate(zip(_MAKERS, (theta, d, a, alpha))):
        T = T @ make(min(max(step - k, 0.0), 1.0) * amount)
    return T


def _checked_step(step) -> float:
    step = as_number(step, "step")
    if not 0 <= step <= 4:
        raise DHLabError(_("step must be between 0 (frame i-1) and 4 (frame i), got {step:g}.").format(step=step))
    return step


def dh_params(A, tol: float = 1e-9):
    """(θ, d, a, α) of a link matrix ``A`` of standard DH form (angles in radians).

    Raises DHLabError when ``A`` is not Rz(θ)·Tz(d)·Tx(a)·Rx(α) for any θ, d, a, α
    (for example seed 004's Rz(θ)·Tr(0, l, 0), a link that is not written in DH form).
    """
    A = np.asarray(A, dtype=float)
    theta = math.atan2(A[1, 0], A[0, 0])
    alpha = math.atan2(A[2, 1], A[2, 2])
    d = A[2, 3]
    a = A[0, 3] * math.cos(theta) + A[1, 3] * math.sin(theta)
    rebuilt = dh_partial(theta, d, a, alpha, 4)
    if not np.allclose(rebuilt, A, atol=tol * max(1.0, np.abs(A[:3, 3]).max())):
        raise DHLabError(_("this link's matrix is not of the DH form Rz(θ)·Tz(d)·Tx(a)·Rx(α) (largest mismatch "
                           "{mismatch:.3g}); the step-through needs a standard DH link: write the robot as a DH table "
                           "(dhlab.DHRobot.from_table).").format(mismatch=np.abs(rebuilt - A).max()))
    return theta, d, a, alpha


def motion_text(step: float, theta: float, d: float, a: float, alpha: float, unit: str = "") -> str:
    """Which motion ``step`` is applying (or has just finished), as HTML, with its
    value (angles in degrees).

    >>> motion_text(1.5, 0.0, 2.0, 0.0, 0.0, "m")
    '<b>Step 2 of 4: Tz(d)</b>, d = 2 m: translate by d along z<sub>i−1</sub>. Done: 50 %.'
    """
    if step >= 4:
        return _("<b>Done:</b> all four motions applied, the frame is now {S<sub>i</sub>}: "
                 "A<sub>i</sub> = Rz(θ)·Tz(d)·Tx(a)·Rx(α).")
    k = int(step)
    fields = dict(k=k + 1, motion=MOTIONS[k][0], what=_describe(k, theta, d, a, alpha, unit))
    if step == k:                      # between two motions: say what comes next
        done = "·".join(m[0] for m in MOTIONS[:k])
        where = _("After {done}").format(done=done) if k else _("At {S<sub>i−1</sub>}")
        return where + _(". <b>Next, step {k} of 4: {motion}</b>, {what}.").format(**fields)
    return _("<b>Step {k} of 4: {motion}</b>, {what}. Done: {percent:.0f} %.").format(
        percent=100 * (step - k), **fields)


def _describe(k, theta, d, a, alpha, unit):
    param, what = MOTIONS[k][1], _(MOTIONS[k][2])
    value = (theta, d, a, alpha)[k]
    shown = (f"{round(math.degrees(value), 1) + 0.0:.1f}°" if param in "θα"
             else f"{round(value, 6) + 0.0:.4g}{(' ' + unit) if unit else ''}")
    return f"{param} = {shown}: {what}"


class StepThroughPanel(Panel):
    """The widget of :func:`stepthrough`: ``slider`` (0…4), ``figure``, ``frame``
    (the current 4x4 frame, in the figure's coordinates), ``text`` and ``matrix``."""

    def __init__(self, theta, d, a, alpha, *, i=1, base=None, unit="", step=0.0,
                 figsize=(6, 6), backend="auto"):
        theta, alpha = as_angle(theta, "theta"), as_angle(alpha, "alpha")
        d, a = as_length(d, "d"), as_length(a, "a")
        self.params = (theta, d, a, alpha)
        self.i, self.unit = as_index(i, "i", 1, 10_000), as_text(unit, "unit")
        self.base = np.eye(4) if base is None else as_matrix4(base, "base")
        step = _checked_step(step)
        # triad length: a third of the link's longest offset (1 when it has none)
        self.length = 0.3 * max(abs(d), abs(a)) if max(abs(d), abs(a)) > 1e-9 else 1.0
        live = LiveFigure(figsize=figsize, backend=backend)
        self._build_figure(live)
        self.slider = widgets.FloatSlider(value=step, min=0, max=4, step=0.05, description=_("step"),
                                          readout_format=".2f", continuous_update=True,
                                          layout=widgets.Layout(width="360px"))
        # a box of fixed size: the text of each step differs, the panel must not (three lines hold
        # the longest, in English and Spanish; a longer one would scroll, not push the panel)
        self.text = widgets.HTML(layout=widgets.Layout(width="480px", height="4.8em", overflow="auto"))
        self.matrix = widgets.HTML()
        self.camera = widgets.ToggleButtons(options=["iso", "front", "side", "top"], value="iso",
                                            description=_("view"),
                                            style={"description_width": "3em", "button_width": "4.2em"})
        self.zoom = widgets.FloatSlider(value=1.0, min=0.5, max=3.0, step=0.05, description=_("zoom"),
                                        readout_format=".2f", continuous_update=False,
                                        style={"description_width": "3em"},
                                        layout=widgets.Layout(width="330px"))
        super().__init__(live, [widgets.HTML(self._table_html()), self.slider, self.text,
                                self.matrix, self.camera, self.zoom])
        self._refresh()
        self.observe_values([self.slider], self._refresh)
        self.observe_values([self.camera, self.zoom], self._look)

    # --- figure ----------------------------------------------------------------------
    def _build_figure(self, live):
        ax = live.figure.add_axes([0.1, 0.08, 0.78, 0.8], projection="3d")
        start, end = self.base, self.base @ dh_partial(*self.params, 4)
        points = np.array([start[:3, 3], end[:3, 3]])
        center = points.mean(axis=0)
        half = max(np.abs(points - center).max() + 1.2 * self.length, 1.4 * self.length)
        ax.set(xlim=(center[0] - half, center[0] + half), ylim=(center[1] - half, center[1] + half),
               zlim=(center[2] - half, center[2] + half), xlabel="x", ylabel="y", zlabel="z")
        ax.set_box_aspect((1, 1, 1), zoom=1.0)
        ax.set_proj_type("ortho")
        set_camera(ax, "iso", frames=np.array([start, end]))   # both triads read
        # the title belongs to this axes; two lines fit the narrowest figure
        ax.set_title(_("Link {i}: the thick frame goes\nfrom {start} to {end}").format(
            i=self.i, start=rf"$\{{S_{{{self.i - 1}}}\}}$", end=rf"$\{{S_{{{self.i}}}\}}$"), pad=2)
        # still: frame i-1 (solid), frame i (faint, where the motions end), the z_(i-1) axis
        self._triad(ax, start, lw=2, alpha=1.0)
        self._triad(ax, end, lw=2.2, alpha=0.6, ls="--")      # the target: dashed, still visible projected
        FrameLabels3D(ax, [rf"$\{{S_{{{self.i - 1}}}\}}$", rf"$\{{S_{{{self.i}}}\}}$"]).set_points(
            [start[:3, 3], end[:3, 3]])
        lo, hi = center - half, center + half
        space_ticks(ax)                       # no colliding tick labels
        keep_texts_inside(ax)                 # nothing clipped at the figure's edge
        ax.plot(*line_in_box(start[:3, 3], start[:3, 2], lo, hi).T, ":", color=axis_colors()[2], lw=1)
        # moving: the frame being carried (with its x, y, z letters), and the path its origin has travelled
        self.moving_axes = self._triad(ax, start, lw=3.5, alpha=1.0)
        self.moving_letters = [ax.plot([], [], [], ls="", marker=m, ms=13, mew=0, color=c)[0]
                               for c, m in zip(axis_colors(), LETTER_MARKERS)]
        self.path, = ax.plot([], [], [], "--", color="0.4", lw=1)
        live.add_moving(*self.moving_axes, *self.moving_letters, self.path)
        self.ax = ax

    def _triad(self, ax, T, **style):
        return [ax.plot(*seg.T, color=c, **style)[0]
                for c, seg in zip(axis_colors(), triad_segments(T[None], self.length))]

    # --- update ------------------------------------------------------------------------
    def _refresh(self):
        step = float(self.slider.value)
        self.frame = self.base @ dh_partial(*self.params, step)
        for line, seg in zip(self.moving_axes, triad_segments(self.frame[None], self.length)):
            line.set_data_3d(*seg.T)
        for mark, tip in zip(self.moving_letters, letter_points(self.frame[None], self.length)):
            mark.set_data_3d(*tip.T)
        # the origin moves only during Tz and Tx: corners at steps 0, 2, 3, then now
        corners = [self.base @ dh_partial(*self.params, min(step, s)) for s in (0, 2, 3, step)]
        self.path.set_data_3d(*np.array([c[:3, 3] for c in corners]).T)
        self.live.refresh()
        self.text.value = motion_text(step, *self.params, unit=self.unit)
        self.matrix.value = matrix_html(dh_partial(*self.params, step), self._product(step))

    def _look(self):
        """The camera preset or the zoom changed: redraw everything (the background)."""
        set_camera(self.ax, self.camera.value, frames=np.array([self.base, self.base @ dh_partial(*self.params, 4)]))
        self.ax.set_box_aspect((1, 1, 1), zoom=float(self.zoom.value))
        space_ticks(self.ax)
        self.live.redraw()

    def frame_at(self, step: float) -> np.ndarray:
        """The frame after ``step`` (0…4) of the four motions, in the figure's
        coordinates, *without* moving the slider (the panel stays where the
        student left it: at 0 after Run All).

        >>> panel = stepthrough(theta_deg=90, d=1.0, a=0.5, alpha_deg=-90, i=2)
        >>> panel.frame_at(2)[:3, 3].round(6).tolist(), panel.slider.value
        ([0.0, 0.0, 1.0], 0.0)
        """
        return self.base @ dh_partial(*self.params, _checked_step(step))

    def _product(self, step):
        names = []
        for k, name in enumerate(m[0] for m in MOTIONS):
            part = min(max(step - k, 0.0), 1.0)
            if part > 0:
                names.append(name if part == 1 else f"{name[:2]}({part:.2f}·{name[3]})")
        return (f"<sup>{self.i - 1}</sup>T<sub>now</sub> = " + ("·".join(names) or "I"))

    def _table_html(self):
        theta, d, a, alpha = self.params
        # rounded, then + 0.0: no "-0.0" for a value like -1e-17
        cells = [f"{round(math.degrees(theta), 1) + 0.0:.1f}°", f"{round(d, 6) + 0.0:.4g}",
                 f"{round(a, 6) + 0.0:.4g}", f"{round(math.degrees(alpha), 1) + 0.0:.1f}°"]
        return ("<table style='border-collapse:collapse;font-family:monospace'>"
                "<tr><th style='padding:0 .6em'>i</th><th style='padding:0 .6em'>θ</th>"
                "<th style='padding:0 .6em'>d</th><th style='padding:0 .6em'>a</th>"
                "<th style='padding:0 .6em'>α</th></tr>"
                f"<tr><td style='padding:0 .6em'>{self.i}</td>"
                + "".join(f"<td style='padding:0 .6em'>{c}</td>" for c in cells) + "</tr></table>")

    def __repr__(self):
        return _("<dhlab DH step-through: link {i}>").format(i=self.i)


def stepthrough(theta_deg: float = 0.0, d: float = 0.0, a: float = 0.0, alpha_deg: float = 0.0,
                *, i: int = 1, unit: str = "", step: float = 0.0, figsize=(6, 6),
                backend: str = "auto") -> StepThroughPanel:
    """Step through one DH link given by its row θ, d, a, α (**angles in degrees**).

    >>> panel = stepthrough(theta_deg=90, d=1.0, a=0.5, alpha_deg=-90, i=2)
    >>> panel.slider.value = 2        # after Rz(θ) and Tz(d)
    >>> panel.frame[:3, 3].round(6).tolist()
    [0.0, 0.0, 1.0]
    """
    theta, alpha = _radians(theta_deg, "theta_deg"), _radians(alpha_deg, "alpha_deg")
    return StepThroughPanel(theta, d, a, alpha, **_options(i, unit, step, figsize, backend))


def _radians(degrees, name: str) -> float:
    """An angle of a DH row typed in degrees (-360 … 360), in radians."""
    if has_angle_mark(degrees):      # deg2rad() made it radians already: converting again would be wrong
        raise DHLabError(_("{name} = {value} is already in radians (made by deg2rad()), but {name} is in degrees: "
                           "write the plain number of degrees (e.g. {name}=90).").format(
                               name=name, value=describe(degrees)))
    value = as_number(degrees, name)
    if abs(value) > 360:
        raise DHLabError(_("{name} = {value:g}° is more than a full turn: {name} is in degrees, from -360 to 360 "
                           "(720° is the same as 0°). Check the number.").format(name=name, value=value))
    return math.radians(value)


def stepthrough_link(robot, i: int, q=None, *, step: float = 0.0, figsize=(6, 6),
                     backend: str = "auto") -> StepThroughPanel:
    """Step through link ``i`` (1…n) of a DH ``robot`` at pose ``q`` (radians / length
    units; default zero, inside the joint limits), placed where the robot puts frame i-1.
    ``step`` (0…4, keyword) is where the slider starts; the panel always starts at 0
    unless told otherwise. Use :meth:`StepThroughPanel.frame_at` to read a step
    without moving the slider."""
    checked_robot(robot)
    i = as_index(i, _("link number i"), 1, robot.n)
    q = checked_start(robot, q)                          # one pose, inside the joint limits (as teach)
    frames = np.asarray(robot.frames(q), dtype=float)
    A = np.linalg.solve(frames[i - 1], frames[i])       # ^{i-1}A_i = inv(F_{i-1}) · F_i
    theta, d, a, alpha = dh_params(A)
    return StepThroughPanel(theta, d, a, alpha, base=frames[i - 1],
                            **_options(i, getattr(robot, "unit", ""), step, figsize, backend))


def _options(i, unit, step, figsize, backend):
    return dict(i=i, unit=unit, step=step, figsize=figsize, backend=backend)
