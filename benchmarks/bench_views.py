"""How long one slider step of ``dhlab.teach(ssrms())`` takes, against the naive
clear-and-replot pattern drawing the same figure, measured side by side in one run.

    python benchmarks/bench_views.py            # ~30 s on a 2-core machine
    python benchmarks/bench_views.py --steps 80 --save /tmp/bench   # more steps, keep the last frames

Three comparisons, each per slider update of the 7-joint SSRMS (8 frames), 6x6 in at 100 dpi:

* inline backend: dhlab sets ``slider.value`` on a teach panel whose figure is an
  ``ipywidgets.Image`` (blit + PNG); the naive pattern clears the axes, plots
  everything again and renders the PNG the inline backend would
  (``savefig(bbox_inches="tight")``, as ``interact`` + ``plt.show()`` does).
* ipympl: the same panel with ipympl's canvas (blit + the PNG diff sent to the
  browser); the naive pattern clears, re-plots and calls ``canvas.draw()``.
  No browser is attached: the front end is emulated as "connected" (no data-URL sync).
* drawing only (Agg): ``view.update(q)`` against clear + re-plot + ``canvas.draw()``.

Each update is checked to be really drawn: its pixels (or PNG) differ from the
previous update's. Implementations alternate step by step so that the machine's
load hits both alike. Times are wall-clock (``time.perf_counter``).
"""
from __future__ import annotations

import argparse
import io
import statistics
import sys
import time
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
from matplotlib.backends.backend_agg import FigureCanvasAgg  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
import dhlab  # noqa: E402
from dhlab.views.teach import teach  # noqa: E402
from dhlab.views.view import AXIS_COLORS, EE_COLOR, LINK_COLOR, triad_segments  # noqa: E402

FIGSIZE, DPI = (6, 6), 100


class NaiveFigure:
    """The same picture as dhlab's 3D view, drawn the usual way: clear the axes,
    plot everything again (links, three triad lines, end effector, labels,
    limits, axis labels, title), then render the whole figure."""

    def __init__(self, robot, canvas="agg"):
        self.robot = robot
        self.figure = Figure(figsize=FIGSIZE, dpi=DPI)
        if canvas == "ipympl":
            from ipympl.backend_nbagg import Canvas, FigureManager
            FigureManager(Canvas(self.figure), 0).canvas.syncing_data_url = False
        else:
            FigureCanvasAgg(self.figure)
        self.ax = self.figure.add_subplot(projection="3d")
        self.figure.subplots_adjust(left=0, right=0.92, bottom=0.04, top=0.95)
        self.box = dhlab.view.workspace_box(robot)
        self.length = 0.06 * float((self.box[1] - self.box[0]).max())

    def plot(self, q):
        ax, F = self.ax, self.robot.frames(q)
        origins = F[:, :3, 3]
        ax.cla()
        ax.plot(*origins.T, "-o", color=LINK_COLOR, lw=3, ms=4)
        for color, seg in zip(AXIS_COLORS, triad_segments(F, self.length)):
            ax.plot(*seg.T, "-", color=color, lw=2)
        ax.plot(*origins[-1:].T, "*", color=EE_COLOR, mec="k", ms=15)
        for i, p in enumerate(origins):
            ax.text(*p, rf"$\{{S_{{{i}}}\}}$", fontsize=9)
        (x0, y0, z0), (x1, y1, z1) = self.box
        ax.set(xlim=(x0, x1), ylim=(y0, y1), zlim=(z0, z1), xlabel="$x_0$", ylabel="$y_0$", zlabel="$z_0$")
        ax.set_box_aspect(self.box[1] - self.box[0])
        ax.set_title(self.robot.name)

    def draw(self, q):
        self.plot(q)
        self.figure.canvas.draw()

    def png(self, q):
        self.plot(q)
        with io.BytesIO() as out:
            self.figure.savefig(out, format="png", bbox_inches="tight")
            return out.getvalue()


def steps(n, joints=7, warmup=False):
    """(joint, degrees) for n slider moves: every move changes the pose (and the
    warm-up moves use other angles than the measured ones)."""
    shift = 0.5 if warmup else 0.0
    return [(i % joints, float((i * 37) % 500 - 250) + shift) for i in range(n)]


def timed(action):
    start = time.perf_counter()
    result = action()
    return (time.perf_counter() - start) * 1e3, result


def pixels_of(figure):
    return bytes(figure.canvas.buffer_rgba())


def compare(name, ours, naive, n):
    """Alternate ``ours(step)`` and ``naive(step)``; each returns what it showed (bytes)."""
    times = {"dhlab": [], "naive": []}
    changed = {"dhlab": 0, "naive": 0}
    last = {"dhlab": None, "naive": None}
    for step in steps(n):
        for who, run in (("dhlab", ours), ("naive", naive)):
            ms, shown = timed(lambda: run(step))
            times[who].append(ms)
            changed[who] += shown != last[who]
            last[who] = shown
    report(name, times, changed, n)
    return times


def report(name, times, changed, n):
    med = {k: statistics.median(v) for k, v in times.items()}
    print(f"\n{name}")
    for who in ("dhlab", "naive"):
        v = sorted(times[who])
        q1, q3 = np.percentile(v, [25, 75])
        print(f"  {who:5s}: median {med[who]:7.2f} ms   IQR {q1:7.2f}-{q3:7.2f} ms   "
              f"min {v[0]:7.2f}  max {v[-1]:7.2f}   updates really drawn: {changed[who]}/{n}")
    print(f"  ratio naive/dhlab (medians): {med['naive'] / med['dhlab']:.1f}x")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--steps", type=int, default=40, help="slider moves per implementation and comparison")
    parser.add_argument("--warmup", type=int, default=5)
    parser.add_argument("--save", type=Path, help="folder to save the last frame of each implementation")
    args = parser.parse_args(argv)
    robot = dhlab.robots.ssrms()
    print(f"dhlab view benchmark: {robot.name}, {robot.n} joints, {robot.n + 1} frames, "
          f"{FIGSIZE[0]}x{FIGSIZE[1]} in at {DPI} dpi; matplotlib {matplotlib.__version__}; "
          f"{args.steps} slider moves each, after {args.warmup} warm-up moves")

    # fk alone, for scale
    q = np.radians([10, 20, 30, 40, 50, 60, 70])
    fk_ms = statistics.median(timed(lambda: robot.frames(q))[0] for _ in range(200))
    print(f"forward kinematics (frames): median {fk_ms:.3f} ms")

    def slider_runner(panel):
        def run(step):
            joint, degrees = step
            panel.sliders[joint].value = degrees          # the observer updates and draws
            return panel
        return run

    results = {}
    # 1. inline backend: PNG per update
    panel = teach(robot, backend="image")
    image = panel.children[0]
    naive = NaiveFigure(robot)
    ours_run = slider_runner(panel)
    qn = np.zeros(7)

    def naive_png(step):
        qn[step[0]] = np.radians(step[1])
        return naive.png(qn)
    for s in steps(args.warmup, warmup=True):
        ours_run(s), naive_png(s)
    results["inline"] = compare("1. inline backend (figure as PNG): slider.value -> picture ready",
                                lambda s: bytes(ours_run(s) and image.value), naive_png, args.steps)

    # 2. ipympl canvas: blit + PNG diff, front end emulated as connected
    panel2 = teach(robot, backend="ipympl")
    panel2.figure.canvas.syncing_data_url = False
    naive2 = NaiveFigure(robot, canvas="ipympl")
    sent = {"dhlab": 0, "naive": 0}

    def count_sent(canvas, who):
        original = canvas.send_binary

        def send_binary(data):
            sent[who] += 1
            return original(data)
        canvas.send_binary = send_binary
    count_sent(panel2.figure.canvas, "dhlab")
    count_sent(naive2.figure.canvas, "naive")
    run2 = slider_runner(panel2)
    qn2 = np.zeros(7)

    def naive_ipympl(step):
        qn2[step[0]] = np.radians(step[1])
        naive2.draw(qn2)
        return pixels_of(naive2.figure)
    for s in steps(args.warmup, warmup=True):
        run2(s), naive_ipympl(s)
    sent.update(dhlab=0, naive=0)
    results["ipympl"] = compare("2. ipympl (%matplotlib widget): slider.value -> PNG diff sent",
                                lambda s: pixels_of(run2(s).figure), naive_ipympl, args.steps)
    print(f"  frames sent to the browser: dhlab {sent['dhlab']}, naive {sent['naive']}")

    # 3. drawing only, Agg (a view that is not shown: no PNG)
    view = dhlab.view.robot_view(robot, backend="image")
    naive3 = NaiveFigure(robot)
    q3, qn3 = np.zeros(7), np.zeros(7)

    def ours_draw(step):
        q3[step[0]] = np.radians(step[1])
        view.update(q3)
        return pixels_of(view.figure)

    def naive_draw(step):
        qn3[step[0]] = np.radians(step[1])
        naive3.draw(qn3)
        return pixels_of(naive3.figure)
    for s in steps(args.warmup, warmup=True):
        ours_draw(s), naive_draw(s)
    results["draw"] = compare("3. drawing only (Agg): update(q) -> pixels in the buffer",
                              ours_draw, naive_draw, args.steps)

    if args.save:
        args.save.mkdir(parents=True, exist_ok=True)
        (args.save / "dhlab_inline.png").write_bytes(bytes(image.value))
        (args.save / "naive_inline.png").write_bytes(naive_png((0, 0.0)))
        print(f"\nlast frames saved in {args.save}")
    worst = min(statistics.median(r["naive"]) / statistics.median(r["dhlab"]) for r in results.values())
    print(f"\nsmallest speed-up over the naive pattern: {worst:.1f}x (target: at least 5x)")
    return 0 if worst >= 5 else 1


if __name__ == "__main__":
    sys.exit(main())
