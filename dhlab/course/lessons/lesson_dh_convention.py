"""The helpers of notebook 5 (the Denavit–Hartenberg convention), kept out of the lesson's cells.

The notebook's cells stay short and about the rules; what they need only to print, to set up an
example or to measure lives here:

* :func:`fmt`: a vector printed as ``(x, y, z)``, rounded, without ``-0``;
* :func:`three_cases`: the three example lines of section 1 (rule 7: intersect, parallel, skew);
* :func:`place_x`: rule 7 on two axes z_(i−1), z_i: which case, the common normal, x_i and O_i
  (:func:`dhlab.lines.relation` finds how the two lines lie);
* :func:`measured_row`: the row (θ, d, a, α) between two frames, by seed 002's definitions
  (measurements between the axes), with no matrix of rule 14;
* :func:`measured_rows_agree`: those measurements against a robot's link matrices A_i;
* :func:`prismatic_a_lines`: seed 002's two sentences for a_i at a prismatic joint, side by side.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...dh import DHRobot
from ...errors import DHLabError
from ...i18n import N_, _
from ...lines import Line, closest_points, relation
from ...transforms import check_rigid, dh_matrix
from ...validation import as_float_array
from . import printing

__all__ = ["fmt", "three_cases", "XPlacement", "place_x", "measured_row", "measured_rows_agree",
           "prismatic_a_lines"]

CASES = {"intersect": 1, "parallel": 2, "skew": 3}       # rule 7's three cases, as seed 000 numbers them


def fmt(v, digits: int = 6) -> str:
    """A vector as ``(x, y, z)``, rounded to ``digits`` decimals, trailing zeros and ``-0`` dropped
    (notebooks 5 and 6; see :func:`dhlab.course.lessons.printing.fmt`)."""
    return printing.fmt(v, digits, trim=True)


def three_cases():
    """Section 1's example: z_(i−1) (the vertical line through the origin) and three lines z_i,
    one per case of rule 7. Returns ``(z_prev, {name: z_i})``, each line a (point, direction) pair."""
    z_prev = (np.zeros(3), np.array([0.0, 0.0, 1.0]))
    examples = {
        N_("case 1"): (np.array([0.0, 0.0, 1.0]), np.array([0.0, 1.0, 0.0])),   # meets z_prev at (0, 0, 1)
        N_("case 2"): (np.array([1.0, 0.0, 0.5]), np.array([0.0, 0.0, 1.0])),   # vertical, 1 away
        N_("case 3"): (np.array([1.0, 0.0, 0.5]), np.array([0.0, 1.0, 0.0])),   # horizontal, 1 away: skew
    }
    return z_prev, examples


@dataclass(frozen=True)
class XPlacement:
    """Where rule 7 puts x_i: ``kind`` of the two axes, ``case`` (1, 2, 3), the common normal from
    ``H`` (on z_(i−1)) to ``origin`` O_i (on z_i), its ``length``, and the unit vector ``x``."""
    kind: str
    case: int
    H: np.ndarray
    origin: np.ndarray
    length: float
    x: np.ndarray

    def __str__(self) -> str:
        text = _("{kind:9s}  common normal from {H} to {origin}, length {length:g};  x_i = {x},  O_i = {origin}")
        return text.format(kind=_(self.kind), H=fmt(self.H), origin=fmt(self.origin), length=self.length,
                           x=fmt(self.x))


def place_x(z_prev, z_i) -> XPlacement:
    """Rule 7 for the axes ``z_prev`` = z_(i−1) and ``z_i`` (each a :class:`Line` or (point, direction)).

    Case 1 (they intersect): the normal has length 0, so x_i = z_(i−1) × z_i (the other sign is
    as good) and O_i is the intersection. Case 2 (parallel): every perpendicular segment is a
    common normal; we take the one through z_i's given point. Case 3 (skew): the unique common
    normal. In cases 2 and 3, x_i points along the normal from z_(i−1) towards z_i.
    """
    rel = relation(z_prev, z_i)                         # checks both lines (a clear error if one is not)
    a = z_prev if isinstance(z_prev, Line) else Line(*z_prev)
    if rel.kind == "coincident":
        raise DHLabError(_("place_x: z_(i-1) and z_i are the same line, so they have no common normal and none "
                           "of rule 7's three cases applies. Any x_i perpendicular to that line will do: choose "
                           "one (seed 002's free choices), or give two different lines."))
    origin = rel.foot                                   # on z_i, where the common normal meets it
    H = a.nearest_point(origin)                         # the normal's other end, on z_(i-1)
    return XPlacement(rel.kind, CASES[rel.kind], H, origin, rel.distance, rel.normal)


def measured_row(S_prev, S_next):
    """(θ, d, a, α) between frames {S_(i−1)} = ``S_prev`` and {S_i} = ``S_next`` (4×4, in the world),
    measured by seed 002's four sentences, radians and lengths:

    * θ: the angle from x_(i−1) to x_i, seen along z_(i−1) (right-hand rule about z_(i−1));
    * d: along z_(i−1), from O_(i−1) to H, the point where the line of x_i crosses z_(i−1);
    * a: along x_i, from H to O_i;
    * α: the angle from z_(i−1) to z_i, seen along x_i (right-hand rule about x_i).
    """
    S_prev, S_next = check_rigid(S_prev, "measured_row: S_prev"), check_rigid(S_next, "measured_row: S_next")
    O0, x0, z0 = S_prev[:3, 3], S_prev[:3, 0], S_prev[:3, 2]
    O1, x1, z1 = S_next[:3, 3], S_next[:3, 0], S_next[:3, 2]
    theta = np.arctan2(np.cross(x0, x1) @ z0, x0 @ x1)      # from x_(i-1) to x_i, seen along z_(i-1)
    alpha = np.arctan2(np.cross(z0, z1) @ x1, z0 @ z1)      # from z_(i-1) to z_i, seen along x_i
    if abs(x1 @ z0) > 1e-6:
        raise DHLabError(_("measured_row: x_i is not perpendicular to z_(i-1), so these two frames are not "
                           "consecutive DH frames (rule 7 puts x_i on the common normal). Place them by rules "
                           "1-9."))
    H, H_on_x = closest_points(Line(O0, z0), Line(O1, x1))  # where the line of x_i crosses z_(i-1)
    if not np.allclose(H, H_on_x, atol=1e-9):
        raise DHLabError(_("measured_row: the line of x_i misses z_(i-1) by {gap:.3g}, so these two frames are "
                           "not consecutive DH frames. Place them by rules 1-9.").format(
                               gap=np.linalg.norm(H - H_on_x)))
    d = (H - O0) @ z0                                        # along z_(i-1), from O_(i-1) to H
    a = (O1 - H) @ x1                                        # along x_i, from H to O_i
    return float(theta), float(d) + 0.0, float(a) + 0.0, float(alpha)


def measured_rows_agree(robot: DHRobot, configurations) -> bool:
    """True when, at every configuration, every link's measured row gives back the robot's A_i."""
    if not isinstance(robot, DHRobot):
        raise DHLabError(_("measured_rows_agree: robot must be a dhlab DHRobot (for instance "
                           "dhlab.robots.seed002_6dof())."))
    Q = np.atleast_2d(as_float_array(configurations, "configurations", finite=True))
    if Q.ndim != 2 or Q.shape[1] != robot.n:
        raise DHLabError(_("measured_rows_agree: configurations must be rows of {n} joint values (one per joint "
                           "of {robot}), got shape {shape}.").format(n=robot.n, robot=robot.name, shape=Q.shape))
    for q in Q:
        F = robot.frames(q)
        for i in range(1, robot.n + 1):
            if not np.allclose(dh_matrix(*measured_row(F[i - 1], F[i])), robot.A(i, q[i - 1]), atol=1e-9):
                return False
    return True


def prismatic_a_lines(robot: DHRobot, configurations) -> list[str]:
    """Seed 002's two sentences for a_i at each prismatic joint of ``robot``: along x_i from H_i to
    O_i (signed), and the shortest distance between z_(i−1) and z_i (a length). One line each."""
    if not isinstance(robot, DHRobot):
        raise DHLabError(_("prismatic_a_lines: robot must be a dhlab DHRobot."))
    prismatic = [i for i in range(1, robot.n + 1) if robot.links[i - 1].is_prismatic]
    out = []
    for q in configurations:
        F = robot.frames(q)
        for i in prismatic:
            along_x = measured_row(F[i - 1], F[i])[2]                       # first sentence
            between = relation(Line(F[i - 1][:3, 3], F[i - 1][:3, 2]), Line(F[i][:3, 3], F[i][:3, 2])).distance
            out.append(_("q = {q}, joint {i} (P): a{i} along x{i} = {along_x:+.4f}, shortest distance between "
                         "z{p} and z{i} = {between:.4f}").format(q=fmt(q, 2), i=i, p=i - 1, along_x=along_x,
                                                                  between=between))
    return out
