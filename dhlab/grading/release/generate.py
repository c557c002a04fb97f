"""Make the student notebook from the source (solutions) notebook, the way nbgrader does.

    python -m dhlab.grading.release.generate                      # in the course's repository: see below
    python -m dhlab.grading.release.generate SOURCE -o STUDENT
    python -m dhlab.grading.release.generate --check              # exit 1 if the student notebook is out of date

**The teacher's source notebook, with the solutions, is not in the package** (students install
it): it is ``tools/teacher/08_puma_assignment.ipynb`` in the course's repository, outside
``notebooks/``, so students never see it in the course's file browser either (``make lab``).
Run from that repository (its top folder or below), the defaults are the course's own files
(:func:`checkout`): the source is that notebook, and the student notebook is written twice, as
``notebooks/08_puma_assignment.ipynb`` and as ``dhlab/grading/template/08_puma_assignment.ipynb``
(:data:`TEMPLATE`, package data: what ``dhlab-assign`` starts from). Elsewhere name the source
(``SOURCE``, or ``--source`` of ``dhlab-grade``, whose self-check runs it): :func:`find_source`
says where to get it when it is missing.

The source notebook is marked exactly as for nbgrader, so a teacher who uses
nbgrader can drop it into ``source/<assignment>/`` and run ``nbgrader
generate_assignment`` instead:

* cell metadata ``metadata.nbgrader`` with the keys ``grade``, ``solution``, ``locked``,
  ``grade_id``, ``points`` (grade cells) and ``schema_version`` 3;
* in a solution cell, the lines from ``### BEGIN SOLUTION`` to ``### END SOLUTION``
  become the code stub (indented like the BEGIN line); a solution cell without them
  becomes the stub entirely (markdown: ``YOUR ANSWER HERE``);
* in a grade cell, the lines from ``### BEGIN HIDDEN TESTS`` to ``### END HIDDEN TESTS``
  are removed;
* a delimiter in a cell without that metadata is an error; outputs are cleared, but for the
  read-only cells that only show the robot (:data:`SHOWN`: its figure and tables, which depend on
  no answer), so the student sees the robot before running anything;
  solution cells become undeletable, grade and read-only cells also uneditable.

The notebook's ``language_info`` is cut to its name, so the student version does
not depend on the Python version the source was last run with.

One difference, on purpose: the code stub is ``# YOUR CODE HERE`` without nbgrader's
``raise NotImplementedError()``. The answer cells start with ``name = ...`` lines,
so the student notebook runs from top to bottom and each check says "not answered".
For the same result with nbgrader, set in ``nbgrader_config.py``::

    c.ClearSolutions.code_stub = {"python": "# YOUR CODE HERE"}

>>> cell = {"cell_type": "code", "source": "x = ...\\n### BEGIN SOLUTION\\nx = 7\\n### END SOLUTION",
...         "metadata": {"nbgrader": {"grade": False, "solution": True, "locked": False,
...                                   "grade_id": "a", "schema_version": 3}}, "outputs": []}
>>> student_cell(cell)["source"]
'x = ...\\n# YOUR CODE HERE'
"""
from __future__ import annotations

import argparse
import copy
import json
import re
import sys
from pathlib import Path

from ...errors import DHLabError
from ...i18n import N_, _

__all__ = ["CODE_STUB", "TEXT_STUB", "GenerateError", "SourceMissing", "clear_solutions", "remove_hidden_tests",
           "check_metadata", "student_cell", "student_notebook", "generate", "main",
           "NOTEBOOK", "TEMPLATE", "CHECKOUT_SOURCE", "CHECKOUT_STUDENTS", "checkout", "find_source"]

CODE_STUB = "# YOUR CODE HERE"
TEXT_STUB = "YOUR ANSWER HERE"
BEGIN_SOLUTION, END_SOLUTION = "BEGIN SOLUTION", "END SOLUTION"
BEGIN_HIDDEN, END_HIDDEN = "BEGIN HIDDEN TESTS", "END HIDDEN TESTS"
# read-only cells that only show the robot (its figure, its axes and points): the student sees
# their outputs before running anything (they depend on no answer); every other output is cleared
SHOWN = ("robot_figure", "axes_table", "points_table")
NBGRADER_KEYS = {"grade", "solution", "locked", "task", "grade_id", "points", "schema_version",
                 "checksum", "cell_type"}

NOTEBOOK = "08_puma_assignment.ipynb"
# the student notebook, shipped with the package (generated; equal to the course's notebooks/08_…)
TEMPLATE = Path(__file__).resolve().parents[1] / "template" / NOTEBOOK     # dhlab/grading/template/
# in the course's repository, from its top folder: the teacher's source notebook (with the solutions)
# and where the student notebook made from it goes (the course's notebook, the package's copy)
CHECKOUT_SOURCE = Path("tools") / "teacher" / NOTEBOOK
CHECKOUT_STUDENTS = (Path("notebooks") / NOTEBOOK, Path("dhlab") / "grading" / "template" / NOTEBOOK)
WHERE_TO_GET = N_("The teacher's source notebook (the assignment with its solutions) is not installed with dhlab, "
                "so that students never get it: it is {path} in the course's repository. Run this from a clone "
                "of the repository (git clone the course, then run from its folder), or give its path "
                "(dhlab-grade … --source PATH; python -m dhlab.grading.release.generate PATH -o STUDENT.ipynb): a "
                "teacher may keep a copy anywhere students cannot read it.")


class GenerateError(ValueError):
    """The source notebook is not marked up the way nbgrader expects."""


class SourceMissing(DHLabError):
    """The teacher's source notebook cannot be found (the message says where to get it)."""


def checkout(start=None):
    """The top folder of the course's repository that holds ``start`` (default: the current folder),
    found by its teacher's notebook (:data:`CHECKOUT_SOURCE`); None outside a checkout."""
    here = Path(start if start is not None else Path.cwd()).resolve()
    return next((folder for folder in (here, *here.parents) if (folder / CHECKOUT_SOURCE).is_file()), None)


def find_source(path=None) -> Path:
    """The teacher's source notebook: ``path`` when given, else the checkout's (run from the course's
    repository); :class:`SourceMissing`, saying where to get it, when there is none."""
    if path is not None:
        if not Path(path).is_file():
            raise SourceMissing(_("no notebook at {path!r}.").format(path=str(path)) + " "
                                + _(WHERE_TO_GET).format(path=CHECKOUT_SOURCE))
        return Path(path)
    top = checkout()
    if top is None:
        raise SourceMissing(_(WHERE_TO_GET).format(path=CHECKOUT_SOURCE))
    return top / CHECKOUT_SOURCE


def _source(cell) -> str:
    source = cell.get("source", "")
    return "".join(source) if isinstance(source, list) else source


def _cut_regions(source: str, begin: str, end: str, what: str, stub=None) -> tuple:
    """Cut every ``begin`` … ``end`` region out of one cell's text, putting ``stub`` (indented
    like the begin line) in its place when given: (new text, whether a region was found)."""
    out, inside, found = [], False, False
    for line in source.split("\n"):
        if begin in line:
            if inside:
                raise GenerateError(f"nested BEGIN {what}")
            inside = found = True
            if stub is not None:
                indent = re.match(r"\s*", line).group(0)
                out += [indent + s for s in stub.split("\n")]
        elif end in line:
            inside = False
        elif not inside:
            out.append(line)
    if inside:
        raise GenerateError(f"BEGIN {what} without END {what}")
    return "\n".join(out), found


def clear_solutions(source: str, stub: str) -> tuple:
    """nbgrader's ClearSolutions on one cell's text: (new text, whether a region was replaced)."""
    return _cut_regions(source, BEGIN_SOLUTION, END_SOLUTION, "SOLUTION", stub)


def remove_hidden_tests(source: str) -> tuple:
    """nbgrader's ClearHiddenTests on one cell's text: (new text, whether a region was removed)."""
    return _cut_regions(source, BEGIN_HIDDEN, END_HIDDEN, "HIDDEN TESTS")


def check_metadata(cells) -> None:
    """The checks of nbgrader's schema 3 (CheckCellMetadata), with a clear message."""
    ids = set()
    for number, cell in enumerate(cells, start=1):
        meta = cell.get("metadata", {}).get("nbgrader")
        if meta is None:
            continue
        where = f"cell {number}"
        unknown = set(meta) - NBGRADER_KEYS
        missing = {"grade", "solution", "locked", "schema_version"} - set(meta)
        if unknown or missing:
            raise GenerateError(f"{where}: nbgrader metadata has unknown keys {sorted(unknown)} "
                                f"or lacks {sorted(missing)}")
        if meta["schema_version"] != 3:
            raise GenerateError(f"{where}: schema_version must be 3")
        if meta["grade"] or meta["solution"] or meta["locked"]:
            gid = meta.get("grade_id")
            if not isinstance(gid, str) or not re.fullmatch(r"[A-Za-z0-9_-]+", gid):
                raise GenerateError(f"{where}: grade_id must match [A-Za-z0-9_-]+, got {gid!r}")
            if gid in ids:
                raise GenerateError(f"{where}: grade_id {gid!r} is used twice")
            ids.add(gid)
        if meta["grade"] and not isinstance(meta.get("points"), (int, float)):
            raise GenerateError(f"{where}: a grade cell needs points")
        if meta["grade"] and cell["cell_type"] == "markdown" and not meta["solution"]:
            raise GenerateError(f"{where}: a markdown grade cell must also be a solution cell")


def student_cell(cell: dict) -> dict:
    """The student's version of one cell (a new dict)."""
    cell = copy.deepcopy(cell)
    meta = cell.get("metadata", {}).get("nbgrader", {})
    is_solution, is_grade = bool(meta.get("solution")), bool(meta.get("grade"))
    is_locked = bool(meta.get("locked")) and not is_solution
    stub = CODE_STUB if cell["cell_type"] == "code" else TEXT_STUB
    source, replaced = clear_solutions(_source(cell), stub)
    if replaced and not is_solution:
        raise GenerateError("a solution region in a cell that is not a solution cell:\n" + _source(cell)[:200])
    if is_solution and not replaced:
        source = stub
    source, removed = remove_hidden_tests(source)
    if removed and not is_grade:
        raise GenerateError("a hidden-tests region in a cell that is not a grade cell:\n" + _source(cell)[:200])
    cell["source"] = source
    if cell["cell_type"] == "code" and not (meta.get("grade_id") in SHOWN and is_locked and not is_grade):
        cell["outputs"] = []
    if cell["cell_type"] == "code":
        cell["execution_count"] = None
    cell.get("metadata", {}).pop("execution", None)
    if is_solution or is_grade or is_locked:                   # nbgrader's LockCells
        cell["metadata"]["deletable"] = False
        if (is_grade or is_locked) and not is_solution:
            cell["metadata"]["editable"] = False
    return cell


def student_notebook(nb: dict) -> dict:
    """The student's version of a whole notebook (a new dict)."""
    check_metadata(nb["cells"])
    out = copy.deepcopy(nb)
    out["cells"] = [student_cell(c) for c in nb["cells"]]
    code = [c for c in out["cells"] if c["cell_type"] == "code"]
    for k, cell in enumerate(code, start=1):      # a shown output carries the count Run All gives it
        if cell.get("outputs"):
            cell["execution_count"] = k
    meta = out.setdefault("metadata", {})
    meta.pop("widgets", None)
    # what running the source wrote (the Python version...) is not part of the assignment
    meta["language_info"] = {"name": meta.get("language_info", {}).get("name", "python")}
    return out


def _dumps(nb: dict) -> str:
    """The file text, as nbformat writes it (so a generated notebook is byte-stable)."""
    import nbformat
    return nbformat.writes(nbformat.from_dict(nb))


def generate(source, student, check: bool = False) -> bool:
    """Write the student notebook (or, with ``check``, only compare). True if it is up to date."""
    nb = json.loads(Path(source).read_text(encoding="utf-8"))
    text = _dumps(student_notebook(nb))
    student = Path(student)
    current = student.read_text(encoding="utf-8") if student.exists() else None
    if check:
        return current == text
    if current != text:
        student.write_text(text, encoding="utf-8")
    return True


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("source", nargs="?", type=Path, default=None,
                        help=f"the teacher's source notebook (default: {CHECKOUT_SOURCE} of the course's "
                             "repository, when run from it)")
    parser.add_argument("-o", "--output", type=Path, default=None,
                        help="the student notebook (default, for the course's source: "
                             f"{' and '.join(map(str, CHECKOUT_STUDENTS))}; required for any other source)")
    parser.add_argument("--check", action="store_true", help="only check that the student notebook is up to date")
    args = parser.parse_args(argv)
    top = checkout() if args.source is None else None
    if args.output is None and top is None:
        if args.source is None:
            print(f"generate: {_(WHERE_TO_GET).format(path=CHECKOUT_SOURCE)}", file=sys.stderr)
            return 2
        parser.error("give -o STUDENT.ipynb for a source other than the course's")
    source = args.source or top / CHECKOUT_SOURCE
    outputs = [args.output] if args.output else [top / path for path in CHECKOUT_STUDENTS]
    failed = 0
    for output in outputs:
        try:
            ok = generate(source, output, check=args.check)
        except GenerateError as e:
            print(f"{source}: {e}", file=sys.stderr)
            return 2
        if args.check and not ok:
            print(f"{output} is out of date: run python -m dhlab.grading.release.generate", file=sys.stderr)
            failed = 1
        else:
            print(f"{output} {'is up to date' if args.check else 'written'}")
    return failed


if __name__ == "__main__":
    sys.exit(main())
