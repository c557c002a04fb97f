"""Homogeneous transformation matrices (4x4), numeric and symbolic.

Every function here works with plain numbers (returning a numpy array) and
with sympy symbols (returning a sympy Matrix), so the same names serve the
derivations and the numbers::

    >>> import sympy as sp
    >>> from dhlab.transforms import Rz, trans
    >>> th, l = sp.symbols("theta l")
    >>> Rz(th) * trans(l, 0, 0)          # rotate, then move along the new x
    Matrix([
    [cos(theta), -sin(theta), 0, l*cos(theta)],
    [sin(theta),  cos(theta), 0, l*sin(theta)],
    [         0,            0, 1,            0],
    [         0,            0, 0,            1]])

With only numbers the result is a float numpy array; mixing it into a sympy
product brings floats (1.0) in: keep at least one symbol, or use sympy numbers.

Angles are radians (use ``dhlab.deg2rad(30)`` for degrees). A numeric angle of
more than one full turn is refused: it is almost always degrees by mistake.

Seed 000 names two products ``Tz[θ, z] = Rz(θ)·Tr(0,0,z)`` and
``Tx[α, x] = Tr(x,0,0)·Rx(α)``; their product is the Denavit-Hartenberg matrix
``dh_matrix(θ, d, a, α) = Rz(θ)·Tr(0, 0, d)·Tr(a, 0, 0)·Rx(α)``.
"""
from __future__ import annotations

import math

import numpy as np

from .errors import DHLabError
from .i18n import _
from .lazy_sympy import is_matrix, is_sympy
from .validation import as_angle, as_length, as_matrix4, as_sym_matrix4, as_text, as_tolerance, rigid_problem

__all__ = [
    "Rx", "Ry", "Rz", "trans", "Tr", "Tz", "Tx", "dh_matrix",
    "inv", "is_rigid", "check_rigid", "rpy", "position", "rotation",
]


def _symbolic(*args) -> bool:
    """True when any argument is a sympy value (then the result is a sympy Matrix)."""
    return any(is_sympy(a) for a in args)


def _angle(value, name: str):
    """A checked angle: a float, or a sympy value (exact numbers stay exact)."""
    return as_angle(value, name, symbolic=True)


def _length(value, name: str):
    """A checked length: a float, or a sympy value."""
    return as_length(value, name, symbolic=True)


def _rotation(axis: int, angle, name: str = "angle"):
    """4x4 rotation about the x (0), y (1) or z (2) axis."""
    angle = _angle(angle, name)
    if _symbolic(angle):
        import sympy as sp  # (loaded already: the angle is a sympy value)
        c, s, M = sp.cos(angle), sp.sin(angle), sp.eye(4)
    else:
        c, s, M = math.cos(angle), math.sin(angle), np.eye(4)
    i, j = (axis + 1) % 3, (axis + 2) % 3   # the plane the rotation turns
    M[i, i], M[i, j] = c, -s
    M[j, i], M[j, j] = s, c
    return M


def Rx(alpha):
    """Rotation by ``alpha`` (radians) about x."""
    return _rotation(0, alpha, "alpha")


def Ry(beta):
    """Rotation by ``beta`` (radians) about y."""
    return _rotation(1, beta, "beta")


def Rz(theta):
    """Rotation by ``theta`` (radians) about z."""
    return _rotation(2, theta, "theta")


def trans(x=0, y=0, z=0):
    """Pure translation by (x, y, z)."""
    x, y, z = (_length(v, n) for v, n in ((x, "x"), (y, "y"), (z, "z")))
    if _symbolic(x, y, z):
        import sympy as sp  # (loaded already: a length is a sympy value)
        M = sp.eye(4)
        M[0, 3], M[1, 3], M[2, 3] = x, y, z
        return M
    M = np.eye(4)
    M[:3, 3] = x, y, z
    return M


Tr = trans  # the seeds' name: Tr(x, y, z) / Tras(x, y, z)


def Tz(theta, z):
    """Seed 000's ``Tz[θ, z] = Rz(θ)·Tr(0, 0, z)``: turn about z, slide along z (they commute)."""
    theta, z = _angle(theta, "theta"), _length(z, "z")
    return Rz(theta) @ trans(0, 0, z) if not _symbolic(theta, z) else Rz(theta) * trans(0, 0, z)


def Tx(alpha, x):
    """Seed 000's ``Tx[α, x] = Tr(x, 0, 0)·Rx(α)``: slide along x, turn about x (they commute)."""
    alpha, x = _angle(alpha, "alpha"), _length(x, "x")
    return trans(x, 0, 0) @ Rx(alpha) if not _symbolic(alpha, x) else trans(x, 0, 0) * Rx(alpha)


def dh_matrix(theta, d, a, alpha):
    """The standard DH matrix ``A = Rz(θ)·Tr(0, 0, d)·Tr(a, 0, 0)·Rx(α)`` (= seed 000's Tz[θ,d]·Tx[α,a]).

    >>> import sympy as sp
    >>> th, d, a, al = sp.symbols("theta d a alpha")
    >>> dh_matrix(th, d, a, al)[0, :]
    Matrix([[cos(theta), -sin(theta)*cos(alpha), sin(alpha)*sin(theta), a*cos(theta)]])
    """
    theta, alpha = _angle(theta, "theta"), _angle(alpha, "alpha")
    d, a = _length(d, "d"), _length(a, "a")
    if _symbolic(theta, d, a, alpha):
        return Tz(theta, d) * Tx(alpha, a)
    return Tz(theta, d) @ Tx(alpha, a)


def rotation(T):
    """The 3x3 rotation block of a homogeneous matrix."""
    return _any_matrix4(T)[:3, :3]


def position(T):
    """The position (translation column) of a homogeneous matrix."""
    return _any_matrix4(T)[:3, 3]


def _any_matrix4(T, name: str = "T"):
    """A 4x4 as it came: a sympy Matrix (checked) or a float array."""
    return as_sym_matrix4(T, name) if is_matrix(T) else as_matrix4(T, name)


def is_rigid(T, tol: float = 1e-9) -> bool:
    """True when the 4x4 ``T`` is a proper rigid transform:
    orthonormal rotation, det R = +1, last row (0, 0, 0, 1)."""
    tol = as_tolerance(tol, "tol", upper=0.1)
    return rigid_problem(as_matrix4(T), tol) is None


def check_rigid(T, name: str = "T", tol: float = 1e-9) -> np.ndarray:
    """Return ``T`` as a float array, or raise DHLabError saying what is wrong with it."""
    name = as_text(name, "name")
    tol = as_tolerance(tol, "tol", upper=0.1)
    T = as_matrix4(T, name)
    problem = rigid_problem(T, tol)
    if problem:
        raise DHLabError(_("{name} is not a proper rigid transform: {problem}.").format(name=name, problem=problem))
    return T


def inv(T):
    """Inverse of a homogeneous transform, using its structure: [Rᵀ, −Rᵀp].

    Symbolic matrices are inverted the same way (no general matrix inverse needed).

    >>> import numpy as np
    >>> T = Rz(0.3) @ trans(1, 2, 3)
    >>> np.allclose(inv(T) @ T, np.eye(4))
    True
    """
    if is_matrix(T):
        import sympy as sp  # (loaded already: T is a sympy Matrix)
        T = as_sym_matrix4(T, "T")
        if not T.free_symbols:
            check_rigid(T, "T")            # a numeric sympy matrix must be rigid, as a numpy one
        elif T[3, :] != sp.Matrix([[0, 0, 0, 1]]):
            raise DHLabError(_("T is not a homogeneous transform: its last row is {row}, not [0, 0, 0, 1]. inv() "
                               "uses the structure [Rᵀ, −Rᵀp] of a rigid transform.").format(
                                   row=T[3, :].tolist()[0]))
        R, p = T[:3, :3], T[:3, 3]
        out = sp.eye(4)
        out[:3, :3] = R.T
        out[:3, 3] = -R.T * p
        return out
    T = check_rigid(T, "T")
    R, p = T[:3, :3], T[:3, 3]
    out = np.eye(4)
    out[:3, :3] = R.T
    out[:3, 3] = -R.T @ p
    return out


def rpy(T):
    """Roll, pitch, yaw (radians) of the rotation of ``T``: R = Rz(yaw)·Ry(pitch)·Rx(roll).

    At pitch = ±90° (gimbal lock) roll is set to 0 and yaw carries the whole turn.

    >>> import numpy as np
    >>> np.round(np.degrees(rpy(Rz(0.5) @ Ry(0.2) @ Rx(-0.1))), 6).tolist()
    [-5.729578, 11.459156, 28.64789]
    """
    R = check_rigid(T, "T")[:3, :3]
    pitch = math.atan2(-R[2, 0], math.hypot(R[0, 0], R[1, 0]))
    if math.isclose(abs(pitch), math.pi / 2, abs_tol=1e-9):
        return 0.0, pitch, math.atan2(-R[0, 1], R[1, 1])
    return math.atan2(R[2, 1], R[2, 2]), pitch, math.atan2(R[1, 0], R[0, 0])
