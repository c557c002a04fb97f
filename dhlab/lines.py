"""Lines in space: how two lines lie (the three cases of x_i in the DH convention).

A joint axis is a line (*recta*): a point on it and a direction. Two lines in space

* **intersect** (*se cortan*): they meet in one point;
* are **parallel** (*paralelas*): same direction (or opposite), and never meet;
* are **skew** (*se cruzan*): not parallel, and they never meet;
* or **coincide** (*coinciden*): they are the same line.

The *common normal* (*normal común*) of two lines is a line perpendicular to both
that meets both; its length between them is the distance between the lines. Skew
lines have exactly one, intersecting lines one of length 0 (along a × b, through
the intersection), parallel lines infinitely many, all of the same length. For the
joint axes z_{i−1} and z_i these are the cases that place x_i (seed 000, rules 6–8):
case 1 (intersect), case 2 (parallel), case 3 (skew); the common normal's length is
|a_i| of the DH table, the angle between the axes is |α_i|.

>>> z0 = Line((0, 0, 0), (0, 0, 1))
>>> z1 = Line((0.2, 0, 0.5), (0, 1, 0))          # 0.2 to the side, at 90° to z0
>>> relation(z0, z1)
LineRelation(kind='skew', distance=0.2, angle=90, foot=(0.2, 0, 0.5), normal=(1, 0, 0))
>>> relation(z0, Line((1, 0, 0), (0, 0, -1)))    # parallel, pointing the other way
LineRelation(kind='parallel', distance=1, angle=180, foot=(1, 0, 0), normal=(1, 0, 0))
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .errors import DHLabError
from .i18n import _
from .validation import as_float_array, as_number, check_length_size

__all__ = ["Line", "LineRelation", "relation", "closest_points"]


@dataclass(frozen=True, eq=False)
class Line:
    """A directed line: a ``point`` on it and its ``direction``, scaled to length 1.

    The direction may be given with any length; its sense matters only for the
    angle between two lines (0° same sense, 180° opposite sense). Both are stored as
    read-only copies, so a line cannot change after it is made.

    >>> axis = Line((0, 0, 1), (0, 0, 2))
    >>> axis.direction.tolist()
    [0.0, 0.0, 1.0]
    >>> axis.distance_to_point((3, 4, 7))
    5.0
    >>> axis.nearest_point((3, 4, 7)).tolist()
    [0.0, 0.0, 7.0]
    """
    point: np.ndarray
    direction: np.ndarray

    def __post_init__(self):
        point = _vector3(self.point, "Line point", length=True)
        direction = _vector3(self.direction, "Line direction")
        largest = float(np.abs(direction).max())      # divided first: the square of 1e308 overflows
        scaled = direction / largest if largest else direction
        if largest * float(np.linalg.norm(scaled)) < 1e-12:
            raise DHLabError(_("Line direction is {got}: a line needs a non-zero direction vector, e.g. (0, 0, 1) "
                               "for a line along z.").format(got=_short(self.direction)))
        direction = scaled / np.linalg.norm(scaled)
        point.setflags(write=False)
        direction.setflags(write=False)
        object.__setattr__(self, "point", point)
        object.__setattr__(self, "direction", direction)

    def nearest_point(self, p) -> np.ndarray:
        """The point of the line nearest ``p``: the foot of the perpendicular from ``p``."""
        w = _vector3(p, "p", length=True) - self.point
        return self.point + (w @ self.direction) * self.direction

    def distance_to_point(self, p) -> float:
        """The distance from ``p`` to the line (along the perpendicular)."""
        w = _vector3(p, "p", length=True) - self.point
        return float(np.linalg.norm(w - (w @ self.direction) * self.direction))

    def __repr__(self) -> str:
        return f"Line(point={_vec(self.point)}, direction={_vec(self.direction)})"


@dataclass(frozen=True, eq=False)
class LineRelation:
    """How line b lies with respect to line a (the result of :func:`relation`).

    * ``kind``: 'intersect', 'parallel', 'skew' or 'coincident';
    * ``distance``: the length of the common normal (0 up to the tolerance when the
      lines meet);
    * ``angle``: the angle between the *directed* lines, degrees, 0…180 (180: parallel
      but opposite); :attr:`acute` is the angle between the lines as sets, 0…90;
    * ``foot``: the point of b nearest a, where the common normal meets b (for
      intersecting lines, the intersection). Parallel lines are equally near
      everywhere: then it is b's own point;
    * ``normal``: the unit common normal from a towards b; for intersecting lines the
      direction of a × b; None for coincident lines (any direction square to them).
    """
    kind: str
    distance: float
    angle: float
    foot: np.ndarray
    normal: np.ndarray | None

    @property
    def acute(self) -> float:
        """The angle between the lines regardless of their sense, degrees, 0…90."""
        return min(self.angle, 180.0 - self.angle)

    @property
    def is_parallel(self) -> bool:
        """True for parallel and coincident lines."""
        return self.kind in ("parallel", "coincident")

    def __repr__(self) -> str:
        normal = "None" if self.normal is None else _vec(self.normal)
        return (f"LineRelation(kind={self.kind!r}, distance={_num(self.distance)}, angle={_num(self.angle)}, "
                f"foot={_vec(self.foot)}, normal={normal})")


def relation(a, b, tol: float = 1e-9, angle_tol: float = 1e-9) -> LineRelation:
    """How line ``b`` lies with respect to line ``a``: intersect, parallel, skew or coincident.

    ``a``, ``b``: :class:`Line`\\ s, or ``(point, direction)`` pairs. ``tol``: lines whose
    common normal is at most ``tol`` long meet (same unit as the points); ``angle_tol``:
    lines less than ``angle_tol`` radians apart (ignoring their sense) are parallel.
    Raise both for data typed with few digits.

    With c = a × b (unit directions) and w from a's point to b's point: the lines are
    parallel when |c| = sin(angle) is 0, and then the distance is the part of w square
    to a; otherwise the distance is |w · c| / |c|, w's component along the common normal.

    >>> x_axis, y_axis = Line((0, 0, 0), (1, 0, 0)), Line((0, 0, 0), (0, 1, 0))
    >>> relation(x_axis, y_axis)                           # the normal is along x × y = z
    LineRelation(kind='intersect', distance=0, angle=90, foot=(0, 0, 0), normal=(0, 0, 1))
    >>> relation(((0, 0, 0), (0, 0, 1)), ((0, 0, 5), (0, 0, -3)))   # (point, direction) pairs
    LineRelation(kind='coincident', distance=0, angle=180, foot=(0, 0, 5), normal=None)
    >>> tilted = Line((1, 0, 0), (0, 0.001, 1))            # 0.057° off z
    >>> relation(Line((0, 0, 0), (0, 0, 1)), tilted).kind
    'skew'
    >>> relation(Line((0, 0, 0), (0, 0, 1)), tilted, angle_tol=math.radians(0.5)).kind
    'parallel'
    """
    a, b = _as_line(a, "a"), _as_line(b, "b")
    tol, angle_tol = _read_tol(tol, angle_tol)
    u, v = a.direction, b.direction
    c = _cross(u, v)
    sin = float(np.linalg.norm(c))
    angle = math.degrees(math.atan2(sin, float(u @ v)))
    w = b.point - a.point
    if sin == 0.0 or math.atan2(sin, abs(float(u @ v))) < angle_tol:
        perp = w - (w @ u) * u                        # from a to b, square to both
        distance = float(np.linalg.norm(perp))
        if distance <= tol:
            return LineRelation("coincident", distance, angle, b.point.copy(), None)
        return LineRelation("parallel", distance, angle, b.point.copy(), perp / distance + 0.0)
    n = c / sin
    along = float(w @ n)                             # w's component along the common normal
    foot = closest_points(a, b)[1]
    if abs(along) <= tol:
        return LineRelation("intersect", abs(along), angle, foot, n + 0.0)
    return LineRelation("skew", abs(along), angle, foot, math.copysign(1.0, along) * n + 0.0)


def closest_points(a, b) -> tuple:
    """The point of line ``a`` nearest line ``b``, and the point of ``b`` nearest ``a``.

    They are the ends of the common normal (the same point when the lines meet). With
    c = a × b and w from a's point p_a to b's point p_b (unit directions u_a, u_b):

        s = (w × u_b) · c / |c|²,   t = (w × u_a) · c / |c|²,
        points p_a + s u_a and p_b + t u_b.

    This form stays accurate for nearly parallel lines, where the textbook form with
    1 − (u_a · u_b)² in the denominator loses every digit. Exactly parallel lines are
    equally near everywhere: then the pair through b's point is returned.

    >>> ca, cb = closest_points(Line((0, 0, 0), (0, 0, 1)), Line((0.2, 0, 0.5), (0, 1, 0)))
    >>> ca.tolist(), cb.tolist()
    ([0.0, 0.0, 0.5], [0.2, 0.0, 0.5])
    """
    a, b = _as_line(a, "a"), _as_line(b, "b")
    u, v = a.direction, b.direction
    c = _cross(u, v)
    cc = float(c @ c)
    if cc == 0.0:
        return a.nearest_point(b.point), b.point.copy()
    w = b.point - a.point
    s = (_cross(w, v) @ c) / cc
    t = (_cross(w, u) @ c) / cc
    return a.point + s * u, b.point + t * v


# --------------------------------------------------------------------------------------
# Small helpers
# --------------------------------------------------------------------------------------
def _as_line(x, name: str) -> Line:
    """A :class:`Line` from a Line or a (point, direction) pair, or a DHLabError."""
    if isinstance(x, Line):
        return x
    if (isinstance(x, (str, bytes)) or (isinstance(x, np.ndarray) and x.ndim == 0)   # 0-d: len() fails
            or not hasattr(x, "__len__") or len(x) != 2):
        raise DHLabError(_("line {name} must be a dhlab.lines.Line or a (point, direction) pair, "
                           "e.g. ((0, 0, 0), (0, 0, 1)); got {got}.").format(name=name, got=_short(x)))
    return Line(*x)


def _read_tol(tol, angle_tol) -> tuple:
    values = []
    for name, value, upper, hint in (("tol", tol, math.inf, _("a length, e.g. 1e-9")),
                                     ("angle_tol", angle_tol, math.pi / 2, _("radians, e.g. 1e-9"))):
        try:
            number = as_number(value, name)       # refuses text ('1e-9') and True, as float() does not
        except DHLabError:
            number = math.nan
        if not 0 <= number < upper:
            message = (_("{name} must be a number ≥ 0 ({hint}, below π/2), got {got}.") if upper < math.inf else
                       _("{name} must be a number ≥ 0 ({hint}), got {got}."))
            raise DHLabError(message.format(name=name, hint=hint, got=_short(value)))
        values.append(number)
    return tuple(values)


def _vector3(value, name: str, length: bool = False) -> np.ndarray:
    """A copy of ``value`` as 3 finite floats, or a DHLabError naming ``name``; with ``length``
    (a point) each coordinate at most LARGEST_LENGTH, so that distances stay finite."""
    arr = np.array(as_float_array(value, name), dtype=float)
    if arr.shape != (3,):
        raise DHLabError(_("{name} must be 3 numbers (x, y, z), got shape {shape}: {got}.").format(
            name=name, shape=arr.shape, got=_short(value)))
    if not np.isfinite(arr).all():
        raise DHLabError(_("{name} is {values}: every coordinate must be a finite number.").format(
            name=name, values=arr.tolist()))
    if length:
        check_length_size(float(np.abs(arr).max()), name)
    return arr


def _cross(a, b) -> np.ndarray:
    """a × b for 3-vectors (numpy's general cross is slow on single vectors)."""
    return np.array([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]])


def _num(x: float) -> str:
    """A number for a repr: 12 significant digits, no -0."""
    text = f"{float(x) + 0.0:.12g}"
    return "0" if text == "-0" else text


def _vec(v) -> str:
    return "(" + ", ".join(_num(x) for x in v) + ")"


def _short(x) -> str:
    text = repr(x)
    return text if len(text) <= 60 else text[:57] + "..."
