"""The kernel's cost of one slider step on the SSRMS teach panel, old backends vs the canvas one.

    .venv/bin/python benchmarks/bench_canvas.py [--steps 60] [--robot ssrms]

For each backend ("image": Agg + PNG into an Image widget; "ipympl": Agg + a diff PNG; "canvas":
the moving artists as numbers, see dhlab/views/canvas.py) it times ``view.update(q)`` (forward
kinematics, mechanism, artists, and what the backend sends) and a whole slider step (the panel's
readouts and matrix too), then the canvas' rest frame (Agg + PNG, once the figure holds still).
The browser's share (decode/paint) is measured by the browser tier (tests/browser).
"""
from __future__ import annotations

import argparse
import statistics
import time

import numpy as np

import dhlab
from dhlab.views.canvas import send_rest


def timed(action, repeats: int) -> list:
    out = []
    for k in range(repeats):
        start = time.perf_counter()
        action(k)
        out.append(1000 * (time.perf_counter() - start))
    return out


def bench(backend: str, robot_name: str, steps: int) -> dict:
    panel = dhlab.teach(getattr(dhlab.robots, robot_name)(), backend=backend)
    live = panel.view.live
    widget = live.widget                                   # as shown in a notebook
    if backend == "canvas":
        widget.send = lambda content, buffers=None: None   # no front end here: the bytes go nowhere
    q0 = panel.view.q.copy()
    slider = panel.sliders[1]
    poses = [q0 + np.deg2rad(0.5 * (k % 40)) * np.eye(len(q0))[1] for k in range(steps)]
    update = timed(lambda k: panel.view.update(poses[k]), steps)
    step = timed(lambda k: setattr(slider, "value", slider.value + (0.5 if k % 80 < 40 else -0.5)), steps)
    row = {"backend": backend, "update": statistics.median(update), "step": statistics.median(step)}
    if backend == "canvas":
        row["rest"] = statistics.median(timed(lambda k: (setattr(live, "_agg_stale", True),
                                                         send_rest(live, live._seq)), 15))
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
    rows = [bench(b, args.robot, args.steps) for b in backends]
    canvas = rows[-1]
    print(f"{args.robot}: kernel ms per update, median of {args.steps}")
    print(f"{'backend':8} {'view.update':>12} {'slider step':>12} {'update vs canvas':>17}")
    for row in rows:
        print(f"{row['backend']:8} {row['update']:12.1f} {row['step']:12.1f} {row['update'] / canvas['update']:16.1f}x")
    print(f"canvas rest frame (Agg + PNG, once the figure holds still): {canvas['rest']:.1f} ms")


if __name__ == "__main__":
    main()
