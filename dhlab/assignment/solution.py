"""The solved notebook: the assignment's answers, computed from the robot, never stored.

The course never keeps the teacher's solutions in a file: students install the course by
cloning its repository, so any file there is theirs too. The grader already knows one valid
answer for any robot — the reference of :mod:`dhlab.assignment.reference` for the PUMA 560, the
reference solution of :mod:`dhlab.assignment.model` for a personal variant
(:mod:`dhlab.assignment.variants`) — so the solutions are written from it when a teacher asks
(``dhlab-assign solutions``, the grader's self-check, ``make notebooks``):

* :func:`answers` — the three answer cells' code, written as a teacher would type it
  (``n_links = …``, ``joint_types = "…"``, ``link_points = {...}``,
  ``T1 = Tz(q1, d1) @ Tx(α1, a1)`` …, ``chain = T1 @ … @ Tn``: the example below);
* :func:`solved_notebook` — a student notebook with them in its answer cells, between
  ``### BEGIN SOLUTION`` and ``### END SOLUTION``: the source notebook nbgrader expects (its
  ``generate_assignment``, like :mod:`dhlab.grading.release.generate`, turns it back into the
  student notebook); its check cells get back the hidden line that gives nbgrader the part's
  partial credit (``feedback_1.score``, between ``### BEGIN HIDDEN TESTS`` and ``### END HIDDEN TESTS``).

A worked example, for the Adept Cobra 600 as published (four joints, the third one slides):

>>> from dhlab.assignment.model import build
>>> code = answers(build("cobra600"))
>>> print(code["part1_answers"])
n_links = 5
n_joints = 4
joint_types = "RRPR"
x_cases = ["parallel", "parallel", "parallel"]
>>> print(code["part3_answers"])
T1 = Tz(q1, 0.387) @ Tx(0, 0.325)
T2 = Tz(q2, 0) @ Tx(180, 0.275)
T3 = Tz(0, q3) @ Tx(0, 0)
T4 = Tz(q4, 0.1) @ Tx(0, 0)
chain = T1 @ T2 @ T3 @ T4
>>> cell = {"cell_type": "code", "source": "# Part 3: write T1 … T4 below\\n# YOUR CODE HERE",
...         "metadata": {"nbgrader": {"grade_id": "part3_answers", "solution": True}}}
>>> solved = solved_notebook({"cells": [cell]}, build("cobra600"))
>>> print(solved["cells"][0]["source"])                     # doctest: +ELLIPSIS
# Part 3: write T1 … T4 below
### BEGIN SOLUTION
T1 = Tz(q1, 0.387) @ Tx(0, 0.325)
...
chain = T1 @ T2 @ T3 @ T4
### END SOLUTION
"""
from __future__ import annotations

import copy
import math
import re

from ..i18n import N_, _
from .model import rows_from_frames
from .reference import reference, relation

__all__ = ["ANSWER_MARKER", "ANSWER_MARKERS", "is_answer_marker", "BEGIN", "END", "ANSWER_CELLS", "answers",
           "part1_answers", "part2_answers",
           "part3_answers", "solved_notebook", "number"]

ANSWER_MARKER = N_("# YOUR CODE HERE")   # where the student notebook's answer cell asks for the answer
# ... and in each language of the course (the Spanish one from the catalog; a test keeps them equal)
ANSWER_MARKERS = {"en": ANSWER_MARKER, "es": "# ESCRIBA SU CÓDIGO AQUÍ"}
BEGIN, END = "### BEGIN SOLUTION", "### END SOLUTION"
HIDDEN_BEGIN, HIDDEN_END = "### BEGIN HIDDEN TESTS", "### END HIDDEN TESTS"
# a check cell's feedback variable, e.g. "feedback_1 = check_part1(globals())"
FEEDBACK = re.compile(r"^(\w+) = check_part\d\(", re.M)
ANSWER_CELLS = ("part1_answers", "part2_answers", "part3_answers")
DIGITS = 6             # metres and degrees: a micrometre, a millionth of a degree (the grader allows 2 mm, 0.5°)


def number(x: float) -> str:
    """A number as a teacher types it: no trailing zeros, no ``-0``.

    >>> number(0.15005000000000002), number(-90.0), number(-1e-12), number(1 / 3)
    ('0.15005', '-90', '0', '0.333333')
    """
    value = round(float(x), DIGITS) + 0.0          # + 0.0: -0.0 becomes 0.0
    return str(int(value)) if value == int(value) else repr(value)


def _angle(radians: float) -> float:
    """Degrees in (-180, 180]: the way an offset is written (q3 - 90, never q3 + 270)."""
    degrees = math.degrees(radians) % 360.0
    return degrees - 360.0 if degrees > 180.0 + 1e-9 else degrees


def _joint_term(sign: int, joint: int, constant: float) -> str:
    """``±q_j + constant`` as the student writes it: ``q3``, ``-q3 + 180``, ``q3 - 90``."""
    term = ("-" if sign < 0 else "") + f"q{joint + 1}"
    if round(constant, DIGITS) == 0:
        return term
    return f"{term} {'-' if constant < 0 else '+'} {number(abs(constant))}"


def _robot(robot):
    return reference() if robot is None else robot


def part1_answers(robot=None) -> str:
    """Part 1: the counts, the joint types and how each x_i is found (default robot: the PUMA 560).
    Two axes on one line are case 2 of the DH rules, as parallel axes are (the check accepts both)."""
    robot = _robot(robot)
    cases = [relation(robot.axes[i - 1], robot.axes[i]).kind for i in range(1, robot.n)]
    cases = ", ".join(f'"{"parallel" if case == "coincident" else case}"' for case in cases)
    return (f"n_links = {robot.n + 1}\nn_joints = {robot.n}\njoint_types = \"{robot.kinds}\"\n"
            f"x_cases = [{cases}]")


def _local_points(robot, k: int, frames):
    """Link k's points in frame k: the reference frame's, or ``frames[k]``'s (another valid placing)."""
    if frames is None:
        return robot.local_points(k)
    F = frames[k]
    return (robot.world_points(k) - F[:3, 3]) @ F[:3, :3]


def part2_answers(robot=None, frames=None) -> str:
    """Part 2: each link's points in its own DH frame (the reference's, or ``frames``: any valid
    placing, one 4×4 pose per link, frame 0 the world), as the points table orders them."""
    robot = _robot(robot)
    lines = ["link_points = {"]
    for k in range(len(robot.points)):
        points = ", ".join("(" + ", ".join(number(v) for v in p) + ")" for p in _local_points(robot, k, frames))
        lines.append(f"    {k}: [{points}],")
    return "\n".join(lines + ["}"])


def part3_answers(robot=None, frames=None) -> str:
    """Part 3: ``T_i = Tz(θ_i, d_i) @ Tx(α_i, a_i)`` of the reference rows, or of the rows that
    ``frames`` make (degrees, metres), then the chain. A revolute joint's variable goes in θ, a
    prismatic one's in d."""
    robot = _robot(robot)
    rows = robot.rows if frames is None else rows_from_frames(robot, frames)
    lines = []
    for i, ((sign, joint, theta, d, a, alpha), kind) in enumerate(zip(rows, robot.kinds), start=1):
        if kind == "P":
            z = f"Tz({number(_angle(theta))}, {_joint_term(sign, joint, d)})"
        else:
            z = f"Tz({_joint_term(sign, joint, _angle(theta))}, {number(d)})"
        lines.append(f"T{i} = {z} @ Tx({number(_angle(alpha))}, {number(a)})")
    lines.append("chain = " + " @ ".join(f"T{i}" for i in range(1, robot.n + 1)))
    return "\n".join(lines)


def answers(robot=None, frames=None) -> dict:
    """grade_id -> the code of that answer cell, for ``robot`` (default: the PUMA 560; else an
    :class:`~dhlab.assignment.model.AssignmentRobot`, e.g. a variant's ``robot_of_variant(v)``),
    with its reference frames or another valid placing ``frames`` (a variant's robot only)."""
    robot = _robot(robot)
    return {"part1_answers": part1_answers(robot), "part2_answers": part2_answers(robot, frames),
            "part3_answers": part3_answers(robot, frames)}


def _source(cell) -> str:
    source = cell.get("source", "")
    return "".join(source) if isinstance(source, list) else source


def is_answer_marker(line: str) -> bool:
    """Whether ``line`` is the answer marker of a student notebook, in any language of the course.

    >>> [is_answer_marker(line) for line in ("    # YOUR CODE HERE", "# ESCRIBA SU CÓDIGO AQUÍ", "x = 1")]
    [True, True, False]
    """
    return line.strip() in ANSWER_MARKERS.values()


def _with_solution(source: str, code: str) -> str:
    """The answer cell's text with ``code`` between BEGIN and END SOLUTION in place of the
    marker line (indented like it); after the text when the cell has no marker."""
    lines = source.split("\n")
    at = next((i for i, line in enumerate(lines) if is_answer_marker(line)), None)
    indent = "" if at is None else lines[at][:len(lines[at]) - len(lines[at].lstrip())]
    block = [indent + line for line in [BEGIN, *code.split("\n"), END]]
    if at is None:
        return "\n".join([*(lines if source.strip() else []), *block])
    return "\n".join(lines[:at] + block + lines[at + 1:])


def _with_hidden_score(source: str) -> str:
    """A check cell's text with its part's score as a hidden test, nbgrader's partial credit
    (the student notebook has it cut out); unchanged when the cell has it or shows no feedback."""
    found = FEEDBACK.search(source)
    if found is None or HIDDEN_BEGIN in source:
        return source
    score = f"{found.group(1)}.score      " + _("# nbgrader: the partial credit of this cell")
    return "\n".join([source, HIDDEN_BEGIN, score, HIDDEN_END])


def solved_notebook(student_nb: dict, robot=None) -> dict:
    """The solved (source) notebook of ``student_nb`` (a new dict): each answer cell
    (:data:`ANSWER_CELLS`) holds :func:`answers` of ``robot`` between ``### BEGIN SOLUTION`` and
    ``### END SOLUTION``; each graded check cell its hidden score line. The nbgrader metadata is
    kept; the ``deletable``/``editable`` flags that releasing put on the nbgrader cells are taken
    off (the source has none: releasing sets them)."""
    nb = copy.deepcopy(student_nb)
    code = answers(robot)
    for cell in nb.get("cells", []):
        meta = cell.get("metadata", {})
        if "nbgrader" not in meta:
            continue
        meta.pop("deletable", None)
        meta.pop("editable", None)
        grade_id = meta["nbgrader"].get("grade_id")
        if grade_id in code:
            cell["source"] = _with_solution(_source(cell), code[grade_id])
        elif meta["nbgrader"].get("grade") and cell.get("cell_type") == "code":
            cell["source"] = _with_hidden_score(_source(cell))
    return nb
