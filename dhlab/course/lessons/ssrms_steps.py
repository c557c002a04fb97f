"""Seed 000's method on the SSRMS, step by step (notebook 7): "Paso 0" … "Paso 3".

* **Paso 0**: count the joints (*articulaciones*) A_1 … A_n and the links (*eslabones*) 0 … n;
* **Paso 1**: put each z_i on the axis of joint A_(i+1) (:func:`z_axes`);
* **Paso 2**: the case of each x_i from how z_(i−1) and z_i lie (intersect / parallel / skew), x_i along
  their common normal, and the origin B_i where that normal meets A_(i+1) (:func:`x_steps`);
* **Paso 3**: y_i = z_i × x_i, which completes each frame B_i (:func:`frames_b`).

The frames are placed by the course's frame-assignment helper (:func:`dhlab.dh_frames.dh_assignment`, notebook 5)
with seed 000's sign for case 1, x_i = z_i × z_(i−1); this module only reads off what each step needs.

>>> [s.case for s in x_steps()]                 # x1 … x6 of the SSRMS: the seed's figure 8
[1, 1, 2, 2, 1, 1]
>>> x_steps()[2].foot.tolist(), x_steps()[2].origin.tolist()     # x3's common normal, from z2 to B3
([0.0, 6.0, -3.5], [12.0, 6.0, -3.5])
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ... import robots
from ...dh_frames import dh_assignment, joint_axes
from ...i18n import N_, _
from ...lines import Line
from ..exercises.dh_common import as_robot

__all__ = ["CASE_NAMES", "case_name", "XStep", "z_axes", "x_steps", "frames_b", "assignment"]

# Paso 2's three cases (English here, for the catalog; shown translated by case_name)
CASE_NAMES = {1: N_("case 1: the axes intersect"), 2: N_("case 2: the axes are parallel"),
              3: N_("case 3: the axes are skew")}


def case_name(case: int) -> str:
    """Paso 2's case ``case`` (1, 2, 3) in words, in the course's language."""
    return _(CASE_NAMES[case])


@dataclass(frozen=True)
class XStep:
    """Paso 2 for x_i: the ``case`` (1, 2, 3), the ``relation`` of z_(i−1) and z_i ('intersecting',
    'parallel', 'skew'), the common normal from ``foot`` (on z_(i−1)) to ``origin`` (B_i, on z_i, the
    axis of A_(i+1)), and the direction ``x`` of x_i (all at θ = 0, in the base frame)."""
    i: int
    case: int
    relation: str
    foot: np.ndarray
    origin: np.ndarray
    x: np.ndarray

    @property
    def length(self) -> float:
        """The common normal's length between the two axes: |a_i| of the table."""
        return float(np.linalg.norm(self.origin - self.foot))

    def __str__(self):
        """One line of Paso 2, in the course's language (``print(step)``)."""
        relation = _(_RELATIONS.get(self.relation, self.relation))
        return _("x{i}: case {case}, {relation}, normal from {foot} to B{i} = {origin}, length {length:g}, "
                 "x{i} = {x}").format(i=self.i, case=self.case, relation=relation, foot=_point(self.foot),
                                      origin=_point(self.origin), length=self.length, x=_point(self.x))


_RELATIONS = {"intersecting": N_("intersecting"), "parallel": N_("parallel"), "skew": N_("skew")}


def _point(v) -> str:
    """(0, 6, -3.5): a point or direction, short (rounding noise shown as 0)."""
    return "(" + ", ".join(f"{round(float(c), 9) + 0.0:g}" for c in v) + ")"


def assignment(robot=None):
    """The frames placed by the rules on ``robot``'s joint axes at θ = 0 (default: the SSRMS), with seed
    000's sign for case 1: the report of :func:`dhlab.dh_frames.dh_assignment`."""
    robot = robots.ssrms() if robot is None else as_robot(robot)
    return dh_assignment(*joint_axes(robot), case1="z x z_prev")


def z_axes(robot=None) -> list:
    """Paso 1: the line of z_0 … z_(n−1), i.e. the axis of joint A_1 … A_n, at θ = 0 (list of
    :class:`~dhlab.lines.Line`, each through the origin B_i of its frame)."""
    frames = assignment(robot).frames
    return [Line(F[:3, 3], F[:3, 2]) for F in frames[:-1]]


def x_steps(robot=None) -> list:
    """Paso 2: one :class:`XStep` for each x_1 … x_(n−1)."""
    report = assignment(robot)
    steps = []
    for step in report.steps[1:-1]:
        previous = report.frames[step.i - 1]
        axis = Line(previous[:3, 3], previous[:3, 2])          # z_(i-1)
        foot = axis.nearest_point(step.origin)                 # where the normal leaves z_(i-1)
        steps.append(XStep(step.i, step.case, step.relation, foot.round(12) + 0.0,
                           np.asarray(step.origin, dtype=float).round(12) + 0.0,
                           np.asarray(step.x, dtype=float).round(12) + 0.0))
    return steps


def frames_b(robot=None) -> np.ndarray:
    """Paso 3: the frames B_0 … B_n at θ = 0, (n+1, 4, 4); column 1 of each is y_i = z_i × x_i."""
    return np.asarray(assignment(robot).frames, dtype=float)
