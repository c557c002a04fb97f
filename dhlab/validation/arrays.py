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

import numpy as np
import sympy as sp

from ..units import Angle
from .values import DHLabError, _real, describe

__all__ = ["as_sequence", "as_float_array", "as_vector", "as_matrix4", "as_sym_matrix4", "rigid_problem"]


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
        why = " (a set has no order)" if isinstance(x, (set, frozenset)) else ""
        raise DHLabError(f"{name} must be {expected}{why}; got {describe(x)}.")
    if size is not None and len(items) != size:
        raise DHLabError(f"{name} must be {expected}: {size} item{'s' if size != 1 else ''}, got {len(items)}: "
                         f"{describe(x)}.")
    return items


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
    if obj is None or any(isinstance(e, (list, tuple)) or isinstance(e, np.ndarray) and e.ndim
                          for e in obj.ravel()):      # a 0-d array is the number it holds
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
