"""The rig (dhlab/views/live/rig.py, rig.js): the browser moves the robot's picture as soon as a slider
moves, from the chain's kinematics and each point's node; it must land where the kernel's next
picture puts it.

For every catalogue robot: the browser's chain (rig.js, run in node) gives the same nodes as
Python; with the rig made at one pose, the browser's prediction of another pose puts every rigged
point within 0.5 px of where the kernel's scene of that pose (i.e. matplotlib) puts it; measuring
the prediction leaves the view exactly as it was.
"""
from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

import dhlab
from dhlab.views.live.rig import nodes, program_steps

NODE = shutil.which("node")
needs_node = pytest.mark.skipif(NODE is None, reason="node (JavaScript) is not installed")
RIG_JS = Path(dhlab.__file__).parent / "views" / "live" / "rig.js"

_RUNNER = """
import * as m from %s;
let text = "";
process.stdin.on("data", (d) => { text += d; });
process.stdin.on("end", () => {
  const jobs = JSON.parse(text);
  const out = jobs.map((job) => {
    if (job.nodes) return Array.from(m.chainNodes(job.steps, job.q));
    if (job.covers) return m.coversAll(job.rig, Float32Array.from(job.rigData), job.items);
    const rigData = Float32Array.from(job.rigData), data = Float32Array.from(job.data, (v) => (v === null ? NaN : v));
    return Array.from(m.rigged(job.rig, rigData, job.items, data, job.q), (v) => (Number.isNaN(v) ? null : v));
  });
  process.stdout.write(JSON.stringify(out));
});
"""


def run_js(jobs: list) -> list:
    result = subprocess.run([NODE, "--input-type=module", "-e", _RUNNER % json.dumps(RIG_JS.as_uri())],
                            input=json.dumps(jobs), capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr[-2000:]
    return json.loads(result.stdout)


def random_q(robot, rng):
    lo, hi = np.array(robot.qlim, dtype=float).T
    return rng.uniform(np.maximum(lo, -np.pi), np.minimum(hi, np.pi))


def test_the_nodes_hold_every_frame_and_end_at_the_end_effector():
    rng = np.random.default_rng(1)
    for name, make in dhlab.robots.catalogue().items():
        robot = make()
        for _ in range(3):
            q = random_q(robot, rng)
            N = nodes(robot, q)
            np.testing.assert_allclose(N[-1], robot.fk(q), atol=1e-12, err_msg=name)
            for frame in robot.frames(q):
                assert np.abs(N - frame).max(axis=(1, 2)).min() < 1e-12, name


@needs_node
def test_the_browser_chain_is_pythons():
    rng = np.random.default_rng(2)
    jobs, expected = [], []
    for make in dhlab.robots.catalogue().values():
        robot = make()
        for _ in range(4):
            q = random_q(robot, rng)
            jobs.append({"nodes": True, "steps": program_steps(robot), "q": q.tolist()})
            expected.append(nodes(robot, q))
    for got, want in zip(run_js(jobs), expected):
        np.testing.assert_allclose(np.reshape(got, want.shape), want, atol=1e-12)


def scene(panel):
    """The scene the kernel sends now (content, float32 numbers) and the moving artists."""
    from dhlab.views.live.scene import describe_scene

    live = panel.view.live
    content, numbers = describe_scene(live.figure, live.moving)
    return content, numbers


def pixels_of(content, item, numbers):
    """Canvas pixels of an item's data points with its space's matrix P."""
    key = {"line": "points", "polys": "faces", "glyphs": "anchors"}[item["kind"]]
    at, count = item[key][0], item[key][1] * (item[key][2] if key == "faces" else 1)
    points = np.asarray(numbers[at:at + 3 * count], dtype=float).reshape(-1, 3)
    P = np.reshape(content["spaces"][item["space"]]["P"], (4, 4))
    h = np.column_stack([points, np.ones(len(points))]) @ P.T
    return h[:, :2] / h[:, 3:]


def panels():
    for name, make in dhlab.robots.catalogue().items():
        robot = make()
        yield name, dhlab.teach(robot, backend="canvas")
        if getattr(robot, "is_planar", False):
            yield name + " (2D)", dhlab.teach(make(), backend="canvas", planar=True)


@needs_node
def test_the_browsers_picture_of_a_new_pose_is_the_kernels():
    rng = np.random.default_rng(3)
    jobs, checks = [], []
    for name, panel in panels():
        live = panel.view.live
        _ = live.widget   # building the widget must not raise
        rig_content, rig_numbers = live.rig.describe(live.moving)
        before, data = scene(panel)
        q1 = random_q(panel.robot, rng)
        panel.set_q(q1)
        after, truth = scene(panel)
        q1 = panel.q                          # as the sliders show it (rounded to their steps)
        jobs.append({"rig": rig_content, "rigData": rig_numbers.tolist(), "items": before["items"],
                     "data": [None if v != v else float(v) for v in data], "q": q1.tolist()})
        checks.append((name, rig_content, rig_numbers, before, after, truth))
        panel.close()
    for got, (name, rig, rig_numbers, before, after, truth) in zip(run_js(jobs), checks):
        got = np.array([np.nan if v is None else v for v in got], dtype=np.float32)
        checked = 0
        for item0, item1 in zip(before["items"], after["items"]):
            assert item0["artist"] == item1["artist"]
            for entry in rig["artists"].get(str(item0["artist"]), []):
                key = entry["key"]
                if item0[key][1:] != item1[key][1:]:
                    continue                  # a different number of points: the kernel's picture is used
                node = rig_numbers[entry["nodes"]:entry["nodes"] + entry["count"]]
                predicted = pixels_of(after, item0, got)[node >= 0]
                actual = pixels_of(after, item1, truth)[node >= 0]
                error = np.abs(predicted - actual).max() if len(actual) else 0.0
                assert error < 0.5, f"{name}: artist {item0['artist']} ({key}) off by {error:.3f} px"
                checked += int((node >= 0).sum())
        assert checked > 10, name


def test_the_teach_panels_robot_is_rigged_whole():
    """Every point the SSRMS and the PUMA panels move is carried by a node: nothing waits for the kernel."""
    for robot in (dhlab.robots.ssrms(), dhlab.robots.puma560()):
        panel = dhlab.teach(robot, backend="canvas")
        live = panel.view.live
        content, numbers = live.rig.describe(live.moving)
        rigged = {int(k) for k in content["artists"]}
        visible = {k for k, a in enumerate(live.moving) if a.get_visible() and a in panel.view.artists}
        assert visible <= rigged
        for entries in content["artists"].values():
            for entry in entries:
                node = numbers[entry["nodes"]:entry["nodes"] + entry["count"]]
                assert (node != -1).all()
        assert content["sliders"] == [s.model_id for s in panel.sliders]
        np.testing.assert_allclose(content["scales"], [np.pi / 180] * robot.n)


def test_probing_leaves_the_picture_as_it_was():
    panel = dhlab.teach(dhlab.robots.ssrms(), backend="canvas")
    panel.sliders[1].value = 35.0
    live = panel.view.live
    before = scene(panel)
    frames = panel.view.frames.copy()
    live.rig.describe(live.moving)
    after = scene(panel)
    assert json.dumps(before[0]) == json.dumps(after[0])
    np.testing.assert_array_equal(before[1], after[1])
    np.testing.assert_array_equal(frames, panel.view.frames)


def test_the_browser_gets_the_rig_and_every_scene_says_its_pose():
    panel = dhlab.teach(dhlab.robots.ssrms(), backend="canvas")
    widget = panel.view.live.widget
    sent = []
    widget.send = lambda content, buffers=None: sent.append(content)
    widget.receive({"kind": "ready"})
    assert [m["kind"] for m in sent] == ["rig", "scene"]
    panel.sliders[2].value = -20.0
    assert sent[-1]["kind"] == "scene"
    np.testing.assert_allclose(sent[-1]["q"], panel.q)
    # without the canvas backend there is no rig
    assert dhlab.teach(dhlab.robots.ssrms(), backend="image").view.live.rig is None


def test_a_pose_with_a_different_number_of_points_keeps_the_kernels_points():
    """rig.js skips an item whose point count is not the rig's (e.g. labels grouped otherwise)."""
    if NODE is None:
        pytest.skip("node is not installed")
    rig = {"steps": [], "artists": {"0": [{"key": "points", "count": 3, "nodes": 0, "local": 3}]}}
    rig_data = [0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3]
    items = [{"kind": "line", "space": 0, "artist": 0, "points": [0, 2]}]
    data = [9.0] * 6
    got, = run_js([{"rig": rig, "rigData": rig_data, "items": items, "data": data, "q": []}])
    assert got == data
    items[0]["points"] = [0, 3]
    got, = run_js([{"rig": rig, "rigData": rig_data, "items": items, "data": [9.0] * 9, "q": []}])
    assert got == [1, 1, 1, 2, 2, 2, 3, 3, 3]


@needs_node
def test_a_kernel_scene_is_repainted_ahead_only_if_the_rig_misses_a_point():
    """While the browser is ahead of the kernel, a kernel scene that the rig covers whole would
    repaint the same picture (not a new frame): rig.js's coversAll says when it does."""
    jobs = []
    for robot in (dhlab.robots.ssrms(), dhlab.robots.puma560()):
        panel = dhlab.teach(robot, backend="canvas")
        live = panel.view.live
        content, numbers = live.rig.describe(live.moving)
        items = scene(panel)[0]["items"]
        jobs.append({"covers": True, "rig": content, "rigData": numbers.tolist(), "items": items})
        panel.close()
    rig = {"artists": {"0": [{"key": "points", "count": 2, "nodes": 0, "local": 2}]}}
    line = {"kind": "line", "space": 0, "artist": 0, "points": [0, 2]}
    jobs += [{"covers": True, "rig": rig, "rigData": nodes_, "items": items}
             for nodes_, items in [([1, 2, 0, 0, 0, 0, 0, 0], [line]),            # whole
                                   ([1, -1, 0, 0, 0, 0, 0, 0], [line]),           # one point the kernel's
                                   ([1, -2, 0, 0, 0, 0, 0, 0], [line]),           # NaN padding: moves nothing
                                   ([1, 2, 0, 0, 0, 0, 0, 0], [dict(line, points=[0, 3])]),   # other count
                                   ([1, 2, 0, 0, 0, 0, 0, 0], [dict(line, artist=1)]),        # not rigged
                                   ([1, 2, 0, 0, 0, 0, 0, 0], [dict(line, space=-1)])]]      # figure text
    assert run_js(jobs) == [True, True, True, False, True, False, False, False]


_SPACED = """
import { SLIDER_MESSAGE_MS, spaceOut } from %s;
// the message throttle of @jupyter-widgets/base's WidgetModel (ipywidgets 8), the part spaceOut uses:
// one message in flight, later values merged into a buffer sent when the kernel says "idle"
class Model {
  constructor() { this._pending_msgs = 0; this._msg_buffer = null; this.sent = []; }
  sync(state) {
    if (this._pending_msgs >= 1) this._msg_buffer = { ...this._msg_buffer, ...state };
    else this.send_sync_message(state);
  }
  send_sync_message(state) {
    this.sent.push([performance.now(), state.value]);
    setTimeout(() => this._handle_status({ content: { execution_state: "idle" } }), 5);   // a quick kernel
    this._pending_msgs++;
    return "msg-id";
  }
  _handle_status(msg) {
    if (msg.content.execution_state !== "idle") return;
    this._pending_msgs--;
    if (this._msg_buffer !== null && this._pending_msgs < 1) {
      const buffered = this._msg_buffer;
      this._msg_buffer = null;
      this.send_sync_message(buffered);
    }
  }
}
const plain = new Model(), spaced = new Model();
spaceOut(spaced);
spaceOut(spaced);                                  // linked twice (two views): spaced once
let value = 0;
const timer = setInterval(() => { value += 1; plain.sync({ value }); spaced.sync({ value }); }, 4);
setTimeout(() => clearInterval(timer), 6 * SLIDER_MESSAGE_MS);
setTimeout(() => process.stdout.write(JSON.stringify({ plain: plain.sent, spaced: spaced.sent, last: value,
                                                       ms: SLIDER_MESSAGE_MS })), 10 * SLIDER_MESSAGE_MS);
"""


@needs_node
def test_a_dragged_slider_tells_the_kernel_at_most_every_250_ms_and_always_its_last_value():
    result = subprocess.run([NODE, "--input-type=module", "-e", _SPACED % json.dumps(RIG_JS.as_uri())],
                            capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr[-2000:]
    sent = json.loads(result.stdout)
    times, values = np.array(sent["spaced"]).T
    assert values[-1] == sent["last"] and sent["plain"][-1][1] == sent["last"]
    assert 100 <= sent["ms"] <= 300                         # readouts that still follow a drag
    assert np.diff(times).min() >= sent["ms"] - 5           # a timer may fire a little early
    assert len(sent["spaced"]) <= 8 < len(sent["plain"]) / 4
    assert (np.diff(values) > 0).all()                      # merged, never out of order


@pytest.fixture
def frozen_clock(monkeypatch):
    """The live figure's clock stands still: every step of a sweep counts as one drag however slow
    the machine (a loaded CI host once took longer than MOTION_S between two steps). A test moves
    it by hand (``live.last_refresh -= 1.0``) to make a pause."""
    from types import SimpleNamespace

    from dhlab.views.live import livefigure

    monkeypatch.setattr(livefigure, "time", SimpleNamespace(monotonic=lambda: 1000.0))


def sweep(panel, joint=1, steps=40):
    s = panel.sliders[joint]
    for v in np.r_[np.linspace(s.value, s.max, steps), np.linspace(s.max, s.min, steps)]:
        s.value = round(float(v) * 2) / 2


def test_a_drag_frames_a_leaving_robot_again_at_most_once_a_second(monkeypatch):
    """While a browser moves the picture, a robot leaving the picture is framed again (a full redraw,
    ~35-55 ms) at most every REDRAW_EVERY_S (1 s): it never stays out of sight longer, and the kernel keeps
    up with the drag; the rest (a robot grown small in its frame) waits, and at rest the view is framed."""
    from types import SimpleNamespace

    from dhlab.views import framing
    from dhlab.views.live import livefigure

    clock = [1000.0]
    monkeypatch.setattr(livefigure, "time", SimpleNamespace(monotonic=lambda: clock[0]))
    panel = dhlab.teach(dhlab.robots.ssrms(), backend="canvas")
    live = panel.view.live
    widget = live.widget
    widget.send = lambda content, buffers=None: None
    widget.receive({"kind": "ready"})
    redraws, out_of_frame = [], []
    widget.observe(lambda change: redraws.append(clock[0]), names="background")
    s = panel.sliders[1]
    for v in np.r_[np.linspace(s.value, s.max, 40), np.linspace(s.max, s.min, 40)]:
        clock[0] += 0.1                                          # a step every 0.1 s: one drag
        s.value = round(float(v) * 2) / 2
        out_of_frame.append(framing.leaves_view(panel.view.ax, panel.view.framed_points()))
    # one background per redraw, even when its labels stick out and matplotlib draws it twice
    assert len(set(redraws)) == len(redraws), redraws
    redraws = sorted(set(redraws))
    assert len(redraws) >= 2, "the view was never framed again during the sweep"
    assert min(np.diff(redraws)) >= livefigure.REDRAW_EVERY_S - 1e-9, redraws
    longest = max((len(run) for run in "".join("x" if o else "." for o in out_of_frame).split(".")), default=0)
    assert longest * 0.1 <= livefigure.REDRAW_EVERY_S + 1e-9, f"out of frame for {longest} steps in a row"
    clock[0] += 1.0
    widget.receive({"kind": "rest", "seq": live.seq})
    assert not live.waits_for_rest and not framing.needs_reframe(panel.view.ax, panel.view.framed_points())
    widget.receive({"kind": "rest", "seq": live.seq})
    assert widget.frame_seq == live.seq                     # then the exact frame


def test_a_drag_that_was_just_framed_waits_for_the_rest(frozen_clock):
    """With the clock standing still (every step within REDRAW_EVERY_S of the last redraw), a view
    that needs framing again leaves it to the rest; the rest frames it."""
    from dhlab.views import framing

    panel = dhlab.teach(dhlab.robots.ssrms(), backend="canvas")
    live = panel.view.live
    widget = live.widget
    widget.send = lambda content, buffers=None: None
    widget.receive({"kind": "ready"})
    redraws, redraw = [], live.redraw
    live.redraw = lambda: (redraws.append(1), redraw())
    sweep(panel)
    assert len(redraws) <= 1 and live.waits_for_rest              # at most one redraw while moving, one waiting
    widget.receive({"kind": "rest", "seq": live.seq})
    assert not live.waits_for_rest
    assert not framing.needs_reframe(panel.view.ax, panel.view.framed_points())


def test_without_a_browser_every_step_is_framed_at_once():
    """No browser said "ready" (a script, nbval): nothing waits; the same limits as the image path."""
    limits = []
    for backend in ("canvas", "image"):
        panel = dhlab.teach(dhlab.robots.ssrms(), backend=backend)
        _ = panel.view.live.widget   # building the widget must not raise
        sweep(panel)
        assert not panel.view.live.waits_for_rest
        limits.append(panel.view.limits)
    np.testing.assert_allclose(np.asarray(limits[0], float), np.asarray(limits[1], float))


def test_a_picture_asked_for_after_a_drag_is_framed(frozen_clock):
    """png() (what a static output or a screenshot takes) frames the robot first."""
    from dhlab.views import framing

    panel = dhlab.teach(dhlab.robots.ssrms(), backend="canvas")
    live = panel.view.live
    widget = live.widget
    widget.send = lambda content, buffers=None: None
    widget.receive({"kind": "ready"})
    sweep(panel)
    assert live.waits_for_rest
    live.png()
    assert not live.waits_for_rest
    assert not framing.needs_reframe(panel.view.ax, panel.view.framed_points())


def test_while_dragged_the_labels_keep_their_place_and_rest_lays_them_out(frozen_clock):
    """A step of a drag skips the labels' layout (half a step's cost): each label keeps its offset
    from its origin; the next step after a pause lays them out again."""
    panel = dhlab.teach(dhlab.robots.ssrms(), backend="canvas")
    live = panel.view.live
    widget = live.widget
    sent = []
    widget.send = lambda content, buffers=None: sent.append((content, buffers))
    widget.receive({"kind": "ready"})
    calls = []
    layout = type(panel.view.labels).layout
    panel.view.labels.layout = lambda: (calls.append(1), layout(panel.view.labels))
    live.last_refresh -= 1.0                      # the panel was made a while ago
    for value in (10.0, 12.0, 14.0):
        panel.sliders[1].value = value
    assert live.dragged and len(calls) == 1        # the first step laid them out, the next two did not
    glyphs = [[i for i in content["items"] if i["kind"] == "glyphs" and i.get("leaders")][0]
              for content, _ in sent if content.get("kind") == "scene"][-2:]
    assert [p["codes"] for p in glyphs[0]["pieces"]] == [p["codes"] for p in glyphs[1]["pieces"]]
    live.last_refresh -= 1.0                      # a pause
    panel.sliders[1].value = 16.0
    assert not live.dragged and len(calls) == 2


@needs_node
def test_the_spaces_panel_moves_its_mechanism_in_the_browser_too():
    robot = dhlab.robots.pr_mechanism()
    panel = dhlab.spaces(robot, backend="canvas",
                         ik=lambda x, y: dhlab.ik.pr_mechanism_ik(robot, x, y))
    live = panel.view.live
    _ = live.widget   # building the widget must not raise
    rig, rig_numbers = live.rig.describe(live.moving)
    assert rig["sliders"] == [s.model_id for s in panel.sliders]
    before, data = scene(panel)
    panel.sliders[0].value = 1.5
    panel.sliders[1].value = 40.0
    after, truth = scene(panel)
    got, = run_js([{"rig": rig, "rigData": rig_numbers.tolist(), "items": before["items"],
                    "data": [None if v != v else float(v) for v in data], "q": panel.q.tolist()}])
    got = np.array([np.nan if v is None else v for v in got], dtype=np.float32)
    mine = {str(live.moving.index(a)) for a in panel.view.artists}
    checked = 0
    for item0, item1 in zip(before["items"], after["items"]):
        for entry in rig["artists"].get(str(item0["artist"]), []):
            assert str(item0["artist"]) in mine            # only the mechanism is rigged, not the ghosts
            node = rig_numbers[entry["nodes"]:entry["nodes"] + entry["count"]]
            if item0[entry["key"]][1:] != item1[entry["key"]][1:]:
                continue
            error = np.abs(pixels_of(after, item0, got) - pixels_of(after, item1, truth))[node >= 0]
            assert error.max() < 0.5
            checked += int((node >= 0).sum())
    assert checked > 10
