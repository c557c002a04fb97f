"""Run one submitted notebook in a fresh, limited kernel and collect its answers as plain data.

The grader starts one runner process per submission::

    python dhlab/grading/run/runner.py NOTEBOOK RESULT.json [--timeout 30] [--total-timeout 120]
                                   [--memory-mb 2048] [--output-mb 10]
                                   [--uid U --gid G --workdir DIR --token T]
    (python -m dhlab.grading.run.runner ... works too)

What it does, and why:

1. Reads the notebook as JSON (a file that is not JSON, or not a notebook, is reported,
   not run).
2. Starts a **fresh kernel** through :mod:`dhlab.grading.run.sandbox`, which lowers the
   kernel's resource limits (memory, CPU, file size) before IPython starts and, with
   ``--uid``, makes the kernel an unprivileged user in its own mount namespace (the
   runner itself stays the grader's user, so the kernel cannot signal it or forge its
   result). The kernel's environment names no file of the grader: only an opaque
   ``DHLAB_GRADE_TOKEN``.
3. Runs every code cell in order, as the student would with "Run all". A cell that
   raises does not stop the others (its error is recorded). A cell that runs longer
   than ``--timeout`` seconds is interrupted. If the kernel dies, cannot be
   interrupted, or a cell prints more than ``--output-mb``, a new kernel runs the
   notebook again without that cell. All of it within ``--total-timeout`` seconds.
4. Asks the kernel to write the values of the answer names as JSON (the source of
   :func:`dhlab.assignment.encode.to_plain` is sent in, so a notebook that changed
   ``dhlab`` cannot change how its answers are read), and reads that file — never
   anything the notebook printed.
5. Writes what happened and the answers' JSON text to ``RESULT.json``. It scores
   nothing: the grader scores in its own process.

The outputs of the cells are counted, not kept.
"""
from __future__ import annotations

import argparse
import inspect
import json
import os
import queue
import re
import secrets
import shutil
import sys
import tempfile
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path

try:
    from ...assignment.encode import ANSWER_NAMES, MAX_JSON_BYTES, encode_json, to_plain
    from .notebook_code import (MAX_CODE_BYTES, MAX_NOTEBOOK_BYTES, NotebookError,  # noqa: F401 (API)
                                read_code_cells, scan_for_tampering)
    from .sandbox import MAX_PROCESSES, OUTPUT_LIMIT_NOTE, apply_limits
    from . import cgroups
except ImportError:      # started as a script by the grader (see RUNNER below): this folder is sys.path[0]
    sys.path.append(str(Path(__file__).resolve().parents[2] / "assignment"))      # for encode.py alone
    from encode import ANSWER_NAMES, MAX_JSON_BYTES, encode_json, to_plain
    from notebook_code import (MAX_CODE_BYTES, MAX_NOTEBOOK_BYTES, NotebookError,  # noqa: F401 (API)
                               read_code_cells, scan_for_tampering)
    from sandbox import MAX_PROCESSES, OUTPUT_LIMIT_NOTE, apply_limits
    import cgroups

__all__ = ["RunResult", "run_notebook", "read_code_cells", "scan_for_tampering", "main",
           "NotebookError", "MAX_NOTEBOOK_BYTES", "MAX_CODE_BYTES"]

# The grader starts this file, and the kernel's launcher, as scripts (python .../runner.py),
# not with -m: so these processes do not import the whole dhlab package (numpy, sympy, ...).
# That saves half a second per submission, and the only dhlab files they read from disk are
# runner.py, notebook_code.py, sandbox.py, cgroups.py and ../../assignment/encode.py; the grader checks
# the whole package unchanged.
RUNNER = Path(__file__).resolve()
SANDBOX = RUNNER.with_name("sandbox.py")
EXTRACT_SECONDS = 20
INTERRUPT_GRACE = 5
LOAD_EXTRA = 60                  # seconds a cell that waited for a CPU may run past its limit (at most 2 x it)
FLOOD_FACTOR = 3                 # output read past the cap before a cell is left out (see _Kernel.execute)
MAX_ATTEMPTS = 3
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
    return str(RUNNER.parents[3])


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


# --- the kernel ------------------------------------------------------------------------------

@dataclass
class _Cell:
    status: str = "ok"          # ok | error | timeout | output | dead | stuck
    stopped_for: str = ""       # timeout | output: why the runner interrupted it
    ename: str = ""
    evalue: str = ""
    output_bytes: int = 0
    capped_in_kernel: bool = False


class _Kernel:
    """A kernel started through the sandbox launcher, driven cell by cell."""

    def __init__(self, workdir: Path, private: Path, memory_mb: float, cpu_seconds: float, file_mb: float,
                 output_mb: float, pid_file: Path | None, token: str = "", user=None, group_dirs=()):
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

    def execute(self, code: str, limit: float, cap_bytes: int, silent: bool = False) -> _Cell:
        result = _Cell()
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

    def _stop(self, msg_id, result, why) -> _Cell:
        """Interrupt the running cell; 'stuck' if the kernel does not come back."""
        result.status = result.stopped_for = why
        try:
            self.km.interrupt_kernel()
        except Exception:
            pass
        end = time.monotonic() + INTERRUPT_GRACE
        while time.monotonic() < end:
            status = self._next(msg_id, 0.5, _Cell())
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


_WRITER = r"""
def write(path, names, namespace):
    out = {}
    for name in names:
        if name in namespace:
            try:
                out[name] = to_plain(namespace[name])
            except BaseException as e:
                out[name] = {"__type__": "unreadable", "repr": (type(e).__name__ + ": " + str(e))[:200]}
    with open(path, "w", encoding="utf-8") as f:
        f.write(encode_json(out))
"""


def _extract_code(path: Path) -> str:
    """The code the kernel runs to write the answers.

    :func:`to_plain`'s own source and a writer are executed in a fresh namespace with
    the real builtins, so a notebook that shadowed ``list`` or ``float`` (or changed
    dhlab) does not change how its answers are read.
    """
    source = inspect.getsource(to_plain) + "\n\n" + inspect.getsource(encode_json) + _WRITER
    return ("__dhlab_g = {'__builtins__': __import__('builtins')}\n"
            f"__import__('builtins').exec({source!r}, __dhlab_g)\n"
            f"__dhlab_g['write']({str(path)!r}, {list(ANSWER_NAMES)!r}, globals())\n"
            "del __dhlab_g\n")


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
            kernel = _Kernel(workdir, private, memory_mb, cpu_seconds=total_timeout + 60, file_mb=64,
                             output_mb=output_mb, pid_file=Path(pid_file) if pid_file else None, token=token,
                             user=user, group_dirs=group.dirs if group else ())
            try:
                if attempt == 0 and user is not None:
                    _describe_isolation(result, kernel.sandbox_missing(), workdir)
                broken = _run_cells(kernel, cells, skip, timeout, deadline, cap, result, attempt == 0, progress)
                if broken is None:
                    _extract(kernel, workdir, result)
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


def _extract(kernel, workdir: Path, result: RunResult) -> None:
    target = workdir / f"answers-{secrets.token_hex(8)}.json"
    cell = kernel.execute(_extract_code(target), EXTRACT_SECONDS, 1_000_000, silent=True)
    if cell.status not in ("ok",):
        result.answers_error = {"error": f"reading the answers failed in the kernel ({cell.ename}: {cell.evalue})",
                                "timeout": "reading the answers took too long",
                                "dead": "the kernel died while the answers were read",
                                "stuck": "the kernel hung while the answers were read"}.get(
                                    cell.status, f"reading the answers failed ({cell.status})")
        return
    # the kernel's own folder: never follow a link, never wait on a pipe, read a bounded amount
    try:
        fd = os.open(target, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK)
    except OSError:
        result.answers_error = "the kernel did not write the answers"
        return
    with os.fdopen(fd, "rb") as f:
        import stat
        if not stat.S_ISREG(os.fstat(f.fileno()).st_mode):
            result.answers_error = "the answers are not a plain file"
            return
        data = f.read(MAX_JSON_BYTES + 1)
    if len(data) > MAX_JSON_BYTES:
        result.answers_error = f"the answers are more than {MAX_JSON_BYTES} bytes"
        return
    result.answers_json = data.decode("utf-8", errors="replace")


def _die_with_the_grader() -> None:
    """End this runner when the grader that started it ends (``prctl(PR_SET_PDEATHSIG)``). A runner
    outliving a grader killed with ``kill -9`` would go on starting kernels as a user that the next
    grader may already have claimed, and end them in the middle of that grader's work."""
    import ctypes
    import ctypes.util
    import signal
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
