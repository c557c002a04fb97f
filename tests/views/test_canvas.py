"""The canvas backend of LiveFigure (dhlab/views/live/canvas.py, scene.py): what it sends, its rest
frame, its fallback, and what it does with bad input from the browser or the user."""
from __future__ import annotations

import functools
import io

import numpy as np
import pytest
from matplotlib.patches import Circle
from PIL import Image

import dhlab
from dhlab.errors import DHLabError
from dhlab.views.live import backend, notebook_cell
from dhlab.views.live.livefigure import LiveFigure, choose_backend
from dhlab.views.live.scene import Unsupported, describe_scene


class Recorder:
    """Stands in for the browser: keeps what the widget sends."""

    def __init__(self, widget):
        self.messages = []
        widget.send = lambda content, buffers=None: self.messages.append((content, buffers))

    def scenes(self):
        return [m for m in self.messages if m[0].get("kind") == "scene"]


def canvas_panel(robot=None, **options):
    panel = dhlab.teach(robot or dhlab.robots.ssrms(), backend="canvas", **options)
    widget = panel.view.live.widget
    return panel, widget, Recorder(widget)


def pixels(png: bytes) -> np.ndarray:
    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB"))


def savefig_pixels(figure) -> np.ndarray:
    buffer = io.BytesIO()
    figure.savefig(buffer, format="rgba", dpi=figure.dpi)
    width, height = (int(round(v)) for v in figure.bbox.size)
    return np.frombuffer(buffer.getvalue(), np.uint8).reshape(height, width, 4)[..., :3]


def test_a_slider_step_sends_the_moving_artists_not_a_picture():
    panel, widget, browser = canvas_panel()
    frame_before = widget.frame
    panel.sliders[1].value += 10
    (content, buffers), = browser.scenes()
    kinds = [item["kind"] for item in content["items"]]
    assert kinds.count("polys") == 1 and "glyphs" in kinds and kinds.count("line") >= 5
    numbers = np.frombuffer(bytes(buffers[0]), np.float32)
    at, n = content["items"][kinds.index("line")]["points"]
    assert at + 3 * n <= len(numbers)
    assert content["seq"] == panel.view.live.seq
    assert widget.frame == frame_before          # no PNG was made for the step


def test_the_sent_points_are_where_the_robot_is():
    panel, widget, browser = canvas_panel()
    panel.sliders[0].value = 40.0
    content, buffers = browser.scenes()[-1]
    numbers = np.frombuffer(bytes(buffers[0]), np.float32)
    ee = content["items"][[i for i, a in enumerate(panel.view.live.moving) if a.get_visible()].index(
        panel.view.live.moving.index(panel.view.ee_marker))]
    at, n = ee["points"]
    np.testing.assert_allclose(numbers[at:at + 3], panel.view.frames[-1][:3, 3], rtol=1e-6, atol=1e-6)


def test_the_rest_frame_is_exactly_what_savefig_draws():
    for robot in (dhlab.robots.ssrms(), dhlab.robots.pr_mechanism()):
        panel, widget, browser = canvas_panel(robot)
        panel.sliders[0].value = panel.sliders[0].value + 0.6 * (panel.sliders[0].max - panel.sliders[0].value)
        live = panel.view.live
        widget.receive({"kind": "rest", "seq": live.seq})
        assert widget.frame_seq == live.seq
        np.testing.assert_array_equal(pixels(widget.frame), savefig_pixels(live.figure))


def test_a_stale_rest_request_is_not_answered():
    panel, widget, browser = canvas_panel()
    panel.sliders[1].value += 5
    old = panel.view.live.seq
    panel.sliders[1].value += 5
    widget.receive({"kind": "rest", "seq": old})
    assert widget.frame_seq < old                 # a newer pose is on its way: no frame for the old one


def test_png_is_current_although_refresh_draws_nothing():
    canvas, _, _ = canvas_panel()
    image = dhlab.teach(dhlab.robots.ssrms(), backend="image")
    for panel in (canvas, image):
        panel.sliders[2].value = 30.0
    np.testing.assert_array_equal(pixels(canvas.view.live.png()), pixels(image.view.live.png()))


def test_an_artist_it_cannot_send_gives_a_full_matplotlib_frame():
    live = LiveFigure(figsize=(4.5, 4.5), backend="canvas")
    ax = live.figure.add_subplot()
    ax.set(xlim=(-1, 1), ylim=(-1, 1))
    dot = Circle((0, 0), 0.2)
    ax.add_patch(dot)
    live.add_moving(dot)
    with pytest.raises(Unsupported):
        describe_scene(live.figure, live.moving)
    widget = live.widget
    browser = Recorder(widget)
    dot.center = (0.5, 0.5)
    live.refresh()
    assert browser.scenes() == []
    assert widget.frame_seq == live.seq
    np.testing.assert_array_equal(pixels(widget.frame), savefig_pixels(live.figure))


def test_turning_the_view_in_the_browser_ends_on_that_view():
    panel, widget, browser = canvas_panel()
    background = widget.background
    widget.receive({"kind": "view", "axes": 0, "elev": 12.5, "azim": 77.25})
    ax = panel.view.ax
    assert (ax.elev, ax.azim) == (12.5, 77.25)
    assert widget.background != background                 # matplotlib drew the new view
    content, _ = browser.scenes()[-1]
    assert content["spaces"][0]["elev"] == 12.5


@pytest.mark.parametrize("message", [
    None, "rest", {"kind": "rest", "seq": "3"}, {"kind": "rest", "seq": True}, {"kind": "view", "axes": 5,
                                                                                "elev": 1, "azim": 2},
    {"kind": "view", "axes": 0, "elev": float("nan"), "azim": 2}, {"kind": "view", "axes": 0, "elev": "1"},
    {"kind": "unknown"}, {}])
def test_odd_messages_from_the_browser_change_nothing(message):
    panel, widget, browser = canvas_panel()
    view = (panel.view.ax.elev, panel.view.ax.azim)
    widget.receive(message)
    assert (panel.view.ax.elev, panel.view.ax.azim) == view
    assert browser.messages == []


def test_a_hidpi_screen_gets_a_sharper_picture_of_the_same_size():
    panel, widget, browser = canvas_panel()
    live = panel.view.live
    css = list(widget.css_size)
    width = pixels(widget.background).shape[1]
    widget.pixel_ratio = 2.0
    assert list(widget.css_size) == css
    assert pixels(widget.background).shape[1] == 2 * width
    assert live.figure.dpi == 2 * live.base_dpi
    widget.pixel_ratio = float("nan")                   # ignored
    widget.pixel_ratio = 40.0                           # clamped
    assert live.figure.dpi == 3 * live.base_dpi


def test_backend_names_and_the_environment_override(monkeypatch):
    monkeypatch.delenv("DHLAB_BACKEND", raising=False)
    # another test in this process may have switched matplotlib to ipympl: decide both ways
    monkeypatch.setattr(backend, "ipympl_active", lambda: False)
    assert choose_backend("auto") == "image"           # no kernel here: nothing shows a widget
    monkeypatch.setattr(backend, "in_kernel", lambda: True)
    assert choose_backend("auto") == "canvas"          # in a kernel: the browser paints
    monkeypatch.setattr(backend, "anywidget_imports", lambda: False)
    assert choose_backend("auto") == "image"           # ... if anywidget is there
    monkeypatch.setattr(backend, "ipympl_active", lambda: True)
    assert choose_backend("auto") == "ipympl"          # under %matplotlib widget
    assert choose_backend("canvas") == "canvas"
    monkeypatch.setenv("DHLAB_BACKEND", "canvas")
    assert choose_backend("auto") == "canvas"
    assert LiveFigure(backend="image").backend == "image"     # an explicit choice wins
    monkeypatch.setenv("DHLAB_BACKEND", "webgl")
    with pytest.raises(DHLabError, match="DHLAB_BACKEND"):
        choose_backend("auto")
    for bad in ("Canvas", 3, None):
        with pytest.raises(DHLabError, match="backend must be one of"):
            LiveFigure(backend=bad)


@pytest.mark.parametrize("make", [
    lambda: dhlab.stepthrough(backend="canvas"),
    lambda: dhlab.teach(dhlab.robots.rrr_example(), backend="canvas"),
    lambda: dhlab.teach(dhlab.robots.puma560(), backend="canvas", joint_axes=True),
    lambda: dhlab.spaces(dhlab.robots.pr_mechanism(), backend="canvas",
                         ik=functools.partial(dhlab.ik.pr_mechanism_ik, dhlab.robots.pr_mechanism())),
])
def test_the_course_panels_send_scenes(make):
    panel = make()
    live = panel.live if hasattr(panel, "live") else panel.view.live
    content, numbers = describe_scene(live.figure, live.moving)        # raises if an artist is not supported
    assert content["items"] and len(numbers)


def _place_boxes_every_spot(anchors, sizes, bounds, obstacles):
    """labels.place_boxes as it was before it stopped at the first free ring: every spot scored."""
    from dhlab.views import labels

    anchors, sizes = np.asarray(anchors, float), np.asarray(sizes, float)
    angles = 2 * np.pi * np.arange(labels._DIRECTIONS) / labels._DIRECTIONS
    unit = np.column_stack([np.cos(angles), np.sin(angles)])
    radii = np.asarray(labels.RADII)
    placed, corners = np.zeros((0, 4)), np.zeros_like(anchors)
    gaps = anchors[:, None, :] - anchors[None, :, :]
    crowd = np.sum(1 / (1 + np.linalg.norm(gaps, axis=2)), axis=1)
    for k in np.argsort(-crowd, kind="stable"):
        a, (w, h), d = anchors[k], sizes[k], gaps[k]
        away = np.sum(d / np.maximum(np.sum(d * d, axis=1), 1.0)[:, None], axis=0)
        if np.linalg.norm(away) < 1e-9:
            away = np.array([0.6, 0.8])
        u = unit[np.argsort(-(unit @ away), kind="stable")]
        reach = labels.GAP + radii[:, None] + 0.5 * (np.abs(u[:, 0]) * w + np.abs(u[:, 1]) * h)[None, :]
        centres = a + u[None, :, :] * reach[:, :, None]
        boxes = np.concatenate([centres - [w / 2, h / 2], centres + [w / 2, h / 2]], axis=-1).reshape(-1, 4)
        cost = (labels.overlap_cost(boxes, placed) + labels.outside_cost(boxes, bounds)
                + labels.cover_cost(boxes, obstacles, a) + 1e-3 * np.repeat(np.arange(len(radii)), len(u)))
        best = int(np.argmin(cost))
        corners[k] = boxes[best, :2]
        placed = np.vstack([placed, boxes[best]])
    return corners


def test_label_placement_stops_early_without_changing_the_result():
    # each slider step places the labels again: place_boxes stops at the first ring with a free
    # spot (costs are never negative), which must give the same spots as scoring them all
    from dhlab.views.labels import place_boxes

    rng = np.random.default_rng(7)
    for _ in range(150):
        k = int(rng.integers(1, 9))
        anchors = rng.random((k, 2)) * rng.choice([60, 200, 500])
        sizes = rng.random((k, 2)) * [60, 20] + [10, 8]
        obstacles = rng.random((int(rng.integers(0, 200)), 2)) * 500
        bounds = (0, 0, float(rng.choice([150, 300, 500])), float(rng.choice([150, 300, 500])))
        got, _ = place_boxes(anchors, sizes, bounds, obstacles)
        np.testing.assert_array_equal(got, _place_boxes_every_spot(anchors, sizes, bounds, obstacles))


def test_a_closed_panel_sends_nothing_and_still_has_a_picture():
    panel, widget, browser = canvas_panel()
    panel.close()
    panel.view.update(panel.view.q + 0.1)           # e.g. a callback after the close
    assert browser.messages == []
    assert panel.view.live.png().startswith(b"\x89PNG")


def test_camera_buttons_and_zoom_redraw_the_background_and_resend_the_scene():
    panel, widget, browser = canvas_panel()
    background = widget.background
    panel.view.set_camera("top")
    assert widget.background != background
    content, _ = browser.scenes()[-1]
    assert (content["spaces"][0]["elev"], content["spaces"][0]["azim"]) == (90.0, -90.0)
    background = widget.background
    panel.view.set_zoom(2.0)
    assert widget.background != background and len(browser.scenes()) == 2


def _ragged_faces():
    return [np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0]], float),
            np.array([[0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], float)]


def test_faces_of_a_ragged_poly3dcollection_on_this_matplotlib():
    """The browser gets every face's corners, NaN where a face has fewer (faces3d)."""
    from matplotlib.figure import Figure
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    from dhlab.views.live.scene import faces3d

    ax = Figure().add_subplot(projection="3d")
    polys = ax.add_collection3d(Poly3DCollection(_ragged_faces()))
    faces = faces3d(polys)
    assert faces.shape == (2, 4, 3)
    np.testing.assert_array_equal(faces[0, :3], _ragged_faces()[0])
    assert np.isnan(faces[0, 3]).all()
    np.testing.assert_array_equal(faces[1], _ragged_faces()[1])


def test_faces_as_matplotlib_3_8_keeps_them():
    """matplotlib 3.8 (the browser edition's Pyodide) keeps the corners as homogeneous columns
    ``_vec`` cut by ``_segslices`` and has no ``_faces``: faces3d reads that layout too."""
    from types import SimpleNamespace

    from dhlab.views.live.scene import faces3d

    points = np.vstack(_ragged_faces())
    old = SimpleNamespace(_vec=np.vstack([points.T, np.ones(len(points))]),
                          _segslices=[slice(0, 3), slice(3, 7)])
    faces = faces3d(old)
    assert faces.shape == (2, 4, 3)
    np.testing.assert_array_equal(faces[1], _ragged_faces()[1])
    np.testing.assert_array_equal(faces[0, :3], _ragged_faces()[0])
    assert np.isnan(faces[0, 3]).all()
    with pytest.raises(Unsupported):                 # neither layout: a full frame, not a crash
        faces3d(SimpleNamespace())


# --- a page that shows widgets but cannot run canvas.js (anywidget's front end missing) ---------
def _in_a_kernel_loop(monkeypatch, front_end: bool, say_loaded: bool):
    """Make a canvas panel inside a running event loop (as in a kernel), in a cell run from a
    notebook page (the request names the cell) or not, the page saying "loaded" or not; wait as a
    kernel would between cells. Returns the panel and its first figure widget."""
    import asyncio

    monkeypatch.setattr(notebook_cell, "_WATCH_S", 0.01)
    monkeypatch.setattr(notebook_cell, "FRONT_END_S", 0.04)
    monkeypatch.setattr(notebook_cell, "current_cell", lambda: ("cell-1", 1) if front_end else None)

    async def scenario():
        panel, widget, _browser = canvas_panel()
        if say_loaded:
            widget.receive({"kind": "loaded"})
        await asyncio.sleep(0.3)
        return panel, widget

    return asyncio.run(scenario())


def test_a_page_that_cannot_run_the_module_gets_png_frames_in_the_same_place(monkeypatch):
    import ipywidgets

    panel, canvas_widget = _in_a_kernel_loop(monkeypatch, front_end=True, say_loaded=False)
    live = panel.view.live
    figure = panel.children[0]
    assert live.backend == "image" and isinstance(figure, ipywidgets.Image)
    assert canvas_widget not in panel.children and "dhlab-figure" in figure._dom_classes
    assert not any(type(w).__name__ == "SliderKeys" for w in panel.children[1].children)
    assert panel.keys_widget is None                       # the keys widget (its front end is missing) closed
    assert np.array_equal(pixels(figure.value), savefig_pixels(panel.figure))
    panel.sliders[1].value += 30                     # the PNG follows the sliders
    assert np.array_equal(pixels(figure.value), savefig_pixels(panel.figure))
    assert canvas_widget.comm is None                # the canvas widget is closed


@pytest.mark.parametrize("front_end, say_loaded", [(True, True), (False, False)])
def test_the_canvas_stays_where_the_page_runs_it_or_no_page_is_there(monkeypatch, front_end, say_loaded):
    panel, canvas_widget = _in_a_kernel_loop(monkeypatch, front_end, say_loaded)
    assert panel.view.live.backend == "canvas" and panel.children[0] is canvas_widget


def test_outside_an_event_loop_nothing_is_watched():
    panel, widget, _browser = canvas_panel()          # a script or a test: no kernel loop
    assert panel.view.live.backend == "canvas" and panel.children[0] is widget
