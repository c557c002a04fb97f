"""The grader as the grading tests run it: from a copy of the package, on notebooks written here.

The grader imports dhlab from a private copy (PYTHONPATH), so that a submission that tampers with
"the installed dhlab" can only touch that copy, and so that its check "dhlab is unchanged" is not
disturbed by anyone editing this working tree.
"""
from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

from dhlab.grading.release.generate import find_source

ROOT = Path(__file__).resolve().parents[2]                              # the repository
SOURCE = find_source()               # the teacher's solved notebook: computed, in a temporary folder


def package_copy(base: Path | None = None) -> Path:
    """dhlab copied into ``base`` (default: a new temporary folder), a folder every user can read (the
    kernels' users must import it). Nothing else: the grader's self-check computes the teacher's solution."""
    base = Path(tempfile.mkdtemp(prefix="dhlab-test-pkg-")) if base is None else base
    shutil.copytree(ROOT / "dhlab", base / "dhlab", ignore=shutil.ignore_patterns("__pycache__"))
    for path in [base, *base.rglob("*")]:
        path.chmod(0o755 if path.is_dir() else 0o644)
    return base


def run_grader(argv, package: Path, **kw):
    """The grader, importing dhlab from ``package`` (run from there: ``-m`` puts the working
    folder first on the path, and this repository's dhlab must not be the one imported)."""
    env = dict(os.environ, PYTHONPATH=str(package))
    return subprocess.run([sys.executable, "-m", "dhlab.grading.cli", *argv], capture_output=True, text=True,
                          env=env, cwd=package, **kw)


def write_notebook(path, *cells):
    """A notebook at ``path`` with one code cell per source in ``cells``, never run."""
    nb = {"nbformat": 4, "nbformat_minor": 5, "metadata": {},
          "cells": [{"cell_type": "code", "metadata": {}, "source": c, "outputs": [], "execution_count": None}
                    for c in cells]}
    path.write_text(json.dumps(nb), encoding="utf-8")
    return path
