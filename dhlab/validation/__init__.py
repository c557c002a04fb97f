"""Checks at the boundary of the public API, each written once and reused everywhere.

Every public function and constructor passes its arguments through these helpers,
so a student never meets a traceback from deep inside numpy or sympy, and never a
silently wrong answer. Every error is a :class:`DHLabError` that says which value
is wrong, what was expected and how to fix it.

Numbers (python, numpy or sympy; ``True``, ``None``, text, complex, dates and
masked values are refused):

* ``as_number(x, name)``         one finite real number, as a float
* ``as_angle(x, name)``          radians, at most one full turn (more is degrees by mistake)
* ``as_length(x, name)``         a length: refuses values made by ``deg2rad()`` and sizes beyond
  ``LARGEST_LENGTH`` (1e150, so that squares stay finite; ``check_length_size`` checks a size)
* ``as_tolerance(x, name)``      a small positive number
* ``as_index(x, name, lo, hi)``  a whole number lo … hi (``1.5``, ``'1'``, ``True`` refused)
* ``symbolic=True`` (on as_number/as_angle/as_length): sympy expressions with symbols
  pass through (checked: real, no nan/zoo), sympy numbers are checked like floats and
  kept exact.

Arrays and vectors:

* ``as_sequence(x, name, expected, size=None)`` the items of an ordered container (a table's
  rows, one value per joint): text, a dict, a set, a 0-d array are refused
* ``as_float_array(x, name, finite=False)``  any shape of real numbers as a float array
* ``as_vector(x, name, size)``               ``size`` finite numbers, shape (size,)
* ``check_joint_values(q, links, name, single=False)``  joint values, (n,) or a batch
  (N, n); radians for revolute joints (at most a full turn), lengths for prismatic
  ones (no ``deg2rad()`` mark, at any depth); ``single=True`` refuses a batch
* ``as_matrix4(T, name, batch=False)``       a finite float 4×4 (or (N, 4, 4))
* ``as_sym_matrix4(T, name)``                a 4×4 as a sympy Matrix (numbers or symbols)
* ``rigid_problem(T, tol)``                  why a float 4×4 is not a rigid transform, or None
* ``as_qlim(qlim, revolute, name)``          one joint's (low, high)

Options: ``as_choice(x, allowed, name)``, ``as_flag(x, name)``, ``as_text(x, name)``,
``as_timeout(x, name)``; ``has_angle_mark(x)`` finds a ``deg2rad()`` value at any depth;
``describe(x)`` is a short repr for messages.

The checks live in four modules, one concept each — :mod:`dhlab.validation.values`
(one value, the options), :mod:`dhlab.validation.arrays` (arrays and 4×4 matrices),
:mod:`dhlab.validation.joints` (joint values and limits), :mod:`dhlab.validation.marks`
(the mark of a value made by ``deg2rad``) — and are imported from here. The error they
raise, :class:`DHLabError`, lives in :mod:`dhlab.errors`.

>>> from dhlab import deg2rad
>>> as_angle(deg2rad(30), "theta")
0.5235987755982988
>>> as_angle(30, "theta")
Traceback (most recent call last):
...
dhlab.validation.DHLabError: theta = 30 rad is more than a full turn: angles are in radians.
    If you meant 30 degrees, pass dhlab.deg2rad(30).
"""
from __future__ import annotations

from ..errors import DHLabError
from .arrays import as_float_array, as_matrix4, as_sequence, as_sym_matrix4, as_vector, check_finite, rigid_problem
from .decimal_commas import decimal_comma_note, looks_like_decimal_comma, with_decimal_comma_note
from .joints import as_qlim, check_joint_values
from .marks import Angle, AngleArray, has_angle_mark, is_angle
from .values import (
                     FULL_TURN,
                     LARGEST_LENGTH,
                     as_angle,
                     as_choice,
                     as_flag,
                     as_index,
                     as_length,
                     as_number,
                     as_text,
                     as_timeout,
                     as_tolerance,
                     check_length_size,
                     describe,
                     real_number,
)

__all__ = [
    "DHLabError", "FULL_TURN", "LARGEST_LENGTH", "describe", "as_number", "as_angle", "as_length", "as_tolerance",
    "as_index", "as_float_array", "as_vector", "check_joint_values", "as_matrix4", "as_sym_matrix4",
    "rigid_problem", "as_qlim", "as_choice", "as_flag", "as_text", "as_timeout", "has_angle_mark",
    "check_length_size", "as_sequence", "check_finite", "real_number", "Angle", "AngleArray", "is_angle",
    "decimal_comma_note", "looks_like_decimal_comma", "with_decimal_comma_note",
]
