"""Placing the DH frames 0 … n at the given pose, one after the other (rules 4–9 of seeds
002/003), with the report of each: frame 0 on z0 (rule 5), frame i by the relation of
z_{i−1} and z_i (rules 6–8: intersecting, parallel, skew), frame n at the end effector
(rule 9).

Part of :mod:`dhlab.dh_frames` (import from there).

>>> _frame(np.zeros(3), np.array([1.0, 0, 0.5]), np.array([0.0, 0, 1])).tolist()[0]
[1.0, 0.0, 0.0, 0.0]
"""
from __future__ import annotations

import math

import numpy as np

from ..i18n import _
from ..lines import Line, relation
from .report import FrameStep, angle_text, length_text

__all__ = ["NEARLY"]

NEARLY = 1e-4          # relations this close to the tolerance get a warning note


class Placer:
    """Frames 0 … n at the given pose, one after the other, with the report of each."""

    def __init__(self, lines, tool_pose, tool_point, rel, tol, sign_rule, case1, parallel, prismatic):
        self.given = lines
        self.lines = [None] * len(lines)          # the axis lines actually used (dhlab.lines.Line)
        self.tool_pose, self.tool_point = tool_pose, tool_point
        self.rel, self.tol, self.scale = rel, tol, tol / rel
        self.sign_rule, self.case1 = sign_rule, case1
        self.parallel, self.prismatic = parallel, prismatic

    def place(self):
        n = len(self.given)
        self._fix_line(0, np.zeros(3))
        frames, steps = [], []
        F, step = self._frame0()
        frames.append(F), steps.append(step)
        for i in range(1, n):
            self._fix_line(i, frames[i - 1][:3, 3])
            F, step = self._frame(i, frames[i - 1])
            frames.append(F), steps.append(step)
        F, step = self._frame_n(n, frames[n - 1])
        frames.append(F), steps.append(step)
        for j, (_point, _direction, kind) in enumerate(self.given):
            if kind == "P":
                steps[j].notes.append(self._prismatic_note(j))
        return frames, steps

    # --- the axis lines: prismatic ones may be moved (only their direction matters) ---
    def _fix_line(self, j, previous_origin):
        """Line of joint j+1 (= z_j): as given, or for a prismatic joint through ``previous_origin``."""
        p, u, kind = self.given[j]
        if kind == "P" and self.prismatic == "through_origin":
            p = previous_origin
        self.lines[j] = Line(p, u)

    def _prismatic_note(self, j) -> str:
        where = (_("the previous origin") if j else _("the world origin")) + " (prismatic='through_origin')"
        if self.prismatic == "given":
            where = _("the given point") + " (prismatic='given')"
        return _("joint {joint} is prismatic: its direction is fixed (the sliding sense), but the line z{j} may lie "
                 "anywhere (seed 002 note 002-n2); it was put through {where}").format(joint=j + 1, j=j, where=where)

    # --- rule 5 -------------------------------------------------------------------
    def _frame0(self):
        z = self.lines[0].direction
        origin = self.lines[0].nearest_point(np.zeros(3))
        world_x = np.array([1.0, 0.0, 0.0])
        x = world_x - (world_x @ z) * z
        x_choice = _("the world x axis, made perpendicular to z0")
        if np.linalg.norm(x) < 1e-6:                  # z0 along world x
            world_y = np.array([0.0, 1.0, 0.0])
            x = world_y - (world_y @ z) * z
            x_choice = _("z0 is along the world x axis, so the world y axis, made perpendicular to z0")
        x = _unit(x)
        why = _("z0 on joint 1's axis (rule 4); origin and x0 are free (rule 5)")
        step = FrameStep(0, "5", None, None, why, _("the point of z0 nearest the world origin"),
                         x_choice + " (y0 = z0 × x0)", origin, x, z)
        return _frame(origin, x, z), step

    # --- rules 6–8 --------------------------------------------------------------------
    def _frame(self, i, F_prev):
        """Frame i from z_{i−1} (joint i's line) and z_i (joint i+1's line)."""
        a, b = self.lines[i - 1], self.lines[i]
        O_prev, x_prev = F_prev[:3, 3], F_prev[:3, 0]
        rel = relation(a, b, tol=self.tol, angle_tol=self.rel)
        kind = "intersecting" if rel.kind == "intersect" else rel.kind     # the report's word
        dist, angle = rel.distance, math.radians(rel.acute)                # lines have no sense here
        za, zb = f"z{i - 1}", f"z{i}"
        notes = []
        if kind in ("intersecting", "skew"):
            origin = rel.foot                         # the point of z_i nearest z_{i-1}
            if kind == "intersecting":
                case = 1
                x, x_choice = self._case1_x(i, rel.normal, x_prev)
                why = _("{za} and {zb} intersect (at {angle}): x{i} is perpendicular to both").format(
                    za=za, zb=zb, angle=angle_text(angle), i=i)
                origin_choice = _("the intersection (rule 6)")
            else:
                case = 3
                x = rel.normal                        # from z_{i-1} towards z_i
                why = _("{za} and {zb} are skew ({angle} apart, distance {distance}): they have one common "
                        "normal").format(za=za, zb=zb, angle=angle_text(angle), distance=length_text(dist))
                origin_choice = _("where the common normal meets {zb} (rule 6)").format(zb=zb)
                x_choice = _("along the common normal, from {za} towards {zb} (a{i} > 0)").format(za=za, zb=zb, i=i)
                if dist < NEARLY * self.scale:
                    notes.append(_("the axes nearly intersect (distance {distance}): if they should, pass a larger "
                                   "tol").format(distance=f"{dist:.2g}"))
            if angle < NEARLY:
                notes.append(_("the axes are nearly parallel ({angle} rad): the common normal lies far away; if they "
                               "should be parallel, pass a larger tol").format(angle=f"{angle:.2g}"))
        else:
            case = 2
            origin, origin_choice = self._parallel_origin(i, b, O_prev)
            antiparallel = rel.angle > 90
            sense = " " + _("(opposite directions, so α = 180°)") if antiparallel else ""
            if kind == "parallel":
                x = _unit(origin - a.nearest_point(origin))
                why = _("{za} ∥ {zb}{sense}, {distance} apart: infinitely many common normals, one is chosen").format(
                    za=za, zb=zb, sense=sense, distance=length_text(dist))
                x_choice = _("along that common normal, from {za} towards {zb} (a{i} > 0)").format(za=za, zb=zb, i=i)
            else:
                x = x_prev
                why = _("{za} and {zb} are the same line{sense}: a{i} = 0, and x{i} and O{i} are free").format(
                    za=za, zb=zb, sense=sense, i=i)
                x_choice = _("x{i} = x{previous} (no turn about {za}: θ{i} offset 0)").format(
                    i=i, previous=i - 1, za=za)
        step = FrameStep(i, "6-8", case, kind, why, origin_choice, x_choice, origin, x, b.direction, notes=notes)
        return _frame(origin, x, b.direction), step

    def _case1_x(self, i, cross, x_prev):
        """x_i for intersecting axes, from the unit ``cross`` = z_{i−1} × z_i / |…|."""
        if self.sign_rule > 0:
            return cross, f"x{i} = z{i - 1} × z{i} (case1='z_prev x z': 0° < α{i} < 180°)"
        if self.sign_rule < 0:
            return -cross, f"x{i} = z{i} × z{i - 1} (case1='z x z_prev', seed 000: -180° < α{i} < 0°)"
        if cross @ x_prev < -1e-9:
            return -cross, _("x{i} = z{i} × z{previous}, the sign nearest x{previous} (case1='nearest')").format(
                i=i, previous=i - 1)
        return cross, _("x{i} = z{previous} × z{i}, the sign nearest x{previous} (case1='nearest')").format(
            i=i, previous=i - 1)

    def _parallel_origin(self, i, b, O_prev):
        if self.parallel == "at_joint":
            origin = b.nearest_point(self.given[i][0])
            return origin, _("joint {joint}'s given point (parallel='at_joint', seed rule 6)").format(joint=i + 1)
        origin = b.nearest_point(O_prev)
        return origin, _("the foot of the normal from O{previous} (parallel='zero_d': d{i} = 0)").format(
            previous=i - 1, i=i)

    # --- rule 9 ---------------------------------------------------------------------------
    def _frame_n(self, n, F_prev):
        line, point = self.lines[n - 1], self.tool_point
        z, foot = line.direction, line.nearest_point(point)
        dist = line.distance_to_point(point)
        za = f"z{n - 1}"
        if dist > self.tol:
            kind, origin, x = "parallel", point, _unit(point - foot)
            why = _("z{n} along {za} (rule 9), through the end effector, {distance} from {za}").format(
                n=n, za=za, distance=length_text(dist))
            x_choice = _("from {za} towards the end effector (a{n} > 0)").format(za=za, n=n)
        else:
            kind, origin = "coincident", foot
            why = _("z{n} along {za} (rule 9); the end effector is on {za}, so x{n} is free").format(n=n, za=za)
            x, x_choice = F_prev[:3, 0], _("x{n} = x{previous} (θ{n} offset 0)").format(n=n, previous=n - 1)
            if self.tool_pose is not None:
                xt = self.tool_pose[:3, 0] - (self.tool_pose[:3, 0] @ z) * z
                if np.linalg.norm(xt) > 1e-6:
                    x, x_choice = _unit(xt), _("the tool's x axis (made perpendicular to z{n})").format(n=n)
        origin_choice = _("the end effector's point (rule 9)")
        step = FrameStep(n, "9", None, kind, why, origin_choice, x_choice, origin, x, z)
        return _frame(origin, x, z), step


def _frame(origin, x, z) -> np.ndarray:
    """The 4x4 frame with this origin, z, and x made exactly perpendicular to z."""
    x = _unit(x - (x @ z) * z)
    F = np.eye(4)
    F[:3, 0], F[:3, 1], F[:3, 2], F[:3, 3] = x, cross(z, x), z, origin
    return F


# --------------------------------------------------------------------------------------
# Small helpers
# --------------------------------------------------------------------------------------
def cross(a, b) -> np.ndarray:
    """a × b for 3-vectors (numpy's general cross is slow on single vectors)."""
    return np.array([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]])


def _unit(v) -> np.ndarray:
    return v / np.linalg.norm(v)
