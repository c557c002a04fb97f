"""The lecture-hall switch: ``projector()`` makes everything larger together.

JupyterLab draws markdown at 14 px, code and widgets at 13 px: from the back of a
lecture hall that is too small, and browser zoom enlarges the menus too. On a
1920×1080 projector the body text should be at least 24 px. ``projector()``
therefore does two things, both undone by ``projector(False)``:

* **figures and panels made afterwards** get more pixels per inch
  (:func:`dhlab.views.figures.set_figure_scale`: text, lines and markers grow together,
  the layout stays), a tall one only as far as it still fits a slide
  (:data:`SLIDE_FIGURE_PX`);
* **the page's text** grows at once: a ``<style>`` output sets JupyterLab's own
  size variables (markdown and LaTeX, code and printed output, widget labels,
  readouts and slider rows). It works wherever JupyterLab's stylesheet is used:
  JupyterLab, its slide deck (jupyterlab-slideshow), the browser edition
  (JupyterLite) and Voilà. (The panels' controls made afterwards are wider to
  match: :func:`dhlab.views.panels.panel.control_width`.)

The style is shown with a fixed display id, so each call also updates the
styles shown by earlier calls: the last call wins, wherever its cell is.

>>> css = stylesheet(1.75)
>>> "--jp-content-font-size1: 24.5px" in css, stylesheet(1.0)
(True, '')
"""
from __future__ import annotations

from . import figures

__all__ = ["projector", "stylesheet", "widgets_scale", "DEFAULT_SCALE", "SLIDE_FIGURE_PX", "JUPYTERLAB_PX"]

# 14 px markdown x 1.75 = 24.5 px: at least 24 px on a 1920x1080 projector
DEFAULT_SCALE = 1.75
# A figure grows in both directions: one taller than this grows less, so that a panel with its
# slide's heading and a line or two of code still fits a 1080 px screen.
SLIDE_FIGURE_PX = 720
DISPLAY_ID = "dhlab-projector-style"

# JupyterLab 4's and ipywidgets 8's sizes (theme-light, jupyterlab-manager), in px.
PAGE_PX = {                                   # multiplied by the scale
    "--jp-content-font-size1": 14,            # markdown (headings are em of it), MathJax follows
    "--jp-code-font-size": 13,                # code cells and printed output
}
WIDGETS_PX = {                                # multiplied by the widgets' scale (below)
    "--jp-widgets-font-size": 13,             # widget labels, readouts, buttons, HTML readouts
    "--jp-widgets-inline-label-width": 80,
    "--jp-widgets-inline-width": 300,
    "--jp-widgets-slider-handle-size": 16,
    "--jp-widgets-slider-track-thickness": 4,
}
JUPYTERLAB_PX = {**PAGE_PX, **WIDGETS_PX}
# A panel's column of controls is as tall as some 25 lines of text (the SSRMS's: 7 sliders, the
# pose, its matrix, the view's buttons) and must fit a 1080 px slide under its heading: widgets
# grow two thirds as much as the text (1.5x at the default 1.75x). A widget row (28 px) is its
# 13 px of text and 15 px of padding: the text grows, the padding and the margins stay.
WIDGETS_SHARE = 2 / 3
ROW_PX, ROW_TEXT_PX = 28, 13


def widgets_scale(scale: float) -> float:
    """How much larger the widgets are when the text is ``scale`` times larger."""
    return 1 + WIDGETS_SHARE * (scale - 1)


def stylesheet(scale: float) -> str:
    """The CSS that makes JupyterLab's text ``scale`` times larger ('' for 1: the theme's own)."""
    if scale == 1:
        return ""
    grow = widgets_scale(scale)
    sizes = {**{name: px * scale for name, px in PAGE_PX.items()},
             **{name: px * grow for name, px in WIDGETS_PX.items()},
             "--jp-widgets-inline-height": ROW_PX + ROW_TEXT_PX * (grow - 1)}
    lines = "\n".join(f"  {name}: {px:g}px;" for name, px in sizes.items())
    # :root:root outranks the theme's and ipywidgets' own :root rules, whatever their order;
    # a table in markdown is drawn at the interface's size (13 px): here at the text's
    return (f":root:root {{\n{lines}\n}}\n"
            ".jp-RenderedHTMLCommon table { font-size: var(--jp-content-font-size1); }\n")


def projector(on: bool = True, scale: float = DEFAULT_SCALE) -> float:
    """Make the notebook readable from the back of a lecture hall: text, code,
    widgets at once, figures and panels made afterwards, ``scale`` times larger
    (1.75: body text 24.5 px). ``projector(False)`` restores. Returns the scale
    now in force.

    Run it at the top of a notebook (then re-run the cells whose figures you want
    larger), or before starting a lecture's deck.

    >>> projector(scale=2)
    2.0
    >>> projector(False)
    1.0
    """
    # checks on and scale; figures made afterwards grow, but no taller than a slide allows
    scale = figures.set_figure_scale(on, scale, max_height_px=SLIDE_FIGURE_PX)
    _show(scale)
    return scale


def _show(scale: float) -> None:
    """Show the stylesheet for ``scale`` as a ``<style>`` output (in a notebook only), and put
    it in place of the styles that earlier calls showed."""
    try:
        from IPython import get_ipython  # lazy: the notebook's own libraries, on first display
        from IPython.display import display, update_display  # lazy: the notebook's own libraries, on first display
    except ImportError:                       # no IPython: nothing to style
        return
    if get_ipython() is None:                 # plain Python (a script, the tests)
        return
    said = f"page text {scale:g}x larger" if scale != 1 else "page text at its normal size"
    page = {"text/html": f"<style>\n{stylesheet(scale)}</style>", "text/plain": f"(dhlab.projector: {said})"}
    display(page, raw=True, display_id=DISPLAY_ID)
    update_display(page, raw=True, display_id=DISPLAY_ID)
