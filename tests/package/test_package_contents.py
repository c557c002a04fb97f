"""What a student installs: the package holds what it reads at run time, and neither the maintainers'
tools (tools/) nor a file of the teacher's solutions; what needs the solutions computes them
(dhlab.assignment.solution), or reads the teacher's own where the teacher says (--source)."""
import ast
import json
import sys
from pathlib import Path
from types import SimpleNamespace

import pytest

from dhlab.grading.release import generate
from dhlab.grading.release.language import SPANISH_TEXTS
from dhlab.grading.run import selfcheck

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "dhlab"


def package_data() -> dict:
    tomllib = pytest.importorskip("tomllib") if sys.version_info >= (3, 11) else pytest.importorskip("tomli")
    return tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]["package-data"]


def test_the_shipped_student_notebook_is_the_course_s():
    """dhlab-assign starts from the package's copy: the very notebook the course hands out, and
    exactly what the generator makes of its solved notebook (no answer typed in, nothing stale)."""
    assert generate.TEMPLATE.read_bytes() == (ROOT / "notebooks" / generate.NOTEBOOK).read_bytes(), \
        "run python -m dhlab.grading.release.generate (make notebooks)"
    assert generate.generate(generate.course_solved(ROOT), generate.TEMPLATE, check=True)
    assert generate.main(["--check"]) == 0


def test_no_notebook_of_the_package_holds_a_solution():
    notebooks = list(PACKAGE.rglob("*.ipynb"))
    assert generate.TEMPLATE in notebooks
    assert not [p for p in notebooks if "BEGIN SOLUTION" in p.read_text(encoding="utf-8")]


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


def _sources(nb) -> list:
    return ["".join(cell["source"]) for cell in nb["cells"]]


def test_the_solution_is_computed_anywhere_and_a_teacher_s_own_is_read_where_given(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)                              # a teacher who pip-installed dhlab: no checkout
    computed = generate.find_source()
    assert "### BEGIN SOLUTION" in computed.read_text(encoding="utf-8")
    assert _sources(json.loads(computed.read_text(encoding="utf-8"))) == _sources(generate.solution_notebook())
    assert generate.find_source(computed) == computed        # a teacher's own source, as given
    with pytest.raises(generate.SourceMissing, match="no notebook at.*--source"):
        generate.find_source(tmp_path / "missing.ipynb")
    with pytest.raises(selfcheck.SelfCheckError, match="nothing was graded.*--source"):
        selfcheck.solution(SimpleNamespace(source=tmp_path / "missing.ipynb"), tmp_path / "s")
    written = selfcheck.solution(SimpleNamespace(source=None), tmp_path / "s")
    assert _sources(json.loads(written.read_text(encoding="utf-8"))) == _sources(generate.solution_notebook())
    assert selfcheck.solution(SimpleNamespace(source=computed), tmp_path / "t") == computed
    student = tmp_path / "student.ipynb"                     # any source, given with -o
    assert generate.main([str(computed), "-o", str(student)]) == 0
    assert student.read_bytes() == generate.TEMPLATE.read_bytes()
    assert generate.main([]) == 2 and "-o STUDENT" in capsys.readouterr().err
