"""Grading a class: N submitted notebooks with ``dhlab-grade -j 2`` and ``-j 1``, wall seconds per submission.

    python benchmarks/bench_grade.py [--count 30] [--jobs 2] [--serial N] [--variants 30] [--json out.json]

The goal: 200 submissions in at most 10 minutes with ``-j 2`` on an idle 2-core
machine, about 3 s of wall time per submission. Each run reports its wall seconds per
submission, and splits them into the grader's fixed start-up (reading the assignment, the
self-check's kernel: paid once a run) and the seconds each submission adds (from the
gradebook's ``seconds`` column: the sum over the rows divided by the jobs); the projection for
200 submissions is start-up + 200 × that. The machine's load is printed with the numbers:
a shared machine measures slower than an idle one.

The class is made of copies of the course's own notebooks, as students hand them in:
the solutions, the test submissions with a valid alternative DH assignment and with a
mistake in each part, and the untouched student version (one of each kind in turn).
No hostile notebooks: they wait for time limits, which measures the limits, not the grader.
The grader runs as it would for a teacher: as root it isolates each kernel (its own user,
mount namespace, processes killed afterwards), and the run says which mode it measured.

In one run, side by side:
  -j 2            all N submissions, two at a time
  -j 1            ``--serial`` of them (default: all N), one at a time (for the ratio)
  variants -j 2   a class of ``--variants`` students with personal robots (``dhlab-assign
                  release --family all``), graded with ``--secret-file --release``: each
                  notebook solved with its robot's reference DH frames, with another valid
                  assignment, with the chain out of order (one item), left unanswered, or
                  handed in by a classmate (graded against the roster's variant); the
                  target is the same, under 2 minutes for 30
Each run checks that every submission got the score (and the variant status) its kind
should get before its time is reported. The release is not timed (bench_release.py).
"""
from __future__ import annotations

import argparse
import contextlib
import csv
import io
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from dhlab.grading.release.generate import find_source

ROOT = Path(__file__).resolve().parents[1]
KINDS = {                       # notebook -> the score it must get
    find_source(): 10.0,        # the teacher's solution, computed (no file holds it)
    ROOT / "tests" / "data" / "submissions" / "valid_alternative.ipynb": 10.0,
    ROOT / "tests" / "data" / "submissions" / "mistake_part1.ipynb": 9.5,
    ROOT / "tests" / "data" / "submissions" / "mistake_part2.ipynb": 9.14,
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


def make_variant_class(folder: Path, n: int) -> tuple:
    """A released class of n students, each handing in a solved notebook of one kind in turn;
    returns (extra grader arguments, expected score or (status, max score) per submission)."""
    import numpy as np
    sys.path.insert(0, str(ROOT / "tests"))
    from dhlab.assignment.model import random_frames_from_axes
    from dhlab.grading.release import notebooks as R
    from support.solved_notebooks import released_robot, solved
    secret = folder.parent / "secret.key"
    secret.write_bytes(b"benchmark-secret-0123456789abcdef\n")
    ids = [f"student_{i + 1:02d}" for i in range(n)]
    roster = folder.parent / "roster.csv"
    roster.write_text("id\n" + "\n".join(ids) + "\n", encoding="utf-8")
    release = folder.parent / "release"
    with contextlib.redirect_stdout(io.StringIO()):
        R.release(roster, release, secret.read_bytes().strip(), "all")
    nbs = {sid: json.loads((release / f"{sid}.ipynb").read_text(encoding="utf-8")) for sid in ids}
    expected = {}
    for i, sid in enumerate(ids):
        nb, robot, kind = nbs[sid], released_robot(nbs[sid]), i % 5
        if kind == 0:
            nb, want = solved(nb, robot), 10.0
        elif kind == 1:
            nb, want = solved(nb, robot, random_frames_from_axes(robot, np.random.default_rng(i))), 10.0
        elif kind == 2:                                  # the chain out of order: one item of part 3
            nb = solved(nb, robot)
            cell = next(c for c in nb["cells"] if c.get("metadata", {}).get("nbgrader", {}).get("grade_id")
                        == "part3_answers")
            cell["source"] = cell["source"].replace("chain = T1 @ T2", "chain = T2 @ T1")
            want = round(10 - 5 / (robot.n + 1), 2)
        elif kind == 3:
            want = 0.0                                   # handed in as released: not answered
        else:                                            # a classmate's solved notebook
            other = ids[i - 1]
            nb, want = solved(nbs[other], released_robot(nbs[other])), ("other_student", 7.0)
        (folder / f"{sid}.ipynb").write_text(json.dumps(nb), encoding="utf-8")
        expected[sid] = want
    return ["--secret-file", str(secret), "--release", str(release)], expected


def package_copy(into: Path) -> Path:
    """dhlab copied where every user can read it: the grader watches its package for changes
    during a batch, and this working tree may be edited meanwhile (the kernels' users import it)."""
    shutil.copytree(ROOT / "dhlab", into / "dhlab", ignore=shutil.ignore_patterns("__pycache__"))
    for path in [into, *into.rglob("*")]:
        path.chmod(0o755 if path.is_dir() else 0o644)
    return into


def grade(folder: Path, jobs: int, expected: dict, extra=(), package: Path | None = None) -> tuple:
    """(wall seconds of one `dhlab-grade` run, a fresh process as a teacher runs it; the sum of
    its rows' own seconds)."""
    out = folder.parent / f"gradebook-j{jobs}.csv"
    env = dict(os.environ, PYTHONPATH=str(package)) if package else None
    started = time.perf_counter()
    proc = subprocess.run([sys.executable, "-m", "dhlab.grading.cli", "puma", str(folder), "-o", str(out),
                           "-j", str(jobs), "-q", *extra], capture_output=True, text=True, env=env,
                          cwd=package)
    seconds = time.perf_counter() - started
    if proc.returncode != 0:
        raise SystemExit(f"dhlab-grade failed:\n{proc.stderr[-2000:]}")
    if "not isolated" in proc.stderr:
        print("(measured without isolation: " + proc.stderr.split("not isolated:", 1)[1].splitlines()[0].strip() + ")")
    with open(out, newline="", encoding="utf-8") as f:
        rows = {row["submission"]: row for row in csv.DictReader(f)}
    scores = {k: float(row["score"]) for k, row in rows.items()}
    wrong = {}
    for k, v in expected.items():
        if isinstance(v, tuple):                         # (variant status, a score it stays under)
            if k not in rows or rows[k].get("variant_status") != v[0] or scores[k] >= v[1]:
                wrong[k] = (rows.get(k, {}).get("variant_status"), scores.get(k), v)
        elif abs(scores.get(k, -1) - v) > 0.01:
            wrong[k] = (scores.get(k), v)
    if wrong:
        raise SystemExit(f"wrong scores (got, expected): {wrong}")
    return seconds, sum(float(row.get("seconds") or 0) for row in rows.values())


def summary(n: int, jobs: int, seconds: float, row_seconds: float) -> dict:
    """Per-submission wall time, and the run split into its fixed start-up and the time each
    submission adds (the rows' own seconds, ``jobs`` at a time)."""
    added = row_seconds / jobs / n
    startup = max(0.0, seconds - row_seconds / jobs)
    return {"submissions": n, "jobs": jobs, "seconds": round(seconds, 2),
            "seconds_per_submission": round(seconds / n, 3), "startup_seconds": round(startup, 1),
            "added_seconds_per_submission": round(added, 3),
            "row_seconds_mean": round(row_seconds / n, 2),
            "projected_200_seconds": round(startup + 200 * added, 1)}


def machine() -> str:
    """Cores and load: a shared machine measures slower than an idle one."""
    load = os.getloadavg() if hasattr(os, "getloadavg") else (float("nan"),) * 3
    return f"{os.cpu_count()} cores, load {load[0]:.2f} {load[1]:.2f} {load[2]:.2f} (1, 5, 15 min)"


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", "--n", dest="count", type=int, default=30,
                        help="submissions of the -j JOBS run (default 30)")
    parser.add_argument("--jobs", type=int, default=2, help="parallel jobs of the main run (default 2)")
    parser.add_argument("--serial", type=int, default=None,
                        help="submissions of the -j 1 run (default: --count; 0: skip)")
    parser.add_argument("--variants", type=int, default=30,
                        help="students of the personal-variants run (0: skip)")
    parser.add_argument("--json", type=Path, default=None, help="write the results here")
    args = parser.parse_args(argv)
    serial = args.count if args.serial is None else args.serial
    results = {}
    runs = [(f"-j {args.jobs}", args.jobs, args.count, False), ("-j 1", 1, serial, False),
            (f"variants -j {args.jobs}", args.jobs, args.variants, True)]
    print(f"machine: {machine()}")
    with tempfile.TemporaryDirectory(prefix="bench-grade-") as tmp:
        tmp = Path(tmp)
        tmp.chmod(0o755)
        package = package_copy(tmp / "package")
        for label, jobs, n, variants in runs:
            if n <= 0:
                continue
            folder = tmp / label.replace(" ", "_").replace("-", "") / "class"
            folder.mkdir(parents=True)
            extra, expected = make_variant_class(folder, n) if variants else ((), make_class(folder, n))
            results[label] = summary(n, jobs, *grade(folder, jobs, expected, extra, package))
    print(f"machine after: {machine()}")
    print(f"{'run':<13} {'subm.':>5} {'total [s]':>9} {'per subm. [s]':>13} {'start-up [s]':>12} "
          f"{'added/subm. [s]':>15} {'row mean [s]':>12} {'200 projected':>14}")
    for label, r in results.items():
        print(f"{label:<13} {r['submissions']:>5} {r['seconds']:>9.1f} {r['seconds_per_submission']:>13.2f} "
              f"{r['startup_seconds']:>12.1f} {r['added_seconds_per_submission']:>15.2f} "
              f"{r['row_seconds_mean']:>12.2f} {_minutes(r['projected_200_seconds']):>14}")
    if f"-j {args.jobs}" in results and "-j 1" in results:
        a, b = results[f"-j {args.jobs}"], results["-j 1"]
        print(f"ratio: -j 1 adds {b['added_seconds_per_submission'] / a['added_seconds_per_submission']:.2f}x "
              f"as much time per submission as -j {args.jobs}")
    for label in (f"-j {args.jobs}", f"variants -j {args.jobs}"):
        if label in results:
            r = results[label]
            verdict = "under" if r["projected_200_seconds"] <= 600 else "OVER"
            print(f"{label}: 200 submissions projected in {_minutes(r['projected_200_seconds'])} "
                  f"({verdict} the 10-minute goal; {r['added_seconds_per_submission']:.2f} s per submission "
                  f"against about 3 s)")
    if args.json:
        args.json.write_text(json.dumps({"machine": machine(), "runs": results}, indent=2), encoding="utf-8")
    return 0


def _minutes(seconds: float) -> str:
    return f"{int(seconds // 60)} min {seconds % 60:02.0f} s"


if __name__ == "__main__":
    sys.exit(main())
