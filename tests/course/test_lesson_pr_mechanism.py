"""Notebook 04's lesson helpers (dhlab.course.lessons.lesson_pr_mechanism): what they print is what the
mechanism does, checked against formulas computed here independently."""
import math
import re

import numpy as np
import pytest
import sympy as sp

import dhlab
from dhlab.course.lessons.lesson_pr_mechanism import (
    branch_residuals,
    branches_within_limits,
    compare_methods,
    fmt,
    geometric_examples_figure,
    ik_report,
    pr_mechanism_figure,
    workspace_report,
)
from dhlab.errors import DHLabError


@pytest.fixture(scope="module")
def pr():
    return dhlab.robots.pr_mechanism()


def test_fmt_fixed_decimals_and_no_negative_zero():
    assert fmt([1, -0.0000001, 2.5], 3) == "(1.000, 0.000, 2.500)"
    assert fmt(np.array([[0.5], [-1e-12]])) == "(0.500000, 0.000000)"


def test_both_branches_reach_the_target_and_the_slides_formula_misses_it():
    residuals = branch_residuals()
    assert residuals["branch A"] == (0, 0) and residuals["branch B"] == (0, 0)
    dx, dy = residuals["the slide's q1 with q2B"]
    assert dy == 0
    x, y = sp.symbols("x y", real=True)
    l2 = sp.Symbol("l2", positive=True)
    assert sp.simplify(dx.subs({y: 0.3, l2: 0.5}) + 0.8) == 0          # −2·√(0.25 − 0.09) = −0.8
    assert x not in dx.free_symbols


def _printed_numbers(line):
    return [float(v) for v in re.findall(r"-?\d+\.\d+", line)]


def test_ik_report_checks_every_solution_by_the_forward_kinematics(pr):
    targets = [(2.0, 0.25), (2.0, -0.4), (1.2, 0.5), (2.0, 0.6), (0.7, -0.1)]
    lines = ik_report(pr, targets).splitlines()
    assert sum(line.startswith("target") for line in lines) == len(targets)
    solution_lines = [line for line in lines if line.lstrip().startswith(("A:", "B:"))]
    assert len(solution_lines) == 2 + 2 + 1 + 0 + 2
    for line in solution_lines:
        q1, q2, degrees, *rest = _printed_numbers(line)
        assert math.isclose(math.degrees(q2), degrees, abs_tol=1e-4)
        x, y = rest[-2:]
        assert math.isclose(q1 + 1 + 0.5 * math.cos(q2), x, abs_tol=1e-6)   # seed 003's FK, by hand
        assert math.isclose(0.5 * math.sin(q2), y, abs_tol=1e-6)


def test_an_angle_beyond_half_a_turn_is_also_given_within_one(pr):
    line = next(line for line in ik_report(pr, [(2.0, -0.4)]).splitlines() if line.lstrip().startswith("B:"))
    q2b = math.pi - math.asin(-0.4 / 0.5)
    assert f"{math.degrees(q2b):.6f}°" in line
    assert f"(the direction {math.degrees(q2b) - 360:.6f}°)" in line
    assert "direction" not in ik_report(pr, [(2.0, 0.25)])


def test_unreachable_target_has_no_solution_line(pr):
    report = ik_report(pr, [(2.0, 0.6)])
    assert "no solution" in report and "A:" not in report and "nan" not in report.lower()


@pytest.mark.parametrize("bad", [[], [(1.0,)], "2, 0.25", [(1, "a")], 3])
def test_ik_report_refuses_targets_that_are_not_pairs(pr, bad):
    with pytest.raises(DHLabError, match="pairs"):
        ik_report(pr, bad)


@pytest.mark.parametrize("x, y", [(1.2, 0.25), (2.0, 0.25), (0.6, 0.0), (3.4, -0.3)])
def test_branches_within_limits_uses_each_branchs_own_slider_position(pr, x, y):
    root = 0.5 * math.sqrt(1 - (y / 0.5) ** 2)
    expected = {"A": x - 1 - root, "B": x - 1 + root}
    for line in branches_within_limits(pr, x, y).splitlines():
        name, q1 = line[0], _printed_numbers(line)[0]
        assert math.isclose(q1, expected[name], abs_tol=1e-6)
        assert line.endswith(str(0 <= expected[name] <= 2))


def test_branches_within_limits_says_when_there_is_no_solution(pr):
    assert "no solution" in branches_within_limits(pr, 2.0, 0.9)


def test_the_workspace_is_the_stadium_around_the_elbows_segment(pr):
    text = workspace_report(pr)
    l1, l2 = pr.params["l1"], pr.params["l2"]
    (lo, hi), _ = pr.qlim
    assert f"from x = {lo + l1:g} to x = {hi + l1:g}" in text
    assert f"x from {lo + l1 - l2:g} to {hi + l1 + l2:g}, y from {-l2:g} to {l2:g}" in text
    assert f"largest distance from the segment: {l2:g}" in text


def _geometric_prr(prr):
    p1, p2, p3 = prr.q_symbols
    l1, l2, l3, l4 = sp.symbols("l1 l2 l3 l4")
    return sp.Matrix([l2 + l3 * sp.sin(p2) + l4 * sp.sin(p2 + p3), 0,
                      p1 + l1 + l3 * sp.cos(p2) + l4 * sp.cos(p2 + p3)])


def test_compare_methods_agrees_for_seed_003s_formulas_and_catches_a_wrong_one():
    prr, prr_dh = dhlab.robots.prr_example_matrices(), dhlab.robots.prr_example()
    right = compare_methods(prr, prr_dh, _geometric_prr(prr), [[0.3, math.radians(30), math.radians(45)]])
    assert "geometric formulas: True" in right
    x, z = 0.5 + 2 * math.sin(math.radians(30)) + 1.5 * math.sin(math.radians(75)), \
        0.3 + 1 + 2 * math.cos(math.radians(30)) + 1.5 * math.cos(math.radians(75))    # seed 003, by hand
    assert right.splitlines()[-1].endswith(f"geometric = matrices = DH = ({x:.6f}, 0.000000, {z:.6f})")
    wrong_formula = _geometric_prr(prr)
    wrong_formula[0] += sp.Symbol("l2")                      # a slip: l2 counted twice
    wrong = compare_methods(prr, prr_dh, wrong_formula, [[0, 0, 0]])
    assert "geometric formulas: False" in wrong
    assert "geometric (1.000000, 0.000000, 4.500000), matrices (0.500000, 0.000000, 4.500000)" in wrong


def test_compare_methods_refuses_a_formula_that_is_not_a_column_of_three():
    prr = dhlab.robots.prr_example_matrices()
    with pytest.raises(DHLabError, match="3×1"):
        compare_methods(prr, prr, sp.Matrix([1, 2]), [[0, 0, 0]])


def test_geometric_examples_figure_one_3d_view_per_mechanism():
    prr, rrr = dhlab.robots.prr_example_matrices(), dhlab.robots.rrr_example_matrices()
    fig = geometric_examples_figure([(prr, [0.3, 0.5, 0.7], "P-R-R"), (rrr, [0.1, 0.2, 0.3], "3R")])
    assert [ax.get_title() for ax in fig.axes] == ["P-R-R", "3R"]
    assert all(ax.name == "3d" for ax in fig.axes)


def test_the_pr_figure_labels_every_variable_and_puts_the_end_effector_where_fk_does(pr):
    q = [0.25, math.radians(45)]
    fig = pr_mechanism_figure(pr, q)
    ax = fig.axes[0]
    texts = [t.get_text() for t in ax.texts]
    for name in ("$q_1$", "$q_2$", r"$\ell_1$", r"$\ell_2$", r"$\{S_0\}$"):
        assert name in texts
    x, y = pr.fk(q)[:2, 3]
    assert f"$(x, y) = ({x:.3f}, {y:.3f})$" in texts
    stars = [line for line in ax.lines if line.get_marker() == "*"]
    assert len(stars) == 1 and np.allclose(np.ravel(stars[0].get_xydata()), [x, y])
    x_lo, x_hi = ax.get_xlim()
    assert x_lo < 0 < x + 0.1 < x_hi                         # the base and the end effector inside


def test_the_pr_figure_refuses_a_pose_outside_the_slider_range(pr):
    with pytest.raises(DHLabError):
        pr_mechanism_figure(pr, [3.0, 0.0])
