"""A released notebook of the assignment solved as a student would solve it: the three answer cells
filled in with a valid DH assignment of the student's own robot (the reference one, or any other
valid placing of the frames); used by the grading tests and by benchmarks/bench_grade.py. The code
of the answers is the package's own (:mod:`dhlab.assignment.solution`, what ``dhlab-assign
solutions`` writes for a teacher): here it only goes into a released notebook's answer cells."""
import copy
import json
from pathlib import Path

from dhlab.assignment import variants as V
from dhlab.assignment.solution import answers


def answer_cells(robot, frames=None) -> dict:
    """The three answer cells (grade_id -> source) of a student who placed DH frames ``frames``
    (default: the reference solution's) on ``robot``."""
    return {grade_id: code + "\n" for grade_id, code in answers(robot, frames).items()}


def solved(nb: dict, robot, frames=None) -> dict:
    """A copy of the released notebook ``nb`` with its answer cells filled in for ``robot``."""
    nb = copy.deepcopy(nb)
    answers = answer_cells(robot, frames)
    for cell in nb["cells"]:
        gid = cell.get("metadata", {}).get("nbgrader", {}).get("grade_id")
        if gid in answers:
            cell["source"] = answers[gid]
    return nb


def released_robot(nb: dict):
    return V.robot_of_variant(V.Variant.from_dict(nb["metadata"]["dhlab"]["variant"]))


def write(path: Path, nb: dict) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(nb), encoding="utf-8")
