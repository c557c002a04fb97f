"""The maintainers' tools (tools/): their docstrings' examples, and the student's own copy of the
course that make lab opens (tools.student_copy): new notebooks added, the student's never touched,
the course's tracked files never changed."""
import doctest
import importlib
import json
import pkgutil
import subprocess
from pathlib import Path

import pytest

import tools
from tools import student_copy as sc

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize("name", sorted(m.name for m in pkgutil.iter_modules(tools.__path__, "tools.")))
def test_docstring_examples(name):
    result = doctest.testmod(importlib.import_module(name), optionflags=doctest.NORMALIZE_WHITESPACE)
    assert result.failed == 0, f"{result.failed} docstring example(s) failed in {name}"


@pytest.fixture
def course(tmp_path):
    """A small course: two notebooks, a Spanish one, an image, the lecturers' plans."""
    root = tmp_path / "notebooks"
    for name, text in {"01_a.ipynb": "one", "02_b.ipynb": "two", "index.ipynb": "home", "es/01_a.ipynb": "uno",
                       "images/x.png": "png", "lecture_plans/README.md": "plan", "sanitize.cfg": "cfg",
                       ".ipynb_checkpoints/01_a-checkpoint.ipynb": "old"}.items():
        (root / name).parent.mkdir(parents=True, exist_ok=True)
        (root / name).write_text(text)
    return root


def files(folder: Path) -> dict:
    return {p.relative_to(folder).as_posix(): p.read_bytes().decode("utf-8", "replace") for p in folder.rglob("*")
            if p.is_file() and p.name != sc.RECORD}


def test_the_first_run_copies_the_notebooks_es_and_images_not_the_plans(course, tmp_path):
    copy = tmp_path / "my-notebooks"
    done = sc.update_copy(course, copy)
    assert files(copy) == {"01_a.ipynb": "one", "02_b.ipynb": "two", "index.ipynb": "home", "es/01_a.ipynb": "uno",
                           "images/x.png": "png"}
    assert sorted(done["added"]) == sorted(files(copy)) and not done["updated"] and not done["kept"]


def test_a_later_run_adds_new_notebooks_and_never_touches_the_student_s(course, tmp_path):
    copy = tmp_path / "my-notebooks"
    sc.update_copy(course, copy)
    (copy / "01_a.ipynb").write_text("one, answered")             # the student's work
    (copy / "mine.ipynb").write_text("my own notebook")
    (course / "03_c.ipynb").write_text("three")                   # next week's material, pulled
    (course / "01_a.ipynb").write_text("one, corrected")          # the course changed a notebook the student changed
    (course / "index.ipynb").write_text("home, with 03")          # and one the student never saved
    before = files(course)
    done = sc.update_copy(course, copy)
    assert files(course) == before                                # the course itself is never written
    assert done == {"added": ["03_c.ipynb"], "updated": ["index.ipynb"], "kept": ["01_a.ipynb"]}
    assert (copy / "01_a.ipynb").read_text() == "one, answered"
    assert (copy / "mine.ipynb").read_text() == "my own notebook"
    assert (copy / "03_c.ipynb").read_text() == "three" and (copy / "index.ipynb").read_text() == "home, with 03"
    assert sc.update_copy(course, copy) == {"added": [], "updated": [], "kept": ["01_a.ipynb"]}
    (copy / "02_b.ipynb").unlink()                                 # deleted (or renamed): the course's comes back
    assert sc.update_copy(course, copy)["added"] == ["02_b.ipynb"]


def test_the_record_is_json_the_student_may_delete(course, tmp_path):
    """Without the record (deleted), a file that differs from the course's is the student's: kept."""
    copy = tmp_path / "my-notebooks"
    sc.update_copy(course, copy)
    assert set(json.loads((copy / sc.RECORD).read_text())) == set(files(copy))
    (copy / sc.RECORD).unlink()
    (course / "02_b.ipynb").write_text("two, corrected")
    assert sc.update_copy(course, copy)["kept"] == ["02_b.ipynb"]


def test_the_real_course_copied_leaves_the_tracked_files_unchanged(tmp_path):
    """make lab's copy of notebooks/, made and brought up to date, writes nothing git tracks."""
    def status():
        return subprocess.run(["git", "status", "--porcelain", "--", "notebooks"], cwd=ROOT, capture_output=True,
                              text=True, check=True).stdout
    before = status()
    copy = tmp_path / "my-notebooks"
    assert sc.main([str(copy)]) == 0
    assert sc.main([str(copy)]) == 0
    assert status() == before
    assert (copy / "index.ipynb").exists() and (copy / "es").is_dir() and not (copy / "lecture_plans").exists()
    originals = sc.course_files()
    assert files(copy) == {name: path.read_bytes().decode("utf-8", "replace") for name, path in originals.items()}


def test_make_test_and_git_leave_the_student_s_copy_alone():
    """pytest does not collect my-notebooks/ (norecursedirs) and git ignores it."""
    tomllib = pytest.importorskip("tomllib")
    options = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["pytest"]["ini_options"]
    assert sc.COPY.name in options["norecursedirs"]
    ignored = subprocess.run(["git", "check-ignore", "-q", f"{sc.COPY.name}/01_start_here.ipynb"], cwd=ROOT)
    assert ignored.returncode == 0
