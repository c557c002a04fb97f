"""Grading a class: 30 submitted PUMA notebooks with ``dhlab-grade -j 2``, time per submission.

    python benchmarks/bench_grade.py [--n 30] [--jobs 2] [--serial 10] [--json out.json]

The class is made of copies of the course's own notebooks, as students hand them in:
the solutions, the test submissions with a valid alternative DH assignment and with a
mistake in each part, and the untouched student version (one of each kind in turn).
No hostile notebooks: they wait for time limits, which measures the limits, not the grader.
The grader runs as it would for a teacher: as root it isolates each kernel (its own user,
mount namespace, processes killed afterwards), and the run says which mode it measured.

In one run, side by side:
  -j 2     all N submissions, two at a time (the target: under 2 minutes for 30)
  -j 1     the first ``--serial`` of them, one at a time (for the ratio)
Each run checks that every submission got the score its kind should get before its time
is reported.
"""
from __future__ import annotations

import argparse
import csv
import json
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
KINDS = {                       # notebook -> the score it must get
    ROOT / "dhlab" / "grading" / "data" / "08_puma_assignment.ipynb": 10.0,
    ROOT / "tests" / "data" / "submissions" / "valid_alternative.ipynb": 10.0,
    ROOT / "tests" / "data" / "submissions" / "mistake_part1.ipynb": 9.5,
    ROOT / "tests" / "data" / "submissions" / "mistake_part2.ipynb": 9.57,
    ROOT / "tests" / "data" / "submissions" / "mistake_part3.ipynb": 8.57,
    ROOT / "tests" / "data" / "submissions" / "slip_alpha1.ipynb": 9.29,
    ROOT / "notebooks" / "08_puma_assignment.ipynb": 0.0,
}


def make_class(folder: Path, n: int) -> dict:
    """n submissions, student_01 … student_n, cycling through the kinds; their expected scores."""
    expected = {}
    kinds = list(KINDS.items())
    for i in range(n):
        path, score = kinds[i % len(kinds)]
        name = f"student_{i + 1:02d}"
        shutil.copy(path, folder / f"{name}.ipynb")
        expected[name] = score
    return expected


def grade(folder: Path, jobs: int, expected: dict) -> float:
    """Seconds for one `dhlab-grade` run (a fresh process, as a teacher runs it)."""
    out = folder.parent / f"gradebook-j{jobs}.csv"
    started = time.perf_counter()
    proc = subprocess.run([sys.executable, "-m", "dhlab.grading.cli", "puma", str(folder), "-o", str(out),
                           "-j", str(jobs), "-q"], capture_output=True, text=True)
    seconds = time.perf_counter() - started
    if proc.returncode != 0:
        raise SystemExit(f"dhlab-grade failed:\n{proc.stderr[-2000:]}")
    if "not isolated" in proc.stderr:
        print("(measured without isolation: " + proc.stderr.split("not isolated:", 1)[1].splitlines()[0].strip() + ")")
    with open(out, newline="", encoding="utf-8") as f:
        scores = {row["submission"]: float(row["score"]) for row in csv.DictReader(f)}
    wrong = {k: (scores.get(k), v) for k, v in expected.items() if abs(scores.get(k, -1) - v) > 0.01}
    if wrong:
        raise SystemExit(f"wrong scores (got, expected): {wrong}")
    return seconds


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=30, help="submissions (default 30)")
    parser.add_argument("--jobs", type=int, default=2, help="parallel jobs of the main run (default 2)")
    parser.add_argument("--serial", type=int, default=10, help="submissions for the -j 1 run (0: skip)")
    parser.add_argument("--json", type=Path, default=None, help="write the results here")
    args = parser.parse_args(argv)
    results = {}
    with tempfile.TemporaryDirectory(prefix="bench-grade-") as tmp:
        tmp = Path(tmp)
        for label, jobs, n in ((f"-j {args.jobs}", args.jobs, args.n), ("-j 1", 1, args.serial)):
            if n <= 0:
                continue
            folder = tmp / f"class-j{jobs}"
            folder.mkdir()
            expected = make_class(folder, n)
            seconds = grade(folder, jobs, expected)
            results[label] = {"submissions": n, "seconds": round(seconds, 2),
                              "seconds_per_submission": round(seconds / n, 3)}
    print(f"{'run':<8} {'submissions':>11} {'total [s]':>10} {'per submission [s]':>19}")
    for label, r in results.items():
        print(f"{label:<8} {r['submissions']:>11} {r['seconds']:>10.1f} {r['seconds_per_submission']:>19.2f}")
    if len(results) == 2:
        a, b = results.values()
        print(f"ratio: -j 1 takes {b['seconds_per_submission'] / a['seconds_per_submission']:.2f}x "
              f"as long per submission as {list(results)[0]}")
    main_run = results[f"-j {args.jobs}"]
    verdict = "under" if main_run["seconds"] < 120 else "OVER"
    print(f"{args.n} submissions with -j {args.jobs}: {main_run['seconds']:.1f} s ({verdict} the 2-minute target)")
    if args.json:
        args.json.write_text(json.dumps(results, indent=2), encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main())
