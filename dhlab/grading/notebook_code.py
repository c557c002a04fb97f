"""A submitted notebook as code: its code cells, read with limits, and what it does to dhlab.

The runner (:mod:`dhlab.grading.runner`) reads the submission with :func:`read_code_cells`
before it starts a kernel: a file that is not JSON, not a notebook, or holds more code than
:data:`MAX_CODE_BYTES`, is reported and not run. :func:`scan_for_tampering` lists what the
code does to dhlab (the grader checks in its own process; the teacher sees it in the status).
The staging of a class (:mod:`dhlab.grading.staging`) reads the notebooks the same way.

Like the runner, this file is also imported as a plain script (no package), so it uses
the standard library only (its messages are translated when it is imported from the package,
by the grader, as the teacher's language: :mod:`dhlab.grading.language`).
"""
from __future__ import annotations

import ast
import json
from pathlib import Path

try:
    from .language import _
except ImportError:          # loaded as a plain script by the runner: its messages stay English there
    def _(message: str) -> str:
        return message

__all__ = ["NotebookError", "read_code_cells", "scan_for_tampering", "MAX_NOTEBOOK_BYTES", "MAX_CODE_BYTES"]

MAX_NOTEBOOK_BYTES = 500_000_000      # a file this big is not read at all
MAX_CODE_BYTES = 1_000_000            # the code of all cells (outputs do not count: they are dropped)


class NotebookError(Exception):
    """The file cannot be run as a notebook (the message says why)."""


def read_code_cells(path=None, raw: bytes | None = None) -> list:
    """[(cell number, source)] of the code cells, numbered 1… over all cells as in Jupyter.

    Outputs are ignored (they are not the submission); the code itself may be at most
    :data:`MAX_CODE_BYTES`.
    """
    if raw is None:
        path = Path(path)
        size = path.stat().st_size
        if size > MAX_NOTEBOOK_BYTES:
            raise NotebookError(_("the file is {size} MB, more than {limit} MB").format(
                size=f"{size / 1e6:.1f}", limit=f"{MAX_NOTEBOOK_BYTES / 1e6:.0f}"))
        raw = path.read_bytes()
    try:
        nb = json.loads(raw.decode("utf-8"))
    except UnicodeDecodeError:
        raise NotebookError(_("not a notebook: the file is not UTF-8 text")) from None
    except (ValueError, RecursionError) as e:
        raise NotebookError(_("not a notebook: the file is not valid JSON ({error})").format(error=str(e)[:80])) from None
    cells = nb.get("cells") if isinstance(nb, dict) else None
    if isinstance(nb, dict) and cells is None and isinstance(nb.get("worksheets"), list):   # nbformat 3
        cells = [c for ws in nb["worksheets"] if isinstance(ws, dict) for c in ws.get("cells", [])]
    if not isinstance(cells, list):
        raise NotebookError(_("not a notebook: no list of cells"))
    out = []
    for number, cell in enumerate(cells, start=1):
        if not isinstance(cell, dict) or cell.get("cell_type") != "code":
            continue
        source = cell.get("source", cell.get("input", ""))      # 'input' in nbformat 3
        if isinstance(source, list):
            source = "".join(s for s in source if isinstance(s, str))
        if not isinstance(source, str):
            raise NotebookError(_("cell {number} has no readable source").format(number=number))
        out.append((number, source))
    code = sum(len(source.encode("utf-8", "replace")) for _number, source in out)
    if code > MAX_CODE_BYTES:
        raise NotebookError(_("code too large: the code cells hold {size} MB of code, more than {limit} MB (outputs "
                              "do not count)").format(size=f"{code / 1e6:.1f}", limit=f"{MAX_CODE_BYTES / 1e6:g}"))
    return out


_DHLAB_CHECK_NAMES = {"check_part", "check_part1", "check_part2", "check_part3", "check_all",
                      "Feedback", "to_plain", "parse_answers", "answers_from_namespace"}


def scan_for_tampering(cells) -> list:
    """What the notebook's code does to dhlab: assignments to attributes of dhlab
    modules, ``setattr`` on them, ``sys.modules`` entries, redefined check functions.

    It changes nothing (the grader checks in its own process); the teacher sees it
    in the status.

    >>> scan_for_tampering([(3, "import dhlab.course.assignment as A\\nA.check_part1 = lambda ns: 'all right'")])
    ['cell 3: assigns A.check_part1']
    """
    found = []
    dhlab_names = set()
    for number, source in cells:
        code = "\n".join("" if line.lstrip().startswith(("%", "!")) else line for line in source.splitlines())
        try:
            tree = ast.parse(code)
        except (SyntaxError, ValueError, RecursionError, MemoryError):
            continue
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                for alias in node.names:
                    if alias.name.split(".")[0] == "dhlab":
                        dhlab_names.add((alias.asname or alias.name).split(".")[0])
            elif isinstance(node, ast.ImportFrom) and (node.module or "").split(".")[0] == "dhlab":
                for alias in node.names:
                    dhlab_names.add(alias.asname or alias.name)
        for node in ast.walk(tree):
            targets = []
            if isinstance(node, (ast.Assign, ast.AugAssign, ast.AnnAssign)):
                targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
                if node.name in _DHLAB_CHECK_NAMES and node.name in dhlab_names:
                    found.append(f"cell {number}: redefines {node.name}")
            elif (isinstance(node, ast.Call) and isinstance(node.func, ast.Name)
                  and node.func.id in ("setattr", "delattr") and node.args
                  and _root(node.args[0]) in dhlab_names | {"dhlab"}):
                found.append(f"cell {number}: {node.func.id} on {ast.unparse(node.args[0])[:40]}")
            for target in targets:
                for t in (target.elts if isinstance(target, ast.Tuple) else [target]):
                    text = ast.unparse(t)[:60]
                    if isinstance(t, ast.Attribute) and _root(t) in dhlab_names | {"dhlab"}:
                        found.append(f"cell {number}: assigns {text}")
                    elif isinstance(t, ast.Subscript) and "sys.modules" in ast.unparse(t.value):
                        found.append(f"cell {number}: assigns {text}")
                    elif isinstance(t, ast.Name) and t.id in _DHLAB_CHECK_NAMES and t.id in dhlab_names:
                        found.append(f"cell {number}: redefines {t.id}")
    return found[:10]


def _root(node):
    while isinstance(node, (ast.Attribute, ast.Subscript, ast.Call)):
        node = node.func if isinstance(node, ast.Call) else node.value
    return node.id if isinstance(node, ast.Name) else None
