"""The mechanism drawn as a textbook draws it (Spong, Craig; RoboAnalyzer; seed 000's program).

A stick figure from origin to origin hides what DH is about. Here, for a pose:

* **each link runs along its translations**: a DH link ``Rz(θ)·Tz(d)·Tx(a)·Rx(α)`` is
  drawn as d along z_(i-1), then a along x_i, so offsets and common normals are
  visible (an L, not a diagonal); a link built from other elementary motions
  (seed 004's ``Rz(θ0)·Tr(0, l1, 0)``) runs along each of its own translations;
* **a revolute joint is a short cylinder** along its axis, where its rotation acts;
* **a prismatic joint is a sleeve** along its axis, from where the joint acts to how
  far it has slid, **with a carriage** at its end: the sleeve's length *is* the joint's
  translation (d for a DH prismatic joint), and it grows and shrinks with the slider;
* **the end effector is a small gripper**: fingers along the approach vector
  (z of the tool frame; for a robot without a tool, the direction its last link
  extends, else z_n) opening along y (the sliding vector).

All solids are made once, in the joint's own coordinates; a pose only moves
them (one small matrix product per joint), so a slider stays fast.

>>> import dhlab, numpy as np
>>> robot = dhlab.robots.ssrms()
>>> m = Mechanism(robot, size=10.0)
>>> shape = m.shape(robot.frames(robot.qz), robot.qz)
>>> shape.path.shape[1], shape.faces.shape[0] == 7 * m.faces_per_joint
(3, True)
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..kinematics import elementary

__all__ = ["Mechanism", "Shape", "cylinder", "box", "shade", "JOINT_COLORS"]

SIDES = 16                       # a cylinder is a 16-sided prism: round at any size on a slide
JOINT_COLORS = {"R": "#8fb3d9", "sleeve": "#e8d2a6", "carriage": "#c98d2e"}
LIGHT = np.array([-0.35, -0.45, 0.82])          # fixed in the world: the robot keeps its shading as it moves
LIGHT = LIGHT / np.linalg.norm(LIGHT)

# sizes, as fractions of the robot's typical size (the triad is 0.14 of it)
CYLINDER_RADIUS, CYLINDER_HALF = 0.032, 0.055
SLEEVE_HALF_WIDTH, CARRIAGE_HALF_WIDTH, CARRIAGE_HALF = 0.038, 0.05, 0.025
GRIPPER_STEM, GRIPPER_WIDTH, FINGER_LENGTH = 0.04, 0.1, 0.07
SLEEVE_ALPHA = 0.5               # the link's line inside the sleeve shows through


def cylinder(radius: float, half: float, sides: int = SIDES) -> np.ndarray:
    """A closed cylinder along local z from -half to +half: (sides + 2, sides, 3).

    Every face has ``sides`` vertices (a side quad repeats its last corner), so
    the whole solid is one array that matplotlib can take without padding.
    """
    t = 2 * np.pi * np.arange(sides + 1) / sides
    rim = np.column_stack([radius * np.cos(t), radius * np.sin(t)])
    faces = np.zeros((sides + 2, sides, 3))
    for k in range(sides):
        quad = [[*rim[k], -half], [*rim[k + 1], -half], [*rim[k + 1], half], [*rim[k], half]]
        faces[k] = quad + [quad[-1]] * (sides - 4)
    faces[sides] = np.column_stack([rim[:-1], np.full(sides, -half)])
    faces[sides + 1] = np.column_stack([rim[:-1], np.full(sides, half)])
    return faces


def box(half_width: float, start: float, end: float, sides: int = SIDES) -> np.ndarray:
    """A square bar along local z from ``start`` to ``end``: 6 faces, padded to ``sides`` vertices."""
    w = half_width
    corners = np.array([[-w, -w], [w, -w], [w, w], [-w, w]])
    lo = np.column_stack([corners, np.full(4, start)])
    hi = np.column_stack([corners, np.full(4, end)])
    quads = [lo, hi] + [[lo[k], lo[(k + 1) % 4], hi[(k + 1) % 4], hi[k]] for k in range(4)]
    return np.array([list(q) + [q[-1]] * (sides - 4) for q in quads], dtype=float)


def face_normals(faces: np.ndarray) -> np.ndarray:
    """Unit normals of faces (F, K, 3), from their first three corners."""
    n = np.cross(faces[:, 1] - faces[:, 0], faces[:, 2] - faces[:, 0])
    length = np.linalg.norm(n, axis=1, keepdims=True)
    return np.divide(n, length, out=np.zeros_like(n), where=length > 1e-15)


def shade(rgb: np.ndarray, normals: np.ndarray, alpha: np.ndarray) -> np.ndarray:
    """Face colours lit from :data:`LIGHT` (two-sided: a face turned away is lit from behind)."""
    light = 0.62 + 0.38 * np.abs(normals @ LIGHT)
    return np.column_stack([np.clip(rgb * light[:, None], 0, 1), alpha])


@dataclass
class Shape:
    """The mechanism at one pose: ``path`` (p, 3) the links with NaN breaks; ``faces``
    (F, K, 3) the joints' solids with ``colors`` (F, 4); ``gripper`` (g, 3) lines with NaN
    breaks; ``points`` the corners of the links (origins and knees: what a view frames);
    ``outline`` points on the solids and the gripper (what labels keep off)."""
    path: np.ndarray
    faces: np.ndarray
    colors: np.ndarray
    gripper: np.ndarray
    points: np.ndarray
    outline: np.ndarray


def _axes_of(pose: np.ndarray, axis: int) -> np.ndarray:
    """The rotation whose third column is the pose's ``axis`` column: local z → that axis."""
    return pose[:3, [(axis + 1) % 3, (axis + 2) % 3, axis]]


class Mechanism:
    """Geometry of a dhlab robot's mechanism, made once; :meth:`shape` places it at a pose.

    ``size`` is the robot's typical size (every solid is a fraction of it)."""

    def __init__(self, robot, size: float):
        from matplotlib.colors import to_rgb  # lazy: matplotlib on first picture
        self.size = float(size)
        self.links = robot.numeric_links     # per link: (kind, axis, value, is_joint, sign), numbers
        self.has_tool = not np.allclose(np.asarray(robot.tool, dtype=float), np.eye(4))
        s = self.size
        self._cylinder = cylinder(CYLINDER_RADIUS * s, CYLINDER_HALF * s)
        self.faces_per_joint = len(self._cylinder)
        solids, colors, alphas = [], [], []
        for factors in self.links:
            kind, _, value, _, sign = next(f for f in factors if f[3])
            if kind == "R":
                solids.append(self._cylinder)
                colors += [to_rgb(JOINT_COLORS["R"])] * self.faces_per_joint
                alphas += [1.0] * self.faces_per_joint
            else:       # sleeve from 0 to 1 along the axis (stretched to the joint's value), carriage at 0
                sleeve = box(SLEEVE_HALF_WIDTH * s, 0.0, 1.0)
                carriage = box(CARRIAGE_HALF_WIDTH * s, -CARRIAGE_HALF * s, CARRIAGE_HALF * s)
                pad = np.repeat(sleeve[:1], self.faces_per_joint - 12, axis=0)   # same face count, unseen
                solids.append(np.concatenate([sleeve, carriage, pad]))
                colors += [to_rgb(JOINT_COLORS["sleeve"])] * 6 + [to_rgb(JOINT_COLORS["carriage"])] * 6 \
                    + [to_rgb(JOINT_COLORS["sleeve"])] * (self.faces_per_joint - 12)
                alphas += [SLEEVE_ALPHA] * 6 + [1.0] * 6 + [0.0] * (self.faces_per_joint - 12)
        self._solids = solids
        # a few corners of each solid: what labels keep off and what the view keeps in sight
        self._outline = [(np.array([SIDES, SIDES + 1]), slice(None, None, 4)) if f[3] and f[0] == "R" else
                         (np.array([0, 1, 6, 7]), slice(0, 4)) for link in self.links for f in link if f[3]]
        self._rgb, self._alpha = np.array(colors, dtype=float).reshape(-1, 3), np.array(alphas, dtype=float)

    # --- one pose ---------------------------------------------------------------------
    def shape(self, frames: np.ndarray, q: np.ndarray) -> Shape:
        """The mechanism for the frames 0…n (and the tool, if any) of the pose ``q``."""
        path, faces, extra = [], [], []
        for j, factors in enumerate(self.links):
            M, approach = frames[j], None
            link_path = [M[:3, 3]]
            for kind, axis, value, is_joint, sign in factors:
                amount = value + sign * q[j] if is_joint else value
                if is_joint:
                    solid = self._place_joint(j, kind, axis, M, amount)
                    faces.append(solid)
                    extra.append(solid[self._outline[j]].reshape(-1, 3))
                M = M @ elementary(kind, axis, amount)
                moved = kind == "T" and abs(amount) > 1e-12 * max(self.size, 1.0)
                if moved or (kind == "T" and is_joint):    # where this link extends (a slider at 0 too)
                    approach = M[:3, axis] * (-1.0 if amount < 0 else 1.0)
                if moved:
                    link_path.append(M[:3, 3])
            link_path[-1] = frames[j + 1][:3, 3]          # the walk ends on frame j+1 exactly
            path += link_path + [np.full(3, np.nan)]
        end = frames[-1]
        if self.has_tool:                                   # frames[-1] is the tool frame
            path += [frames[-2][:3, 3], end[:3, 3], np.full(3, np.nan)]
            approach = end[:3, 2]
        elif approach is None:
            approach = end[:3, 2]                           # DH's approach vector a = z_n
        gripper = self._gripper(end, approach)
        faces = np.concatenate(faces) if faces else np.zeros((0, SIDES, 3))
        colors = shade(self._rgb, face_normals(faces), self._alpha) if len(faces) else np.zeros((0, 4))
        kept = [p for p in path if np.isfinite(p).all()]
        outline = np.vstack([gripper[np.isfinite(gripper).all(axis=1)], *extra])
        return Shape(np.array(path), faces, colors, gripper, np.array(kept), outline)

    def _place_joint(self, j, kind, axis, M, amount) -> np.ndarray:
        R, p = _axes_of(M, axis), M[:3, 3]
        solid = self._solids[j]
        if kind == "T":              # stretch the sleeve (faces 0…5), move the carriage (6…11)
            solid = solid.copy()
            solid[:6, :, 2] *= amount
            solid[6:12, :, 2] += amount
        return solid @ R.T + p

    def _gripper(self, pose: np.ndarray, approach: np.ndarray) -> np.ndarray:
        """A stem, a palm and two fingers along ``approach`` from the end effector's origin,
        opening along its y (the sliding vector s)."""
        a = approach / np.linalg.norm(approach)
        o = pose[:3, 1] - (pose[:3, 1] @ a) * a            # y, made square to the approach
        if np.linalg.norm(o) < 1e-6:
            o = pose[:3, 2] - (pose[:3, 2] @ a) * a
        o = o / np.linalg.norm(o)
        p, w, f = pose[:3, 3], 0.5 * GRIPPER_WIDTH * self.size, FINGER_LENGTH * self.size
        palm, gap = p + GRIPPER_STEM * self.size * a, np.full(3, np.nan)
        return np.array([p, palm, gap, palm + w * o + f * a, palm + w * o, palm - w * o, palm - w * o + f * a, gap])
