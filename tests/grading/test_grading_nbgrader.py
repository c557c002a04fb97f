"""nbgrader accepts the PUMA source notebook (skipped when nbgrader is not installed).

    make test-nbgrader        # installs nbgrader into .venv, then runs this file

The source notebook (computed: dhlab.assignment.solution, never stored) is marked as nbgrader
marks notebooks, so a teacher who uses nbgrader can put it in ``source/<assignment>/`` and run
``nbgrader generate_assignment``. With the code stub set to ``# YOUR CODE HERE`` (see
dhlab.grading.release.generate) nbgrader's release is our student notebook, cell for cell.
``--no-db`` keeps nbgrader away from its database (which also needs ``alembic`` on the PATH).
"""
import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

pytest.importorskip("nbgrader")

from dhlab.grading.release.generate import find_source

ROOT = Path(__file__).resolve().parents[2]
SOURCE = find_source()            # the teacher's, with the solutions: computed, in a temporary folder
STUDENT = ROOT / "notebooks" / "08_puma_assignment.ipynb"
CONFIG = """c = get_config()
c.CourseDirectory.root = {root!r}
c.CourseDirectory.course_id = "dhlab"
c.ClearSolutions.code_stub = {{"python": "# YOUR CODE HERE"}}
"""


def _nbgrader(*args, cwd):
    return subprocess.run([sys.executable, "-m", "nbgrader", *args], cwd=cwd, capture_output=True, text=True,
                          timeout=600)


def _source(cell):
    return "".join(cell["source"]) if isinstance(cell["source"], list) else cell["source"]


@pytest.fixture
def course(tmp_path):
    root = tmp_path / "course"
    (root / "source" / "puma").mkdir(parents=True)
    shutil.copy(SOURCE, root / "source" / "puma" / SOURCE.name)
    (root / "nbgrader_config.py").write_text(CONFIG.format(root=str(root)), encoding="utf-8")
    return root


def test_nbgrader_generate_assignment_gives_our_student_notebook(course):
    proc = _nbgrader("generate_assignment", "puma", "--no-db", "--force", cwd=course)
    assert proc.returncode == 0, proc.stderr[-2000:]
    release = json.loads((course / "release" / "puma" / SOURCE.name).read_text(encoding="utf-8"))
    ours = json.loads(STUDENT.read_text(encoding="utf-8"))
    assert len(release["cells"]) == len(ours["cells"])
    for theirs, mine in zip(release["cells"], ours["cells"]):
        assert (theirs["cell_type"], _source(theirs)) == (mine["cell_type"], _source(mine))
        for key in ("editable", "deletable"):
            assert theirs["metadata"].get(key) == mine["metadata"].get(key)
        if "nbgrader" in mine["metadata"]:
            added = {"checksum", "cell_type"}           # nbgrader adds these two in its release
            assert {k: v for k, v in theirs["metadata"]["nbgrader"].items() if k not in added} == \
                mine["metadata"]["nbgrader"]


def test_nbgrader_validate_passes_the_source_notebook(course):
    proc = _nbgrader("validate", str(course / "source" / "puma" / SOURCE.name), cwd=course)
    assert "Success! Your notebook passes all the tests." in proc.stdout, proc.stdout[-2000:] + proc.stderr[-2000:]


def test_a_spanish_source_gives_our_spanish_student_notebook(tmp_path):
    """The Spanish solved notebook (dhlab-assign solutions --language es) through nbgrader with the Spanish
    stub is what our generator makes of it: the same cells, the answers replaced by ``# ESCRIBA SU CÓDIGO AQUÍ``."""
    from dhlab.assignment.solution import ANSWER_MARKERS
    from dhlab.grading.release.generate import TEMPLATE, student_notebook
    from dhlab.grading.release.solutions import puma_solutions
    root = tmp_path / "course"
    (root / "source" / "puma").mkdir(parents=True)
    source = puma_solutions(json.loads(TEMPLATE.read_text(encoding="utf-8")), "es")
    (root / "source" / "puma" / SOURCE.name).write_text(json.dumps(source), encoding="utf-8")
    config = CONFIG.format(root=str(root)).replace("# YOUR CODE HERE", ANSWER_MARKERS["es"])
    (root / "nbgrader_config.py").write_text(config, encoding="utf-8")
    proc = _nbgrader("generate_assignment", "puma", "--no-db", "--force", cwd=root)
    assert proc.returncode == 0, proc.stderr[-2000:]
    release = json.loads((root / "release" / "puma" / SOURCE.name).read_text(encoding="utf-8"))
    ours = student_notebook(source)
    assert [(c["cell_type"], _source(c)) for c in release["cells"]] == [(c["cell_type"], _source(c))
                                                                        for c in ours["cells"]]
    code = "\n".join(_source(c) for c in ours["cells"] if c["cell_type"] == "code")
    assert code.count(ANSWER_MARKERS["es"]) == 3 and ANSWER_MARKERS["en"] not in code
    proc = _nbgrader("validate", str(root / "source" / "puma" / SOURCE.name), cwd=root)
    assert "Success! Your notebook passes all the tests." in proc.stdout, proc.stdout[-2000:] + proc.stderr[-2000:]
