"""Releasing the assignment to a class: ``dhlab-assign release`` for N students, wall time.

    python benchmarks/bench_release.py [--n 300] [--family all] [--json out.json]

In one run, side by side (each a fresh process, as a teacher runs it):
  default      N notebooks; the robot's picture is drawn when the student runs its cell
               (target: N = 300 in under a minute)
  --figures    the same roster with the picture stored in every notebook (for the ratio;
               only the first --n-figures students, it costs about 0.5 s of CPU each)
Each run checks that every notebook's signed record verifies for its student before its
time is reported, and that the two runs gave every student the same variant.
"""
from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from dhlab.assignment import variants as V  # noqa: E402

SECRET = b"benchmark-secret-0123456789abcdef"


def run(roster: Path, out: Path, secret: Path, family: str, figures: bool) -> float:
    cmd = [sys.executable, "-m", "dhlab.grading.release", "release", str(roster), "-o", str(out),
           "--secret-file", str(secret), "--family", family] + (["--figures"] if figures else [])
    started = time.perf_counter()
    proc = subprocess.run(cmd, capture_output=True, text=True, cwd=ROOT)
    seconds = time.perf_counter() - started
    if proc.returncode != 0:
        raise SystemExit(f"dhlab-assign failed:\n{proc.stderr[-2000:]}")
    return seconds


def check(out: Path, ids) -> dict:
    """Every notebook verifies for its student; returns id -> variant fingerprint."""
    records = json.loads((out / "_teacher" / "variants.json").read_text(encoding="utf-8"))
    prints = {}
    for sid in ids:
        from dhlab.grading.release.roster import safe_filename
        nb = json.loads((out / f"{safe_filename(sid)}.ipynb").read_text(encoding="utf-8"))
        result = V.verify(nb["metadata"][V.METADATA_KEY], sid, SECRET)
        if result.status != "ok" or records[sid] != nb["metadata"][V.METADATA_KEY]:
            raise SystemExit(f"{sid}: {result.status} ({result.message})")
        prints[sid] = V.fingerprint(result.variant)
    if len(set(prints.values())) != len(ids):
        raise SystemExit("two students got the same robot")
    return prints


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=300)
    parser.add_argument("--n-figures", type=int, default=30)
    parser.add_argument("--family", default="all")
    parser.add_argument("--json", default=None)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        ids = [f"student_{i:03d}" for i in range(1, args.n + 1)]
        roster = tmp / "roster.csv"
        roster.write_text("id\n" + "\n".join(ids) + "\n", encoding="utf-8")
        secret = tmp / "secret.key"
        secret.write_bytes(SECRET)
        results = {}
        prints = {}
        small = tmp / "roster_small.csv"
        small.write_text("id\n" + "\n".join(ids[:args.n_figures]) + "\n", encoding="utf-8")
        for label, figures, path, n in (("default", False, roster, args.n),
                                        ("--figures", True, small, args.n_figures)):
            out = tmp / label.strip("-")
            seconds = run(path, out, secret, args.family, figures)
            prints[label] = check(out, ids[:n])
            size = sum(p.stat().st_size for p in out.glob("*.ipynb")) / n / 1e3
            results[label] = {"students": n, "seconds": round(seconds, 2),
                              "per_student_ms": round(1e3 * seconds / n, 1), "kb_per_notebook": round(size, 1)}
        if any(prints["default"][sid] != fp for sid, fp in prints["--figures"].items()):
            raise SystemExit("the two runs gave different variants")
    base = results["default"]["per_student_ms"]
    print(f"dhlab-assign release, family {args.family!r} (wall time of a fresh process)")
    print(f"{'run':<10} {'students':>8} {'seconds':>8} {'ms/student':>11} {'kB/notebook':>12} {'ratio':>6}")
    for label, r in results.items():
        print(f"{label:<10} {r['students']:>8} {r['seconds']:>8.2f} {r['per_student_ms']:>11.1f} "
              f"{r['kb_per_notebook']:>12.1f} {r['per_student_ms'] / base:>6.2f}")
    target = results["default"]["seconds"] < 60 * args.n / 300
    print(f"target (300 in under a minute, scaled to {args.n}): {'met' if target else 'MISSED'}")
    if args.json:
        Path(args.json).write_text(json.dumps({"n": args.n, "family": args.family, "results": results},
                                              indent=1), encoding="utf-8")
    return 0 if target else 1


if __name__ == "__main__":
    sys.exit(main())
