"""Page-side probes for the screen-rate measurements, shared by JupyterLab's
tier (tests/browser) and the browser edition's (tests/lite).

What counts as a *frame* of the figure, whatever the backend draws with:

* an ``<img>`` in the notebook's outputs finishes loading a new picture (the inline
  backend: ``ipywidgets.Image``);
* a ``<canvas>`` in the outputs is drawn on (ipympl's ``drawImage`` of the new pixels, or
  the browser-side canvas backend's own strokes and fills): every 2D-context drawing
  call on a canvas inside ``.jp-OutputArea-output`` (or Voilà's) marks the figure dirty.

A ``requestAnimationFrame`` loop then counts the screen frames on which the figure was
dirty: that is the number of distinct pictures the screen showed. A key press is timed
from its ``keydown`` time stamp to the animation frame after the first picture that
follows it (the same method as test_latency_browser.py: the frame is really painted
after that animation frame starts; the time is what the student waits for).

A picture drawn *inside* an animation frame callback (the canvas backend paints in
``requestAnimationFrame``) is on the screen in that same frame; the probe's own
frame callback of that frame may have run before it, so it would only count it one
frame (~17 ms) later. Such a press is timed at the start of the callback that drew it
(the time the probe's callback would have recorded had it run after), so every
backend is timed to the frame that shows its picture.
"""
from __future__ import annotations

import time

import numpy as np

PROBE_JS = r"""() => {
  if (window.__dhlabRate) return;
  const rate = window.__dhlabRate = {dirty: false, frames: [], press: null, counting: false};
  const now = () => performance.now();
  const inFigure = (node) => node && node.closest
      && node.closest('.jp-OutputArea-output, .jupyter-widgets');
  // a drawing made inside an animation frame callback shows in that frame (see above)
  let frameStart = null;
  const request = window.requestAnimationFrame.bind(window);
  window.requestAnimationFrame = (callback) => request((t) => {
    const outer = frameStart;
    frameStart = now();
    try { return callback(t); } finally { frameStart = outer; }
  });
  const mark = () => {
    rate.dirty = true;
    const p = rate.press;
    if (p && p.drawn === undefined) {
      p.drawn = now();
      if (frameStart !== null) p.painted = frameStart;
    }
  };
  document.addEventListener('keydown', (e) => {
    if (['ArrowRight', 'ArrowLeft', 'ArrowUp', 'ArrowDown', 'PageUp', 'PageDown', 'Home', 'End'].includes(e.key))
      rate.press = {key: e.timeStamp};
  }, true);
  document.addEventListener('load', (e) => { if (e.target.tagName === 'IMG' && inFigure(e.target)) mark(); }, true);
  const proto = CanvasRenderingContext2D.prototype;
  for (const name of ['drawImage', 'putImageData', 'fill', 'stroke', 'fillText', 'strokeText', 'fillRect']) {
    const original = proto[name];
    proto[name] = function (...args) {
      if (this.canvas && this.canvas.isConnected && inFigure(this.canvas)) mark();
      return original.apply(this, args);
    };
  }
  const tick = () => {
    const t = now();
    if (rate.dirty) {
      rate.dirty = false;
      if (rate.counting) rate.frames.push(t);
      const p = rate.press;
      if (p && p.drawn !== undefined && p.painted === undefined) p.painted = t;
    }
    request(tick);
  };
  request(tick);
}"""


def install(page) -> None:
    """Put the probes in the page (once per page)."""
    page.evaluate(PROBE_JS)


def stats(values) -> dict:
    """Median, 90th percentile and count of the values (None left out)."""
    values = np.asarray([v for v in values if v is not None], dtype=float)
    if not len(values):
        return {"median": None, "p90": None, "n": 0}
    return {"median": round(float(np.median(values)), 1), "p90": round(float(np.percentile(values, 90)), 1),
            "n": int(len(values))}


def key_presses(page, handle, figure_pixels, presses: int, key: str = "ArrowRight") -> list:
    """``presses`` presses of ``key`` on the slider ``handle``, each after the figure settled;
    for each: ms from the key to the painted frame, and the number of changed pixels."""
    results = []
    for _ in range(presses):
        before = figure_pixels()
        page.evaluate("() => { window.__dhlabRate.press = null; }")
        handle.focus()
        page.keyboard.press(key)
        try:
            page.wait_for_function("() => { const p = window.__dhlabRate.press;"
                                   " return p && p.painted !== undefined; }", timeout=10_000)
        except Exception:                 # never painted: recorded as such, the test decides
            results.append({"ms": None, "changed_pixels": 0})
            continue
        press = page.evaluate("() => window.__dhlabRate.press")
        after = figure_pixels()
        changed = int((np.abs(after - before).max(axis=2) > 0).sum()) if after.shape == before.shape \
            else int(after.size)
        results.append({"ms": press["painted"] - press["key"], "changed_pixels": changed})
    return results


def frames_during(page, drag, seconds: float) -> dict:
    """Run ``drag()`` (which lasts about ``seconds``) and count the figure's distinct
    frames painted while it ran: frames per second, and the longest gap between two."""
    page.evaluate("() => { const r = window.__dhlabRate; r.frames = []; r.dirty = false; r.counting = true; }")
    start = page.evaluate("() => performance.now()")
    drag()
    end = page.evaluate("() => performance.now()")
    frames = page.evaluate("() => { const r = window.__dhlabRate; r.counting = false; return r.frames; }")
    inside = [t for t in frames if start <= t <= end]
    gaps = np.diff([start, *inside, end])
    span = max(end - start, 1.0) / 1000
    return {"fps": round(len(inside) / span, 1), "frames": len(inside), "seconds": round(span, 2),
            "longest_gap_ms": round(float(gaps.max()), 1) if len(gaps) else None, "window_ms": [start, end]}


def mouse_drag(page, start: tuple, end: tuple, seconds: float, back: bool = False) -> None:
    """Press the mouse at ``start``, move it to ``end`` (and back, with ``back``) in steps of
    ~16 ms (a 60 Hz mouse) over ``seconds``, release it."""
    path = [np.asarray(start, float), np.asarray(end, float)]
    if back:
        path.append(np.asarray(start, float))
    legs = len(path) - 1
    steps = max(int(seconds * 60 / legs), 2)
    page.mouse.move(*path[0])
    page.mouse.down()
    t0 = time.monotonic()
    k = 0
    for a, b in zip(path, path[1:]):
        for s in range(1, steps + 1):
            page.mouse.move(*(a + (b - a) * s / steps))
            k += 1
            wait = t0 + k * seconds / (steps * legs) - time.monotonic()
            if wait > 0:
                time.sleep(wait)
    page.mouse.up()


def screencast_changes(page, box: dict, action):
    """Run ``action()`` while Chrome screencasts the page (``Page.startScreencast``: one JPEG per
    frame the compositor produces); returns what ``action`` returned and the times (page clock,
    ms, as ``performance.now()``) of the screen frames in which the figure's box ``box`` (CSS px)
    looks different from the frame before: the pictures of the figure that reached the screen."""
    import base64
    import io

    from PIL import Image

    cdp = page.context.new_cdp_session(page)
    frames = []

    def on_frame(params):
        frames.append((params["metadata"]["timestamp"], params["data"]))
        cdp.send("Page.screencastFrameAck", {"sessionId": params["sessionId"]})

    cdp.on("Page.screencastFrame", on_frame)
    cdp.send("Page.startScreencast", {"format": "jpeg", "quality": 60, "everyNthFrame": 1})
    try:
        time.sleep(0.5)
        result = action()
        time.sleep(0.3)
    finally:
        cdp.send("Page.stopScreencast")
        cdp.detach()
    origin = page.evaluate("() => performance.timeOrigin")            # epoch ms of performance.now() == 0
    width, height = page.viewport_size["width"], page.viewport_size["height"]
    changes, last = [], None
    for stamp, data in frames:
        image = np.asarray(Image.open(io.BytesIO(base64.b64decode(data))).convert("L"), dtype=np.int16)
        sx, sy = image.shape[1] / width, image.shape[0] / height
        crop = image[int(box["y"] * sy):int((box["y"] + box["height"]) * sy),
                     int(box["x"] * sx):int((box["x"] + box["width"]) * sx)]
        if last is not None and np.abs(crop - last).max() > 40:     # more than JPEG's own noise
            changes.append(stamp * 1000 - origin)
        last = crop
    return result, changes
