"""Notebook 2's helpers (dhlab.course.lessons.lesson_homogeneous): the print helpers and the seeds' matrices
as printed, each checked against what dhlab computes or against an independent transcription."""
import numpy as np
import pytest
import sympy as sp

from dhlab.course.exercises import seed001_DefinirTHz
from dhlab.course.lessons.lesson_homogeneous import fmt, matrix_text, seed001_rotation_block, seed002_A, seed004_eq1
from dhlab.errors import DHLabError
from dhlab.transforms import Rz, dh_matrix, trans

theta, alpha, d, a, px, py, pz = sp.symbols("theta alpha d a p_x p_y p_z")


def test_fmt_rounds_and_never_prints_minus_zero():
    assert fmt([-1e-12, 0.5, -2.5], 1) == "(0.0, 0.5, -2.5)"
    assert "-0.0" not in fmt(np.array([-1e-9, -0.0, 1.0]))
    assert fmt(sp.Matrix([0.7, 0, 0]), 2) == "(0.70, 0.00, 0.00)"


def test_matrix_text_has_no_minus_zero():
    text = matrix_text(Rz(np.pi) @ trans(0, 0, 1))          # cos π = -1, sin π ≈ 1e-16
    assert "-0." not in text.replace("-1.", "")
    assert text.count("\n") == 3


@pytest.mark.parametrize("bad", ["abc", [1, "x"], sp.Matrix([theta, 0])])
def test_print_helpers_refuse_what_is_not_numbers(bad):
    with pytest.raises(DHLabError, match="must be numbers"):
        fmt(bad)


def test_seed004_eq1_is_rotate_then_move():
    eq1 = seed004_eq1(theta, px, py, pz)
    assert sp.simplify(Rz(theta) * trans(px, py, pz) - eq1) == sp.zeros(4)
    assert sp.simplify(trans(px, py, pz) * Rz(theta) - eq1) != sp.zeros(4)


def test_seed002_A_is_the_dh_matrix():
    assert sp.simplify(seed002_A(theta, d, a, alpha) - dh_matrix(theta, d, a, alpha)) == sp.zeros(4)


@pytest.mark.parametrize("angle", [0.0, 0.3, np.pi / 4, 1.2, np.pi / 2])
def test_seed001_rotation_block_is_the_listings(angle):
    """Two transcriptions of the listing (symbolic here, line by line in exercises) agree."""
    block = np.array(seed001_rotation_block(theta).subs(theta, angle), dtype=float)
    assert np.allclose(block, seed001_DefinirTHz(angle, (0.0, 0.0, 2.5))[:3, :3])
    assert np.isclose(np.linalg.det(block), -np.cos(2 * angle))
