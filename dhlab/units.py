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

import functools
import math
import warnings

import numpy as np

from .errors import DHLabError
from .i18n import _
from .lazy_sympy import is_expr, is_matrix
from .validation import as_float_array, as_number
from .validation.marks import Angle, AngleArray, has_angle_mark, is_angle

__all__ = ["deg2rad", "rad2deg", "Angle", "AngleArray", "is_angle", "has_angle_mark"]


def _short(x) -> str:
    text = repr(x)
    return text if len(text) <= 60 else text[:57] + "..."


MOST_TURNS = 100          # no angle of a robot turns more: a larger value is not an angle (a length? a typo?)


def _degrees_in(x, what: str, full_turn: float):
    """``x`` checked to be real numbers (a number or a rectangular array) of at most
    :data:`MOST_TURNS` turns (``full_turn`` is 360 or 2π in the unit of ``x``), as floats."""
    if isinstance(x, (list, tuple, np.ndarray)) or is_matrix(x):
        values = as_float_array(x, what, finite=True)
    else:
        values = np.array(as_number(x, what))
    if values.size and np.abs(values).max() > MOST_TURNS * full_turn:
        raise DHLabError(_("{what} = {value:g} is too large, more than {turns} full turns: no angle of a robot turns "
                           "that far. Check the number (is it a length, or a value in the other unit?).").format(
                               what=what, value=np.abs(values).max(), turns=MOST_TURNS))
    return values


def deg2rad(x):
    """Degrees -> radians. Scalars give an :class:`Angle`, sequences an :class:`AngleArray`;
    a sympy expression with symbols gives the exact ``x·π/180``.

    >>> deg2rad([0, 90, 180]).round(4).tolist()
    [0.0, 1.5708, 3.1416]
    """
    if is_expr(x) and x.free_symbols:      # a formula: sympy is loaded already, the result is exact
        import sympy as sp  # lazy: sympy on first symbolic use
        return x * sp.pi / 180
    if has_angle_mark(x):
        raise DHLabError(_("deg2rad(x): x = {x} is already in radians (it was made by deg2rad()): do not convert "
                           "twice, use the value as it is.").format(x=_short(x)))
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
    if is_expr(x) and x.free_symbols:      # a formula: sympy is loaded already, the result is exact
        import sympy as sp  # lazy: sympy on first symbolic use
        return x * 180 / sp.pi
    values = _degrees_in(x, _("rad2deg(x): x (radians)"), 2 * math.pi)
    degrees = math.degrees(float(values)) if values.ndim == 0 else np.degrees(np.asarray(values, dtype=float))
    return float(degrees) if values.ndim == 0 else degrees


def _renamed(old: str, new):
    """``old`` kept working for one release, with a message that names the new function."""
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
