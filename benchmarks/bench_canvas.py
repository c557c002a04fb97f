"""The kernel's cost of one slider step on the SSRMS teach panel, old backends vs the canvas one.

    .venv/bin/python benchmarks/bench_canvas.py [--steps 60] [--robot ssrms]

For each backend ("image": Agg + PNG into an Image widget; "ipympl": Agg + a diff PNG; "canvas":
the moving artists as numbers, see dhlab/views/live/canvas.py) it times ``view.update(q)`` (forward
kinematics, mechanism, artists, and what the backend sends) and a whole slider step (the panel's
readouts and matrix too), then the canvas' rest frame (Agg + PNG, once the figure holds still).
"canvas, dragged" is the canvas backend shown in a browser while a slider is dragged (steps
closer than 0.3 s: frame labels keep their place, see dhlab/views/live/scene.py). Then a sweep of
joint 2 across its range and back (the robot leaves its frame: the PNG backends frame it again
at once, a full redraw; a dragged canvas at most once a second and when the drag stops, see
dhlab/views/live/livefigure.py, REDRAW_EVERY_S): total ms.
The browser's share (decode/paint) is measured by the browser tier (tests/browser).
"""
from __future__ import annotations

import argparse
import statistics
import time

import numpy as np

import dhlab
from dhlab.views.live.canvas import send_rest


def timed(action, repeats: int) -> list:
    out = []
    for k in range(repeats):
        start = time.perf_counter()
        action(k)
        out.append(1000 * (time.perf_counter() - start))
    return out


def shown(backend: str, robot_name: str, dragged: bool = False):
    panel = dhlab.teach(getattr(dhlab.robots, robot_name)(), backend=backend)
    widget = panel.view.live.widget                        # as shown in a notebook
    if backend == "canvas":
        widget.send = lambda content, buffers=None: None   # no front end here: the bytes go nowhere
        if dragged:                                        # a browser shows it (and has the rig)
            widget.receive({"kind": "ready"})
    return panel


def sweep_ms(backend: str, robot_name: str, dragged: bool = False) -> float:
    """Joint 2 from its value to its upper limit, down to its lower one and back: total ms."""
    panel = shown(backend, robot_name, dragged)
    slider = panel.sliders[1]
    values = np.r_[np.linspace(slider.value, slider.max, 40), np.linspace(slider.max, slider.min, 80),
                   np.linspace(slider.min, slider.value, 40)]
    start = time.perf_counter()
    for value in values:
        slider.value = round(float(value) * 2) / 2
    total = 1000 * (time.perf_counter() - start)
    panel.close()
    return total


def bench(backend: str, robot_name: str, steps: int, dragged: bool = False) -> dict:
    panel = shown(backend, robot_name, dragged)
    live = panel.view.live
    q0 = panel.view.q.copy()
    slider = panel.sliders[1]
    poses = [q0 + np.deg2rad(0.5 * (k % 40)) * np.eye(len(q0))[1] for k in range(steps)]
    update = timed(lambda k: panel.view.update(poses[k]), steps)
    step = timed(lambda k: setattr(slider, "value", slider.value + (0.5 if k % 80 < 40 else -0.5)), steps)
    row = {"backend": backend + (", dragged" if dragged else ""), "update": statistics.median(update),
           "step": statistics.median(step), "sweep": sweep_ms(backend, robot_name, dragged)}
    if backend == "canvas":
        row["rest"] = statistics.median(timed(lambda k: (setattr(live, "_agg_stale", True),
                                                         send_rest(live, live.seq)), 15))
    panel.close()
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=60)
    parser.add_argument("--robot", default="ssrms")
    args = parser.parse_args()
    backends = ["image", "canvas"]
    try:
        import ipympl  # noqa: F401
        backends.insert(1, "ipympl")
    except ImportError:
        pass
    rows = [bench(b, args.robot, args.steps) for b in backends] + [bench("canvas", args.robot, args.steps, True)]
    canvas = rows[-2]
    print(f"{args.robot}: kernel ms per update, median of {args.steps}; a 160-step sweep of joint 2, total ms")
    print(f"{'backend':16} {'view.update':>12} {'slider step':>12} {'step vs image':>14} {'sweep':>8}")
    for row in rows:
        print(f"{row['backend']:16} {row['update']:12.1f} {row['step']:12.1f} "
              f"{rows[0]['step'] / row['step']:13.1f}x {row['sweep']:8.0f}")
    print(f"canvas rest frame (Agg + PNG, once the figure holds still): {canvas['rest']:.1f} ms")


if __name__ == "__main__":
    main()
