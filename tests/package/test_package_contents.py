"""What a student installs: the package holds what it reads at run time, and neither the maintainers'
tools (tools/) nor the teacher's solutions (tools/teacher/); what needs the solutions finds them in the
course's repository or where the teacher says (--source), and says where to get them otherwise."""
import ast
import sys
from pathlib import Path
from types import SimpleNamespace

import pytest

from dhlab.grading.release import generate
from dhlab.grading.run import selfcheck
from dhlab.grading.release.language import SPANISH_TEXTS

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "dhlab"
TEACHER = ROOT / generate.CHECKOUT_SOURCE


def package_data() -> dict:
    tomllib = pytest.importorskip("tomllib") if sys.version_info >= (3, 11) else pytest.importorskip("tomli")
    return tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]["package-data"]


def test_the_shipped_student_notebook_is_the_course_s():
    """dhlab-assign starts from the package's copy: the very notebook the course hands out."""
    assert generate.TEMPLATE.read_bytes() == (ROOT / "notebooks" / generate.NOTEBOOK).read_bytes(), \
        "run python -m dhlab.grading.release.generate (make notebooks)"
    assert generate.generate(TEACHER, generate.TEMPLATE, check=True)


def test_the_teacher_s_solutions_are_in_the_repository_not_in_the_package():
    assert "BEGIN SOLUTION" in TEACHER.read_text(encoding="utf-8")
    notebooks = list(PACKAGE.rglob("*.ipynb"))
    assert generate.TEMPLATE in notebooks
    assert not [p for p in notebooks if "BEGIN SOLUTION" in p.read_text(encoding="utf-8")]
    assert not any("notebooks" in p.relative_to(ROOT).parts for p in [TEACHER])


def test_the_package_data_is_what_the_runtime_reads():
    """The notebooks' catalogs stay in the repository (tools/locale/); notebook 8's Spanish text is
    shipped as the JSON release_language reads (written by python -m tools.edition build)."""
    data = package_data()
    patterns = [pattern for patterns in data.values() for pattern in patterns]
    assert not [p for p in patterns if "notebooks" in p or "data/*.ipynb" in p]
    assert SPANISH_TEXTS.is_file() and SPANISH_TEXTS.parent == generate.TEMPLATE.parent
    assert not list(PACKAGE.rglob("notebooks/*.po"))
    assert sorted(p.stem for p in (ROOT / "tools" / "locale" / "es" / "notebooks").glob("*.po"))


def test_the_package_never_imports_the_tools():
    for path in PACKAGE.rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            names = ([a.name for a in node.names] if isinstance(node, ast.Import)
                     else [node.module or ""] if isinstance(node, ast.ImportFrom) and not node.level else [])
            assert not [n for n in names if n.split(".")[0] == "tools"], path


def test_the_source_is_found_in_a_checkout_and_only_there(tmp_path, monkeypatch):
    monkeypatch.chdir(ROOT / "notebooks")                    # anywhere inside the checkout
    assert generate.find_source() == TEACHER
    assert generate.find_source(TEACHER) == TEACHER
    monkeypatch.chdir(tmp_path)                              # a teacher who pip-installed dhlab
    with pytest.raises(generate.SourceMissing, match="tools/teacher/08_puma_assignment.ipynb.*--source"):
        generate.find_source()
    with pytest.raises(generate.SourceMissing, match="no notebook at"):
        generate.find_source(tmp_path / "missing.ipynb")


def test_outside_a_checkout_generate_and_the_self_check_say_where_to_get_the_source(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    assert generate.main([]) == 2
    assert "git clone" in capsys.readouterr().err
    with pytest.raises(selfcheck.SelfCheckError, match="nothing was graded.*--source"):
        selfcheck.solution(SimpleNamespace(source=None))
    assert selfcheck.solution(SimpleNamespace(source=TEACHER)) == TEACHER
    student = tmp_path / "student.ipynb"                     # any source, given with -o
    assert generate.main([str(TEACHER), "-o", str(student)]) == 0
    assert student.read_bytes() == generate.TEMPLATE.read_bytes()
