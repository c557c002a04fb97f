"""Regression tests for the boundary bugs of the hostile sweep's KNOWN_RULES (tests/test_hostile_sweep.py):
each bad value gets a DHLabError that names the argument, and the good values still work."""
import time

import matplotlib
import numpy as np
import pytest
import sympy as sp

matplotlib.use("Agg")

import dhlab  # noqa: E402
from dhlab import DHLabError, deg2rad, rad2deg, robots  # noqa: E402
from dhlab.dh import DHRobot, RevoluteDH  # noqa: E402
from dhlab.lines import Line, closest_points, relation  # noqa: E402
from dhlab.symbolic import compact, legend  # noqa: E402
from dhlab.transforms import check_rigid  # noqa: E402

Q1 = sp.Symbol("q1")
Z = Line((0, 0, 0), (0, 0, 1))


# --- dh.py / chain.py: fk_sym(simplify=True) on a long chain -----------------------------------------
def _long_chain(n=50):
    return DHRobot([RevoluteDH(a=0.1 * (i % 3 + 1), d=0.05, alpha=[0, np.pi / 2, 0.3][i % 3]) for i in range(n)])


def test_sym_blocks_builds_the_link_matrices_once(monkeypatch):
    robot = _long_chain(12)
    calls = []
    original = DHRobot.link_matrices_sym
    monkeypatch.setattr(DHRobot, "link_matrices_sym", lambda self: calls.append(1) or original(self))
    blocks = robot._sym_blocks()
    assert len(calls) == 1
    assert len(blocks) >= 1


def test_fk_sym_timeout_counts_building_the_blocks():
    robot = _long_chain(50)
    start = time.monotonic()
    try:
        robot.fk_sym(simplify=True, timeout=1)
    except DHLabError as error:
        assert "timeout" in str(error)
    assert time.monotonic() - start < 3.0          # was 17 s: the deadline started after the blocks


def test_fk_sym_timeout_too_short_for_the_blocks_stops():
    with pytest.raises(DHLabError, match="timeout"):
        _long_chain(50).fk_sym(simplify=True, timeout=1e-6)


# --- dh.py: from_table with a degree angle beyond a full turn -------------------------------------------
@pytest.mark.parametrize("row, words", [(("q1", 0, 1, 720), "row 1, α = 720°"), (("q1", 0, 1, 1e308), "row 1, α"),
                                        (("q1 + 900", 0, 1, 0), "row 1, θ = 900°")])
def test_from_table_degrees_beyond_a_full_turn(row, words):
    with pytest.raises(DHLabError, match=words) as error:
        DHRobot.from_table([row])
    assert "more than a full turn" in str(error.value) and "deg2rad(" not in str(error.value)


def test_from_table_degrees_within_a_turn_still_work():
    robot = DHRobot.from_table([("q1 - 90", 0, 1, 360), ("q2", 0, 1, -360)])
    assert robot.n == 2


# --- units.py -------------------------------------------------------------------------------------------
@pytest.mark.parametrize("value", [deg2rad(30), -deg2rad(30), 2 * deg2rad(10), deg2rad([10, 20]), [deg2rad(10), 1.0]])
def test_deg_of_a_deg_value_is_refused(value):
    with pytest.raises(DHLabError, match=r"deg2rad\(x\): x .*already in radians"):
        deg2rad(value)


@pytest.mark.parametrize("value", [1e308, -1e308, [0.0, 1e308]])
def test_rad_refuses_an_infinite_result(value):
    with pytest.raises(DHLabError, match=r"rad2deg\(x\): x .*too large"):
        rad2deg(value)


def test_deg_and_rad_still_convert():
    assert rad2deg(deg2rad(45)) == pytest.approx(45.0)
    assert isinstance(rad2deg(1.0), float) and rad2deg(np.pi) == 180.0
    assert rad2deg([np.pi, 0]).tolist() == [180.0, 0.0]


# --- transforms.py --------------------------------------------------------------------------------------
@pytest.mark.parametrize("name", [None, 5, float("nan"), b"x", ["a"]])
def test_check_rigid_name_must_be_text(name):
    with pytest.raises(DHLabError, match="name must be text"):
        check_rigid(np.eye(4), name=name)


# --- symbolic.py ----------------------------------------------------------------------------------------
@pytest.mark.parametrize("fn", [compact, legend])
@pytest.mark.parametrize("M", [sp.Matrix([[sp.cos(Q1), sp.zoo]]), sp.Matrix([[sp.nan]]), sp.oo * Q1,
                               sp.Matrix([[sp.cos(Q1), -sp.oo]])])
def test_compact_and_legend_refuse_non_finite_entries(fn, M):
    with pytest.raises(DHLabError, match=r"M(\[\d, \d\])? = .*not finite"):
        fn(M, [Q1])


# --- lines.py -------------------------------------------------------------------------------------------
@pytest.mark.parametrize("fn", [relation, closest_points])
@pytest.mark.parametrize("b", [np.array(0.5), np.ma.masked])
def test_a_0d_array_is_not_a_line(fn, b):
    with pytest.raises(DHLabError, match="line b must be"):
        fn(Z, b)


@pytest.mark.parametrize("kwargs, words", [({"tol": "1e-9"}, "tol must be"), ({"tol": True}, "tol must be"),
                                           ({"angle_tol": "1e-9"}, "angle_tol must be"),
                                           ({"angle_tol": True}, "angle_tol must be")])
def test_relation_tolerances_are_numbers(kwargs, words):
    with pytest.raises(DHLabError, match=words):
        relation(Z, Line((1, 0, 0), (0, 1, 0)), **kwargs)


@pytest.mark.parametrize("point, direction, words", [((1e308, 0, 0), (0, 0, 1), "Line point"),
                                                     ((1e151, 0, 0), (0, 0, 1), "Line point")])
def test_a_huge_line_point_is_refused(point, direction, words):
    with pytest.raises(DHLabError, match=words):
        Line(point, direction)


def test_a_huge_point_to_a_line_is_refused():
    for method in (Z.distance_to_point, Z.nearest_point):
        with pytest.raises(DHLabError, match="p = .*too large"):
            method((1e308, 0, 0))


def test_a_huge_direction_is_scaled_first():
    line = Line((0, 0, 0), (1e308, 1e308, 0))
    np.testing.assert_allclose(line.direction, [2 ** -0.5, 2 ** -0.5, 0])
    assert Line((0, 0, 0), (0, 0, 2)).direction.tolist() == [0.0, 0.0, 1.0]
    with pytest.raises(DHLabError, match="non-zero direction"):
        Line((0, 0, 0), (1e-13, 0, 0))


# --- robots.py ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("factory, name", [(robots.pr_mechanism, "l1"), (robots.pr_mechanism, "l2"),
                                           (robots.rrr_example, "l3"), (robots.seed002_4dof, "l4"),
                                           (robots.robot_no_tan_elemental_1, "l1"),
                                           (robots.robot_no_tan_elemental_2, "l"),
                                           (robots.prr_example_matrices, "l2"), (robots.seed003_6dof, "l1")])
def test_factory_lengths_refuse_deg_values(factory, name):
    with pytest.raises(DHLabError, match=f"^{name} is a length"):
        factory(**{name: deg2rad(30)})


def test_factory_lengths_still_accept_numbers():
    arm = robots.pr_mechanism(l1=np.float32(2.0), l2=sp.Rational(1, 2))
    assert arm.params == {"l1": 2.0, "l2": 0.5}


# --- views ----------------------------------------------------------------------------------------------
@pytest.mark.parametrize("fn", [dhlab.teach, dhlab.robot_view])
def test_figsize_zero_is_refused_not_the_default(fn):
    with pytest.raises(DHLabError, match="figsize"):
        fn(robots.puma560(), figsize=0)


@pytest.mark.parametrize("M, where", [(sp.Matrix([[1, sp.zoo]]), r"M\[0, 1\] = zoo"),
                                      (sp.Matrix([[sp.nan, 0]]), r"M\[0, 0\] = nan"),
                                      ([[1.0, float("inf")]], r"M\[0, 1\] = oo"), (sp.oo, r"M\[0, 0\] = oo")])
def test_show_matrix_refuses_non_finite_entries(M, where):
    with pytest.raises(DHLabError, match=f"show_matrix: {where}"):
        dhlab.show_matrix(M)
