"""dhlab-assign release: one signed, personal notebook per student, the same every time."""
import json

import nbformat
import pytest

from dhlab import DHLabError
from dhlab.assignment import variants as V
from dhlab.assignment.notebook_cells import SEAM_CELL_ID, prepare_submission, release_notebook, seam_source
from dhlab.grading.options import DEFAULT_SECRET_FILE
from dhlab.grading.release import notebooks as R
from dhlab.grading.release.folder import load_teacher_records
from dhlab.grading.release.roster import read_roster, safe_filename

SECRET = b"0123456789abcdef-the-teacher-secret"


@pytest.fixture(autouse=True)
def _the_puma_again():
    """A test that runs a notebook's "Your robot" cell (use_variant) leaves the PUMA in place after it."""
    from dhlab.assignment.notebook_cells import clear_variant
    yield
    clear_variant()


@pytest.fixture
def class_folder(tmp_path):
    roster = tmp_path / "roster.csv"
    roster.write_text("Name,ID,email\nAna,ana,a@x\nBruno,bruno,b@x\nAna M,Ana María,c@x\nAna_M,Ana_María,d@x\n"
                      "Cobra,cobra,e@x\n", encoding="utf-8")
    secret = tmp_path / "secret.key"
    secret.write_bytes(SECRET + b"\n")
    return tmp_path, roster, secret


def _code_cells(nb):
    return {c.get("id"): "".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "code"}


def test_release_writes_one_signed_notebook_per_student(class_folder):
    folder, roster, secret = class_folder
    assert R.main(["release", str(roster), "-o", str(folder / "out"), "--secret-file", str(secret),
                   "--family", "all"]) == 0
    files = sorted(p.name for p in (folder / "out").glob("*.ipynb"))
    assert files == sorted(["ana.ipynb", "bruno.ipynb", "cobra.ipynb", safe_filename("Ana María") + ".ipynb",
                            safe_filename("Ana_María") + ".ipynb"])
    manifest = (folder / "out" / "_teacher" / "manifest.csv").read_text(encoding="utf-8-sig").splitlines()
    assert manifest[0] == "student_id,file,family,fingerprint,language" and len(manifest) == 6
    fingerprints = set()
    for line in manifest[1:]:
        sid, file = line.split(",")[:2]
        nb = json.loads((folder / "out" / file).read_text(encoding="utf-8"))
        nbformat.validate(nbformat.from_dict(nb))            # a notebook Jupyter opens
        record = nb["metadata"][V.METADATA_KEY]
        check = V.verify(record, sid, SECRET)
        assert check.status == "ok" and record["student_id"] == sid
        fingerprints.add(V.fingerprint(check.variant))
        seam = _code_cells(nb)[SEAM_CELL_ID]
        namespace = {"joint_variables": lambda n: tuple(range(n))}
        exec(seam, namespace)                      # the cell the student's kernel runs
        assert V.fingerprint(namespace["my_robot"]) == V.fingerprint(check.variant)
        n = namespace["my_robot"].n
        sources = "\n".join(_code_cells(nb).values())
        assert f"T{n} " in sources and f"T{n + 1} " not in sources
        assert "my_robot.figure()" in sources and "my_robot.axes_table()" in sources
        assert "puma_figure()" not in sources
    assert len(fingerprints) == 5                   # five different robots


def test_same_roster_and_secret_give_byte_identical_notebooks(class_folder):
    folder, roster, secret = class_folder
    for out in ("a", "b"):
        assert R.main(["release", str(roster), "-o", str(folder / out), "--secret-file", str(secret),
                       "--family", "kr5,cobra600", "--figures"]) == 0
    names = sorted(p.name for p in (folder / "a").glob("*.ipynb"))
    for name in names + ["_teacher/manifest.csv", "_teacher/variants.json"]:
        assert (folder / "a" / name).read_bytes() == (folder / "b" / name).read_bytes()
    nb = json.loads((folder / "a" / "ana.ipynb").read_text(encoding="utf-8"))
    figure = next(c for c in nb["cells"] if c.get("metadata", {}).get("nbgrader", {}).get("grade_id") == "robot_figure")
    assert figure["outputs"][0]["data"]["image/png"]       # --figures: the picture is in the notebook
    table = next(c for c in nb["cells"] if c.get("metadata", {}).get("nbgrader", {}).get("grade_id") == "axes_table")
    assert "joint 1" in "".join(table["outputs"][0]["data"]["text/plain"])
    other = folder / "other.key"
    other.write_bytes(SECRET + b"2")
    R.main(["release", str(roster), "-o", str(folder / "c"), "--secret-file", str(other)])
    R.main(["release", str(roster), "-o", str(folder / "d"), "--secret-file", str(secret)])
    assert (folder / "c" / "ana.ipynb").read_bytes() != (folder / "d" / "ana.ipynb").read_bytes()


@pytest.mark.parametrize("text,match", [
    ("name,email\nAna,a@x\n", "no id column: its columns are \\['name', 'email'\\]"),
    ("id,name\nana,A\nbruno,B\nana,C\n", "'ana' appears twice \\(rows 2 and 4\\)"),
    ("id,name\nana,A\n,B\n", "row 3: the id column 'id' is empty"),
    ("", "is empty"),
    ("id\n", "no students"),
])
def test_bad_rosters_are_clear_errors(tmp_path, text, match):
    roster = tmp_path / "roster.csv"
    roster.write_text(text, encoding="utf-8")
    with pytest.raises(DHLabError, match=match):
        read_roster(roster)


def test_roster_details(tmp_path):
    roster = tmp_path / "roster.csv"
    roster.write_text("\ufeffLogin;Name\n ana ;A\nbruno;B\n", encoding="utf-8")        # BOM, ';', spaces
    assert read_roster(roster) == ["ana", "bruno"]
    roster.write_text("matricula,name\nA1,x\n", encoding="utf-8")
    assert read_roster(roster, id_column="Matricula") == ["A1"]
    with pytest.raises(DHLabError, match="no column 'dni'"):
        read_roster(roster, id_column="dni")
    roster.write_bytes("id\nJos\xe9\n".encode("latin-1"))
    with pytest.raises(DHLabError, match="not UTF-8"):
        read_roster(roster)
    with pytest.raises(DHLabError, match="cannot read the roster"):
        read_roster(tmp_path / "missing.csv")


def test_safe_filenames_are_safe_and_distinct():
    ids = ["ana", "Ana", "Ana María", "Ana_María", "../../etc/passwd", "a/b", "CON", "李雷", "x" * 200, ".hidden",
           "ana maría", "ana\tmaría"]
    names = [safe_filename(i) for i in ids]
    assert names[0] == "ana" and names[1] == "Ana"
    assert len(set(names)) == len(ids)
    for name in names:
        assert name and "/" not in name and "\\" not in name and not name.startswith(".") and len(name) <= 80
        assert all(ch.isascii() and (ch.isalnum() or ch in "._-") for ch in name)


def test_main_reports_a_bad_roster(tmp_path, capsys):
    roster = tmp_path / "r.csv"
    roster.write_text("name\nAna\n", encoding="utf-8")
    secret = tmp_path / "k"
    secret.write_bytes(SECRET)
    assert R.main(["release", str(roster), "-o", str(tmp_path / "o"), "--secret-file", str(secret)]) == 2
    assert "dhlab-assign: error: the roster r.csv has no id column" in capsys.readouterr().err
    assert R.main(["release", str(roster), "-o", str(tmp_path / "o"), "--secret-file", str(tmp_path / "none")]) == 2
    roster.write_text("id\nana\n", encoding="utf-8")
    assert R.main(["release", str(roster), "-o", str(tmp_path / "o"), "--secret-file", str(secret),
                   "--family", "r2d2"]) == 2
    assert "no robot 'r2d2'" in capsys.readouterr().err


def test_a_secret_is_made_when_none_is_given(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "r.csv").write_text("id\nana\n", encoding="utf-8")
    assert R.main(["release", "r.csv", "-o", "out"]) == 0
    key = tmp_path / DEFAULT_SECRET_FILE
    assert "never hand it out" in capsys.readouterr().err and oct(key.stat().st_mode)[-3:] == "600"
    first = (tmp_path / "out" / "ana.ipynb").read_bytes()
    assert R.main(["release", "r.csv", "-o", "out2"]) == 0        # the same key again
    assert (tmp_path / "out2" / "ana.ipynb").read_bytes() == first


def test_a_changed_template_still_releases(tmp_path):
    """Without the cells it knows, the robot section is added after the first code cell."""
    template = {"cells": [{"cell_type": "markdown", "id": "t", "metadata": {}, "source": ["# Title\n"]},
                          {"cell_type": "code", "id": "c", "metadata": {}, "outputs": [], "execution_count": None,
                           "source": ["from dhlab.course.assignment import joint_variables\n"]}],
                "metadata": {}, "nbformat": 4, "nbformat_minor": 5}
    record = V.sign_record(V.variant("ur5", 1), "ana", SECRET)
    nb, notes = release_notebook(template, record, figures=False)
    ids = [c["id"] for c in nb["cells"]]
    assert ids[:3] == ["t", "c", "dhlab-your-robot-intro"] and SEAM_CELL_ID in ids
    assert any("robot_figure" in n for n in notes) and nb["metadata"]["dhlab"] == record


def test_grader_seam_picks_the_right_variant(class_folder):
    """What dhlab-grade will do: verify the notebook's record, fall back to the released one,
    and rewrite the robot cell from the verified variant."""
    folder, roster, secret = class_folder
    assert R.main(["release", str(roster), "-o", str(folder / "out"), "--secret-file", str(secret),
                   "--family", "all"]) == 0
    teacher = load_teacher_records(folder / "out" / "_teacher" / "variants.json")
    ana = json.loads((folder / "out" / "ana.ipynb").read_text(encoding="utf-8"))
    bruno = json.loads((folder / "out" / "bruno.ipynb").read_text(encoding="utf-8"))
    released = V.Variant.from_dict(teacher["ana"]["variant"])

    v, check, source = R.submission_variant(ana, "ana", SECRET, teacher)
    assert (v, check.status, source) == (released, "ok", "notebook")
    v, check, source = R.submission_variant(bruno, "ana", SECRET, teacher)      # a classmate's notebook
    assert (v, check.status, check.signed_for, source) == (released, "other_student", "bruno", "roster")
    stripped = dict(ana, metadata={})
    v, check, source = R.submission_variant(stripped, "ana", SECRET, teacher)
    assert (v, check.status, source) == (released, "missing", "roster")
    assert R.submission_variant(stripped, "ana", SECRET)[::2] == (None, None)    # no teacher's record: no variant
    edited = json.loads(json.dumps(ana))
    edited["metadata"]["dhlab"]["variant"]["senses"][1] *= -1
    assert R.submission_variant(edited, "ana", SECRET, teacher)[1].status == "tampered"

    # the student rewrote the robot cell to use a classmate's robot: the grader puts theirs back
    hacked = json.loads(json.dumps(ana))
    cell = next(c for c in hacked["cells"] if c.get("id") == SEAM_CELL_ID)
    cell["source"] = seam_source({"variant": teacher["bruno"]["variant"], "student_id": "ana"})
    fixed = prepare_submission(hacked, released, "ana")
    seams = [c for c in fixed["cells"] if c.get("id") == SEAM_CELL_ID]
    assert len(seams) == 1
    namespace = {"joint_variables": lambda n: tuple(range(n))}
    exec("".join(seams[0]["source"]), namespace)
    assert V.fingerprint(namespace["my_robot"]) == V.fingerprint(released)
    gone = dict(ana, cells=[c for c in ana["cells"] if c.get("id") != SEAM_CELL_ID])
    assert sum(c.get("id") == SEAM_CELL_ID for c in prepare_submission(gone, released, "ana")["cells"]) == 1
