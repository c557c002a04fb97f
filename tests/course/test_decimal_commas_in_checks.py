"""The course's checkers that count a row's or an answer's numbers name decimal commas (0,4)."""
from __future__ import annotations

import pytest

from dhlab import robots
from dhlab.course.exercises.dh_common import read_numbers
from dhlab.course.exercises.dh_tables import _row_problem as row_problem
from dhlab.course.predict import _at_pose as at_pose
from dhlab.i18n import speaking


@pytest.mark.parametrize("language, word", [("en", "decimal point"), ("es", "coma")])
def test_a_row_with_decimal_commas_is_named(language, word):
    robot = robots.rrr_example()
    with speaking(language):
        assert word in at_pose(("q1", 0, 4, 0, 35, 0), robot, 0, [0, 0, 0])[1]
        assert word in row_problem([("q1", 0, 4, 0, 35, 0)])
        assert word in read_numbers((0, 4, 0, 35, 1), 3, "(x, y, z)")[1]
        assert word in read_numbers("0,4", 1, "")[1]


def test_a_row_that_is_only_too_long_says_nothing_of_commas():
    robot = robots.rrr_example()
    assert "decimal" not in at_pose(("q1", 0.4, 0.35, 0, 7.5), robot, 0, [0, 0, 0])[1]
    assert "decimal" not in row_problem([("q1", 0.4, 0.35, 0, 7.5)])
    assert "decimal" not in read_numbers((0.5, 0.25, 1.5, 2.5), 3, "(x, y, z)")[1]
