"""The grader checks itself before it grades anyone.

Before the first submission runs, :func:`check` starts **one kernel exactly as the submissions'
will be started** — through the same runner, as the same unprivileged user, in the same mount
namespace, with a working folder made the same way (hence the same ``TMPDIR``) and the same
limits (``--memory-mb`` included) — and grades the teacher's solution (:func:`solution`: what a
correct submission does, from ``import dhlab`` to the last answer), which must earn full marks.
No file holds that solution (students install the course too): it is computed for the PUMA 560
(:func:`dhlab.assignment.solution.solved_notebook`), or it is the teacher's own source notebook,
``--source PATH`` (``options.source``).
If it cannot, the grader stops with one message that says why (which user cannot enter which
folder; or the memory limit, and a limit that worked) and what to do, and grades nothing: a
machine problem must not become 300 rows of "grader error", nor a limit 300 zeros.

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

from ...assignment.answers import parse_json
from ...assignment.checks import check_all
from ...i18n import _
from ..release.generate import NOTEBOOK, SourceMissing, find_source, solution_notebook
from .isolation import blocked_on_the_way, package_dir
from .launch import run_submission
from .staging import stage

__all__ = ["SelfCheckError", "check", "solution"]

LARGER_MB = 2048                     # tried when the teacher's memory limit fails (unless theirs is larger)


class SelfCheckError(Exception):
    """The grader cannot run a kernel as the submissions' would run (the message says why and
    what to do)."""


def check(iso, options) -> None:
    """Grade the teacher's solution the way :func:`dhlab.grading.run.launch.run_submission` runs a
    submission (``iso``: the batch's :class:`~dhlab.grading.run.isolation.Isolation`; ``options``: its
    limits, ``options.memory_mb`` included); raise :class:`SelfCheckError` unless it runs without an
    error and earns full marks. Why a whole correct notebook and not a one-line probe: with
    ``--memory-mb 1024`` a probe passed, then every correct notebook scored 0. When the limit is
    the cause, the message names it and a limit that worked."""
    run, ok = _grade_solution(iso, options, options.memory_mb)
    if ok:
        return
    larger = max(LARGER_MB, 2 * float(options.memory_mb))
    if run.get("limit") == "memory" or float(options.memory_mb) < LARGER_MB:
        retry, retry_ok = _grade_solution(iso, options, larger)
        if retry_ok:
            raise SelfCheckError(memory_message(options.memory_mb, larger, run))
        if run.get("limit") == "memory":
            raise SelfCheckError(memory_message(options.memory_mb, None, run))
    raise SelfCheckError(explain(iso, run))


def solution(options, folder) -> Path:
    """The teacher's solution as a file, a correct submission run exactly as every submission will
    be: ``options.source`` when given (:class:`SelfCheckError` when it is not there; what it holds is
    staged as a submission is), else the one computed for the PUMA 560, written into ``folder``."""
    source = getattr(options, "source", None)
    if source is not None:
        try:
            return find_source(source)
        except SourceMissing as e:
            raise SelfCheckError(_("The grader's self-check needs the teacher's solution, so nothing was graded.")
                                 + f" {e}") from None
    Path(folder).mkdir(mode=0o700, exist_ok=True)
    written = Path(folder) / NOTEBOOK
    written.write_text(json.dumps(solution_notebook(), ensure_ascii=False), encoding="utf-8")
    return written


def _grade_solution(iso, options, memory_mb) -> tuple:
    """(the runner's result, whether it ran without an error and earns full marks) for the
    solution notebook, copied as a submission is (:func:`dhlab.grading.run.staging.stage`)."""
    folder = Path(tempfile.mkdtemp(prefix="dhlab-grade-copies-"))     # where the real copies go
    os.chmod(folder, 0o700)
    try:
        source = solution(options, folder / "solution")
        staged = stage(source, source.parent, folder, 0)
        if staged.copy is None:
            return {"grader_error": f"{source}: {staged.error}"}, False
        limits = SimpleNamespace(timeout=max(60.0, options.timeout), total_timeout=max(120.0, options.total_timeout),
                                 memory_mb=memory_mb, output_mb=options.output_mb)
        run = run_submission(staged, limits, iso, retries=0)
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    return run, not run.get("grader_error") and not run.get("errors") and _full_marks(run)


def _full_marks(run: dict) -> bool:
    """Whether the answers the kernel wrote earn full marks against the PUMA 560."""
    try:
        report = check_all(parse_json(run.get("answers_json") or "{}"))
    except (ValueError, AttributeError, TypeError):
        return False
    return report.score >= report.max_score


def _what_failed(run: dict) -> str:
    return (run.get("grader_error") or "; ".join(f"{e[1]}: {e[2]}" for e in run.get("errors", []))
            or run.get("answers_error") or "it did not earn full marks")


def memory_message(memory_mb, worked, run: dict) -> str:
    """The self-check failed for the memory limit: name it, and the limit that worked (``worked``;
    None when a larger one failed too)."""
    head = (f"The grader's self-check failed, so nothing was graded: a correct notebook (the teacher's solution, "
            f"run as every submission will be) did not run within the memory limit --memory-mb {float(memory_mb):g} "
            f"({_what_failed(run)[:200]}).")
    if worked is not None:
        return (f"{head} With --memory-mb {worked:g} it earned full marks. What to do: grade with "
                f"--memory-mb {worked:g} (or more).")
    return (f"{head} What to do: grade with a larger --memory-mb; if that fails too, see the message of a run "
            "with the default (2048).")


def explain(iso, run: dict) -> str:
    """One message: what failed, why (which user cannot reach which path), and what to do."""
    what = _what_failed(run)
    user = iso.users[0] if iso.users else None
    who = f"user {user[0]} (uid {user[1]})" if user else f"the grader's own user (uid {os.geteuid()})"
    head = (f"The grader's self-check failed, so nothing was graded: a kernel started as every submission's "
            f"will be ({who}) did not grade the teacher's solution ({what[:200]}).")
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
