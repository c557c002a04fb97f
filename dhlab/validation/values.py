"""Checks of one value at the boundary: a number, an angle, a length, a tolerance, an
index, an option (each raises :class:`dhlab.errors.DHLabError` with the fix).

Numbers may be python, numpy or sympy; ``True``, ``None``, text, complex, dates and
masked values are refused with the fix for their type. Part of :mod:`dhlab.validation`
(import from there).

>>> as_number(np.float32(0.5), "x")
0.5
>>> from dhlab import deg2rad
>>> as_length(deg2rad(30), "d")
Traceback (most recent call last):
...
dhlab.validation.DHLabError: d is a length, but you gave an angle (deg2rad(30)): pass a plain number.
"""
from __future__ import annotations

import datetime
import math
import numbers
from decimal import Decimal
from fractions import Fraction

import numpy as np

from ..errors import DHLabError
from ..i18n import N_, _
from ..lazy_sympy import has_symbols, is_sympy
from .decimal_commas import looks_like_decimal_comma
from .marks import Angle, has_angle_mark

__all__ = ["FULL_TURN", "real_number", "LARGEST_LENGTH", "describe", "as_number", "as_angle", "as_length",
           "check_length_size", "as_tolerance", "as_index", "as_choice", "as_flag", "as_text", "as_timeout"]

FULL_TURN = 2 * math.pi
LARGEST_LENGTH = 1e150      # no robot is longer; and the square of a length (a distance, a norm) stays finite
_PLAIN = (float, int, Angle, np.float64, np.float32, np.int64, np.int32, np.int16, np.int8,
          np.uint8, np.uint16, np.uint32, np.uint64, np.float16)


TOO_LARGE = N_("{name} = {value} is too large to be a number of this course.")


def describe(x) -> str:
    """A short repr of ``x`` for an error message."""
    try:
        text = repr(x)
    except Exception:               # a broken __repr__ must not hide the real message
        text = f"<{type(x).__name__}>"
    return text if len(text) <= 60 else text[:57] + "..."


# ------------------------------------------------------------------------------------------
# One number
# ------------------------------------------------------------------------------------------
def _not_a_number(x, name: str) -> DHLabError:
    """The error for a value that is not a real number, with the fix for its type."""
    if x is None:
        why = _("it is missing (None): give a number")
    elif isinstance(x, (bool, np.bool_)):
        why = _("True/False is not a number here: give the number itself (e.g. 1.0 or 0.0)")
    elif looks_like_decimal_comma(x):
        why = _("it is text with a decimal comma: write {fixed}, with a decimal point and without quotes").format(
            fixed=x.strip().replace(",", ".").replace("−", "-"))
    elif isinstance(x, (str, bytes)):
        why = _("it is text: write the number without quotes (e.g. 0.5, not '0.5')")
    elif isinstance(x, (complex, np.complexfloating)) or (is_sympy(x) and x.is_number):
        why = _("it is a complex number: only real numbers make a pose (check for a sqrt or arcsin of a value "
                "out of range)")
    elif isinstance(x, (datetime.date, datetime.time, datetime.timedelta, np.datetime64, np.timedelta64)):
        why = _("it is a date or a time, not a number")
    elif has_symbols(x):
        why = _("it has the symbols {symbols}: here pass plain numbers (symbols belong in the symbolic functions, "
                "e.g. robot.fk_sym(); substitute with .subs())").format(symbols=sorted(map(str, x.free_symbols)))
    elif x is np.ma.masked:
        why = _("it is a masked (missing) value: fill it in first")
    else:
        kind = type(x).__name__
        why = (_("it is an {kind}, not a number") if kind[:1] in "aeiou" else
               _("it is a {kind}, not a number")).format(kind=kind)
    return DHLabError(_("{name} = {value} is not a valid number: {why}.").format(name=name, value=describe(x), why=why))


def real_number(x, name: str, symbolic: bool = False):
    """``x`` (one real number of python, numpy or sympy) as a float; with ``symbolic`` a sympy
    value stays sympy (checked). Unlike :func:`as_number`, an infinite value passes."""
    if isinstance(x, _PLAIN) and not isinstance(x, (bool, np.bool_)):
        try:
            return float(x)
        except OverflowError:
            raise DHLabError(_(TOO_LARGE).format(name=name, value=describe(x))) from None
    if isinstance(x, np.ndarray) and x.ndim == 0 and not isinstance(x, np.ma.MaskedArray):
        return real_number(x[()], name, symbolic)
    if isinstance(x, (Fraction, Decimal, np.floating, np.integer)) and not isinstance(x, np.bool_):
        try:
            value = float(x)
        except (OverflowError, ValueError):
            value = math.inf
        infinite = x.is_infinite() if isinstance(x, Decimal) else isinstance(x, np.floating) and np.isinf(x)
        if math.isinf(value) and not infinite:          # a finite value too large for a float (Decimal('1e400'))
            raise DHLabError(_(TOO_LARGE).format(name=name, value=describe(x))) from None
        return value
    if is_sympy(x):
        return _sympy_real(x, name, symbolic)
    raise _not_a_number(x, name)


def _sympy_real(x, name: str, symbolic: bool):
    import sympy as sp  # (loaded already: x is a sympy object)
    if not isinstance(x, sp.Expr) or isinstance(x, sp.MatrixBase):
        raise DHLabError(_("{name} = {value} is not a number or an expression (a {type}).").format(
            name=name, value=describe(x), type=type(x).__name__))
    if x.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
        raise DHLabError(_("{name} = {value}: every value must be a finite number (no nan, oo or zoo).").format(
            name=name, value=describe(x)))
    if x.free_symbols:
        if not symbolic:
            raise _not_a_number(x, name)
        if x.has(sp.I) or x.is_extended_real is False:
            raise DHLabError(_("{name} = {value} is not real: angles and lengths are real numbers.").format(
                name=name, value=describe(x)))
        return x
    try:
        value = complex(x.evalf(30))
    except (TypeError, ValueError, OverflowError, ArithmeticError):
        raise _not_a_number(x, name) from None
    if abs(value.imag) > 1e-12 * max(1.0, abs(value.real)):
        raise _not_a_number(complex(value), name)
    if not math.isfinite(value.real):
        raise DHLabError(_("{name} = {value} is too large: every value must be a finite number.").format(
            name=name, value=describe(x)))
    return x if symbolic else float(value.real)


def _finite(value, name: str):
    if isinstance(value, float) and not math.isfinite(value):
        raise DHLabError(_("{name} is {value}: it must be a finite number.").format(name=name, value=value))
    return value


def as_number(x, name: str, *, symbolic: bool = False, finite: bool = True):
    """One real number as a float (or, with ``symbolic``, a checked sympy expression).

    >>> as_number(np.float32(0.5), "x")
    0.5
    """
    value = real_number(x, name, symbolic)
    return _finite(value, name) if finite else value


def _magnitude(value) -> float:
    return 0.0 if has_symbols(value) else abs(float(value))


def as_angle(x, name: str, *, symbolic: bool = False, turns: float = 1.0):
    """An angle in radians: finite, at most ``turns`` full turns (more is degrees by mistake)."""
    value = as_number(x, name, symbolic=symbolic)
    size = _magnitude(value)
    if size > turns * FULL_TURN + 1e-9:
        shown = f"{float(value):g}"
        message = (_("{name} = {shown} rad is more than a full turn: angles are in radians. If you meant {shown} "
                     "degrees, pass dhlab.deg2rad({shown}).") if turns == 1 else
                   _("{name} = {shown} rad is more than {turns:g} turns: angles are in radians. If you meant {shown} "
                     "degrees, pass dhlab.deg2rad({shown})."))
        raise DHLabError(message.format(name=name, shown=shown, turns=turns))
    return value


def as_length(x, name: str, *, symbolic: bool = False):
    """A finite length, at most :data:`LARGEST_LENGTH`; a value made by ``deg2rad()`` (an angle) is refused."""
    if has_angle_mark(x):
        raise DHLabError(_("{name} is a length, but you gave an angle ({value}): pass a plain number.").format(
            name=name, value=describe(x)))
    value = as_number(x, name, symbolic=symbolic)
    check_length_size(_magnitude(value), name)
    return value


def check_length_size(size: float, name: str) -> None:
    """Refuse a length whose size (absolute value) is beyond :data:`LARGEST_LENGTH`."""
    if size > LARGEST_LENGTH:
        raise DHLabError(_("{name} = {size:g} is too large for a length: at most {largest:g} in the robot's unit "
                           "(beyond that, a pose or a distance overflows). Check the number and its unit.").format(
                               name=name, size=size, largest=LARGEST_LENGTH))


def as_tolerance(x, name: str = "tol", upper: float = 1e-2, zero: bool = False) -> float:
    """A small positive number (``zero=True`` also allows 0), at most ``upper``."""
    value = as_number(x, name)
    if not (0 <= value if zero else 0 < value) or value > upper:
        low = "≥ 0" if zero else "> 0"
        raise DHLabError(_("{name} must be a small number {low} and at most {upper:g} (e.g. 1e-9), "
                           "got {value}.").format(name=name, low=low, upper=upper, value=describe(x)))
    return value


def as_index(x, name: str, lo: int, hi: int) -> int:
    """A whole number in lo … hi (1.5, '1' and True are refused)."""
    whole = isinstance(x, (numbers.Integral, np.integer)) or is_sympy(x) and x.is_Integer
    if isinstance(x, (bool, np.bool_)) or not whole:
        raise DHLabError(_("{name} must be a whole number from {lo} to {hi}, got {value}.").format(
            name=name, lo=lo, hi=hi, value=describe(x)))
    value = int(x)
    if not lo <= value <= hi:
        raise DHLabError(_("{name} must be from {lo} to {hi}, got {value}.").format(
            name=name, lo=lo, hi=hi, value=value))
    return value


# ------------------------------------------------------------------------------------------
# Options
# ------------------------------------------------------------------------------------------
def as_choice(x, allowed, name: str):
    """One of ``allowed`` (text options compared as typed)."""
    if not isinstance(x, (str, type(None), bool, int)) or x not in tuple(allowed):
        options = ", ".join(repr(a) for a in allowed)
        raise DHLabError(_("{name} must be one of {options}, got {value}.").format(
            name=name, options=options, value=describe(x)))
    return x


def as_flag(x, name: str) -> bool:
    """True or False (1/0 and numpy booleans too; text and None are refused)."""
    if isinstance(x, (bool, np.bool_)) or (isinstance(x, int) and x in (0, 1)):
        return bool(x)
    raise DHLabError(_("{name} must be True or False, got {value}.").format(name=name, value=describe(x)))


def as_text(x, name: str) -> str:
    """A string (a name, a label)."""
    if not isinstance(x, str):
        raise DHLabError(_("{name} must be text (a str), got {value}.").format(name=name, value=describe(x)))
    return x


def as_timeout(x, name: str = "timeout") -> float | None:
    """Seconds (a positive number), or None for no limit."""
    if x is None:
        return None
    value = as_number(x, name)
    if value <= 0:
        raise DHLabError(_("{name} must be a positive number of seconds (or None for no limit), got {value}.").format(
            name=name, value=describe(x)))
    return value
