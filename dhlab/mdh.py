"""Modified Denavit-Hartenberg robots (Craig's convention), and converting tables both ways.

The course uses **standard** DH (Spong, Corke, the seeds): frame i sits on the axis of
joint i+1 and

    A_i = Rz(θ_i)·Tr(0, 0, d_i)·Tr(a_i, 0, 0)·Rx(α_i).

Craig's *Introduction to Robotics* (and many datasheets) use **modified** DH: frame i
sits on the axis of joint i itself, and the link matrix takes the same four motions in
the other order, with the x motions of the link before:

    A_i = Rx(α_(i−1))·Tr(a_(i−1), 0, 0)·Rz(θ_i)·Tr(0, 0, d_i).

In both, x_i runs along the common normal of the axes of joints i and i+1, so θ_i and
d_i are the same numbers; only a and α move by one row. Tables here keep the course's
column order (θ, d, a, α): in a modified table, row i holds θ_i, d_i, a_(i−1), α_(i−1)
(Craig prints the columns as α_(i−1), a_(i−1), d_i, θ_i).

>>> import numpy as np
>>> from dhlab import DHRobot, MDHRobot, to_modified
>>> planar = MDHRobot.from_table([("q1", 0, 0, 0), ("q2", 0, 1.0, 0)])   # a1 = 1 sits in row 2
>>> planar.fk([0, 0]).round(6)[:3, 3].tolist()
[1.0, 0.0, 0.0]
>>> arm = DHRobot.from_table([("q1", 0, 1.0, 0), ("q2", 0, 0.5, 90)])
>>> print(to_modified(arm).table())
 i | θ_i | d_i | a_(i−1) | α_(i−1) | joint
 1 | q1  | 0   | 0       | 0°      | R
 2 | q2  | 0   | 1       | 0°      | R
>>> bool(np.allclose(to_modified(arm).fk([0.3, -0.7]), arm.fk([0.3, -0.7])))
True

Converting shifts a and α by one row. What falls off an end goes into a fixed transform,
so that the end effector's pose is the same at every configuration:

* standard → modified (:func:`to_modified`): the last row's a_n, α_n have no row; the
  tool takes them, ``tool' = Tr(a_n, 0, 0)·Rx(α_n)·tool`` (the first row's a_0 = α_0 = 0);
* modified → standard (:func:`to_standard`): the first row's a_0, α_0 have no row; the
  base takes them, ``base' = base·Rx(α_0)·Tr(a_0, 0, 0)`` (the last row's a_n = α_n = 0).

The intermediate frames differ (frame i moves from joint i+1's axis to joint i's):
only the base, the joint axes and the end effector are the same.
"""
from __future__ import annotations

from .chain import Robot
from .chain_inputs import link_list
from .dh import (
    DHParameters,
    DHRobot,
    PrismaticDH,
    RevoluteDH,
    links_from_table,
    parse_entry,
    refuse_convention,
    table_rows,
)
from .errors import DHLabError
from .i18n import N_, _
from .lazy_sympy import has_symbols, is_matrix
from .table import DHTable
from .transforms import Rx, Rz, trans
from .validation import describe

__all__ = ["RevoluteMDH", "PrismaticMDH", "MDHRobot", "mdh_matrix", "to_modified", "to_standard",
           "to_modified_rows", "to_standard_rows"]


def mdh_matrix(theta, d, a, alpha):
    """The modified DH (Craig) matrix ``Rx(α)·Tr(a, 0, 0)·Rz(θ)·Tr(0, 0, d)`` of row
    (θ_i, d_i, a_(i−1), α_(i−1)).

    >>> import sympy as sp
    >>> th, d, a, al = sp.symbols("theta d a alpha")
    >>> mdh_matrix(th, d, a, al)[:, 3].T
    Matrix([[a, -d*sin(alpha), d*cos(alpha), 1]])
    """
    factors = [Rx(alpha), trans(a, 0, 0), Rz(theta), trans(0, 0, d)]   # each checks its value
    if any(is_matrix(M) for M in factors):
        import sympy as sp  # (loaded already: a factor is a sympy Matrix)
        return sp.Matrix(factors[0]) * sp.Matrix(factors[1]) * sp.Matrix(factors[2]) * sp.Matrix(factors[3])
    return factors[0] @ factors[1] @ factors[2] @ factors[3]


class MDHLink(DHParameters):
    """Common part of RevoluteMDH and PrismaticMDH:
    ``A_i = Rx(α_(i−1))·Tr(a_(i−1), 0, 0)·Rz(θ_i)·Tr(0, 0, d_i)``.
    Its ``a`` and ``alpha`` are a_(i−1), α_(i−1): the common normal from the previous joint's axis."""

    convention = "modified"

    @staticmethod
    def motions(along_z: list, along_x: list) -> list:
        """Modified DH: first along x_(i−1) (α_(i−1), a_(i−1)), then along z_i (θ_i, d_i)."""
        move_x, turn_x = along_x
        return [turn_x, move_x] + along_z


class RevoluteMDH(MDHLink):
    """A revolute modified-DH link: θ_i = q + offset; d_i, a_(i−1), α_(i−1) constant (radians)."""

    def __init__(self, d=0, a=0, alpha=0, offset=0, qlim=None, name: str = ""):
        super().__init__(0, d, a, alpha, offset, True, qlim, name)


class PrismaticMDH(MDHLink):
    """A prismatic modified-DH link: d_i = q + offset; θ_i, a_(i−1), α_(i−1) constant (radians)."""

    def __init__(self, theta=0, a=0, alpha=0, offset=0, qlim=None, name: str = ""):
        super().__init__(theta, 0, a, alpha, offset, False, qlim, name)


class MDHRobot(Robot):
    """A serial robot described by a modified-DH (Craig) table: one :class:`RevoluteMDH` or
    :class:`PrismaticMDH` per joint, with optional base and tool transforms.
    Its symbolic matrices (``A(i)``, ``fk_sym()``) are the modified ones."""

    def __init__(self, links, name: str = "robot", base=None, tool=None,
                 params=None, joint_symbols=None, unit: str = ""):
        refuse_convention(links, "standard", N_("standard DH"),
                          N_("an MDHRobot is modified DH (Craig). Use RevoluteMDH / PrismaticMDH, or build a "
                             "dhlab.DHRobot and convert it with dhlab.to_modified(robot)."))
        links = link_list(links, MDHLink, "RevoluteMDH(...) or PrismaticMDH(...)")
        super().__init__(links, name=name, base=base, tool=tool, params=params,
                         joint_symbols=joint_symbols, unit=unit)

    def table(self) -> DHTable:
        """The table in the course's column order: θ_i, d_i, a_(i−1), α_(i−1) (angles in degrees)."""
        return DHTable(self)

    @classmethod
    def from_table(cls, rows, name: str = "robot", params=None, angles: str = "deg",
                   qlim=None, **kwargs) -> MDHRobot:
        """A robot from modified-DH rows ``(θ_i, d_i, a_(i−1), α_(i−1))``, typed as for
        :meth:`dhlab.DHRobot.from_table` (same columns, text such as ``"q2 - 90"``, degrees
        by default). Craig prints the columns as α_(i−1), a_(i−1), d_i, θ_i: reorder them."""
        links, symbols, params = links_from_table(rows, params, angles, qlim, RevoluteMDH, PrismaticMDH)
        return cls(links, name=name, params=params, joint_symbols=symbols, **kwargs)


# --- converting: the same robot in the other convention ------------------------------------------
def _number(value, robot) -> float:
    """A link parameter (a number or an expression in the robot's params) as a float."""
    if has_symbols(value):
        value = value.subs({s: robot.params[str(s)] for s in value.free_symbols})
    return float(value)


def _same_joint(link, kind, a, alpha):
    """``link``'s joint and θ, d, offset, limits, name, as a link of class ``kind`` with a, α given."""
    if link.is_revolute:
        return kind[0](d=link.d, a=a, alpha=alpha, offset=link.offset, qlim=link.qlim, name=link.name)
    return kind[1](theta=link.theta, a=a, alpha=alpha, offset=link.offset, qlim=link.qlim, name=link.name)


def _robot(robot, cls, what: str):
    if not isinstance(robot, cls):
        message = (_("{what} takes a dhlab.{cls}, got {got} (it is already in the other convention).")
                   if isinstance(robot, Robot) else _("{what} takes a dhlab.{cls}, got {got}."))
        raise DHLabError(message.format(what=what, cls=cls.__name__, got=describe(robot)))
    return robot


def to_modified(robot) -> MDHRobot:
    """The same robot as a modified-DH (Craig) table: row i takes a_(i−1), α_(i−1) of the standard
    row above it (a_0 = α_0 = 0), and the tool takes the last row's a_n, α_n:
    ``tool' = Tr(a_n, 0, 0)·Rx(α_n)·tool``. Same base, joints, limits and end-effector pose."""
    robot = _robot(robot, DHRobot, "to_modified")
    links, above = [], (0, 0)
    for link in robot.links:
        links.append(_same_joint(link, (RevoluteMDH, PrismaticMDH), *above))
        above = (link.a, link.alpha)
    last = robot.links[-1]
    tool = trans(_number(last.a, robot), 0, 0) @ Rx(_number(last.alpha, robot)) @ robot.tool
    return MDHRobot(links, name=f"{robot.name} (modified DH)", base=robot.base, tool=tool, params=robot.params,
                    joint_symbols=robot.joint_names, unit=robot.unit)


def to_standard(robot) -> DHRobot:
    """The same robot as a standard DH table: row i takes a_i, α_i from the modified row below it
    (a_n = α_n = 0), and the base takes the first row's a_0, α_0: ``base' = base·Rx(α_0)·Tr(a_0, 0, 0)``.
    Same tool, joints, limits and end-effector pose."""
    robot = _robot(robot, MDHRobot, "to_standard")
    links = [_same_joint(link, (RevoluteDH, PrismaticDH), below.a, below.alpha)
             for link, below in zip(robot.links, robot.links[1:])]
    links.append(_same_joint(robot.links[-1], (RevoluteDH, PrismaticDH), 0, 0))
    first = robot.links[0]
    base = robot.base @ Rx(_number(first.alpha, robot)) @ trans(_number(first.a, robot), 0, 0)
    return DHRobot(links, name=f"{robot.name} (standard DH)", base=base, tool=robot.tool, params=robot.params,
                   joint_symbols=robot.joint_names, unit=robot.unit)


def _typed_rows(rows) -> list:
    """The rows as tuples, each entry checked as :meth:`~dhlab.DHRobot.from_table` reads it
    (the entries are returned as typed: ``"q2 - 90"`` stays text)."""
    rows = [tuple(row) for row in table_rows(rows)]
    for i, row in enumerate(rows, start=1):
        theta, d, _a, _alpha = (parse_entry(value, _("row {i}, {column}").format(i=i, column=column),
                                       length=column in "da") for value, column in zip(row, "θdaα"))
        if not (theta.free_symbols or d.free_symbols):
            raise DHLabError(_("row {i} {row!r} has no joint variable: θ (revolute) or d (prismatic) must "
                               "contain a symbol such as q{i}.").format(i=i, row=row))
    return rows


def to_modified_rows(rows) -> tuple:
    """Standard rows ``(θ_i, d_i, a_i, α_i)``, typed as for ``from_table``, as modified rows
    ``(θ_i, d_i, a_(i−1), α_(i−1))``, and the pair ``(a_n, α_n)`` left over, which the tool
    must take: ``tool' = Tr(a_n, 0, 0)·Rx(α_n)·tool`` (nothing to do when both are 0).

    >>> to_modified_rows([("q1", 0.5, 0.2, -90), ("q2 - 90", 0, 0.5, 0)])
    ([('q1', 0.5, 0, 0), ('q2 - 90', 0, 0.2, -90)], (0.5, 0))
    """
    rows = _typed_rows(rows)
    above = [(0, 0)] + [(a, alpha) for _theta, _d, a, alpha in rows]
    return [(theta, d, a, alpha) for (theta, d, _a, _alpha), (a, alpha) in zip(rows, above)], above[-1]


def to_standard_rows(rows) -> tuple:
    """Modified rows ``(θ_i, d_i, a_(i−1), α_(i−1))`` as standard rows ``(θ_i, d_i, a_i, α_i)``,
    and the pair ``(a_0, α_0)`` left over, which the base must take:
    ``base' = base·Rx(α_0)·Tr(a_0, 0, 0)`` (nothing to do when both are 0).

    >>> to_standard_rows([('q1', 0.5, 0, 0), ('q2 - 90', 0, 0.2, -90)])
    ([('q1', 0.5, 0.2, -90), ('q2 - 90', 0, 0, 0)], (0, 0))
    """
    rows = _typed_rows(rows)
    below = [(a, alpha) for _theta, _d, a, alpha in rows[1:]] + [(0, 0)]
    return [(theta, d, a, alpha) for (theta, d, _a, _alpha), (a, alpha) in zip(rows, below)], rows[0][2:]
