"""Start the runner process of one submission, and end everything it started.

The grader (:mod:`dhlab.grading.cli`) calls :func:`run_submission` for each staged copy;
the runner (:mod:`dhlab.grading.run.runner`, started as a script) runs the notebook in its own
kernel and writes a result file, which is all that comes back.

Each runner is started in a session of its own, so a Ctrl-C in the teacher's terminal does not
reach it: the grader decides. On a second Ctrl-C it calls :func:`stop_all`: no runner starts any
more, every running one is killed with its kernel, and :func:`run_submission` raises
:class:`Stopped` for them (their rows are not written, so ``--resume`` grades them).
"""
from __future__ import annotations

import json
import os
import secrets
import signal
import subprocess
import sys
import tempfile
import threading
from pathlib import Path

from .isolation import setup
from .runner import RUNNER

__all__ = ["run_submission", "stop_all", "allow_runs", "Stopped"]

_RUNNING = {}                        # pid -> the Popen of every runner running now
_RUNNING_LOCK = threading.RLock()    # reentrant: stop_all runs in a signal handler, maybe inside it
STOPPING = threading.Event()         # set by stop_all: no runner starts any more


class Stopped(Exception):
    """The grader was told to stop (a second Ctrl-C) while this submission ran: it has no result."""


def stop_all() -> None:
    """Kill every running runner's process group (its kernel goes with it: :func:`_run_once`
    ends it afterwards) and start no other. Safe in a signal handler."""
    STOPPING.set()
    with _RUNNING_LOCK:
        running = list(_RUNNING.values())
    for proc in running:
        try:
            os.killpg(proc.pid, signal.SIGKILL)
        except (ProcessLookupError, PermissionError):
            pass


def allow_runs() -> None:
    """Forget an earlier :func:`stop_all` (a new batch in the same process, e.g. in tests)."""
    STOPPING.clear()


def _kill_kernel(pid_file: Path) -> None:
    """Kill the kernel a runner started (its own process group), if it is still there."""
    try:
        pid = int(pid_file.read_text().strip())
        cmdline = Path(f"/proc/{pid}/cmdline").read_bytes()
    except (OSError, ValueError):
        return
    if b"sandbox.py" in cmdline:
        try:
            os.killpg(pid, signal.SIGKILL)
        except (ProcessLookupError, PermissionError):
            pass


def run_submission(staged, options, iso=None, retries: int = 2) -> dict:
    """Run one staged notebook in a runner process; the runner's result (a dict).

    If the runner process itself dies (a notebook can kill its kernel's parent when it
    runs as the grader's user), the notebook is run again without the cell that was
    running, at most ``retries`` times. Afterwards every process the submission started
    is ended and its folder removed.
    """
    if STOPPING.is_set():
        raise Stopped(staged.file)
    iso = iso or setup(1, "none")
    user = iso.acquire()
    token = secrets.token_hex(12)
    workdir = iso.workdir(user)
    try:
        killed = []
        for attempt in range(retries + 1):
            run, cell = _run_once(staged.copy, options, skip=killed, user=user, workdir=workdir, token=token)
            if STOPPING.is_set() and run.get("grader_error"):     # killed by stop_all, not by the notebook
                raise Stopped(staged.file)
            if not run.get("grader_error") or cell is None or cell in killed or attempt == retries:
                break
            killed.append(cell)
            iso.cleanup(user, Path("/nonexistent"), token)
        if killed and not run.get("grader_error"):
            run["runner_killed"] = killed
        elif killed:
            run["grader_error"] += f" (also in a run without cell {', '.join(map(str, killed))})"
        return run
    finally:
        iso.cleanup(user, workdir, token)
        iso.release(user)


def _run_once(copy: Path, options, skip, user=None, workdir=None, token="") -> tuple:
    """(result dict, the cell that was running when the runner stopped or None)."""
    with tempfile.TemporaryDirectory(prefix="dhlab-grade-run-") as tmp:
        tmp = Path(tmp)
        result, pid_file, log = tmp / "result.json", tmp / "kernel.pid", tmp / "runner.log"
        progress = tmp / "progress"
        cmd = [sys.executable, "-B", str(RUNNER), str(copy), str(result),
               "--timeout", str(options.timeout), "--total-timeout", str(options.total_timeout),
               "--memory-mb", str(options.memory_mb), "--output-mb", str(options.output_mb),
               "--pid-file", str(pid_file), "--progress-file", str(progress), "--token", token]
        if workdir is not None:
            cmd += ["--workdir", str(workdir)]
        if user is not None:
            cmd += ["--uid", str(user[1]), "--gid", str(user[2])]
        for cell in skip:
            cmd += ["--skip", str(cell)]
        hard_limit = options.total_timeout + 150          # kernel starts and the answers' read
        env = dict(os.environ, TMPDIR=str(tmp), JUPYTER_RUNTIME_DIR=str(tmp / "runtime"),
                   PYTHONDONTWRITEBYTECODE="1")
        with open(log, "wb") as err:
            # TMPDIR: the runner's own files (connection file, kernel spec) land in this private
            # folder, which goes away even if the runner is killed
            with _RUNNING_LOCK:                   # stop_all sees every runner that starts
                if STOPPING.is_set():
                    return {"grader_error": "stopped before it started"}, None
                proc = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=err,
                                        start_new_session=True, env=env)
                _RUNNING[proc.pid] = proc
            try:
                proc.wait(timeout=hard_limit)
            except subprocess.TimeoutExpired:
                os.killpg(proc.pid, signal.SIGKILL)
                proc.wait()
            finally:
                with _RUNNING_LOCK:
                    _RUNNING.pop(proc.pid, None)
                _kill_kernel(pid_file)
                try:
                    os.killpg(proc.pid, signal.SIGKILL)          # whatever is left of the runner's session
                except (ProcessLookupError, PermissionError):
                    pass
        if result.exists():
            try:
                return json.loads(result.read_text(encoding="utf-8")), None
            except ValueError:
                pass
        try:
            cell = int(progress.read_text())
        except (OSError, ValueError):
            cell = None
        tail = log.read_bytes()[-300:].decode("utf-8", "replace").strip().splitlines()[-1:] if log.exists() else []
        why = (f"the runner did not finish in {hard_limit:.0f} s" if proc.returncode in (-9, None)
               else f"the runner stopped (exit code {proc.returncode})")
        if cell is not None:
            why += f" while running cell {cell}"
        return {"grader_error": why + (f": {tail[0][:150]}" if tail else "")}, cell
