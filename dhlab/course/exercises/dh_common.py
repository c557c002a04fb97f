"""What the DH exercise checks share: reading an answer, wording the feedback, joint axes as lines.

Every check of notebooks 5-7 returns a :class:`~dhlab.course.checks.feedback.Feedback` for *any*
answer: the readers here turn what cannot be read (text, NaN, a dict where a list is
asked, …) into a reason, never into an exception. Used by the modules of
:mod:`dhlab.course.exercises`, by :mod:`dhlab.course.predict` and by
:mod:`dhlab.course.lessons.ssrms_steps`.
"""
from __future__ import annotations

import math
import numbers
from dataclasses import dataclass

import numpy as np

from ...chain import Robot
from ...dh import DHRobot
from ...errors import DHLabError
from ...i18n import _
from ...lines import Line, relation
from ...mdh import MDHRobot
from ...validation import as_index, as_tolerance, describe, with_decimal_comma_note
from ..checks.feedback import Feedback, short_repr
from ..checks.reading import Refused, to_vector

__all__ = ["ANGLE_TOL", "right_answer", "wrong_answer", "number_text", "quoted", "vector_text", "read_numbers",
           "whole_number", "as_robot", "as_samples", "Relation", "axis_relation", "axes_of", "row_at_zero"]

ANGLE_TOL = 0.5          # degrees: typed answers are read to half a degree


# --- feedback in the style of dhlab.course.checks (a blank answer: checks.reading.is_unanswered and
# checks.feedback.unanswered) -----------------------------------------------------------------------------
def right_answer(name: str, items=(), plural: bool = False) -> Feedback:
    """A right answer, with ``items`` to say why; ``plural``: the name is of several things ('the cases of
    x1 … x3 are right')."""
    title = _("correct: {name} are right.") if plural else _("correct: {name} is right.")
    return Feedback("correct", title.format(name=name), items)


def wrong_answer(name: str, items, why: str = "", plural: bool = False) -> Feedback:
    """A wrong answer, one item per problem; ``why`` (optional) ends the title.

    >>> wrong_answer("your table", ["joint 3: α2 must be 0° or 180°."], "fix this first.")
    ✗ your table is not right yet: fix this first.
      • joint 3: α2 must be 0° or 180°.
    """
    if why:
        title = _("{name} are not right yet: {why}") if plural else _("{name} is not right yet: {why}")
    else:
        title = _("{name} are not right yet.") if plural else _("{name} is not right yet.")
    return Feedback("wrong", title.format(name=name, why=why), items)


def number_text(x: float, digits: int = 4) -> str:
    """A number for a message: 0.2, -90, 12 (no -0)."""
    text = f"{round(float(x), digits) + 0.0:.{digits}f}"
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return "0" if text == "-0" else text


def quoted(value) -> str:
    """A student's value quoted in a message (at most 40 characters; never raises)."""
    return short_repr(value, 40)


def vector_text(v, digits: int = 3) -> str:
    """A point or a vector for a message: ``vector_text([0.5, -0.0, 1]) == "(0.5, 0, 1)"``."""
    return "(" + ", ".join(number_text(x, digits) for x in v) + ")"


def read_numbers(answer, count: int, what: str):
    """``count`` finite real numbers, or (None, the reason they cannot be read).

    Refuses what is not a list of numbers in a given order (text, a dict, a set), NaN,
    infinity, complex numbers, ``None`` or ``True`` inside, symbols where numbers are asked.
    """
    if isinstance(answer, (dict, set, frozenset)):
        return None, _("your answer is a {type}: give {count} numbers {what}, as a list or tuple in that "
                       "order.").format(type=type(answer).__name__, count=count, what=what)
    try:
        values = to_vector(answer, _("your answer"), count)
    except Refused as why:
        return None, with_decimal_comma_note(
            _("{why} Give {count} numbers {what}.").format(why=why, count=count, what=what), answer, count)
    if isinstance(values, list):          # sympy expressions with symbols in them
        return None, _("give {count} numbers {what}, not symbols.").format(count=count, what=what)
    return [float(v) for v in values], ""


def whole_number(value):
    """``value`` as an int when it is a whole number (4, 4.0, np.int64(4)); else None (True, 4.5, nan, 'x')."""
    if isinstance(value, (bool, np.bool_)):
        return None
    if isinstance(value, numbers.Integral):
        return int(value)
    if isinstance(value, (float, np.floating)) and math.isfinite(value) and float(value).is_integer():
        return int(value)
    return None


# --- the teacher's arguments of a check -----------------------------------------------------------
def as_robot(robot, name: str = "robot", kind=DHRobot, joints: int = 1):
    """``robot`` checked: a dhlab robot of class ``kind`` (default a standard-DH robot, whose frame
    k−1 has its z on joint k's axis: the checks read the axes there) with at least ``joints`` joints."""
    if not isinstance(robot, kind):
        hint = ""
        if isinstance(robot, MDHRobot) and kind is DHRobot:
            hint = _(" It is a modified-DH (Craig) robot: convert it with dhlab.to_standard(robot).")
        elif isinstance(robot, Robot) and kind is DHRobot:
            hint = _(" (a robot built from motions has no DH frames: build it with DHRobot.from_table).")
        raise DHLabError(_("{name} must be a dhlab {kind}, e.g. dhlab.robots.ssrms(), got {value}.").format(
            name=name, kind=kind.__name__, value=describe(robot)) + hint)
    if robot.n < joints:
        message = (_("{name} has {n} joint; this check needs at least {joints}.") if robot.n == 1 else
                   _("{name} has {n} joints; this check needs at least {joints}."))
        raise DHLabError(message.format(name=name, n=robot.n, joints=joints))
    return robot


def as_samples(samples, seed):
    """How many random configurations (1 … 100000), and the seed of their generator (a whole number ≥ 0)."""
    return as_index(samples, "samples", 1, 100_000), as_index(seed, "seed", 0, 2 ** 63 - 1)


# --- lines in space (the geometry is dhlab.lines) ----------------------------------------------
@dataclass(frozen=True)
class Relation:
    """How two lines lie: ``kind`` is 'intersect', 'parallel', 'skew' or 'coincident';
    ``distance`` is the length of their common normal, ``angle`` the angle between
    their directions in degrees (0…180: 180 means parallel but opposite).
    :func:`dhlab.lines.relation`'s result, rounded for messages."""
    kind: str
    distance: float
    angle: float

    @property
    def is_parallel(self) -> bool:
        return self.kind in ("parallel", "coincident")


def axis_relation(p1, u1, p2, u2, tol: float = 1e-9) -> Relation:
    """The relation of line 1 (through ``p1``, direction ``u1``) and line 2, by
    :func:`dhlab.lines.relation`. ``tol`` is relative: lines closer than ``tol`` times
    the size of the coordinates (at least 1) meet; directions less than 1e-9 rad apart
    are parallel.

    >>> axis_relation([0, 0, 0], [0, 0, 1], [1, 0, 5], [0, 0, -1])
    Relation(kind='parallel', distance=1.0, angle=180.0)
    >>> axis_relation([0, 0, 0], [0, 0, 1], [0.2, 0, 0.5], [0, 1, 0]).kind
    'skew'
    """
    tol = as_tolerance(tol, "tol")
    a, b = Line(p1, u1), Line(p2, u2)
    scale = max(1.0, float(np.abs(a.point).max()), float(np.abs(b.point).max()))
    rel = relation(a, b, tol=tol * scale, angle_tol=1e-9)
    return Relation(rel.kind, round(rel.distance, 12) + 0.0, round(rel.angle, 9) + 0.0)


def axes_of(robot, q):
    """Joint axes of ``robot`` at ``q``: points (n,3) and unit directions (n,3); joint k is z_(k-1)."""
    F = np.asarray(robot.frames(q), dtype=float)
    return F[:-1, :3, 3], F[:-1, :3, 2]


def row_at_zero(robot, i: int):
    """(θ, d, a, α) of link i at q = 0, read from its numeric matrix (angles in degrees)."""
    A = np.asarray(robot.A(i, 0.0), dtype=float)
    theta = math.atan2(A[1, 0], A[0, 0])
    a = A[0, 3] * math.cos(theta) + A[1, 3] * math.sin(theta)
    return math.degrees(theta), float(A[2, 3]), float(a), math.degrees(math.atan2(A[2, 1], A[2, 2]))
