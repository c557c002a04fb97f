"""The DH assignment (notebook 8): the pieces its cells use.

Seed 000 ends with an exercise: do the DH configuration of the PUMA robot, graded
in three points — the sketch, the link models drawn in their own frames, and the
transformations ``T_i = Tz[θ_i, d_i]·Tx[α_i, a_i]``. This module gives the
notebook the robot to look at (:func:`puma_figure`, :func:`axes_table`,
:func:`points_table`), the two factors to write the transformations with (:func:`Tz`,
:func:`Tx`, :func:`joint_variables`), immediate feedback after each part
(:func:`check_part1` … :func:`check_part3`: the same checks, on the same plain data, as
the grader, :mod:`dhlab.assignment.checks`), and the student's own robot assembled and in
a teach panel (:mod:`dhlab.assignment.student_robot`).

The robot of the assignment is the PUMA 560, unless the notebook's "Your robot" cell
made the student's own variant the robot (:func:`dhlab.assignment.notebook_cells.use_variant`,
see :func:`current_robot`): then the parts, the checks, the tables and the teach panel
are the same, for that robot and its n joints.

The transformations are written as in the seed (angles in **degrees**, lengths in
metres), with the joint variables q1…q6:

>>> q1, q2, q3, q4, q5, q6 = joint_variables(6)
>>> T3 = Tz(q3, 0.2) @ Tx(-90, 0.05)
>>> T3
Tz[q3, 0.2]·Tx[-90°, 0.05]
>>> T3.matrix(0).round(5)[:3, 3].tolist()        # numeric at q3 = 0 (radians)
[0.05, 0.0, 0.2]
>>> T4 = Tz(q4, 0.3) @ Tx(90, 0)
>>> chain = T3 @ T4
>>> len(chain)
2
>>> Tx(90, 0) @ Tz(q1, 0)
Traceback (most recent call last):
...
dhlab.validation.DHLabError: only the form Tz[θ, d]·Tx[α, a] is allowed (seed 000): write Tz(...) @ Tx(...), Tz first.
"""
from __future__ import annotations

import html

import numpy as np

from .. import transforms
from ..errors import DHLabError
from ..i18n import _, current_language, speaking
from ..validation import describe, with_decimal_comma_note
from . import checks
from . import inputs as _inputs
from .answers import Row, answers_from_namespace, parse_answers
from .checks.analysis import matrix
from .encode import to_plain
from .notebook_cells import current_robot, use_variant
from .pictures import Note, puma_picture
from .reference import reference
from .student_robot import my_robot_figure, robot_of, teach
from .tables import Table, puma_axes_table, puma_points_table

__all__ = ["joint_variables", "Tz", "Tx", "JointTerm", "ZFactor", "XFactor", "DHTransform", "DHChain",
           "check_part1", "check_part2", "check_part3", "check_part", "PartReport",
           "axes_table", "points_table", "puma_figure", "robot_of", "teach", "my_robot_figure", "Note",
           "current_robot", "use_variant"]


# --- the joint variables and the two factors -------------------------------------------------

class JointTerm:
    """``±q_j + constant``: a joint variable with a constant offset (degrees for θ, metres for d).

    >>> q1, q2 = joint_variables(2)
    >>> q2 + 90, -q1, 90 - q2
    (q2 + 90, -q1, -q2 + 90)
    """

    __array_ufunc__ = None      # numpy hands ``array - q1`` back to us, to be refused clearly

    def __init__(self, joint: int, sign: int = 1, const: float = 0.0):
        self.joint, self.sign = _inputs.joint_number(joint), _inputs.sign(sign)
        self.const = _inputs.constant(const, _("the constant of q{j}").format(j=self.joint))

    def _shift(self, number, sign_of_number=1):
        if isinstance(number, JointTerm):
            raise DHLabError(_("θ_i holds one joint variable, q_i, plus a constant: "
                               "{a} and {b} cannot be added.").format(a=repr(self), b=repr(number)))
        number = _inputs.degrees(number, _("the number added to {term}").format(term=repr(self)),
                                 unit=_("angle (degrees) or length (metres)"))     # a deg2rad() value: back to degrees
        return JointTerm(self.joint, self.sign, self.const + sign_of_number * number)

    def __add__(self, number):
        return self._shift(number)

    __radd__ = __add__

    def __sub__(self, number):
        return self._shift(number, -1)

    def __rsub__(self, number):
        return (-self)._shift(number)

    def __neg__(self):
        return JointTerm(self.joint, -self.sign, 0.0 - self.const)      # 0.0 - 0.0 is +0.0: never "-0°"

    def __pos__(self):
        return self

    def __mul__(self, factor):
        unit = _inputs.unit_factor(factor)
        if unit is not None:
            return self if unit == 1 else -self
        raise DHLabError(_("θ_i = ±q_i + constant: the joint variable cannot be multiplied by {factor}.").format(
            factor=describe(factor)))

    __rmul__ = __mul__

    def __repr__(self):
        var = ("-" if self.sign < 0 else "") + f"q{self.joint}"
        if self.const == 0:
            return var
        return f"{var} {'-' if self.const < 0 else '+'} {abs(self.const):g}"


def joint_variables(n: int = 6) -> tuple:
    """The joint variables q1…qn (physical joint angles, measured from the home pose)."""
    return tuple(JointTerm(j) for j in range(1, _inputs.joint_count(n) + 1))


class ZFactor:
    """``Tz[θ, d]``: rotate θ about z, move d along z (seed 000's ``AplicarTHz``).

    θ may also be typed as text, as on the slides: ``Tz("q2 + 90", 0)``.
    """

    def __init__(self, theta, d):
        if _inputs.is_text(theta):
            theta = JointTerm(*_inputs.term_parts(theta, _("θ in Tz[θ, d]")))
        if _inputs.is_text(d):
            d = JointTerm(*_inputs.term_parts(d, _("d in Tz[θ, d]")))
        if isinstance(theta, JointTerm) and isinstance(d, JointTerm):
            raise DHLabError(_("Tz[{theta}, {d}] has two joint variables: a link has one, in θ for a "
                               "revolute joint or in d for a prismatic one; the other entry is a constant.").format(
                theta=repr(theta), d=repr(d)))
        self.theta = theta if isinstance(theta, JointTerm) else _inputs.degrees(theta, _("θ in Tz[θ, d]"))
        self.d = d if isinstance(d, JointTerm) else _inputs.length(d, _("d in Tz[θ, d]"))

    def __matmul__(self, other):
        if isinstance(other, XFactor):
            return DHTransform(self, other)
        raise DHLabError(_("only the form Tz[θ, d]·Tx[α, a] is allowed (seed 000): a Tz is followed by a Tx."))

    __mul__ = __matmul__          # the seed writes the product with *

    def __repr__(self):
        theta = self.theta if isinstance(self.theta, JointTerm) else f"{self.theta:g}°"
        return f"Tz[{theta}, {self.d if isinstance(self.d, JointTerm) else format(self.d, 'g')}]"


class XFactor:
    """``Tx[α, a]``: rotate α about x, move a along x (seed 000's ``AplicarTHx``)."""

    def __init__(self, alpha, a):
        if isinstance(alpha, JointTerm) or isinstance(a, JointTerm):
            raise DHLabError(_("α and a are constants of the link: the joint variable goes in Tz "
                               "(in θ for a revolute joint)."))
        self.alpha, self.a = _inputs.degrees(alpha, _("α in Tx[α, a]")), _inputs.length(a, _("a in Tx[α, a]"))

    def __matmul__(self, other):
        raise DHLabError(_("only the form Tz[θ, d]·Tx[α, a] is allowed (seed 000): "
                           "write Tz(...) @ Tx(...), Tz first."))

    __mul__ = __matmul__

    def __repr__(self):
        return f"Tx[{self.alpha:g}°, {self.a:g}]"


def _two_values(name: str, names: str, values: tuple) -> None:
    """A clear message, not Python's TypeError, when Tz or Tx gets more than its two values
    (decimal commas, ``Tz(q1, 0,4)``, are the usual reason: the message says so)."""
    if len(values) > 2:
        raise DHLabError(with_decimal_comma_note(_("{name} takes two values ({names}); got {count}: {values}.").format(
            name=name, names=names, count=len(values), values=", ".join(map(str, values))), values, 2))


def Tz(theta, d, *more) -> ZFactor:
    """Seed 000's ``Tz[θ, d]``: θ in degrees (e.g. ``q2 + 90``), d in metres."""
    _two_values("Tz", "θ, d", (theta, d, *more))
    return ZFactor(theta, d)


def Tx(alpha, a, *more) -> XFactor:
    """Seed 000's ``Tx[α, a]``: α in degrees, a in metres."""
    _two_values("Tx", "α, a", (alpha, a, *more))
    return XFactor(alpha, a)


class DHTransform:
    """One ``T_i = Tz[θ_i, d_i]·Tx[α_i, a_i]``; ``T_i @ T_j`` starts a chain."""

    def __init__(self, z: ZFactor, x: XFactor):
        if not isinstance(z, ZFactor) or not isinstance(x, XFactor):
            raise DHLabError(_("a transformation is Tz(θ, d) @ Tx(α, a); DHTransform(z, x) takes a Tz and a Tx, "
                               "got {z} and {x}.").format(z=type(z).__name__, x=type(x).__name__))
        self.z, self.x = z, x

    def __matmul__(self, other):
        if isinstance(other, (DHTransform, DHChain)):
            return DHChain([self]) @ other
        raise DHLabError(_("a transformation T_i is multiplied by another T_j (write T1 @ T2 @ ...)."))

    __mul__ = __matmul__

    def matrix(self, q=None):
        """The 4x4 matrix: numeric at joint value ``q`` (radians), symbolic in q_i when omitted."""
        theta, d = self.z.theta, self.z.d
        if q is None:
            import sympy as sp  # lazy: sympy on first symbolic use

            def exact(x):                   # 90 -> 90, 0.4318 -> 0.4318 (no 1.0 factors)
                return sp.Integer(int(x)) if float(x).is_integer() else sp.Float(x)

            def sym(part, unit):
                if isinstance(part, JointTerm):
                    return part.sign * sp.Symbol(f"q{part.joint}", real=True) + exact(part.const) * unit
                return exact(part) * unit
            return transforms.Tz(sym(theta, sp.pi / 180), sym(d, 1)) * transforms.Tx(
                sym(self.x.alpha, sp.pi / 180), sym(self.x.a, 1))
        row = self.row()
        return matrix(row, _inputs.joint_value(q, row.joint[2]))

    def row(self) -> Row:
        """This transformation as the grader reads it (:class:`dhlab.assignment.answers.Row`)."""
        row = parse_answers({"T1": to_plain(self)}).T[0]
        if not isinstance(row, Row):       # only if its fields were changed after Tz/Tx checked them
            raise DHLabError(_("{transform} cannot be read: {why}.").format(
                transform=repr(self), why=getattr(row, "why", row)))
        return row

    def __repr__(self):
        return f"{self.z!r}·{self.x!r}"


class DHChain:
    """The chain ``T1·T2···Tn`` (the seed's ``THList`` product)."""

    def __init__(self, transforms):
        try:
            transforms = list(transforms)
        except TypeError:
            transforms = [transforms]
        if not all(isinstance(t, DHTransform) for t in transforms):
            raise DHLabError(_("a chain is a list of transformations T_i = Tz(θ, d) @ Tx(α, a) "
                               "(write T1 @ T2 @ ...)."))
        self.transforms = transforms

    def __matmul__(self, other):
        if isinstance(other, DHTransform):
            return DHChain(self.transforms + [other])
        if isinstance(other, DHChain):
            return DHChain(self.transforms + other.transforms)
        raise DHLabError(_("a chain is multiplied by transformations T_i (write T1 @ T2 @ ...)."))

    __mul__ = __matmul__

    def __len__(self):
        return len(self.transforms)

    def __getitem__(self, k):
        return self.transforms[k]

    def frames(self, q) -> np.ndarray:
        """Every frame 0…n at joint values ``q`` (radians), shape (n+1, 4, 4)."""
        rows = [t.row() for t in self.transforms]
        return _frames_of(rows, q)

    def matrix(self, q) -> np.ndarray:
        """The product at joint values ``q`` (radians)."""
        return self.frames(q)[-1]

    def __repr__(self):
        return " · ".join(f"({t!r})" for t in self.transforms)


def _frames_of(rows, q) -> np.ndarray:
    q = _inputs.chain_joint_values(q, rows)          # q[i - 1] is q_i: one value per joint variable
    F = [np.eye(4)]
    for row in rows:
        j = row.joint[0]
        value = q[j - 1] if j is not None else 0.0
        F.append(F[-1] @ matrix(row, value))
    return np.array(F)


# --- immediate feedback ---------------------------------------------------------------------

class PartReport:
    """What checking one part of the assignment found: shown as a list of ✓/✗ lines;
    ``score`` and ``points`` are numbers (nbgrader reads ``score`` as the part's partial
    credit). ``part`` is the grader's :class:`~dhlab.assignment.checks.PartResult`, ``also``
    more of them shown after it, ``note`` a line between."""

    def __init__(self, part, also=(), note: str = ""):
        self.part, self.also, self.note = part, list(also), note

    @property
    def score(self) -> float:
        return self.part.score

    @property
    def points(self) -> int:
        return self.part.points

    @property
    def full_marks(self) -> bool:
        return self.part.full_marks

    def text(self) -> str:
        blocks = [self.part.text()] + ([self.note] if self.note else [])
        blocks += [p.text() for p in self.also]
        return "\n".join(blocks)

    def __repr__(self):
        return self.text()

    def _repr_html_(self):
        note = f"<div><i>{html.escape(self.note)}</i></div>" if self.note else ""
        return self.part.html() + note + "".join(p.html() for p in self.also)


def check_part(part: int, namespace) -> PartReport:
    """Check part 1, 2 or 3 of the assignment from the notebook's variables
    (``namespace``: pass ``globals()``), against the robot of the assignment
    (:func:`current_robot`). The answers are read by name — n_links, n_joints,
    joint_types, x_cases (part 1), link_points (part 2), T1…Tn and chain (part 3) —
    exactly as the grader reads them, and checked by the same functions: part 2 in
    the frames the student's T1…Tn build (so its scored cell comes after part 3)."""
    part = _inputs.part_number(part)
    if not hasattr(namespace, "keys"):
        raise DHLabError(_("pass the notebook's variables: check_part(1, globals())."))
    ref = current_robot()
    answers = answers_from_namespace(namespace, ref.n)     # exactly as the grader reads them
    if part == 1:
        return PartReport(checks.check_part1(answers, ref))
    analysis = checks.analysis_of(answers, ref)       # part 2 is checked in the frames of the student's T_k
    if part == 2:
        return PartReport(checks.check_part2(answers, analysis))
    moved = [label.split(" (")[0] for label in _moved_links(answers, analysis)]
    note = ""
    if moved:
        note = (_("(part 2 again, in the frames these T1…T{n} build: {links} not drawn in them; "
                  "see part 2's score below)") if len(moved) > 1 else
                _("(part 2 again, in the frames these T1…T{n} build: {links} not drawn in it; "
                  "see part 2's score below)")).format(n=ref.n, links=", ".join(moved))
    return PartReport(checks.check_part3(answers, analysis), note=note)


def _moved_links(answers, analysis) -> list:
    """The labels (in the current language) of the links part 2 finds drawn in a valid DH
    frame, but not in the one the student's T_k give them. The grader's message says which:
    it is read in English (the same items, in the same order, in either language)."""
    with speaking("en"):                                            # this thread only
        english = checks.check_part2(answers, analysis).items
    items = english if current_language() == "en" else checks.check_part2(answers, analysis).items
    return [item.label for item, en in zip(items, english)
            if en.ok is False and en.message.startswith("drawn in a valid DH frame")]


def check_part1(namespace) -> PartReport:
    """Part 1, the sketch: ``check_part1(globals())``."""
    return check_part(1, namespace)


def check_part2(namespace) -> PartReport:
    """Part 2, each link in its own frame: ``check_part2(globals())``."""
    return check_part(2, namespace)


def check_part3(namespace) -> PartReport:
    """Part 3, the transformations and the chain: ``check_part3(globals())``."""
    return check_part(3, namespace)


# --- what the student reads: the robot, its axes and points at the home pose ----------------

def puma_figure():
    """The robot of the assignment at its home pose, with its joint axes, their positive
    directions and senses (:mod:`dhlab.assignment.pictures`): the PUMA 560 whole and its
    wrist, or a student's own robot (:meth:`~dhlab.assignment.model.AssignmentRobot.figure`).
    No DH frames: placing them is the exercise."""
    ref = current_robot()
    return puma_picture(ref) if ref is reference() else ref.figure()


def axes_table() -> Table:
    """The joint axes at the home pose, in the world frame (frame 0): a point on each
    and the direction of its drawn arrow (positive q_i turns by the right-hand rule).
    For a student's own robot, its own table."""
    ref = current_robot()
    return puma_axes_table(ref) if ref is reference() else ref.axes_table()


def points_table() -> Table:
    """The points that draw each link, in the world frame at the home pose (metres).
    For a student's own robot, its own table."""
    ref = current_robot()
    return puma_points_table(ref) if ref is reference() else ref.points_table()
