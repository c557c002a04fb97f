"""The mark of an angle: a value made from degrees by ``deg2rad`` remembers it is an angle.

``deg2rad(30)`` (in :mod:`dhlab.units`) returns an :class:`Angle`, a float that prints as
``deg2rad(30)``; an array of degrees becomes an :class:`AngleArray`. The checks
(:mod:`dhlab.validation`) read the mark to refuse an angle where a length belongs: a
prismatic joint moved by ``deg2rad(30)`` would silently slide 0.52 length units.
The mark survives the arithmetic of angles: ``-θ``, ``2θ``, ``θ/2``, ``θ ± a number``.

>>> theta = Angle(0.5235987755982988)
>>> theta, -theta, 2 * theta
(deg2rad(30), deg2rad(-30), deg2rad(60))
>>> has_angle_mark([0.1, (0.2, theta)]), is_angle(0.5)
(True, False)
"""
from __future__ import annotations

import math

import numpy as np

__all__ = ["Angle", "AngleArray", "is_angle", "has_angle_mark"]


def _is_real_scalar(x) -> bool:
    return isinstance(x, (int, float, np.integer, np.floating)) and not isinstance(x, (bool, np.bool_))


class Angle(float):
    """A float in radians that was made from degrees by :func:`dhlab.deg2rad`."""

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
    """An array in radians that was made from degrees by :func:`dhlab.deg2rad`."""

    def __array_finalize__(self, obj):  # keep the subclass through views and arithmetic
        pass


def is_angle(x) -> bool:
    """True when ``x`` was made by :func:`dhlab.deg2rad` (so it is an angle, not a length)."""
    return isinstance(x, (Angle, AngleArray))


def has_angle_mark(x) -> bool:
    """True when ``x`` or anything inside it (lists, tuples, object arrays) was made by :func:`dhlab.deg2rad`."""
    if isinstance(x, (Angle, AngleArray)):
        return True
    if isinstance(x, (list, tuple)):
        return any(has_angle_mark(v) for v in x)
    if isinstance(x, np.ndarray) and x.dtype == object:
        return any(has_angle_mark(v) for v in x.ravel())
    return False
