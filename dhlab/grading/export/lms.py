"""The gradebook as a CSV file that Canvas or Moodle imports.

    dhlab-grade export canvas gradebook.csv --roster ROSTER.csv -o canvas.csv [--assignment "PUMA assignment"]
    dhlab-grade export moodle gradebook.csv --roster ROSTER.csv -o moodle.csv [--id-column email]

Each gradebook row is matched to a student of the roster: the roster's id column (as for
``dhlab-assign release``: ``id``, ``student_id``, ``student``, ``username``, ``login``, or
``--id-column``) must equal the student the submission is from — its file's name
(``ana.ipynb``), the folder after nbgrader's ``submitted/``, or the release's file name of that
id (``--release``). In nbgrader's layout the folder is the student, whatever the file's name
(``submitted/ana/ps8/bob.ipynb`` is ana's). Which gradebook rows
matched no student, and which students have no graded row, is reported; they are left out of the
file (an LMS import then leaves those grades as they were). A row that was not graded — the grader
failed on it (no score), or it had no variant to grade against ("student not identified",
``variant_source`` none) — is never exported as a grade: it is listed instead (:func:`not_graded`).

The roster may be in Spanish: ``identificador``, ``usuario``… as ids (see
:data:`dhlab.grading.release.roster.ID_COLUMNS`; any other column, e.g. ``correo`` or ``email``, with
``--id-column``), ``nombre`` and ``apellidos`` (or ``nombre completo``) as the name. The files
written are UTF-8 with a BOM, so that Excel shows ``José``, and no cell runs as a formula
(:mod:`dhlab.grading.csvsafe`: the grade column keeps its numbers, the rest is text).

* **Canvas** (Grades → Import): ``Student, ID, SIS User ID, SIS Login ID, Section, <assignment>``,
  then a ``Points Possible`` row. Canvas matches a student by ``ID``, then ``SIS User ID`` or
  ``SIS Login ID``, then name; export Canvas's own gradebook (Grades → Export) and pass it as
  the roster with ``--id-column "SIS Login ID"`` (or ``ID``), and every column Canvas needs is
  copied from it. With another roster, ``Student`` is its ``name`` column when it has one and
  ``SIS Login ID`` is the id.
* **Moodle** (Grades → Import → CSV file): the roster's id column (map it to ``useridnumber``,
  ``username`` or ``useremail``, as it is), ``grade`` (map to the assignment) and ``feedback``
  (map to its feedback: the text of the submission's feedback file).
"""
from __future__ import annotations

from pathlib import Path, PurePosixPath

from ...errors import DHLabError
from ..atomic_file import write_atomic
from ..csvsafe import csv_text
from ..release.roster import checked_id, csv_rows, id_column_index, look_alikes

__all__ = ["read_roster_rows", "match", "not_graded", "canvas_rows", "moodle_rows", "write", "CANVAS_COLUMNS"]

CANVAS_COLUMNS = ["Student", "ID", "SIS User ID", "SIS Login ID", "Section"]
POINTS_POSSIBLE = "    Points Possible"      # Canvas's own export writes it so
GRADE_COLUMNS = {"canvas": [len(CANVAS_COLUMNS)], "moodle": [1]}    # the numeric columns of each file


def read_roster_rows(path, id_column=None) -> tuple:
    """(the id column's name, {id: the roster row as a dict}), with clear errors (no such file, no
    id column, an empty or repeated id). Canvas's ``Points Possible`` row is not a student."""
    path = Path(path)
    rows = csv_rows(path)
    if len(rows) < 2:
        raise DHLabError(f"the roster {str(path)!r} needs a header row and one row per student.")
    header = [h.strip() for h in rows[0]]
    column = header[id_column_index(header, id_column, path)]
    out = {}
    for line, row in enumerate(rows[1:], start=2):
        record = {h: (row[k].strip() if k < len(row) else "") for k, h in enumerate(header)}
        if row and row[0].strip() == POINTS_POSSIBLE.strip():
            continue
        sid = checked_id(record[column], path.name, line, column)
        if sid in out:
            raise DHLabError(f"roster {path.name}: the id {sid!r} appears twice; every student needs a different id.")
        out[sid] = record
    look_alikes(list(out), path.name)
    return column, out


def _student_of(row: dict, ids, files: dict) -> str | None:
    """The roster id a gradebook row is from: in nbgrader's layout the folder after
    ``submitted/`` (the folder is the student, whatever the file's name), else the file's
    stem (a release file name counts as its id)."""
    parts = PurePosixPath(row.get("file") or row["submission"] + ".ipynb").parts
    folders = [parts[i + 1] for i, p in enumerate(parts[:-2]) if p == "submitted"]
    candidates = folders[:1] or [PurePosixPath(parts[-1]).stem]
    for c in candidates:
        if c in ids:
            return c
        if c in files:
            return files[c]
    return None


def match(gradebook_rows, roster: dict, files=None) -> tuple:
    """({roster id: gradebook row}, [submissions matching no student], [ids with no graded row]).
    Rows that were not graded (:func:`not_graded`) are never a student's grade."""
    files = files or {}
    by_id, unmatched = {}, []
    for row in gradebook_rows:
        sid = _student_of(row, roster, files)
        if sid is None:
            unmatched.append(row["submission"])
        elif _graded(row):
            if sid in by_id:
                raise DHLabError(f"two submissions are from {sid!r}: {by_id[sid]['submission']!r} and "
                                 f"{row['submission']!r}; keep one in the gradebook and export again.")
            by_id[sid] = row
    missing = [sid for sid in roster if sid not in by_id]
    return by_id, unmatched, missing


def _graded(row: dict) -> bool:
    """Whether a gradebook row holds a grade: it has a score, and it was run against a variant
    (with personal variants, ``variant_source`` 'none' is a submission not run: its 0 is no grade)."""
    return row.get("score", "") != "" and row.get("variant_source", "") != "none"


def not_graded(gradebook_rows) -> list:
    """The submissions whose rows hold no grade (the grader failed, or the student was not
    identified): the teacher grades them by hand or grades them again."""
    return [row["submission"] for row in gradebook_rows if not _graded(row)]


FULL_NAMES = ("student", "name", "full name", "fullname", "nombre completo", "estudiante", "alumno", "alumna")
FIRST_NAMES = ("first name", "firstname", "given name", "nombre", "nombres")
LAST_NAMES = ("last name", "surname", "family name", "apellidos", "apellido")


def _name(record: dict) -> str:
    """The student's name for Canvas: a full-name column, else 'last, first' (English or Spanish
    column names: ``nombre`` and ``apellidos`` give 'García López, Ana')."""
    lowered = {k.strip().lower(): v for k, v in record.items()}
    full = next((lowered[k] for k in FULL_NAMES if lowered.get(k)), "")
    first = next((lowered[k] for k in FIRST_NAMES if lowered.get(k)), "")
    last = next((lowered[k] for k in LAST_NAMES if lowered.get(k)), "")
    if full:
        return full
    return f"{last}, {first}" if first and last else first or last


def canvas_rows(by_id: dict, roster: dict, assignment: str, max_score) -> list:
    """The Canvas import: header, the Points Possible row, one row per graded student."""
    rows = [CANVAS_COLUMNS + [assignment], [POINTS_POSSIBLE, "", "", "", "", f"{float(max_score):g}"]]
    for sid, grade in by_id.items():
        record = roster[sid]
        row = [record.get(c, "") for c in CANVAS_COLUMNS]
        if not any(row[1:4]):                          # not Canvas's own roster: the id is the login
            row[3] = sid
        row[0] = row[0] or _name(record) or sid
        rows.append(row + [grade["score"]])
    return rows


def moodle_rows(by_id: dict, id_column: str, feedback_dir=None) -> list:
    """The Moodle import: the id column, grade, feedback (the text of the feedback file)."""
    rows = [[id_column, "grade", "feedback"]]
    for sid, grade in by_id.items():
        text = ""
        if feedback_dir is not None and grade.get("feedback"):
            try:
                text = (Path(feedback_dir) / grade["feedback"]).read_text(encoding="utf-8").strip()
            except OSError:
                text = grade.get("status", "")
        rows.append([sid, grade["score"], text or grade.get("status", "")])
    return rows


def write(path, rows, numeric_columns=()) -> None:
    """A CSV file for Excel and the LMS: UTF-8 with a BOM, comma-separated, every field quoted
    only when it must be, no cell a formula (``numeric_columns``: the indexes of the grade
    columns, whose numbers are kept; see :mod:`dhlab.grading.csvsafe`)."""
    write_atomic(path, csv_text(rows, numeric_columns))
