"""Angle units: the API works in radians; people read and type degrees.

``deg(30)`` converts degrees to radians *and remembers that the value is an
angle*, so that passing it to a prismatic joint (which expects a length) is
caught instead of silently moving the joint by 0.52 length units.

>>> from dhlab import deg, rad
>>> round(deg(90), 6)
1.570796
>>> rad(deg(45))
45.0
"""
from __future__ import annotations

import math

import numpy as np

__all__ = ["deg", "rad", "Angle", "AngleArray", "is_angle"]


class Angle(float):
    """A float in radians that was made from degrees by :func:`deg`."""

    def __repr__(self) -> str:
        return f"deg({math.degrees(self):g})"


class AngleArray(np.ndarray):
    """An array in radians that was made from degrees by :func:`deg`."""

    def __array_finalize__(self, obj):  # keep the subclass through views only
        pass


def deg(x):
    """Degrees -> radians. Scalars give an :class:`Angle`, sequences an :class:`AngleArray`.

    >>> deg([0, 90, 180]).round(4).tolist()
    [0.0, 1.5708, 3.1416]
    """
    if np.ndim(x) == 0:
        return Angle(math.radians(float(x)))
    return np.radians(np.asarray(x, dtype=float)).view(AngleArray)


def rad(x):
    """Radians -> degrees (plain floats or arrays: the inverse of :func:`deg`).

    >>> rad(np.pi)
    180.0
    """
    if np.ndim(x) == 0:
        return math.degrees(float(x))
    return np.degrees(np.asarray(x, dtype=float))


def is_angle(x) -> bool:
    """True when ``x`` was made by :func:`deg` (so it is an angle, not a length)."""
    return isinstance(x, (Angle, AngleArray))
