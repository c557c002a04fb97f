"""The gradebook (a CSV) and one feedback file per submission, written atomically.

A file is written to a temporary name in the same folder and then renamed over the
old one (:func:`os.replace`), so a reader — or a second grading run — never sees a
half-written gradebook, even if the grader is stopped in the middle. The grader
rewrites the gradebook after **every** submission, so a batch that is killed keeps
every finished row, and ``--resume`` (:func:`read_csv`) continues from them.

Each row names the submitted file (``file``), its SHA-256 and its feedback file,
whose name is made safe and unique by a hash of the submission's path
(:func:`feedback_filename`): two students never share a feedback file.

>>> status_text({"errors": [[4, "NameError", "name 'T9' is not defined"]]}, report_answered=True)
"error in cell 4 (NameError: name 'T9' is not defined)"

A row the grader could not grade (its own failure, never the student's) has an empty
score and says so (:data:`GRADE_AGAIN`); ``--resume`` grades it again (:func:`grade_again`).
"""
from __future__ import annotations

import csv
import functools
import hashlib
import json
import re
import unicodedata

from ...assignment import variants
from ...assignment.family import shown_name
from ...assignment.notebook_cells import SEAM_CELL_ID, release_notebook
from ...i18n import N_, _, speaking
from ..atomic_file import write_atomic
from ..csvsafe import GRADEBOOK_BOM, csv_text, restored
from ..release.comments import with_comments
from ..release.generate import TEMPLATE
from ..release.language import in_spanish, spanish_comments

__all__ = ["COLUMNS", "VARIANT_COLUMNS", "PART_COLUMNS", "GRADE_AGAIN", "REMOVED", "write_csv",
           "read_csv", "feedback_filename", "Cells", "error_text", "cell_error", "status_text", "feedback_text",
           "not_graded_feedback", "grade_again", "assignment_cells"]

PART_COLUMNS = {"part1": "part1_sketch", "part2": "part2_links", "part3": "part3_transforms"}
COLUMNS = ["submission", "score", "max_score", "status", *PART_COLUMNS.values(), "seconds", "feedback",
           "file", "sha256", "isolation"]      # isolation: how the kernel was kept apart (runner.RunResult)
# with personal variants (--secret-file) the gradebook has these too, at the end, so that a
# reader of the first columns reads it as before (see dhlab.grading.book.grade_variants)
VARIANT_COLUMNS = COLUMNS + ["variant_status", "variant_source", "variant_family", "variant_id", "signed_for"]
# the end of the status of a row the grader must grade again (its own failure, or the machine's)
GRADE_AGAIN = "grade again with --resume"      # (a key --resume finds: never translated)
NOT_THE_STUDENTS = N_("not the student's fault: {again}")
# the start of the status of a row kept by --resume although its file is no longer in the folder
REMOVED = "removed since the last run"          # (a key --resume finds: never translated)




def write_csv(path, rows, columns=COLUMNS) -> None:
    """The gradebook: one row per submission (dicts with the keys of ``columns``:
    :data:`COLUMNS`, or :data:`VARIANT_COLUMNS` when grading variants). A teacher opens it in
    a spreadsheet, so no cell runs as a formula (:mod:`dhlab.grading.csvsafe`): the numeric
    columns — ``score``, ``max_score``, the three parts and ``seconds`` — keep their numbers;
    every other cell is text, escaped when it starts like a formula (a file named
    ``=1+2.ipynb`` is the row ``'=1+2``). UTF-8, with a BOM if :data:`~dhlab.grading.csvsafe.GRADEBOOK_BOM`."""
    numeric = {"score", "max_score", *PART_COLUMNS.values(), "seconds"}
    table = [list(columns)] + [[row.get(c, "") for c in columns]
                               for row in sorted(rows, key=lambda r: r["submission"])]
    write_atomic(path, csv_text(table, [k for k, c in enumerate(columns) if c in numeric], bom=GRADEBOOK_BOM))


def read_csv(path, columns=COLUMNS) -> list:
    """The rows of an existing gradebook (for ``--resume``); [] when there is none or it
    is not a gradebook of these columns (one graded with variants is not resumed without
    them, nor the other way round: every row is graded again). With or without a BOM; each
    cell as it was before :func:`write_csv` escaped it (the submission ``=1+2`` again)."""
    try:
        with open(path, newline="", encoding="utf-8-sig") as f:
            reader = csv.DictReader(f)
            if reader.fieldnames not in (list(columns), [c for c in columns if c != "isolation"]):
                return []                         # (a gradebook from before the isolation column still resumes)
            return [{k: restored(v) for k, v in row.items() if k is not None} for row in reader]
    except (OSError, csv.Error, UnicodeDecodeError):
        return []


def feedback_filename(submission: str) -> str:
    """A safe, unique file name for a submission's feedback: readable letters of its path
    and 8 hex digits of its hash (so 'Ana María' and 'Ana_María' get different files,
    on any file system, case-insensitive ones included).

    >>> feedback_filename("alice/ps1/puma")
    'alice__ps1__puma-a78cf37e.txt'
    """
    text = unicodedata.normalize("NFKD", submission)
    text = "".join(ch for ch in text if not unicodedata.combining(ch))
    name = re.sub(r"[^A-Za-z0-9._-]+", "_", text.replace("/", "__")).strip("._") or "submission"
    digest = hashlib.sha256(submission.encode("utf-8", "surrogateescape")).hexdigest()[:8]
    return f"{name[:120]}-{digest}.txt"


def grade_again(row) -> bool:
    """Whether ``--resume`` grades this row again although its file is unchanged: the grader
    failed on it (older gradebooks wrote such rows as 0 with 'grader error: …')."""
    status = row.get("status") or ""
    return GRADE_AGAIN in status or "grader error:" in status


# --- naming the cells of a notebook ---------------------------------------------------------------

ANSWER_PARTS = {"part1": ("n_links", "n_joints", "joint_types", "x_cases"), "part2": ("link_points",)}
_ASSIGNED = re.compile(r"^[ \t]*\(?[ \t]*([A-Za-z_]\w*(?:[ \t]*,[ \t]*[A-Za-z_]\w*)*)[ \t]*\)?[ \t]*=(?!=)", re.M)
_FILE_LINE = re.compile(r"\s*\((?:[^()]*\.py|<[^<>]*>), line (\d+)\)$")


class Cells:
    """A notebook's code cells, named the way a student finds them: counted from the top among
    the code cells only (Jupyter shows no cell numbers, and markdown cells are not code), and
    quoted by their first line. ``code_cells``: [(number among all cells, source)], as
    :func:`dhlab.grading.run.notebook_code.read_code_cells` gives them; without them, the runner's numbers.

    >>> cells = Cells([(2, "import numpy as np"), (5, "# Part 2: write link_points below\\nlink_points = [")])
    >>> cells.number(5), cells.quote(5), cells.answer_parts(5)
    (2, '"# Part 2: write link_points below"', ['part2'])
    """

    def __init__(self, code_cells=()):
        self.order = {number: k for k, (number, _source) in enumerate(code_cells, start=1)}
        self.source = dict(code_cells)

    def number(self, cell: int) -> int:
        return self.order.get(cell, cell)

    def quote(self, cell: int, width: int = 45) -> str:
        """The cell's first line that is not blank, quoted ('' when unknown)."""
        lines = [line.strip() for line in self.source.get(cell, "").splitlines() if line.strip()]
        if not lines:
            return ""
        first = lines[0]
        return f'"{first[:width - 1].rstrip()}…"' if len(first) > width else f'"{first}"'

    def of_assignment(self, cell: int) -> bool:
        """Whether the cell is one of the assignment's locked cells (the student cannot edit them)."""
        code, seam_lines, _stubs = assignment_cells()
        source = self.source.get(cell)
        return source is not None and (source.strip() in code or source.lstrip().startswith(seam_lines))

    def answer_parts(self, cell: int) -> list:
        """The parts whose answer cell this is (it opens with that cell's comment) or whose answers
        it assigns: read from the text, since it may not even parse."""
        source = self.source.get(cell, "")
        names = {name.strip() for group in _ASSIGNED.findall(source) for name in group.split(",")}
        parts = {part for part, wanted in ANSWER_PARTS.items() if names & set(wanted)}
        if any(re.fullmatch(r"T\d+|chain", name) for name in names):
            parts.add("part3")
        stub = assignment_cells()[2].get(source.lstrip().split("\n", 1)[0].strip())
        return sorted(parts | ({stub} if stub else set()))


@functools.cache
def assignment_cells() -> tuple:
    """(the code of every locked cell of the assignment, as handed out or released with a personal
    robot, in English or in Spanish (whose comments are translated); the first line of the released
    "Your robot" cell in either language, which the grader rewrites; the part of each answer cell's first
    line, e.g. '# Part 2: write link_points below: …' or '# Parte 2: escriba link_points debajo: …')."""
    handed_out = json.loads(TEMPLATE.read_text(encoding="utf-8"))     # the student notebook, package data
    cells = list(handed_out["cells"])
    comments = spanish_comments(handed_out)       # the Spanish edition's notebook 8: its comments in Spanish
    cells += [{**cell, "source": with_comments("".join(cell["source"]), comments[cell["id"]])}
              for cell in handed_out["cells"] if cell.get("id") in comments]
    for family in variants.family_names():        # each robot's release says its own joints (setup cell)
        record = {"variant": variants.variant(family, "any").to_dict(), "student_id": "any"}
        cells += release_notebook(handed_out, record, figures=False)[0]["cells"]
        with speaking("es"):                      # this thread only: the grader's workers may be running
            released = release_notebook(handed_out, record, figures=False)[0]
            cells += in_spanish(released, handed_out, record, set())["cells"]
    code, seam_lines, stubs = set(), set(), {}
    for cell in cells:
        meta = cell.get("metadata", {}).get("nbgrader", {})
        source = "".join(cell["source"]) if isinstance(cell["source"], list) else cell["source"]
        part = re.fullmatch(r"(part\d)_answers", meta.get("grade_id", ""))
        if cell["cell_type"] == "code" and part and source.strip():
            stubs[source.strip().split("\n", 1)[0].strip()] = part[1]
        elif cell["cell_type"] == "code" and meta.get("locked") and not meta.get("solution"):
            code.add(source.strip())
            if cell.get("id") == SEAM_CELL_ID:
                seam_lines.add(source.splitlines()[0])
    return frozenset(code), tuple(sorted(seam_lines)) or ("\0",), stubs


def error_text(ename: str, evalue: str) -> str:
    """'NameError: …'; a SyntaxError says its line in the cell, without the kernel's file name:
    'SyntaxError on line 14: …' (not '… (98695007.py, line 14)')."""
    found = _FILE_LINE.search(evalue or "")
    if found and ename in ("SyntaxError", "IndentationError", "TabError"):
        return _("{error} on line {line}: {message}").format(error=ename, line=found[1], message=evalue[:found.start()])
    return f"{ename}: {evalue}" if evalue else ename


def cell_error(number: int, ename: str, evalue: str, cells=None) -> str:
    """Why an answer cell was not read: 'your answer cell (cell 7) has a SyntaxError on line 14'."""
    where = _("your answer cell ({cells})").format(cells=_cells([number], cells))
    found = _FILE_LINE.search(evalue or "")
    if found and ename in ("SyntaxError", "IndentationError", "TabError"):
        return _("{where} has a {error} on line {line}").format(where=where, error=ename, line=found[1])
    return _("{where} raised {error}").format(where=where, error=error_text(ename, evalue))


def _cells(numbers, cells=None) -> str:
    numbers = [cells.number(n) if cells is not None else n for n in numbers]
    listed = ", ".join(str(n) for n in numbers)
    return _("cell {n}").format(n=listed) if len(numbers) == 1 else _("cells {numbers}").format(numbers=listed)


def _renumber(text: str, cells) -> str:
    """The runner's 'cell 11: …' with the cell counted as a student counts it."""
    return re.sub(r"^cell (\d+)", lambda m: _cells([int(m[1])], cells), text)


def _stopped(what: str, numbers, cells) -> str:
    """'kernel died in cell 7 (run again without it)' (``what`` with '{cells}' in it), unless the
    cell is the assignment's own: the student did nothing wrong there, and cannot delete it."""
    text = _(what).format(cells=_cells(numbers, cells))
    ours = [n for n in numbers if cells is not None and cells.of_assignment(n)]
    if ours:
        return text + " " + _("(a cell of the assignment: {quote}; probably {fault})").format(
            quote=cells.quote(ours[0]), fault=_not_the_students())
    return text + " " + _("(run again without it)")


def _not_the_students() -> str:
    return _(NOT_THE_STUDENTS).format(again=GRADE_AGAIN)


def status_text(run: dict, report_answered: bool, answers_problem: str = "", cells=None) -> str:
    """One line for the gradebook's status column: 'ok', or every reason, joined by '; '.
    ``cells`` (:class:`Cells`): name the cells as a student counts them."""
    if run.get("grader_error"):                   # nothing else it says can be trusted
        status = "grader error: " + _("{error} ({fault})").format(error=run["grader_error"], fault=_not_the_students())
        return status + (f" ({run['isolation_note']})" if run.get("isolation_note") else "")
    reasons = []
    if run.get("notebook_error"):
        reasons.append(_("invalid notebook: {error}").format(error=run["notebook_error"]))
    memory = [e for e in run.get("errors", []) if e[1] == "MemoryError"]
    others = [e for e in run.get("errors", []) if e[1] != "MemoryError"]
    if memory:
        reasons.append(_("memory limit reached in {cells} (MemoryError)").format(
            cells=_cells((e[0] for e in memory), cells)))
    if others:
        detail = f" ({error_text(others[0][1], others[0][2])})"
        reasons.append(_("error in {cells}").format(cells=_cells((e[0] for e in others), cells)) + (
            detail if len(others) == 1 else _(", first") + detail))
    if run.get("timeouts"):
        reasons.append(_("timeout: {cells} stopped at the time limit").format(cells=_cells(run["timeouts"], cells)))
    if run.get("output_capped"):
        reasons.append(_("output limit: printed {sizes} (stopped, run again without it)").format(
            sizes=_output_sizes(run, cells)))
    if run.get("kernel_died") and run.get("limit") == "memory":    # the memory limit stopped the kernel
        reasons.append(_stopped(N_("memory limit reached in {cells} (the kernel was stopped)"), run["kernel_died"],
                                cells))
    elif run.get("kernel_died"):
        reasons.append(_stopped(N_("kernel died in {cells}"), run["kernel_died"], cells))
    if run.get("stuck"):
        reasons.append(_stopped(N_("{cells} could not be interrupted"), run["stuck"], cells))
    if run.get("runner_killed"):
        reasons.append(_stopped(N_("the grader's runner was killed in {cells}"), run["runner_killed"], cells))
    if run.get("out_of_time"):
        reasons.append(_("time limit for the whole notebook reached"))
    if run.get("answers_error"):
        reasons.append(_("answers not read: {error}").format(error=run["answers_error"]))
    if answers_problem:
        reasons.append(answers_problem)
    if run.get("tampering"):
        reasons.append(_("modifies dhlab, ignored ({what})").format(what=_renumber(run["tampering"][0], cells)))
    if not report_answered and not run.get("notebook_error"):
        reasons.append(_("not answered"))
    status = "; ".join(reasons) or "ok"
    if run.get("isolation_note"):
        status += f" ({run['isolation_note']})"
    return status


def _output_sizes(run: dict, cells=None) -> str:
    """'more than 10 MB in cell 5': the limit the cell went over. Not the count the runner saw: the
    kernel stops a flood itself, so the runner may have received only a little of an 11 MB print
    (which read 'printed 0.0 MB'), and it counts characters, not bytes. ``run["output_mb"]``: the
    limit (:func:`dhlab.grading.book.submission_row.grade_submission` puts it there); without it, the count."""
    limit = run.get("output_mb")
    if limit:
        return ", ".join(_("more than {limit} MB in {cells}").format(limit=f"{float(limit):g}",
                                                                      cells=_cells([c], cells))
                         for c, _count in run["output_capped"])
    return ", ".join(_("{size} MB in {cells}").format(size=f"{count / 1e6:.1f}", cells=_cells([c], cells))
                     for c, count in run["output_capped"])


def feedback_text(submission: str, run: dict, report, status: str, robot_lines=(), cells=None) -> str:
    """The feedback file of one submission: the score, what happened, every check
    (``robot_lines``: which robot it was graded against, with variants)."""
    lines = [_("Submission: {submission}").format(submission=submission),
             _("File: {file}").format(file=run.get("file", submission + ".ipynb")),
             _("Status: {status}").format(status=status), ""]
    lines += list(robot_lines)
    lines.append(report.text())
    details = []
    for number, ename, evalue in run.get("errors", []):
        quote = f" ({cells.quote(number)})" if cells is not None and cells.quote(number) else ""
        details.append(_("{cells}{quote} raised {error}").format(cells=_cells([number], cells), quote=quote,
                                                                  error=error_text(ename, evalue)))
    if run.get("skipped"):
        details.append(_("the notebook was run again without {cells}").format(cells=_cells(run["skipped"], cells)))
    if run.get("tampering"):
        details += [_("{what} (this has no effect: the grader checks your answers in its own process)").format(
            what=_renumber(t, cells)) for t in run["tampering"]]
    if details:
        head = (_("How your notebook ran (cells counted from the top, code cells only):") if cells is not None
                else _("How your notebook ran:"))
        lines += [head, *[f"  - {d}" for d in details], ""]

    robot = (_("your {robot}").format(robot=shown_name(report.robot)) if report.robot != "PUMA 560"
             else _("the PUMA 560"))
    lines.append(_("Your answers were read from the variables n_links, n_joints, joint_types, x_cases, link_points, "
                   "T1…T{n} and chain after your notebook ran, and checked by the grader against {robot}.").format(
        n=report.n, robot=robot))
    return "\n".join(lines) + "\n"


def not_graded_feedback(submission: str, file: str, status: str, robot_lines=()) -> str:
    """The feedback file of a submission the grader failed on: no score, and why not."""
    return "\n".join([_("Submission: {submission}").format(submission=submission), _("File: {file}").format(file=file),
                      _("Status: {status}").format(status=status), "", *robot_lines,
                      _("Not graded: the grader failed on this notebook (a grader error: the grading machine's "
                        "problem, not your work), so it has no score yet. Your teacher will grade it again."), ""])
