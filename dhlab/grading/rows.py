"""One submission's gradebook row: run it, read its answers, score them in the grader's process.

:func:`grade_submission` is the grader's step for one staged submission (the command is
:mod:`dhlab.grading.cli`): the runner (:mod:`dhlab.grading.launch`) returns the student's
answers as plain data, and they are scored **here**, by :mod:`dhlab.grading.checks`, against
the PUMA 560 or the student's own robot (``staged.variant``). The other helpers make the row
of a submission that was not graded (a variant with no marks, a grader error: never a 0 that
looks like a mark).
"""
from __future__ import annotations

import time

from .launch import run_submission

__all__ = ["grade_submission"]


def grade_submission(staged, options, iso=None, hide=()) -> dict:
    """Run, read the answers, score in this process: one gradebook row (+ feedback text).
    With variants (``staged.variant``), against that student's robot."""
    from . import checks
    from . import grade_variants as GV
    from .answers import N_JOINTS, Answers, Unreadable, parse_json
    from .gradebook import PART_COLUMNS, feedback_filename, feedback_text, status_text

    started = time.monotonic()
    info = staged.variant
    robot = info.robot if info is not None else None
    if info is not None and info.variant is None:
        return _not_graded_row(staged, info)
    if staged.copy is None:
        run = {"notebook_error": staged.error}
    else:
        run = run_submission(staged, options, iso, hide)
    run["file"] = staged.file
    if iso is not None and iso.note():
        run["isolation_note"] = iso.note()
    if run.get("grader_error"):                   # the grader failed, not the student: no score
        return _grader_error_row(staged, status_text(run, report_answered=False))
    cells = _cells_of(staged)
    answers, problem = Answers(), ""
    if run.get("answers_json"):
        try:
            answers = parse_json(run["answers_json"], robot.n if robot is not None else N_JOINTS)
        except ValueError as e:
            problem = f"answers not read: {e}"
    report = checks.check_all(answers, ref=robot)
    unreadable = [name for name, value in answers.items() if isinstance(value, Unreadable)]
    if unreadable and not problem:
        problem = f"unreadable answers: {', '.join(unreadable)}"
    _mark_unread(report, run, cells)
    status = status_text(run, report_answered=answers.answered(), answers_problem=problem, cells=cells)
    note = GV.status_note(info)
    if note:
        status = note if status == "ok" else f"{note}; {status}"
    row = {"submission": staged.submission, "score": f"{report.score:g}", "max_score": report.max_score,
           "status": status, "seconds": f"{time.monotonic() - started:.1f}",
           "feedback": feedback_filename(staged.submission), "file": staged.file, "sha256": staged.sha256}
    for part in report.parts:
        row[PART_COLUMNS[part.key]] = f"{part.score:g}"
    if info is not None:
        row.update(GV.columns(info))
    row["_feedback_text"] = feedback_text(staged.submission, run, report, status, GV.feedback_lines(info), cells)
    row["_part_text"] = {part.key: part.text() for part in report.parts}     # Gradescope's tests (gradescope.py)
    return row


def _cells_of(staged):
    """The submission's code cells, to name them as a student counts them (None: unknown)."""
    from .gradebook import Cells
    from .runner import NotebookError, read_code_cells
    try:
        return Cells(read_code_cells(staged.copy)) if staged.copy is not None else None
    except (NotebookError, OSError):
        return None


def _mark_unread(report, run, cells) -> None:
    """A part whose answer cell failed (a SyntaxError, say) was not read, rather than not answered:
    its feedback says so, and which cell (the score is what was read)."""
    from .gradebook import cell_error
    if cells is None:
        return
    for number, ename, evalue in run.get("errors", []):
        for key in cells.answer_parts(number):
            part = report.part(key)
            if not part.unread and any(item.ok is None for item in part.items):
                part.unread = cell_error(number, ename, evalue, cells)


def _not_graded_row(staged, info) -> dict:
    """The row of a submission with no variant to grade it against (not run: no marks)."""
    from . import grade_variants as GV
    from .checks import POINTS
    from .gradebook import PART_COLUMNS, feedback_filename
    status = GV.status_note(info)
    row = {"submission": staged.submission, "score": "0", "max_score": sum(POINTS.values()), "status": status,
           "seconds": "0.0", "feedback": feedback_filename(staged.submission), "file": staged.file,
           "sha256": staged.sha256, **{c: "0" for c in PART_COLUMNS.values()}, **GV.columns(info)}
    row["_feedback_text"] = (f"Submission: {staged.submission}\nFile: {staged.file}\nStatus: {status}\n\n"
                             "Not graded: your teacher will look at this submission.\n")
    return row


def _error_row(staged, exc) -> dict:
    """The row of a submission the grader itself failed on (it keeps the batch going)."""
    from .gradebook import status_text
    return _grader_error_row(staged, status_text({"grader_error": f"{type(exc).__name__}: {str(exc)[:150]}"},
                                                 report_answered=False))


def _grader_error_row(staged, status: str) -> dict:
    """Not graded, because the grader failed: the score and the parts are left empty (a 0 would
    read as the student's), the feedback says so, and ``--resume`` grades it again."""
    from . import grade_variants as GV
    from .checks import POINTS
    from .gradebook import PART_COLUMNS, feedback_filename, not_graded_feedback
    note = GV.status_note(staged.variant)
    status = f"{note}; {status}" if note else status
    row = {"submission": staged.submission, "score": "", "max_score": sum(POINTS.values()), "status": status,
           "seconds": "0", "feedback": feedback_filename(staged.submission), "file": staged.file,
           "sha256": staged.sha256, **{c: "" for c in PART_COLUMNS.values()}}
    if staged.variant is not None:
        row.update(GV.columns(staged.variant))
    row["_feedback_text"] = not_graded_feedback(staged.submission, staged.file, status,
                                                GV.feedback_lines(staged.variant))
    return row
