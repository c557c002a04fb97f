"""A student's kernel, started through the sandbox launcher and driven cell by cell.

The runner (:mod:`dhlab.grading.run.runner`) makes one :class:`Kernel` per attempt at a notebook. It
starts with an environment built from an allow-list (:func:`kernel_environment`), through
:mod:`dhlab.grading.run.sandbox`, which lowers its limits before IPython starts. :meth:`Kernel.execute`
runs one cell and says how it ended (a :class:`CellRun`): it interrupts a cell that runs past its time,
stops reading a flood of output, and notices a kernel that died. The outputs are counted, not kept.

Like the runner, this file is also imported as a plain script (no package): plain standard library
at module level, and its neighbours imported by their file names in that case.
"""
from __future__ import annotations

import json
import os
import queue
import re
import secrets
import sys
import time
from dataclasses import dataclass
from pathlib import Path

try:
    from .sandbox import OUTPUT_LIMIT_NOTE
except ImportError:      # imported by the runner started as a script: this folder is sys.path[0]
    from sandbox import OUTPUT_LIMIT_NOTE

__all__ = ["Kernel", "CellRun", "kernel_environment", "FLOOD_FACTOR", "LOAD_EXTRA", "KERNEL_START_SECONDS"]

SANDBOX = Path(__file__).resolve().with_name("sandbox.py")
INTERRUPT_GRACE = 5
LOAD_EXTRA = 60                  # seconds a cell that waited for a CPU may run past its limit (at most 2 x it)
FLOOD_FACTOR = 3                 # output read past the cap before a cell is left out (see Kernel.execute)
KERNEL_START_SECONDS = 120       # a loaded machine (two graders, load 10 on 2 cores) starts kernels slowly
TMP_MB = 64                      # the kernel's private /tmp and /dev/shm (tmpfs: counts as its memory)
# what the kernel may inherit of the grader's environment: the language, nothing else (no token,
# password or path of the teacher's reaches a student's code); values must look like a locale
PASSED_ENV = ("LANG", "LANGUAGE", "LC_ALL", "LC_CTYPE", "LC_MESSAGES", "LC_NUMERIC", "TZ", "DHLAB_LANGUAGE")
_LOCALE_LIKE = re.compile(r"[A-Za-z0-9_.:@/+-]{1,64}")


def kernel_environment(workdir: Path, token: str = "", environ=None) -> dict:
    """The whole environment of a student's kernel, built from an allow-list, never inherited.

    >>> env = kernel_environment(Path("/tmp/k"), environ={"LANG": "es_ES.UTF-8", "CANVAS_API_TOKEN": "xyz"})
    >>> env["LANG"], "CANVAS_API_TOKEN" in env, env["HOME"]
    ('es_ES.UTF-8', False, '/tmp/k')
    """
    environ = os.environ if environ is None else environ
    env = {k: environ[k] for k in PASSED_ENV if _LOCALE_LIKE.fullmatch(environ.get(k, ""))}
    env.update(PATH=os.pathsep.join([os.path.dirname(sys.executable), "/usr/local/bin", "/usr/bin", "/bin"]),
               # the kernel writes no compiled modules (dhlab's __pycache__ is part of its fingerprint)
               PYTHONDONTWRITEBYTECODE="1", PYTHONNOUSERSITE="1", PYTHONHASHSEED="0",
               OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1", MKL_NUM_THREADS="1", MPLBACKEND="agg",
               HOME=str(workdir), TMPDIR=str(workdir), IPYTHONDIR=str(workdir / ".ipython"),
               MPLCONFIGDIR=str(workdir / ".matplotlib"), JUPYTER_RUNTIME_DIR=str(workdir / ".runtime"),
               DHLAB_GRADE_TOKEN=token)      # which submission a kernel runs (ps, cleanup)
    dhlab_parent = _dhlab_parent()
    if dhlab_parent and dhlab_parent in environ.get("PYTHONPATH", "").split(os.pathsep):
        env["PYTHONPATH"] = dhlab_parent     # dhlab found only through PYTHONPATH: that entry alone
    return env


def _dhlab_parent() -> str:
    """The folder holding the dhlab package (three levels above this file: dhlab/grading/run/)."""
    return str(Path(__file__).resolve().parents[3])


@dataclass
class CellRun:
    """How one cell ended, and how much it printed."""
    status: str = "ok"          # ok | error | timeout | output | dead | stuck
    stopped_for: str = ""       # timeout | output: why the runner interrupted it
    ename: str = ""
    evalue: str = ""
    output_bytes: int = 0
    capped_in_kernel: bool = False


class Kernel:
    """A kernel started through the sandbox launcher, driven cell by cell."""

    def __init__(self, workdir: Path, private: Path, memory_mb: float, cpu_seconds: float, file_mb: float,
                 output_mb: float, pid_file: Path | None, token: str = "", user=None, group_dirs=()):
        # lazy: the grader imports this module for its names and starts no kernel (jupyter_client and
        # zmq take ~0.15 s); only the runner process does
        from jupyter_client import KernelManager
        from jupyter_client.kernelspec import KernelSpecManager

        spec_dir = private / ".kernels" / "dhlab-sandbox"
        spec_dir.mkdir(parents=True, exist_ok=True)
        argv = [sys.executable, "-B", str(SANDBOX), "--memory-mb", str(memory_mb),
                "--cpu-seconds", str(cpu_seconds), "--file-mb", str(file_mb), "--output-mb", str(output_mb)]
        self.report = workdir / f".sandbox-{secrets.token_hex(8)}"
        if user is not None:
            argv += ["--uid", str(user[0]), "--gid", str(user[1]), "--workdir", str(workdir),
                     "--tmp-mb", str(TMP_MB), "--report", str(self.report)]
            argv += [a for folder in group_dirs for a in ("--group", folder)]
        # outputs are counted, never kept: no pictures are rendered (text and HTML still count for floods)
        argv += ["--", "-f", "{connection_file}", "--DisplayFormatter.active_types=text/plain",
                 "--DisplayFormatter.active_types=text/html"]
        (spec_dir / "kernel.json").write_text(json.dumps(
            {"argv": argv, "display_name": "dhlab sandbox", "language": "python"}), encoding="utf-8")
        # Unix sockets in the kernel's own folder, not TCP ports: the kernel may have no network at all
        # (its own network namespace, sandbox.py), and no two kernels can ever pick the same port
        self.km = KernelManager(kernel_name="dhlab-sandbox", transport="ipc", ip=str(workdir / "kernel"),
                                kernel_spec_manager=KernelSpecManager(kernel_dirs=[str(spec_dir.parent)]))
        self.km.connection_file = str(private / f"connection-{secrets.token_hex(8)}.json")
        self.km.start_kernel(cwd=str(workdir), env=kernel_environment(workdir, token))
        self.pid = pid = getattr(getattr(self.km, "provisioner", None), "pid", None)
        if pid_file is not None and pid:
            pid_file.write_text(str(pid), encoding="utf-8")
        self.kc = self.km.client()
        self.kc.start_channels()
        self.kc.wait_for_ready(timeout=KERNEL_START_SECONDS)

    def sandbox_missing(self) -> list:
        """What the sandbox could not do for this kernel (it wrote it as root, before any cell ran)."""
        try:
            fd = os.open(self.report, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK)
        except OSError:
            return []
        with os.fdopen(fd, "rb") as f:
            return [line for line in f.read(4000).decode("utf-8", "replace").splitlines() if line]

    def waited(self) -> float:
        """Seconds the kernel process has spent waiting for a CPU (the scheduler's run-queue
        time, /proc/PID/schedstat); 0 where the system does not say."""
        try:
            with open(f"/proc/{self.pid}/schedstat", "rb") as f:
                return int(f.read().split()[1]) / 1e9
        except (OSError, ValueError, IndexError, TypeError):
            return 0.0

    def alive(self) -> bool:
        return bool(self.km.is_alive())

    def execute(self, code: str, limit: float, cap_bytes: int, silent: bool = False) -> CellRun:
        result = CellRun()
        try:
            msg_id = self.kc.execute(code, silent=silent, store_history=not silent, allow_stdin=False,
                                     stop_on_error=False)
        except Exception:
            result.status = "dead"
            return result
        start, waited = time.monotonic(), self.waited()
        while True:
            # the limit counts the time the cell ran or slept, not the time it waited for a CPU:
            # on a loaded machine (two graders, -j above the cores) a correct cell is not cut off
            # for the machine's slowness; the wall-clock time is bounded all the same (LOAD_EXTRA)
            wall = time.monotonic() - start
            left = min(limit - (wall - (self.waited() - waited)), limit + min(2 * limit, LOAD_EXTRA) - wall)
            if left <= 0:
                return self._stop(msg_id, result, "timeout")
            status = self._next(msg_id, min(left, 0.5), result)
            if status == "idle":
                return result
            if status == "dead":
                result.status = "dead"
                return result
            if result.output_bytes > FLOOD_FACTOR * cap_bytes:
                # far past the cap: the kernel is not capping this output (it is not print's), so
                # it still holds a backlog that would stall every later cell: a new kernel runs
                # the notebook without this cell
                result.status = result.stopped_for = "output"
                return result
            # up to then the flood only costs reading: the kernel drops a cell's print output
            # past the cap itself (sandbox.limit_output), so the cell goes on and its answers count

    def _next(self, msg_id, wait, result):
        """Read one message of the running cell: 'idle' when it is done, 'dead' when the
        kernel is gone or its messages are no longer readable, else None."""
        try:
            msg = self.kc.get_iopub_msg(timeout=wait)
        except queue.Empty:
            return None if self.alive() else "dead"
        except Exception:                  # e.g. the notebook replaced json inside the kernel
            return "dead"
        try:
            return self._handle(msg, msg_id, result)
        except Exception:
            return "dead"

    def _handle(self, msg, msg_id, result):
        if msg.get("parent_header", {}).get("msg_id") != msg_id:
            return None
        kind, content = msg["msg_type"], msg["content"]
        if kind == "stream":
            text = content.get("text", "")
            result.output_bytes += len(text)
            if OUTPUT_LIMIT_NOTE in text:                  # the kernel's own cap (sandbox.py)
                result.capped_in_kernel = True
        elif kind in ("display_data", "execute_result", "update_display_data"):
            result.output_bytes += sum(len(str(v)) for v in content.get("data", {}).values())
        elif kind == "error":
            if result.status == "ok":
                result.status = "error"
            result.ename = str(content.get("ename", ""))[:80]
            result.evalue = str(content.get("evalue", ""))[:200]
        elif kind == "status" and content.get("execution_state") == "idle":
            return "idle"
        return None

    def _stop(self, msg_id, result, why) -> CellRun:
        """Interrupt the running cell; 'stuck' if the kernel does not come back."""
        result.status = result.stopped_for = why
        try:
            self.km.interrupt_kernel()
        except Exception:
            pass
        end = time.monotonic() + INTERRUPT_GRACE
        while time.monotonic() < end:
            status = self._next(msg_id, 0.5, CellRun())
            if status == "idle":
                return result
            if status == "dead":
                result.status = "dead"
                return result
        result.status = "stuck"
        return result

    def shutdown(self):
        try:
            self.kc.stop_channels()
        except Exception:
            pass
        try:
            self.km.shutdown_kernel(now=True)
        except Exception:
            pass
