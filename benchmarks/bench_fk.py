"""Batched forward kinematics of the PUMA 560: configurations per second, side by side.

    python benchmarks/bench_fk.py [--n 100000] [--repeat 7]

In one run, on the same random configurations (within the joint limits):
  dhlab batch      robot.fk(Q) for all N at once
  no input check   the same compiled kinematics without the boundary check of Q
                   (dhlab.kinematics.run): what the check costs
  numpy matmul     the usual batched numpy: build (N,4,4) DH matrices, chain with @
  dhlab loop       robot.fk(q) in a Python loop, one configuration at a time
  RTB              roboticstoolbox-python's Puma560().fkine(Q), when it is installed
Every method's poses are checked against dhlab's before its time is reported.
Reports the median rate and the spread (min–max) over the repeats (run round robin), and ratios.
Then the boundary check alone (dhlab.validation.check_joint_values) on the same N
configurations, for the PUMA (6 revolute joints) and seed 002's 4-DOF robot (two
prismatic joints: the deg2rad() mark and size checks), as a share of fk's time.
"""
from __future__ import annotations

import argparse
import json
import statistics
import time

import numpy as np

import dhlab


def numpy_matmul_fk(robot, Q):
    """The straightforward batched numpy way: one (N,4,4) DH matrix per link, then @."""
    T = np.broadcast_to(robot.base, (len(Q), 4, 4)).copy()
    for j, link in enumerate(robot.links):
        th = Q[:, j] + float(link.offset)
        d, a, al = float(link.d), float(link.a), float(link.alpha)
        ct, st, ca, sa = np.cos(th), np.sin(th), np.cos(al), np.sin(al)
        A = np.zeros((len(Q), 4, 4))
        A[:, 0, 0], A[:, 0, 1], A[:, 0, 2], A[:, 0, 3] = ct, -st * ca, st * sa, a * ct
        A[:, 1, 0], A[:, 1, 1], A[:, 1, 2], A[:, 1, 3] = st, ct * ca, -ct * sa, a * st
        A[:, 2, 1], A[:, 2, 2], A[:, 2, 3], A[:, 3, 3] = sa, ca, d, 1.0
        T = T @ A
    return T @ robot.tool


def timed(fn, repeat):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return out, times


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=100_000)
    parser.add_argument("--repeat", type=int, default=7)
    parser.add_argument("--json", help="also write the results to this file")
    args = parser.parse_args(argv)

    robot = dhlab.robots.puma560()
    rng = np.random.default_rng(0)
    lo, hi = robot.qlim.T
    Q = lo + (hi - lo) * rng.random((args.n, robot.n))
    reference = robot.fk(Q)

    methods = {}
    methods["dhlab batch"] = (lambda: robot.fk(Q), args.n)
    methods["no input check"] = (lambda: dhlab.kinematics.run(robot.program, Q), args.n)
    methods["numpy matmul"] = (lambda: numpy_matmul_fk(robot, Q), args.n)
    n_loop = min(args.n, 5_000)
    methods["dhlab loop"] = (lambda: np.array([robot.fk(q) for q in Q[:n_loop]]), n_loop)
    try:
        import roboticstoolbox as rtb
        rtb_robot = rtb.models.DH.Puma560()
        rtb_robot.links[0].d = 0.0        # dhlab.robots.puma560() is mdl_puma560: frame 0 at the shoulder
        n_rtb = min(args.n, 20_000)
        methods["RTB fkine"] = (lambda: np.array([T.A for T in rtb_robot.fkine(Q[:n_rtb])]), n_rtb)
    except ImportError:
        print("roboticstoolbox-python is not installed: its row is skipped "
              "(pip install roboticstoolbox-python to include it)")

    # round robin: every repeat runs every method once, so a change of the machine's load
    # (other processes) falls on all of them alike
    times = {name: [] for name in methods}
    outputs = {}
    for _ in range(args.repeat):
        for name, (fn, _count) in methods.items():
            out, (t,) = timed(fn, 1)
            times[name].append(t)
            outputs[name] = out
    results = {}
    for name, (_fn, count) in methods.items():
        err = float(np.abs(outputs[name] - reference[:count]).max())
        assert err < 1e-9, f"{name} disagrees with dhlab by {err}"
        rates = sorted(count / t for t in times[name])
        results[name] = {"configs": count, "median_per_s": statistics.median(rates),
                         "min_per_s": rates[0], "max_per_s": rates[-1], "max_abs_diff": err}

    ours = results["dhlab batch"]["median_per_s"]
    print(f"PUMA 560 batched forward kinematics, N = {args.n:,} (median of repeats; spread min–max)")
    print(f"{'method':<16}{'configs':>9}{'configs/s (median)':>22}{'spread':>26}   dhlab batch vs it")
    for name, r in results.items():
        spread = f"{r['min_per_s']:,.0f}–{r['max_per_s']:,.0f}"
        ratio = ours / r["median_per_s"]
        text = "" if name == "dhlab batch" else f"{ratio:,.2f}× ({'faster' if ratio >= 1 else 'slower'})"
        r["dhlab_batch_ratio"] = ratio
        print(f"{name:<16}{r['configs']:>9,}{r['median_per_s']:>22,.0f}{spread:>26}   {text}")
    results["boundary check"] = boundary_check(Q, args.repeat, rng)
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(results, fh, indent=1)
    return results


def boundary_check(Q, repeat, rng):
    """check_joint_values alone on N configurations, as a share of robot.fk's time."""
    from dhlab.validation import check_joint_values
    out = {}
    print(f"\nthe boundary check alone (check_joint_values), N = {len(Q):,}")
    for robot in (dhlab.robots.puma560(), dhlab.robots.seed002_4dof()):
        lo, hi = robot.qlim.T
        q = lo + (hi - lo) * rng.random((len(Q), robot.n))
        t_check, t_fk = [], []
        for _ in range(repeat):                  # round robin, as above
            t_check += timed(lambda: check_joint_values(q, robot.links), 1)[1]
            t_fk += timed(lambda: robot.fk(q), 1)[1]
        check, fk = statistics.median(t_check), statistics.median(t_fk)
        kinds = "".join("R" if link.is_revolute else "P" for link in robot.links)
        out[robot.name] = {"check_s": check, "fk_s": fk, "share": check / fk}
        print(f"  {robot.name:<28} ({kinds}): check {check * 1e3:7.2f} ms of fk's {fk * 1e3:7.2f} ms "
              f"({100 * check / fk:.0f} %)")
    return out


if __name__ == "__main__":
    main()
