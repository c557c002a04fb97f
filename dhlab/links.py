"""A link as a product of elementary motions: rotations about, and translations along, x, y or z.

Not every robot of the course is written in DH form: seed 004's first link is
``Rz(θ0)·Tr(0, l1, 0)``. So a link here is any product of elementary motions
(:class:`Factor`, made by :func:`Rot` and :func:`Move`), exactly one of which carries
the joint variable. A DH link is the special case ``Rz(θ)·Tr(0, 0, d)·Tr(a, 0, 0)·Rx(α)``
(see :mod:`dhlab.dh`). A robot is a chain of links: :mod:`dhlab.chain`.

>>> from dhlab.links import Link, Rot, Move
>>> link = Link([Rot("z", joint=True), Move("x", 0.5)])
>>> link.is_revolute, str(link.joint), link.A(0).round(6)[:3, 3].tolist()
(True, 'Rz(q)', [0.5, 0.0, 0.0])
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .errors import DHLabError
from .i18n import _
from .lazy_sympy import has_symbols, is_matrix, is_sympy
from .transforms import Rx, Ry, Rz, trans
from .validation import (
    FULL_TURN,
    Angle,
    as_angle,
    as_choice,
    as_flag,
    as_length,
    as_number,
    as_qlim,
    as_sequence,
    as_text,
    describe,
)

__all__ = ["Factor", "Rot", "Move", "Link", "AXES", "DEFAULT_PRISMATIC_RANGE", "joint_value"]

AXES = {"x": 0, "y": 1, "z": 2}
DEFAULT_PRISMATIC_RANGE = (0.0, 1.0)


@dataclass(frozen=True)
class Factor:
    """One elementary motion: a rotation (``kind='R'``) or translation (``'T'``) along an axis.

    Its amount is ``value`` (a constant), plus ``sign * q`` when ``joint`` is
    True (q is the link's joint variable). ``value`` may be a number or a sympy
    expression in the robot's parameters (e.g. ``l1``).
    """
    kind: str            # 'R' or 'T'
    axis: str            # 'x', 'y' or 'z'
    value: object = 0
    joint: bool = False
    sign: int = 1

    def __post_init__(self):
        as_choice(self.kind, ("R", "T"), _("Factor kind ('R' rotation, 'T' translation)"))
        as_choice(self.axis, tuple(AXES), "axis")
        object.__setattr__(self, "joint", as_flag(self.joint, "joint"))
        what = "Rot" if self.kind == "R" else "Move"
        object.__setattr__(self, "sign", _sign(self.sign, what))
        if isinstance(self.value, str):
            raise DHLabError(_(
                "{what}('{axis}', {value!r}): the amount is text. For a named length or angle use a sympy "
                "symbol, e.g. {what}('{axis}', sympy.Symbol({value!r})), and give its number in the robot's "
                "params, e.g. params={{{value!r}: 0.5}}.").format(what=what, axis=self.axis, value=self.value))
        name = _("the amount of {what}('{axis}', ...)").format(what=what, axis=self.axis)
        if self.kind == "R":
            value = as_angle(self.value, name + " (radians)", symbolic=True)
        else:
            value = as_length(self.value, name + " (a length)", symbolic=True)
        keep = is_sympy(value) or not isinstance(self.value, Angle)
        object.__setattr__(self, "value", value if keep else self.value)   # deg2rad() values keep their repr

    def matrix(self, q=0):
        """The 4x4 matrix of this motion; sympy (with exact constants) when ``q`` is a symbol."""
        value = self.value
        if self.joint:
            q = joint_value(q, self.kind)
        if is_sympy(q):
            from .symbolic import exact_angle, exact_length  # lazy: sympy, and q is a sympy value here
            value = exact_angle(value) if self.kind == "R" else exact_length(value)
        amount = value + self.sign * q if self.joint else value
        if self.kind == "R":
            return (Rx, Ry, Rz)[AXES[self.axis]](_within_a_turn(amount))
        shift = [0, 0, 0]
        shift[AXES[self.axis]] = amount
        return trans(*shift)

    def __str__(self):
        """``Rz(q)``, ``Rx(-pi/2)`` for a rotation; ``Tr(0, l1, 0)`` for a translation (the course's
        one name for a pure translation: ``Tz``/``Tx`` are seed 000's combined factors)."""
        var = ("-" if self.sign < 0 else "") + "q"
        amount = var if self.joint else str(self.value)
        if self.joint and self.value != 0:
            amount = f"{var} + {self.value}"
        if self.kind == "R":
            return f"R{self.axis}({amount})"
        return "Tr(" + ", ".join(amount if k == AXES[self.axis] else "0" for k in range(3)) + ")"


def _sign(sign, what: str) -> int:
    """+1 or -1 of any numeric type, kept as an int (a sympy or Fraction sign would break fk)."""
    try:
        value = as_number(sign, "sign")
    except DHLabError as error:
        raise DHLabError(_("{what}(sign=...): sign must be +1 or -1, got {got}: {error}").format(
            what=what, got=describe(sign), error=error)) from None
    if value not in (1.0, -1.0):
        raise DHLabError(_("{what}(sign=...): sign must be +1 or -1, got {got}.").format(what=what, got=describe(sign)))
    return int(value)


def joint_value(q, kind: str):
    """One link's joint value: an angle in radians ('R') or a length ('T'); a sympy symbol passes."""
    if kind == "R":
        return as_angle(q, "q (the joint angle, in radians)", symbolic=True)
    return as_length(q, "q (the joint displacement, a length)", symbolic=True)


def _within_a_turn(angle):
    """offset + q may pass a full turn though each is within one: the same rotation, one turn less."""
    if has_symbols(angle) or abs(float(angle)) <= FULL_TURN:
        return angle
    if is_sympy(angle):
        import sympy as sp  # (loaded already: the angle is a sympy value)
        return angle - sp.sign(angle) * 2 * sp.pi
    return angle - math.copysign(FULL_TURN, angle)


def Rot(axis: str, value=0, joint: bool = False, sign: int = 1) -> Factor:
    """A rotation about ``axis`` by ``value`` radians (+ sign·q if ``joint``)."""
    return Factor("R", axis, value, joint, sign)


def Move(axis: str, value=0, joint: bool = False, sign: int = 1) -> Factor:
    """A translation along ``axis`` by ``value`` (+ sign·q if ``joint``)."""
    return Factor("T", axis, value, joint, sign)


@dataclass
class Link:
    """A link (*eslabón*): a product of elementary motions, one of which is its joint (*articulación*).

    ``qlim`` is the joint's range (radians or length units); by default a full
    turn for a revolute joint and ``(0, 1)`` for a prismatic one.
    """
    factors: list
    name: str = ""
    qlim: tuple | None = None
    joint_index: int = field(init=False)

    def __post_init__(self):
        self.factors = as_sequence(self.factors, _("a Link's motions"), _("a list of motions, e.g. "
                                   "Link([Rot('z', joint=True), Move('x', 0.5)])"))
        self.name = as_text(self.name, _("link name"))
        moving = [i for i, f in enumerate(self.factors) if isinstance(f, Factor) and f.joint]
        if len(moving) != 1 or not all(isinstance(f, Factor) for f in self.factors):
            raise DHLabError(_(
                "link {name} must be a list of Factor motions with exactly one joint motion (joint=True), "
                "got {count} joint motions.").format(name=self.name or "", count=len(moving)))
        self.joint_index = moving[0]
        if self.qlim is None:
            self.qlim = (-np.pi, np.pi) if self.is_revolute else DEFAULT_PRISMATIC_RANGE
        label = f"qlim of link {self.name!r}" if self.name else "qlim"
        self.qlim = as_qlim(self.qlim, self.is_revolute, label)

    @property
    def joint(self) -> Factor:
        return self.factors[self.joint_index]

    @property
    def is_revolute(self) -> bool:
        return self.joint.kind == "R"

    @property
    def is_prismatic(self) -> bool:
        return self.joint.kind == "T"

    def A(self, q):
        """The link's transform ^{i-1}H_i for joint value ``q`` (symbolic if q is a symbol)."""
        q = joint_value(q, self.joint.kind)       # checked before any factor uses it
        M = self.factors[0].matrix(q)
        for f in self.factors[1:]:
            M = M * f.matrix(q) if is_matrix(M) else M @ f.matrix(q)
        return M
