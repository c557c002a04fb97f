"""dhlab.course.lessons.lesson_dh_convention: notebook 5's helpers place x_i by rule 7 and measure DH rows by seed
002's sentences; checked against the geometry and the robots' own link matrices, not against typed answers."""
import math

import numpy as np
import pytest

import dhlab
from dhlab.course.lessons.lesson_dh_convention import (
    fmt,
    measured_row,
    measured_rows_agree,
    place_x,
    prismatic_a_lines,
    three_cases,
)
from dhlab.errors import DHLabError
from dhlab.transforms import dh_matrix

RNG = np.random.default_rng(11)


def _unit(v):
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)


def test_fmt_rounds_and_drops_negative_zero():
    assert fmt([-0.0, 1.23456789, -2.5]) == "(0, 1.234568, -2.5)"
    assert fmt([1e-12, 3], digits=2) == "(0, 3)"


def test_three_cases_are_one_of_each():
    z_prev, examples = three_cases()
    assert [place_x(z_prev, z_i).case for z_i in examples.values()] == [1, 2, 3]


@pytest.mark.parametrize("trial", range(20))
def test_place_x_puts_x_on_a_common_normal_from_z_prev_to_z_i(trial):
    p1, u1 = RNG.normal(size=3), _unit(RNG.normal(size=3))
    p2, u2 = RNG.normal(size=3), _unit(RNG.normal(size=3))
    placed = place_x((p1, u1), (p2, u2))
    assert placed.case == 3 and placed.kind == "skew"           # random lines are skew
    assert abs(placed.x @ u1) < 1e-9 and abs(placed.x @ u2) < 1e-9 and math.isclose(np.linalg.norm(placed.x), 1)
    assert np.linalg.norm(np.cross(placed.H - p1, u1)) < 1e-9          # H on z_(i-1)
    assert np.linalg.norm(np.cross(placed.origin - p2, u2)) < 1e-9     # O_i on z_i
    assert np.allclose(placed.origin - placed.H, placed.length * placed.x)   # x_i from z_(i-1) towards z_i
    # the common normal is the shortest segment: no other pair of points is closer
    s, t = RNG.normal(size=2)
    assert placed.length <= np.linalg.norm((p2 + t * u2) - (p1 + s * u1)) + 1e-12


def test_place_x_intersecting_and_parallel_lines():
    z_prev = ((0, 0, 0), (0, 0, 1))
    crossing = place_x(z_prev, ((2, 0, 3), (1, 0, 0)))          # meets z_prev at (0, 0, 3)
    assert crossing.case == 1 and crossing.length < 1e-12
    assert np.allclose(crossing.origin, (0, 0, 3)) and np.allclose(crossing.x, np.cross((0, 0, 1), (1, 0, 0)))
    parallel = place_x(z_prev, ((0, 2, 5), (0, 0, -1)))
    assert parallel.case == 2 and math.isclose(parallel.length, 2)
    assert np.allclose(parallel.x, (0, 1, 0)) and np.allclose(parallel.origin, (0, 2, 5))
    assert "x_i = (0, 1, 0)" in str(parallel)


def test_place_x_refuses_one_line_twice_and_bad_lines():
    with pytest.raises(DHLabError, match="same line"):
        place_x(((0, 0, 0), (0, 0, 1)), ((0, 0, 4), (0, 0, 2)))
    with pytest.raises(DHLabError):
        place_x(((0, 0, 0), (0, 0, 0)), ((1, 0, 0), (0, 1, 0)))     # no direction


@pytest.mark.parametrize("trial", range(20))
def test_measured_row_gives_back_a_random_row(trial):
    theta, alpha = RNG.uniform(-math.pi + 0.01, math.pi - 0.01, size=2)
    d, a = RNG.uniform(-2, 2, size=2)
    S_prev = dh_matrix(*RNG.uniform(-3, 3, size=4))                 # any frame in the world
    S_next = S_prev @ dh_matrix(theta, d, a, alpha)
    assert np.allclose(measured_row(S_prev, S_next), (theta, d, a, alpha), atol=1e-9)


def test_measured_row_refuses_frames_that_are_not_consecutive_dh_frames():
    S = np.eye(4)
    tilted = np.asarray(dhlab.transforms.Ry(0.3), dtype=float)        # x_1 not square to z_0
    with pytest.raises(DHLabError, match="not perpendicular"):
        measured_row(S, tilted)
    missed = np.asarray(dh_matrix(0.2, 0.5, 1.0, 0.4), dtype=float)
    missed[:3, 3] += missed[:3, 1] * 0.3                                # O_1 moved off the line through H along y_1
    with pytest.raises(DHLabError, match="misses"):
        measured_row(S, missed)
    with pytest.raises(DHLabError):
        measured_row(S, np.ones((4, 4)))                              # not a rigid transform
    with pytest.raises(DHLabError):
        measured_row("S", S)


def test_measured_rows_agree_on_the_seed_arm_and_not_on_a_wrong_robot():
    arm6 = dhlab.robots.seed002_6dof()
    Q = RNG.uniform(-math.pi, math.pi, size=(10, 6))
    assert measured_rows_agree(arm6, Q)

    other = dhlab.robots.seed002_6dof()
    other.A = lambda i, q: arm6.A(i, q + 0.1)        # the same frames, link matrices that do not match them
    assert not measured_rows_agree(other, Q)
    with pytest.raises(DHLabError):
        measured_rows_agree("arm", Q)
    with pytest.raises(DHLabError, match="6 joint values"):
        measured_rows_agree(arm6, Q[:, :4])
    with pytest.raises(DHLabError):
        measured_rows_agree(arm6, "q")


def test_prismatic_a_lines_one_line_per_prismatic_joint_and_both_sentences_agree_in_length():
    rppr = dhlab.robots.seed002_4dof()
    shifted = dhlab.DHRobot.from_table([("q1", "l1", 0, 0), (90, "d2", 0.3, 90), (0, "d3", -0.3, 0),
                                        ("q4", "l4", 0, 0)], params=rppr.params)
    lines = prismatic_a_lines(shifted, [shifted.qz, [0.5, 0.2, 0.7, -1.0]])
    assert len(lines) == 4 and all("(P)" in line for line in lines)
    for line in lines:
        along, between = (float(part.split("=")[-1]) for part in line.split(",")[-2:])
        assert math.isclose(abs(along), between, abs_tol=1e-4) and math.isclose(between, 0.3, abs_tol=1e-4)
