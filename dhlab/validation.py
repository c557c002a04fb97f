"""Checks at the boundary of the public API.

Every error says which value is wrong, what was expected and how to fix it,
so that a student never meets a traceback from deep inside numpy or sympy.
"""
from __future__ import annotations

import math

import numpy as np

from .units import Angle, AngleArray

__all__ = ["DHLabError", "as_float_array", "as_matrix4", "rigid_problem", "check_joint_values"]

FULL_TURN = 2 * math.pi


class DHLabError(ValueError):
    """Bad input to dhlab: the message says what was wrong and how to fix it."""


def _describe(x) -> str:
    text = repr(x)
    return text if len(text) <= 60 else text[:57] + "..."


def as_float_array(x, name: str) -> np.ndarray:
    """``x`` as a float array, or a DHLabError naming ``name``."""
    try:
        arr = np.asarray(x, dtype=float)
    except (TypeError, ValueError):
        raise DHLabError(
            f"{name} must be numbers, got {_describe(x)}. "
            "Symbols belong in the symbolic functions (e.g. robot.fk_sym()); "
            "here pass plain numbers (angles in radians, lengths in the robot's unit)."
        ) from None
    return arr


def _check_finite(arr: np.ndarray, name: str) -> None:
    bad = ~np.isfinite(arr)
    if bad.any():
        index = tuple(int(i) for i in np.argwhere(bad)[0])
        where = f"{name}[{', '.join(map(str, index))}]" if arr.ndim else name
        raise DHLabError(f"{where} is {arr[index]}: every value must be a finite number.")


def as_matrix4(T, name: str = "T", batch: bool = False) -> np.ndarray:
    """A finite float 4x4 (or (N,4,4) when ``batch``) array, or a clear error."""
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


def check_joint_values(q, links, name: str = "q") -> np.ndarray:
    """Joint values as a float array of shape (n,) or (N, n), checked against the links.

    Revolute values are radians; a value beyond one full turn is almost always
    degrees typed by mistake, so it is refused with the fix (``dhlab.deg``).
    A value made by ``deg()`` given to a prismatic joint (a length) is refused too.
    """
    n = len(links)
    _check_angle_marks(q, links, name)
    arr = as_float_array(q, name)
    if arr.ndim == 0 or arr.shape[-1] != n or arr.ndim > 2:
        raise DHLabError(
            f"{name} must hold {n} joint value{'s' if n != 1 else ''} "
            f"(shape ({n},), or (N, {n}) for a batch), got shape {arr.shape}."
        )
    _check_finite(arr, name)
    for j, link in enumerate(links):
        if link.is_revolute:
            worst = np.abs(arr[..., j]).max()
            if worst > FULL_TURN + 1e-9:
                raise DHLabError(
                    f"{name}[{j}] (joint {j + 1}, revolute) is {worst:g} rad, more than a full turn: "
                    f"angles are in radians. If you meant {worst:g} degrees, pass dhlab.deg({worst:g})."
                )
    return arr


def _check_angle_marks(q, links, name: str) -> None:
    """Refuse deg() values given to prismatic joints."""
    prismatic = [j for j, link in enumerate(links) if link.is_prismatic]
    if not prismatic:
        return
    if isinstance(q, AngleArray):
        j = prismatic[0]
        raise DHLabError(
            f"{name} was made with dhlab.deg(), but joint {j + 1} is prismatic: its value is a length, "
            "not an angle. Convert only the revolute values, e.g. [deg(30), 0.5, deg(45)]."
        )
    if isinstance(q, (list, tuple)) and len(q) == len(links):
        for j in prismatic:
            if isinstance(q[j], (Angle, AngleArray)):
                raise DHLabError(
                    f"{name}[{j}] = {q[j]!r} is an angle, but joint {j + 1} is prismatic: "
                    "give its displacement as a length (in the robot's unit)."
                )
