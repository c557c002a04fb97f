"""The teacher's solutions are computed (dhlab.assignment.solution), never stored: no file of the
repository holds them (students clone it), and what is computed earns full marks for the PUMA 560 and
for the variants of every family; ``dhlab-assign solutions`` writes them for a teacher."""
import json
import shutil
import subprocess
from pathlib import Path

import pytest

from dhlab.assignment import notebook as A
from dhlab.assignment import variants as V
from dhlab.assignment.notebook_cells import clear_variant, release_notebook
from dhlab.assignment.solution import ANSWER_CELLS, ANSWER_MARKERS, BEGIN, END, answers, solved_notebook
from dhlab.grading.release import generate
from dhlab.grading.release import notebooks as R
from dhlab.i18n import current_language, set_language

ROOT = Path(__file__).resolve().parents[2]
STUDENT = ROOT / "notebooks" / generate.NOTEBOOK
SECRET = b"solution-test-secret-0123456789abcdef"
# The one place of the repository that holds the default PUMA 560's answers: the grader's own test
# submissions (a full-marks one, typed mistakes, a valid alternative placing of the frames). The
# PUMA 560's DH table is published in every textbook (Craig; Corke's toolbox); what only this course
# knows, a student's personal variant and its answers, no file holds.
SUBMISSIONS = "tests/data/submissions/"


@pytest.fixture(autouse=True)
def _the_puma_again():
    language = current_language()
    yield
    clear_variant()
    set_language(language)          # a Spanish notebook's set-up cell, run here, set the course's language


def _tracked() -> list:
    if shutil.which("git") is None or not (ROOT / ".git").exists():
        pytest.skip("not a git checkout")
    out = subprocess.run(["git", "ls-files", "-z"], cwd=ROOT, capture_output=True, check=True).stdout
    return [name for name in out.decode("utf-8").split("\0") if name and (ROOT / name).is_file()]


def _solution_lines() -> set:
    """The lines of the PUMA's computed answers that say more than a count (``n_links = 7`` is in many a
    test) or than the question (the chain's line is in it)."""
    return {line for code in answers().values() for line in code.splitlines()
            if not line.startswith(("chain =", "n_links =", "n_joints =", "link_points = {", "}"))}


def _holding(lines) -> dict:
    found = {}
    for name in _tracked():
        try:
            text = (ROOT / name).read_text(encoding="utf-8")
        except (UnicodeDecodeError, OSError):
            continue
        held = [line for line in lines if line in text or json.dumps(line)[1:-1] in text]
        if held:
            found[name] = held
    return found


def test_every_tracked_notebook_answer_cell_holds_only_the_stub():
    for name in _tracked():
        if not name.endswith(".ipynb") or name.startswith(SUBMISSIONS):
            continue
        try:
            cells = json.loads((ROOT / name).read_text(encoding="utf-8")).get("cells", [])
        except ValueError:
            continue
        for cell in cells:
            source = "".join(cell.get("source", ""))
            assert BEGIN not in source, name
            if cell.get("metadata", {}).get("nbgrader", {}).get("solution"):
                lines = [line for line in source.splitlines() if line.strip()]
                assert lines[-1] in ANSWER_MARKERS.values(), (name, source)
                assert all(line.startswith("#") for line in lines), (name, source)


def test_no_tracked_file_holds_the_computed_solution_lines():
    lines = _solution_lines()
    assert any(line.startswith("T3 = ") for line in lines) and len(lines) > 10
    found = {name: held for name, held in _holding(lines).items() if not name.startswith(SUBMISSIONS)}
    assert found == {}
    assert not (ROOT / "tools" / "teacher").exists()


def test_the_solved_notebook_is_the_student_notebook_with_the_answers():
    student = json.loads(STUDENT.read_text(encoding="utf-8"))
    solved = solved_notebook(student)
    assert generate.generate(solved, STUDENT, check=True)          # solutions out: the stored notebook again
    cells = {c["metadata"]["nbgrader"]["grade_id"]: "".join(c["source"]) for c in solved["cells"]
             if "nbgrader" in c["metadata"]}
    for grade_id in ANSWER_CELLS:
        assert f"{BEGIN}\n{answers()[grade_id]}\n{END}" in cells[grade_id]
    for part in (1, 2, 3):                                          # nbgrader's partial credit, hidden
        assert f"feedback_{part}.score" in cells[f"part{part}_check"]
    assert not any("deletable" in c["metadata"] or "editable" in c["metadata"] for c in solved["cells"])


def _run(nb: dict) -> dict:
    """The set-up cell, the "Your robot" cell and the answer cells of ``nb``, run here (our own code)."""
    ns = {}
    for cell in nb["cells"]:
        grade_id = cell.get("metadata", {}).get("nbgrader", {}).get("grade_id")
        if grade_id in ("setup", "your_robot", *ANSWER_CELLS):
            exec(compile("".join(cell["source"]), str(grade_id), "exec"), ns)
    return ns


def _full_marks(ns) -> None:
    for part in (1, 2, 3):
        report = A.check_part(part, ns)
        assert report.full_marks, report.text()


def test_the_computed_solution_earns_full_marks_for_the_puma():
    _full_marks(_run(solved_notebook(json.loads(STUDENT.read_text(encoding="utf-8")))))


@pytest.mark.parametrize("family", V.family_names())
@pytest.mark.parametrize("seed", ["ana", "bruno", 3])
def test_the_computed_solution_earns_full_marks_for_every_family(family, seed):
    template = json.loads(generate.TEMPLATE.read_text(encoding="utf-8"))
    record = V.sign_record(V.variant(family, seed), str(seed), SECRET)
    nb, _notes = release_notebook(template, record, figures=False)
    _full_marks(_run(solved_notebook(nb, V.robot_of_variant(V.Variant.from_dict(record["variant"])))))


def test_dhlab_assign_solutions_writes_the_puma_s_and_a_student_s(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    assert R.main(["solutions", "puma.ipynb", "--language", "es"]) == 0
    puma = json.loads((tmp_path / "puma.ipynb").read_text(encoding="utf-8"))
    assert puma["metadata"]["dhlab"]["language"] == "es" and "Parte 1" in json.dumps(puma, ensure_ascii=False)
    _full_marks(_run(puma))
    (tmp_path / "roster.csv").write_text("id,language\nana,es\nbruno,en\n", encoding="utf-8")
    (tmp_path / "key").write_bytes(SECRET)
    assert R.main(["release", "roster.csv", "-o", "rel", "--family", "all", "--secret-file", "key"]) == 0
    for how in (["--release", "rel"], ["--roster", "roster.csv", "--family", "all"]):
        assert R.main(["solutions", "ana.ipynb", "--student", "ana", "--secret-file", "key", *how]) == 0
        ana = json.loads((tmp_path / "ana.ipynb").read_text(encoding="utf-8"))
        released = json.loads((tmp_path / "rel" / "ana.ipynb").read_text(encoding="utf-8"))
        assert ana["metadata"]["dhlab"] == released["metadata"]["dhlab"]       # her robot, her language (es)
        _full_marks(_run(ana))
        clear_variant()
    assert R.main(["solutions", "x.ipynb", "--student", "zoe", "--release", "rel", "--secret-file", "key"]) == 2
    assert "'zoe'" in capsys.readouterr().err
    assert R.main(["solutions", "x.ipynb", "--student", "ana"]) == 2
