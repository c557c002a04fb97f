"""Feedback on an offset along a run of parallel axes names the d the student changed
(dhlab.assignment.checks.offsets): on the UR5 (joints 2-3-4 parallel) and the Cobra (every axis vertical)
a slip in d2 shows only at the end of the run, where d2, d3, d4 … are equivalent fixes."""
import re

import numpy as np
import pytest

from dhlab.assignment import reference as R
from dhlab.assignment import variants as V
from dhlab.assignment.model import random_frames_from_axes
from support import written_answers as W


def _robot(key, seed=123):
    return V.robot_of_variant(V.variant(key, seed))


def _slip_d(robot, frames, k, by=0.05):
    """The rows of ``frames`` with d_k off by ``by``: the report and the charged part-3 messages."""
    rows = W.rows_in_degrees(robot, frames)
    s, j, th, d, a, al = rows[k - 1]
    rows[k - 1] = (s, j, th, d + by, a, al)
    report = W.report(W.namespace_from_rows(robot, rows, frames), robot)
    messages = [item.message for part in report.parts if part.key == "part3" for item in part.items if not item.ok]
    return report, messages


def _named(message):
    return {int(k) for advice in re.findall(r"check ([^(:;]*)", message) for k in re.findall(r"\bd(\d+)\b", advice)}


def test_a_d2_slip_on_the_reference_frames_of_a_ur5_names_d2():
    robot = _robot("ur5")
    report, messages = _slip_d(robot, list(robot.home_frames), 2)
    assert len(W.lost(report)) == 1 and len(messages) == 1
    assert _named(messages[0]) == {2}, messages[0]          # not "check d4 … or d3"


@pytest.mark.parametrize("key, k, run", [("ur5", 2, {2, 3, 4}), ("ur5", 3, {2, 3, 4}),
                                         ("cobra600", 1, {1, 2, 3, 4}), ("cobra600", 2, {1, 2, 3, 4})])
def test_on_frames_of_the_students_own_the_equivalent_offsets_are_all_named(key, k, run):
    """Slid origins (d's of the student's own): the slipped d cannot be told from the others, so
    every equivalent one is named, the slipped one among them; never a distance below the tolerance."""
    robot = _robot(key)
    rng = np.random.default_rng(7)
    for _ in range(4):
        frames = random_frames_from_axes(robot, rng, slide=0.3)
        report, messages = _slip_d(robot, frames, k)
        assert len(W.lost(report)) == 1 and len(messages) == 1, messages
        named = _named(messages[0])
        assert k in named and named <= run, messages[0]
        for distance in re.findall(r"([0-9.e-]+) m (?:short of|past|away)", messages[0]):
            assert float(distance) > R.TOL_POS, messages[0]


def test_the_cobra_reference_frames_name_the_slipped_offset():
    robot = _robot("cobra600")
    for k in (1, 2, 4):
        _, messages = _slip_d(robot, list(robot.home_frames), k)
        assert len(messages) == 1 and _named(messages[0]) == {k}, (k, messages)


def test_an_offset_off_no_parallel_run_names_only_its_own_d():
    robot = _robot("ur5")
    _, messages = _slip_d(robot, list(robot.home_frames), 5)
    assert len(messages) == 1 and _named(messages[0]) == {5}, messages
