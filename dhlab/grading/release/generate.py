"""The student notebook, and the solved notebook nbgrader calls the source, the way nbgrader makes them.

    python -m dhlab.grading.release.generate                      # in the course's repository: see below
    python -m dhlab.grading.release.generate SOLVED               # ... the student notebook from SOLVED
    python -m dhlab.grading.release.generate SOURCE -o STUDENT    # a teacher's own source notebook
    python -m dhlab.grading.release.generate --solved OUT         # the solved notebook, computed
    python -m dhlab.grading.release.generate --check              # exit 1 if a student notebook is out of date

**No file of the course holds the teacher's solutions** (students install the course by cloning
its repository): the course keeps the student notebook, ``notebooks/08_puma_assignment.ipynb``,
and its copy in the package, ``dhlab/grading/template/08_puma_assignment.ipynb`` (:data:`TEMPLATE`:
what ``dhlab-assign`` starts from). The solved notebook is computed from the reference robot
when it is needed (:func:`dhlab.assignment.solution.solved_notebook`; :func:`solution_notebook`):
by the grader's self-check, by ``dhlab-assign solutions``, by ``make notebooks``. Run from the
course's repository (its top folder or below: :func:`checkout`), this module writes the student
notebook twice, the course's and the package's copy (:data:`CHECKOUT_STUDENTS`): from ``SOLVED``
when given (``make notebooks`` passes the solved notebook it has just executed, so the figure and
tables the student sees are what the code draws), else from the course's own notebook (its text
edited by hand: the copies are made equal and tidy). ``--check`` says whether both copies are what
that run would write. A teacher who keeps their own source notebook names it (``SOURCE -o
STUDENT``; ``--source`` of ``dhlab-grade``); :func:`find_source` reads it, or computes the PUMA's.

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

A Spanish source notebook (its set-up cell says ``dhlab.set_language("es")``) gets the Spanish stub,
``# ESCRIBA SU CÓDIGO AQUÍ`` (:data:`dhlab.assignment.solution.ANSWER_MARKERS`; for nbgrader, the same
``code_stub`` setting with that line); the grader reads a blank answer in either language the same way.

>>> cell = {"cell_type": "code", "source": "x = ...\\n### BEGIN SOLUTION\\nx = 7\\n### END SOLUTION",
...         "metadata": {"nbgrader": {"grade": False, "solution": True, "locked": False,
...                                   "grade_id": "a", "schema_version": 3}}, "outputs": []}
>>> student_cell(cell)["source"]
'x = ...\\n# YOUR CODE HERE'
"""
from __future__ import annotations

import argparse
import atexit
import copy
import json
import re
import shutil
import sys
import tempfile
from pathlib import Path

import nbformat

from ...assignment.solution import ANSWER_MARKER, ANSWER_MARKERS, solved_notebook
from ...errors import DHLabError
from ...i18n import N_, _
from .language import notebook_language

__all__ = ["CODE_STUB", "TEXT_STUB", "GenerateError", "SourceMissing", "clear_solutions", "remove_hidden_tests",
           "check_metadata", "student_cell", "student_notebook", "generate", "main", "solution_notebook",
           "NOTEBOOK", "TEMPLATE", "CHECKOUT_STUDENTS", "checkout", "find_source", "course_solved"]

CODE_STUB = ANSWER_MARKER              # what the solved notebook's solution becomes (and where it goes back)
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
# in the course's repository, from its top folder: the student notebook (the course's, edited by
# hand) and the package's copy of it, both written by this module
CHECKOUT_STUDENTS = (Path("notebooks") / NOTEBOOK, Path("dhlab") / "grading" / "template" / NOTEBOOK)
NO_SOURCE = N_("Leave --source out to use the solution dhlab computes for the PUMA 560 "
               "(dhlab-assign solutions OUT.ipynb writes it to a file).")


class GenerateError(ValueError):
    """The source notebook is not marked up the way nbgrader expects."""


class SourceMissing(DHLabError):
    """The teacher's own source notebook (``--source``) is not there (the message says what to do)."""


def checkout(start=None):
    """The top folder of the course's repository that holds ``start`` (default: the current folder),
    found by its two student notebooks (:data:`CHECKOUT_STUDENTS`); None outside a checkout."""
    here = Path(start if start is not None else Path.cwd()).resolve()
    return next((folder for folder in (here, *here.parents)
                 if all((folder / path).is_file() for path in CHECKOUT_STUDENTS)), None)


def _read(path) -> dict:
    return json.loads(Path(path).read_text(encoding="utf-8"))


def course_solved(top=None) -> dict:
    """The solved notebook of the course's student notebook (the checkout ``top``'s, else the
    package's :data:`TEMPLATE`), for the PUMA 560: computed, never stored."""
    return solved_notebook(_read(top / CHECKOUT_STUDENTS[0] if top is not None else TEMPLATE))


def _given(path) -> Path:
    """A teacher's own source notebook, which must be there (:class:`SourceMissing` saying what to do)."""
    if not Path(path).is_file():
        raise SourceMissing(_("no notebook at {path!r}.").format(path=str(path)) + " " + _(NO_SOURCE))
    return Path(path)


def solution_notebook(path=None) -> dict:
    """The teacher's solution: the source notebook at ``path`` when given (:class:`SourceMissing`
    when there is none), else the one computed for the PUMA 560 (:func:`course_solved`)."""
    return course_solved() if path is None else _read(_given(path))


def find_source(path=None) -> Path:
    """The teacher's solution as a file: ``path`` when given (:class:`SourceMissing` when there is
    none), else the computed one (:func:`solution_notebook`) written to a fresh temporary folder,
    removed when the process ends."""
    if path is not None:
        return _given(path)
    folder = Path(tempfile.mkdtemp(prefix="dhlab-solution-"))
    atexit.register(shutil.rmtree, folder, True)
    written = folder / NOTEBOOK
    written.write_text(_dumps(solution_notebook()), encoding="utf-8")
    return written


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


def student_cell(cell: dict, code_stub: str = CODE_STUB) -> dict:
    """The student's version of one cell (a new dict); ``code_stub`` replaces a code solution."""
    cell = copy.deepcopy(cell)
    meta = cell.get("metadata", {}).get("nbgrader", {})
    is_solution, is_grade = bool(meta.get("solution")), bool(meta.get("grade"))
    is_locked = bool(meta.get("locked")) and not is_solution
    stub = code_stub if cell["cell_type"] == "code" else TEXT_STUB
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
    """The student's version of a whole notebook (a new dict), its code stub in the notebook's language."""
    check_metadata(nb["cells"])
    out = copy.deepcopy(nb)
    stub = ANSWER_MARKERS.get(notebook_language(nb) or "en", CODE_STUB)
    out["cells"] = [student_cell(c, stub) for c in nb["cells"]]
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
    return nbformat.writes(nbformat.from_dict(nb))


def generate(source, student, check: bool = False) -> bool:
    """Write the student notebook made from the solved notebook ``source`` (a path or a notebook
    dict); with ``check``, only compare. True if it is up to date."""
    nb = source if isinstance(source, dict) else _read(source)
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
                        help="a solved (source) notebook (default: the course's student notebook, solved for "
                             "the PUMA 560, when run from the course's repository)")
    parser.add_argument("-o", "--output", type=Path, default=None,
                        help="the student notebook (default, in the course's repository: "
                             f"{' and '.join(map(str, CHECKOUT_STUDENTS))})")
    parser.add_argument("--solved", type=Path, default=None, metavar="OUT",
                        help="write the solved notebook to OUT instead (computed; nothing else is written)")
    parser.add_argument("--check", action="store_true", help="only check that the student notebook is up to date")
    args = parser.parse_args(argv)
    top = checkout()
    if args.solved is not None:
        args.solved.write_text(_dumps(course_solved(top)), encoding="utf-8")
        print(f"{args.solved} written (the solutions: never hand it to students)")
        return 0
    if args.output is None and top is None:
        print("generate: outside the course's repository, give -o STUDENT.ipynb (or --solved OUT)", file=sys.stderr)
        return 2
    source = args.source if args.source is not None else course_solved(top)
    outputs = [args.output] if args.output else [top / path for path in CHECKOUT_STUDENTS]
    failed = 0
    for output in outputs:
        try:
            ok = generate(source, output, check=args.check)
        except GenerateError as e:
            print(f"{args.source or CHECKOUT_STUDENTS[0]}: {e}", file=sys.stderr)
            return 2
        if args.check and not ok:
            print(f"{output} is out of date: run python -m dhlab.grading.release.generate", file=sys.stderr)
            failed = 1
        else:
            print(f"{output} {'is up to date' if args.check else 'written'}")
    return failed


if __name__ == "__main__":
    sys.exit(main())
