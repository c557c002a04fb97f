"""A robot as a chain of links, each link a product of elementary transforms.

Not every robot of the course is written in DH form: seed 004's first robot is
``Rz(θ0)·Tr(0, l1, 0) · Rz(θ1)·Tr(l2, 0, 0)``. So a link here is any product
of elementary motions (rotations about, and translations along, x, y or z),
exactly one of which carries the joint variable. A DH link is the special case
``Rz(θ)·Tr(0, 0, d)·Tr(a, 0, 0)·Rx(α)`` (see :mod:`dhlab.dh`). Both kinds go through the
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
import math
import time
from dataclasses import dataclass, field

import numpy as np

from . import kinematics
from .i18n import _
from .lazy_sympy import has_symbols, is_matrix, is_symbol, is_sympy
from .transforms import Rx, Ry, Rz, trans
from .units import Angle
from .validation import (FULL_TURN, DHLabError, as_angle, as_choice, as_flag, as_index, as_length,
                         as_matrix4, as_number, as_qlim, as_sequence, as_text, as_timeout, check_joint_values,
                         describe, rigid_problem)

__all__ = ["Factor", "Rot", "Move", "Link", "Robot"]

# The symbolic side (fk_sym, A(i), compact) needs sympy, which takes longer to import than the rest
# of dhlab: :mod:`dhlab.symbolic` is imported inside the methods that use it, on their first call.

AXES = {"x": 0, "y": 1, "z": 2}
SYMPY_CONSTANTS = {"pi": "π", "E": "Euler's number e", "I": "the imaginary unit", "oo": "infinity",
                   "zoo": "complex infinity", "nan": "not a number"}
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
            q = _joint_value(q, self.kind)
        if is_sympy(q):
            from .symbolic import exact_angle, exact_length
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


def _joint_value(q, kind: str):
    """One link's joint value: an angle in radians ('R') or a length ('T'); a sympy symbol passes."""
    if kind == "R":
        return as_angle(q, "q (the joint angle, in radians)", symbolic=True)
    return as_length(q, "q (the joint displacement, a length)", symbolic=True)


def _within_a_turn(angle):
    """offset + q may pass a full turn though each is within one: the same rotation, one turn less."""
    if has_symbols(angle) or abs(float(angle)) <= FULL_TURN:
        return angle
    if is_sympy(angle):
        import sympy as sp      # (loaded already: the angle is a sympy value)
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
        q = _joint_value(q, self.joint.kind)       # checked before any factor uses it
        M = self.factors[0].matrix(q)
        for f in self.factors[1:]:
            M = M * f.matrix(q) if is_matrix(M) else M @ f.matrix(q)
        return M


class Robot:
    """A serial robot: ``base · A1(q1) · A2(q2) ··· An(qn) · tool``.

    ``params`` gives numbers to the symbols used in the links (e.g.
    ``{"l1": 0.7}``); ``joint_symbols`` names the joint variables (default
    ``q1 … qn``: ``robot.joint_names``, and as sympy symbols ``robot.q_symbols``, made on
    first use). Joint values are radians for revolute joints and the robot's
    length unit for prismatic ones.
    """

    def __init__(self, links, name: str = "robot", base=None, tool=None,
                 params=None, joint_symbols=None, unit: str = ""):
        self.links = link_list(links)
        self.name = as_text(name, "name")
        self.unit = as_text(unit, "unit")
        self.params = numeric_params(params)
        self.joint_names = _joint_names(joint_symbols, self.n)
        clash = sorted(set(self.params) & set(self.joint_names))
        if clash:
            raise DHLabError(_("{name} is both a joint variable and a parameter with a fixed value "
                               "(params={{{name!r}: ...}}): rename the parameter or the joint.").format(
                                   name=clash[0]))
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
        T = as_matrix4(T, name)
        problem = rigid_problem(T)
        if problem:
            raise DHLabError(_("the robot's {name} transform is not a proper rigid transform: {problem}.").format(
                name=name, problem=problem))
        return T

    def _number(self, factor: Factor, link: int) -> float:
        """A factor's constant as a float, substituting the robot's parameters, checked as what it
        is: an angle for a rotation ('R'), a length for a translation ('T')."""
        value, kind = factor.value, factor.kind
        where = _("link {link} ({factor})").format(link=link, factor=factor)
        if has_symbols(value):
            names = sorted(str(s) for s in value.free_symbols)
            missing = [s for s in names if s not in self.params]
            if missing:
                raise DHLabError(_(
                    "{where} uses {names}, which has no numeric value: give it in params, "
                    "e.g. params={{'{first}': 1.0}}.").format(where=where, names=", ".join(missing), first=missing[0]))
            angles = [s for s in names if isinstance(self.params[s], Angle)]
            if kind == "T" and angles:
                raise DHLabError(_("{where} is a length, but parameter {name} = {value!r} is an angle (made by "
                                   "deg2rad()): give it as a plain number.").format(
                                       where=where, name=angles[0], value=self.params[angles[0]]))
            value = value.subs({s: self.params[str(s)] for s in value.free_symbols})
            where = _("link {link} ({factor}, {names} from params)").format(
                link=link, factor=factor, names=", ".join(names))
        return as_angle(value, where) if kind == "R" else as_length(value, where)

    def _numeric_factors(self):
        """Per link, its factors with numeric values (what the fast kinematics runs on)."""
        out = []
        for i, link in enumerate(self.links):
            out.append([(f.kind, AXES[f.axis], self._number(f, i + 1),
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
        return [_label(s) for s in self.joint_names]

    @functools.cached_property
    def q_symbols(self) -> tuple:
        """The joint variables as real sympy symbols (``joint_symbols``, default q1 … qn)."""
        import sympy as sp      # (the symbolic side: imported on first use)
        return tuple(sp.Symbol(s, real=True) for s in self.joint_names)

    @property
    def numeric_links(self) -> list:
        """Per link, its motions with numbers for their constants: ``(kind, axis, value, is_joint,
        sign)``, kind 'R'/'T', axis 0/1/2 (what the fast kinematics and the views' mechanism use)."""
        return [list(factors) for factors in self._numeric]

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
        return _("<{type} {name!r}: {n} joints ({kinds})>").format(
            type=type(self).__name__, name=self.name, n=self.n, kinds=kinds)

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
        i = as_index(i, "link index i", 1, self.n)
        link = self.links[i - 1]
        if q is None:
            from .symbolic import exact
            return exact(link.A(self.q_symbols[i - 1]))
        values = [0.0] * self.n
        values[i - 1] = _one_value(q, i)
        value = check_joint_values(values, self.links, name=f"q (joint {i})")[i - 1]
        M = np.eye(4)
        for kind, axis, const, joint, sign in self._numeric[i - 1]:
            M = M @ kinematics.elementary(kind, axis, const + sign * value if joint else const)
        return M

    def reach(self) -> float:
        """An upper bound on how far any frame origin gets from frame 0's origin."""
        total = np.linalg.norm(self.tool[:3, 3])
        for link, factors in zip(self.links, self._numeric):
            for kind, _axis, const, joint, _sign in factors:
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
        from .symbolic import exact
        return [exact(link.A(s)) for link, s in zip(self.links, self.q_symbols)]

    def fk_sym(self, simplify: bool = False, timeout: float | None = 60.0):
        """Symbolic forward kinematics in the joint symbols (a sympy Matrix).

        ``simplify=True`` returns the compact form of the slides, with sums of
        the angles of parallel joints collapsed (see :mod:`dhlab.symbolic`).
        Simplifying a long chain can take long: after ``timeout`` seconds (None:
        no limit) it stops with a DHLabError; the kernel's stop button
        (KeyboardInterrupt) stops it at any time.
        """
        import sympy as sp

        from .symbolic import chain_product, exact, simplify_chain
        simplify = as_flag(simplify, "simplify")
        timeout = as_timeout(timeout)
        start = time.monotonic()                  # the timeout counts building the blocks too
        base, tool = exact(sp.Matrix(self.base)), exact(sp.Matrix(self.tool))
        if simplify:
            # DH robots merge parallel joints before multiplying; other chains
            # collapse the sums of angles afterwards.
            blocks = self._sym_blocks()
            left = None if timeout is None else timeout - (time.monotonic() - start)
            return simplify_chain(blocks, base, tool, self.q_symbols,
                                  sum_angles=not self.merges_parallel_joints, timeout=left)
        return chain_product([base] + self.link_matrices_sym() + [tool])

    merges_parallel_joints = False   # DHRobot writes parallel joints' angle sums directly

    def compact(self, M):
        """``M`` in the slides' notation for this robot's joints: C1, S23, … (for reading)."""
        from .symbolic import compact
        return compact(M, self.q_symbols)

    def legend(self, M) -> str:
        """What the names in ``compact(M)`` stand for, e.g. 'C1 = cos(q1), S23 = sin(q2 + q3)'."""
        from .symbolic import legend
        return legend(M, self.q_symbols)

    def _sym_blocks(self):
        """The matrices to multiply for the compact form: here, one per link."""
        return self.link_matrices_sym()


def link_list(links, expected=None, what: str = "a Link (or RevoluteDH / PrismaticDH)") -> list:
    """The robot's links as a list of ``expected`` (default :class:`Link`), or a clear error."""
    if isinstance(links, (str, bytes, dict, Link)) or not hasattr(links, "__iter__"):
        raise DHLabError(_("a robot takes a list of links, e.g. [RevoluteDH(a=1), RevoluteDH(a=0.5)]; "
                           "got {got}.").format(got=describe(links)))
    try:
        links = list(links)
    except TypeError:            # iterable in name only, e.g. a 0-d numpy array
        raise DHLabError(_("a robot takes a list of links, e.g. [RevoluteDH(a=1), RevoluteDH(a=0.5)]; "
                           "got {got}.").format(got=describe(links))) from None
    if not links:
        raise DHLabError(_("a robot needs at least one link."))
    for i, link in enumerate(links, start=1):
        if not isinstance(link, expected or Link):
            raise DHLabError(_("link {i} must be {what}, got {got}.").format(i=i, what=what, got=describe(link)))
    return links


def _joint_names(names, n: int) -> tuple:
    """The names of the joint variables (text or sympy symbols): default q1 … qn; names must be distinct."""
    if names is None:
        names = [f"q{i + 1}" for i in range(n)]
    if isinstance(names, (str, bytes, dict)) or not hasattr(names, "__iter__"):
        raise DHLabError(_("joint_symbols must be a list of {n} names, e.g. {example}; got {got}.").format(
            n=n, example=[f"q{i + 1}" for i in range(n)], got=describe(names)))
    try:
        names = list(names)
    except TypeError:            # iterable in name only, e.g. a 0-d numpy array
        raise DHLabError(_("joint_symbols must be a list of {n} names; got {got}.").format(
            n=n, got=describe(names))) from None
    if len(names) != n:
        raise DHLabError(_("joint_symbols must name {n} joints, got {count}: {got}.").format(
            n=n, count=len(names), got=describe(names)))
    text = []
    for k, s in enumerate(names):
        if is_symbol(s):
            s = s.name
        if not isinstance(s, str) or not s.isidentifier():
            raise DHLabError(_("joint_symbols[{k}] must be a name such as 'q{k1}' or 'theta{k1}', got {got}.").format(
                k=k, k1=k + 1, got=describe(s)))
        if s in SYMPY_CONSTANTS:        # it would print, and be read back, as the constant
            raise DHLabError(_("joint_symbols[{k}] = {name!r} is the name of a constant in the printed maths "
                               "({constant}); name the joint e.g. 'q{k1}' or 'theta{k1}'.").format(
                                   k=k, name=s, constant=SYMPY_CONSTANTS[s], k1=k + 1))
        text.append(s)
    repeated = sorted({s for s in text if text.count(s) > 1})
    if repeated:
        raise DHLabError(_("joint_symbols name {name!r} twice: every joint needs its own variable, "
                           "or two joints would merge into one in fk_sym().").format(name=repeated[0]))
    return tuple(text)


def _one_value(q, i: int):
    """The value of joint i: as given, or the element of a one-element list or array (checked later)."""
    if isinstance(q, np.ma.MaskedArray) and q.size == 1:          # keep a missing value missing
        return np.ma.masked if np.ma.is_masked(q) else q.data.ravel()[0]
    if isinstance(q, np.ndarray) and q.ndim == 0 or not (isinstance(q, (list, tuple, np.ndarray)) or is_matrix(q)):
        return q
    try:
        arr = None if is_matrix(q) else np.asarray(q, dtype=object).ravel()
    except (ValueError, TypeError):          # ragged beyond what an object array holds
        arr = None
    if arr is None or arr.size != 1:
        raise DHLabError(_("q must be one number, the value of joint {i}, got {got}.").format(i=i, got=describe(q)))
    return arr[0]


def numeric_params(params) -> dict:
    """Robot parameters as {name: float}, refusing anything that is not a finite number."""
    if params is None:
        return {}
    if not isinstance(params, dict):
        raise DHLabError(_("params must be a dict of numbers, e.g. {{'l1': 0.7}}; got {got}.").format(
            got=describe(params)))
    out = {}
    for key, value in params.items():
        name = key.name if is_symbol(key) else key
        if not isinstance(name, str) or not name.isidentifier():
            raise DHLabError(_("params keys must be names such as 'l1', got {got}.").format(got=describe(key)))
        if has_symbols(value) or isinstance(value, str):
            raise DHLabError(_("parameter {name} = {value!r} must be a finite number (a length or an angle in "
                               "radians).").format(name=name, value=value))
        number = as_number(value, _("parameter {name}").format(name=name))
        out[name] = value if isinstance(value, Angle) else number   # deg2rad() values stay marked as angles
    return out


def _label(symbol) -> str:
    """'theta1' -> 'θ1', 'q2' -> 'q2'."""
    name = str(symbol)
    for greek, char in (("theta", "θ"), ("alpha", "α"), ("phi", "φ")):
        if name.startswith(greek):
            return char + name[len(greek):].lstrip("_")
    return name
