"""Forwarder, kept for one release: the exercises of notebooks 5-7 now live in :mod:`dhlab.course.exercises`.

``from dhlab.course.exercises_dh import exercise`` still works (and ``exercise`` knows every key of the
course, "1.1" … "7.3"); new code writes ``from dhlab.course.exercises import exercise``. The checks are in
:mod:`dhlab.course.exercises.dh_rules`, ``dh_tables``, ``dh_links`` and ``ssrms``.
"""
from .exercises import (ANGLE_TOL, ROW_EXERCISE, WRIST_Q_DEG, Relation, UnknownExercise, available, axis_relation,
                        check_dh_row, check_key_jump, check_link_matrix, check_parallel_pairs, check_table,
                        check_thlist_slots, check_wrist_centre, check_x_cases, compare_robots, exercise,
                        four_axis_arm, link_exercise_robot, parallel_pairs, printed_key_position,
                        row_exercise_frames, show_axes, thlist_slot)

__all__ = [
    "exercise", "available", "UnknownExercise",
    "Relation", "axis_relation", "four_axis_arm", "show_axes", "ANGLE_TOL",
    "check_x_cases", "row_exercise_frames", "check_dh_row", "check_table", "compare_robots",
    "link_exercise_robot", "check_link_matrix", "WRIST_Q_DEG", "check_wrist_centre",
    "thlist_slot", "check_thlist_slots", "parallel_pairs", "check_parallel_pairs",
    "printed_key_position", "check_key_jump", "ROW_EXERCISE",
]
