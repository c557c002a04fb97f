"""What the checks of parts 2 and 3 share: the items, the frames the student meant, one row on one frame.

* :class:`Item` — one thing checked, right, wrong or not answered, with its message;
* :class:`Analysis` — part 3's reading of the student's ``T_1 … T_n``: an item per row and
  the DH frames the student evidently meant (:mod:`~dhlab.assignment.checks.transforms`
  finds it; the links of part 2 are checked in those frames,
  :mod:`~dhlab.assignment.checks.links`);
* :func:`rows_of`, :func:`matrix` — the student's rows, and one row as a matrix;
* :func:`fits` — whether a row, placed on a frame, builds a valid DH frame that turns its
  joint the pictured way;
* :func:`slips_of` — the rows a student may have meant, one typical slip away;
* :func:`point_text` — a point as the feedback prints it.

>>> from dhlab.assignment.answers import Row, Term
>>> from dhlab.assignment.reference import reference
>>> row = Row(Term(0.0, 1), Term(0.0), 90.0, 0.0)        # T1 of the PUMA: Tz[q1, 0]·Tx[90°, 0]
>>> fits(reference(), 1, np.eye(4), row)
True
>>> len(slips_of(row)), point_text([0.4318, -1e-17, 0.15005])
(7, '(0.4318, 0.0000, 0.1500)')
"""
from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from ..answers import NOT_ANSWERED, Answers, Row
from ..reference import row_matrix
from ..valid_frames import is_valid_frame

__all__ = ["Item", "Analysis", "rows_of", "matrix", "along_arrow", "fits", "slips_of", "point_text"]


@dataclass
class Item:
    """One thing checked: ``ok`` True, False, or None (not answered)."""
    label: str
    ok: bool | None
    message: str = ""


@dataclass
class Analysis:
    """Part 3's reading of a chain of rows: an item per row, and the frames the student meant."""
    rows: list                  # T_1…T_n as read (Row or a marker)
    items: list                 # one Item per T_i
    frames: list                # the intended frame k at home (4x4), k = 0…n
    valid: list                 # whether the student's own T_k built that frame (True) or it was inferred
    structural_ok: bool         # every T_i is a Row with its own joint's variable in θ (d for a sliding joint)
    ref: object = None
    alternatives: list = dataclasses.field(default_factory=list)   # other readings that charge as many rows


def rows_of(answers: Answers, n: int | None = None) -> list:
    """T_1…T_n: the T_i variable, or the chain's i-th factor when T_i is missing
    (``NOT_ANSWERED`` when neither is there)."""
    rows = []
    chain = answers.chain if isinstance(answers.chain, list) else []
    given = list(answers.T)
    n = len(given) if n is None else n
    for i in range(n):
        value = given[i] if i < len(given) else NOT_ANSWERED
        if not isinstance(value, Row) and i < len(chain):
            value = chain[i]
        rows.append(value)
    return rows


def matrix(row: Row, q: float = 0.0) -> np.ndarray:
    """T_i at joint value q (radians or metres; q only enters where the row's variable is)."""
    theta = math.radians(row.theta.const) + (row.theta.sign * q if row.theta.joint is not None else 0.0)
    d = row.d.const + (row.d.sign * q if row.d.joint is not None else 0.0)
    return row_matrix(theta, d, row.a, math.radians(row.alpha))


def along_arrow(ref, i: int, V) -> bool:
    """Whether z_{i−1} of frame ``V`` points along the drawn positive sense of joint i (then
    θ_i, or d_i, must grow with q_i)."""
    return float(V[:3, 2] @ ref.axes[i - 1].direction) > 0


def fits(ref, i: int, V, row: Row, A=None) -> bool:
    """Whether T_i (its matrix ``A``, :func:`matrix` when not given), placed on frame V, gives a
    valid frame i that turns joint i the pictured way."""
    A = matrix(row) if A is None else A
    return (row.joint[1] > 0) == along_arrow(ref, i, V) and is_valid_frame(ref, i, V @ A)


def slips_of(row: Row) -> list:
    """T_i with one parameter changed the way students slip (a sign, 180°): the rows it may have meant."""
    theta, d = row.theta, row.d
    edits = [dataclasses.replace(row, theta=dataclasses.replace(theta, const=theta.const + 180)),
             dataclasses.replace(row, theta=dataclasses.replace(theta, sign=-theta.sign, const=-theta.const)),
             dataclasses.replace(row, theta=dataclasses.replace(theta, sign=-theta.sign)),
             dataclasses.replace(row, alpha=row.alpha + 180), dataclasses.replace(row, alpha=-row.alpha),
             dataclasses.replace(row, a=-row.a), dataclasses.replace(row, d=dataclasses.replace(d, const=-d.const))]
    if d.joint is not None:                         # a sliding joint: the sign of its variable
        edits.append(dataclasses.replace(row, d=dataclasses.replace(d, sign=-d.sign)))
    return edits


def point_text(v, digits: int = 4) -> str:
    """A point as '(x, y, z)'; rounded first, so that -0.00001 prints as 0.0000, not -0.0000."""
    return "(" + ", ".join(f"{round(x, digits) + 0.0:.{digits}f}" for x in np.asarray(v, float).tolist()) + ")"
