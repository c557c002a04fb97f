"""Run one submitted notebook in a fresh, limited kernel and collect its answers as plain data.

The grader starts one runner process per submission::

    python dhlab/grading/run/runner.py NOTEBOOK RESULT.json [--timeout 30] [--total-timeout 120]
                                   [--memory-mb 2048] [--output-mb 10]
                                   [--uid U --gid G --workdir DIR --token T]
    (python -m dhlab.grading.run.runner ... works too)

What it does, and why:

1. Reads the notebook as JSON (a file that is not JSON, or not a notebook, is reported,
   not run).
2. Starts a **fresh kernel** (:mod:`dhlab.grading.run.kernel`) through
   :mod:`dhlab.grading.run.sandbox`, which lowers the kernel's resource limits (memory,
   CPU, file size) before IPython starts and, with
   ``--uid``, makes the kernel an unprivileged user in its own mount namespace (the
   runner itself stays the grader's user, so the kernel cannot signal it or forge its
   result). The kernel's environment names no file of the grader: only an opaque
   ``DHLAB_GRADE_TOKEN``.
3. Runs every code cell in order, as the student would with "Run all". A cell that
   raises does not stop the others (its error is recorded). A cell that runs longer
   than ``--timeout`` seconds is interrupted. If the kernel dies, cannot be
   interrupted, or a cell prints more than ``--output-mb``, a new kernel runs the
   notebook again without that cell. All of it within ``--total-timeout`` seconds.
4. Asks the kernel to write the values of the answer names as JSON
   (:mod:`dhlab.grading.run.read_answers`: the source of
   :func:`dhlab.assignment.encode.to_plain` is sent in, so a notebook that changed
   ``dhlab`` cannot change how its answers are read), and reads that file — never
   anything the notebook printed.
5. Writes what happened and the answers' JSON text to ``RESULT.json``. It scores
   nothing: the grader scores in its own process.

The outputs of the cells are counted, not kept.
"""
from __future__ import annotations

import argparse
import ctypes
import ctypes.util
import json
import os
import secrets
import shutil
import signal
import sys
import tempfile
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path

try:
    from . import cgroups
    from .kernel import FLOOD_FACTOR, Kernel
    from .notebook_code import MAX_CODE_BYTES, MAX_NOTEBOOK_BYTES, NotebookError, read_code_cells, scan_for_tampering
    from .read_answers import read_answers
    from .sandbox import MAX_PROCESSES, apply_limits
except ImportError:      # started as a script by the grader (see RUNNER below): this folder is sys.path[0]
    import cgroups
    from kernel import FLOOD_FACTOR, Kernel  # noqa: F401 (API)
    from notebook_code import MAX_CODE_BYTES, MAX_NOTEBOOK_BYTES, NotebookError, read_code_cells, scan_for_tampering
    from read_answers import read_answers
    from sandbox import MAX_PROCESSES, apply_limits

__all__ = ["RunResult", "run_notebook", "read_code_cells", "scan_for_tampering", "main",
           "NotebookError", "MAX_NOTEBOOK_BYTES", "MAX_CODE_BYTES"]

# The grader starts this file, and the kernel's launcher, as scripts (python .../runner.py),
# not with -m: so these processes do not import the whole dhlab package (numpy, sympy, ...).
# That saves half a second per submission, and the only dhlab files they read from disk are
# runner.py, kernel.py, read_answers.py, notebook_code.py, sandbox.py, cgroups.py and
# ../../assignment/encode.py; the grader checks the whole package unchanged.
RUNNER = Path(__file__).resolve()
MAX_ATTEMPTS = 3


@dataclass
class RunResult:
    """What happened to one submission (plain data, written as JSON for the grader)."""
    notebook_error: str = ""
    cells: int = 0                                   # code cells in the notebook
    errors: list = field(default_factory=list)       # [cell, ename, evalue]
    timeouts: list = field(default_factory=list)     # cells interrupted after --timeout
    output_capped: list = field(default_factory=list)  # [cell, bytes]
    kernel_died: list = field(default_factory=list)  # cells during which the kernel died
    stuck: list = field(default_factory=list)        # cells that could not be interrupted
    skipped: list = field(default_factory=list)      # cells left out of a re-run
    runner_killed: list = field(default_factory=list)  # cells during which the runner itself was killed
    out_of_time: bool = False                        # --total-timeout reached
    restarts: int = 0
    tampering: list = field(default_factory=list)    # what the notebook does to dhlab
    limit: str = ""                                  # "memory": the submission's memory limit was reached
    isolation: str = ""                              # how the kernel was kept apart (what held, what did not)
    answers_json: str | None = None
    answers_error: str = ""
    grader_error: str = ""
    seconds: float = 0.0


# --- one notebook ---------------------------------------------------------------------------

def run_notebook(path, timeout: float = 30, total_timeout: float = 120, memory_mb: float = 2048,
                 output_mb: float = 10, pid_file=None, progress_file=None, skip=(), workdir=None,
                 user=None, token: str = "") -> RunResult:
    """Run the notebook at ``path`` in a sandboxed kernel and read its answers (see the module doc).

    ``pid_file``: where to write the kernel's process id (so the grader can end it);
    ``progress_file``: where to write the number of the cell being run (so the grader
    knows which cell to leave out if this whole process is killed); ``skip``: cells
    not to run; ``workdir``: the kernel's own folder (default: a new temporary one);
    ``user``: (uid, gid) the kernel runs as (the runner must be root: the kernel then gets a
    private root, in which no folder but its own exists, and the submission a control group);
    ``token``: put in the kernel's environment.
    """
    started = time.monotonic()
    result = RunResult()
    try:
        cells = read_code_cells(path)
    except (NotebookError, OSError) as e:
        result.notebook_error = str(e)
        return result
    result.cells = len(cells)
    result.tampering = scan_for_tampering(cells)
    cap = int(output_mb * 1e6)
    deadline = started + total_timeout
    skip = set(skip)
    result.skipped = sorted(skip)
    progress = Path(progress_file) if progress_file else None
    own_workdir = workdir is None
    workdir = Path(tempfile.mkdtemp(prefix="dhlab-grade-")) if own_workdir else Path(workdir)
    private = Path(tempfile.mkdtemp(prefix="dhlab-runner-"))        # the grader's user only (0700)
    token = token or secrets.token_hex(8)
    group = _submission_group(user, token, memory_mb, result)
    try:
        for attempt in range(MAX_ATTEMPTS):
            kernel = Kernel(workdir, private, memory_mb, cpu_seconds=total_timeout + 60, file_mb=64,
                             output_mb=output_mb, pid_file=Path(pid_file) if pid_file else None, token=token,
                             user=user, group_dirs=group.dirs if group else ())
            try:
                if attempt == 0 and user is not None:
                    _describe_isolation(result, kernel.sandbox_missing(), workdir)
                broken = _run_cells(kernel, cells, skip, timeout, deadline, cap, result, attempt == 0, progress)
                if broken is None:
                    read_answers(kernel, workdir, result)
                    return result
            finally:
                kernel.shutdown()
                if group is not None and group.oom_kills():
                    result.limit = "memory"
                # nothing of this attempt lives into the next one (a daemon that plants links in
                # the kernel's folder for the next kernel's start, say)
                _end_processes(group)
            skip.add(broken)
            result.skipped = sorted(skip)
            if time.monotonic() > deadline - 2 or attempt == MAX_ATTEMPTS - 1:
                result.answers_error = "the kernel died or hung, and there was no time left to run the notebook again"
                return result
            result.restarts += 1
        return result
    except Exception as e:                       # the grader's fault, not the student's
        result.grader_error = f"{type(e).__name__}: {str(e)[:200]}"
        return result
    finally:
        result.seconds = round(time.monotonic() - started, 2)
        if group is not None:
            if group.oom_kills():
                result.limit = "memory"
            group.remove()                       # every process the submission started ends here
        shutil.rmtree(private, ignore_errors=True)
        if own_workdir:
            shutil.rmtree(workdir, ignore_errors=True)
        shutil.rmtree(f"{workdir}.root", ignore_errors=True)      # the private root's mount point


def _submission_group(user, token: str, memory_mb: float, result: RunResult):
    """The submission's control group (memory and processes of the whole submission, children
    included: :mod:`dhlab.grading.run.cgroups`), or None where none can be made (then each process
    has its own limits, and ``result.isolation`` says so)."""
    if user is None:
        result.isolation = "none: the grader's own user, limits per process"
        return None
    group = cgroups.create(f"sub-{token}", memory_mb, MAX_PROCESSES)
    result.isolation = group.describe() if group else (
        f"limits per process only ({cgroups.last_refusal}): {memory_mb:.0f} MB of address space each")
    return group


def _end_processes(group) -> None:
    """End every process of this submission's control group (none: the grader ends the user's
    processes after the submission, :meth:`dhlab.grading.run.isolation.Isolation.cleanup`). Never all
    of the user's here: a runner does not own its user, its grader does (see :func:`main`)."""
    if group is not None:
        group.kill_all()


def _describe_isolation(result: RunResult, missing: list, kernel_folder=None) -> None:
    """``result.isolation``: the user, the private root and network, the limits — and what did not hold."""
    held = ["own user"]
    if not any("private root" in m for m in missing):
        held.append("private root")
    if kernel_folder is not None and os.path.ismount(kernel_folder):
        held.append("own folder a tmpfs")
    else:
        missing = [*missing, "its own folder is on the disk, with no size limit but 64 MB per file"]
    if not any("network" in m for m in missing):
        held.append("no network")
    result.isolation = "; ".join([", ".join(held), result.isolation] + [f"NOT: {m}" for m in missing])


def _run_cells(kernel, cells, skip, timeout, deadline, cap, result, record, progress) -> int | None:
    """Run the cells; the number of a cell that killed or hung the kernel, else None."""
    for number, source in cells:
        if number in skip or not source.strip():
            continue
        if progress is not None:
            progress.write_text(str(number), encoding="utf-8")
        left = deadline - time.monotonic()
        if left <= 0:
            result.out_of_time = True
            return None if kernel.alive() else number
        cell = kernel.execute(source, min(timeout, left), cap)
        if (cell.capped_in_kernel or cell.output_bytes > cap) and cell.stopped_for != "output" \
                and number not in [c for c, _ in result.output_capped]:
            result.output_capped.append([number, cell.output_bytes])     # its output past the cap was dropped
        if cell.status == "error" and record:
            result.errors.append([number, cell.ename, cell.evalue])
        if cell.stopped_for == "timeout":
            if min(timeout, left) < timeout:
                result.out_of_time = True
            elif number not in result.timeouts:
                result.timeouts.append(number)
        elif cell.stopped_for == "output":
            if number not in [c for c, _ in result.output_capped]:
                result.output_capped.append([number, cell.output_bytes])
            return number
        if cell.status == "dead":
            result.kernel_died.append(number)
            return number
        elif cell.status == "stuck":
            result.stuck.append(number)
            return number
    return None


def _die_with_the_grader() -> None:
    """End this runner when the grader that started it ends (``prctl(PR_SET_PDEATHSIG)``). A runner
    outliving a grader killed with ``kill -9`` would go on starting kernels as a user that the next
    grader may already have claimed, and end them in the middle of that grader's work."""
    parent = os.getppid()
    try:
        libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6", use_errno=True)
        libc.prctl(1, signal.SIGKILL, 0, 0, 0)        # PR_SET_PDEATHSIG
    except (OSError, AttributeError):
        return
    if os.getppid() != parent:                        # the grader ended before the call: so do we
        os._exit(1)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("notebook")
    parser.add_argument("result")
    parser.add_argument("--timeout", type=float, default=30, help="seconds per cell (default 30)")
    parser.add_argument("--total-timeout", type=float, default=120, help="seconds for the whole notebook")
    parser.add_argument("--memory-mb", type=float, default=2048, help="the kernel's address-space limit")
    parser.add_argument("--output-mb", type=float, default=10, help="output a cell may print before it is stopped")
    parser.add_argument("--pid-file", default=None, help="where to write the kernel's process id")
    parser.add_argument("--progress-file", default=None, help="where to write the number of the cell being run")
    parser.add_argument("--skip", type=int, action="append", default=[], help="a cell not to run (repeatable)")
    parser.add_argument("--workdir", default=None, help="the kernel's own folder (owned by --uid)")
    parser.add_argument("--uid", type=int, default=None, help="the unprivileged user the kernel runs as")
    parser.add_argument("--gid", type=int, default=None)
    parser.add_argument("--token", default="", help="an opaque mark put in the kernel's environment")
    args = parser.parse_args(argv)
    _die_with_the_grader()
    apply_limits(memory_mb=max(4096, 2 * args.memory_mb), cpu_seconds=None, file_mb=None)
    user = (args.uid, args.gid) if args.uid is not None else None
    result = run_notebook(args.notebook, args.timeout, args.total_timeout, args.memory_mb, args.output_mb,
                          args.pid_file, args.progress_file, args.skip, args.workdir, user, args.token)
    out = Path(args.result)
    tmp = out.with_name(out.name + ".tmp")
    tmp.write_text(json.dumps(asdict(result)), encoding="utf-8")
    os.replace(tmp, out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
