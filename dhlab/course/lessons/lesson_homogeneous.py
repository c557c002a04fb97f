"""What notebook 2 (homogeneous matrices) needs besides the lesson itself.

* :func:`fmt`, :func:`matrix_text` and :func:`show`: print a vector, a numeric matrix or a symbolic
  matrix the same way in every cell (fixed decimals, no ``-0.000000``), so that the stored outputs
  are stable and the numbers in the text can be found in them; notebook 3 uses them too.
* The seeds' matrices **as printed** (the notebook compares them with what ``dhlab`` computes):
  :func:`seed004_eq1` (seed 004's eq. 1), :func:`seed002_A` (seed 002's closed-form DH matrix) and
  :func:`seed001_rotation_block` (the rotation block of seed 001's faulty ``DefinirTHz``).

Keeping them here keeps each lesson cell short and about the lesson: the cell says *what* is
compared, this module holds the long transcriptions.
"""
from __future__ import annotations

import numpy as np
import sympy as sp

from ...validation import as_float_array
from .printing import fmt, show  # fmt: fixed decimals: (0.500000, 0.000000, 1.000000)

__all__ = ["fmt", "matrix_text", "show", "seed004_eq1", "seed002_A", "seed001_rotation_block"]


def matrix_text(T, digits: int = 6) -> str:
    """A numeric matrix, rounded to ``digits`` decimals, without ``-0``."""
    return str(np.round(as_float_array(T, "T", finite=True), digits) + 0.0)




def seed004_eq1(theta, px, py, pz) -> sp.Matrix:
    """Seed 004's eq. (1), "traslaciones seguidas de rotaciones según el eje z", as printed."""
    c, s = sp.cos(theta), sp.sin(theta)
    return sp.Matrix([[c, -s, 0, px * c - py * s],
                      [s, c, 0, px * s + py * c],
                      [0, 0, 1, pz],
                      [0, 0, 0, 1]])


def seed002_A(theta, d, a, alpha) -> sp.Matrix:
    """Seed 002's closed-form Denavit–Hartenberg matrix A, as printed on its slide."""
    ct, st, ca, sa = sp.cos(theta), sp.sin(theta), sp.cos(alpha), sp.sin(alpha)
    return sp.Matrix([[ct, -ca * st, sa * st, a * ct],
                      [st, ca * ct, -sa * ct, a * st],
                      [0, sa, ca, d],
                      [0, 0, 0, 1]])


def seed001_rotation_block(theta) -> sp.Matrix:
    """The 3×3 rotation block that seed 001's ``DefinirTHz`` listing writes (entry [0][0] is −cos θ)."""
    c, s = sp.cos(theta), sp.sin(theta)
    return sp.Matrix([[-c, -s, 0], [s, c, 0], [0, 0, 1]])
