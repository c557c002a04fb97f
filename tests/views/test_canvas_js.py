"""The browser layer's maths (dhlab/views/live/canvas.js) against matplotlib's, run in node.

For every catalogue robot, in its 3D view and (if planar) its 2D view, at random poses: the pixel
the browser computes for every moving point (links, mechanism faces, triads, letters, labels'
anchors) must be within 0.5 px of the pixel matplotlib draws it at; the mechanism's faces must be
painted in mplot3d's depth order; the view matrix the browser builds while turning the view must be
matplotlib's ``get_proj`` after ``view_init``.
"""
from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest
from mpl_toolkits.mplot3d import proj3d

import dhlab
from dhlab.views.live.scene import axes_camera, describe_scene, faces3d
from dhlab.views.view import robot_view

NODE = shutil.which("node")
pytestmark = pytest.mark.skipif(NODE is None, reason="node (JavaScript) is not installed: the browser "
                                "layer's maths cannot be checked here")
MODULE = Path(dhlab.__file__).parent / "views" / "live" / "canvas.js"

# reads {"calls": [[name, args...], ...]} on stdin, prints the results as JSON
_RUNNER = """
import * as m from %s;
let text = "";
process.stdin.on("data", (d) => { text += d; });
process.stdin.on("end", () => {
  const { calls } = JSON.parse(text);
  const out = calls.map(([name, ...args]) => {
    if (name === "project") {
      const [P, data, at, n] = args;
      return Array.from(m.project(P, Float32Array.from(data, (v) => (v === null ? NaN : v)), at, n));
    }
    if (name === "depthOrder") {
      const [xy, f, k, sort] = args;
      return m.depthOrder(xy.map((v) => (v === null ? NaN : v)), f, k, sort);
    }
    return m[name](...args);
  });
  process.stdout.write(JSON.stringify(out, (k, v) => (Number.isNaN(v) ? null : v)));
});
"""


def run_js(calls: list) -> list:
    script = _RUNNER % json.dumps(MODULE.as_uri())
    text = json.dumps({"calls": _no_nan(calls)}, allow_nan=False)     # JSON has no NaN: null
    result = subprocess.run([NODE, "--input-type=module", "-e", script], input=text,
                            capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr[-2000:]
    return json.loads(result.stdout)


def _no_nan(value):
    if isinstance(value, float):
        return None if value != value else value
    if isinstance(value, (list, tuple)):
        return [_no_nan(v) for v in value]
    if isinstance(value, dict):
        return {k: _no_nan(v) for k, v in value.items()}
    return value


def mpl_pixels(ax, points) -> np.ndarray:
    """Where matplotlib draws data ``points`` (n, 3) of ``ax``: canvas pixels, y down."""
    points = np.asarray(points, dtype=float)
    if getattr(ax, "name", "") == "3d":
        x, y, _ = proj3d.proj_transform(*points.T, ax.M)
        xy = ax.transData.transform(np.column_stack([x, y]))
    else:
        xy = ax.transData.transform(points[:, :2])
    return np.column_stack([xy[:, 0], ax.figure.bbox.height - xy[:, 1]])


def views():
    rng = np.random.default_rng(23)
    for name, make in dhlab.robots.catalogue().items():
        robot = make()
        planar_options = (False, True) if getattr(robot, "is_planar", False) else (False,)
        for planar in planar_options:
            view = robot_view(robot, planar=planar, backend="image", joint_axes=not planar)
            qlo, qhi = np.array([link.qlim for link in robot.links], dtype=float).T
            yield name, planar, view, [qlo + (qhi - qlo) * rng.random(robot.n) for _ in range(3)]


def test_every_moving_point_lands_on_matplotlibs_pixel():
    calls, expected, where = [], [], []
    for name, planar, view, poses in views():
        for q in poses:
            view.update(q)                       # a full draw when reframed, else a blit
            view.live.png()                      # makes sure matplotlib has drawn this pose
            content, numbers = describe_scene(view.figure, view.live.moving)
            ax = view.ax
            P = content["spaces"][0]["P"]
            for item in content["items"]:
                at, n = item["points"] if item["kind"] == "line" else (
                    (item["faces"][0], item["faces"][1] * item["faces"][2]) if item["kind"] == "polys"
                    else item["anchors"])
                if n == 0:
                    continue
                points = numbers[at:at + 3 * n].reshape(n, 3).astype(float)
                calls.append(["project", P, numbers[at:at + 3 * n].tolist(), 0, n])
                expected.append(mpl_pixels(ax, points))
                where.append(f"{name} {'2D' if planar else '3D'} {item['kind']}")
    results = run_js(calls)
    assert len(results) == len(expected) > 50
    worst = 0.0
    for got, want, label in zip(results, expected, where):
        got = np.array(got, dtype=float).reshape(-1, 3)[:, :2]
        finite = np.isfinite(want).all(axis=1)
        assert np.array_equal(np.isfinite(got).all(axis=1), finite), label
        error = float(np.abs(got[finite] - want[finite]).max()) if finite.any() else 0.0
        worst = max(worst, error)
        assert error < 0.5, f"{label}: {error:.3f} px"
    print(f"worst error {worst:.2e} px over {len(results)} artists")


def test_faces_are_painted_in_mplot3ds_depth_order():
    view = robot_view(dhlab.robots.ssrms(), backend="image")
    rng = np.random.default_rng(5)
    solids = view.joint_solids
    calls, keys = [], []
    for _ in range(4):
        qlo, qhi = np.array([link.qlim for link in view.robot.links], dtype=float).T
        view.update(qlo + (qhi - qlo) * rng.random(view.robot.n))
        view.live.png()
        content, numbers = describe_scene(view.figure, view.live.moving)
        item = next(i for i in content["items"] if i["kind"] == "polys")
        at, f, k = item["faces"]
        xy = run_js([["project", content["spaces"][0]["P"], numbers[at:at + 3 * f * k].tolist(), 0, f * k]])[0]
        calls.append(["depthOrder", xy, f, k, item["sort"]])
        _, _, z = proj3d.proj_transform(*faces3d(solids).reshape(-1, 3).T, view.ax.M)
        keys.append(z.reshape(f, k).mean(axis=1))
    for order, key in zip(run_js(calls), keys):
        want = np.argsort(key)[::-1]
        assert sorted(order) == list(range(len(key)))
        np.testing.assert_allclose(key[order], key[want], atol=1e-9)   # the same sequence (ties aside)


@pytest.mark.parametrize("elev, azim, roll, focal", [
    (30.0, -60.0, 0.0, None), (24.0, 145.0, 0.0, None), (-40.0, 10.0, 0.0, None), (95.0, 30.0, 0.0, None),
    (120.0, -170.0, 0.0, None), (20.0, 33.0, 25.0, None), (35.0, -80.0, 0.0, 1.0), (90.0, -90.0, 0.0, None)])
def test_turning_the_view_builds_matplotlibs_projection(elev, azim, roll, focal):
    view = robot_view(dhlab.robots.puma560(), backend="image")
    ax = view.ax
    if focal is not None:
        ax.set_proj_type("persp", focal_length=focal)
    view.live.png()
    camera = axes_camera(ax)                              # what the browser knows before turning
    ax.view_init(elev=elev, azim=azim, roll=roll)
    want = ax.get_proj()
    camera["roll"] = roll
    M, P = run_js([["viewMatrix", camera, elev, azim, roll],
                   ["compose", camera["A"], want.tolist()]])
    np.testing.assert_allclose(np.array(M), want, rtol=1e-9, atol=1e-12)
    ax.M = want
    np.testing.assert_allclose(np.array(P).reshape(4, 4), np.array(axes_camera(ax)["P"]).reshape(4, 4),
                               rtol=1e-9, atol=1e-9)


def test_a_drag_turns_the_view_as_mplot3ds_azel_style():
    camera = {"elev": 30.0, "azim": -60.0, "roll": 0.0}
    # half the axes' width to the right: the scene turns 90° (azim decreases, as mplot3d does)
    (elev, azim), = run_js([["dragView", camera, 200.0, 0.0, 400.0, 400.0]])
    assert (elev, azim) == pytest.approx((30.0, -150.0))
    (elev, azim), = run_js([["dragView", camera, 0.0, -100.0, 400.0, 400.0]])   # up on the screen
    assert (elev, azim) == pytest.approx((30.0 - 45.0, -60.0))


_BOUNDS = """
import * as m from %s;
import * as d from %s;
let text = "";
process.stdin.on("data", (c) => { text += c; });
process.stdin.on("end", () => {
  const out = JSON.parse(text).map(({ scene, data }) => {
    const numbers = Float32Array.from(data, (v) => (v === null ? NaN : v));
    const projected = m.projectItems(scene, numbers);
    return d.paintedBounds(scene.items, projected, numbers, 1e6, 1e6);
  });
  process.stdout.write(JSON.stringify(out));
});
"""


def test_a_repaint_clipped_to_the_items_bounds_misses_no_changed_pixel():
    """dirty.js: while a slider moves, the browser repaints only the rectangle of the moving items
    (before and after the step). Every pixel matplotlib changes by drawing the moving artists over
    the background must lie in that rectangle: lines, markers, faces, letters, halos, leaders."""
    cases, changed, where = [], [], []
    for name, planar, view, poses in views():
        for q in poses:
            view.update(q)
            live = view.live
            live.png()
            canvas = view.figure.canvas
            canvas.draw()                        # the background: the moving artists are left out
            background = np.asarray(canvas.buffer_rgba()).copy()
            for artist in live.moving:
                view.figure.draw_artist(artist)
            picture = np.asarray(canvas.buffer_rgba())
            rows, cols = np.nonzero((picture != background).any(axis=2))
            if not len(rows):
                continue
            content, numbers = describe_scene(view.figure, live.moving)
            cases.append({"scene": content, "data": _no_nan(numbers.astype(float).tolist())})
            changed.append((cols.min(), rows.min(), cols.max() + 1, rows.max() + 1))
            where.append(f"{name} {'2D' if planar else '3D'} q={np.round(q, 2).tolist()}")
    script = _BOUNDS % (json.dumps(MODULE.as_uri()), json.dumps((MODULE.parent / "dirty.js").as_uri()))
    result = subprocess.run([NODE, "--input-type=module", "-e", script], input=json.dumps(cases),
                            capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr[-2000:]
    boxes = json.loads(result.stdout)
    assert len(boxes) == len(changed) > 20
    areas = []
    for box, pixels, label in zip(boxes, changed, where):
        assert box is not None, label
        x0, y0, x1, y1 = box
        assert x0 <= pixels[0] and y0 <= pixels[1] and pixels[2] <= x1 and pixels[3] <= y1, \
            f"{label}: changed pixels {pixels} outside the repainted {box}"
        areas.append((x1 - x0) * (y1 - y0) / ((pixels[2] - pixels[0]) * (pixels[3] - pixels[1])))
    assert np.median(areas) < 2.0              # and not the whole canvas either: a tight rectangle
