"""Run every benchmark of this folder, one after the other, and keep their results.

    python benchmarks/run_all.py            # or: make bench   (make bench RTB=1 adds the Robotics Toolbox)

Each ``bench_*.py`` prints its own table (methods side by side in one run, with
ratios); the JSON results go to ``benchmarks/results/`` (not committed). Among them
``bench_import.py``: ``import dhlab`` beside ``import roboticstoolbox`` (when this
interpreter has the toolbox), each in a fresh interpreter.
"""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).parent


def main() -> int:
    out_dir = HERE / "results"
    out_dir.mkdir(exist_ok=True)
    failed = []
    for script in sorted(HERE.glob("bench_*.py")):
        print(f"\n=== {script.name} ===", flush=True)
        result = subprocess.run([sys.executable, str(script), "--json", str(out_dir / f"{script.stem}.json")])
        if result.returncode:
            failed.append(script.name)
    if failed:
        print(f"\nfailed: {', '.join(failed)}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
