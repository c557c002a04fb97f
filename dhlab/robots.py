"""The robot catalogue: every robot of the course, with the seeds' numbers.

Where a seed gives no numbers, the defaults are those of
``shared/reference/VERIFIED_MATH.md`` (marked "verifier's choice"); every length
can be changed by keyword. Lengths keep their symbols (``l1`` …) so that
``robot.fk_sym()`` prints like the slides, and their numbers for ``robot.fk``.

>>> from dhlab import robots
>>> arm = robots.ssrms()
>>> arm.fk(arm.qz).round(6)[:3, 3].tolist()
[24.0, 0.0, -10.5]
"""
from __future__ import annotations

import math

from .chain import Robot
from .dh import DHRobot, RevoluteDH
from .errors import DHLabError
from .i18n import _
from .links import Link, Move, Rot
from .validation import as_flag, as_length

__all__ = [
    "robot_no_tan_elemental_1", "robot_no_tan_elemental_2", "pr_mechanism",
    "prr_example", "prr_example_matrices", "rrr_example", "rrr_example_matrices",
    "seed002_4dof", "seed002_6dof", "seed003_6dof", "ssrms", "puma560", "catalogue",
]



def _symbol(name: str):
    """The sympy symbol of a length of a drawing (``l1`` …), so that ``fk_sym()`` prints like the slides.
    (sympy is imported here, when a robot is built, not when dhlab is imported.)"""
    import sympy as sp  # lazy: sympy on first symbolic use
    return sp.Symbol(name)


def _lengths(**lengths) -> dict:
    """The factory's length arguments as params, each read by :func:`_link_length`; text is left to
    the robot's params check ("parameter l1 = 'long' must be a finite number")."""
    return {name: value if isinstance(value, str) else _link_length(value, name) for name, value in lengths.items()}


def _link_length(value, name: str) -> float:
    """A length of the robot's drawing (l1, d_max …): a number ≥ 0, read by as_length (a deg2rad() angle is
    refused). A negative one is a mistake: where a seed's table needs −l2, the table writes the sign."""
    value = as_length(value, name)
    if value < 0:
        raise DHLabError(_("{name} = {value:g} is a length of the robot's links: it must be 0 or more. Where a "
                           "table needs a negative a or d, the table itself writes the sign (e.g. '-l2').").format(
                               name=name, value=value))
    return value + 0.0                 # -0.0 -> 0.0


def robot_no_tan_elemental_1(l1: float = 0.70, l2: float = 0.30) -> Robot:
    """Seed 004's first "robot no tan elemental": planar R-R, joint variables θ0, θ1.

    ⁰H₁ = Rz(θ0)·Tr(0, l1, 0) (link 1 lies along y0 at rest), ¹H₂ = Rz(θ1)·Tr(l2, 0, 0).
    """
    return Robot([Link([Rot("z", joint=True), Move("y", _symbol("l1"))], name="link 1"),
                  Link([Rot("z", joint=True), Move("x", _symbol("l2"))], name="link 2")],
                 name=_("robot no tan elemental 1 (seed 004)"), params=_lengths(l1=l1, l2=l2),
                 joint_symbols=("theta0", "theta1"), unit="m")


def robot_no_tan_elemental_2(l: float = 0.70, d_max: float = 0.30) -> Robot:
    """Seed 004's "otro robot no tan elemental": a rotation θ about z0, then a
    prismatic joint d along y1, 0 ≤ d ≤ d_max (d_max = 0.30: verifier's choice).

    ⁰H₁ = Rz(θ)·Tr(0, l, 0), ¹H₂ = Tr(0, d, 0).
    """
    return Robot([Link([Rot("z", joint=True), Move("y", _symbol("l"))], name="link 1"),
                  Link([Move("y", joint=True)], name="link 2", qlim=(0.0, _link_length(d_max, "d_max")))],
                 name=_("robot no tan elemental 2 (seed 004)"), params=_lengths(l=l),
                 joint_symbols=("theta", "d"), unit="m")


def pr_mechanism(l1: float = 1.0, l2: float = 0.5, q1_range=(0.0, 2.0)) -> Robot:
    """Seed 003's prismatic-rotational mechanism: x = q1 + l1 + l2·cos q2, y = l2·sin q2,
    i.e. Tr(q1 + l1, 0, 0)·Rz(q2)·Tr(l2, 0, 0). l1 = 1, l2 = 0.5: verifier's choice
    (the seed gives no unit, so none is shown)."""
    return Robot([Link([Move("x", _symbol("l1"), joint=True)], name="slider", qlim=q1_range),
                  Link([Rot("z", joint=True), Move("x", _symbol("l2"))], name="arm")],
                 name=_("P-R mechanism (seed 003)"), params=_lengths(l1=l1, l2=l2))


def prr_example(l1=1.0, l2=0.5, l3=2.0, l4=1.5) -> DHRobot:
    """Seed 003's geometric example 1, the planar P-R-R (plane xz), as a DH table.
    Lengths: verifier's choice."""
    return DHRobot.from_table([(0, "q1 + l1", "l2", -90), ("q2 - 90", 0, "l3", 0), ("q3", 0, "l4", 0)],
                              name=_("P-R-R example (seed 003)"), params=_lengths(l1=l1, l2=l2, l3=l3, l4=l4),
                              qlim=[(0.0, 1.0), (-180, 180), (-180, 180)])


def prr_example_matrices(l1=1.0, l2=0.5, l3=2.0, l4=1.5) -> Robot:
    """The same P-R-R by homogeneous matrices:
    Tr(0,0,q1+l1)·Tr(l2,0,0) · Ry(q2)·Tr(0,0,l3) · Ry(q3)·Tr(0,0,l4)."""
    return Robot([Link([Move("z", _symbol("l1"), joint=True), Move("x", _symbol("l2"))], name="slider",
                       qlim=(0.0, 1.0)),
                  Link([Rot("y", joint=True), Move("z", _symbol("l3"))], name="link 2"),
                  Link([Rot("y", joint=True), Move("z", _symbol("l4"))], name="link 3")],
                 name=_("P-R-R example by matrices (seed 003)"), params=_lengths(l1=l1, l2=l2, l3=l3, l4=l4))


# The DH base frame of the 3R example: x0 = world y, y0 = world z, z0 = world x.
RRR_BASE = [[0, 0, 1, 0], [1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 1]]


def rrr_example(l1=1.0, l2=2.0, l3=1.5) -> DHRobot:
    """Seed 003's geometric example 2 (3R, joint 1 about the world x axis) as a DH table,
    with the base transform that puts z0 on world x. Lengths: verifier's choice."""
    return DHRobot.from_table([("q1", "l1", 0, 90), ("q2", 0, "l2", 0), ("q3", 0, "l3", 0)],
                              name=_("3R example (seed 003)"), params=_lengths(l1=l1, l2=l2, l3=l3),
                              base=RRR_BASE)


def rrr_example_matrices(l1=1.0, l2=2.0, l3=1.5) -> Robot:
    """The same 3R by homogeneous matrices: Tr(l1,0,0)·Rx(q1) · Rz(−q2)·Tr(0,l2,0) · Rz(−q3)·Tr(0,l3,0)."""
    return Robot([Link([Move("x", _symbol("l1")), Rot("x", joint=True)], name="link 1"),
                  Link([Rot("z", joint=True, sign=-1), Move("y", _symbol("l2"))], name="link 2"),
                  Link([Rot("z", joint=True, sign=-1), Move("y", _symbol("l3"))], name="link 3")],
                 name=_("3R example by matrices (seed 003)"), params=_lengths(l1=l1, l2=l2, l3=l3))


def seed002_4dof(l1=1.0, l4=0.5, d_range=(0.0, 1.0)) -> DHRobot:
    """Seed 002's 4-DOF R-P-P-R table. l1 = 1, l4 = 0.5: verifier's choice."""
    return DHRobot.from_table([("q1", "l1", 0, 0), (90, "d2", 0, 90), (0, "d3", 0, 0), ("q4", "l4", 0, 0)],
                              name=_("4-DOF R-P-P-R (seed 002)"), params=_lengths(l1=l1, l4=l4),
                              qlim=[(-180, 180), d_range, d_range, (-180, 180)])


def seed002_6dof(l1=1.0, l2=2.0, l3=3.0, l4=4.0) -> DHRobot:
    """Seed 002's 6-DOF revolute table (θ1…θ6). Lengths 1, 2, 3, 4: verifier's choice."""
    return DHRobot.from_table([("theta1", 0, 0, -90), ("theta2", "l1", 0, 90), ("theta3 - 90", 0, "-l2", 90),
                               ("theta4", "l3", 0, -90), ("theta5", 0, 0, 90), ("theta6", "l4", 0, 0)],
                              name=_("6-DOF robot (seed 002)"), params=_lengths(l1=l1, l2=l2, l3=l3, l4=l4))


def seed003_6dof(l1=1.0, l2=2.0, l3=3.0, l4=4.0) -> DHRobot:
    """Seed 003's 6-DOF revolute table (q1…q6): straight up at q = 0, spherical wrist.
    Lengths 1, 2, 3, 4: verifier's choice."""
    return DHRobot.from_table([("q1", "l1", 0, 90), ("q2 + 90", 0, "l2", 0), ("q3 - 90", 0, 0, -90),
                               ("q4 - 90", "l3", 0, -90), ("q5", 0, 0, 90), ("q6", "l4", 0, 0)],
                              name=_("6-DOF robot (seed 003)"), params=_lengths(l1=l1, l2=l2, l3=l3, l4=l4))


def ssrms() -> DHRobot:
    """The SSRMS (Canadarm2) of seed 000: its 14 factors Tz[θ,d]·Tx[α,a] as a DH table
    (lengths in the seed's units; joints ±270° as on the real arm).

    Its table is all numbers, so the links are made from them directly rather than read as text
    by :meth:`DHRobot.from_table` (which reads with sympy): building and moving the arm, the browser
    edition's first slider, never loads sympy. Its symbolic side (``fk_sym()``, ``A(i)``) is the same,
    made exact on first use (-90° is -π/2, 2.5 is 5/2).

    >>> arm = ssrms()
    >>> print(arm.table())
     i | θ  | d   | a  | α    | joint
     1 | θ1 | 2.5 | 0  | -90° | R
     2 | θ2 | 6   | 0  | -90° | R
     3 | θ3 | 6   | 12 | 0°   | R
     4 | θ4 | 1   | 12 | 0°   | R
     5 | θ5 | 6   | 0  | -90° | R
     6 | θ6 | 6   | 0  | -90° | R
     7 | θ7 | 0   | 0  | 0°   | R
    """
    rows = [("theta1", 2.5, 0, -90), ("theta2", 6, 0, -90), ("theta3", 6, 12, 0), ("theta4", 1, 12, 0),
            ("theta5", 6, 0, -90), ("theta6", 6, 0, -90), ("theta7", 0, 0, 0)]
    limits = (math.radians(-270), math.radians(270))
    links = [RevoluteDH(d=float(d), a=float(a), alpha=math.radians(alpha), qlim=limits) for _q, d, a, alpha in rows]
    return DHRobot(links, name=_("SSRMS (seed 000)"), joint_symbols=[q for q, *_numbers in rows])


PUMA_QLIM_DEG = [(-160, 160), (-45, 225), (-225, 45), (-110, 170), (-100, 100), (-266, 266)]


def puma560(floor: bool = False) -> DHRobot:
    """The PUMA 560 in standard DH, as P. Corke's ``mdl_puma560`` (metres): frame 0 at the
    shoulder (d1 = 0). ``floor=True`` gives the Python Robotics Toolbox variant, with frame 0
    on the floor under the pedestal (d1 = 0.67183 m): every pose 0.67183 m higher."""
    d1 = 0.67183 if as_flag(floor, "floor") else 0
    rows = [("q1", d1, 0, 90), ("q2", 0, 0.4318, 0), ("q3", 0.15005, 0.0203, -90),
            ("q4", 0.4318, 0, 90), ("q5", 0, 0, -90), ("q6", 0, 0, 0)]
    return DHRobot.from_table(rows, name="PUMA 560", qlim=PUMA_QLIM_DEG, unit="m")


def catalogue() -> dict:
    """Every robot of the course by name (factories with the default lengths)."""
    return {name: globals()[name] for name in __all__ if name not in ("catalogue",)}
