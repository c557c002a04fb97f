"""The grader checks itself before it grades anyone.

Before the first submission runs, :func:`check` starts **one kernel exactly as the submissions'
will be started** — through the same runner, as the same unprivileged user, in the same mount
namespace, with a working folder made the same way (hence the same ``TMPDIR``) — and asks it to
import dhlab and answer one value. If it cannot, the grader stops with one message that says
why (which user cannot enter which folder) and what to do, and grades nothing: a machine
problem must not become 300 rows of "grader error".

Why: run as root with ``TMPDIR`` pointing into a folder other users cannot enter (a ``0700``
folder, as ``mktemp -d`` makes), every kernel died before it replied, and every submission
came back "grader error: Kernel died before replying to kernel_info" — 43 rows and no reason
a teacher could act on.
"""
from __future__ import annotations

import json
import os
import shutil
import sys
import tempfile
from pathlib import Path
from types import SimpleNamespace

__all__ = ["SelfCheckError", "check", "PROBE_VALUE"]

PROBE_VALUE = 7                      # what the probe kernel must answer (as n_links)
PROBE_CODE = ("import dhlab, dhlab.grading.answers  # the grader's self-check: dhlab must import\n"
              f"n_links = {PROBE_VALUE}\n")


class SelfCheckError(Exception):
    """The grader cannot run a kernel as the submissions' would run (the message says why and
    what to do)."""


def _probe_notebook(folder: Path) -> Path:
    nb = {"nbformat": 4, "nbformat_minor": 5, "metadata": {},
          "cells": [{"cell_type": "code", "metadata": {}, "source": PROBE_CODE, "outputs": [],
                     "execution_count": None}]}
    path = folder / "self-check.ipynb"
    path.write_text(json.dumps(nb), encoding="utf-8")
    return path


def _answered(run: dict) -> bool:
    try:
        return json.loads(run.get("answers_json") or "{}").get("n_links") == PROBE_VALUE
    except (ValueError, AttributeError):
        return False


def check(iso, options, hide=()) -> None:
    """Run the probe kernel the way :func:`dhlab.grading.launch.run_submission` runs a submission
    (``iso``: the batch's :class:`~dhlab.grading.isolation.Isolation`; ``options``: its limits);
    raise :class:`SelfCheckError` when it does not import dhlab and answer."""
    from .launch import run_submission
    from .staging import Staged
    folder = Path(tempfile.mkdtemp(prefix="dhlab-grade-copies-"))     # where the real copies go
    os.chmod(folder, 0o700)
    try:
        staged = Staged("(self-check)", "self-check.ipynb", "", _probe_notebook(folder))
        limits = SimpleNamespace(timeout=max(60.0, options.timeout), total_timeout=max(120.0, options.total_timeout),
                                 memory_mb=options.memory_mb, output_mb=options.output_mb)
        run = run_submission(staged, limits, iso, hide, retries=0)
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    if not run.get("grader_error") and not run.get("errors") and _answered(run):
        return
    raise SelfCheckError(explain(iso, run))


def explain(iso, run: dict) -> str:
    """One message: what failed, why (which user cannot reach which path), and what to do."""
    from .isolation import blocked_on_the_way, package_dir
    what = (run.get("grader_error") or "; ".join(f"{e[1]}: {e[2]}" for e in run.get("errors", []))
            or run.get("answers_error") or "it did not answer")
    user = iso.users[0] if iso.users else None
    who = f"user {user[0]} (uid {user[1]})" if user else f"the grader's own user (uid {os.geteuid()})"
    head = (f"The grader's self-check failed, so nothing was graded: a kernel started as every submission's "
            f"will be ({who}) did not import dhlab and answer ({what[:200]}).")
    if user is not None:
        gids = os.getgrouplist(user[0], user[2]) if hasattr(os, "getgrouplist") else [user[2]]
        kernels = iso.base if iso.base is not None else Path(tempfile.gettempdir())
        blocked = blocked_on_the_way(kernels, user[1], gids)
        if blocked:
            return (f"{head} Why: {who} cannot enter {blocked}, on the way to the kernels' folder {kernels}. "
                    "What to do: point TMPDIR (or DHLAB_GRADE_KERNELS_DIR) to a folder every user can enter, "
                    "e.g. `TMPDIR=/tmp dhlab-grade …`, or grade with --isolation none (less safe).")
        for path in (Path(sys.executable).parent, package_dir()):
            blocked = blocked_on_the_way(path, user[1], gids)
            if blocked:
                return (f"{head} Why: {who} cannot enter {blocked}, on the way to {path}, and the sandbox could "
                        "not make it reachable. What to do: install Python and dhlab where every user can read "
                        "them (e.g. a virtual environment under /opt), or grade with --isolation none (less safe).")
    return (f"{head} What to do: check that `{sys.executable} -m ipykernel --version` and "
            f"`{sys.executable} -c 'import dhlab'` work"
            + (f" as {user[0]} (e.g. `runuser -u {user[0]} -- …`)" if user else "")
            + ", then grade again; --isolation none runs the kernels as the grader's own user.")
