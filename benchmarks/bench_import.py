"""The time of ``import dhlab``, side by side with ``import roboticstoolbox``, each in a fresh interpreter.

    python benchmarks/bench_import.py [--repeat 15] [--python PATH]

A student pays the import once per kernel, and the browser edition pays it before its first
slider: ``import dhlab`` loads the maths only (numpy), and leaves sympy, matplotlib, ipywidgets,
the course, the assignment and the grader to the first name that needs them (see ``dhlab/__init__``).

Each run starts a new ``python -c`` that times its own import with ``time.perf_counter`` (so the
interpreter's start-up is not counted, and the disk cache is warm after the first run: the first
run is a warm-up and is not counted). Reports the best and the median over ``--repeat`` runs per
module, run round robin, their ratio (goal: dhlab <= 0.25 x the toolbox's), and which heavy modules
``import dhlab`` loaded (none should be). ``--python`` runs another interpreter, e.g. a throw-away
venv with roboticstoolbox-python installed and dhlab on its ``PYTHONPATH``; without the toolbox,
only dhlab is measured.
"""
from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
from pathlib import Path

# what ``import dhlab`` must not load (it is loaded on first use, or never by dhlab itself)
HEAVY = ("sympy", "matplotlib", "matplotlib.pyplot", "mpl_toolkits.mplot3d", "ipywidgets", "anywidget",
         "dhlab.views", "dhlab.course", "dhlab.assignment", "dhlab.grading", "scipy")

PROBE = """\
import json, sys, time
start = time.perf_counter()
import {module}
seconds = time.perf_counter() - start
print(json.dumps({{"seconds": seconds, "loaded": [m for m in {heavy!r} if m in sys.modules],
                  "modules": len(sys.modules)}}))
"""


def import_once(python: str, module: str) -> dict:
    """One fresh interpreter's ``import module``: its seconds, the heavy modules it loaded, how many in all."""
    env = dict(os.environ)
    repository = str(Path(__file__).resolve().parents[1])
    env["PYTHONPATH"] = os.pathsep.join(p for p in (repository, env.get("PYTHONPATH", "")) if p)
    out = subprocess.run([python, "-c", PROBE.format(module=module, heavy=HEAVY)], env=env,
                         capture_output=True, text=True, check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def importable(python: str, module: str) -> bool:
    """True when ``module`` can be found by ``python`` (without importing it)."""
    probe = f"import importlib.util, sys; sys.exit(importlib.util.find_spec({module!r}) is None)"
    return subprocess.run([python, "-c", probe], capture_output=True).returncode == 0


def measure(python: str, modules: list, repeat: int) -> dict:
    """Per module: every run's seconds (round robin, after one warm-up each) and the last run's facts."""
    runs = {m: [] for m in modules}
    facts = {m: import_once(python, m) for m in modules}          # warm-up: caches and .pyc files
    for _ in range(repeat):
        for m in modules:
            facts[m] = import_once(python, m)
            runs[m].append(facts[m]["seconds"])
    return {m: {"best": min(runs[m]), "median": statistics.median(runs[m]), "runs": runs[m],
                "loaded": facts[m]["loaded"], "modules": facts[m]["modules"]} for m in modules}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=15)
    parser.add_argument("--python", default=sys.executable, help="the interpreter to measure (default: this one)")
    parser.add_argument("--json", help="also write the results to this file")
    args = parser.parse_args(argv)

    modules = ["dhlab"] + (["roboticstoolbox"] if importable(args.python, "roboticstoolbox") else [])
    results = measure(args.python, modules, args.repeat)
    print(f"import time, fresh interpreter each run ({args.repeat} runs, after a warm-up); python: {args.python}")
    print(f"{'module':<18} {'best ms':>8} {'median ms':>10} {'modules':>8}  heavy modules loaded")
    for m, r in results.items():
        heavy = ", ".join(r["loaded"]) or "none"
        print(f"{m:<18} {r['best'] * 1e3:8.1f} {r['median'] * 1e3:10.1f} {r['modules']:8d}  {heavy}")
    if "roboticstoolbox" in results:
        ratio = results["dhlab"]["median"] / results["roboticstoolbox"]["median"]
        best = results["dhlab"]["best"] / results["roboticstoolbox"]["best"]
        results["ratio"] = {"median": ratio, "best": best, "goal": 0.25}
        print(f"dhlab / roboticstoolbox: {ratio:.3f} (median), {best:.3f} (best); goal <= 0.25")
    else:
        print("roboticstoolbox is not installed for this interpreter: dhlab alone (see --python)")
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(results, fh, indent=1)
    return 1 if results["dhlab"]["loaded"] else 0


if __name__ == "__main__":
    sys.exit(main())
