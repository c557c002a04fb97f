"""A released notebook reads as the student's own robot.

Every family's notebook is released from the real student notebook; its text and code must
name that robot and its number of joints: no PUMA text for another robot, no T5/T6 or q5, q6
for a 4-joint robot, the recap counting the robot's own joints and links. And an id with
letters outside ASCII keeps a readable release file name, by which the grader still finds
the student.
"""
import json
import re

import pytest

from dhlab.assignment import variants as V
from dhlab.assignment.notebook_cells import clear_variant, release_notebook
from dhlab.grading.book import grade_variants as GV
from dhlab.grading.release import notebooks as R
from dhlab.grading.release.generate import find_source, student_notebook
from dhlab.grading.release.roster import safe_filename

SOURCE = find_source()                  # the teacher's notebook, computed (in a temporary folder)

SECRET = b"release-text-test-secret-0123456789"


@pytest.fixture(scope="module")
def template():
    return student_notebook(json.loads(SOURCE.read_text(encoding="utf-8")))


@pytest.fixture(autouse=True)
def _the_puma_again():
    yield
    clear_variant()


def _texts(nb):
    return [(c.get("id"), c["cell_type"], "".join(c["source"])) for c in nb["cells"]]


@pytest.mark.parametrize("family", V.family_names())
def test_every_cell_speaks_of_the_students_robot(template, family):
    record = V.sign_record(V.variant(family, "ana"), "ana", SECRET)
    nb, notes = release_notebook(template, record, figures=False)
    robot = V.robot_of_variant(V.Variant.from_dict(record["variant"]))
    n = robot.n
    for cell_id, kind, text in _texts(nb):
        if family != "puma560" and kind == "markdown":
            assert "PUMA" not in text, (cell_id, text[:300])
        assert not re.search(rf"\b[Tq][{n + 1}-9]\b", text), (cell_id, re.findall(rf".*\b[Tq][{n + 1}-9]\b.*", text))
        if n != 6:
            assert not re.search(r"\bsix\b|1\s*…\s*6\$|\bz_6\b", text), (cell_id, text[:300])
    setup = next(text for _, kind, text in _texts(nb) if "joint_variables(" in text and kind == "code")
    assert ", ".join(f"q{i}" for i in range(1, n + 1)) + f" = joint_variables({n})" in setup
    recap = next(text for _, _, text in _texts(nb) if text.startswith("## Recap"))
    assert f"has {n} joints" in recap and f"and {n + 1} links" in recap
    chain = " @ ".join(f"T{i}" for i in range(1, n + 1))
    assert any(f"chain = {chain}`" in text for _, kind, text in _texts(nb) if kind == "markdown")


def test_the_puma_variant_keeps_its_name(template):
    record = V.sign_record(V.variant("puma560", "ana"), "ana", SECRET)
    nb, _ = release_notebook(template, record, figures=False)
    recap = next(text for _, _, text in _texts(nb) if text.startswith("## Recap"))
    assert "PUMA 560 has 6 joints (6 revolute) and 7 links" in recap


@pytest.mark.parametrize("sid, name", [("Łukasz.Øster", "Lukasz.Oster-"), ("Straße", "Strasse-"),
                                       ("Иван.Петров", "Ivan.Petrov-"), ("Йоан Щукин", "Yoan_Shchukin-"),
                                       ("Αλέξανδρος", "Alexandros-"), ("zoë.núñez", "zoe.nunez-"),
                                       ("ž.nuñ-ñ", "z.nun-n-"), ("李雷", "student-")])
def test_ids_beyond_ascii_keep_readable_ascii_file_names(sid, name):
    assert safe_filename(sid).startswith(name) and safe_filename(sid).isascii()
    assert len(safe_filename(sid)) == len(name) + 6                   # the name, then 6 hex digits of the id
    assert safe_filename(sid) != safe_filename(sid + "x")


def test_the_grader_finds_the_student_by_a_readable_file_name_even_decomposed(tmp_path):
    import unicodedata
    roster = tmp_path / "roster.csv"
    roster.write_text("id\nzoë.núñez\nЙоан.Петров\n", encoding="utf-8")
    secret = tmp_path / "secret.key"
    secret.write_bytes(SECRET + b"\n")
    assert R.main(["release", str(roster), "-o", str(tmp_path / "out"), "--secret-file", str(secret)]) == 0
    vs = GV.setup(secret, tmp_path / "out")
    for sid in ("zoë.núñez", "Йоан.Петров"):
        file = safe_filename(sid) + ".ipynb"
        assert (tmp_path / "out" / file).is_file()
        assert GV.identify(vs, file)[0] == sid
        assert GV.identify(vs, unicodedata.normalize("NFD", file))[0] == sid     # as a Mac hands it back
    assert GV.identify(vs, unicodedata.normalize("NFD", "zoë.núñez.ipynb"))[0] == "zoë.núñez"  # the id as name
