"""The checks of what a student gives the assignment's tools (:mod:`dhlab.assignment.notebook`):
numbers typed in degrees or metres, ``±q_i + constant`` terms, the part to check, and
joint values (radians) for a numeric matrix.

The limits are the grader's (:mod:`dhlab.assignment.answers`: a constant of at most
``MAX_NUMBER`` degrees or metres, joint variables q1 … q50), so whatever ``Tz`` and ``Tx``
accept, the grader and the notebook's own check can read; a value beyond them is refused
where it is typed, with the fix.

>>> degrees(90, "α in Tx[α, a]")
90.0
>>> degrees("90", "α in Tx[α, a]")
Traceback (most recent call last):
...
dhlab.validation.DHLabError: α in Tx[α, a] = '90' is not a valid number: it is text:
    write the number without quotes (e.g. 0.5, not '0.5').
"""
from __future__ import annotations

import math
import numbers
import re
from types import SimpleNamespace

import numpy as np

from ..errors import DHLabError
from ..i18n import _
from ..validation import as_angle, as_index, as_length, as_number, check_joint_values, describe, with_decimal_comma_note
from ..validation.marks import has_angle_mark, is_angle
from .answers import MAX_NUMBER

__all__ = ["MAX_JOINT", "degrees", "length", "constant", "joint_number", "sign", "unit_factor", "term_parts",
           "is_text", "joint_count", "part_number", "joint_value", "chain_joint_values"]

MAX_JOINT = 50          # the grader reads the joint variables q1 … q50 (answers._term)


# --- one constant: degrees or metres, as typed ----------------------------------------------

def constant(value, what: str, unit: str = "") -> float:
    """A finite number of at most ``MAX_NUMBER`` (the grader's limit) as a float."""
    number = as_number(value, what)
    if abs(number) > MAX_NUMBER:
        raise DHLabError(_("{what} = {number:g} is too large: no {unit} of this robot is that big "
                           "(at most {limit:g}). Check the number and its unit.").format(
            what=what, number=number, unit=unit or _("angle (degrees) or length (metres)"), limit=MAX_NUMBER))
    return number + 0.0                 # -0.0 -> 0.0: feedback never shows "-0°"


def degrees(value, what: str, unit: str = "") -> float:
    """A number typed in degrees (a value made by dhlab.deg2rad() is converted back)."""
    if is_angle(value):
        value = math.degrees(as_number(value, what))
    return constant(value, what, unit or _("angle (degrees)"))


def length(value, what: str) -> float:
    """A length typed in metres (a value made by dhlab.deg2rad() is an angle: refused)."""
    if has_angle_mark(value):
        raise DHLabError(_("{what} is a length, but you gave an angle ({value}): give metres.").format(
            what=what, value=describe(value)))
    return constant(value, what, _("length (metres)"))


# --- the parts of ±q_i + constant --------------------------------------------------------------

def joint_number(joint) -> int:
    """The i of q_i: a whole number 1 … MAX_JOINT."""
    return as_index(joint, _("the joint number i of q_i"), 1, MAX_JOINT)


def sign(value) -> int:
    """+1 (q_i) or -1 (-q_i)."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Integral) or value not in (1, -1):
        raise DHLabError(_("sign must be 1 (for q_i) or -1 (for -q_i), got {value}.").format(value=describe(value)))
    return int(value)


def unit_factor(factor) -> int | None:
    """``factor`` as +1 or -1 if it is one (``q_i * -1``), else None."""
    if isinstance(factor, (bool, np.bool_)):
        return None
    try:
        value = as_number(factor, "factor")
    except DHLabError:
        return None
    return int(value) if value in (1.0, -1.0) else None


_TERM_TEXT = re.compile(r"^\s*(?:(?P<c1>[+-]?\s*\d+(?:\.\d*)?)\s*)?(?P<s>[+-])?\s*q(?P<j>\d+)\s*"
                        r"(?:(?P<c2>[+-]\s*\d+(?:\.\d*)?)\s*)?$")


def term_parts(value, what: str) -> tuple:
    """'q2 + 90', '-q3', '90 - q2' (or a sympy expression printed so) -> (joint, sign, constant)."""
    text = str(value).replace("−", "-").replace("°", "")
    m = _TERM_TEXT.match(text)
    if not m or (m["c1"] and m["c2"]) or (m["c1"] and not m["s"]):
        raise DHLabError(with_decimal_comma_note(                 # "0,4": a decimal comma
            _("{what} must be a number or ±q_i + a constant, like q2 + 90, got {value}.").format(
                what=what, value=repr(value)), value))
    const = float((m["c1"] or m["c2"] or "0").replace(" ", ""))
    return int(m["j"]), -1 if m["s"] == "-" else 1, const


def is_text(value) -> bool:
    """Text, or a sympy expression with symbols (read as text, like 'q2 + 90')."""
    return isinstance(value, str) or (hasattr(value, "free_symbols") and bool(value.free_symbols))


# --- the notebook's other inputs -------------------------------------------------------------

def joint_count(n) -> int:
    """How many joint variables q1 … qn to make."""
    return as_index(n, _("n (the number of joint variables)"), 1, MAX_JOINT)


def part_number(part) -> int:
    """1, 2 or 3: the part of the assignment to check."""
    if isinstance(part, (bool, np.bool_)) or not isinstance(part, numbers.Integral) or part not in (1, 2, 3):
        raise DHLabError(_("the assignment has parts 1, 2 and 3 to check, not {part}.").format(part=describe(part)))
    return int(part)


def joint_value(q, where) -> float:
    """The joint value of one T_i: radians where q_i is in θ_i, metres where it is in d_i
    (``where`` is 'θ' or 'd'; None for a row without a joint variable)."""
    if not isinstance(where, (str, type(None))):
        raise DHLabError(_("where must say which entry holds the joint variable, 'θ' or 'd', got {value}.").format(
            value=describe(where)))

    return as_length(q, "q") if where == "d" else as_angle(q, "q")


def chain_joint_values(q, rows) -> np.ndarray:
    """``q`` for a chain of :class:`~dhlab.assignment.answers.Row`: one value per joint variable
    q1 … qn (n, the largest i of the chain's q_i), checked as the rest of the course checks
    joint values (radians; metres for a q_i that only appears in a d)."""
    uses = {}
    for row in rows:
        joint, _sign, where = row.joint
        if joint is not None:
            uses.setdefault(joint, set()).add(where)
    n = max(uses, default=0)
    joints = [SimpleNamespace(is_prismatic=uses.get(j) == {"d"}) for j in range(1, n + 1)]
    return check_joint_values(q, joints, "q", single=True)
