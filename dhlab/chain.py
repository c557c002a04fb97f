"""A robot as a chain of links, each link a product of elementary transforms.

Not every robot of the course is written in DH form: seed 004's first robot is
``Rz(θ0)·Tr(0, l1, 0) · Rz(θ1)·Tr(l2, 0, 0)``. So a link here is any product
of elementary motions (rotations about, and translations along, x, y or z),
exactly one of which carries the joint variable (:mod:`dhlab.links`). A DH link is the
special case ``Rz(θ)·Tr(0, 0, d)·Tr(a, 0, 0)·Rx(α)`` (see :mod:`dhlab.dh`). Both kinds go
through the same forward-kinematics code (:mod:`dhlab.kinematics`). What a robot is given
(links, joint names, parameters) is checked by :mod:`dhlab.chain_inputs`.

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
import time

import numpy as np

from . import kinematics
from .chain_inputs import joint_label, joint_names, link_list, numeric_params, one_value
from .errors import DHLabError
from .i18n import _
from .lazy_sympy import has_symbols
from .links import AXES, Factor, Link, Move, Rot
from .validation import (
    Angle,
    as_angle,
    as_flag,
    as_index,
    as_length,
    as_matrix4,
    as_text,
    as_timeout,
    check_joint_values,
    rigid_problem,
)

# Factor, Rot, Move and Link live in dhlab.links, the checks of a robot's arguments in dhlab.chain_inputs;
# named here too, where the notebooks (`from dhlab.chain import Link, Robot, Rot`) have always imported
# them (the package's own modules import each from its home)
__all__ = ["Factor", "Rot", "Move", "Link", "Robot", "link_list", "numeric_params"]

# The symbolic side (fk_sym, A(i), compact) needs sympy, which takes longer to import than the rest
# of dhlab: :mod:`dhlab.symbolic` is imported inside the methods that use it, on their first call.


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
        self.joint_names = joint_names(joint_symbols, self.n)
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

    @property
    def program(self):
        """The chain compiled for :func:`dhlab.kinematics.run` (rebuilt when ``base`` or ``tool``
        changes): what :meth:`fk` and :meth:`frames` run, and what the browser's rig is made from."""
        return self._program

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
        return [joint_label(s) for s in self.joint_names]

    @functools.cached_property
    def q_symbols(self) -> tuple:
        """The joint variables as real sympy symbols (``joint_symbols``, default q1 … qn)."""
        import sympy as sp  # (the symbolic side: imported on first use)
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
            from .symbolic import exact  # lazy: symbolic pulls in sympy
            return exact(link.A(self.q_symbols[i - 1]))
        values = [0.0] * self.n
        values[i - 1] = one_value(q, i)
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
        from .symbolic import exact  # lazy: symbolic pulls in sympy
        return [exact(link.A(s)) for link, s in zip(self.links, self.q_symbols)]

    def fk_sym(self, simplify: bool = False, timeout: float | None = 60.0):
        """Symbolic forward kinematics in the joint symbols (a sympy Matrix).

        ``simplify=True`` returns the compact form of the slides, with sums of
        the angles of parallel joints collapsed (see :mod:`dhlab.symbolic`).
        Simplifying a long chain can take long: after ``timeout`` seconds (None:
        no limit) it stops with a DHLabError; the kernel's stop button
        (KeyboardInterrupt) stops it at any time.
        """
        import sympy as sp  # lazy: sympy on first symbolic use

        from .symbolic import chain_product, exact, simplify_chain  # lazy: symbolic pulls in sympy
        simplify = as_flag(simplify, "simplify")
        timeout = as_timeout(timeout)
        start = time.monotonic()                  # the timeout counts building the blocks too
        base, tool = exact(sp.Matrix(self.base)), exact(sp.Matrix(self.tool))
        if simplify:
            # DH robots merge parallel joints before multiplying; other chains
            # collapse the sums of angles afterwards.
            blocks = self._sym_blocks()
            left = None if timeout is None else timeout - (time.monotonic() - start)
            return simplify_chain(blocks, base, tool,
                                  sum_angles=not self.merges_parallel_joints, timeout=left)
        return chain_product([base] + self.link_matrices_sym() + [tool])

    merges_parallel_joints = False   # DHRobot writes parallel joints' angle sums directly

    def compact(self, M):
        """``M`` in the slides' notation for this robot's joints: C1, S23, … (for reading)."""
        from .symbolic import compact  # lazy: symbolic pulls in sympy
        return compact(M, self.q_symbols)

    def legend(self, M) -> str:
        """What the names in ``compact(M)`` stand for, e.g. 'C1 = cos(q1), S23 = sin(q2 + q3)'."""
        from .symbolic import legend  # lazy: symbolic pulls in sympy
        return legend(M, self.q_symbols)

    def _sym_blocks(self):
        """The matrices to multiply for the compact form: here, one per link."""
        return self.link_matrices_sym()
