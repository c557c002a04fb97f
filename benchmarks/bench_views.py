"""How long one slider step of ``dhlab.teach(robot)`` takes, against the naive
clear-and-replot pattern drawing the same figure, measured side by side in one run,
for the SSRMS (7 joints) and the PUMA 560 (6 joints).

    python benchmarks/bench_views.py            # ~60 s on a 2-core machine
    python benchmarks/bench_views.py --steps 80 --save /tmp/bench   # more steps, keep the last frames
    python benchmarks/bench_views.py --moves drag   # slider drags (small steps) instead of jumps

The figure is the lecture-grade one: frame labels placed apart and
merged where frames share an origin, the joint axes as dashed lines, the
limits framed around the robot (re-framed when it needs it), title and axis
labels, at the teach panel's size. The naive pattern draws all of that again
on every step (its labels as ``ax.text``, its limits framed at every step, as
a hand-written ``interact`` function would). dhlab re-frames only when the
robot nears the border or gets small; those steps are full redraws and are
counted in its times (their share is printed).

Three comparisons per robot, each per slider update:

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

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

import dhlab
from dhlab.views import framing
from dhlab.views.labels import group_points, merged_name
from dhlab.views.mechanism import Mechanism
from dhlab.views.panels.teach import teach
from dhlab.views.triads import (
    AXIS_COLORS,
    letter_points,
    triad_segments,
)
from dhlab.views.viewbase import EE_COLOR, JOINT_AXIS_COLOR, LINK_COLOR, TRIAD_FRACTION, line_in_box, typical_size

FIGSIZE, DPI = (5.6, 5.6), 100       # the teach panel's default size


class NaiveFigure:
    """The same picture as dhlab's 3D view, drawn the usual way: clear the axes,
    plot everything again (the mechanism: links along their d and a segments,
    joints as solids, the gripper; three triad lines and their x/y/z letters, end
    effector, labels, limits, axis labels, title), then render the whole figure."""

    def __init__(self, robot, canvas="agg"):
        self.robot = robot
        self.figure = Figure(figsize=FIGSIZE, dpi=DPI)
        if canvas == "ipympl":
            from ipympl.backend_nbagg import Canvas, FigureManager
            FigureManager(Canvas(self.figure), 0).canvas.syncing_data_url = False
        else:
            FigureCanvasAgg(self.figure)
        self.ax = self.figure.add_axes([0.1, 0.06, 0.8, 0.84], projection="3d", proj_type="ortho")
        self.length = TRIAD_FRACTION * typical_size(robot)
        self.mechanism = Mechanism(robot, typical_size(robot))

    def plot(self, q):
        ax, F = self.ax, np.asarray(self.robot.frames(q), dtype=float)
        origins = F[:, :3, 3]
        shape = self.mechanism.shape(F, np.asarray(q, dtype=float))
        ax.cla()
        lo, hi = framing.frame_box(shape.points, pad=0.6 * self.length)
        ax.set(xlim=(lo[0], hi[0]), ylim=(lo[1], hi[1]), zlim=(lo[2], hi[2]), xlabel="$x_0$",
               ylabel="$y_0$", zlabel="$z_0$")
        framing.fit_zoom(ax)
        axes = [np.vstack([*line_in_box(f[:3, 3], f[:3, 2], lo, hi), np.full(3, np.nan)]) for f in F[:-1]]
        ax.plot(*np.vstack(axes).T, "--", color=JOINT_AXIS_COLOR, lw=1)
        ax.plot(*shape.path.T, "-", color=LINK_COLOR, lw=4)
        ax.add_collection3d(Poly3DCollection(shape.faces, facecolors=shape.colors, linewidths=0.5))
        ax.plot(*shape.gripper.T, "-", color=EE_COLOR, lw=3.5)
        for color, seg, tips, letter in zip(AXIS_COLORS, triad_segments(F, self.length),
                                            letter_points(F, self.length), "xyz"):
            ax.plot(*seg.T, "-", color=color, lw=2.5)
            for tip in tips:
                ax.text(*tip, letter, color=color, fontsize=10, ha="center", va="center")
        ax.plot(*origins[-1:].T, "*", color=EE_COLOR, mec="k", ms=15)
        names = [rf"$\{{S_{{{i}}}\}}$" for i in range(len(F))]
        for group in group_points(origins, 1e-9):
            ax.text(*origins[group[0]], merged_name([names[i] for i in group]), fontsize=10)
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


def compare(name, ours, naive, moves):
    """Alternate ``ours(step)`` and ``naive(step)``; each returns what it showed (bytes)."""
    n = len(moves)
    times = {"dhlab": [], "naive": []}
    changed = {"dhlab": 0, "naive": 0}
    last = {"dhlab": None, "naive": None}
    for step in moves:
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


def clamped(robot, step):
    """A jump of the slider (a click on its track) to an angle inside the joint's
    limits: angles outside them are folded back in, so that every move moves."""
    joint, degrees = step
    lo, hi = np.degrees(robot.links[joint].qlim)
    span = hi - lo
    folded = lo + (degrees - lo) % (2 * span)
    return joint, float(folded if folded <= hi else hi - (folded - hi))


def drags(robot, n, start=0, per_event=2.5):
    """(joint, degrees) for n slider events of drags: each joint in turn is dragged
    by 12 events of ``per_event`` degrees (what ``continuous_update`` sends while
    the mouse moves), turning back at its limits."""
    q = np.degrees(np.clip(np.zeros(robot.n), *robot.qlim.T))
    direction = np.ones(robot.n)
    moves = []
    for i in range(start, start + n):
        joint = (i // 12) % robot.n
        lo, hi = np.degrees(robot.links[joint].qlim)
        if not lo <= q[joint] + direction[joint] * per_event <= hi:
            direction[joint] *= -1
        q[joint] += direction[joint] * per_event
        moves.append((joint, float(q[joint])))
    return moves


def bench_robot(robot, args):
    """The three comparisons for one robot; returns {name: {"dhlab": [...], "naive": [...]}}."""
    n = robot.n
    print(f"\n=== {robot.name}: {n} joints, {n + 1} frames, {FIGSIZE[0]}x{FIGSIZE[1]} in at {DPI} dpi; "
          f"{args.steps} slider moves each, after {args.warmup} warm-up moves")
    q = np.radians(np.linspace(10, 70, n))
    fk_ms = statistics.median(timed(lambda: robot.frames(q))[0] for _ in range(200))
    print(f"forward kinematics (frames): median {fk_ms:.3f} ms")
    if args.moves == "drag":
        warm, moves = drags(robot, args.warmup), drags(robot, args.steps, start=args.warmup)
    else:
        moves = [clamped(robot, s) for s in steps(args.steps, n)]
        warm = [clamped(robot, s) for s in steps(args.warmup, n, warmup=True)]

    def slider_runner(panel):
        def run(step):
            joint, degrees = step
            panel.sliders[joint].value = degrees          # the observer updates and draws
            return panel
        return run

    def count_reframes(panel):
        full = []
        panel.figure.canvas.mpl_connect("draw_event", lambda event: full.append(1))
        return full

    results = {}
    # 1. inline backend: PNG per update
    panel = teach(robot, backend="image", joint_axes=True)
    image = panel.children[0]
    naive = NaiveFigure(robot)
    ours_run = slider_runner(panel)
    qn = np.zeros(n)

    def naive_png(step):
        qn[step[0]] = np.radians(step[1])
        return naive.png(qn)
    for s in warm:
        ours_run(s), naive_png(s)
    full = count_reframes(panel)
    results["inline"] = compare("1. inline backend (figure as PNG): slider.value -> picture ready",
                                lambda s: bytes(ours_run(s) and image.value), naive_png, moves)
    print(f"  dhlab re-framed (full redraw) on {len(full)} of {len(moves)} moves")

    # 2. ipympl canvas: blit + PNG diff, front end emulated as connected
    panel2 = teach(robot, backend="ipympl", joint_axes=True)
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
    qn2 = np.zeros(n)

    def naive_ipympl(step):
        qn2[step[0]] = np.radians(step[1])
        naive2.draw(qn2)
        return pixels_of(naive2.figure)
    for s in warm:
        run2(s), naive_ipympl(s)
    sent.update(dhlab=0, naive=0)
    results["ipympl"] = compare("2. ipympl (%matplotlib widget): slider.value -> PNG diff sent",
                                lambda s: pixels_of(run2(s).figure), naive_ipympl, moves)
    print(f"  frames sent to the browser: dhlab {sent['dhlab']}, naive {sent['naive']}")

    # 3. drawing only, Agg (a view that is not shown: no PNG)
    view = dhlab.view.robot_view(robot, backend="image", joint_axes=True)
    naive3 = NaiveFigure(robot)
    q3, qn3 = np.zeros(n), np.zeros(n)

    def ours_draw(step):
        q3[step[0]] = np.radians(step[1])
        view.update(q3)
        return pixels_of(view.figure)

    def naive_draw(step):
        qn3[step[0]] = np.radians(step[1])
        naive3.draw(qn3)
        return pixels_of(naive3.figure)
    for s in warm:
        ours_draw(s), naive_draw(s)
    results["draw"] = compare("3. drawing only (Agg): update(q) -> pixels in the buffer",
                              ours_draw, naive_draw, moves)

    if args.save:
        args.save.mkdir(parents=True, exist_ok=True)
        tag = robot.name.split()[0].lower()
        (args.save / f"dhlab_inline_{tag}.png").write_bytes(bytes(image.value))
        (args.save / f"naive_inline_{tag}.png").write_bytes(naive_png(moves[-1]))
        print(f"\nlast frames saved in {args.save}")
    return results


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--steps", type=int, default=40, help="slider moves per implementation and comparison")
    parser.add_argument("--warmup", type=int, default=5)
    parser.add_argument("--save", type=Path, help="folder to save the last frame of each implementation")
    parser.add_argument("--moves", choices=("jump", "drag"), default="jump",
                        help="jump: each move sets a slider to a far angle (a click on the track; "
                             "the robot re-frames often); drag: small steps of 2.5 degrees")
    args = parser.parse_args(argv)
    print(f"dhlab view benchmark; matplotlib {matplotlib.__version__}; moves: {args.moves}")
    worst = np.inf
    for robot in (dhlab.robots.ssrms(), dhlab.robots.puma560()):
        results = bench_robot(robot, args)
        worst = min(worst, *(statistics.median(r["naive"]) / statistics.median(r["dhlab"])
                             for r in results.values()))
    print(f"\nsmallest speed-up over the naive pattern: {worst:.1f}x (target: at least 5x)")
    return 0 if worst >= 5 else 1


if __name__ == "__main__":
    sys.exit(main())
