"""The "canvas" backend of a LiveFigure: the browser paints what moves, matplotlib the rest.

Why: with the PNG backends every slider step costs a full Agg render and a PNG in the kernel
(~17 ms for the SSRMS teach panel) and a PNG decode in the browser, so a drag shows 12-20
frames a second. Here (an anywidget, its ES module ``canvas.js``):

* matplotlib renders the figure **without** the moving artists once (the *background*, the
  picture :class:`~dhlab.views.live.livefigure.LiveFigure` already keeps for blitting), and again
  only when it changes (reframing, camera, zoom, labels toggled, the screen's pixel ratio);
* each refresh sends the moving artists as numbers (:mod:`dhlab.views.live.scene`) in one custom
  message with a float32 buffer (not a trait: no echo, nothing kept); the browser projects them
  with the axes' own matrices and paints them over the background;
* when no pose has arrived for 150 ms, the browser asks for the **rest frame**: matplotlib
  draws the whole figure with Agg and sends it as a PNG, shown instead of the overlay. At rest
  the picture is exactly matplotlib's;
* with a rig (:mod:`dhlab.views.live.rig`: a teach or spaces panel), the browser moves the robot
  itself as soon as a joint slider moves, and the kernel's scene of that pose replaces it;
* dragging a 3D axes turns it in the browser; on release the final (elev, azim) comes back
  here, the axes take that view and matplotlib redraws;
* a notebook page that cannot run ``canvas.js`` (anywidget's front end is not installed where
  JupyterLab runs) never says "loaded": after a few seconds the figure falls back to PNG
  frames (the "image" backend) in the same place (:func:`dhlab.views.live.notebook_cell.watch_front_end`).

An artist the browser cannot paint (see :class:`~dhlab.views.live.scene.Unsupported`) makes that
figure send a full matplotlib frame at every step instead (the old cost, never a wrong
picture). Without a browser (nbval, scripts) nothing waits for one: the messages go nowhere.
"""
from __future__ import annotations

import math
import weakref
from pathlib import Path

import anywidget
import traitlets

from .scene import Unsupported, css_color, describe_scene

__all__ = ["CanvasWidget", "send_scene", "send_rig", "send_rest", "turned", "set_pixel_ratio",
           "MIN_RATIO", "MAX_RATIO"]

MIN_RATIO, MAX_RATIO = 1.0, 3.0        # pixel ratios rendered (a 4K laptop reports 2 to 2.5)


def _bundle(*names) -> str:
    """One ES module from several files of this folder (anywidget loads one module): each file's
    imports of the others (``import ... from "./x.js"``) are dropped, their code comes first."""
    here = Path(__file__).parent
    parts = []
    for name in names:
        text = (here / name).read_text(encoding="utf-8")
        parts.append("\n".join(line for line in text.splitlines()
                               if not (line.startswith("import ") and '"./' in line)))
    return "\n".join(parts)



class CanvasWidget(anywidget.AnyWidget):
    """The browser view of a LiveFigure with the canvas backend.

    Traits: ``background`` (PNG without the moving artists), ``frame`` and ``frame_seq`` (the
    last full matplotlib frame and the pose it shows), ``css_size`` (width, height in CSS
    pixels), ``pixel_ratio`` (set by the browser: the figure is rendered at that many device
    pixels per CSS pixel, so that it is sharp on a HiDPI screen).
    """

    _esm = _bundle("dirty.js", "rig.js", "canvas.js")
    background = traitlets.Bytes(b"").tag(sync=True)
    frame = traitlets.Bytes(b"").tag(sync=True)
    frame_seq = traitlets.Int(-1).tag(sync=True)
    css_size = traitlets.List([0, 0]).tag(sync=True)
    pixel_ratio = traitlets.Float(1.0).tag(sync=True)

    def __init__(self, live, **kwargs):
        super().__init__(**kwargs)
        self._live = weakref.ref(live)          # the figure must not live on because of its widget
        self.shown = False                      # a browser shows it (it said "ready")
        self.loaded = False                     # a browser runs canvas.js (it said "loaded")
        self.on_msg(self._on_browser_message)
        self.observe(self._on_ratio, names="pixel_ratio")

    # --- what the browser says -------------------------------------------------------------
    def _on_browser_message(self, _widget, content, _buffers):
        self.receive(content)

    def receive(self, message) -> None:
        """Act on one ``message`` of the browser (``canvas.js``), as anywidget delivers it:

        * ``{"kind": "loaded"}``: the page runs ``canvas.js``; ``{"kind": "ready"}``: it shows the
          figure — the kernel sends the rig and the scene;
        * ``{"kind": "rest", "seq": n}``: the picture has not moved for a while — the kernel sends
          matplotlib's frame of pose ``n`` if it is still the last one (:attr:`LiveFigure.seq`);
        * ``{"kind": "view", "axes": i, "elev": e, "azim": a}``: a 3D axes was turned in the browser.

        Anything else (a newer or older front end) is ignored. Tests drive the protocol with it
        as a browser would.
        """
        live = self._live()
        content = message
        if live is None or not isinstance(content, dict):
            return
        kind = content.get("kind")
        if kind in ("loaded", "ready"):
            self.loaded = True
        if kind == "ready":
            self.shown = True
            send_rig(live)
            send_scene(live)
        elif kind == "rest" and _whole(content.get("seq")):
            send_rest(live, content["seq"])
        elif kind == "view":
            axes, elev, azim = content.get("axes"), content.get("elev"), content.get("azim")
            if _whole(axes) and 0 <= axes < len(live.figure.axes) and _finite(elev) and _finite(azim):
                turned(live, live.figure.axes[axes], float(elev), float(azim))
        # anything else (a newer or older front end): ignored, the picture stays right

    def _on_ratio(self, change):
        live = self._live()
        ratio = change["new"]
        if live is not None and _finite(ratio):
            set_pixel_ratio(live, min(max(float(ratio), MIN_RATIO), MAX_RATIO))

    # --- what the kernel sends ----------------------------------------------------------------
    def send_scene(self, content: dict, numbers) -> None:
        """The moving artists (see :func:`dhlab.views.live.scene.describe_scene`)."""
        self.send(dict(content, kind="scene"), buffers=[memoryview(numbers.tobytes())])

    def show_frame(self, png: bytes, seq: int) -> None:
        """A full matplotlib frame: the browser shows it if no newer pose has arrived."""
        with self.hold_sync():
            self.frame, self.frame_seq = png, seq


# --- what a LiveFigure does on the canvas path ----------------------------------------------
def send_scene(live) -> None:
    """The moving artists to the browser; a full frame if one of them cannot be sent."""
    try:
        content, numbers = describe_scene(live.figure, live.moving, quick=live.dragged)
    except Unsupported:
        live.canvas_widget.show_frame(live.current_png(), live.seq)
        return
    content["seq"] = live.seq
    if live.rig is not None:
        content["q"] = live.rig.q          # the pose drawn: the browser's own may be newer
    content["face"] = css_color(live.figure.get_facecolor())
    live.canvas_widget.send_scene(content, numbers)


def send_rig(live) -> None:
    """How the picture hangs on the chain (:mod:`dhlab.views.live.rig`), if the figure has a rig:
    the browser then moves it as soon as a slider moves."""
    if live.rig is None:
        return
    content, numbers = live.rig.describe(live.moving)
    live.canvas_widget.send(content, buffers=[memoryview(numbers.tobytes())])


def send_rest(live, seq: int) -> None:
    """The browser rests on pose ``seq``: matplotlib's frame of it (if still the current one)."""
    live.settle()        # e.g. framing the robot again after a drag: a new scene (and seq) if it redraws
    if seq == live.seq and live.canvas_widget is not None:
        live.canvas_widget.show_frame(live.current_png(), seq)


def turned(live, ax, elev: float, azim: float) -> None:
    """The browser turned ``ax`` to (elev, azim): the axes take that view and matplotlib draws it."""
    ax.view_init(elev=elev, azim=azim, roll=getattr(ax, "roll", 0.0))
    live.redraw()


def set_pixel_ratio(live, ratio: float) -> None:
    """Render at ``ratio`` device pixels per CSS pixel (:meth:`LiveFigure.set_pixel_ratio`)."""
    live.set_pixel_ratio(ratio)


def _whole(value) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)


def _finite(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)
