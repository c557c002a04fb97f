"""Symbolic forward kinematics, simplified: dhlab's compact product vs sympy.simplify.

    python benchmarks/bench_symbolic.py [--repeat 3]

For the PUMA 560 and the SSRMS, in one run:
  dhlab           robot.fk_sym(simplify=True)  (parallel joints merged, no trig simplification)
  sympy.simplify  element-wise sympy.simplify of the plain product of the DH matrices
Reports seconds (median of repeats for dhlab; one run of simplify, it is slow),
operation counts (sympy.count_ops over the 16 entries) and the speed-up; checks
that both results are the same matrix at random configurations.

Then a long general chain (12 joints, a = 0.1, α = 30°, no parallel axes), each
result checked against the numeric robot.fk at random configurations:
  fk_sym()                  the plain product, entry by entry
  Matrix.__mul__            the same product with sympy's matrix product (how fk_sym() multiplied before)
  fk_sym(simplify=True)     the compact form (entries too large to expand stay as multiplied)
  sympy.simplify            of one entry of the plain product, in a child process stopped after
                            --budget seconds (it does not finish: the ratio is then a lower bound)
and the two ways a simplification that takes too long stops:
  timeout                   fk_sym(simplify=True, timeout=--bound) on a --bound-joints chain:
                            when the DHLabError comes, and how far past the bound
  stop button               a KeyboardInterrupt (what Jupyter's stop button sends) 0.5 s into
                            fk_sym(simplify=True, timeout=None): how long until it stops
"""
from __future__ import annotations

import argparse
import json
import multiprocessing
import signal
import statistics
import time

import numpy as np
import sympy as sp

import dhlab
from dhlab.symbolic import count_ops, exact


def same_numbers(robot, A, B, trials=5):
    f = sp.lambdify(robot.q_symbols, A - B, "numpy")
    rng = np.random.default_rng(1)
    return max(np.abs(np.array(f(*rng.uniform(-3, 3, robot.n)), dtype=float)).max() for _ in range(trials))


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--json")
    parser.add_argument("--joints", type=int, default=12, help="joints of the long general chain")
    parser.add_argument("--budget", type=float, default=30.0,
                        help="seconds given to sympy.simplify of one entry of the long chain")
    parser.add_argument("--bound-joints", type=int, default=50,
                        help="joints of the chain whose simplification is stopped by its timeout")
    parser.add_argument("--bound", type=float, default=1.0, help="the timeout (seconds) of that simplification")
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
    results["long chain"] = long_chain(args.joints, args.budget, args.repeat)
    results["bounded simplify"] = bounded(args.bound_joints, args.bound)
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(results, fh, indent=1)
    return results


def general_chain(n):
    return dhlab.DHRobot([dhlab.RevoluteDH(a=0.1, alpha=dhlab.deg2rad(30))] * n, name=f"{n}-joint chain")


def numeric_error(robot, T, trials=3):
    f = sp.lambdify(robot.q_symbols, T, "numpy", cse=True)
    rng = np.random.default_rng(2)
    return max(np.abs(np.array(f(*q), dtype=float) - robot.fk(q)).max()
               for q in rng.uniform(-3, 3, (trials, robot.n)))


def median_time(fn, repeat):
    """fn()'s result and its median time over ``repeat`` runs."""
    times = []
    for _ in range(max(1, repeat)):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return out, statistics.median(times)


def plain_sympy_product(robot):
    """base · A1 ··· An · tool with sympy's Matrix.__mul__ (how fk_sym() multiplied before)."""
    T = exact(sp.Matrix(robot.base))
    for A in robot.link_matrices_sym():
        T = T * A
    return T * exact(sp.Matrix(robot.tool))


def _simplify_entry(n, queue):
    T = general_chain(n).fk_sym()
    t0 = time.perf_counter()
    sp.simplify(T[0, 3])
    queue.put(time.perf_counter() - t0)


def simplify_one_entry(n, budget):
    """Seconds sympy.simplify takes on entry (0, 3) of the n-joint chain's plain product, or None
    when it has not finished after ``budget`` seconds (it runs in a child process, stopped then)."""
    ctx = multiprocessing.get_context("fork" if "fork" in multiprocessing.get_all_start_methods() else "spawn")
    queue = ctx.Queue()
    child = ctx.Process(target=_simplify_entry, args=(n, queue), daemon=True)
    child.start()
    child.join(budget + 5)          # + the child's own fk_sym()
    if child.is_alive():
        child.terminate()
        child.join()
        return None
    return queue.get() if not queue.empty() else None


def long_chain(n, budget, repeat=3):
    """fk_sym of an n-joint general chain, plain and simplified, each beside the slow way."""
    robot = general_chain(n)
    plain, t_plain = median_time(robot.fk_sym, repeat)
    compact, t_simplify = median_time(lambda: robot.fk_sym(simplify=True, timeout=120), repeat)
    t0 = time.perf_counter()
    product = plain_sympy_product(robot)
    t_sympy = time.perf_counter() - t0
    err = max(numeric_error(robot, plain), numeric_error(robot, product), numeric_error(robot, compact))
    assert err < 1e-9, f"the {n}-joint chain's symbolic pose differs from fk by {err}"
    t_slow = simplify_one_entry(n, budget)
    slow = f"{t_slow:10.3f} s" if t_slow is not None else f"{'> ' + format(budget, 'g'):>10} s"
    ratio = (f"{t_slow / t_simplify:,.0f}× faster" if t_slow is not None
             else f"> {budget / t_simplify:,.0f}× faster (sympy.simplify did not finish)")
    print(f"\n{robot.name:<18}{'method':<34}{'seconds':>12}   dhlab is")
    print(f"{'':<18}{'fk_sym()':<34}{t_plain:>10.3f} s   {t_sympy / t_plain:.1f}× faster"
          f"   (error vs fk {err:.1e})")
    print(f"{'':<18}{'Matrix.__mul__ product':<34}{t_sympy:>10.3f} s")
    print(f"{'':<18}{'fk_sym(simplify=True)':<34}{t_simplify:>10.3f} s   {ratio}")
    print(f"{'':<18}{'sympy.simplify of entry (0, 3)':<34}{slow}")
    return {"joints": n, "fk_sym_s": t_plain, "sympy_matmul_s": t_sympy, "fk_sym_simplify_s": t_simplify,
            "sympy_simplify_one_entry_s": t_slow, "simplify_budget_s": budget, "max_error": err,
            "plain_speedup": t_sympy / t_plain,
            "simplify_speedup_at_least": (t_slow if t_slow is not None else budget) / t_simplify}


def bounded(n, bound):
    """When fk_sym(simplify=True) of an n-joint chain stops: at its timeout, and at a KeyboardInterrupt."""
    robot = general_chain(n)
    t0 = time.perf_counter()
    try:
        robot.fk_sym(simplify=True, timeout=bound)
        took, how = time.perf_counter() - t0, "returned"
    except dhlab.DHLabError:
        took, how = time.perf_counter() - t0, "stopped (DHLabError)"
    late = took - bound
    result = {"joints": n, "timeout_s": bound, "seconds": took, "outcome": how, "past_the_bound_s": late}
    verdict = "within the bound" if late <= 0.5 + 0.5 * bound else "the bound is NOT kept"
    print(f"\n{robot.name:<18}{f'fk_sym(simplify=True, timeout={bound:g})':<34}{took:>10.3f} s   "
          f"{how}, {late:+.3f} s past the bound: {verdict}")
    if hasattr(signal, "setitimer"):
        def interrupt(*_):
            raise KeyboardInterrupt
        previous = signal.signal(signal.SIGALRM, interrupt)
        signal.setitimer(signal.ITIMER_REAL, 0.5)
        t0 = time.perf_counter()
        try:
            robot.fk_sym(simplify=True, timeout=None)
            latency = None
        except KeyboardInterrupt:
            latency = time.perf_counter() - t0 - 0.5
        finally:
            signal.setitimer(signal.ITIMER_REAL, 0)
            signal.signal(signal.SIGALRM, previous)
        result["interrupt_latency_s"] = latency
        print(f"{'':<18}{'KeyboardInterrupt at 0.5 s':<34}", end="")
        print(f"{latency:>10.3f} s   until it stopped" if latency is not None else "finished before the interrupt")
    return result


if __name__ == "__main__":
    main()
