"""Figures that are pictures: readable, never clipped, shown as an image everywhere.

Every figure of the course is made by :func:`new_figure`. It is a matplotlib
``Figure`` made **without pyplot** (re-running a cell does not pile up figures,
``plt.show()`` never shows it twice), and it:

* **displays as a PNG picture** in Jupyter on a first Run All in a fresh
  kernel, with the inline backend and with ``%matplotlib widget``, even when
  pyplot was never imported (a bare Agg figure would show only the text
  ``<Figure size 1200x620 with 2 Axes>``): it has a ``_repr_mimebundle_``
  that IPython asks before any other formatter;
* is **readable**: at least :data:`MIN_DPI` dots per inch, at least
  :data:`MIN_WIDTH_PX` pixels wide (a smaller ``figsize`` is scaled up, its
  shape kept) and no text smaller than :data:`MIN_TEXT_PX` pixels (smaller
  fonts are raised when the figure is drawn);
* is **never clipped** when shown: the picture is the figure, widened where a
  title, a label or a marker sticks out of it;
* honours the **projector** setting: ``projector()`` makes every figure and
  panel made afterwards larger (more pixels per inch: text, lines and markers
  grow together, the layout stays the same), without editing the notebooks.

>>> fig = new_figure((3.2, 3.2))          # too small for a lecture: scaled up
>>> fig.dpi, fig.get_size_inches().round(2).tolist()
(100.0, [4.5, 4.5])
>>> ax = fig.add_subplot()
>>> _ = ax.plot([0, 1], [0, 1])
>>> fig._repr_png_()[:8] == b"\\x89PNG\\r\\n\\x1a\\n"
True
"""
from __future__ import annotations

import base64
import io
import math
import numbers

import matplotlib
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.text import Text
from matplotlib.transforms import Bbox

from ..errors import DHLabError
from ..i18n import _

__all__ = ["new_figure", "CourseFigure", "set_figure_scale", "projector_scale", "figure_size",
           "MIN_DPI", "MIN_WIDTH_PX", "MIN_TEXT_PX", "min_fontsize"]

MIN_DPI = 100             # dots per inch, before the projector scale
MIN_WIDTH_PX = 450        # pixels, before the projector scale
MIN_TEXT_PX = 12          # the smallest text, in pixels (12 px = 8.64 pt at 100 dpi)

_projector = {"scale": 1.0, "max_height_px": None}


def set_figure_scale(on: bool = True, scale: float = 1.5, max_height_px: float | None = None) -> float:
    """Make every figure and panel made from now on ``scale`` times larger (a
    lecture hall), or back to normal with ``set_figure_scale(False)``. Returns the scale
    now in force. ``max_height_px``: a figure that would be taller than this
    grows less (never below its normal size), so that it still fits a slide.

    Only figures made afterwards change: run it at the top of a notebook (or
    in a startup file) and re-run the cells. (``dhlab.projector()`` calls this
    and also makes the page's text larger: :mod:`dhlab.views.projector`.)

    >>> set_figure_scale(scale=1.5)
    1.5
    >>> set_figure_scale(False)
    1.0
    """
    if not isinstance(on, (bool, int)) or isinstance(on, float):
        raise DHLabError(_("projector(on) takes True or False, got {value}.").format(value=repr(on)))
    if on:
        scale = _positive(scale, "scale", hint=_("e.g. projector(scale=1.5)"))
        if not 0.5 <= scale <= 4:
            raise DHLabError(_("projector scale must be between 0.5 and 4, got {scale:g}; "
                               "1.5 suits most lecture halls.").format(scale=scale))
        if max_height_px is not None:
            max_height_px = _positive(max_height_px, "max_height_px", hint=_("pixels, e.g. 760"))
        _projector.update(scale=scale, max_height_px=max_height_px)
    else:
        _projector.update(scale=1.0, max_height_px=None)
    return _projector["scale"]


def projector_scale() -> float:
    """The current projector scale (1.0: normal)."""
    return _projector["scale"]


def min_fontsize(dpi: float) -> float:
    """The smallest font size (points) that is :data:`MIN_TEXT_PX` pixels at ``dpi``."""
    return MIN_TEXT_PX * 72.0 / dpi


def _positive(value, name, hint=""):
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise DHLabError(_("{name} must be a positive number, got {value}").format(name=name, value=repr(value))
                         + (f" ({hint})." if hint else "."))
    value = float(value)
    if not math.isfinite(value) or value <= 0:
        raise DHLabError(_("{name} must be a positive, finite number, got {value}").format(
            name=name, value=repr(value)) + (f" ({hint})." if hint else "."))
    return value


def figure_size(figsize=None, dpi=None) -> tuple:
    """``((width, height) in inches, dpi)`` for a course figure: the projector
    scale applied to the dpi (no taller than the projector's ``max_height_px``),
    then at least :data:`MIN_DPI` dpi and :data:`MIN_WIDTH_PX` px wide (scaled up
    with its shape kept). ``None``: matplotlib's default size and dpi.

    >>> figure_size((3.6, 3.6), dpi=80)
    ((4.5, 4.5), 100.0)
    """
    if figsize is None:
        figsize = matplotlib.rcParams["figure.figsize"]
    if isinstance(figsize, (str, bytes)) or not hasattr(figsize, "__len__") or len(figsize) != 2:
        raise DHLabError(_("figsize must be (width, height) in inches, e.g. (6, 4), got {value}.").format(
            value=repr(figsize)))
    width, height = (_positive(v, "figsize", hint=_("(width, height) in inches, e.g. (6, 4)"))
                     for v in figsize)
    if max(width, height) > 40:
        raise DHLabError(_("figsize {value} is larger than 40 inches; give it in inches, e.g. (6, 4).").format(
            value=repr(figsize)))
    if not 0.1 <= width / height <= 10:
        raise DHLabError(_("figsize {value} is too thin to show anything: keep the width and the height "
                           "within a factor 10 of each other, e.g. (6, 4).").format(value=repr(figsize)))
    base = MIN_DPI if dpi is None else _positive(dpi, "dpi", hint=_("dots per inch, e.g. 100"))
    base = max(base, MIN_DPI)
    if width * base < MIN_WIDTH_PX:                       # too narrow: scale up, keep the shape
        grow = MIN_WIDTH_PX / (width * base)
        width, height = width * grow, height * grow
    dpi = base * projector_scale()
    tallest = _projector["max_height_px"]
    if tallest is not None and height * dpi > tallest:     # on a slide: grow only as far as it fits
        dpi = max(base, tallest / height)
    return (round(width, 4), round(height, 4)), dpi


class CourseFigure(Figure):
    """A matplotlib Figure that shows itself as a PNG and keeps its text readable.

    Made by :func:`new_figure`; see the module's description.
    """

    _depth = 0              # draws under way (a draw_event handler may draw again)
    _when_drawn = ()        # see when_drawn

    def draw(self, renderer):
        enforce_min_text(self)
        self._depth += 1
        try:
            super().draw(renderer)
        finally:
            self._depth -= 1
        if not self._depth:
            for callback in self._when_drawn:
                callback()

    def when_drawn(self, callback) -> None:
        """Call ``callback()`` after each full draw, once the draws it set off are done too (a
        ``draw_event`` handler may draw again: see :func:`dhlab.views.layout.keep_texts_inside`)."""
        self._when_drawn = (*self._when_drawn, callback)

    def png(self) -> bytes:
        """The whole figure as PNG bytes, widened where something sticks out."""
        if self.canvas is None or not hasattr(self.canvas, "print_png"):
            FigureCanvasAgg(self)
        renderer = self.canvas.get_renderer() if hasattr(self.canvas, "get_renderer") else None
        bbox = "tight"
        if renderer is not None:
            enforce_min_text(self)
            tight = self.get_tightbbox(renderer)
            if tight is not None:                 # never crop, only widen: the minimum size holds
                bbox = Bbox.union([self.bbox_inches, tight.padded(0.05), *self._texts_3d(renderer)])
        buffer = io.BytesIO()
        self.savefig(buffer, format="png", dpi=self.dpi, bbox_inches=bbox,
                     facecolor=self.get_facecolor())
        return buffer.getvalue()

    def _texts_3d(self, renderer) -> list:
        """Where the labels of 3D axes are really drawn (inches): matplotlib's tight box
        misses some of them (an axis label of a turned 3D axes), so they are added."""
        from .layout import drawn_texts  # (it brings mplot3d: only figures with 3D axes need it)
        axes3d = [ax for ax in self.axes if getattr(ax, "name", "") == "3d"]
        if not axes3d:
            return []
        self.canvas.draw()                        # the labels sit where the last draw put them
        to_inches = self.dpi_scale_trans.inverted()
        return [t.get_window_extent(renderer).transformed(to_inches).padded(0.05)
                for ax in axes3d for t in drawn_texts(ax)]

    def _repr_png_(self):
        return self.png() if self.axes else None

    def _repr_mimebundle_(self, include=None, exclude=None):
        # IPython asks this before its own Figure formatter (which exists only
        # once pyplot was imported): the same picture with any backend.
        if not self.axes:
            return None
        return {"image/png": base64.b64encode(self.png()).decode("ascii")}


def enforce_min_text(figure) -> None:
    """Raise every text of ``figure`` smaller than :data:`MIN_TEXT_PX` pixels to that
    size (tick labels included, also those made later)."""
    smallest = min_fontsize(figure.dpi)
    for ax in figure.axes:
        for axis in getattr(ax, "_axis_map", {}).values():
            ticks = axis.get_major_ticks(1) if not axis.majorTicks else axis.majorTicks
            if ticks and ticks[0].label1.get_fontsize() < smallest - 1e-9:
                axis.set_tick_params(which="both", labelsize=smallest)
    for text in figure.findobj(Text):
        if text.get_fontsize() < smallest - 1e-9:
            text.set_fontsize(smallest)


def new_figure(figsize=None, **kwargs) -> CourseFigure:
    """A course figure (see the module): ``figsize`` in inches (default
    matplotlib's), any other ``matplotlib.figure.Figure`` option (``dpi``,
    ``layout``, ...). Its layout is ``"constrained"`` unless you give another.

    Draw into it as into any figure (``fig.add_subplot()``, ``fig.subplots(1, 2)``);
    the last line of a cell that is the figure shows it.

    >>> fig = new_figure((8, 4))
    >>> ax1, ax2 = fig.subplots(1, 2)
    """
    kwargs.pop("FigureClass", None)
    (width, height), dpi = figure_size(figsize, kwargs.pop("dpi", None))
    kwargs.setdefault("layout", "constrained")
    try:
        figure = CourseFigure(figsize=(width, height), dpi=dpi, **kwargs)
    except (TypeError, ValueError) as exc:
        raise DHLabError(_("new_figure: {error} (options are those of matplotlib.figure.Figure).").format(
            error=exc)) from None

    FigureCanvasAgg(figure)
    return figure
