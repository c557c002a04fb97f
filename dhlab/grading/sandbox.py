"""Start an IPython kernel inside resource limits (the grader's kernels run this).

The grader's runner starts each student kernel as::

    python .../dhlab/grading/sandbox.py --memory-mb 2048 --cpu-seconds 300 --file-mb 64 --output-mb 10 \\
        -- -f CONNECTION_FILE

Before IPython starts, this process lowers its own limits with
:func:`resource.setrlimit`; the kernel inherits them:

* ``RLIMIT_AS`` (address space): an allocation beyond it fails with ``MemoryError``
  in the student's cell instead of eating the machine's memory;
* ``RLIMIT_CPU``: a backstop that ends a kernel still spinning long after the
  grader stopped waiting for it (the runner's wall-clock limit acts first);
* ``RLIMIT_FSIZE``: a file the notebook writes cannot grow past the limit (the write
  fails with an error; ``SIGXFSZ`` is ignored so the kernel is not killed);
* ``RLIMIT_CORE`` 0: a crash leaves no core file.

Soft and hard limits are set equal, so an ordinary user's code cannot raise them
again. (A process running as root can: grade untrusted work as an unprivileged
user, or in a container, for real isolation.)

It also caps what one cell may print (``--output-mb``): beyond it, the kernel drops the
cell's further ``print`` output and says so once (:data:`OUTPUT_LIMIT_NOTE`). Without
that, a cell printing in a loop makes the kernel buffer output faster than it can send
it, until the buffer exhausts the memory limit.
"""
from __future__ import annotations

import argparse
import os
import resource
import signal
import sys

__all__ = ["apply_limits", "limit_output", "OUTPUT_LIMIT_NOTE", "main"]

MB = 1024 * 1024
OUTPUT_LIMIT_NOTE = "[dhlab grader: output limit reached; the rest of this cell's output is dropped]"


def apply_limits(memory_mb: float | None, cpu_seconds: float | None, file_mb: float | None) -> None:
    """Lower this process's resource limits (None leaves a limit as it is)."""
    def lower(kind, value):
        soft, hard = resource.getrlimit(kind)
        value = int(value)
        if hard != resource.RLIM_INFINITY:
            value = min(value, hard)
        resource.setrlimit(kind, (value, value))

    if memory_mb:
        lower(resource.RLIMIT_AS, memory_mb * MB)
    if cpu_seconds:
        lower(resource.RLIMIT_CPU, cpu_seconds)
    if file_mb:
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        lower(resource.RLIMIT_FSIZE, file_mb * MB)
    lower(resource.RLIMIT_CORE, 0)


def limit_output(max_bytes: int) -> None:
    """Make the kernel's stdout/stderr drop a cell's output beyond ``max_bytes`` characters."""
    from ipykernel import iostream

    write = iostream.OutStream.write
    counts = {}                                   # characters written, for the running cell only

    def limited_write(self, string):
        if not isinstance(string, str):
            return write(self, string)            # ipykernel's own error for a wrong type
        try:
            cell = (self.parent_header or {}).get("msg_id")
        except Exception:
            cell = None
        if cell not in counts:
            counts.clear()
            counts[cell] = 0
        before = counts[cell]
        counts[cell] = before + len(string)
        if before > max_bytes:
            return len(string)
        if counts[cell] > max_bytes:
            write(self, "\n" + OUTPUT_LIMIT_NOTE + "\n")
            return len(string)
        return write(self, string)

    iostream.OutStream.write = limited_write


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--memory-mb", type=float, default=None)
    parser.add_argument("--cpu-seconds", type=float, default=None)
    parser.add_argument("--file-mb", type=float, default=None)
    parser.add_argument("--output-mb", type=float, default=None)
    parser.add_argument("kernel_args", nargs=argparse.REMAINDER,
                        help="arguments for ipykernel, after --")
    args = parser.parse_args(argv)
    rest = args.kernel_args[1:] if args.kernel_args[:1] == ["--"] else args.kernel_args
    apply_limits(args.memory_mb, args.cpu_seconds, args.file_mb)
    if args.output_mb:
        limit_output(int(args.output_mb * 1e6))
    # started as a script, this folder is sys.path[0]; a kernel started with -m has '' (its cwd)
    here = os.path.dirname(os.path.abspath(__file__))
    sys.path[:] = [""] + [p for p in sys.path if p and os.path.abspath(p) != here]
    from ipykernel import kernelapp
    sys.argv = [sys.argv[0], *rest]
    kernelapp.launch_new_instance()


if __name__ == "__main__":
    main()
