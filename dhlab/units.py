"""Angle units: the API works in radians; people read and type degrees.

Each name says its direction: ``deg2rad`` (degrees to radians) and ``rad2deg``
(radians to degrees), as in numpy. ``deg2rad(30)`` converts degrees to radians *and
remembers that the value is an angle*, so that passing it to a prismatic joint (which expects a length) is
caught instead of silently moving the joint by 0.52 length units. The mark
survives the arithmetic of angles: ``-deg2rad(30)``, ``2 * deg2rad(30)``,
``deg2rad(30) + 0.1`` are angles too.

>>> from dhlab import deg2rad, rad2deg
>>> round(deg2rad(90), 6)
1.570796
>>> rad2deg(deg2rad(45))
45.0
>>> -deg2rad(30)
deg2rad(-30)
"""
from __future__ import annotations

import math

import numpy as np
import sympy as sp

from .i18n import _

__all__ = ["deg2rad", "rad2deg", "deg", "rad", "Angle", "AngleArray", "is_angle", "has_angle_mark"]


def _is_real_scalar(x) -> bool:
    return isinstance(x, (int, float, np.integer, np.floating)) and not isinstance(x, (bool, np.bool_))


class Angle(float):
    """A float in radians that was made from degrees by :func:`deg2rad`."""

    def __repr__(self) -> str:
        return f"deg2rad({math.degrees(self):g})"

    # the arithmetic of angles keeps the mark: -θ, 2θ, θ/2, θ ± a number
    def __neg__(self):
        return Angle(-float(self))

    def __pos__(self):
        return self

    def __abs__(self):
        return Angle(abs(float(self)))

    def _keep(self, value, other):
        return Angle(value) if _is_real_scalar(other) and isinstance(value, float) else value

    def __add__(self, other):
        return self._keep(float.__add__(self, other), other)

    __radd__ = __add__

    def __sub__(self, other):
        return self._keep(float.__sub__(self, other), other)

    def __rsub__(self, other):
        return self._keep(float.__rsub__(self, other), other)

    def __mul__(self, other):
        return float.__mul__(self, other) if isinstance(other, Angle) else self._keep(float.__mul__(self, other), other)

    __rmul__ = __mul__

    def __truediv__(self, other):
        value = float.__truediv__(self, other)
        return value if isinstance(other, Angle) else self._keep(value, other)


class AngleArray(np.ndarray):
    """An array in radians that was made from degrees by :func:`deg2rad`."""

    def __array_finalize__(self, obj):  # keep the subclass through views and arithmetic
        pass


def is_angle(x) -> bool:
    """True when ``x`` was made by :func:`deg2rad` (so it is an angle, not a length)."""
    return isinstance(x, (Angle, AngleArray))


def has_angle_mark(x) -> bool:
    """True when ``x`` or anything inside it (lists, tuples, object arrays) was made by :func:`deg2rad`."""
    if isinstance(x, (Angle, AngleArray)):
        return True
    if isinstance(x, (list, tuple)):
        return any(has_angle_mark(v) for v in x)
    if isinstance(x, np.ndarray) and x.dtype == object:
        return any(has_angle_mark(v) for v in x.ravel())
    return False


def _short(x) -> str:
    text = repr(x)
    return text if len(text) <= 60 else text[:57] + "..."


def _error(message):
    from .validation import DHLabError     # (validation imports this module)
    return DHLabError(message)


MOST_TURNS = 100          # no angle of a robot turns more: a larger value is not an angle (a length? a typo?)


def _degrees_in(x, what: str, full_turn: float):
    """``x`` checked to be real numbers (a number or a rectangular array) of at most
    :data:`MOST_TURNS` turns (``full_turn`` is 360 or 2π in the unit of ``x``), as floats."""
    from .validation import as_float_array, as_number
    if isinstance(x, (list, tuple, np.ndarray, sp.MatrixBase)):
        values = as_float_array(x, what, finite=True)
    else:
        values = np.array(as_number(x, what))
    if values.size and np.abs(values).max() > MOST_TURNS * full_turn:
        raise _error(_("{what} = {value:g} is too large, more than {turns} full turns: no angle of a robot turns that "
                       "far. Check the number (is it a length, or a value in the other unit?).").format(
                           what=what, value=np.abs(values).max(), turns=MOST_TURNS))
    return values


def deg2rad(x):
    """Degrees -> radians. Scalars give an :class:`Angle`, sequences an :class:`AngleArray`;
    a sympy expression with symbols gives the exact ``x·π/180``.

    >>> deg2rad([0, 90, 180]).round(4).tolist()
    [0.0, 1.5708, 3.1416]
    """
    if isinstance(x, sp.Expr) and x.free_symbols:
        return x * sp.pi / 180
    if has_angle_mark(x):
        raise _error(_("deg2rad(x): x = {x} is already in radians (it was made by deg2rad()): do not convert twice, "
                       "use the value as it is.").format(x=_short(x)))
    values = _degrees_in(x, _("deg2rad(x): x (degrees)"), 360.0)
    if values.ndim == 0:
        return Angle(math.radians(float(values)))
    return np.radians(values).view(AngleArray)


def rad2deg(x):
    """Radians -> degrees (plain floats or arrays: the inverse of :func:`deg2rad`);
    a sympy expression with symbols gives the exact ``x·180/π``.

    >>> rad2deg(np.pi)
    180.0
    """
    if isinstance(x, sp.Expr) and x.free_symbols:
        return x * 180 / sp.pi
    values = _degrees_in(x, _("rad2deg(x): x (radians)"), 2 * math.pi)
    degrees = math.degrees(float(values)) if values.ndim == 0 else np.degrees(np.asarray(values, dtype=float))
    return float(degrees) if values.ndim == 0 else degrees


def _renamed(old: str, new):
    """``old`` kept working for one release, with a message that names the new function."""
    import functools
    import warnings

    @functools.wraps(new)
    def old_name(x):
        warnings.warn(_("dhlab.{old}() is renamed dhlab.{new}() (the name says the direction); {old}() will be "
                        "removed in the next release.").format(old=old, new=new.__name__), FutureWarning, stacklevel=2)
        return new(x)
    old_name.__name__ = old
    old_name.__qualname__ = old
    return old_name


deg = _renamed("deg", deg2rad)      # deprecated: degrees -> radians
rad = _renamed("rad", rad2deg)      # deprecated: radians -> degrees
