"""Screen rate of the SSRMS teach panel, old backends and new, side by side in one run.

For each backend — the old ``"ipympl"`` and ``"image"`` (inline) paths and the new
browser-side ``"canvas"`` (skipped, with the reason, until it imports) — at device
pixel ratio 1 and 2 (Playwright's ``device_scale_factor``), on
``dhlab.teach(dhlab.robots.ssrms(), backend=...)`` in JupyterLab:

* **key → changed pixels**: joint 2's slider handle focused, ``PRESSES`` presses of →,
  each after the figure settled; median and 90th percentile (ms), and every press must
  change the figure's pixels;
* **slider drag**: the mouse drags joint 2's handle along its track and back for 2 s;
  distinct frames of the figure per second (screenrate.py counts them), the messages the page
  sent the kernel meanwhile, and the kernel must end on the value the drag ended on;
* **rotation**: the mouse drags across the 3D figure for 2 s: frames per second (the
  inline image cannot rotate: it shows none, which is recorded, not asserted);
* **a panel that holds still**: the panel's bounding box, measured with joint 2 set to
  values across its whole range, is the same at each (±1 px), in a notebook column of
  968 px (JupyterLab's file browser open, as the issue measured) and 1,400 px.

Everything goes to ``tests/browser/results/screen_rate.json`` and a printed table.

What is asserted, and why: this machine is shared and has 2 cores, so the times
are recorded, not held to the issue's targets, unless ``DHLAB_RATE_THRESHOLDS=1``
(for the run on an idle machine): then key → pixels median ≤ 33 ms and p90 ≤ 50 ms,
slider drag and rotation ≥ 30 frames/s for the new backend. Always asserted: every
key press repaints the figure (pixels changed), the drag paints frames, the panel's
size never changes, and — when the canvas backend runs — it is faster than both old
ones (median key → pixels) and paints more frames in a drag.
"""
from __future__ import annotations

import json
import os
import re
import time
from pathlib import Path

import numpy as np
import pytest

import dhlab
import labdriver
from labdriver import NOTEBOOK_JS, close_notebook, open_notebook, run_all, settled
from screenrate import frames_during, install, key_presses, mouse_drag, screencast_changes, stats

HERE = Path(__file__).parent
BACKENDS = ["ipympl", "image", "canvas"]
RATIOS = [1, 2]
PRESSES = 30
DRAG_SECONDS = 2.0
SLIDER = 1                                  # joint 2 (the shoulder): the whole arm moves
COLUMNS = [968, 1400]                       # notebook column widths, px
THRESHOLDS = os.environ.get("DHLAB_RATE_THRESHOLDS", "") not in ("", "0")
TARGET = {"key_median_ms": 33, "key_p90_ms": 50, "drag_fps": 30, "rotation_fps": 30}
# searched inside an output area: the canvas backend's <canvas> carries its own class
FIGURE = (".jupyter-matplotlib-canvas-container canvas, .widget-image, canvas.dhlab-canvas")
_results: dict = {}
# how often the page lets a dragged slider tell the kernel (dhlab/views/live/rig.js)
RIG_JS = Path(dhlab.__file__).parent / "views" / "live" / "rig.js"
SLIDER_MESSAGE_MS = int(re.search(r"SLIDER_MESSAGE_MS = (\d+);", RIG_JS.read_text()).group(1))


def skip_unless_available(backend: str) -> None:
    """The canvas backend is measured once ``LiveFigure(backend="canvas")`` works here."""
    if backend != "canvas":
        return
    from dhlab.views.live.livefigure import LiveFigure

    try:
        LiveFigure(figsize=(3, 3), backend="canvas").close()
    except Exception as exc:                 # not built yet (DHLabError), or anywidget missing
        pytest.skip(f"the canvas backend is not available yet: {type(exc).__name__}: {exc}")




def set_column(page, column: int) -> None:
    """Resize the window until the notebook's output column is ``column`` px wide."""
    for _ in range(3):
        width = page.evaluate(f"() => {NOTEBOOK_JS}.node.getBoundingClientRect().width")
        if abs(width - column) < 1:
            return
        size = page.viewport_size
        page.set_viewport_size({"width": int(round(size["width"] + column - width)), "height": size["height"]})
        time.sleep(0.5)


def kernel(page, code: str) -> str:
    from test_latency_browser import execute

    return execute(page, code)


def opened_panel(page, lab_root, backend):
    path = labdriver.ssrms_panel_notebook(lab_root / "rate", backend, "rate")
    open_notebook(page, f"rate/{path.name}")
    run_all(page)
    output = page.locator(".jp-OutputArea-output", has=page.locator(".widget-slider")).first
    figure = output.locator(FIGURE).first
    try:
        figure.wait_for(timeout=120_000)
    except Exception:                       # say what the cell showed instead of a figure
        cell = page.locator(".jp-Cell .jp-OutputArea").first
        raise AssertionError(f"no figure in the {backend} panel; the output shows: "
                             f"{cell.inner_text()[:800]!r}") from None
    figure.scroll_into_view_if_needed()
    errors = output.locator(".widget-html", has_text="Error while updating")
    assert errors.count() == 0, errors.first.inner_text()[:500]
    return output, figure


def record(key: str, result: dict, results_dir: Path) -> None:
    path = results_dir / "screen_rate.json"
    everything = json.loads(path.read_text()) if path.exists() else {}
    everything[key] = result
    _results[key] = result
    path.write_text(json.dumps(everything, indent=1, sort_keys=True))


@pytest.mark.parametrize("ratio", RATIOS)
@pytest.mark.parametrize("backend", BACKENDS)
def test_screen_rate(browser, lab_server, lab_root, results_dir, backend, ratio):
    skip_unless_available(backend)
    page = labdriver.open_lab(browser, lab_server, 1400, 1000, ratio)   # file browser open
    sent = []                               # the page's messages to the kernel, while counting
    page.on("websocket", lambda ws: ws.on("framesent", lambda _payload: sent.append(1) if counting else None))
    counting = False
    try:
        output, figure = opened_panel(page, lab_root, backend)
        if backend == "canvas":             # the low-latency canvas (canvas.js): faster full repaints
            attributes = figure.evaluate("(c) => c.getContext('2d').getContextAttributes()")
            assert attributes.get("desynchronized") is True and attributes.get("alpha") is False, attributes
        install(page)
        handle = output.locator(".widget-slider .noUi-handle").nth(SLIDER)
        presses = key_presses(page, handle, lambda: settled(figure, pause=0.15), PRESSES)
        shown = float(handle.get_attribute("aria-valuenow") or "nan")
        track = output.locator(".widget-slider .noUi-target").nth(SLIDER).bounding_box()
        y = track["y"] + track["height"] / 2
        knob = handle.bounding_box()
        start = (knob["x"] + knob["width"] / 2, y)
        counting = True
        drag = frames_during(page, lambda: mouse_drag(page, start, (track["x"] + track["width"] - 2, y),
                                                      DRAG_SECONDS, back=True), DRAG_SECONDS)
        counting = False
        drag["messages_to_kernel"] = len(sent)
        settled(figure, pause=0.3)
        dragged_to = float(handle.get_attribute("aria-valuenow") or "nan")
        kernel_value = float(kernel(page, f"print(panel.sliders[{SLIDER}].value)"))
        box = figure.bounding_box()
        center = (box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
        rotation = frames_during(page, lambda: mouse_drag(page, center, (center[0] + 160, center[1] + 40),
                                                          DRAG_SECONDS, back=True), DRAG_SECONDS)
        view = kernel(page, "print(round(panel.view.ax.elev, 3), round(panel.view.ax.azim, 3))").split()
    finally:
        close_notebook(page)
        page.close()

    times = [p["ms"] for p in presses]
    result = {"backend": backend, "device_pixel_ratio": ratio, "presses": len(presses),
              "key_to_pixels_ms": stats(times), "unpainted_presses": sum(t is None for t in times),
              "changed_pixels_per_press": stats([p["changed_pixels"] for p in presses]),
              "slider_drag": drag, "rotation": rotation, "view_after_rotation": view,
              "slider_value_after_keys": shown, "thresholds_asserted": THRESHOLDS}
    record(f"{backend}@{ratio}x", result, results_dir)
    print(f"\nSSRMS teach panel, {backend}, pixel ratio {ratio}: " + json.dumps(result))

    assert result["unpainted_presses"] == 0, "a key press was never painted"
    assert all(p["changed_pixels"] > 0 for p in presses), "a key press left the figure's pixels unchanged"
    assert shown == pytest.approx(0.5 * PRESSES), "the slider did not take one step per key press"
    assert drag["frames"] > 0, "a slider drag painted no frame"
    assert kernel_value == pytest.approx(dragged_to), "the kernel did not get the value the drag ended on"
    if backend == "canvas":                 # the page spaces a dragged slider's messages (rig.js)
        per_second = 1000 / SLIDER_MESSAGE_MS       # + the first value, the last, and room for noise
        assert drag["messages_to_kernel"] <= per_second * drag["seconds"] + 8, drag
        for old in ("ipympl", "image"):
            before = _results.get(f"{old}@{ratio}x")
            if before and before["key_to_pixels_ms"]["median"] is not None:
                assert result["key_to_pixels_ms"]["median"] < before["key_to_pixels_ms"]["median"], old
                assert drag["fps"] > before["slider_drag"]["fps"], old
        if THRESHOLDS:
            assert result["key_to_pixels_ms"]["median"] <= TARGET["key_median_ms"]
            assert result["key_to_pixels_ms"]["p90"] <= TARGET["key_p90_ms"]
            assert drag["fps"] >= TARGET["drag_fps"] and rotation["fps"] >= TARGET["rotation_fps"]


@pytest.mark.parametrize("column", COLUMNS)
@pytest.mark.parametrize("backend", BACKENDS)
def test_panel_holds_still_while_a_slider_sweeps(browser, lab_server, lab_root, results_dir, backend, column):
    """The panel's box is the same (±1 px) at every value of joint 2 across its range."""
    skip_unless_available(backend)
    page = labdriver.open_lab(browser, lab_server, column + 400, 1000)
    try:
        output, figure = opened_panel(page, lab_root, backend)
        set_column(page, column)
        time.sleep(1.0)
        panel = output.locator(".widget-hbox", has=page.locator(FIGURE)).first
        readout = output.locator(".widget-html", has_text="x = ").first
        sizes = {}
        lo, hi = (float(v) for v in kernel(page, "s = panel.sliders[1]; print(s.min, s.max)").split())
        for value in np.linspace(lo, hi, 25):
            text = readout.inner_text()
            kernel(page, f"panel.sliders[1].value = {value:.1f}")
            deadline = time.monotonic() + 10
            while readout.inner_text() == text and time.monotonic() < deadline:
                time.sleep(0.05)
            time.sleep(0.25)
            box = panel.bounding_box()
            sizes[round(value, 1)] = (round(box["width"], 1), round(box["height"], 1))
        page.screenshot(path=str(results_dir / f"rate_holds_still-{backend}-{column}.png"))
    finally:
        close_notebook(page)
        page.close()
    widths, heights = (np.array([s[k] for s in sizes.values()]) for k in (0, 1))
    record(f"layout {backend} column {column}px", {"sizes_px": {str(k): v for k, v in sizes.items()}},
           results_dir)
    assert np.ptp(widths) <= 1 and np.ptp(heights) <= 1, f"the panel changed size: {sizes}"


def test_the_robot_moves_while_the_kernel_runs_another_cell(browser, lab_server, lab_root, results_dir):
    """Canvas backend: with the kernel busy (a cell sleeping 10 s), arrow keys on a slider still
    move the robot (the browser computes the pose: dhlab/views/live/rig.py); the kernel's readout
    follows once the cell ends."""
    skip_unless_available("canvas")
    page = labdriver.open_lab(browser, lab_server, 1400, 1000)
    try:
        output, figure = opened_panel(page, lab_root, "canvas")
        readout = output.locator(".widget-html", has_text="x = ").first
        text = readout.inner_text()
        before = settled(figure, pause=0.3)
        page.evaluate(f"""() => {{ window.__busy = {NOTEBOOK_JS}.sessionContext.session.kernel
            .requestExecute({{code: 'import time; time.sleep(10)'}}).done; }}""")
        page.wait_for_function(f"() => {NOTEBOOK_JS}.sessionContext.session.kernel.status === 'busy'")
        handle = output.locator(".widget-slider .noUi-handle").nth(SLIDER)
        handle.focus()
        page.evaluate("() => { globalThis.__dhlabCanvas.verify = true; }")   # dirty.js, checked
        for _ in range(10):                 # a key every 50 ms: one paint each (faster keys share a frame)
            page.keyboard.press("ArrowRight")
            time.sleep(0.05)
        time.sleep(0.5)
        moved = settled(figure, pause=0.2)
        checked, wrong = page.evaluate("() => { const t = globalThis.__dhlabCanvas; t.verify = false;"
                                       " return [t.dirtyChecked || 0, t.dirtyWrong || 0]; }")
        busy = page.evaluate(f"() => {NOTEBOOK_JS}.sessionContext.session.kernel.status")
        readout_then = readout.inner_text()
        page.screenshot(path=str(results_dir / "rate_kernel_busy.png"))
        page.evaluate("() => window.__busy")                       # the cell ends
        deadline = time.monotonic() + 20
        while readout.inner_text() == text and time.monotonic() < deadline:
            time.sleep(0.1)
        readout_after = readout.inner_text()
    finally:
        close_notebook(page)
        page.close()
    assert busy == "busy", "the kernel finished before the keys were tried: nothing shown"
    changed = (np.abs(moved.astype(int) - before.astype(int)).max(axis=2) > 40).mean()
    assert changed > 0.002, f"the robot did not move while the kernel was busy ({changed:.4%} of the pixels)"
    assert readout_then == text                 # the readout is the kernel's: it waited
    # each step repainted only the rectangle of the robot before and after it (dirty.js): the canvas
    # then held exactly what a full repaint would have
    assert checked >= 5 and wrong == 0, f"{checked} clipped repaints, up to {wrong} pixels unlike a full one"
    assert readout_after != text                # and came once the kernel was free


@pytest.mark.parametrize("ratio", RATIOS)
def test_the_counted_frames_reach_the_screen(browser, lab_server, lab_root, results_dir, ratio):
    """The page-side counter (screenrate.py: drawing calls, per animation frame) counts pictures
    that reach the screen: during a slider drag and a rotation of the canvas backend (whose
    low-latency canvas hands its pictures to the compositor outside the page's own frames), a
    screencast of the page sees as many frames in which the figure changed. The claim has a
    direction: the page must not count pictures that never reach the screen (counted at most 15 %
    above the screencast: seen 0 %), and it must not miss many (the screencast at most 25 % above
    the count: seen 0-15 %, a loaded CI machine seeing most, as the screencast also catches the
    compositor's half-way pictures during a drag). The screencast encodes every frame, so the rates
    themselves are lower here than in test_screen_rate: only the agreement is asserted."""
    skip_unless_available("canvas")
    page = labdriver.open_lab(browser, lab_server, 1400, 1000, ratio)
    counts = {}
    try:
        output, figure = opened_panel(page, lab_root, "canvas")
        install(page)
        handle = output.locator(".widget-slider .noUi-handle").nth(SLIDER)
        track = output.locator(".widget-slider .noUi-target").nth(SLIDER).bounding_box()
        y = track["y"] + track["height"] / 2
        knob = handle.bounding_box()
        box = figure.bounding_box()
        center = (box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
        moves = {"slider drag": lambda: mouse_drag(page, (knob["x"] + knob["width"] / 2, y),
                                                   (track["x"] + track["width"] - 2, y), DRAG_SECONDS, back=True),
                 "rotation": lambda: mouse_drag(page, center, (center[0] + 160, center[1] + 40),
                                                DRAG_SECONDS, back=True)}
        for name, move in moves.items():
            settled(figure, pause=0.3)
            counted, changes = screencast_changes(page, box, lambda: frames_during(page, move, DRAG_SECONDS))
            start, end = counted["window_ms"]
            counts[name] = {"counted": counted["frames"], "screencast": sum(start <= t <= end for t in changes)}
    finally:
        close_notebook(page)
        page.close()
    record(f"probe vs screencast @{ratio}x", counts, results_dir)
    print(f"\npixel ratio {ratio}: frames counted in the page vs seen by the screencast: {counts}")
    for name, c in counts.items():
        assert c["counted"] > 20, (name, c)
        assert c["counted"] - c["screencast"] <= max(3, 0.15 * c["counted"]), ("counted, not shown", name, c)
        assert c["screencast"] - c["counted"] <= max(3, 0.25 * c["counted"]), ("shown, not counted", name, c)


def test_print_table(results_dir):
    """The side-by-side table of what this run measured (runs last in the module)."""
    rows = [(k, r) for k, r in _results.items() if "key_to_pixels_ms" in r]
    if not rows:
        pytest.skip("nothing measured in this run")
    lines = ["| backend @ pixel ratio | key → pixels median (p90), ms | drag fps | rotation fps |",
             "|---|---|---|---|"]
    for key, r in rows:
        k = r["key_to_pixels_ms"]
        lines.append(f"| {key} | {k['median']} ({k['p90']}) | {r['slider_drag']['fps']} | {r['rotation']['fps']} |")
    table = "\n".join(lines)
    (results_dir / "screen_rate.md").write_text(table + "\n")
    print("\n" + table)
