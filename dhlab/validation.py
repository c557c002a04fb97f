"""Checks at the boundary of the public API, each written once and reused everywhere.

Every public function and constructor passes its arguments through these helpers,
so a student never meets a traceback from deep inside numpy or sympy, and never a
silently wrong answer. Every error is a :class:`DHLabError` that says which value
is wrong, what was expected and how to fix it.

Numbers (python, numpy or sympy; ``True``, ``None``, text, complex, dates and
masked values are refused):

* ``as_number(x, name)``         one finite real number, as a float
* ``as_angle(x, name)``          radians, at most one full turn (more is degrees by mistake)
* ``as_length(x, name)``         a length: refuses values made by ``deg()``
* ``as_tolerance(x, name)``      a small positive number
* ``as_index(x, name, lo, hi)``  a whole number lo … hi (``1.5``, ``'1'``, ``True`` refused)
* ``symbolic=True`` (on as_number/as_angle/as_length): sympy expressions with symbols
  pass through (checked: real, no nan/zoo), sympy numbers are checked like floats and
  kept exact.

Arrays and vectors:

* ``as_float_array(x, name, finite=False)``  any shape of real numbers as a float array
* ``as_vector(x, name, size)``               ``size`` finite numbers, shape (size,)
* ``check_joint_values(q, links, name, single=False)``  joint values, (n,) or a batch
  (N, n); radians for revolute joints (at most a full turn), lengths for prismatic
  ones (no ``deg()`` mark, at any depth); ``single=True`` refuses a batch
* ``as_matrix4(T, name, batch=False)``       a finite float 4×4 (or (N, 4, 4))
* ``as_sym_matrix4(T, name)``                a 4×4 as a sympy Matrix (numbers or symbols)
* ``rigid_problem(T, tol)``                  why a float 4×4 is not a rigid transform, or None
* ``as_qlim(qlim, revolute, name)``          one joint's (low, high)

Options: ``as_choice(x, allowed, name)``, ``as_flag(x, name)``, ``as_text(x, name)``,
``as_timeout(x, name)``; ``has_angle_mark(x)`` finds a ``deg()`` value at any depth;
``describe(x)`` is a short repr for messages.

>>> as_angle(deg(30), "theta")
0.5235987755982988
>>> as_angle(30, "theta")
Traceback (most recent call last):
...
dhlab.validation.DHLabError: theta = 30 rad is more than a full turn: angles are in radians. If you meant 30 degrees, pass dhlab.deg(30).
"""
from __future__ import annotations

import datetime
import math
import numbers
from decimal import Decimal
from fractions import Fraction

import numpy as np
import sympy as sp

from .units import Angle, AngleArray, deg, has_angle_mark  # noqa: F401 (deg: for the doctest)

__all__ = [
    "DHLabError", "FULL_TURN", "describe", "as_number", "as_angle", "as_length", "as_tolerance",
    "as_index", "as_float_array", "as_vector", "check_joint_values", "as_matrix4", "as_sym_matrix4",
    "rigid_problem", "as_qlim", "as_choice", "as_flag", "as_text", "as_timeout", "has_angle_mark",
]

FULL_TURN = 2 * math.pi
_PLAIN = (float, int, Angle, np.float64, np.float32, np.int64, np.int32, np.int16, np.int8,
          np.uint8, np.uint16, np.uint32, np.uint64, np.float16)


class DHLabError(ValueError):
    """Bad input to dhlab: the message says what was wrong and how to fix it."""


def describe(x) -> str:
    """A short repr of ``x`` for an error message."""
    try:
        text = repr(x)
    except Exception:               # a broken __repr__ must not hide the real message
        text = f"<{type(x).__name__}>"
    return text if len(text) <= 60 else text[:57] + "..."


_describe = describe   # the old private name


# ------------------------------------------------------------------------------------------
# One number
# ------------------------------------------------------------------------------------------
def _not_a_number(x, name: str) -> DHLabError:
    """The error for a value that is not a real number, with the fix for its type."""
    if x is None:
        why = "it is missing (None): give a number"
    elif isinstance(x, (bool, np.bool_)):
        why = "True/False is not a number here: give the number itself (e.g. 1.0 or 0.0)"
    elif isinstance(x, (str, bytes)):
        why = "it is text: write the number without quotes (e.g. 0.5, not '0.5')"
    elif isinstance(x, (complex, np.complexfloating)) or (isinstance(x, sp.Basic) and x.is_number):
        why = "it is a complex number: only real numbers make a pose (check for a sqrt or arcsin of a value out of range)"
    elif isinstance(x, (datetime.date, datetime.time, datetime.timedelta, np.datetime64, np.timedelta64)):
        why = "it is a date or a time, not a number"
    elif isinstance(x, sp.Basic) and x.free_symbols:
        why = (f"it has the symbols {sorted(map(str, x.free_symbols))}: here pass plain numbers "
               "(symbols belong in the symbolic functions, e.g. robot.fk_sym(); substitute with .subs())")
    elif x is np.ma.masked:
        why = "it is a masked (missing) value: fill it in first"
    else:
        why = f"it is a {type(x).__name__}, not a number"
    return DHLabError(f"{name} = {describe(x)} is not a valid number: {why}.")


def _real(x, name: str, symbolic: bool = False):
    """``x`` as a float; with ``symbolic`` a sympy value stays sympy (checked)."""
    if isinstance(x, _PLAIN) and not isinstance(x, (bool, np.bool_)):
        try:
            return float(x)
        except OverflowError:
            raise DHLabError(f"{name} = {describe(x)} is too large to be a number of this course.") from None
    if isinstance(x, np.ndarray) and x.ndim == 0 and not isinstance(x, np.ma.MaskedArray):
        return _real(x[()], name, symbolic)
    if isinstance(x, (Fraction, Decimal, np.floating, np.integer)) and not isinstance(x, np.bool_):
        try:
            return float(x)
        except (OverflowError, ValueError):
            raise DHLabError(f"{name} = {describe(x)} is too large to be a number of this course.") from None
    if isinstance(x, sp.Basic):
        return _sympy_real(x, name, symbolic)
    raise _not_a_number(x, name)


def _sympy_real(x, name: str, symbolic: bool):
    if not isinstance(x, sp.Expr) or isinstance(x, sp.MatrixBase):
        raise DHLabError(f"{name} = {describe(x)} is not a number or an expression (a {type(x).__name__}).")
    if x.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
        raise DHLabError(f"{name} = {describe(x)}: every value must be a finite number (no nan, oo or zoo).")
    if x.free_symbols:
        if not symbolic:
            raise _not_a_number(x, name)
        if x.has(sp.I) or x.is_extended_real is False:
            raise DHLabError(f"{name} = {describe(x)} is not real: angles and lengths are real numbers.")
        return x
    try:
        value = complex(x.evalf(30))
    except (TypeError, ValueError, OverflowError, ArithmeticError):
        raise _not_a_number(x, name) from None
    if abs(value.imag) > 1e-12 * max(1.0, abs(value.real)):
        raise _not_a_number(complex(value), name)
    if not math.isfinite(value.real):
        raise DHLabError(f"{name} = {describe(x)} is too large: every value must be a finite number.")
    return x if symbolic else float(value.real)


def _finite(value, name: str):
    if isinstance(value, float) and not math.isfinite(value):
        raise DHLabError(f"{name} is {value}: it must be a finite number.")
    return value


def as_number(x, name: str, *, symbolic: bool = False, finite: bool = True):
    """One real number as a float (or, with ``symbolic``, a checked sympy expression).

    >>> as_number(np.float32(0.5), "x")
    0.5
    """
    value = _real(x, name, symbolic)
    return _finite(value, name) if finite else value


def _magnitude(value) -> float:
    return abs(float(value)) if not isinstance(value, sp.Basic) or not value.free_symbols else 0.0


def as_angle(x, name: str, *, symbolic: bool = False, turns: float = 1.0):
    """An angle in radians: finite, at most ``turns`` full turns (more is degrees by mistake)."""
    value = as_number(x, name, symbolic=symbolic)
    size = _magnitude(value)
    if size > turns * FULL_TURN + 1e-9:
        shown = f"{float(value):g}"
        raise DHLabError(
            f"{name} = {shown} rad is more than {'a full turn' if turns == 1 else f'{turns:g} turns'}: "
            f"angles are in radians. If you meant {shown} degrees, pass dhlab.deg({shown})."
        )
    return value


def as_length(x, name: str, *, symbolic: bool = False):
    """A finite length; a value made by ``deg()`` (an angle) is refused."""
    if has_angle_mark(x):
        raise DHLabError(f"{name} is a length, but you gave an angle ({describe(x)}): pass a plain number.")
    return as_number(x, name, symbolic=symbolic)


def as_tolerance(x, name: str = "tol", upper: float = 1e-2, zero: bool = False) -> float:
    """A small positive number (``zero=True`` also allows 0), at most ``upper``."""
    value = as_number(x, name)
    if not (0 <= value if zero else 0 < value) or value > upper:
        low = "≥ 0" if zero else "> 0"
        raise DHLabError(f"{name} must be a small number {low} and at most {upper:g} (e.g. 1e-9), "
                         f"got {describe(x)}.")
    return value


def as_index(x, name: str, lo: int, hi: int) -> int:
    """A whole number in lo … hi (1.5, '1' and True are refused)."""
    if isinstance(x, (bool, np.bool_)) or not isinstance(x, (numbers.Integral, np.integer, sp.Integer)):
        raise DHLabError(f"{name} must be a whole number from {lo} to {hi}, got {describe(x)}.")
    value = int(x)
    if not lo <= value <= hi:
        raise DHLabError(f"{name} must be from {lo} to {hi}, got {value}.")
    return value


# ------------------------------------------------------------------------------------------
# Arrays
# ------------------------------------------------------------------------------------------
def as_float_array(x, name: str, finite: bool = False) -> np.ndarray:
    """``x`` (a number, nested lists, a numpy array or a sympy Matrix of real numbers)
    as a float array, or a DHLabError naming ``name``."""
    if isinstance(x, np.ndarray):
        arr = _numpy_floats(x, name)
    elif isinstance(x, sp.MatrixBase):
        arr = _objects_floats(np.array(x.tolist(), dtype=object).reshape(x.shape), name)
    elif isinstance(x, (list, tuple)):
        arr = _sequence_floats(x, name)
    else:
        try:
            arr = np.array(_real(x, name), dtype=float)
        except DHLabError as error:
            raise DHLabError(f"{name} must be numbers: {error}") from None
    if finite:
        _check_finite(arr, name)
    return arr


def _numpy_floats(x: np.ndarray, name: str) -> np.ndarray:
    if isinstance(x, np.ma.MaskedArray):
        if np.ma.is_masked(x):
            raise DHLabError(f"{name} has masked (missing) values: fill them in first, e.g. {name}.filled(0.0), "
                             "or drop those entries.")
        x = np.asarray(x.data)
    kind = x.dtype.kind
    if kind == "f":
        return np.asarray(x, dtype=float)
    if kind in "iu":
        return x.astype(float)
    if kind == "O":
        return _objects_floats(x, name)
    what = {"b": "True/False values", "c": "complex numbers", "M": "dates", "m": "time spans",
            "U": "text", "S": "text"}.get(kind, f"values of type {x.dtype}")
    raise DHLabError(f"{name} holds {what}, not real numbers: give plain numbers "
                     "(angles in radians, lengths in the robot's unit).")


def _sequence_floats(x, name: str) -> np.ndarray:
    try:
        obj = np.array(x, dtype=object)
    except (ValueError, TypeError):
        obj = None
    if obj is None or any(isinstance(e, (list, tuple, np.ndarray)) for e in obj.ravel()):
        raise DHLabError(f"{name} = {describe(x)} is ragged: its rows have different lengths. "
                         "Every row must have the same number of values.")
    return _objects_floats(obj, name)


def _objects_floats(obj: np.ndarray, name: str) -> np.ndarray:
    flat = obj.ravel()
    if set(map(type, flat)) <= {float, int, Angle, np.float64}:
        try:
            return np.array(flat, dtype=float).reshape(obj.shape)
        except OverflowError:
            pass                                  # a huge int: named below
    out = np.empty(len(flat))
    for k, e in enumerate(flat):
        where = name if obj.ndim == 0 else f"{name}[{', '.join(map(str, np.unravel_index(k, obj.shape)))}]"
        if isinstance(e, (list, tuple, np.ndarray)) and not (isinstance(e, np.ndarray) and e.ndim == 0):
            raise DHLabError(f"{name} is ragged: {where} is a sequence where a number was expected.")
        try:
            out[k] = _real(e, where)
        except DHLabError as error:
            raise DHLabError(f"{name} must be numbers: {error}") from None
    return out.reshape(obj.shape)


def _check_finite(arr: np.ndarray, name: str) -> None:
    bad = ~np.isfinite(arr)
    if bad.any():
        index = tuple(int(i) for i in np.argwhere(bad)[0])
        where = f"{name}[{', '.join(map(str, index))}]" if arr.ndim else name
        raise DHLabError(f"{where} is {arr[index]}: every value must be a finite number.")


def as_vector(x, name: str, size: int) -> np.ndarray:
    """``size`` finite numbers as a float array of shape (size,)."""
    arr = as_float_array(x, name)
    if arr.shape != (size,):
        raise DHLabError(f"{name} must be {size} numbers, got shape {arr.shape}: {describe(x)}.")
    _check_finite(arr, name)
    return arr


# ------------------------------------------------------------------------------------------
# Joint values
# ------------------------------------------------------------------------------------------
def check_joint_values(q, links, name: str = "q", single: bool = False) -> np.ndarray:
    """Joint values as a float array of shape (n,) or (N, n), checked against the links.

    Revolute values are radians; a value beyond one full turn is almost always
    degrees typed by mistake, so it is refused with the fix (``dhlab.deg``).
    A value made by ``deg()`` given to a prismatic joint (a length) is refused too,
    wherever it sits (a list, a nested batch, a numpy array). ``single=True``
    refuses a batch where one pose is expected. A batch may be empty, (0, n).
    """
    n = len(links)
    prismatic = [j for j, link in enumerate(links) if link.is_prismatic]
    if prismatic:
        _check_angle_marks(q, n, prismatic, name)
    arr = as_float_array(q, name)
    plural = "s" if n != 1 else ""
    if arr.ndim == 0 or arr.shape[-1] != n or arr.ndim > 2 or (single and arr.ndim != 1):
        expected = f"shape ({n},)" + ("" if single else f", or (N, {n}) for a batch")
        hint = (" This function takes one pose, not a batch: pass one row, e.g. q[0]."
                if single and arr.ndim == 2 and arr.shape[-1] == n else "")
        raise DHLabError(f"{name} must hold {n} joint value{plural} ({expected}), got shape {arr.shape}.{hint}")
    _check_finite(arr, name)
    if arr.size == 0:
        return arr
    revolute = [j for j in range(n) if j not in prismatic]
    if revolute:
        for j in revolute:
            value = np.abs(arr[..., j]).max()      # column by column: faster than max(axis=0)
            if value > FULL_TURN + 1e-9:
                raise DHLabError(
                    f"{name}[{j}] (joint {j + 1}, revolute) is {value:g} rad, more than a full turn: "
                    f"angles are in radians. If you meant {value:g} degrees, pass dhlab.deg({value:g})."
                )
    for j in prismatic:
        _check_not_radians(arr[..., j], j, name)
    return arr


def _angle_columns(q, n: int) -> set:
    """The positions j (0 … n−1) whose value carries a deg() mark, at any depth of ``q``."""
    if isinstance(q, AngleArray):
        return set(range(n))
    if isinstance(q, Angle):
        return {0} if n == 1 else set()
    if isinstance(q, (list, tuple)) or (isinstance(q, np.ndarray) and q.dtype == object):
        items = list(q) if not isinstance(q, np.ndarray) or q.ndim else [q[()]]
        if items and all(isinstance(v, (list, tuple, np.ndarray)) and np.ndim(v) > 0 for v in items):
            return set().union(*(_angle_columns(v, n) for v in items))       # a batch: every row
        return {j for j, v in enumerate(items) if j < n and has_angle_mark(v)}
    return set()


def _check_angle_marks(q, n: int, prismatic: list, name: str) -> None:
    """Refuse deg() values given to prismatic joints."""
    marked = _angle_columns(q, n) & set(prismatic)
    if not marked:
        return
    j = min(marked)
    if isinstance(q, AngleArray):
        raise DHLabError(
            f"{name} was made with dhlab.deg(), but joint {j + 1} is prismatic: its value is a length, "
            "not an angle. Convert only the revolute values, e.g. [deg(30), 0.5, deg(45)]."
        )
    shown = f" = {q[j]!r}" if isinstance(q, (list, tuple)) and len(q) == n else ""
    raise DHLabError(
        f"{name}[{j}]{shown} is an angle, but joint {j + 1} is prismatic: "
        "give its displacement as a length (in the robot's unit)."
    )


def _check_not_radians(column: np.ndarray, j: int, name: str) -> None:
    """A prismatic value equal, to the last bit, to a whole number of degrees in radians
    (deg(30) = 0.5235987755982988) is an angle whose deg() mark numpy dropped."""
    degrees = np.round(column * (180 / math.pi))
    hit = (degrees != 0) & (np.abs(degrees) <= 360) & (np.radians(degrees) == column)
    if hit.any():
        value = column[np.argmax(hit)] if column.ndim else column
        raise DHLabError(
            f"{name}[{j}] = {float(value)!r} is exactly deg({float(np.degrees(value)):g}), an angle, but joint "
            f"{j + 1} is prismatic: give its displacement as a length (in the robot's unit)."
        )


# ------------------------------------------------------------------------------------------
# Matrices
# ------------------------------------------------------------------------------------------
def as_matrix4(T, name: str = "T", batch: bool = False) -> np.ndarray:
    """A finite float 4x4 (or (N,4,4) when ``batch``) array, or a clear error.

    A sympy Matrix is accepted when it has no symbols.
    """
    if isinstance(T, sp.MatrixBase) and T.free_symbols:
        raise DHLabError(f"{name} has symbols {sorted(map(str, T.free_symbols))}: "
                         "substitute numbers (M.subs(...)) before using it numerically.")
    arr = as_float_array(T, name)
    ok = arr.shape == (4, 4) or (batch and arr.ndim == 3 and arr.shape[1:] == (4, 4))
    if not ok:
        expected = "(4, 4) or (N, 4, 4)" if batch else "(4, 4)"
        raise DHLabError(
            f"{name} must be a homogeneous matrix of shape {expected}, got shape {arr.shape}. "
            "A homogeneous transform is [[R, p], [0, 0, 0, 1]] with a 3x3 rotation R and a position p."
        )
    _check_finite(arr, name)
    return arr


def as_sym_matrix4(T, name: str = "T") -> sp.Matrix:
    """A 4x4 sympy Matrix (numbers or expressions), every entry real and finite."""
    if not isinstance(T, sp.MatrixBase):
        return sp.Matrix(as_matrix4(T, name))
    if T.shape != (4, 4):
        raise DHLabError(f"{name} must be a 4x4 homogeneous matrix, got shape {T.shape}. "
                         "A homogeneous transform is [[R, p], [0, 0, 0, 1]].")
    for (i, j), e in np.ndenumerate(np.array(T.tolist(), dtype=object)):
        _real(e, f"{name}[{i}, {j}]", symbolic=True)
    return sp.Matrix(T)


def rigid_problem(T: np.ndarray, tol: float = 1e-9) -> str | None:
    """Why the 4x4 ``T`` is not a proper rigid transform, or None if it is."""
    R = T[:3, :3]
    if not np.allclose(T[3], [0, 0, 0, 1], atol=tol):
        return f"its last row is {np.round(T[3], 6).tolist()}, not [0, 0, 0, 1]"
    gram = R.T @ R
    if not np.allclose(gram, np.eye(3), atol=max(tol, 1e-9) * 10):
        err = np.abs(gram - np.eye(3)).max()
        return (f"its rotation part is not orthonormal (|RᵀR − I| reaches {err:.3g}): "
                "its columns must be unit vectors at right angles")
    det = np.linalg.det(R)
    if det < 0:
        return f"det R = {det:.6g}: it is a reflection (a mirror), not a rotation"
    return None


# ------------------------------------------------------------------------------------------
# Joint limits and options
# ------------------------------------------------------------------------------------------
def as_qlim(qlim, revolute: bool, name: str = "qlim") -> tuple:
    """One joint's limits (low, high): finite, low < high; radians (at most a full turn
    either way) for a revolute joint, lengths (no deg() mark) for a prismatic one."""
    unit = "radians, e.g. (deg(-90), deg(90))" if revolute else "lengths, e.g. (0.0, 0.5)"
    if isinstance(qlim, (str, bytes, dict, set)) or not hasattr(qlim, "__len__") or np.ndim(qlim) != 1 \
            or len(qlim) != 2:
        raise DHLabError(f"{name} must be two numbers (low, high) in {unit}; got {describe(qlim)}.")
    if not revolute and has_angle_mark(qlim):
        raise DHLabError(f"{name} of a prismatic joint is a range of lengths, but it was made with deg(): "
                         f"give lengths, e.g. (0.0, 0.5); got {describe(qlim)}.")
    low, high = (as_number(v, f"{name}[{k}]") for k, v in enumerate(qlim))
    if not low < high:
        raise DHLabError(f"{name} must be (low, high) with low < high, got {describe(qlim)}.")
    if revolute:
        for v in (low, high):
            as_angle(v, f"{name} (a revolute joint's limit)")
    return (low, high)


def as_choice(x, allowed, name: str):
    """One of ``allowed`` (text options compared as typed)."""
    if not isinstance(x, (str, type(None), bool, int)) or x not in tuple(allowed):
        options = ", ".join(repr(a) for a in allowed)
        raise DHLabError(f"{name} must be one of {options}, got {describe(x)}.")
    return x


def as_flag(x, name: str) -> bool:
    """True or False (1/0 and numpy booleans too; text and None are refused)."""
    if isinstance(x, (bool, np.bool_)) or (isinstance(x, int) and x in (0, 1)):
        return bool(x)
    raise DHLabError(f"{name} must be True or False, got {describe(x)}.")


def as_text(x, name: str) -> str:
    """A string (a name, a label)."""
    if not isinstance(x, str):
        raise DHLabError(f"{name} must be text (a str), got {describe(x)}.")
    return x


def as_timeout(x, name: str = "timeout") -> float | None:
    """Seconds (a positive number), or None for no limit."""
    if x is None:
        return None
    value = as_number(x, name)
    if value <= 0:
        raise DHLabError(f"{name} must be a positive number of seconds (or None for no limit), got {describe(x)}.")
    return value

