"""Notebook 3's helpers (dhlab.course.lessons.lesson_two_dof): the seed's matrices as printed, slips included,
measured against dhlab's robots; the link directions; the figures; the comparison table."""
import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest
import sympy as sp

from dhlab import deg2rad, robots
from dhlab.course.lessons import lesson_two_dof as lesson
from dhlab.errors import DHLabError

l1, l2, l = sp.symbols("l1 l2 l")


@pytest.fixture(scope="module")
def robot1():
    return robots.robot_no_tan_elemental_1()


@pytest.fixture(scope="module")
def robot2():
    return robots.robot_no_tan_elemental_2()


def differing_entries(M, N):
    return [(i, j) for i in range(4) for j in range(4) if sp.simplify(M[i, j] - N[i, j]) != 0]


def test_first_robot_as_printed_right_and_wrong_where_the_errata_say(robot1):
    th0, th1 = robot1.q_symbols
    printed = lesson.seed004_first_robot_printed(th0, th1, l1, l2)
    assert printed["eq. (2)"] == robot1.A(2) and printed["eq. (8)"] == robot1.A(1)
    assert differing_entries(printed["eq. (3)"], robot1.A(1)) == [(0, 3), (1, 3)]          # erratum 004-1
    assert differing_entries(printed["eq. (5) second"], robot1.A(2)) == [(0, 3), (1, 3)]   # erratum 004-3
    assert differing_entries(printed["eq. (6)"], robot1.fk_sym()) == [(0, 1)]              # erratum 004-4


def test_second_robot_as_printed_is_right(robot2):
    theta, d = robot2.q_symbols
    printed = lesson.seed004_second_robot_printed(theta, d, l)
    assert printed["eq. (10)"] == robot2.A(2) and printed["eq. (11)"] == robot2.A(1)
    assert differing_entries(printed["eq. (13)"], robot2.fk_sym()) == []


def test_link_directions_of_the_segundo_caso(robot1):
    links = lesson.link_directions(robot1, deg2rad([-60, 90]))
    assert links["link 1 [deg]"] == pytest.approx(30) and links["link 2 [deg]"] == pytest.approx(30)
    assert np.linalg.norm(links["pen"]) == pytest.approx(robot1.params["l1"] + robot1.params["l2"])
    assert np.allclose(links["joint 2"], [0.7 * np.cos(np.pi / 6), 0.7 * np.sin(np.pi / 6), 0])


def test_link_directions_wants_two_links():
    with pytest.raises(DHLabError, match="two links"):
        lesson.link_directions(_three_links(), [0, 0, 0])


def _three_links():
    import dhlab
    links = [dhlab.Link([dhlab.Rot("z", joint=True), dhlab.Move("x", 1.0)]) for _ in range(3)]
    return dhlab.Robot(links, name="three links")


def test_two_cases_figure_marks_where_eq3_puts_S1(robot1):
    fig = lesson.two_cases_figure(robot1, deg2rad([-60, 90]), wrong_S1=(-0.7, 0.0))
    left, right = fig.axes[:2]
    diamonds = [line for line in left.lines if line.get_marker() == "D"]
    assert len(diamonds) == 1 and np.allclose(diamonds[0].get_xydata(), [[-0.7, 0.0]])
    assert right.patches, "the triangle of l.169 is not drawn"


def test_three_poses_figure_one_panel_per_pose(robot2):
    poses = [([0, 0], "a"), ([deg2rad(-45), 0.3], "b"), ([deg2rad(-90), 0.3], "c")]
    fig = lesson.three_poses_figure(robot2, poses)
    assert [ax.get_title() for ax in fig.axes] == ["a", "b", "c"]


def test_seed004_comparison_agrees_where_the_seed_is_right(robot1, robot2):
    rows = lesson.seed004_comparison(robot1, robot2).splitlines()
    assert len(rows) == 6
    agree = {row.split()[0]: row for row in rows[1:]}
    assert all(" True " in agree[k] for k in ("primer", "segundo", "θ", "en"))
    assert "(not given)" in agree["reader's"]
    assert "(1.000000, 0.000000, 0.000000)" in agree["reader's"]     # l + d_max along x0
