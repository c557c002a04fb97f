"""Reading and checking the input of :func:`dhlab.dh_frames.dh_assignment`: the joint axes,
the end effector, the options, the tolerance and the joint limits — each refused with a
:class:`~dhlab.DHLabError` that names the value, what was expected and how to fix it.

Part of :mod:`dhlab.dh_frames` (import from there).

>>> read_axes([((0, 0, 0), (0, 0, 2), "R")])[0][1].tolist()
[0.0, 0.0, 1.0]
>>> read_axes([((0, 0, 0), (0, 0, 1), "r")])
Traceback (most recent call last):
...
dhlab.validation.DHLabError: axes[0] (joint 1) kind must be 'R' or 'P', got 'r'. Write it in capitals: 'R'.
"""
from __future__ import annotations

import numpy as np

from ..errors import DHLabError
from ..i18n import _
from ..units import has_angle_mark
from ..validation import FULL_TURN, as_float_array, as_number, check_length_size, rigid_problem
from .report import vector_text

__all__ = ["CASE1_RULES", "PARALLEL_RULES", "PRISMATIC_RULES", "short_repr"]

CASE1_RULES = {"z_prev x z": +1, "z x z_prev": -1, "nearest": 0}
PARALLEL_RULES = ("at_joint", "zero_d")
PRISMATIC_RULES = ("given", "through_origin")


def read_axes(axes) -> list:
    """[(point, unit direction, kind)] or a DHLabError naming the bad entry."""
    example = "[((0, 0, 0), (0, 0, 1), 'R'), ((0, 0, 1), (0, 1, 0), 'P')]"
    if isinstance(axes, (str, bytes, dict)) or not _count(axes):
        raise DHLabError(_("axes must be a list with one (point, direction, kind) per joint, e.g. {example}; "
                           "got {value}.").format(example=example, value=short_repr(axes)))
    lines = []
    for j, entry in enumerate(axes):
        where = _("axes[{j}] (joint {joint})").format(j=j, joint=j + 1)
        if isinstance(entry, (str, bytes, dict)) or _count(entry) != 3:
            raise DHLabError(_("{where} must be (point, direction, kind), e.g. ((0, 0, 0), (0, 0, 1), 'R'); "
                               "got {value}.").format(where=where, value=short_repr(entry)))
        point, direction, kind = entry
        p = _vector3(point, _("{where} point").format(where=where))
        u = _vector3(direction, _("{where} direction").format(where=where), length=False)
        size = float(np.abs(u).max())
        if size < 1e-12:
            raise DHLabError(_(
                "{where} direction is {value}: a joint axis needs a non-zero direction vector. Its sense is the "
                "positive sense of q{joint} (right-hand rule for 'R', sliding sense for 'P').").format(
                where=where, value=vector_text(u), joint=j + 1))
        if not isinstance(kind, str) or kind not in ("R", "P"):
            hint = " " + (_("Write it in capitals: {kind!r}.").format(kind=kind.upper())
                          if isinstance(kind, str) and kind in ("r", "p") else
                          _("'R' is a revolute joint (it turns about the axis), "
                            "'P' a prismatic one (it slides along it)."))
            raise DHLabError(_("{where} kind must be 'R' or 'P', got {value}.").format(
                where=where, value=short_repr(kind)) + hint)
        u = u / size                                   # first to about 1: no overflow in the norm of (0, 0, 1e308)
        lines.append((p, u / np.linalg.norm(u), kind))
    return lines


def _vector3(value, name: str, length: bool = True) -> np.ndarray:
    """3 finite numbers; with ``length`` (a point) each at most LARGEST_LENGTH."""
    arr = as_float_array(value, name)
    if arr.shape != (3,):
        raise DHLabError(_("{name} must be 3 numbers (x, y, z), got shape {shape}: {value}.").format(
            name=name, shape=arr.shape, value=short_repr(value)))
    if not np.isfinite(arr).all():
        raise DHLabError(_("{name} is {value}: every coordinate must be a finite number.").format(
            name=name, value=arr.tolist()))
    if length:
        check_length_size(float(np.abs(arr).max()), name)
    return arr


def read_tool(tool):
    """(pose or None, point) from a 4x4 pose or a 3-point."""
    if tool is None:
        raise DHLabError(_(
            "tool is missing: rule 9 puts frame n at the end effector, so give its pose (4x4) or its point "
            "(x, y, z), in the same pose and world frame as the axes. If the end effector is on the last "
            "joint's axis, a point on that axis will do, e.g. tool=axes[-1][0]."))
    arr = as_float_array(tool, "tool")
    if arr.shape == (3,):
        return None, _vector3(arr, "tool")
    if arr.shape != (4, 4):
        raise DHLabError(_("tool must be the end effector's pose (4x4) or point (x, y, z), got shape {shape}.").format(
            shape=arr.shape))
    if not np.isfinite(arr).all():
        raise DHLabError(_("tool has a value that is not a finite number (nan or inf): check the pose."))
    problem = rigid_problem(arr)
    if problem:
        raise DHLabError(_("tool is not a proper rigid transform: {problem}.").format(problem=problem))
    check_length_size(float(np.abs(arr[:3, 3]).max()), "tool (its position)")
    return arr, arr[:3, 3].copy()


def read_choice(value, allowed, name: str):
    """``value`` as one of the option names ``allowed`` (``×`` may be written ``x``), or a clear error."""
    key = " ".join(value.replace("×", "x").split()) if isinstance(value, str) else None
    if key not in allowed:                        # (text only: a list or a dict is not an option)
        options = ", ".join(repr(a) for a in allowed)
        raise DHLabError(_("{name} must be one of {options}, got {value}.").format(
            name=name, options=options, value=short_repr(value)))
    return allowed[key] if isinstance(allowed, dict) else key


def read_tol(tol) -> float:
    """The relative tolerance ``tol``: a small positive number (at most 1e-2), or a clear error."""
    expected = _("tol must be a small positive number (relative tolerance, e.g. 1e-9; at most 1e-2)")
    try:
        value = as_number(tol, "tol")              # text, True, None, nan, complex: refused
    except DHLabError as error:
        raise DHLabError(_("{expected}, got {value}: {error}").format(expected=expected, value=short_repr(tol),
                                                                   error=error)) from None
    if not (0 < value <= 1e-2):
        raise DHLabError(_("{expected}, got {value}.").format(expected=expected, value=short_repr(tol)))
    return value


def read_qlim(qlim, kinds) -> list:
    """One (low, high) or None per joint of ``kinds`` ('R'/'P'), checked as each joint's limits."""
    if qlim is None:
        return [None] * len(kinds)
    if isinstance(qlim, (str, bytes, dict, set)) or _count(qlim) != len(kinds):
        raise DHLabError(_("qlim must give one (low, high) per joint ({n}), got {value}.").format(
            n=len(kinds), value=short_repr(qlim)))
    out = []
    for j, (limits, kind) in enumerate(zip(qlim, kinds)):
        if kind == "P" and has_angle_mark(limits):
            raise DHLabError(_("qlim[{j}] (joint {joint}, prismatic) is a range of lengths, but it was made with "
                               "deg2rad(): give lengths, e.g. (0.0, 0.5); got {value}.").format(
                j=j, joint=j + 1, value=short_repr(limits)))
        arr = as_float_array(limits, f"qlim[{j}]")
        if arr.shape != (2,) or not np.isfinite(arr).all() or not arr[0] < arr[1]:
            raise DHLabError(_("qlim[{j}] (joint {joint}) must be (low, high) with low < high, got {value}.").format(
                j=j, joint=j + 1, value=short_repr(limits)))
        if kind == "R" and np.abs(arr).max() > FULL_TURN + 1e-9:
            raise DHLabError(_(
                "qlim[{j}] (joint {joint}, revolute) is {value}: more than one full turn. Limits are radians: for "
                "degrees write dhlab.deg2rad({low}), dhlab.deg2rad({high}).").format(
                j=j, joint=j + 1, value=arr.tolist(), low=f"{arr[0]:g}", high=f"{arr[1]:g}"))
        out.append((float(arr[0]), float(arr[1])))
    return out


def robot_size(points) -> float:
    """The robot's size: the spread of the given points (not less than 1e-3 of their distance
    from the world origin, which sets the rounding error of their coordinates)."""
    P = np.array(points)
    spread = float(np.linalg.norm(P - P[0], axis=1).max())
    size = max(spread, 1e-3 * float(np.linalg.norm(P, axis=1).max()))
    return size if size > 0 else 1.0


def short_repr(x, width: int = 60) -> str:
    """``repr(x)`` cut to ``width`` characters for a message (the input's errors here, a student's
    answer in the course's feedback). Never raises: a value whose repr fails (a list nested
    thousands deep, a broken ``__repr__``) is named by its type.

    >>> short_repr(list(range(30)), 20)
    '[0, 1, 2, 3, 4, 5…'
    """
    try:
        text = repr(x)
    except Exception:                     # RecursionError, or whatever a student's __repr__ raises
        text = _("<a {type} that cannot be printed>").format(type=type(x).__name__)
    return text if len(text) <= width else text[:width - 3] + "…"


def _count(x):
    """len(x), or None when x has no length (a number, a 0-d array)."""
    try:
        return len(x)
    except TypeError:
        return None
