"""Checks of arrays at the boundary: numbers of any shape, vectors, 4×4 matrices
(numeric and symbolic), and whether a 4×4 is a rigid transform.

Part of :mod:`dhlab.validation` (import from there).

>>> as_float_array([[1, 2], [3, 4]], "M").tolist()
[[1.0, 2.0], [3.0, 4.0]]
>>> as_vector([1, None, 3], "p", 3)
Traceback (most recent call last):
...
dhlab.validation.DHLabError: p must be numbers: p[1] = None is not a valid number: it is missing (None): give a number.
"""
from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from ..errors import DHLabError
from ..i18n import N_, _
from ..lazy_sympy import is_matrix
from .decimal_commas import with_decimal_comma_note
from .marks import Angle
from .values import describe, real_number

if TYPE_CHECKING:
    import sympy as sp

MUST_BE_NUMBERS = N_("{name} must be numbers: {error}")

__all__ = ["check_finite", "as_sequence", "as_float_array", "as_vector", "as_matrix4", "as_sym_matrix4",
           "rigid_problem"]


# ------------------------------------------------------------------------------------------
# Sequences (rows of a table, one item per joint): ordered, so no sets; not text or a mapping
# ------------------------------------------------------------------------------------------
def as_sequence(x, name: str, expected: str, size: int | None = None) -> list:
    """``x`` (a list, tuple, 1-d or deeper array, or a generator) as a list of its items, in order.

    Text, bytes, a dict, a set (it has no order), a 0-d array and a number are refused with
    ``expected`` (what to give, e.g. "one (low, high) per row"); ``size``, when given, is the
    number of items needed.
    """
    ordered = not isinstance(x, (str, bytes, bytearray, dict, set, frozenset)) and hasattr(x, "__iter__")
    try:
        items = list(x) if ordered else None
    except TypeError:              # iterable in name only, e.g. a 0-d numpy array
        items = None
    if items is None:
        message = (_("{name} must be {expected} (a set has no order); got {value}.") if isinstance(x, (set, frozenset))
                   else _("{name} must be {expected}; got {value}."))
        raise DHLabError(message.format(name=name, expected=expected, value=describe(x)))
    if size is not None and len(items) != size:
        message = (_("{name} must be {expected}: {size} item, got {k}: {value}.") if size == 1 else
                   _("{name} must be {expected}: {size} items, got {k}: {value}."))
        # ("q1", 0,4, 0,35, 0) has six items, not four
        raise DHLabError(with_decimal_comma_note(
            message.format(name=name, expected=expected, size=size, k=len(items), value=describe(x)), items, size))
    return items


# ------------------------------------------------------------------------------------------
# Arrays
# ------------------------------------------------------------------------------------------
def as_float_array(x, name: str, finite: bool = False) -> np.ndarray:
    """``x`` (a number, nested lists, a numpy array or a sympy Matrix of real numbers)
    as a float array, or a DHLabError naming ``name``."""
    if isinstance(x, np.ndarray):
        arr = _numpy_floats(x, name)
    elif is_matrix(x):
        arr = _objects_floats(np.array(x.tolist(), dtype=object).reshape(x.shape), name)
    elif isinstance(x, (list, tuple)):
        arr = _sequence_floats(x, name)
    else:
        try:
            arr = np.array(real_number(x, name), dtype=float)
        except DHLabError as error:
            raise DHLabError(_(MUST_BE_NUMBERS).format(name=name, error=error)) from None
    if finite:
        check_finite(arr, name)
    return arr


def _numpy_floats(x: np.ndarray, name: str) -> np.ndarray:
    if isinstance(x, np.ma.MaskedArray):
        if np.ma.is_masked(x):
            raise DHLabError(_("{name} has masked (missing) values: fill them in first, e.g. {name}.filled(0.0), "
                               "or drop those entries.").format(name=name))
        x = np.asarray(x.data)
    kind = x.dtype.kind
    if kind == "f":
        return np.asarray(x, dtype=float)
    if kind in "iu":
        return x.astype(float)
    if kind == "O":
        return _objects_floats(x, name)
    what = {"b": N_("True/False values"), "c": N_("complex numbers"), "M": N_("dates"), "m": N_("time spans"),
            "U": N_("text"), "S": N_("text")}.get(kind)
    what = _(what) if what else _("values of type {dtype}").format(dtype=x.dtype)
    raise DHLabError(_("{name} holds {what}, not real numbers: give plain numbers (angles in radians, lengths in "
                       "the robot's unit).").format(name=name, what=what))


def _sequence_floats(x, name: str) -> np.ndarray:
    try:
        obj = np.array(x, dtype=object)
    except (ValueError, TypeError):
        obj = None
    if obj is None or any(isinstance(e, (list, tuple)) or isinstance(e, np.ndarray) and e.ndim
                          for e in obj.ravel()):      # a 0-d array is the number it holds
        raise DHLabError(_("{name} = {value} is ragged: its rows have different lengths. Every row must have the "
                           "same number of values.").format(name=name, value=describe(x)))
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
            raise DHLabError(_("{name} is ragged: {where} is a sequence where a number was expected.").format(
                name=name, where=where))
        try:
            out[k] = real_number(e, where)
        except DHLabError as error:
            raise DHLabError(_(MUST_BE_NUMBERS).format(name=name, error=error)) from None
    return out.reshape(obj.shape)


def check_finite(arr: np.ndarray, name: str) -> None:
    """Refuse a float array with a nan or an infinity, naming the first such entry."""
    bad = ~np.isfinite(arr)
    if bad.any():
        index = tuple(int(i) for i in np.argwhere(bad)[0])
        where = f"{name}[{', '.join(map(str, index))}]" if arr.ndim else name
        raise DHLabError(_("{where} is {value}: every value must be a finite number.").format(
            where=where, value=arr[index]))


def as_vector(x, name: str, size: int) -> np.ndarray:
    """``size`` finite numbers as a float array of shape (size,)."""
    arr = as_float_array(x, name)
    if arr.shape != (size,):
        message = _("{name} must be {size} numbers, got shape {shape}: {value}.").format(
            name=name, size=size, shape=arr.shape, value=describe(x))
        raise DHLabError(with_decimal_comma_note(message, arr.tolist(), size) if arr.ndim == 1 else message)
    check_finite(arr, name)
    return arr


# ------------------------------------------------------------------------------------------
# Matrices
# ------------------------------------------------------------------------------------------
def as_matrix4(T, name: str = "T", batch: bool = False) -> np.ndarray:
    """A finite float 4x4 (or (N,4,4) when ``batch``) array, or a clear error.

    A sympy Matrix is accepted when it has no symbols.
    """
    if is_matrix(T) and T.free_symbols:
        raise DHLabError(_("{name} has symbols {symbols}: substitute numbers (M.subs(...)) before using it "
                           "numerically.").format(name=name, symbols=sorted(map(str, T.free_symbols))))
    arr = as_float_array(T, name)
    ok = arr.shape == (4, 4) or (batch and arr.ndim == 3 and arr.shape[1:] == (4, 4))
    if not ok:
        expected = "(4, 4) or (N, 4, 4)" if batch else "(4, 4)"
        raise DHLabError(_("{name} must be a homogeneous matrix of shape {expected}, got shape {shape}. A "
                           "homogeneous transform is [[R, p], [0, 0, 0, 1]] with a 3x3 rotation R and a position "
                           "p.").format(name=name, expected=expected, shape=arr.shape))
    check_finite(arr, name)
    return arr


def as_sym_matrix4(T, name: str = "T") -> sp.Matrix:
    """A 4x4 sympy Matrix (numbers or expressions), every entry real and finite."""
    import sympy as sp  # (a symbolic result: imported on first use, see dhlab.lazy_sympy)
    if not isinstance(T, sp.MatrixBase):
        return sp.Matrix(as_matrix4(T, name))
    if T.shape != (4, 4):
        raise DHLabError(_("{name} must be a 4x4 homogeneous matrix, got shape {shape}. A homogeneous transform is "
                           "[[R, p], [0, 0, 0, 1]].").format(name=name, shape=T.shape))
    for (i, j), e in np.ndenumerate(np.array(T.tolist(), dtype=object)):
        real_number(e, f"{name}[{i}, {j}]", symbolic=True)
    return sp.Matrix(T)


def rigid_problem(T: np.ndarray, tol: float = 1e-9) -> str | None:
    """Why the 4x4 ``T`` is not a proper rigid transform, or None if it is."""
    R = T[:3, :3]
    if not np.allclose(T[3], [0, 0, 0, 1], atol=tol):
        return _("its last row is {row}, not [0, 0, 0, 1]").format(row=np.round(T[3], 6).tolist())
    gram = R.T @ R
    if not np.allclose(gram, np.eye(3), atol=max(tol, 1e-9) * 10):
        err = np.abs(gram - np.eye(3)).max()
        return _("its rotation part is not orthonormal (|RᵀR − I| reaches {err:.3g}): its columns must be unit "
                 "vectors at right angles").format(err=err)
    det = np.linalg.det(R)
    if det < 0:
        return _("det R = {det:.6g}: it is a reflection (a mirror), not a rotation").format(det=det)
    return None
