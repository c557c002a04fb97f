"""The report of the DH frame placement (:func:`dhlab.dh_frames.dh_assignment`): one
:class:`FrameStep` per frame — the rule, the case and why, the choices, the DH row — and
:class:`DHAssignment`, which prints them as text or shows them as a table in Jupyter.

Part of :mod:`dhlab.dh_frames` (import from there).

>>> import dhlab
>>> report = dhlab.dh_assignment([((0, 0, 0), (0, 0, 1), "R")], tool=(1, 0, 0))
>>> print(report.steps[1].title)
frame 1 (rule 9, end effector)
>>> report.steps[1].row
('q1', '0', '1', '0°')
"""
from __future__ import annotations

import html
from dataclasses import dataclass, field

import numpy as np

from ..i18n import _
from ..table import format_angle, format_length

__all__ = ["FrameStep", "DHAssignment"]


@dataclass
class FrameStep:
    """How frame ``i`` was placed: the rule, the case and why, the choices, the DH row.

    ``case`` is 1 (z_{i−1}, z_i intersect), 2 (parallel; also when they are the same
    line) or 3 (skew) for frames 1 … n−1, and None for frame 0 (rule 5) and frame n
    (rule 9). ``relation`` names what the axes do: 'intersecting', 'parallel',
    'coincident' or 'skew' (None for frame 0). ``origin``, ``x`` and ``z`` are the
    frame's origin and axes in the world, at q = 0; ``row`` is the table row
    (θ, d, a, α) as printed (None for frame 0).
    """
    i: int
    rule: str
    case: int | None
    relation: str | None
    why: str
    origin_choice: str
    x_choice: str
    origin: np.ndarray
    x: np.ndarray
    z: np.ndarray
    row: tuple | None = None
    notes: list = field(default_factory=list)

    @property
    def title(self) -> str:
        if self.i == 0:
            return _("frame 0 (rule 5)")
        if self.case is None:
            return _("frame {i} (rule 9, end effector)").format(i=self.i)
        return _("frame {i}: case {case}").format(i=self.i, case=self.case)

    def lines(self) -> list:
        """The step as text lines (what ``print(report)`` shows for it)."""
        out = [f"{self.title} — {self.why}",
               "    " + _("origin O{i} = {point}: {choice}").format(i=self.i, point=vector_text(self.origin),
                                                                     choice=self.origin_choice),
               f"    x{self.i} = {vector_text(self.x)}: {self.x_choice}"]
        if self.row is not None:
            theta, d, a, alpha = self.row
            out.append("    " + _("row {i}: θ = {theta}, d = {d}, a = {a}, α = {alpha}").format(
                i=self.i, theta=theta, d=d, a=a, alpha=alpha))
        out += ["    " + _("note: {note}").format(note=note) for note in self.notes]
        return out


class DHAssignment:
    """The report of :func:`dh_assignment`: one :class:`FrameStep` per frame 0 … n.

    ``print(report)`` gives the text; in Jupyter it shows as a table. Attributes:
    ``robot`` (the DHRobot built), ``steps``, ``frames`` (the DH frames in the world at
    q = 0, (n+1, 4, 4)), ``tol`` (lengths below it count as zero), ``options`` (the
    choices used), and ``check`` (the largest distance from a z_{i−1} to joint i's given
    axis and the end-effector deviation, measured on the robot built).
    """

    def __init__(self, robot, steps, tol, scale, options, check):
        self.robot = robot
        self.steps = steps
        self.tol = tol
        self.scale = scale
        self.options = options
        self.check = check

    @property
    def frames(self) -> np.ndarray:
        return self.robot.frames(self.robot.qz)

    @property
    def cases(self) -> list:
        """The case (1, 2 or 3) of x1 … x_{n−1}, as in seed 000's Paso 2."""
        return [step.case for step in self.steps[1:-1]]

    def table(self):
        """The DH table of the robot built (``robot.table()``)."""
        return self.robot.table()

    def _header(self) -> str:
        kinds = " ".join("R" if link.is_revolute else "P" for link in self.robot.links)
        return _("DH frames of {name!r}: {n} joints ({kinds}); lengths below {tol} count as 0").format(
            name=self.robot.name, n=self.robot.n, kinds=kinds, tol=f"{self.tol:.2g}")

    def _footer(self) -> str:
        rounding = 1e-12 * self.scale                 # differences below this are rounding: shown as 0
        axis_dev, tool_dev = (f"{v:.1g}" if v > rounding else "0" for v in self.check)
        return _("check at q = 0: every z_(i-1) lies on joint i's axis with its direction (off by {axis}), the end "
                 "effector is as given (off by {tool}); rounding below {rounding} shows as 0").format(
            axis=axis_dev, tool=tool_dev, rounding=f"{rounding:.1g}")

    def __str__(self) -> str:
        lines = [self._header()]
        for step in self.steps:
            lines += step.lines()
        lines.append(self._footer())
        return "\n".join(lines)

    def __repr__(self) -> str:
        return str(self)

    def _repr_html_(self) -> str:
        head = "".join(f"<th>{h}</th>" for h in
                       (_("frame"), _("case"), _("why"), _("origin"), "x", "θ", "d", "a", "α"))
        body = []
        for s in self.steps:
            case = _("rule 5") if s.i == 0 else (_("rule 9") if s.case is None else str(s.case))
            why = html.escape(s.why)
            choice = html.escape(_("origin: {origin}; x{i}: {x}").format(origin=s.origin_choice, i=s.i, x=s.x_choice))
            notes = "".join("<br><em>" + html.escape(_("note: {note}").format(note=n)) + "</em>" for n in s.notes)
            row = s.row or ("", "", "", "")
            cells = [str(s.i), case, f"{why}<br><small>{choice}</small>{notes}",
                     html.escape(vector_text(s.origin)), html.escape(vector_text(s.x))] + [html.escape(c) for c in row]
            body.append("<tr>" + "".join(f"<td>{c}</td>" for c in cells) + "</tr>")
        caption = html.escape(self._header())
        foot = html.escape(self._footer())
        return (f"<table><caption>{caption}</caption><thead><tr>{head}</tr></thead>"
                f"<tbody>{''.join(body)}</tbody></table><p><small>{foot}</small></p>")


# --------------------------------------------------------------------------------------
# Numbers as the report writes them
# --------------------------------------------------------------------------------------
def length_text(v: float) -> str:
    """A length as the report prints it (as the DH table does)."""
    return format_length(float(v))


def vector_text(v) -> str:
    """A point or a direction as the report prints it: ``(0, 0.5, 1)``."""
    return "(" + ", ".join(length_text(c) for c in np.asarray(v, dtype=float)) + ")"


def angle_text(angle: float) -> str:
    """An angle (radians) as the report prints it, in degrees: ``90°``."""
    return format_angle(angle)
