"""A sweep of random single slips on every family of robots: does each cost exactly one item?

    python benchmarks/bench_grade_slips.py [--per-family 360] [--pairs 60] [--seed 22] [--json out.json]

For each family (PUMA 560, IRB 140, KR 5, LR Mate, UR5, Cobra, Stanford), random personal
variants, each answered in a random valid DH assignment (z and x either way, origins slid
along parallel axes, sliding axes drawn on other lines), then ONE slip: a typical mistake in
one row T_i (the joint's sense, θ + 90°, θ + 180°, d or a off by 5 cm, −a, −α, α + 90°,
α in radians) or a wrong point of one link. Ground truth, independent of the grader: the
chain's motion (every axis on the robot's line, the drawn way, the end point in place) and
whether each link lands where the student's own T_1…T_k place it. A slip that changes what
the answer says must cost exactly one item; one that leaves a valid answer, none.

For every slip in an offset d (d + 5 cm) the benchmark also reads the charged item's feedback:
does it name the slipped d alone, among its equivalents along a run of parallel axes, or only
another d (misleading)?

``--pairs``: two independent slips, in two rows, each costing one item alone; how many are
charged as two items (the rest as one: the trade-off of reading runs of parallel axes as
free to slide, see the README).

The checks run in this process (no kernels): it measures the checks, not the grader.
"""
from __future__ import annotations

import argparse
import json
import re
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))


def _slips(robot, rows):
    from support.written_answers import row_mistakes
    return [(i, what, row) for i, what, row in row_mistakes(robot, rows) if row != rows[i]]


def _named_offsets(message: str) -> set:
    """The offsets d_k a message asks to check ('check d2, d3 or d4 (yours: …)' → {2, 3, 4})."""
    named = set()
    for advice in re.findall(r"check ([^(:;]*)", message):
        named |= {int(k) for k in re.findall(r"\bd(\d+)\b", advice)}
    return named | {int(k) for k in re.findall(r"— or d(\d+)", message)}     # 'check d4 … — or d3'


def _count_named(counts: dict, slipped: int, report) -> None:
    """A slip in d_slipped: does the feedback of the charged item name d_slipped (alone, among others)?"""
    named = set()
    for part in report.parts:
        for item in part.items:
            if not item.ok and part.key == "part3":
                named |= _named_offsets(getattr(item, "message", "") or "")
    counts["d slips"] += 1
    if named == {slipped}:
        counts["names it alone"] += 1
    elif slipped in named:
        counts["names it among others"] += 1
    else:
        counts["names another only"] += 1
        if len(counts["examples"]) < 5:
            counts["examples"].append(f"d{slipped} slipped, feedback names {sorted(named) or 'no offset'}")


def sweep(per_family: int, pairs: int, seed: int) -> dict:
    from dhlab.assignment import variants as V
    from dhlab.assignment.family import family_names
    from dhlab.assignment.model import random_frames_from_axes
    from support.written_answers import (
        links_not_in_their_frames,
        moves_like,
        namespace_from_rows,
        report,
        rows_in_degrees,
    )
    from support.written_answers import lost as lost_items
    rng = np.random.default_rng(seed)
    out = {}
    for key in family_names():
        counts = {"slips": 0, "valid": 0, "one item": 0, "two or more": 0, "none (missed)": 0,
                  "d slips": 0, "names it alone": 0, "names it among others": 0, "names another only": 0,
                  "pairs": 0, "pairs as two": 0, "pairs as one": 0, "examples": []}
        started = time.monotonic()
        for _ in range(per_family // 12 + 1):
            robot = V.robot_of_variant(V.variant(key, int(rng.integers(1 << 30))))
            Q = np.vstack([np.zeros(robot.n)] + [[rng.uniform(max(lo, -3.0), min(hi, 3.0)) for lo, hi in robot.qlim]
                                                 for _ in range(6)])
            frames = random_frames_from_axes(robot, rng, slide=0.3)
            rows = rows_in_degrees(robot, frames)
            slips = _slips(robot, rows)
            for idx in rng.choice(len(slips), size=min(12, len(slips)), replace=False):
                if counts["slips"] >= per_family:
                    break
                i, what, row = slips[idx]
                changed = rows[:i] + [row] + rows[i + 1:]
                ns = namespace_from_rows(robot, changed, frames)
                lost = lost_items(report(ns, robot))
                counts["slips"] += 1
                if moves_like(robot, changed, Q):
                    expected = len(links_not_in_their_frames(robot, ns, frames))
                    counts["valid"] += 1
                    ok = len(lost) == expected
                else:
                    expected = 1
                    ok = len(lost) == 1 and lost[0][0] == "part3"
                if what == "d + 5 cm" and lost:
                    _count_named(counts, i + 1, report(ns, robot))
                if ok:
                    counts["one item"] += expected      # a valid chain whose frames did not move costs nothing
                else:
                    counts["two or more" if len(lost) > expected else "none (missed)"] += 1
                if not ok and len(counts["examples"]) < 5:
                    counts["examples"].append(f"T{i + 1}: {what}: {lost}")
            for _ in range(pairs // 6 + 1):
                if counts["pairs"] >= pairs:
                    break
                a, b = sorted(rng.choice(len(slips), size=2, replace=False))
                (i, _, ra), (j, _, rb) = slips[a], slips[b]
                if i == j:
                    continue
                one_a, one_b = rows[:i] + [ra] + rows[i + 1:], rows[:j] + [rb] + rows[j + 1:]
                both = list(rows)
                both[i], both[j] = ra, rb
                if moves_like(robot, one_a, Q) or moves_like(robot, one_b, Q) or moves_like(robot, both, Q):
                    continue
                lost = [x for x in lost_items(report(namespace_from_rows(robot, both, frames), robot))
                        if x[0] == "part3"]
                counts["pairs"] += 1
                counts["pairs as two" if len(lost) >= 2 else "pairs as one"] += 1
        counts["seconds"] = round(time.monotonic() - started, 1)
        out[key] = counts
    return out


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--per-family", type=int, default=360)
    parser.add_argument("--pairs", type=int, default=60)
    parser.add_argument("--seed", type=int, default=22)
    parser.add_argument("--json", type=Path)
    args = parser.parse_args()
    result = sweep(args.per_family, args.pairs, args.seed)
    total = {k: sum(r[k] for r in result.values()) for k in ("slips", "valid", "one item", "two or more",
                                                             "none (missed)", "pairs", "pairs as two", "d slips",
                                                             "names another only")}
    for key, r in result.items():
        print(f"{key:12s} slips {r['slips']:4d}: one item {r['one item']:4d}, valid (0 or its link) {r['valid']:3d}, "
              f"two or more {r['two or more']:2d}, missed {r['none (missed)']:2d}; "
              f"pairs {r['pairs']:3d}: as two {r['pairs as two']:3d}  ({r['seconds']} s)")
        print(f"{'':12s} d slips {r['d slips']:3d}: feedback names the slipped d alone {r['names it alone']:3d}, "
              f"among its equivalents {r['names it among others']:3d}, only another {r['names another only']:3d}")
        for example in r["examples"]:
            print("    ", example)
    print(f"all: {total['slips']} slips, {total['two or more']} cost two or more, {total['none (missed)']} missed; "
          f"{total['pairs']} pairs of slips, {total['pairs as two']} charged as two; "
          f"{total['d slips']} slips in a d, {total['names another only']} whose feedback names only another d")
    if args.json:
        args.json.write_text(json.dumps(result, indent=1), encoding="utf-8")
    return 0 if total["two or more"] == 0 and total["none (missed)"] == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
