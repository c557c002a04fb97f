"""The exercises of notebooks 1-7, with their right answers and the feedback for each typical mistake.

One registry for the whole course: :func:`exercise` makes any of them by its key ("1.1" … "7.3"),
:func:`available` lists the keys. The exercises live in one module per notebook (or subject):

* :mod:`~dhlab.course.exercises.basics` — notebook 1 (1.1-1.3);
* :mod:`~dhlab.course.exercises.homogeneous` — notebook 2 (2.1-2.5), and seed 001's listing
  :func:`seed001_DefinirTHz`;
* :mod:`~dhlab.course.exercises.first_robots` — notebook 3 (3.1-3.5), seed 004's two robots;
* :mod:`~dhlab.course.exercises.pr_mechanism` — notebook 4 (4.1-4.5), the P-R mechanism;
* :mod:`~dhlab.course.exercises.dh_rules` — notebook 5 (5.1 the case of each x_i, 5.2 a row from two frames);
* :mod:`~dhlab.course.exercises.dh_tables` — notebook 5's exercise arm, and whole DH tables (5.3, 6.3);
* :mod:`~dhlab.course.exercises.dh_links` — notebook 6 (6.1 a link matrix, 6.2 the wrist centre);
* :mod:`~dhlab.course.exercises.ssrms` — notebook 7 (7.1-7.3, the SSRMS's C++ program);
* :mod:`~dhlab.course.exercises.dh_common` — what the DH checks share (reading an answer, joint axes as lines).

The checks they are built of are :mod:`dhlab.course.checks`; the names a notebook uses are re-exported
here, so that one import serves a notebook. A check says *what* is wrong and *where*, and never raises on a
student's answer.

>>> import sympy as sp
>>> th = sp.Symbol("theta")
>>> R = sp.Matrix([[sp.cos(th), -sp.sin(th)], [sp.sin(th), sp.cos(th)]])
>>> check_matrix(R, R, name="R")
✓ correct: R is right.
>>> check_matrix(R.T, R, name="R")
✗ R is not right yet.
  • your rotation block is the transpose of the right one: that is the rotation the other way (by −θ instead of θ).

>>> from dhlab import deg2rad
>>> ex = exercise("1.1")
>>> ex.check([45, -90])
✗ Exercise 1.1: your q is not right yet.
  • θ0: you gave 45, which is the angle in degrees: the API takes radians. Write deg2rad(45) (or 45·π/180).
  • θ1: you gave -90, which is the angle in degrees: the API takes radians. Write deg2rad(-90) (or -90·π/180).
  Stuck? Call .hint() on this exercise (2 hints).
>>> ex.check(deg2rad([45, -90]))
✓ Exercise 1.1: correct: your q is right.
>>> exercise("5.1").check({1: "skew", 2: "parallel", 3: "intersect"})
✓ Exercise 5.1: correct: the cases of x1 … x3 are right.
>>> try:
...     exercise("5.4")
... except UnknownExercise as error:
...     print(str(error).split(":")[0])
no exercise '5.4' in the course (did you mean '5.3'?)
"""
from __future__ import annotations

import difflib

from ...errors import DHLabError
from ...i18n import _
from ..checks.feedback import NOT_ANSWERED, Exercise, Feedback
from ..checks.matrix import TRANSPOSED_ROTATION, check_function, check_matrix
from ..checks.values import check_solutions, check_value
from ..checks.words import check_choice, check_terms
from . import basics, dh_links, dh_rules, dh_tables, first_robots, homogeneous, pr_mechanism, ssrms
from .dh_common import ANGLE_TOL, Relation, axis_relation
from .dh_links import WRIST_Q_DEG, check_link_matrix, check_wrist_centre, link_exercise_robot
from .dh_rules import ROW_EXERCISE, check_dh_row, check_x_cases, row_exercise_frames
from .dh_tables import check_table, compare_robots, four_axis_arm, show_axes
from .homogeneous import seed001_DefinirTHz
from .ssrms import (
    check_key_jump,
    check_parallel_pairs,
    check_thlist_slots,
    parallel_pairs,
    printed_key_position,
    thlist_slot,
)

__all__ = [
    "exercise", "available", "UnknownExercise",
    # the checks, for an exercise a notebook makes itself
    "Feedback", "Exercise", "NOT_ANSWERED", "TRANSPOSED_ROTATION", "check_matrix", "check_value",
    "check_solutions", "check_choice", "check_terms", "check_function",
    # what the notebooks use besides their exercises
    "seed001_DefinirTHz",
    "Relation", "axis_relation", "four_axis_arm", "show_axes", "ANGLE_TOL",
    "check_x_cases", "row_exercise_frames", "check_dh_row", "check_table", "compare_robots",
    "link_exercise_robot", "check_link_matrix", "WRIST_Q_DEG", "check_wrist_centre",
    "thlist_slot", "check_thlist_slots", "parallel_pairs", "check_parallel_pairs",
    "printed_key_position", "check_key_jump", "ROW_EXERCISE",
]

# key -> a function making a fresh Exercise (fresh: its hints start again from the first), in the order of the
# notebooks ("6.3" is in dh_tables, "6.1" in dh_links: the keys are sorted as numbers, "5.10" after "5.9")
_COURSE = dict(sorted(((key, make) for module in (basics, homogeneous, first_robots, pr_mechanism, dh_rules,
                                                  dh_tables, dh_links, ssrms)
                       for key, make in module.EXERCISES.items()),
                      key=lambda item: [int(part) for part in item[0].split(".")]))


def available() -> list:
    """The keys of the course's exercises, in the order of the notebooks.

    >>> available()[:3], available()[-1]
    (['1.1', '1.2', '1.3'], '7.3')
    """
    return list(_COURSE)


class UnknownExercise(DHLabError, KeyError):
    """``exercise(key)`` with a key the course does not have."""

    __str__ = DHLabError.__str__


def exercise(key: str) -> Exercise:
    """A fresh :class:`~dhlab.course.checks.feedback.Exercise` of the course by its key, e.g. ``exercise("3.1")``."""
    if not isinstance(key, str) or key not in _COURSE:
        raise UnknownExercise(_unknown_message(key))
    return _COURSE[key]()


def _unknown_message(key) -> str:
    """Why ``key`` is no exercise, with the nearest key when one is close (``5.4`` -> ``5.3``, ``3,1`` -> ``3.1``)."""
    keys = ", ".join(_COURSE)
    typed = str(key).strip().replace(",", ".")
    near = typed if typed in _COURSE else next(iter(difflib.get_close_matches(typed, _COURSE, n=1, cutoff=0.6)), "")
    if near:
        return _("no exercise {key!r} in the course (did you mean {near!r}?): the keys are {keys}.").format(
            key=key, near=near, keys=keys)
    return _("no exercise {key!r} in the course: the keys are {keys}.").format(key=key, keys=keys)
