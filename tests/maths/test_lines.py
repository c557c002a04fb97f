"""dhlab.lines: how two lines in space lie (the three cases of x_i, and coincident lines),
the common normal's length and direction, the angle, the foot point, closest points."""
import math

import numpy as np
import pytest

from dhlab import exercises_dh
from dhlab.assignment import reference as puma
from dhlab.errors import DHLabError
from dhlab.lines import Line, LineRelation, closest_points, relation

Z = Line((0, 0, 0), (0, 0, 1))                 # the z axis


# --- the four kinds ---------------------------------------------------------------------------
def test_intersecting_lines():
    rel = relation(Z, Line((0, 0, 2), (1, 0, 1)))
    assert rel.kind == "intersect"
    assert rel.distance == pytest.approx(0, abs=1e-15)
    assert rel.angle == pytest.approx(45) and rel.acute == pytest.approx(45)
    np.testing.assert_allclose(rel.foot, [0, 0, 2], atol=1e-15)                # the intersection
    np.testing.assert_allclose(rel.normal, [0, 1, 0], atol=1e-15)              # along z × (1, 0, 1)


def test_parallel_lines_same_and_opposite_sense():
    same = relation(Z, Line((3, 4, 9), (0, 0, 2)))
    assert (same.kind, same.distance, same.angle, same.acute) == ("parallel", 5.0, 0.0, 0.0)
    np.testing.assert_allclose(same.normal, [0.6, 0.8, 0], atol=1e-15)        # from a towards b
    np.testing.assert_array_equal(same.foot, [3, 4, 9])                        # every point is as near: b's own
    opposite = relation(Z, Line((3, 4, 9), (0, 0, -1)))
    assert (opposite.kind, opposite.distance, opposite.angle, opposite.acute) == ("parallel", 5.0, 180.0, 0.0)
    assert opposite.is_parallel and same.is_parallel


def test_skew_lines_common_normal_from_a_towards_b():
    rel = relation(Z, Line((0.2, 0, 0.5), (0, 1, 0)))
    assert rel.kind == "skew" and rel.distance == pytest.approx(0.2) and rel.angle == pytest.approx(90)
    np.testing.assert_allclose(rel.foot, [0.2, 0, 0.5], atol=1e-15)
    np.testing.assert_allclose(rel.normal, [1, 0, 0], atol=1e-15)
    other_side = relation(Z, Line((-0.2, 0, 0.5), (0, 1, 0)))
    np.testing.assert_allclose(other_side.normal, [-1, 0, 0], atol=1e-15)     # still from a towards b
    assert not rel.is_parallel


def test_coincident_lines_have_no_normal():
    rel = relation(Z, Line((0, 0, 7), (0, 0, -3)))
    assert (rel.kind, rel.distance, rel.angle, rel.normal) == ("coincident", 0.0, 180.0, None)
    assert rel.is_parallel


def test_the_angle_is_between_directed_lines_and_acute_ignores_the_sense():
    for theta in (0.0, 10.0, 45.0, 90.0, 120.0, 179.0):
        t = math.radians(theta)
        rel = relation(Z, Line((1, 0, 0), (0, math.sin(t), math.cos(t))))
        assert rel.angle == pytest.approx(theta, abs=1e-12)
        assert rel.acute == pytest.approx(min(theta, 180 - theta), abs=1e-12)


# --- the geometry holds for random lines ---------------------------------------------------------
def test_random_lines_foot_normal_and_distance_agree():
    rng = np.random.default_rng(1)
    for _ in range(300):
        a = Line(rng.uniform(-3, 3, 3), rng.normal(size=3))
        b = Line(rng.uniform(-3, 3, 3), rng.normal(size=3))
        rel = relation(a, b)
        ca, cb = closest_points(a, b)
        assert rel.kind == "skew"
        np.testing.assert_allclose(rel.foot, cb, atol=1e-12)
        assert b.distance_to_point(rel.foot) < 1e-12                        # the foot is on b ...
        assert a.distance_to_point(rel.foot - rel.distance * rel.normal) < 1e-11   # ... the normal reaches a
        assert np.linalg.norm(cb - ca) == pytest.approx(rel.distance, abs=1e-12)
        np.testing.assert_allclose(cb - ca, rel.distance * rel.normal, atol=1e-11)
        assert abs(rel.normal @ a.direction) < 1e-12 and abs(rel.normal @ b.direction) < 1e-12
        assert np.linalg.norm(rel.normal) == pytest.approx(1)


def test_the_relation_does_not_depend_on_where_the_points_are_or_the_directions_length():
    rng = np.random.default_rng(2)
    a = Line((0.1, 0.2, 0.3), (1, 2, 2))
    b = Line((1, -1, 0), (0, 1, 1))
    rel = relation(a, b)
    for _ in range(20):
        s, t, k1, k2 = rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(0.1, 9), rng.uniform(0.1, 9)
        moved = relation(Line(a.point + s * a.direction, k1 * a.direction),
                         Line(b.point + t * b.direction, k2 * b.direction))
        assert moved.kind == rel.kind
        assert moved.distance == pytest.approx(rel.distance, abs=1e-12)
        assert moved.angle == pytest.approx(rel.angle, abs=1e-12)
        np.testing.assert_allclose(moved.foot, rel.foot, atol=1e-12)
        np.testing.assert_allclose(moved.normal, rel.normal, atol=1e-12)


def test_reversing_a_direction_turns_the_angle_and_flips_the_intersection_normal():
    b = Line((0, 0, 1), (1, 0, 0))
    forward, backward = relation(Z, b), relation(Z, Line(b.point, -b.direction))
    assert backward.angle == pytest.approx(180 - forward.angle)
    np.testing.assert_allclose(backward.normal, -forward.normal, atol=1e-15)


# --- directions that are not unit vectors -----------------------------------------------------------
def test_directions_of_any_length_are_scaled_to_length_1():
    line = Line([1, 2, 3], [0, 3, 4])
    np.testing.assert_allclose(line.direction, [0, 0.6, 0.8])
    assert line.distance_to_point([1, 2, 3] + np.array([0, 3, 4])) == pytest.approx(0, abs=1e-15)
    assert line.distance_to_point([2, 2, 3]) == pytest.approx(1)
    np.testing.assert_allclose(line.nearest_point([2, 5, 7]), [1, 5, 7])
    rel = relation(((0, 0, 0), (0, 0, 1e-6)), ((1, 0, 0), (0, 0, 250)))
    assert rel.kind == "parallel" and rel.distance == pytest.approx(1)


def test_a_line_is_a_frozen_copy():
    p = np.array([1.0, 2.0, 3.0])
    line = Line(p, (0, 0, 1))
    p[0] = 99.0
    assert line.point[0] == 1.0
    with pytest.raises(ValueError):
        line.point[0] = 5.0


# --- nearly parallel lines: the careful closest-point formula ------------------------------------------
@pytest.mark.parametrize("eps", [1e-4, 1e-6, 1e-8])
def test_nearly_parallel_lines_closest_points_stay_accurate(eps):
    """Line b, ``eps`` rad off the z axis, passes 0.5 from it: its closest points to z are
    exactly (0, 0, 0) and (0.5, 0, 0), whatever ``eps``. The textbook form, with
    1 − (u·v)² ≈ eps² in the denominator, loses every digit at eps = 1e-8 (it divides by 0).

    The axes are turned only by signed permutations (exact in floating point): a rounded
    direction of a general rotation moves these points by about 1e-16 · 0.5 / eps², which
    no formula can undo, so a test with one would measure the input's rounding."""
    rng = np.random.default_rng(int(-math.log10(eps)))
    for _ in range(10):
        R = np.eye(3)[rng.permutation(3)] * rng.choice([-1, 1], 3)
        shift = rng.uniform(-1, 1, 3)
        a = Line(shift, R @ [0, 0, 1])
        b = Line(shift + R @ [0.5, eps * 3, 3], R @ [0, eps, 1])     # (0.5, 0, 0) + 3·(0, eps, 1)
        rel = relation(a, b)
        ca, cb = closest_points(a, b)
        np.testing.assert_allclose(ca, shift, atol=1e-7)
        np.testing.assert_allclose(cb, shift + R @ [0.5, 0, 0], atol=1e-7)
        np.testing.assert_array_equal(rel.foot, cb)
        assert rel.kind == "skew" and rel.distance == pytest.approx(0.5, abs=1e-12)
        assert rel.acute == pytest.approx(math.degrees(math.atan(eps)), rel=1e-9)
        np.testing.assert_allclose(rel.normal, R @ [1, 0, 0], atol=1e-12)


def test_exactly_parallel_lines_closest_points_go_through_bs_point():
    b = Line((3, 4, 9), (0, 0, 1))
    ca, cb = closest_points(Z, b)
    np.testing.assert_array_equal(cb, [3, 4, 9])
    np.testing.assert_allclose(ca, [0, 0, 9])


# --- the tolerances ---------------------------------------------------------------------------------
def test_tol_decides_whether_lines_meet_and_angle_tol_whether_they_are_parallel():
    b = Line((0.001, 0, 0), (0, 1, 0))                               # misses the z axis by 1 mm
    assert relation(Z, b).kind == "skew"
    assert relation(Z, b, tol=2e-3).kind == "intersect"
    tilted = Line((1, 0, 0), (0, math.tan(math.radians(0.3)), 1))   # 0.3° off z
    assert relation(Z, tilted).kind == "skew"
    assert relation(Z, tilted, angle_tol=math.radians(0.5)).kind == "parallel"
    on_z = Line((1e-4, 0, 0), (0, math.tan(math.radians(0.3)), 1))
    assert relation(Z, on_z, tol=1e-3, angle_tol=math.radians(0.5)).kind == "coincident"


def test_zero_tolerances_mean_exact():
    assert relation(Z, Line((0, 0, 5), (0, 0, 1)), tol=0, angle_tol=0).kind == "coincident"
    assert relation(Z, Line((1, 0, 5), (0, 0, 1)), tol=0, angle_tol=0).kind == "parallel"
    assert relation(Z, Line((0, 0, 5), (1, 0, 0)), tol=0, angle_tol=0).kind == "intersect"


# --- the three modules that use it --------------------------------------------------------------------
def test_the_grader_uses_dhlab_lines_with_its_tolerances():
    assert puma.Line is Line
    tilted = Line((1, 0, 0), (0, math.tan(math.radians(0.3)), 1))
    rel = puma.relation(Z, tilted)
    assert isinstance(rel, LineRelation) and rel.kind == "parallel"               # within 0.5°
    assert puma.relation(Z, Line((0.001, 0, 0), (0, 1, 0))).kind == "intersect"  # within 2 mm
    assert puma.relation(Z, Line((0.01, 0, 0), (0, 1, 0))).kind == "skew"


def test_exercises_axis_relation_is_the_same_relation_rounded():
    rng = np.random.default_rng(4)
    for _ in range(50):
        p1, u1, p2, u2 = rng.uniform(-1, 1, (4, 3))
        mine = exercises_dh.axis_relation(p1, u1, p2, u2)
        rel = relation(Line(p1, u1), Line(p2, u2))
        assert mine.kind == rel.kind
        assert mine.distance == pytest.approx(rel.distance, abs=1e-12)
        assert mine.angle == pytest.approx(rel.angle, abs=1e-9)


# --- bad input ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("point, direction, words", [
    ((0, 0, 0), (0, 0, 0), "non-zero direction"),
    ((0, 0), (0, 0, 1), "Line point must be 3 numbers"),
    ((0, 0, 0), (0, 0, 1, 0), "Line direction must be 3 numbers"),
    ((0, math.nan, 0), (0, 0, 1), "finite"),
    ((0, 0, 0), (0, math.inf, 1), "finite"),
    ("origin", (0, 0, 1), "Line point must be numbers"),
    ((0, 0, 0), ("x", "y", "z"), "Line direction must be numbers"),
])
def test_bad_lines_raise_a_clear_error(point, direction, words):
    with pytest.raises(DHLabError, match=words):
        Line(point, direction)


@pytest.mark.parametrize("a, b, kwargs, words", [
    ((0, 0, 1), Z, {}, "line a must be a dhlab.lines.Line or a \\(point, direction\\) pair"),
    (Z, "z axis", {}, "line b must be"),
    (Z, ((0, 0, 0), (0, 0, 0)), {}, "non-zero direction"),
    (Z, Z, {"tol": -1e-9}, "tol must be a number ≥ 0"),
    (Z, Z, {"tol": "small"}, "tol must be a number ≥ 0"),
    (Z, Z, {"angle_tol": math.nan}, "angle_tol must be a number ≥ 0"),
    (Z, Z, {"angle_tol": 2.0}, "below π/2"),
])
def test_bad_relation_input_raises_a_clear_error(a, b, kwargs, words):
    with pytest.raises(DHLabError, match=words):
        relation(a, b, **kwargs)


def test_closest_points_refuses_what_is_not_a_line():
    with pytest.raises(DHLabError, match="line b must be"):
        closest_points(Z, None)
