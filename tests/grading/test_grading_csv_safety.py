"""Every CSV a spreadsheet opens is safe and readable; releases add, never replace; ids and file names.

The gradebook, the Canvas and Moodle files and the release's
manifest never hold a cell a spreadsheet runs as a formula (OWASP "CSV Injection": a leading
``= + - @``, tab or CR gets a ``'``), reversibly where the grader reads its own file back;
the files for Excel carry a BOM; Spanish roster columns are understood; a row that was not
graded is never a grade; a second release into a folder adds to the teacher's records; look-alike
ids and unsafe file names are refused or made safe; in nbgrader's layout the folder is the student.
"""
import csv
import io
import json
import re
import unicodedata

import pytest

from dhlab import DHLabError
from dhlab.assignment import variants as V
from dhlab.grading import csvsafe
from dhlab.grading.book import grade_variants as GV
from dhlab.grading.book.gradebook import COLUMNS, VARIANT_COLUMNS, feedback_filename, read_csv, write_csv
from dhlab.grading.export import lms
from dhlab.grading.export.command import main as export
from dhlab.grading.release import notebooks as R
from dhlab.grading.release import roster
from dhlab.grading.release.roster import read_roster, safe_filename

SECRET = b"0123456789abcdef-the-teacher-secret"
HOSTILE = ["=1+2", "+SUM(A1)", "-2+3", "@cmd", "\tx", "\rx", "'quoted", "''twice", "José", "ana"]
FORMULA_START = ("=", "+", "-", "@", "\t", "\r")


@pytest.fixture(autouse=True)
def _the_puma_again():
    from dhlab.assignment.notebook_cells import clear_variant
    yield
    clear_variant()


def _row(submission, score="10", **extra):
    return {"submission": submission, "score": score, "max_score": 10, "status": "ok", "part1_sketch": "2",
            "part2_links": "4", "part3_transforms": "4", "seconds": "3.0", "feedback": feedback_filename(submission),
            "file": submission + ".ipynb", "sha256": "0" * 64, **extra}


def _cells(path) -> list:
    """The rows of a CSV file as a spreadsheet gets them (the BOM, if any, dropped)."""
    return list(csv.reader(io.StringIO(path.read_text(encoding="utf-8-sig"), newline="")))


def _assert_no_formula(rows, numeric=()):
    for row in rows:
        for k, cell in enumerate(row):
            if k in numeric and csvsafe.is_number(cell):
                continue
            assert not cell.startswith(FORMULA_START), f"a formula cell {cell!r} in {row}"


# --- 1. the escape ----------------------------------------------------------------------------------

@pytest.mark.parametrize("value", HOSTILE + ["", "-", "'", "=", "\n=1"])
def test_every_cell_round_trips_and_none_is_a_formula(value):
    cell = csvsafe.neutralised(value)
    assert not cell.startswith(FORMULA_START) and csvsafe.restored(cell) == value


def test_numbers_stay_numbers_only_where_the_column_is_numeric():
    assert [csvsafe.neutralised(v, numeric=True) for v in ("-0.5", "10", "8.57", "-3", "1e-3")] == \
        ["-0.5", "10", "8.57", "-3", "1e-3"]
    assert csvsafe.neutralised("-1+1", numeric=True) == "'-1+1"         # not a number: text, escaped
    assert csvsafe.neutralised("-0.5") == "'-0.5"                      # a text column: a name, escaped


def test_the_gradebook_neutralises_and_resume_reads_the_names_back(tmp_path):
    rows = [_row(name) for name in HOSTILE] + [_row("penalised", score="-0.5")]
    path = tmp_path / "gradebook.csv"
    write_csv(path, rows)
    table = _cells(path)
    numeric = [COLUMNS.index(c) for c in ("score", "max_score", "part1_sketch", "part2_links",
                                          "part3_transforms", "seconds")]
    _assert_no_formula(table, numeric)
    assert "'=1+2" in {r[0] for r in table} and "'=1+2.ipynb" in {r[COLUMNS.index("file")] for r in table}
    penalised = next(r for r in table if r[0] == "penalised")
    assert penalised[COLUMNS.index("score")] == "-0.5"                 # a number, not the text '-0.5
    back = {r["submission"]: r for r in read_csv(path)}
    assert set(back) == set(HOSTILE) | {"penalised"}                   # --resume finds every one again
    assert back["=1+2"]["file"] == "=1+2.ipynb" and back["'quoted"]["file"] == "'quoted.ipynb"
    assert back["penalised"]["score"] == "-0.5"


def test_read_csv_accepts_a_gradebook_with_or_without_a_bom(tmp_path):
    path = tmp_path / "gradebook.csv"
    write_csv(path, [_row("José")])
    text = path.read_text(encoding="utf-8")
    for variant in (text.lstrip(csvsafe.BOM), csvsafe.BOM + text.lstrip(csvsafe.BOM)):
        path.write_text(variant, encoding="utf-8")
        assert [r["submission"] for r in read_csv(path)] == ["José"]


# --- 1-4. Canvas and Moodle -------------------------------------------------------------------------

@pytest.fixture
def hostile_class(tmp_path):
    """A gradebook and a roster whose ids and names start like formulas, and an accented name."""
    ids = ["=1+2", "+SUM(A1)", "-2+3", "@cmd", "\tx", "josé"]
    gradebook = tmp_path / "gradebook.csv"
    write_csv(gradebook, [_row(sid, score="7.5") for sid in ids] + [_row("ghost", score="")])
    roster = tmp_path / "roster.csv"
    with open(roster, "w", newline="", encoding="utf-8") as f:
        writer = csv.writer(f)
        writer.writerow(["id", "name"])
        writer.writerows([[sid, f"=HYPERLINK(\"http://x\",\"{sid}\")"] for sid in ids[:4]] + [["\tx", "Tab"],
                                                                                             ["josé", "José Núñez"]])
    return tmp_path, gradebook, roster


@pytest.mark.parametrize("target", ["canvas", "moodle"])
def test_lms_files_have_a_bom_and_no_formula(hostile_class, target, capsys):
    tmp, gradebook, roster = hostile_class
    out = tmp / f"{target}.csv"
    assert export([target, str(gradebook), "--roster", str(roster), "-o", str(out)]) == 0
    raw = out.read_bytes()
    assert raw.startswith(b"\xef\xbb\xbf")                             # UTF-8 with BOM: Excel shows José
    table = _cells(out)
    _assert_no_formula(table, lms.GRADE_COLUMNS[target])
    text = raw.decode("utf-8-sig")
    assert "José Núñez" in text if target == "canvas" else "josé" in text
    grades = [row[lms.GRADE_COLUMNS[target][0]] for row in table[1:]]
    assert "7.5" in grades
    err = capsys.readouterr().err
    assert "leading '" in err and "=1+2" in err                        # the teacher is told which ids


def test_spanish_roster_columns(tmp_path, capsys):
    roster = tmp_path / "lista.csv"
    roster.write_text("Identificador;Nombre;Apellidos;Correo\nana;Ana;García López;ana@uni.es\n"
                      "bruno;Bruno;Silva;bruno@uni.es\n", encoding="utf-8")
    assert read_roster(roster) == ["ana", "bruno"]
    assert read_roster(roster, id_column="correo") == ["ana@uni.es", "bruno@uni.es"]
    gradebook = tmp_path / "gradebook.csv"
    write_csv(gradebook, [_row("ana"), _row("bruno", score="8")])
    out = tmp_path / "canvas.csv"
    assert export(["canvas", str(gradebook), "--roster", str(roster), "-o", str(out)]) == 0
    names = {row[0] for row in _cells(out)[2:]}
    assert names == {"García López, Ana", "Silva, Bruno"}
    other = tmp_path / "usuarios.csv"
    other.write_text("Nombre completo,Usuario\nAna García,ana\n", encoding="utf-8")
    assert read_roster(other) == ["ana"]
    column, records = lms.read_roster_rows(other)
    assert column == "Usuario" and lms._name(records["ana"]) == "Ana García"


def _variant_rows():
    """An identified and graded row, a 'student not identified' row (score 0, not run) and a grader error."""
    graded = _row("ana", score="9", variant_status="ok", variant_source="notebook")
    unknown = _row("bruno", score="0", status="student not identified: …", variant_status="unknown_student",
                   variant_source="none")
    error = _row("carla", score="", status="grader error: … grade again with --resume", variant_status="ok",
                 variant_source="notebook")
    return [graded, unknown, error]


def test_a_row_not_graded_is_never_a_grade(tmp_path, capsys):
    gradebook = tmp_path / "gradebook.csv"
    write_csv(gradebook, _variant_rows(), VARIANT_COLUMNS)
    roster = tmp_path / "roster.csv"
    roster.write_text("id\nana\nbruno\ncarla\n", encoding="utf-8")
    out = tmp_path / "moodle.csv"
    assert export(["moodle", str(gradebook), "--roster", str(roster), "-o", str(out)]) == 0
    assert [row[:2] for row in _cells(out)] == [["id", "grade"], ["ana", "9"]]        # no 0 for bruno
    err = capsys.readouterr().err
    assert "not graded (2" in err and "bruno" in err and "carla" in err
    assert lms.not_graded(_variant_rows()) == ["bruno", "carla"]


def test_an_export_that_matches_nobody_fails_and_writes_nothing(tmp_path, capsys):
    gradebook = tmp_path / "gradebook.csv"
    write_csv(gradebook, [_row("mallory")])
    roster = tmp_path / "roster.csv"
    roster.write_text("id\nana\n", encoding="utf-8")
    out = tmp_path / "moodle.csv"
    assert export(["moodle", str(gradebook), "--roster", str(roster), "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert "no graded row" in err and "--id-column" in err and "Traceback" not in err and not out.exists()
    assert export(["moodle", str(tmp_path / "nothing.csv"), "--roster", str(roster), "-o", str(out)]) == 2
    assert "cannot read the gradebook" in capsys.readouterr().err


# --- 5. a second release adds -----------------------------------------------------------------------

def _release(tmp, roster_text, secret=SECRET, name="roster.csv"):
    roster = tmp / name
    roster.write_text(roster_text, encoding="utf-8")
    key = tmp / f"{name}.key"
    key.write_bytes(secret + b"\n")
    return R.main(["release", str(roster), "-o", str(tmp / "release"), "--secret-file", str(key),
                   "--family", "all"])


def _teacher(tmp):
    records = json.loads((tmp / "release" / "_teacher" / "variants.json").read_text(encoding="utf-8"))
    manifest = list(csv.DictReader(io.StringIO((tmp / "release" / "_teacher" / "manifest.csv")
                                               .read_text(encoding="utf-8-sig"))))
    return records, manifest


def test_a_second_release_adds_to_the_teachers_records(tmp_path, capsys):
    assert _release(tmp_path, "id\nana\nbruno\n") == 0
    first, _ = _teacher(tmp_path)
    assert _release(tmp_path, "id\nbruno\ncarla\n", name="late.csv") == 0
    records, manifest = _teacher(tmp_path)
    assert set(records) == {"ana", "bruno", "carla"}
    assert records["ana"] == first["ana"] and records["bruno"] == first["bruno"]       # the same robots
    assert [row["student_id"] for row in manifest] == ["ana", "bruno", "carla"]
    fingerprints = {V.fingerprint(V.Variant.from_dict(r["variant"])) for r in records.values()}
    assert len(fingerprints) == 3                                      # the newcomer's robot is her own
    assert "added to, not replaced" in capsys.readouterr().err
    vs = GV.setup(tmp_path / "late.csv.key", tmp_path / "release")     # every student still identified
    assert [GV.identify(vs, f"{sid}.ipynb")[0] for sid in ("ana", "bruno", "carla")] == ["ana", "bruno", "carla"]


def test_a_release_with_another_secret_into_the_folder_is_refused(tmp_path, capsys):
    assert _release(tmp_path, "id\nana\n") == 0
    before = [(tmp_path / "release" / "_teacher" / n).read_bytes() for n in ("variants.json", "manifest.csv")]
    assert _release(tmp_path, "id\nbruno\n", secret=SECRET + b"-another", name="other.csv") == 2
    err = capsys.readouterr().err
    assert "do not verify with this secret" in err and "new folder" in err
    after = [(tmp_path / "release" / "_teacher" / n).read_bytes() for n in ("variants.json", "manifest.csv")]
    assert after == before and not (tmp_path / "release" / "bruno.ipynb").exists()


# --- 6. ids and file names --------------------------------------------------------------------------

def test_look_alike_ids_are_refused_naming_the_rows(tmp_path):
    composed, decomposed = unicodedata.normalize("NFC", "José"), unicodedata.normalize("NFD", "José")
    assert composed != decomposed
    roster = tmp_path / "roster.csv"
    roster.write_text(f"id\n{composed}\nana\n{decomposed}\n", encoding="utf-8")
    with pytest.raises(DHLabError, match=r"same name written two ways \(Unicode NFC and NFD\) \(rows 2 and 4\)"):
        read_roster(roster)
    with pytest.raises(DHLabError, match="same name written two ways"):
        lms.read_roster_rows(roster)


@pytest.mark.parametrize("bad,char", [("ana\x00x", "U+0000"), ('"ana\nx"', "U+000A"), ("ana\u202ex", "U+202E"),
                                      ("a\u200bna", "U+200B")])
def test_ids_with_control_characters_are_refused(tmp_path, bad, char):
    roster = tmp_path / "roster.csv"
    roster.write_text(f"id\nbruno\n{bad}\n", encoding="utf-8")
    with pytest.raises(DHLabError, match=f"row 3: .* character {re.escape(char)}"):
        read_roster(roster)
    with pytest.raises(DHLabError, match=re.escape(char)):
        lms.read_roster_rows(roster)


@pytest.mark.parametrize("sid", ["-rf", "--help", "nul.txt", "CON", "con", "com1.x", "LPT9.a.b", "aux.ipynb",
                                 "NUL .txt"])
def test_release_file_names_are_safe(sid):
    name = safe_filename(sid)
    assert not name.startswith(("-", ".")) and safe_filename(sid) == name
    device = name.split(".")[0].rstrip(" ").upper()
    assert device not in roster.RESERVED, name                              # Windows opens no device for it


def test_the_manifest_has_no_formula_and_the_grader_reads_it_back(tmp_path):
    assert _release(tmp_path, "id\n=1+2\n-rf\n@cmd\nJosé\n") == 0
    raw = (tmp_path / "release" / "_teacher" / "manifest.csv").read_bytes()
    assert raw.startswith(b"\xef\xbb\xbf")
    table = _cells(tmp_path / "release" / "_teacher" / "manifest.csv")
    _assert_no_formula(table)
    assert not any(p.name.startswith("-") for p in (tmp_path / "release").iterdir())
    vs = GV.setup(tmp_path / "roster.csv.key", tmp_path / "release")
    files = {row[0]: row[1] for row in table[1:]}
    assert GV.identify(vs, files["'=1+2"])[0] == "=1+2" and GV.identify(vs, files["'-rf"])[0] == "-rf"
    assert GV.release_files(tmp_path / "release", vs.records)[files["'@cmd"][:-len(".ipynb")]] == "@cmd"


# --- 7. nbgrader: the folder is the student ---------------------------------------------------------

def test_in_nbgraders_layout_the_folder_is_the_student(tmp_path):
    assert _release(tmp_path, "id\nana\nbob\n") == 0
    vs = GV.setup(tmp_path / "roster.csv.key", tmp_path / "release")
    assert GV.identify(vs, "submitted/ana/ps8/bob.ipynb")[0] == "ana"
    assert GV.identify(vs, "submitted/mallory/ps8/bob.ipynb")[0] is None
    assert GV.identify(vs, "bob.ipynb")[0] == "bob"
    roster = {"ana": {}, "bob": {}}
    by_id, unmatched, _ = lms.match([_row("submitted/ana/ps8/bob")], roster)
    assert list(by_id) == ["ana"] and unmatched == []
