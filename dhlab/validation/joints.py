"""Checks of joint values at the boundary: one pose or a batch, radians for revolute
joints (at most a full turn: more is degrees by mistake), lengths for prismatic ones
(no ``deg2rad()`` mark, at any depth; at most ``LARGEST_LENGTH``), and each joint's limits.

Part of :mod:`dhlab.validation` (import from there).

>>> from dhlab import PrismaticDH, RevoluteDH, deg2rad
>>> links = [RevoluteDH(), PrismaticDH()]
>>> check_joint_values([deg2rad(30), 0.2], links).round(4).tolist()
[0.5236, 0.2]
>>> check_joint_values([0.1, deg2rad(30)], links)
Traceback (most recent call last):
...
dhlab.validation.DHLabError: q[1] = deg2rad(30) is an angle, but joint 2 is prismatic:
    give its displacement as a length (in the robot's unit).
"""
from __future__ import annotations

import math

import numpy as np

from ..errors import DHLabError
from ..i18n import _
from .arrays import as_float_array, check_finite
from .marks import Angle, AngleArray, has_angle_mark
from .values import FULL_TURN, as_angle, as_number, check_length_size, describe

__all__ = ["check_joint_values", "as_qlim"]


# ------------------------------------------------------------------------------------------
# Joint values
# ------------------------------------------------------------------------------------------
def check_joint_values(q, links, name: str = "q", single: bool = False) -> np.ndarray:
    """Joint values as a float array of shape (n,) or (N, n), checked against the links.

    Revolute values are radians; a value beyond one full turn is almost always
    degrees typed by mistake, so it is refused with the fix (``dhlab.deg2rad``).
    A value made by ``deg2rad()`` given to a prismatic joint (a length) is refused too,
    wherever it sits (a list, a nested batch, a numpy array). ``single=True``
    refuses a batch where one pose is expected. A batch may be empty, (0, n).
    """
    n = len(links)
    prismatic = [j for j, link in enumerate(links) if link.is_prismatic]
    if prismatic:
        _check_angle_marks(q, n, prismatic, name)
    arr = as_float_array(q, name)
    if arr.ndim == 0 or arr.shape[-1] != n or arr.ndim > 2 or (single and arr.ndim != 1):
        expected = (_("shape ({n},)") if single else _("shape ({n},), or (N, {n}) for a batch")).format(n=n)
        hint = (_(" This function takes one pose, not a batch: pass one row, e.g. q[0].")
                if single and arr.ndim == 2 and arr.shape[-1] == n else "")
        message = (_("{name} must hold {n} joint value ({expected}), got shape {shape}.") if n == 1 else
                   _("{name} must hold {n} joint values ({expected}), got shape {shape}."))
        raise DHLabError(message.format(name=name, n=n, expected=expected, shape=arr.shape) + hint)
    check_finite(arr, name)
    if arr.size == 0:
        return arr
    revolute = [j for j in range(n) if j not in prismatic]
    if revolute:
        for j in revolute:
            value = np.abs(arr[..., j]).max()      # column by column: faster than max(axis=0)
            if value > FULL_TURN + 1e-9:
                raise DHLabError(_("{name}[{j}] (joint {joint}, revolute) is {value:g} rad, more than a full turn: "
                                   "angles are in radians. If you meant {value:g} degrees, pass "
                                   "dhlab.deg2rad({value:g}).").format(name=name, j=j, joint=j + 1, value=value))
    for j in prismatic:
        column = arr[..., j]
        check_length_size(float(np.abs(column).max()),
                          _("{name}[{j}] (joint {joint}, prismatic)").format(name=name, j=j, joint=j + 1))
        _check_not_radians(column, j, name)
    return arr


def _angle_columns(q, n: int) -> set:
    """The positions j (0 … n−1) whose value carries a deg2rad() mark, at any depth of ``q``."""
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
    """Refuse deg2rad() values given to prismatic joints."""
    marked = _angle_columns(q, n) & set(prismatic)
    if not marked:
        return
    j = min(marked)
    if isinstance(q, AngleArray):
        raise DHLabError(_("{name} was made with dhlab.deg2rad(), but joint {joint} is prismatic: its value is a "
                           "length, not an angle. Convert only the revolute values, e.g. [deg2rad(30), 0.5, "
                           "deg2rad(45)].").format(name=name, joint=j + 1))
    shown = f" = {q[j]!r}" if isinstance(q, (list, tuple)) and len(q) == n else ""
    raise DHLabError(_("{name}[{j}]{shown} is an angle, but joint {joint} is prismatic: give its displacement as a "
                       "length (in the robot's unit).").format(name=name, j=j, shown=shown, joint=j + 1))


def _check_not_radians(column: np.ndarray, j: int, name: str) -> None:
    """A prismatic value equal, to the last bit, to a whole number of degrees in radians
    (deg2rad(30) = 0.5235987755982988) is an angle whose deg2rad() mark numpy dropped."""
    degrees = np.round(column * (180 / math.pi))
    hit = (degrees != 0) & (np.abs(degrees) <= 360) & (np.radians(degrees) == column)
    if hit.any():
        value = column[np.argmax(hit)] if column.ndim else column
        raise DHLabError(_("{name}[{j}] = {value!r} is exactly deg2rad({degrees:g}), an angle, but joint {joint} is "
                           "prismatic: give its displacement as a length (in the robot's unit).").format(
                               name=name, j=j, value=float(value), degrees=float(np.degrees(value)), joint=j + 1))


# ------------------------------------------------------------------------------------------
# Joint limits
# ------------------------------------------------------------------------------------------
def as_qlim(qlim, revolute: bool, name: str = "qlim") -> tuple:
    """One joint's limits (low, high): finite, low < high; radians (at most a full turn
    either way) for a revolute joint, lengths (no deg2rad() mark, at most ``LARGEST_LENGTH``)
    for a prismatic one."""
    if not _is_pair(qlim):
        message = (_("{name} must be two numbers (low, high) in radians, e.g. (deg2rad(-90), deg2rad(90)); got "
                     "{value}.") if revolute else
                   _("{name} must be two numbers (low, high) in lengths, e.g. (0.0, 0.5); got {value}."))
        raise DHLabError(message.format(name=name, value=describe(qlim)))
    if not revolute and has_angle_mark(qlim):
        raise DHLabError(_("{name} of a prismatic joint is a range of lengths, but it was made with deg2rad(): give "
                           "lengths, e.g. (0.0, 0.5); got {value}.").format(name=name, value=describe(qlim)))
    low, high = (as_number(v, f"{name}[{k}]") for k, v in enumerate(qlim))
    if not low < high:
        raise DHLabError(_("{name} must be (low, high) with low < high, got {value}.").format(
            name=name, value=describe(qlim)))
    for v in (low, high):
        if revolute:
            as_angle(v, _("{name} (a revolute joint's limit)").format(name=name))
        else:                       # a longer range overflows the robot's reach and its sampled poses
            check_length_size(abs(v), _("{name} (a prismatic joint's limit)").format(name=name))
    return (low, high)


def _is_pair(qlim) -> bool:
    """True for two entries side by side (a list, a tuple, a 1-d array), not text, a mapping or a set."""
    if isinstance(qlim, (str, bytes, dict, set)) or not hasattr(qlim, "__len__"):
        return False
    try:
        return np.ndim(qlim) == 1 and len(qlim) == 2
    except (ValueError, TypeError):            # ragged, e.g. (0, [1]): numpy cannot make an array of it
        return False
