"""The gradebook as the CSV files Canvas and Moodle import (dhlab-grade export canvas|moodle).

Canvas's gradebook importer reads ``Student, ID, SIS User ID, SIS Login ID, Section`` and then
one column per assignment, with an optional ``Points Possible`` row; it matches a student by
ID, then SIS ids, then name. Moodle's CSV import maps one column to a user field (id number,
username or email) and the others to a grade item and its feedback. The gradebook here is
written with the grader's own writer, so the test follows the gradebook's real columns.
"""
import csv
import io

import pytest

from dhlab.grading.book.gradebook import COLUMNS, feedback_filename, write_csv
from dhlab.grading.export import lms
from dhlab.grading.export.command import main as export


def _row(submission, score, status="ok", parts=("", "", "")):
    return {"submission": submission, "score": score, "max_score": 10, "status": status,
            "part1_sketch": parts[0], "part2_links": parts[1], "part3_transforms": parts[2], "seconds": "3.0",
            "feedback": feedback_filename(submission), "file": submission + ".ipynb", "sha256": "0" * 64}


@pytest.fixture
def graded(tmp_path):
    """A gradebook of four submissions: two by file name, one in nbgrader's layout, a grader error,
    and one file whose name is no student's; and their feedback files."""
    rows = [_row("ana", "10"), _row("submitted/bruno/ps8/08_puma_assignment", "8.57"),
            _row("carla", "", "grader error: RuntimeError: x (not the student's fault: grade again with --resume)"),
            _row("mystery", "5")]
    out = tmp_path / "gradebook.csv"
    write_csv(out, rows, COLUMNS)
    feedback = tmp_path / "gradebook_feedback"
    feedback.mkdir()
    for row in rows:
        (feedback / row["feedback"]).write_text(f"Submission: {row['submission']}\nPart 3: ✗ T2, check α2\n",
                                                encoding="utf-8")
    return out


def _read(path) -> list:
    text = path.read_text(encoding="utf-8")
    assert text.startswith("\ufeff")                     # UTF-8 with BOM: Excel shows 'García'
    return list(csv.reader(io.StringIO(text[1:])))


def test_canvas_from_canvas_own_export(graded, tmp_path, capsys):
    """Canvas's own gradebook export as the roster: every column Canvas matches on is copied from it."""
    roster = tmp_path / "canvas_export.csv"
    roster.write_text("Student,ID,SIS User ID,SIS Login ID,Section,Quiz 1 (11)\n"
                      "    Points Possible,,,,,5\n"
                      "\"García, Ana\",101,A-1,ana,Lab 1,4\n"
                      "\"Silva, Bruno\",102,A-2,bruno,Lab 2,3\n"
                      "\"Ruiz, Carla\",103,A-3,carla,Lab 1,5\n"
                      "\"Díaz, Dora\",104,A-4,dora,Lab 2,5\n", encoding="utf-8")
    out = tmp_path / "canvas.csv"
    assert export(["canvas", str(graded), "--roster", str(roster), "--id-column", "SIS Login ID", "-o", str(out),
                   "--assignment", "PUMA assignment (42)"]) == 0
    rows = _read(out)
    assert rows[0] == ["Student", "ID", "SIS User ID", "SIS Login ID", "Section", "PUMA assignment (42)"]
    assert rows[1][0].strip() == "Points Possible" and rows[1][-1] == "10"
    assert rows[2:] == [["García, Ana", "101", "A-1", "ana", "Lab 1", "10"],
                        ["Silva, Bruno", "102", "A-2", "bruno", "Lab 2", "8.57"]]
    err = capsys.readouterr().err
    assert "2 grades" in err and "mystery" in err and "carla" in err and "dora" in err   # reported, not exported


def test_canvas_from_a_plain_roster_uses_the_id_as_login(graded, tmp_path):
    roster = tmp_path / "roster.csv"
    roster.write_text("id,name\nana,Ana García\nbruno,Bruno Silva\ncarla,Carla Ruiz\n", encoding="utf-8")
    out = tmp_path / "canvas.csv"
    assert export(["canvas", str(graded), "--roster", str(roster), "-o", str(out)]) == 0
    rows = _read(out)
    assert rows[2:] == [["Ana García", "", "", "ana", "", "10"], ["Bruno Silva", "", "", "bruno", "", "8.57"]]


def test_moodle_has_the_id_the_grade_and_the_feedback(graded, tmp_path):
    roster = tmp_path / "roster.csv"
    roster.write_text("username,email\nana,ana@uni.edu\nbruno,bruno@uni.edu\ncarla,carla@uni.edu\n",
                      encoding="utf-8")
    out = tmp_path / "moodle.csv"
    assert export(["moodle", str(graded), "--roster", str(roster), "-o", str(out)]) == 0
    rows = _read(out)
    assert rows[0] == ["username", "grade", "feedback"]
    assert [r[:2] for r in rows[1:]] == [["ana", "10"], ["bruno", "8.57"]]      # no 0 for carla's grader error
    assert rows[2][2] == "Submission: submitted/bruno/ps8/08_puma_assignment\nPart 3: ✗ T2, check α2"


def test_a_student_with_two_submissions_is_an_error_not_a_guess(graded, tmp_path, capsys):
    rows = list(csv.DictReader(open(graded, newline="", encoding="utf-8-sig")))
    rows.append(_row("submitted/ana/ps8/08_puma_assignment", "3"))
    write_csv(graded, rows, COLUMNS)
    roster = tmp_path / "roster.csv"
    roster.write_text("id\nana\nbruno\n", encoding="utf-8")
    assert export(["moodle", str(graded), "--roster", str(roster), "-o", str(tmp_path / "m.csv")]) == 2
    assert "two submissions are from 'ana'" in capsys.readouterr().err


def test_bad_inputs_say_what_to_fix(graded, tmp_path, capsys):
    roster = tmp_path / "roster.csv"
    roster.write_text("name\nAna\n", encoding="utf-8")
    assert export(["canvas", str(graded), "--roster", str(roster), "-o", str(tmp_path / "c.csv")]) == 2
    assert "has no id column" in capsys.readouterr().err
    not_a_gradebook = tmp_path / "other.csv"
    not_a_gradebook.write_text("a,b\n1,2\n", encoding="utf-8")
    assert export(["canvas", str(not_a_gradebook), "--roster", str(roster), "-o", str(tmp_path / "c.csv")]) == 2
    assert "not a gradebook" in capsys.readouterr().err


def test_release_file_names_count_as_their_students(tmp_path):
    by_id, unmatched, missing = lms.match([_row("Ana_Maria-8358ed", "7")], {"Ana María": {}, "bruno": {}},
                                          files={"Ana_Maria-8358ed": "Ana María"})
    assert list(by_id) == ["Ana María"] and unmatched == [] and missing == ["bruno"]
