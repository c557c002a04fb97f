"""A robot as a chain of links, each link a product of elementary transforms.

Not every robot of the course is written in DH form: seed 004's first robot is
``Rz(θ0)·Tr(0, l1, 0) · Rz(θ1)·Tr(l2, 0, 0)``. So a link here is any product
of elementary motions (rotations about, and translations along, x, y or z),
exactly one of which carries the joint variable. A DH link is the special case
``Rz(θ)·Tz(d)·Tx(a)·Rx(α)`` (see :mod:`dhlab.dh`). Both kinds go through the
same forward-kinematics code (:mod:`dhlab.kinematics`).

>>> import sympy as sp
>>> from dhlab.chain import Link, Robot, Rot, Move
>>> l1, l2 = sp.symbols("l1 l2")
>>> robot = Robot([Link([Rot("z", joint=True), Move("y", l1)]),
...                Link([Rot("z", joint=True), Move("x", l2)])],
...               params={"l1": 0.7, "l2": 0.3}, joint_symbols=("theta0", "theta1"))
>>> robot.fk([0, 0]).round(6)[:3, 3].tolist()
[0.3, 0.7, 0.0]
"""
from __future__ import annotations

import functools
from dataclasses import dataclass, field

import numpy as np
import sympy as sp

from . import kinematics
from .symbolic import compact, exact, exact_angle, exact_length, legend, simplify_chain
from .transforms import Rx, Ry, Rz, trans
from .validation import DHLabError, as_matrix4, check_joint_values, rigid_problem

__all__ = ["Factor", "Rot", "Move", "Link", "Robot"]

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
        if self.kind not in ("R", "T"):
            raise DHLabError(f"Factor kind must be 'R' (rotation) or 'T' (translation), got {self.kind!r}.")
        if self.axis not in AXES:
            raise DHLabError(f"Factor axis must be 'x', 'y' or 'z', got {self.axis!r}.")
        if self.sign not in (1, -1):
            raise DHLabError(f"Factor sign must be +1 or -1, got {self.sign!r}.")

    def matrix(self, q=0):
        """The 4x4 matrix of this motion; sympy (with exact constants) when ``q`` is a symbol."""
        value = self.value
        if isinstance(q, sp.Basic):
            value = exact_angle(value) if self.kind == "R" else exact_length(value)
        amount = value + self.sign * q if self.joint else value
        if self.kind == "R":
            return (Rx, Ry, Rz)[AXES[self.axis]](amount)
        shift = [0, 0, 0]
        shift[AXES[self.axis]] = amount
        return trans(*shift)

    def __str__(self):
        name = ("R" if self.kind == "R" else "T") + self.axis
        var = ("-" if self.sign < 0 else "") + "q"
        amount = var if self.joint else str(self.value)
        if self.joint and self.value != 0:
            amount = f"{var} + {self.value}"
        return f"{name}({amount})"


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
        self.factors = list(self.factors)
        moving = [i for i, f in enumerate(self.factors) if isinstance(f, Factor) and f.joint]
        if len(moving) != 1 or not all(isinstance(f, Factor) for f in self.factors):
            raise DHLabError(
                f"link {self.name or ''} must be a list of Factor motions with exactly one joint "
                f"motion (joint=True), got {len(moving)} joint motions."
            )
        self.joint_index = moving[0]
        if self.qlim is None:
            self.qlim = (-np.pi, np.pi) if self.is_revolute else DEFAULT_PRISMATIC_RANGE
        lo, hi = (float(v) for v in self.qlim)
        if not lo < hi:
            raise DHLabError(f"qlim of link {self.name or ''} must be (low, high) with low < high, got {self.qlim}.")
        self.qlim = (lo, hi)

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
        M = self.factors[0].matrix(q)
        for f in self.factors[1:]:
            M = M * f.matrix(q) if isinstance(M, sp.MatrixBase) else M @ f.matrix(q)
        return M


class Robot:
    """A serial robot: ``base · A1(q1) · A2(q2) ··· An(qn) · tool``.

    ``params`` gives numbers to the symbols used in the links (e.g.
    ``{"l1": 0.7}``); ``joint_symbols`` names the joint variables (default
    ``q1 … qn``). Joint values are radians for revolute joints and the robot's
    length unit for prismatic ones.
    """

    def __init__(self, links, name: str = "robot", base=None, tool=None,
                 params=None, joint_symbols=None, unit: str = ""):
        self.links = list(links)
        if not self.links:
            raise DHLabError("a robot needs at least one link.")
        self.name = name
        self.unit = unit
        self.params = _numeric_params(params)
        names = joint_symbols or [f"q{i + 1}" for i in range(self.n)]
        if len(names) != self.n:
            raise DHLabError(f"joint_symbols must name {self.n} joints, got {len(names)}: {list(names)}.")
        self.q_symbols = tuple(sp.Symbol(str(s), real=True) for s in names)
        self._numeric = self._numeric_factors()
        self._base = self._fixed_transform(base, "base")
        self._tool = self._fixed_transform(tool, "tool")
        self._compile()

    # --- base and tool: checked, and the kinematics recompiled when they change ---
    @property
    def base(self) -> np.ndarray:
        """Pose of frame 0 in the world (4x4)."""
        return self._base

    @base.setter
    def base(self, T):
        self._base = self._fixed_transform(T, "base")
        self._compile()

    @property
    def tool(self) -> np.ndarray:
        """Pose of the end effector in frame n (4x4)."""
        return self._tool

    @tool.setter
    def tool(self, T):
        self._tool = self._fixed_transform(T, "tool")
        self._compile()

    def _compile(self):
        self._program = kinematics.compile_chain(self._numeric, self._base, self._tool)

    # --- construction helpers ------------------------------------------------
    @staticmethod
    def _fixed_transform(T, name):
        if T is None:
            return np.eye(4)
        T = as_matrix4(np.array(T, dtype=float) if isinstance(T, sp.MatrixBase) else T, name)
        problem = rigid_problem(T)
        if problem:
            raise DHLabError(f"the robot's {name} transform is not a proper rigid transform: {problem}.")
        return T

    def _number(self, value, where: str) -> float:
        """A link constant as a float, substituting the robot's parameters."""
        if isinstance(value, sp.Basic):
            missing = sorted(str(s) for s in value.free_symbols if str(s) not in self.params)
            if missing:
                raise DHLabError(
                    f"{where} uses {', '.join(missing)}, which has no numeric value: "
                    f"give it in params, e.g. params={{'{missing[0]}': 1.0}}."
                )
            value = value.subs({s: self.params[str(s)] for s in value.free_symbols})
        return float(value)

    def _numeric_factors(self):
        """Per link, its factors with numeric values (what the fast kinematics runs on)."""
        out = []
        for i, link in enumerate(self.links):
            out.append([(f.kind, AXES[f.axis], self._number(f.value, f"link {i + 1} ({f})"),
                         f.joint, f.sign) for f in link.factors])
        return out

    # --- basic facts -----------------------------------------------------------
    @property
    def n(self) -> int:
        """Number of joints (degrees of freedom)."""
        return len(self.links)

    @property
    def joint_labels(self) -> list:
        """Display names of the joint variables, e.g. ['q1', 'q2'] or ['θ0', 'θ1']."""
        return [_label(s) for s in self.q_symbols]

    @property
    def qz(self) -> np.ndarray:
        """The zero configuration."""
        return np.zeros(self.n)

    @property
    def qlim(self) -> np.ndarray:
        """Joint limits, shape (n, 2): radians or length units."""
        return np.array([link.qlim for link in self.links])

    def __repr__(self):
        kinds = "".join("R" if l.is_revolute else "P" for l in self.links)
        return f"<{type(self).__name__} {self.name!r}: {self.n} joints ({kinds})>"

    # --- numeric kinematics ------------------------------------------------------
    def _q(self, q):
        return check_joint_values(q, self.links)

    def fk(self, q) -> np.ndarray:
        """Pose of the end effector: (4,4) for ``q`` of shape (n,), (N,4,4) for (N,n)."""
        return kinematics.run(self._program, self._q(q), frames=False)

    def frames(self, q) -> np.ndarray:
        """Every frame 0…n in the base frame: (n+1,4,4), or (N,n+1,4,4) for a batch.

        Frame 0 is the base; ``fk(q) == frames(q)[-1] @ tool``.
        """
        return kinematics.run(self._program, self._q(q), frames=True)

    def A(self, i: int, q=None):
        """Link ``i``'s transform ^{i-1}A_i (1-based ``i``): numeric for a number,
        symbolic in the joint symbol when ``q`` is omitted."""
        if not 1 <= i <= self.n:
            raise DHLabError(f"link index must be 1…{self.n}, got {i}.")
        link = self.links[i - 1]
        if q is None:
            return exact(link.A(self.q_symbols[i - 1]))
        values = [0.0] * self.n
        values[i - 1] = q
        value = check_joint_values(values, self.links)[i - 1]
        M = np.eye(4)
        for kind, axis, const, joint, sign in self._numeric[i - 1]:
            M = M @ kinematics.elementary(kind, axis, const + sign * value if joint else const)
        return M

    def reach(self) -> float:
        """An upper bound on how far any frame origin gets from frame 0's origin."""
        total = np.linalg.norm(self.tool[:3, 3])
        for link, factors in zip(self.links, self._numeric):
            for kind, _, const, joint, _ in factors:
                if kind == "T":
                    total += abs(const) + (max(abs(v) for v in link.qlim) if joint else 0.0)
        return float(total)

    @functools.cached_property
    def is_planar(self) -> bool:
        """True when every frame origin stays in the base xy plane (checked at random poses)."""
        rng = np.random.default_rng(0)
        lo, hi = self.qlim.T
        Q = lo + (hi - lo) * rng.random((8, self.n))
        origins = self.frames(Q)[..., :3, 3] - self.base[:3, 3]
        return bool(np.abs(origins @ self.base[:3, 2]).max() < 1e-9)

    # --- symbolic kinematics -------------------------------------------------------
    def link_matrices_sym(self):
        """The symbolic ^{i-1}A_i of every link, exact (degrees like 90° become π/2)."""
        return [exact(link.A(s)) for link, s in zip(self.links, self.q_symbols)]

    def fk_sym(self, simplify: bool = False):
        """Symbolic forward kinematics in the joint symbols (a sympy Matrix).

        ``simplify=True`` returns the compact form of the slides, with sums of
        the angles of parallel joints collapsed (see :mod:`dhlab.symbolic`).
        """
        base, tool = exact(sp.Matrix(self.base)), exact(sp.Matrix(self.tool))
        if simplify:
            # DH robots merge parallel joints before multiplying; other chains are
            # small, and collapse the sums of angles afterwards.
            return simplify_chain(self._sym_blocks(), base, tool, self.q_symbols,
                                  sum_angles=not self.merges_parallel_joints)
        T = base
        for A in self.link_matrices_sym():
            T = T * A
        return T * tool

    merges_parallel_joints = False   # DHRobot writes parallel joints' angle sums directly

    def compact(self, M):
        """``M`` in the slides' notation for this robot's joints: C1, S23, … (for reading)."""
        return compact(M, self.q_symbols)

    def legend(self, M) -> str:
        """What the names in ``compact(M)`` stand for, e.g. 'C1 = cos(q1), S23 = sin(q2 + q3)'."""
        return legend(M, self.q_symbols)

    def _sym_blocks(self):
        """The matrices to multiply for the compact form: here, one per link."""
        return self.link_matrices_sym()


def _numeric_params(params) -> dict:
    """Robot parameters as {name: float}, refusing anything that is not a finite number."""
    out = {}
    for key, value in dict(params or {}).items():
        try:
            number = float(value)
        except (TypeError, ValueError):
            number = float("nan")
        if not np.isfinite(number):
            raise DHLabError(f"parameter {key} = {value!r} must be a finite number (a length or an angle in radians).")
        out[str(key)] = number
    return out


def _label(symbol) -> str:
    """'theta1' -> 'θ1', 'q2' -> 'q2'."""
    name = str(symbol)
    for greek, char in (("theta", "θ"), ("alpha", "α"), ("phi", "φ")):
        if name.startswith(greek):
            return char + name[len(greek):].lstrip("_")
    return name
