"""How the runner reads a notebook's answers out of its kernel: as JSON written by code it sends in.

After the cells ran, the runner (:mod:`dhlab.grading.run.runner`) asks the kernel to write the values
of the answer names as JSON (:func:`answer_code`), then reads that file (:func:`read_answers`) — never
anything the notebook printed. The code sent in carries the source of
:func:`dhlab.assignment.encode.to_plain` and :func:`~dhlab.assignment.encode.encode_json`, run with the
real builtins, so a notebook that changed ``dhlab``, ``list`` or ``float`` cannot change how its
answers are read.

>>> "def to_plain(" in answer_code(Path("/tmp/answers.json"))
True
"""
from __future__ import annotations

import inspect
import os
import secrets
import stat
import sys
from pathlib import Path

try:
    from ...assignment.encode import ANSWER_NAMES, MAX_JSON_BYTES, encode_json, to_plain
except ImportError:      # imported by the runner started as a script: dhlab is not a package there
    sys.path.append(str(Path(__file__).resolve().parents[2] / "assignment"))      # for encode.py alone
    from encode import ANSWER_NAMES, MAX_JSON_BYTES, encode_json, to_plain

__all__ = ["answer_code", "read_answers", "EXTRACT_SECONDS"]

EXTRACT_SECONDS = 20

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


def answer_code(path: Path) -> str:
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


def read_answers(kernel, workdir: Path, result) -> None:
    """Have ``kernel`` write its answers into ``workdir`` and put their JSON text in ``result.answers_json``
    (or what went wrong in ``result.answers_error``: ``result`` is the runner's RunResult)."""
    target = workdir / f"answers-{secrets.token_hex(8)}.json"
    cell = kernel.execute(answer_code(target), EXTRACT_SECONDS, 1_000_000, silent=True)
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
        if not stat.S_ISREG(os.fstat(f.fileno()).st_mode):
            result.answers_error = "the answers are not a plain file"
            return
        data = f.read(MAX_JSON_BYTES + 1)
    if len(data) > MAX_JSON_BYTES:
        result.answers_error = f"the answers are more than {MAX_JSON_BYTES} bytes"
        return
    result.answers_json = data.decode("utf-8", errors="replace")
