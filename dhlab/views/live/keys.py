"""Keys that reach the slider: a panel's focused slider takes the arrow keys, Page Up/Down,
Home and End wherever the panel is shown (JupyterLab, the browser edition, Voilà, a
lecture deck), every other key (Space: next slide) still reaches JupyterLab's shortcuts,
and the figure's picture cannot be dragged away.

Why a widget of its own: JupyterLab's keyboard shortcuts see a key before the page's
widgets do; in the browser edition (JupyterLab 4.4) and in the decks
(jupyterlab-slideshow binds → to "next slide") a focused slider never got its arrow
keys. JupyterLab's own way out is an HTML attribute, ``data-lm-suppress-shortcuts``:
no shortcut applies to a key typed inside an element that has it. ipywidgets cannot
set an attribute on a slider, so :class:`SliderKeys`, an invisible widget (anywidget,
its ES module is ``keys.js``) put in the panel, sets it on the focused slider while one
of the slider's own keys is dispatched, and only then (left there, it would stop Space
too: a lecturer could not go on after dragging a slider), and stops the browser's drag
of an ``<img>`` figure (``draggable=false``, and CSS).

>>> keys = slider_keys()           # None where anywidget is not installed
>>> keys is None or keys.layout.display == "none"
True
"""
from __future__ import annotations

import functools
from pathlib import Path

__all__ = ["slider_keys", "FIGURE_CLASS"]

FIGURE_CLASS = "dhlab-figure"       # the panels' figure widgets carry this CSS class

# the picture of a figure is not an image to drag or select: a drag on it rotates or does nothing
_CSS = f"""
.{FIGURE_CLASS}, .{FIGURE_CLASS} img, img.{FIGURE_CLASS} {{
  -webkit-user-drag: none;
  user-select: none;
  -webkit-user-select: none;
}}
"""


def slider_keys():
    """A new invisible :class:`SliderKeys` widget, or None when anywidget is missing
    (then the notebook's shortcuts may take a focused slider's arrow keys)."""
    cls = _widget_class()
    return None if cls is None else cls()


@functools.cache
def _widget_class():
    """The widget class, made on first use (anywidget is imported only then)."""
    try:
        import anywidget  # lazy: the notebook's own libraries, on first display
        import ipywidgets as widgets  # lazy: the notebook's own libraries, on first display
    except ImportError:
        return None

    class SliderKeys(anywidget.AnyWidget):
        """Gives its panel's focused slider the keyboard (see the module's docstring)."""

        _esm = Path(__file__).with_name("keys.js")
        _css = _CSS

        def __init__(self):
            super().__init__(layout=widgets.Layout(display="none"))

    return SliderKeys
