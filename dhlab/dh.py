"""Standard Denavit-Hartenberg robots: ``A_i = Rz(θ_i)·Tr(0, 0, d_i)·Tr(a_i, 0, 0)·Rx(α_i)``.

A DH link is a :class:`~dhlab.chain.Link` with exactly those four motions; the
joint variable is added to θ (revolute) or to d (prismatic). Angles are radians:

>>> import numpy as np
>>> from dhlab import DHRobot, RevoluteDH, deg2rad
>>> arm = DHRobot([RevoluteDH(a=1.0), RevoluteDH(a=0.5)], name="2R")
>>> arm.fk([deg2rad(90), 0]).round(6)[:3, 3].tolist()
[0.0, 1.5, 0.0]

Tables typed from the slides (degrees, joint variables by name) go through
:meth:`DHRobot.from_table`:

>>> ssrms_like = DHRobot.from_table([("q1", 2.5, 0, -90), ("q2", 6, 0, 0)])
>>> print(ssrms_like.table())
 i | θ  | d   | a | α    | joint
 1 | q1 | 2.5 | 0 | -90° | R
 2 | q2 | 6   | 0 | 0°   | R
"""
from __future__ import annotations

import math
import re

import numpy as np

from .chain import Robot
from .chain_inputs import link_list, numeric_params
from .errors import DHLabError
from .i18n import N_, _
from .lazy_sympy import is_sympy
from .links import Link, Move, Rot
from .table import DHTable
from .transforms import Rx, Rz
from .validation import Angle, as_angle, as_choice, as_length, as_number, as_sequence, describe, has_angle_mark

__all__ = ["RevoluteDH", "PrismaticDH", "DHRobot"]


def _check_angle_param(value, name: str):
    """A DH angle (θ, α, offset): radians or a sympy expression; kept as given (deg2rad() keeps its mark)."""
    if isinstance(value, str):
        raise DHLabError(_("{name} = {value!r} is text: pass a number of radians (e.g. dhlab.deg2rad(90)) or a "
                           "sympy expression. Tables typed as text go through DHRobot.from_table.").format(
                               name=name, value=value))
    checked = as_angle(value, name, symbolic=True)
    return checked if is_sympy(checked) or not isinstance(value, Angle) else value


def _check_length_param(value, name: str):
    """A DH length (d, a, offset): a number or a sympy expression, never a deg2rad() value."""
    if isinstance(value, str):
        raise DHLabError(_("{name} = {value!r} is text: pass a number or a sympy symbol, e.g. "
                           "sympy.Symbol({value!r}) with its value in the robot's params. Tables typed as text go "
                           "through DHRobot.from_table.").format(name=name, value=value))
    return as_length(value, name, symbolic=True)


class DHParameters(Link):
    """A link given by the four DH parameters θ, d, a, α (checked) and its joint; the
    convention (:class:`DHLink` here, :class:`~dhlab.mdh.MDHLink`) orders the four motions."""

    convention = ""              # "standard" or "modified"

    def __init__(self, theta, d, a, alpha, offset, revolute: bool, qlim, name):
        self.theta = _check_angle_param(theta, "theta")
        self.d = _check_length_param(d, "d")
        self.a = _check_length_param(a, "a")
        self.alpha = _check_angle_param(alpha, "alpha")
        if revolute:
            self.offset = _check_angle_param(offset, "offset (added to the joint angle)")
            along_z = [Rot("z", self.offset, joint=True), Move("z", self.d)]
        else:
            self.offset = _check_length_param(offset, "offset (added to the joint displacement)")
            along_z = [Rot("z", self.theta), Move("z", self.offset, joint=True)]
        along_x = [Move("x", self.a), Rot("x", self.alpha)]      # Tr(a, 0, 0) and Rx(α) commute
        super().__init__(self.motions(along_z, along_x), name=name, qlim=qlim)

    @staticmethod
    def motions(along_z: list, along_x: list) -> list:
        raise NotImplementedError

    def __repr__(self):
        kind = type(self).__name__
        return f"{kind}(theta={self.theta}, d={self.d}, a={self.a}, alpha={self.alpha}, offset={self.offset})"


class DHLink(DHParameters):
    """Common part of RevoluteDH and PrismaticDH: ``A_i = Rz(θ_i)·Tr(0, 0, d_i)·Tr(a_i, 0, 0)·Rx(α_i)``."""

    convention = "standard"

    @staticmethod
    def motions(along_z: list, along_x: list) -> list:
        """Standard DH: first along z_(i−1) (θ_i, d_i), then along x_i (a_i, α_i)."""
        return along_z + along_x


class RevoluteDH(DHLink):
    """A revolute DH link: θ = q + offset; d, a, α constant (α, offset in radians)."""

    def __init__(self, d=0, a=0, alpha=0, offset=0, qlim=None, name: str = ""):
        super().__init__(0, d, a, alpha, offset, True, qlim, name)


class PrismaticDH(DHLink):
    """A prismatic DH link: d = q + offset; θ, a, α constant (θ, α in radians)."""

    def __init__(self, theta=0, a=0, alpha=0, offset=0, qlim=None, name: str = ""):
        super().__init__(theta, 0, a, alpha, offset, False, qlim, name)


class DHRobot(Robot):
    """A serial robot described by a standard DH table (one :class:`RevoluteDH` or
    :class:`PrismaticDH` per joint), with optional base and tool transforms."""

    def __init__(self, links, name: str = "robot", base=None, tool=None,
                 params=None, joint_symbols=None, unit: str = ""):
        _no_modified_links(links)
        links = link_list(links, DHLink, "RevoluteDH(...) or PrismaticDH(...) (for other products of "
                                          "motions use dhlab.Robot)")
        super().__init__(links, name=name, base=base, tool=tool, params=params,
                         joint_symbols=joint_symbols, unit=unit)

    def table(self) -> DHTable:
        """The DH table in the seeds' column order θ, d, a, α (angles in degrees)."""
        return DHTable(self)

    # --- symbolic: merge joints with parallel axes before multiplying ---------------
    merges_parallel_joints = True

    def _sym_blocks(self):
        """Link matrices, with each run of revolute joints about parallel axes
        (α = 0 between them) written as one block in the sums of their angles."""
        from .symbolic import exact_angle  # (sympy: imported on first symbolic use)
        matrices = self.link_matrices_sym()          # once: each call builds all n
        blocks, i = [], 0
        while i < self.n:
            j = i
            while (j + 1 < self.n and self.links[j].is_revolute and self.links[j + 1].is_revolute
                   and exact_angle(self.links[j].alpha) == 0):
                j += 1
            blocks.append(self._run_block(i, j) if j > i else matrices[i])
            i = j + 1
        return blocks

    def _run_block(self, first: int, last: int):
        """A_first ··· A_last for revolute links whose α are 0 except the last one's:
        [Rz(φ_last)·Rx(α_last) | (Σ a_j cos φ_j, Σ a_j sin φ_j, Σ d_j)], φ_j the partial sums."""
        import sympy as sp  # lazy: sympy on first symbolic use

        from .symbolic import exact_angle, exact_length  # lazy: symbolic pulls in sympy
        phi, p = 0, sp.zeros(3, 1)
        for k in range(first, last + 1):
            link = self.links[k]
            phi = phi + self.q_symbols[k] + exact_angle(link.offset)
            a, d = exact_length(link.a), exact_length(link.d)
            p += sp.Matrix([a * sp.cos(phi), a * sp.sin(phi), d])
        block = Rz(phi) * Rx(exact_angle(self.links[last].alpha))
        block[:3, 3] = p
        return block

    # --- tables typed from slides ---------------------------------------------------
    @classmethod
    def from_table(cls, rows, name: str = "robot", params=None, angles: str = "deg",
                   qlim=None, **kwargs) -> DHRobot:
        """A robot from rows ``(θ, d, a, α)`` typed as on the slides.

        Entries are numbers or text such as ``"q2 + 90"``, ``"θ3 - 90"``, ``"l1"``,
        ``"-l2"``. Angles are in **degrees** by default (``angles="rad"`` for
        radians). In each row the joint variable is the symbol in θ (revolute) or,
        if θ has none, the symbol in d that ``params`` does not give (prismatic).
        ``params`` gives the numbers of the other symbols, e.g. ``{"l1": 1}``;
        ``qlim`` one (low, high) per row, in the table's angle unit for revolute joints.
        """
        links, symbols, params = links_from_table(rows, params, angles, qlim, RevoluteDH, PrismaticDH)
        return cls(links, name=name, params=params, joint_symbols=symbols, **kwargs)


def links_from_table(rows, params, angles, qlim, revolute, prismatic) -> tuple:
    """The links of a table typed as on the slides (see :meth:`DHRobot.from_table`), made by
    the link classes ``revolute`` and ``prismatic``: (links, joint symbols, params)."""
    import sympy as sp  # a typed table is read as sympy expressions
    angles = as_choice(angles, ("deg", "rad"), "angles")
    params = numeric_params(params)
    rows = table_rows(rows)
    limits_per_row = _table_qlim(qlim, len(rows))
    to_rad = (lambda e: e * sp.pi / 180) if angles == "deg" else (lambda e: e)
    links, symbols = [], []
    for i, row in enumerate(rows, start=1):
        theta, d, a, alpha = (parse_entry(v, _("row {i}, {column}").format(i=i, column=col),
                                     col in "θα" and angles == "deg", col in "da")
                              for v, col in zip(row, "θdaα"))
        limits = limits_per_row[i - 1]
        if angles == "deg":
            _no_marked_angles(params, {"θ": theta, "α": alpha}, i)
        q = _joint_symbol(theta, params)
        if q is not None:
            offset = to_rad(_offset(theta, q, _("row {i}, {column}").format(i=i, column="θ")))
            if limits is not None and angles == "deg":
                limits = _degrees_to_radians(limits, f"qlim[{i - 1}] (row {i}, degrees)")
            links.append(revolute(d=d, a=a, alpha=to_rad(alpha), offset=offset, qlim=limits))
        else:
            q = _joint_symbol(d, params)
            if q is None:
                raise DHLabError(_(
                    "row {i} {row!r} has no joint variable: θ (revolute) or d (prismatic) must contain a symbol "
                    "such as q{i} that params does not give a value.").format(i=i, row=row))
            links.append(prismatic(theta=to_rad(theta), a=a, alpha=to_rad(alpha),
                                   offset=_offset(d, q, _("row {i}, {column}").format(i=i, column="d")), qlim=limits))
        if str(q) in symbols:
            raise DHLabError(_("rows {first} and {i} both use {q} as their joint variable: every joint needs its "
                               "own (q1, q2, …).").format(first=symbols.index(str(q)) + 1, i=i, q=q))
        symbols.append(str(q))
    return links, symbols, params


def refuse_convention(links, convention: str, what: str, advice: str) -> None:
    """A link of the other DH convention in a robot (``convention`` 'modified' in a DHRobot,
    'standard' in an MDHRobot): say which link, which convention, and what to do."""
    if isinstance(links, (list, tuple)):
        for i, link in enumerate(links, start=1):
            if getattr(link, "convention", "") == convention:
                raise DHLabError(_("link {i} is a {what} link, {kind}: {advice}").format(
                    i=i, what=_(what), kind=type(link).__name__, advice=_(advice)))


def _no_modified_links(links) -> None:
    refuse_convention(links, "modified", N_("modified-DH (Craig)"),
                      N_("a DHRobot is standard DH. Build the robot with dhlab.MDHRobot, or convert it with "
                         "dhlab.to_standard(dhlab.MDHRobot(links))."))


def _no_marked_angles(params, angles: dict, i: int) -> None:
    """In a table typed in degrees, a deg2rad() parameter in θ or α would be converted twice."""
    for col, expr in angles.items():
        for symbol in sorted(expr.free_symbols, key=str):
            value = params.get(str(symbol))
            if isinstance(value, Angle):
                raise DHLabError(_("parameter {symbol} = {value!r} is in row {i}'s {column}, and this table is in "
                                   "degrees: give the plain number of degrees ({symbol}={degrees:g}), or use "
                                   "angles='rad'.").format(symbol=symbol, value=value, i=i, column=col,
                                                           degrees=math.degrees(value)))


def table_rows(rows) -> list:
    """The table as a list of rows of 4 entries, or a clear error."""
    example = "[('q1', 0, 1, 0), ('q2', 0, 0.5, 0)]"
    rows = as_sequence(rows, _("the table"), _("a list of rows (θ, d, a, α), e.g. {example}").format(example=example))
    if not rows:
        raise DHLabError(_("the table is empty: give one row (θ, d, a, α) per joint, e.g. {example}.").format(
            example=example))
    for i, row in enumerate(rows, start=1):
        try:
            count = None if isinstance(row, (str, bytes, dict, set, frozenset)) else len(row)
        except TypeError:        # no length (a number, a 0-d array)
            count = None
        if count != 4:
            count = "not 4" if count is None else count
            raise DHLabError(_("row {i} must have 4 entries (θ, d, a, α), got {count}: {got}.").format(
                i=i, count=count, got=describe(row)))
    return rows


def _table_qlim(qlim, n: int) -> list:
    if qlim is None:
        return [None] * n
    return as_sequence(qlim, "qlim", _("one (low, high) per row ({n} rows)").format(n=n), size=n)


def _degrees_to_radians(limits, name: str) -> tuple:
    """A revolute joint's limits typed in degrees, as radians (a deg2rad() value here is ambiguous)."""
    if has_angle_mark(limits):
        raise DHLabError(_("{name}: the table's angles are degrees, so write the limits as plain degrees "
                           "(e.g. (-90, 90)), not with deg2rad(); got {got}.").format(name=name, got=describe(limits)))
    limits = as_sequence(limits, name, _("two numbers (low, high)"), size=2)
    return tuple(float(v) for v in np.radians([as_number(v, name) for v in limits]))


_TEXT = re.compile(r"[\w\s+\-*/().]*")


def parse_entry(value, where: str, degrees: bool = False, length: bool = False):
    """A table entry as a sympy number or expression, checked (finite, real)."""
    import sympy as sp  # a typed table is read as sympy expressions
    if degrees and has_angle_mark(value):
        raise DHLabError(_("{where} = {value!r} is already in radians (made by deg2rad()), but this table's "
                           "angles are degrees: write the plain number of degrees (e.g. 90), or pass "
                           "angles='rad'.").format(where=where, value=value))
    if length and has_angle_mark(value):
        raise DHLabError(_("{where} is a length, but you gave an angle ({got}): pass a plain number.").format(
            where=where, got=describe(value)))
    if isinstance(value, str):
        text = value.replace("θ", "theta").replace("−", "-").replace("°", "").replace("º", "")
        text = re.sub(r"\s+", " ", text).strip()
        if not text or not _TEXT.fullmatch(text) or "__" in text:
            raise DHLabError(_("{where}: cannot read {value!r} as a number or an expression like 'q2 + 90'.").format(
                where=where, value=value))
        names = {n: sp.Symbol(n) for n in re.findall(r"[A-Za-z_]\w*", text) if n != "pi"}
        try:
            value = sp.sympify(text, locals=names)
        except (sp.SympifyError, SyntaxError, TypeError, ValueError, AttributeError, ZeroDivisionError):
            raise DHLabError(_("{where}: cannot read {value!r} as a number or an expression like 'q2 + 90'.").format(
                where=where, value=value)) from None
    if is_sympy(value):
        value = as_number(value, where, symbolic=True)
    else:
        number = as_number(value, where)
        value = sp.nsimplify(number) if number.is_integer() else sp.Float(number)
    if degrees:
        _check_degrees(value, where)
    return value


_parse = parse_entry     # its old private name (dhlab/course/predict.py), for one release


def _check_degrees(value, where: str) -> None:
    """An angle of a degree table (its constant part, as in 'q2 + 90') is at most a full turn."""
    constant = value.as_coeff_Add()[0]
    if constant.is_number and abs(float(constant)) > 360:
        raise DHLabError(_("{where} = {value:g}° is more than a full turn: this table's angles are degrees, "
                           "from -360 to 360 (720° is the same as 0°). Check the number.").format(
                               where=where, value=float(constant)))


def _joint_symbol(expr, params):
    free = [s for s in expr.free_symbols if str(s) not in params]
    if len(free) > 1:
        raise DHLabError(_("{expr} has several unknown symbols {names}: give the constant ones in params "
                           "(e.g. params={{'l1': 1.0}}) so the joint variable is clear.").format(
                               expr=expr, names=sorted(map(str, free))))
    return free[0] if free else None


def _offset(expr, q, where: str):
    offset = (expr - q).expand()
    if offset.has(q):
        raise DHLabError(_("{where}: the joint variable must appear as '+{q}', got {expr}.").format(
            where=where, q=q, expr=expr))
    return offset
