"""Display of a DH table in the seeds' column order θ, d, a, α, angles in degrees.

Joint variables appear as on the slides, with their offset: ``q2 + 90°``.
A table renders as HTML in Jupyter and as aligned text in a terminal. The table of a
modified-DH (Craig) robot has the same columns, headed with what row i holds there:
θ_i, d_i, a_(i−1), α_(i−1) (see :mod:`dhlab.mdh`).
"""
from __future__ import annotations

import html
import math

from .errors import DHLabError
from .i18n import N_, _
from .lazy_sympy import has_symbols
from .validation import describe

__all__ = ["DHTable", "format_angle", "format_length"]


def _number(v: float) -> str:
    text = f"{v:.6g}"
    return "0" if text in ("-0", "0") else text


def format_angle(value) -> str:
    """An angle (radians, number or sympy) as degrees: pi/2 -> '90°'."""
    if has_symbols(value):
        import sympy as sp  # (loaded already: the value is a sympy formula)
        return str(sp.nsimplify(value * 180 / sp.pi)) + "°"
    return _number(math.degrees(float(value))) + "°"


def format_length(value) -> str:
    """A length (number or sympy expression) as text: 2.5 -> '2.5', -l2 -> '-l2'."""
    if has_symbols(value):
        return str(value)
    return _number(float(value))


def _with_offset(var: str, offset: str) -> str:
    """'q2', '90°' -> 'q2 + 90°'; '-90°' -> 'q2 − 90°'; '0' -> 'q2'."""
    if offset in ("0°", "0"):
        return var
    if offset.startswith("-"):
        return f"{var} − {offset[1:]}"
    return f"{var} + {offset}"


class DHTable:
    """The DH table of a :class:`~dhlab.DHRobot`, for display (``print`` or Jupyter)."""

    header = ("i", "θ", "d", "a", "α", N_("joint"))        # words marked N_ are translated when shown
    modified_header = ("i", "θ_i", "d_i", "a_(i−1)", "α_(i−1)", N_("joint"))

    def __init__(self, robot):
        if not all(hasattr(robot, name) for name in ("links", "joint_labels", "name")) or \
                not all(hasattr(link, "alpha") for link in getattr(robot, "links", [None])):
            raise DHLabError(_("DHTable shows the table of a DHRobot (e.g. DHTable(dhlab.robots.puma560()), "
                               "or robot.table()); got {got}.").format(got=describe(robot)))
        self.robot = robot
        self.modified = all(getattr(link, "convention", "") == "modified" for link in robot.links)
        if self.modified:
            self.header = self.modified_header
        self.rows = [self._row(i, link, label) for i, (link, label)
                     in enumerate(zip(robot.links, robot.joint_labels), start=1)]

    @staticmethod
    def _row(i, link, label):
        if link.is_revolute:
            theta = _with_offset(label, format_angle(link.offset))
            d = format_length(link.d)
        else:
            theta = format_angle(link.theta)
            d = _with_offset(label, format_length(link.offset))
        return (str(i), theta, d, format_length(link.a), format_angle(link.alpha),
                "R" if link.is_revolute else "P")

    def __str__(self) -> str:
        cells = [self._shown_header()] + self.rows
        widths = [max(len(r[c]) for r in cells) for c in range(len(self.header))]
        lines = [" | ".join(cell.ljust(w) for cell, w in zip(row, widths)).rstrip() for row in cells]
        return "\n".join(" " + line for line in lines)

    def _title(self, name: str) -> str:
        return (_("modified DH (Craig) table of {name}") if self.modified else _("DH table of {name}")).format(
            name=name)

    def _shown_header(self) -> tuple:
        return tuple(_(h) if h == "joint" else h for h in self.header)

    def __repr__(self) -> str:
        return f"{self._title(repr(self.robot.name))}:\n{self}"

    def _repr_html_(self) -> str:
        head = "".join(f"<th>{html.escape(h)}</th>" for h in self._shown_header())
        body = "".join("<tr>" + "".join(f"<td>{html.escape(c)}</td>" for c in row) + "</tr>"
                       for row in self.rows)
        caption = html.escape(_("{title} (angles in degrees)").format(title=self._title(self.robot.name)))
        return f"<table><caption>{caption}</caption><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"
