"""Symbolic forward kinematics, simplified: dhlab's compact product vs sympy.simplify.

    python benchmarks/bench_symbolic.py [--repeat 3]

For the PUMA 560 and the SSRMS, in one run:
  dhlab           robot.fk_sym(simplify=True)  (parallel joints merged, no trig simplification)
  sympy.simplify  element-wise sympy.simplify of the plain product of the DH matrices
Reports seconds (median of repeats for dhlab; one run of simplify, it is slow),
operation counts (sympy.count_ops over the 16 entries) and the speed-up; checks
that both results are the same matrix at random configurations.
"""
from __future__ import annotations

import argparse
import json
import statistics
import time

import numpy as np
import sympy as sp

import dhlab
from dhlab.symbolic import count_ops


def same_numbers(robot, A, B, trials=5):
    f = sp.lambdify(robot.q_symbols, A - B, "numpy")
    rng = np.random.default_rng(1)
    return max(np.abs(np.array(f(*rng.uniform(-3, 3, robot.n)), dtype=float)).max() for _ in range(trials))


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--json")
    args = parser.parse_args(argv)
    results = {}
    print(f"{'robot':<18}{'method':<16}{'seconds':>12}{'spread':>18}{'count_ops':>11}{'speed-up':>10}")
    for factory in (dhlab.robots.puma560, dhlab.robots.ssrms):
        robot = factory()
        times = []
        for _ in range(args.repeat):
            t0 = time.perf_counter()
            ours = robot.fk_sym(simplify=True)
            times.append(time.perf_counter() - t0)
        plain = robot.fk_sym(simplify=False)
        t0 = time.perf_counter()
        simplified = plain.applyfunc(sp.simplify)
        t_simplify = time.perf_counter() - t0
        diff = same_numbers(robot, ours, simplified)
        assert diff < 1e-9, f"{robot.name}: results differ by {diff}"
        t_ours = statistics.median(times)
        r = {"dhlab_s": t_ours, "dhlab_min_s": min(times), "dhlab_max_s": max(times),
             "dhlab_ops": count_ops(ours), "simplify_s": t_simplify, "simplify_ops": count_ops(simplified),
             "plain_ops": count_ops(plain), "speedup": t_simplify / t_ours}
        results[robot.name] = r
        print(f"{robot.name:<18}{'dhlab':<16}{t_ours:>12.3f}{f'{min(times):.3f}–{max(times):.3f}':>18}"
              f"{r['dhlab_ops']:>11}{r['speedup']:>9.0f}×")
        print(f"{'':<18}{'sympy.simplify':<16}{t_simplify:>12.3f}{'(1 run)':>18}{r['simplify_ops']:>11}")
        print(f"{'':<18}{'plain product':<16}{'':>12}{'':>18}{r['plain_ops']:>11}")
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(results, fh, indent=1)
    return results


if __name__ == "__main__":
    main()
