"""The valid DH frames of each link of an assignment robot, and how near a frame is to them.

DH frames are not unique: z_i may point either way along its axis, x_i either way along the
common normal, an origin may slide along parallel axes, x_i may turn about coincident ones,
and a prismatic joint's axis may be drawn on any line parallel to it. :func:`frame_family`
describes every valid frame k of a robot at its home pose (a :class:`FrameFamily`); the
checks place a student's frame against it (:func:`nearest_valid_frame`, :func:`is_valid_frame`,
:func:`fit_link`). The robot is a :class:`dhlab.assignment.reference.Reference` (the PUMA 560) or an
:class:`~dhlab.assignment.model.AssignmentRobot`; the tolerances are the grader's
(:data:`dhlab.assignment.reference.TOL_POS`, :data:`~dhlab.assignment.reference.TOL_DEG`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from . import model
from .reference import TOL_DEG, TOL_POS, Reference, cache_of, reference, relation, row_matrix

__all__ = ["FrameFamily", "frame_family", "nearest_valid_frame", "valid_frames_near", "is_valid_frame",
           "fit_link", "random_family_frames", "dh_rows_from_frames"]


@dataclass
class FrameFamily:
    """Every valid DH frame k at home: ``Tr(v) · base · Rz(φ) · Tr(s, 0, t)`` for each base in
    ``bases``, with φ free when ``spin``, t free when ``shift``, s free when ``slide_x`` and
    v free in the span of the world directions ``slides`` (else all 0).

    ``slide_x`` and ``slides`` come with a prismatic joint: only the direction of a sliding
    joint's axis is fixed, so the student places its line (z of the frame before it)."""
    bases: list
    spin: bool
    shift: bool
    slide_x: bool = False
    slides: tuple = ()

    @property
    def loose(self) -> bool:
        """Whether the origin may move off the line(s) of the revolute case."""
        return self.slide_x or bool(self.slides)


def _frame(origin, x, z) -> np.ndarray:
    F = np.eye(4)
    F[:3, 0], F[:3, 2] = x, z
    F[:3, 1] = np.cross(z, x)
    F[:3, 3] = origin
    return F


def _any_perpendicular(z) -> np.ndarray:
    helper = np.array([1.0, 0, 0]) if abs(z[0]) < 0.9 else np.array([0, 1.0, 0])
    x = helper - (helper @ z) * z
    return x / np.linalg.norm(x)


def frame_family(ref: Reference, k: int) -> FrameFamily:
    """The valid DH frames of link k (computed once per reference robot)."""
    families = cache_of(ref).setdefault("frame families", {})
    if k not in families:
        families[k] = _frame_family(ref, k)
    return families[k]


def _frame_family(ref: Reference, k: int) -> FrameFamily:
    """The valid DH frames for link k at the home pose.

    Frame 0 is the pictured world frame (fixed). For 1 ≤ k < n: z_k along the axis
    of joint k+1 (either sense), x_k along the common normal of the axes of joints k
    and k+1 (either sense), origin where x_k meets z_k; when the axes are parallel the
    origin may slide along z_k; when they coincide x_k may also turn. Frame n: origin
    at the wrist centre, z_n along the axis of joint n, x_n free about it. Next to a
    prismatic joint, see :func:`_sliding_family`.
    """
    n = ref.n
    if k == 0:
        return FrameFamily([np.eye(4)], False, False)
    if k == n:
        w = ref.axes[n - 1].direction
        x = _any_perpendicular(w)
        return FrameFamily([_frame(ref.wrist_centre, x, w), _frame(ref.wrist_centre, x, -w)], True, False)
    rel = relation(ref.axes[k - 1], ref.axes[k])
    if "P" in ref.kinds[k - 1:k + 1]:
        return _sliding_family(ref, k, rel)
    w = ref.axes[k].direction
    bases = []
    for sz in (1, -1):
        if rel.normal is None:                       # coincident axes
            bases.append(_frame(rel.foot, _any_perpendicular(w), sz * w))
            continue
        for sx in (1, -1):
            bases.append(_frame(rel.foot, sx * rel.normal, sz * w))
    return FrameFamily(bases, spin=rel.normal is None, shift=rel.kind in ("parallel", "coincident"))


def _sliding_family(ref: Reference, k: int, rel) -> FrameFamily:
    """Frame k when joint k or joint k+1 slides (1 ≤ k < n).

    A prismatic joint's axis is a direction: the DH convention lets its line be drawn
    anywhere parallel to it. So when joint k+1 slides, z_k is any line along its
    direction; when joint k slides, z_{k-1} is, and x_k (the common normal from z_{k-1}
    to z_k) follows it. Whatever the lines, z_k keeps its direction, x_k stays square to
    the directions of both axes, and x_k still crosses the axis of a revolute joint k:

    * joint k+1 slides, joint k turns: the origin lies on a line that crosses the axis of
      joint k square to both directions (``slides``: that normal and joint k's direction);
      parallel axes: x_k points away from joint k's axis, any way round it (``spin``,
      ``slide_x``, ``shift``);
    * joint k slides, joint k+1 turns: the origin anywhere on the axis of joint k+1
      (``shift``), x_k along the normal of the two directions, or any way round when
      they are parallel (``spin``);
    * both slide: the origin anywhere.
    """
    prev_slides, this_slides = ref.kinds[k - 1] == "P", ref.kinds[k] == "P"
    a, b = ref.axes[k - 1], ref.axes[k]
    w = b.direction
    everywhere = tuple(np.eye(3))
    if rel.is_parallel:
        origin = a.nearest_point(b.point) if this_slides and not prev_slides else b.point
        x = _any_perpendicular(w)
        bases = [_frame(origin, x, w), _frame(origin, x, -w)]
        if prev_slides and this_slides:
            return FrameFamily(bases, True, False, slides=everywhere)
        return FrameFamily(bases, True, True, slide_x=this_slides)
    normal = np.cross(a.direction, w)
    normal = normal / np.linalg.norm(normal)
    if this_slides and not prev_slides:
        origin, slides, shift = a.nearest_point(rel.foot), (normal, a.direction), False
    else:
        origin, slides, shift = b.point, (everywhere if this_slides else ()), not this_slides
    bases = [_frame(origin, sx * normal, sz * w) for sz in (1, -1) for sx in (1, -1)]
    return FrameFamily(bases, False, shift, slides=slides)


def _member(base, phi, t):
    c, s = math.cos(phi), math.sin(phi)
    M = np.array([[c, -s, 0, 0], [s, c, 0, 0], [0, 0, 1, t], [0, 0, 0, 1.0]])
    return base @ M


def _free_directions(family: FrameFamily, R) -> np.ndarray:
    """The directions (world, columns) the origin may move along, for a frame turned R."""
    dirs = list(family.slides) + ([R[:, 2]] if family.shift else []) + ([R[:, 0]] if family.slide_x else [])
    return np.array(dirs, float).T if dirs else np.zeros((3, 0))


def _loose_member(family: FrameFamily, base, phi, offset) -> tuple:
    """The member of a loose family turned φ from ``base`` whose origin is nearest
    ``base``'s origin + ``offset``: (frame, the offset left over)."""
    c, s_ = math.cos(phi), math.sin(phi)
    R = base[:3, :3] @ np.array([[c, -s_, 0], [s_, c, 0], [0, 0, 1.0]])
    D = _free_directions(family, R)
    move = D @ np.linalg.lstsq(D, offset, rcond=None)[0] if D.shape[1] else np.zeros(3)
    F = np.eye(4)
    F[:3, :3], F[:3, 3] = R, base[:3, 3] + move
    return F, offset - move


def nearest_valid_frame(ref: Reference, k: int, F) -> tuple:
    """The valid DH frame k nearest to ``F`` (home pose): (frame, angle°, distance m)."""
    angle, dist, build = min(_near(ref, k, F), key=lambda m: math.radians(m[0]) + m[1] / 0.1)
    return build(), angle, dist


def valid_frames_near(ref: Reference, k: int, F) -> list:
    """For each base of frame k's family (each sense of z and x), its member nearest to
    ``F``: [(frame, angle°, distance m)], the nearest first."""
    near = sorted(_near(ref, k, F), key=lambda m: math.radians(m[0]) + m[1] / 0.1)
    return [(build(), angle, dist) for angle, dist, build in near]


def _near(ref: Reference, k: int, F) -> list:
    """Per base: (angle°, distance m, a function that builds the member). Worked in the base
    frame's coordinates (a rigid motion keeps angles and distances), so that only the
    members asked for are built as matrices."""
    family = frame_family(ref, k)
    F = np.asarray(F, float)
    out = []
    for base in family.bases:
        Rb, ob = base[:3, :3], base[:3, 3]
        L = (Rb.T @ F[:3, :3]).tolist()
        o = (Rb.T @ (F[:3, 3] - ob)).tolist()
        phi = math.atan2(L[1][0], L[0][0]) if family.spin else 0.0
        c, s_ = math.cos(phi), math.sin(phi)
        trace = c * (L[0][0] + L[1][1]) + s_ * (L[1][0] - L[0][1]) + L[2][2]
        angle = math.degrees(math.acos(max(-1.0, min(1.0, (trace - 1) / 2))))
        if family.loose:
            member, left = _loose_member(family, base, phi, F[:3, 3] - ob)
            out.append((angle, float(np.linalg.norm(left)), lambda member=member: member))
        else:
            t = o[2] if family.shift else 0.0
            out.append((angle, math.sqrt(o[0] ** 2 + o[1] ** 2 + (o[2] - t) ** 2),
                        lambda base=base, phi=phi, t=t: _member(base, phi, t)))
    return out


def is_valid_frame(ref: Reference, k: int, F) -> bool:
    """Whether ``F`` is a valid DH frame k, within the grader's tolerances."""
    _, angle, dist = nearest_valid_frame(ref, k, F)
    return angle <= TOL_DEG and dist <= TOL_POS


def fit_link(ref: Reference, k: int, local_points, world=None) -> tuple:
    """The valid DH frame k in which ``local_points`` land best on link k's points
    (or on the points ``world``: part 2 also asks which valid frame j carries a later
    link's points, given in frame j, onto that link).

    Returns (frame, worst point distance in metres).
    """
    family = frame_family(ref, k)
    P = np.asarray(local_points, float)
    W = ref.world_points(k) if world is None else np.asarray(world, float)
    if family.loose:
        return min((_fit_loose(family, base, P, W) for base in family.bases), key=lambda fit: fit[1])
    best = None
    for base in family.bases:
        U = (W - base[:3, 3]) @ base[:3, :3]            # the world points in the base frame
        phi = 0.0
        if family.spin:
            num = float(np.sum(P[:, 0] * U[:, 1] - P[:, 1] * U[:, 0]))
            den = float(np.sum(P[:, 0] * U[:, 0] + P[:, 1] * U[:, 1]))
            phi = math.atan2(num, den) if abs(num) + abs(den) > 1e-12 else 0.0
        c, s = math.cos(phi), math.sin(phi)
        rotated = P @ np.array([[c, s, 0], [-s, c, 0], [0, 0, 1.0]])
        t = float(np.mean(U[:, 2] - rotated[:, 2])) if family.shift else 0.0
        C = _member(base, phi, t)
        err = float(np.max(np.linalg.norm(P @ C[:3, :3].T + C[:3, 3] - W, axis=1)))
        if best is None or err < best[1]:
            best = (C, err)
    return best


def _fit_loose(family: FrameFamily, base, P, W) -> tuple:
    """:func:`fit_link` in a loose family, from one base: the origin by least squares for
    each turn φ tried. Exact for points of a valid frame: φ of the rigid fit in the xy
    plane, or, when the points do not fix it (all on one line along z), the turns that put
    the origin's offset along x (``slide_x``)."""
    def at(phi):
        c, s_ = math.cos(phi), math.sin(phi)
        R = base[:3, :3] @ np.array([[c, -s_, 0], [s_, c, 0], [0, 0, 1.0]])
        C, _ = _loose_member(family, base, phi, (W - base[:3, 3] - P @ R.T).mean(axis=0))
        return float(np.max(np.linalg.norm(P @ C[:3, :3].T + C[:3, 3] - W, axis=1))), C
    if not family.spin:
        err, C = at(0.0)
        return C, err
    U = (W - base[:3, 3]) @ base[:3, :3]
    phis = []
    for p, u in ((P[:, :2] - P[:, :2].mean(axis=0), U[:, :2] - U[:, :2].mean(axis=0)), (P[:, :2], U[:, :2])):
        num = float(np.sum(p[:, 0] * u[:, 1] - p[:, 1] * u[:, 0]))
        den = float(np.sum(p[:, 0] * u[:, 0] + p[:, 1] * u[:, 1]))
        phis.append(math.atan2(num, den) if abs(num) + abs(den) > 1e-12 else 0.0)
    (_px, py), (ux, uy) = P[:, :2].mean(axis=0), U[:, :2].mean(axis=0)
    r = math.hypot(ux, uy)
    if r > 1e-12:                                  # uy·cos φ − ux·sin φ = py: the offset along x
        beta, gamma = math.atan2(ux, uy), math.acos(max(-1.0, min(1.0, py / r)))
        phis += [gamma - beta, -gamma - beta]
    err, C = min((at(phi) for phi in phis), key=lambda fit: fit[0])
    return C, err


# --- other valid answers: the free choices of the DH convention ------------------------------

def random_family_frames(rng, ref: Reference | None = None) -> list:
    """A random valid set of DH frames 0…n at home, each frame drawn from its family, the very
    families the checks accept (signs of z and x, origins slid along parallel axes, the last x
    turned). A robot with a prismatic joint (an :class:`~dhlab.assignment.model.AssignmentRobot`):
    :func:`~dhlab.assignment.model.random_frames_from_axes`, which also moves the sliding axes' lines."""
    ref = ref or reference()
    if "P" in ref.kinds:               # the line of a sliding axis ties two frames' choices together
        return model.random_frames_from_axes(ref, rng)
    frames = []
    for k in range(ref.n + 1):
        family = frame_family(ref, k)
        base = family.bases[int(rng.integers(len(family.bases)))]
        phi = float(rng.uniform(-math.pi, math.pi)) if family.spin else 0.0
        t = float(rng.uniform(-0.3, 0.3)) if family.shift else 0.0
        frames.append(_member(base, phi, t))
    return frames


def dh_rows_from_frames(frames, ref: Reference | None = None) -> list:
    """The DH rows that carry ``frames`` (home pose) into each other, with the joint
    variables of the PUMA: per link ``(sign, θ0°, d, a, α°)`` meaning
    ``T_i = Tz[sign·q_i + θ0, d]·Tx[α, a]``; sign = −1 where z_{i−1} points against
    the joint's drawn positive sense.

    >>> rows = dh_rows_from_frames(reference().home_frames)
    >>> [tuple(round(v, 5) + 0.0 for v in row) for row in rows][:3]
    [(1.0, 0.0, 0.0, 0.0, 90.0), (1.0, 0.0, 0.0, 0.4318, 0.0), (1.0, 0.0, 0.15005, 0.0203, -90.0)]
    """
    ref = ref or reference()
    rows = []
    for k in range(1, len(frames)):
        A = np.linalg.inv(frames[k - 1]) @ frames[k]
        theta = math.atan2(A[1, 0], A[0, 0])
        alpha = math.atan2(A[2, 1], A[2, 2])
        d = A[2, 3]
        a = A[0, 3] * math.cos(theta) + A[1, 3] * math.sin(theta)
        if not np.allclose(row_matrix(theta, d, a, alpha), A, atol=1e-9):
            raise ValueError(f"frames {k - 1} and {k} are not related by Tz·Tx (not DH frames)")
        sign = 1 if frames[k - 1][:3, 2] @ ref.axes[k - 1].direction > 0 else -1
        rows.append((sign, math.degrees(theta), float(d), float(a), math.degrees(alpha)))
    return rows
