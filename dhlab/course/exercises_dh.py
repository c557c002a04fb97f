"""Exercise checks for the DH notebooks: 5 (the convention), 6 (worked examples), 7 (the SSRMS).

Built on :mod:`dhlab.course.exercises` (its :class:`~dhlab.course.exercises.Feedback`,
:class:`~dhlab.course.exercises.Exercise`, ``check_matrix`` and ``check_value``), with
the checks that need the geometry of DH frames, in four modules re-exported here:

* :mod:`~dhlab.course.exercises_dh_rules`: notebook 5 (5.1 the case of each x_i, 5.2 a row
  from two frames);
* :mod:`~dhlab.course.exercises_dh_frames`: notebook 5's exercise arm, and whole tables (5.3, 6.3);
* :mod:`~dhlab.course.exercises_dh_links`: notebook 6 (6.1 a link matrix, 6.2 the wrist centre);
* :mod:`~dhlab.course.exercises_dh_ssrms`: notebook 7 (7.1-7.3, the SSRMS's C++ program).

The feedback names the joint and the quantity that is off ("joint 2: your α1 is -90°, but z0
and z1 are parallel") without giving the answer away, and no answer makes a check raise. A row,
a table or a link matrix written in modified DH (Craig's convention, :mod:`dhlab.mdh`) is named
as such ("this table is in modified DH (Craig): …"), with what the course's standard DH changes.

>>> ex = exercise("5.1")
>>> ex.check({1: "skew", 2: "parallel", 3: "intersect"})
✓ Exercise 5.1: correct: the cases of x1 … x3 are right.
>>> check_table([("q1", 0.5, 0.2, -90), ("q2 - 90", 0, 0.5, -90), ("q3", 0, 0, -90), ("q4", 0.5, 0, 0)])
✗ your table is not right yet: fix this first (the joints after it are checked next).
  • joint 3: your α2 is -90°, but z1 and z2 (the axes of joints 2 and 3) are parallel: α2 must be 0° or 180°.
"""
from __future__ import annotations

from ..i18n import N_, _
from ..validation import DHLabError
from .exercises import Exercise
from .exercises_dh_common import ANGLE_TOL, Relation, axis_relation
from .exercises_dh_frames import check_table, compare_robots, four_axis_arm, show_axes
from .exercises_dh_rules import ROW_EXERCISE, check_dh_row, check_x_cases, row_exercise_frames
from .exercises_dh_links import WRIST_Q_DEG, check_link_matrix, check_wrist_centre, link_exercise_robot
from .exercises_dh_ssrms import (check_key_jump, check_parallel_pairs, check_thlist_slots, parallel_pairs,
                                 printed_key_position, thlist_slot)

__all__ = [
    "exercise", "available", "UnknownExercise",
    "Relation", "axis_relation", "four_axis_arm", "show_axes", "ANGLE_TOL",
    "check_x_cases", "row_exercise_frames", "check_dh_row", "check_table", "compare_robots",
    "link_exercise_robot", "check_link_matrix", "WRIST_Q_DEG", "check_wrist_centre",
    "thlist_slot", "check_thlist_slots", "parallel_pairs", "check_parallel_pairs",
    "printed_key_position", "check_key_jump", "ROW_EXERCISE",
]


# --- the exercises of notebooks 5-7, with their hints ---------------------------------------------------
def _rows_hint_arm():
    return [N_("Draw x1 first: z0 and z1 are skew, so x1 is their common normal, from z0 towards z1. "
               "Then d1, a1 and α1 follow from rules 11-13."),
            N_("z1 ∥ z2: α2 is 0° or 180°; x2 runs along a common normal from z1 to z2. At q = 0, x1 and x2 "
               "are not parallel, so θ2 has an offset."),
            N_("Frame 4 sits at the star, with z4 along z3 (rule 9).")]


_COURSE = {
    "5.1": lambda: Exercise("5.1", N_("the case of each x_i"), check_x_cases, [
        N_("Look at z_(i−1) and z_i (the axes of joints i and i+1): do they meet, are they parallel, or neither?"),
        N_("Skew lines are not parallel and never meet: their common normal is unique (case 3).")]),
    "5.2": lambda: Exercise("5.2", N_("a DH row from two frames"), check_dh_row, [
        N_("Read the figure, one motion at a time: θ turns about z_(i−1) until x_(i−1) points along x_i; "
           "d is how far along z_(i−1) the foot of x_i (where x_i crosses z_(i−1)) is from O_(i−1)."),
        N_("a is how far O_i is from that foot, measured along x_i; α turns about x_i until z_(i−1) "
           "points along z_i (right-hand rule for the signs)."),
        N_("Give the angles in degrees.")]),
    "5.3": lambda: Exercise("5.3", N_("the table of the 4-axis arm"), lambda rows: check_table(rows, "arm"),
                            _rows_hint_arm()),
    "6.1": lambda: Exercise("6.1", N_("¹A₂ by hand"), lambda M: check_link_matrix(M, 2), [
        N_("Put θ2 = q2 + 90° and α2 = −90° into the general A of rule 14."),
        N_("cos(q2 + 90°) = −S2, sin(q2 + 90°) = C2, cos(−90°) = 0, sin(−90°) = −1.")]),
    "6.2": lambda: Exercise("6.2", N_("the wrist centre"), check_wrist_centre, [
        N_("The axes of joints 4, 5 and 6 meet in one point, O4 = O5: the wrist centre."),
        N_("From T = robot.fk(q): p_w = p − l4·a, with a = T[:3, 2] and l4 = 4.")]),
    "6.3": lambda: Exercise("6.3", N_("another valid table of the R-P-P-R robot"),
                            lambda rows: check_table(rows, "seed002_4dof", different=True), [
        N_("z1 and z2 intersect: x2 = ±(z1 × z2). Choose the other sign than the slide."),
        N_("Turning x2 by 180° changes θ2 by 180° and the sign of α2; the next row's θ3 then changes by 180°."),
        N_("Or use note 002-n2: joint 3 is prismatic, so the line z2 may be moved sideways (a2 ≠ 0), "
           "if row 3 moves the origin back (a3 = −a2).")]),
    "7.1": lambda: Exercise("7.1", N_("the THList slot of each joint"), check_thlist_slots, [
        N_("configurarTH pushes two matrices per link (THz, then THx), starting with the base's pair."),
        N_("Key '1' (code 97) writes THList[2] for joint 1.")]),
    "7.2": lambda: Exercise("7.2", N_("which joint axes stay parallel"), check_parallel_pairs, [
        N_("Not only consecutive joints: if z2 ∥ z3 and z3 ∥ z4, then z2 ∥ z4."),
        N_("A pair that is parallel at θ = 0 must stay parallel when any joint turns.")]),
    "7.3": lambda: Exercise("7.3", N_("where the printed key handler sends the arm"), check_key_jump, [
        N_("As printed, the key of joint k sets THList[2k] = THx, and THx is the identity at that moment."),
        N_("Both slots stay overwritten: multiply the 14 factors with Tz[θ2, 6] and Tz[θ5, 6] replaced by "
           "the identity, all joints at 0.")]),
}


def available() -> list:
    """The keys of the exercises of notebooks 5-7."""
    return list(_COURSE)


class UnknownExercise(DHLabError, KeyError):
    """``exercise(key)`` with a key notebooks 5-7 do not have."""

    __str__ = DHLabError.__str__


def exercise(key: str) -> Exercise:
    """A fresh :class:`~dhlab.course.exercises.Exercise` of notebooks 5-7, e.g. ``exercise("5.3")``."""
    if not isinstance(key, str) or key not in _COURSE:
        raise UnknownExercise(_("no exercise {key!r} in notebooks 5-7: the keys are {keys} (notebooks 1-4: "
                                "dhlab.course.exercises.exercise).").format(key=key, keys=", ".join(_COURSE)))
    return _COURSE[key]()
