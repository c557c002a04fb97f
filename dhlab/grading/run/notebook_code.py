"""A submitted notebook as code: its code cells, read with limits, and what it does to dhlab.

The runner (:mod:`dhlab.grading.run.runner`) reads the submission with :func:`read_code_cells`
before it starts a kernel: a file that is not JSON, not a notebook, holds a cell whose source
is not text, or more code than :data:`MAX_CODE_BYTES`, is reported and not run. A file is
measured before its JSON is read (:func:`check_notebook_bytes`), so that one crafted file
cannot take all the grader's memory. :func:`scan_for_tampering` lists what the
code does to dhlab (the grader checks in its own process; the teacher sees it in the status).
The staging of a class (:mod:`dhlab.grading.run.staging`) reads the notebooks the same way.

Like the runner, this file is also imported as a plain script (no package), so it uses
the standard library only (its messages are translated when it is imported from the package,
by the grader, as the teacher's language: :mod:`dhlab.i18n`).
"""
from __future__ import annotations

import ast
import json
import re
from pathlib import Path

try:
    from ...i18n import _
except ImportError:          # loaded as a plain script by the runner: its messages stay English there
    def _(message: str) -> str:
        return message

__all__ = ["NotebookError", "read_code_cells", "read_notebook_bytes", "read_notebook_json", "check_notebook_bytes",
           "code_cells_of", "memory_to_read", "scan_for_tampering", "MAX_NOTEBOOK_BYTES", "MAX_JSON_VALUES",
           "MAX_READ_BYTES", "MAX_CODE_BYTES"]

# What one file may cost the grader. Python's JSON reader needs far more memory than the file
# (a 198 MB file of ``[],[],…`` needs about 5 GB; one emoji makes Python keep the text at 4 bytes
# a character), so the file is measured before it is read (check_notebook_bytes): at most
# MAX_NOTEBOOK_BYTES (a notebook of this course is a few MB, with its outputs), at most
# MAX_JSON_VALUES commas and brackets (each ends or starts one JSON value), and at most
# MAX_READ_BYTES of memory by an upper estimate (memory_to_read).
MAX_NOTEBOOK_BYTES = 100_000_000      # a bigger file is not read at all
MAX_JSON_VALUES = 1_000_000           # a real notebook of the course holds a few thousand
MAX_READ_BYTES = 600_000_000          # the memory reading one file may take
_BYTES_PER_VALUE = 100                # a JSON value in Python: an object and its place in a list or dict
_WIDE_ESCAPE = re.compile(rb"\\u[dD][89abAB]")        # '\ud83d': a character beyond U+FFFF, 4 bytes each
_MEDIUM_ESCAPE = re.compile(rb"\\u(?!00)")             # '\u2192': beyond U+00FF, 2 bytes each
MAX_CODE_BYTES = 1_000_000            # the code of all cells (outputs do not count: they are dropped)


class NotebookError(Exception):
    """The file cannot be run as a notebook (the message says why)."""


def _clear_outputs() -> str:
    return _("its saved outputs make it big: clear them (Edit → Clear Outputs of All Cells), save the notebook "
             "and hand it in again")


def _too_big(size: int) -> NotebookError:
    return NotebookError(_("the file is {size} MB, more than {limit} MB").format(
        size=f"{size / 1e6:.1f}", limit=f"{MAX_NOTEBOOK_BYTES / 1e6:.0f}") + "; " + _clear_outputs())


def read_notebook_bytes(path) -> bytes:
    """The bytes of the file at ``path``; a file over :data:`MAX_NOTEBOOK_BYTES` is refused
    before it is read (and never more than that is read, should it grow meanwhile)."""
    path = Path(path)
    size = path.stat().st_size
    if size > MAX_NOTEBOOK_BYTES:
        raise _too_big(size)
    with open(path, "rb") as f:
        raw = f.read(MAX_NOTEBOOK_BYTES + 1)
    if len(raw) > MAX_NOTEBOOK_BYTES:
        raise _too_big(len(raw))
    return raw


def check_notebook_bytes(raw: bytes) -> None:
    """Refuse (:class:`NotebookError`) a file whose JSON would need too much memory to read:
    over :data:`MAX_NOTEBOOK_BYTES`, or holding more than :data:`MAX_JSON_VALUES` values (counted
    from its commas and brackets, an upper bound, without reading the JSON)."""
    if len(raw) > MAX_NOTEBOOK_BYTES:
        raise _too_big(len(raw))
    values = _json_values(raw)
    if values > MAX_JSON_VALUES:
        raise NotebookError(_("the file holds about {count} JSON values, more than {limit} (a notebook of this "
                              "assignment holds a few thousand)").format(count=values, limit=MAX_JSON_VALUES)
                            + "; " + _clear_outputs())
    needed = memory_to_read(raw)
    if needed > MAX_READ_BYTES:
        raise NotebookError(_("reading the file would take about {size} MB of memory, more than {limit} MB").format(
            size=f"{needed / 1e6:.0f}", limit=f"{MAX_READ_BYTES / 1e6:.0f}") + "; " + _clear_outputs())


def _json_values(raw: bytes) -> int:
    """An upper bound of the values in a JSON text: each but the first follows a comma or opens a container."""
    return raw.count(b",") + raw.count(b"[") + raw.count(b"{") + 1


def _text_width(raw: bytes) -> int:
    """The bytes a character of the widest text the JSON makes: 1, 2 or 4 (fast searches, no decoding)."""
    wide = not raw.isascii() and any(bytes([lead]) in raw for lead in range(0xF0, 0xF5))   # 4-byte UTF-8
    if wide or _WIDE_ESCAPE.search(raw):
        return 4
    medium = not raw.isascii() and any(bytes([lead]) in raw for lead in range(0xC4, 0xF0))   # U+0100…U+FFFF
    return 2 if medium or _MEDIUM_ESCAPE.search(raw) else 1


def memory_to_read(raw: bytes) -> int:
    """An upper estimate of the memory ``json.loads`` of this file takes: the bytes, their text and its
    strings (1, 2 or 4 bytes a character: Python stores a text at the width of its widest character),
    and every value."""
    width = _text_width(raw)
    return len(raw) * (1 + 2 * width) + _json_values(raw) * _BYTES_PER_VALUE


def read_notebook_json(raw: bytes, checked: bool = False):
    """The JSON value of a notebook file's bytes, read with bounded memory
    (:func:`check_notebook_bytes` first, unless the caller ``checked`` them); :class:`NotebookError`
    when it is not UTF-8 JSON."""
    if not checked:
        check_notebook_bytes(raw)
    try:
        return json.loads(raw.decode("utf-8"))
    except UnicodeDecodeError:
        raise NotebookError(_("not a notebook: the file is not UTF-8 text")) from None
    except RecursionError:
        raise NotebookError(_("not a notebook: its JSON is nested too deeply to read")) from None
    except ValueError as e:
        raise NotebookError(_("not a notebook: the file is not valid JSON ({error})").format(
            error=str(e)[:80])) from None


def read_code_cells(path=None, raw: bytes | None = None) -> list:
    """[(cell number, source)] of the code cells, numbered 1… over all cells as in Jupyter.

    Outputs are ignored (they are not the submission); the code itself may be at most
    :data:`MAX_CODE_BYTES`.
    """
    if raw is None:
        raw = read_notebook_bytes(path)
    return code_cells_of(read_notebook_json(raw))


def code_cells_of(nb) -> list:
    """:func:`read_code_cells` of a notebook's JSON value (a dict, nbformat 3 or 4)."""
    cells = nb.get("cells") if isinstance(nb, dict) else None
    if isinstance(nb, dict) and cells is None and isinstance(nb.get("worksheets"), list):   # nbformat 3
        cells = [c for ws in nb["worksheets"] if isinstance(ws, dict) for c in ws.get("cells", [])]
    if not isinstance(cells, list):
        raise NotebookError(_("not a notebook: no list of cells"))
    out = []
    for number, cell in enumerate(cells, start=1):
        if not isinstance(cell, dict) or cell.get("cell_type") != "code":
            continue
        out.append((number, _cell_source(cell, number)))
    code = sum(len(source.encode("utf-8", "replace")) for _number, source in out)
    if code > MAX_CODE_BYTES:
        raise NotebookError(_("code too large: the code cells hold {size} MB of code, more than {limit} MB (outputs "
                              "do not count)").format(size=f"{code / 1e6:.1f}", limit=f"{MAX_CODE_BYTES / 1e6:g}"))
    return out


def _cell_source(cell: dict, number: int) -> str:
    """The code of a code cell: its source, a string or a list of strings (lines) as Jupyter
    writes it. Anything else is refused with the cell's number, never dropped: Jupyter itself
    does not open such a file, and a notebook run without one of its cells would be graded as
    if the student had not written it."""
    source = cell.get("source", cell.get("input", ""))      # 'input' in nbformat 3
    if isinstance(source, str):
        return source
    if not isinstance(source, list):
        raise NotebookError(_("cell {number} cannot be read: its source is {what}, not text (a string or a list of "
                              "strings, as Jupyter saves it); open the notebook in Jupyter, save it and hand it in "
                              "again").format(number=number, what=_json_kind(source)))
    for line, part in enumerate(source, start=1):
        if not isinstance(part, str):
            raise NotebookError(_("cell {number} cannot be read: line {line} of its source is {what}, not text (a "
                                  "string, as Jupyter saves it); open the notebook in Jupyter, save it and hand it "
                                  "in again").format(number=number, line=line, what=_json_kind(part)))
    return "".join(source)


def _json_kind(value) -> str:
    """'a number (5)', 'an object (a dict)', 'null': what a JSON value is, for a message."""
    if value is None:
        return "null"
    if isinstance(value, bool):
        return _("true/false ({value})").format(value=json.dumps(value))
    if isinstance(value, (int, float)):
        return _("a number ({value})").format(value=str(value)[:20])
    if isinstance(value, dict):
        return _("an object (a dict)")
    return _("a list")


_DHLAB_CHECK_NAMES = {"check_part", "check_part1", "check_part2", "check_part3", "check_all",
                      "Feedback", "PartReport", "to_plain", "parse_answers", "answers_from_namespace"}


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
