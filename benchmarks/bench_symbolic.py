"""Symbolic forward kinematics, simplified: dhlab's compact product vs sympy.simplify.

    python benchmarks/bench_symbolic.py [--repeat 3]

For the PUMA 560 and the SSRMS, in one run:
  dhlab           robot.fk_sym(simplify=True)  (parallel joints merged, no trig simplification)
  sympy.simplify  element-wise sympy.simplify of the plain product of the DH matrices
Reports seconds (median of repeats for dhlab; one run of simplify, it is slow),
operation counts (sympy.count_ops over the 16 entries) and the speed-up; checks
that both results are the same matrix at random configurations.

Then a long general chain (issue 14: 12 joints, a = 0.1, α = 30°, no parallel axes):
  fk_sym()                 the plain product, entry by entry
  fk_sym(simplify=True)    the compact form (entries too large to expand stay as multiplied)
  Matrix.__mul__ (n = 6)   sympy's own matrix product, the way fk_sym() multiplied before
                           (198 s at 12 joints: timed at 6 joints only, with --plain-joints)
each checked against the numeric robot.fk at random configurations.
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
    parser.add_argument("--joints", type=int, default=12, help="joints of the long general chain")
    parser.add_argument("--plain-joints", type=int, default=6,
                        help="joints for sympy's Matrix.__mul__ comparison (it grows fast: 8 takes ~25 s)")
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
    results["long chain"] = long_chain(args.joints, args.plain_joints)
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(results, fh, indent=1)
    return results


def general_chain(n):
    return dhlab.DHRobot([dhlab.RevoluteDH(a=0.1, alpha=dhlab.deg(30))] * n, name=f"{n}-joint chain")


def numeric_error(robot, T, trials=3):
    f = sp.lambdify(robot.q_symbols, T, "numpy", cse=True)
    rng = np.random.default_rng(2)
    return max(np.abs(np.array(f(*q), dtype=float) - robot.fk(q)).max()
               for q in rng.uniform(-3, 3, (trials, robot.n)))


def long_chain(n, n_plain):
    """fk_sym of an n-joint general chain, plain and simplified, and sympy's Matrix product."""
    robot = general_chain(n)
    t0 = time.perf_counter()
    plain = robot.fk_sym()
    t_plain = time.perf_counter() - t0
    t0 = time.perf_counter()
    compact = robot.fk_sym(simplify=True, timeout=120)
    t_simplify = time.perf_counter() - t0
    err = max(numeric_error(robot, plain), numeric_error(robot, compact))
    assert err < 1e-9, f"the {n}-joint chain's symbolic pose differs from fk by {err}"
    small = general_chain(n_plain)
    mats = small.link_matrices_sym()
    t0 = time.perf_counter()
    product = mats[0]
    for A in mats[1:]:
        product = product * A
    t_sympy = time.perf_counter() - t0
    t0 = time.perf_counter()
    ours_small = small.fk_sym()
    t_ours_small = time.perf_counter() - t0
    assert ours_small == product
    print(f"\n{robot.name:<18}{'fk_sym()':<24}{t_plain:>10.3f} s   (error vs fk {err:.1e})")
    print(f"{'':<18}{'fk_sym(simplify=True)':<24}{t_simplify:>10.3f} s")
    print(f"{small.name:<18}{'Matrix.__mul__':<24}{t_sympy:>10.3f} s")
    print(f"{'':<18}{'fk_sym() (same matrix)':<24}{t_ours_small:>10.3f} s   ({t_sympy / t_ours_small:.0f}× faster)")
    return {"joints": n, "fk_sym_s": t_plain, "fk_sym_simplify_s": t_simplify, "max_error": err,
            "plain_joints": n_plain, "sympy_matmul_s": t_sympy, "fk_sym_small_s": t_ours_small}


if __name__ == "__main__":
    main()
