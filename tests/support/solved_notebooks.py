"""A released notebook of the assignment solved as a student would solve it: the three answer cells
filled in with a valid DH assignment of the student's own robot; used by the grading tests and by
benchmarks/bench_grade.py. It lives in the tests, not in the package: a function that solves a
student's notebook must not ship with the course."""
import copy
import json
import math
from pathlib import Path

from dhlab.assignment import variants as V

# the word the notebook asks for in part 1 for each relation of two axes (coincident axes are case 2)
CASES = {"intersect": "intersect", "parallel": "parallel", "coincident": "parallel", "skew": "skew"}


def answer_cells(robot, frames=None) -> dict:
    """The three answer cells (grade_id -> source) of a student who placed DH frames ``frames``
    (default: the reference solution's) on ``robot``."""
    from dhlab.assignment.model import rows_from_frames
    from dhlab.lines import relation
    frames = robot.home_frames if frames is None else frames
    n = robot.n
    cases = [CASES[relation(robot.axes[i - 1], robot.axes[i], tol=2e-3).kind] for i in range(1, n)]
    part1 = f"n_links = {n + 1}\nn_joints = {n}\njoint_types = {robot.kinds!r}\nx_cases = {cases!r}\n"
    links = []
    for k, F in enumerate(frames):
        local = (robot.world_points(k) - F[:3, 3]) @ F[:3, :3]
        links.append(f"    {k}: [" + ", ".join("(" + ", ".join(repr(float(x)) for x in p) + ")" for p in local) + "],")
    part2 = "link_points = {\n" + "\n".join(links) + "\n}\n"
    lines = []
    for i, (sign, j, th, d, a, al) in enumerate(rows_from_frames(robot, frames), start=1):
        q = f"{'-' if sign < 0 else ''}q{j + 1}"
        th, al = repr(round(math.degrees(th), 9)), repr(round(math.degrees(al), 9))
        z = f"Tz({q} + {th}, {d!r})" if robot.kinds[i - 1] == "R" else f"Tz({th}, {q} + {d!r})"
        lines.append(f"T{i} = {z} @ Tx({al}, {a!r})")
    lines.append("chain = " + " @ ".join(f"T{i}" for i in range(1, n + 1)))
    return {"part1_answers": part1, "part2_answers": part2, "part3_answers": "\n".join(lines) + "\n"}


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
