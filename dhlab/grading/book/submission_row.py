"""One submission's gradebook row: run it, read its answers, score them in the grader's process.

:func:`grade_submission` is the grader's step for one staged submission (the command is
:mod:`dhlab.grading.cli`): the runner (:mod:`dhlab.grading.run.launch`) returns the student's
answers as plain data, and they are scored **here**, by :mod:`dhlab.assignment.checks`, against
the PUMA 560 or the student's own robot (``staged.variant``). The other helpers make the row
of a submission that was not graded (a variant with no marks, a grader error: never a 0 that
looks like a mark).

Two languages (:mod:`dhlab.i18n`): the row's status is in the teacher's (the
grader's language, ``dhlab-grade --language``), the feedback file and the Gradescope tests'
text in the student's (``staged.language``: the submitted notebook's own).
"""
from __future__ import annotations

import time

from ...assignment import checks
from ...assignment.answers import N_JOINTS, Answers, Unreadable, parse_json
from ...assignment.checks import POINTS, check_all
from ...i18n import N_, _, current_language, speaking
from ..run.launch import run_submission
from ..run.notebook_code import NotebookError, read_code_cells
from . import grade_variants as GV
from .gradebook import (
    PART_COLUMNS,
    Cells,
    cell_error,
    feedback_filename,
    feedback_text,
    not_graded_feedback,
    status_text,
)

__all__ = ["grade_submission", "error_row"]


def grade_submission(staged, options, iso=None) -> dict:
    """Run, read the answers, score in this process: one gradebook row (+ feedback text).
    With variants (``staged.variant``), against that student's robot."""

    started = time.monotonic()
    info = staged.variant
    robot = info.robot if info is not None else None
    if info is not None and info.variant is None:
        return _not_graded_row(staged, info)
    missing = _file_missing(staged, options)
    if missing:                                   # gone before it ran: the grader's problem
        run = {"grader_error": missing}
    elif staged.copy is None:                     # the grader ran out of memory or disk on it: its fault
        fault = "grader_error" if getattr(staged, "grader_fault", False) else "notebook_error"
        run = {fault: staged.error}
    else:
        run = run_submission(staged, options, iso)
    run["file"] = staged.file
    run["output_mb"] = getattr(options, "output_mb", None)
    if iso is not None and iso.note():
        run["isolation_note"] = iso.note()
    cells = _cells_of(staged)
    n = robot.n if robot is not None else N_JOINTS

    def read_answers():
        """The answers, and what kept some from being read (in the current language)."""
        answers, problem = Answers(), ""
        if run.get("answers_json"):
            try:
                answers = parse_json(run["answers_json"], n)
            except ValueError as e:
                problem = _("answers not read: {why}").format(why=e)
        unreadable = [name for name, value in answers.items() if isinstance(value, Unreadable)]
        if unreadable and not problem:
            problem = _("unreadable answers: {names}").format(names=", ".join(unreadable))
        return answers, problem

    if not run.get("grader_error"):
        run["grader_error"] = _grader_fault(staged, run, cells, options, read_answers()[0], robot)
    if run.get("grader_error"):                   # the grader failed, not the student: no score
        return _grader_error_row(staged, run)

    def status_of(answers, problem):
        status = status_text(run, report_answered=answers.answered(), answers_problem=problem, cells=cells)
        note = GV.status_note(info)
        return (note if status == "ok" else f"{note}; {status}") if note else status

    with speaking(current_language()):            # the teacher's: the gradebook's status column
        status = status_of(*read_answers())
    with speaking(_language(staged)):             # the student's: the feedback
        answers, problem = read_answers()
        report = checks.check_all(answers, ref=robot)
        _mark_unread(report, run, cells)
        feedback = feedback_text(staged.submission, run, report, status_of(answers, problem),
                                 GV.feedback_lines(info), cells)
        part_text = {part.key: part.text() for part in report.parts}     # Gradescope's tests (gradescope.py)
    row = {"submission": staged.submission, "score": f"{report.score:g}", "max_score": report.max_score,
           "status": status, "seconds": f"{time.monotonic() - started:.1f}",
           "feedback": feedback_filename(staged.submission), "file": staged.file, "sha256": staged.sha256,
           "isolation": run.get("isolation", "")}
    for part in report.parts:
        row[PART_COLUMNS[part.key]] = f"{part.score:g}"
    if info is not None:
        row.update(GV.columns(info))
    row["_feedback_text"] = feedback
    row["_part_text"] = part_text
    row["_language"] = _language(staged)
    return row


def _file_missing(staged, options) -> str:
    """Why the submission cannot be run through no fault of its student ('' when it can): its
    staged copy was removed before it ran (a folder cleaner, a second grader's --clean), or the
    submitted file vanished while it was being read (it is reported, not scored 0)."""
    if staged.copy is not None and not staged.copy.exists():
        return _("the grader's copy of {file} was removed before it ran ({copy}: did something clean the "
                 "temporary folder?)").format(file=staged.file, copy=staged.copy)
    folder = getattr(options, "submissions", None)
    if staged.copy is None and not staged.sha256 and folder is not None and not (folder / staged.file).is_file():
        return _("{file} could not be read ({error}): put it back in {folder}").format(
            file=staged.file, error=staged.error, folder=folder)
    return ""


def _grader_fault(staged, run: dict, cells, options, answers, robot) -> str:
    """Why this run says nothing about the student's work ('' when it does): the kernel ran out of
    the memory the teacher set before any answer was read, the grader's own copy could not be read,
    the notebook was stopped for floods until no answer could be read, or a cell of the assignment
    (which the student cannot change: the imports, a figure) was stopped and the answers read
    then do not earn full marks. The text says what to change; the row then has no score and
    ``--resume`` grades it again (:func:`_grader_error_row`). A notebook whose own cell raises,
    or that answered nothing, is the student's: it scores what it earns."""
    memory_mb = getattr(options, "memory_mb", None)
    if run.get("limit") == "memory" and not answers.answered():
        return _memory_advice(memory_mb)
    if run.get("notebook_error") and staged.copy is not None:   # staging read it: the copy broke since
        return _("the grader could not read its copy of {file} ({error})").format(
            file=staged.file, error=run["notebook_error"])
    if run.get("output_capped") and not answers.answered() and run.get("answers_error"):
        return _("the notebook was stopped for its output in {cells} until no answer could be read: grade "
                 "again with a larger --output-mb (now {mb} MB)").format(
            cells=", ".join(_cell_name(c, cells) for c, _count in run["output_capped"]),
            mb=f"{float(getattr(options, 'output_mb', 0) or 0):g}")
    ours = _assignment_cell_stopped(run, cells)
    if ours is None:
        return ""
    report = check_all(answers, ref=robot)
    if report.score >= report.max_score:          # nothing was lost: the marks stand
        return ""
    number, how = ours
    text = _("{cell} of the assignment ({quote}) {how}").format(
        cell=_cell_name(number, cells), quote=cells.quote(number), how=_(STOPPED_HOW[how]))
    if run.get("limit") == "memory":
        return text + "; " + _memory_advice(memory_mb)
    if how == "timeouts":
        return text + "; " + _("the machine may be busy: grade again with a larger --timeout")
    return text


# how a cell was stopped (the runner's key: the words of a grader-error status)
STOPPED_HOW = {"kernel_died": N_("stopped the kernel"), "stuck": N_("could not be interrupted"),
               "runner_killed": N_("stopped the grader's runner"), "timeouts": N_("did not finish in time")}


def _memory_advice(memory_mb) -> str:
    """What to change when the kernel ran out of the memory the teacher set."""
    if not memory_mb:
        return _("the kernel ran out of memory: grade again with a larger --memory-mb")
    return _("the kernel ran out of the {mb} MB set with --memory-mb: grade again with a larger --memory-mb "
             "(e.g. {larger})").format(mb=f"{float(memory_mb):g}", larger=f"{max(2048, 2 * float(memory_mb)):g}")


def _assignment_cell_stopped(run: dict, cells):
    """(cell, how) of the first cell of the assignment's own that the kernel died, hung or timed out
    in (``how``: a key of :data:`STOPPED_HOW`); None when there is none. Without that cell (the
    imports, say) every later cell fails: the score would be the grader's failure."""
    if cells is None:
        return None
    for how in STOPPED_HOW:
        for number in run.get(how, []):
            if cells.of_assignment(number):
                return number, how
    return None


def _cell_name(number: int, cells) -> str:
    """'cell 3', counted as the student counts the cells."""
    return _("cell {n}").format(n=cells.number(number) if cells is not None else number)


def _language(staged) -> str:
    """The student's language: the submitted notebook's (staging read it), else the grader's."""
    return getattr(staged, "language", "") or current_language()


def _cells_of(staged):
    """The submission's code cells, to name them as a student counts them (None: unknown)."""
    try:
        return Cells(read_code_cells(staged.copy)) if staged.copy is not None else None
    except (NotebookError, OSError):
        return None


def _mark_unread(report, run, cells) -> None:
    """A part whose answer cell failed (a SyntaxError, say) was not read, rather than not answered:
    its feedback says so, and which cell (the score is what was read)."""
    if cells is None:
        return
    for number, ename, evalue in run.get("errors", []):
        for key in cells.answer_parts(number):
            part = report.part(key)
            if not part.unread and any(item.ok is None for item in part.items):
                part.unread = cell_error(number, ename, evalue, cells)


def _not_graded_row(staged, info) -> dict:
    """The row of a submission with no variant to grade it against (not run: no marks)."""
    status = GV.status_note(info)
    row = {"submission": staged.submission, "score": "0", "max_score": sum(POINTS.values()), "status": status,
           "seconds": "0.0", "feedback": feedback_filename(staged.submission), "file": staged.file,
           "sha256": staged.sha256, "isolation": "not run", **{c: "0" for c in PART_COLUMNS.values()},
           **GV.columns(info)}
    with speaking(_language(staged)):
        row["_feedback_text"] = "\n".join([
            _("Submission: {submission}").format(submission=staged.submission),
            _("File: {file}").format(file=staged.file),
            _("Status: {status}").format(status=GV.status_note(info)), "",
            _("Not graded: your teacher will look at this submission."), ""])
    row["_language"] = _language(staged)
    return row


def error_row(staged, exc) -> dict:
    """The row of a submission the grader itself failed on (it keeps the batch going)."""
    return _grader_error_row(staged, {"grader_error": f"{type(exc).__name__}: {str(exc)[:150]}"})


def _grader_error_row(staged, run: dict) -> dict:
    """Not graded, because the grader failed: the score and the parts are left empty (a 0 would
    read as the student's), the feedback says so, and ``--resume`` grades it again."""

    def status_now():
        status, note = status_text(run, report_answered=False), GV.status_note(staged.variant)
        return f"{note}; {status}" if note else status
    status = status_now()                         # in the teacher's language
    row = {"submission": staged.submission, "score": "", "max_score": sum(POINTS.values()), "status": status,
           "seconds": "0", "feedback": feedback_filename(staged.submission), "file": staged.file,
           "sha256": staged.sha256, "isolation": run.get("isolation", ""), **{c: "" for c in PART_COLUMNS.values()}}
    if staged.variant is not None:
        row.update(GV.columns(staged.variant))
    with speaking(_language(staged)):
        row["_feedback_text"] = not_graded_feedback(staged.submission, staged.file, status_now(),
                                                    GV.feedback_lines(staged.variant))
    row["_language"] = _language(staged)
    return row
