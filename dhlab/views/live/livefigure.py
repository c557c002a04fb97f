"""A matplotlib figure that redraws only what moves, shown as a Jupyter widget.

Why this exists: the usual ``ipywidgets.interact`` pattern clears the axes and
plots everything again on every slider step. For a 3D robot that costs about
70 ms a step, and almost all of it is spent on things that never move: the
panes, the grid, the ticks and their labels. A :class:`LiveFigure` draws those
once, keeps the picture (the *background*) and, on each update, pastes the
background back and paints only the moving artists on top ("blitting").

It has three ways to reach the browser (``backend=``; ``DHLAB_BACKEND=canvas|ipympl|image`` in
the environment overrides ``"auto"``):

* ``%matplotlib widget`` (ipympl): the figure is an interactive canvas widget
  (you can rotate the 3D view with the mouse); each update sends only the
  changed pixels to the browser.
* ``"canvas"`` (the default in a Jupyter kernel where anywidget imports): the browser
  paints the moving artists over the cached background from numbers the kernel sends,
  and shows matplotlib's own frame whenever the figure rests (:mod:`dhlab.views.live.canvas`);
  a 3D view turns with the mouse in the browser.
* the default inline backend: the figure is shown in an ``ipywidgets.Image``
  that receives a fresh PNG after each update. (No ``Output`` widget is used:
  executing notebooks whose sliders print into one can hang, see
  nbclient#312.)

The figure is a course figure (:func:`~dhlab.views.figures.new_figure`: at
least 100 dpi and 450 px wide, readable text, the projector scale applied) and
is *not* registered with ``pyplot``: re-running a cell does not pile
up figures, and ``plt.show()`` never shows it a second time.

>>> live = LiveFigure(figsize=(3, 3))
>>> ax = live.figure.add_subplot()
>>> dot, = ax.plot([0], [0], "o")
>>> _ = live.add_moving(dot)        # drawn on every refresh, over the cached background
>>> dot.set_data([0.5], [0.5])
>>> live.refresh()                   # pixels are really drawn (into the Agg buffer)
"""
from __future__ import annotations

import math
import time
import weakref

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg

from ..figures import new_figure
from .backend import BACKENDS, choose_backend, ipympl_active
from .ipympl_canvas import attach_ipympl_canvas
from .notebook_cell import forget_previous_run, watch_front_end
from .png import PNG_WITH_ALPHA, encode_png

# choosing the backend (backend.py), ipympl's canvas (ipympl_canvas.py) and what the running cell
# says (notebook_cell.py) have their own modules; their public names are here too, where the panels,
# the tests and the notebooks have always imported them
__all__ = ["LiveFigure", "ipympl_active", "forget_previous_run", "watch_front_end", "encode_png", "BACKENDS",
           "choose_backend", "MOTION_S", "REDRAW_EVERY_S"]

# The canvas path's module (dhlab.views.live.canvas) is imported inside the methods that take that
# path: it brings anywidget, which takes longer to import (~0.2 s) than this whole module.

# ipympl loses a diff frame now and then, which leaves stale pixels until the
# next full image (matplotlib#19116); sending a full frame every so often heals it.
_FULL_FRAME_EVERY = 30

# refreshes closer than this (seconds) are a slider being dragged (LiveFigure.in_motion)
MOTION_S = 0.3

# while a slider is dragged, a full redraw (framing a robot that leaves the picture: ~35 ms of kernel,
# 55 at pixel ratio 2, and a new background for the page) at most this often (seconds): a 2-s drag at
# pixel ratio 2 kept its 46-49 frames/s at 1 s, and lost a tenth of them at 0.5 s (LiveFigure.may_redraw)
REDRAW_EVERY_S = 1.0


class LiveFigure:
    """A figure with a cached background and a list of moving artists.

    ``backend`` is ``"auto"`` (see :func:`choose_backend`), ``"canvas"``, ``"ipympl"`` or
    ``"image"``; ``live.backend`` says which one is used.
    """

    def __init__(self, figsize=(6, 6), dpi=100, backend: str = "auto"):
        self.backend = choose_backend(backend)
        # at least 100 dpi and 450 px wide, text at least 12 px, the projector scale applied
        self.figure = new_figure(figsize, dpi=dpi, layout="none")
        self.uses_ipympl = self.backend == "ipympl"
        self._base_dpi = self.figure.dpi      # the canvas backend renders at base dpi x pixel ratio
        self._canvas = None          # the CanvasWidget of the canvas path, made on demand
        self._agg_stale = False      # canvas path: the Agg buffer lags behind the moving artists
        self._seq = 0                # canvas path: the number of the pose last sent
        self.rig = None              # canvas path: how the picture follows the sliders (rig.py)
        self.last_refresh = -math.inf   # time.monotonic() of the last refresh (in_motion compares with it)
        self._last_redraw = -math.inf   # time.monotonic() of the last full redraw
        self._at_rest = {}           # what waits until the picture stops moving (when_at_rest)
        self.dragged = False         # this refresh follows another closely (see in_motion)
        if self.uses_ipympl:
            attach_ipympl_canvas(self.figure)
        else:
            FigureCanvasAgg(self.figure)
        self._moving = []
        self._background = None
        self._background_sent = True  # canvas path: the browser has the current background
        self._image = None           # the Image widget of the inline path, made on demand
        self._new_widget_callbacks = []   # see on_new_widget
        self._refreshes = 0
        self.figure.canvas.mpl_connect("draw_event", self._on_full_draw)
        self.figure.when_drawn(self._send_background)

    # --- what moves ------------------------------------------------------------
    def add_moving(self, *artists):
        """Mark artists as moving: they are left out of the background and
        painted on every :meth:`refresh`, in the order added. Returns them."""
        for artist in artists:
            artist.set_animated(True)
            self._moving.append(artist)
        return artists

    @property
    def moving(self) -> list:
        """The moving artists, in drawing order."""
        return list(self._moving)

    # --- drawing -----------------------------------------------------------------
    def _on_full_draw(self, event):
        # A full draw (first show, resize, 3D rotation with the mouse) renders
        # everything but the moving artists: keep that as the new background.
        canvas = self.figure.canvas
        if canvas.is_saving():        # savefig draws the moving artists too: not a background
            return
        self._background = canvas.copy_from_bbox(self.figure.bbox)
        self._background_sent = False         # sent once the draws this one sets off are done too
        self._paint_moving()
        self._agg_stale = False

    def _send_background(self):
        # the browser gets the new background, once per full draw: a draw whose texts stick out draws
        # again at once (layout.py), and only the last picture is worth encoding and sending
        if self._canvas is not None and not self._background_sent and self._background is not None:
            self._background_sent = True
            self._canvas.background = self.background_png()

    def _paint_moving(self):
        for artist in self._moving:
            self.figure.draw_artist(artist)

    def in_motion(self) -> bool:
        """True while a browser moves the picture itself (canvas backend with a rig, shown) and
        the last refresh was less than :data:`MOTION_S` ago: a slider is being dragged."""
        return (self.rig is not None and self._canvas is not None and self._canvas.shown
                and time.monotonic() - self.last_refresh < MOTION_S)

    def may_redraw(self) -> bool:
        """Whether a full redraw may happen now: always at rest; while a slider is dragged (see
        :meth:`in_motion`), at most every :data:`REDRAW_EVERY_S`."""
        return not self.in_motion() or time.monotonic() - self._last_redraw >= REDRAW_EVERY_S

    # --- what the canvas path and the tests read (the protocol with the browser: canvas.py) ------
    @property
    def seq(self) -> int:
        """The number of the pose last sent to the browser (canvas path): the browser's rest-frame
        request names it, and a frame is shown only if no newer pose has been sent since."""
        return self._seq

    @property
    def base_dpi(self) -> float:
        """The figure's dpi at pixel ratio 1: the canvas path renders at ``base_dpi`` × the screen's ratio."""
        return self._base_dpi

    @property
    def waits_for_rest(self) -> bool:
        """True while an action waits for the picture to stop moving (:meth:`when_at_rest`)."""
        return bool(self._at_rest)

    def when_at_rest(self, owner, action) -> None:
        """Call ``action()`` once the picture stops moving (the browser asks for its rest frame,
        or a picture is asked for: :meth:`png`); one pending action per ``owner``."""
        self._at_rest[id(owner)] = action

    def settle(self) -> None:
        """Run what waited for the picture to stop moving (see :meth:`when_at_rest`)."""
        while self._at_rest:
            _owner, action = self._at_rest.popitem()
            action()

    def redraw(self):
        """Draw everything again (after changing something that does not move,
        e.g. the axis limits or a title)."""
        self.dragged = False
        self._last_redraw = time.monotonic()
        self.figure.canvas.draw()
        self._publish()

    def refresh(self):
        """Show the moving artists where they are now: draws the pixels (the image and ipympl
        paths), or sends the artists to the browser (the canvas path: Agg draws them only when
        a picture is asked for, by :meth:`png` or the browser's rest frame)."""
        canvas = self.figure.canvas
        self.dragged = self.in_motion()      # the previous refresh was a moment ago
        self.last_refresh = time.monotonic()
        if self._background is None:
            canvas.draw()             # the draw_event handler caches the background
        elif self.backend == "canvas":
            self._agg_stale = True    # the browser paints; Agg only when a PNG is asked for
        else:
            canvas.restore_region(self._background)
            self._paint_moving()
            self._refreshes += 1
            if self.uses_ipympl and self._refreshes % _FULL_FRAME_EVERY == 0:
                canvas._force_full = True
            canvas.blit(self.figure.bbox)   # ipympl: sends the changed pixels; Agg: no-op
        self._publish()

    # --- showing -------------------------------------------------------------------
    @property
    def widget(self):
        """The widget that shows the figure: a :class:`~dhlab.views.live.canvas.CanvasWidget`,
        ipympl's canvas, or an ``ipywidgets.Image``."""
        if self.uses_ipympl:
            return self.figure.canvas
        if self.backend == "canvas":
            return self._canvas_widget()
        if self._image is None:
            import ipywidgets as widgets  # lazy: only the image path shows an ipywidgets.Image
            width, height = self.figure.canvas.get_width_height()
            self._image = widgets.Image(format="png", width=width, height=height)
            if self._background is None:
                self.figure.canvas.draw()
            self._publish()
        return self._image

    def on_new_widget(self, method) -> None:
        """Call the bound ``method(old, new)`` when :meth:`fall_back_to_image` replaces the figure's
        widget (a panel puts the new one where the old one was); held weakly."""
        self._new_widget_callbacks.append(weakref.WeakMethod(method))

    def fall_back_to_image(self) -> None:
        """Show PNG frames (the "image" backend) instead of the canvas backend's widget, whose
        module the page cannot run (see :func:`watch_front_end`)."""
        if self.backend != "canvas" or self._canvas is None:
            return
        old, self._canvas = self._canvas, None
        self.backend = "image"
        new = self.widget                       # the Image, with the current picture
        for ref in self._new_widget_callbacks:
            callback = ref()
            if callback is not None:
                callback(old, new)
        old.close()

    def _publish(self):
        if self._image is not None:
            self._image.value = self.png()
        if self._canvas is not None:
            from .canvas import send_scene  # here: canvas loads anywidget, which only the canvas backend needs

            self._seq += 1
            send_scene(self)

    def png(self) -> bytes:
        """The pixels as they are now, as PNG bytes."""
        self.settle()
        return self.current_png()

    def current_png(self) -> bytes:
        """The pixels of the moving artists where they are now, as PNG bytes, without running
        what waits for the picture to rest (:meth:`png` runs it first)."""
        self._current_agg()
        return self._encode()

    def background_png(self) -> bytes:
        """The figure without its moving artists (its cached background), as PNG bytes; the Agg
        buffer keeps what it holds (the moving artists too, if it had them)."""
        try:
            pixels = np.asarray(self._background)          # the region's own pixels (matplotlib >= 3.8)
        except (TypeError, ValueError):
            pixels = None
        if pixels is not None and pixels.shape == np.asarray(self.figure.canvas.buffer_rgba()).shape:
            return encode_png(pixels, alpha=PNG_WITH_ALPHA)
        self.figure.canvas.restore_region(self._background)      # an older matplotlib: via the buffer
        png = self._encode()
        self._paint_moving()
        self._agg_stale = False
        return png

    @property
    def css_size(self) -> list:
        """The figure's size in CSS pixels (its pixels at :attr:`base_dpi`)."""
        ratio = self.figure.dpi / self._base_dpi
        return [round(v / ratio) for v in self.figure.canvas.get_width_height()]

    def set_pixel_ratio(self, ratio: float) -> None:
        """Render at ``ratio`` device pixels per CSS pixel (sharp on a HiDPI screen): the figure is
        drawn again at ``base_dpi × ratio``, its widget keeps its CSS size."""
        if abs(self.figure.dpi - self._base_dpi * ratio) < 1e-9:
            return
        self.figure.set_dpi(self._base_dpi * ratio)
        self._background = None
        self.figure.canvas.draw()
        if self._canvas is not None:
            self._canvas.css_size = self.css_size
        self._publish()

    def _current_agg(self):
        """Bring the Agg buffer up to date (the canvas path paints it only when asked)."""
        if self._background is None:
            self.figure.canvas.draw()
        elif self._agg_stale:
            self.figure.canvas.restore_region(self._background)
            self._paint_moving()
            self._agg_stale = False

    def _encode(self) -> bytes:
        return encode_png(np.asarray(self.figure.canvas.buffer_rgba()), alpha=PNG_WITH_ALPHA)

    # --- the canvas path (see dhlab.views.live.canvas) -------------------------------------------
    @property
    def canvas_widget(self):
        """The :class:`~dhlab.views.live.canvas.CanvasWidget` of the canvas path once it is shown, else None."""
        return self._canvas

    def _canvas_widget(self):
        if self._canvas is None:
            from .canvas import CanvasWidget  # here: canvas loads anywidget, which only the canvas backend needs

            # set before the first draw: its draw_event handler sends the background to the widget
            self._canvas = CanvasWidget(self, css_size=self.css_size)
            if self._background is None:
                self.figure.canvas.draw()
            else:
                self._canvas.background = self.background_png()
            self._canvas.show_frame(self.current_png(), self._seq)
            watch_front_end(self)
        return self._canvas

    def close(self):
        """Release the widget (its browser view goes away); the figure can be garbage-collected."""
        if self.uses_ipympl:
            self.figure.canvas.close()
        elif self._image is not None:
            self._image.close()
        if self._canvas is not None:
            self._canvas.close()
            self._canvas = None
        self._background = None
