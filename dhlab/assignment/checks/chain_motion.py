"""The whole chain, moving: a student's T_1 … T_n compared with the robot at many configurations.

Part 3's last item (the chain) and the summary under it: the chain of the student's rows
is evaluated at the home pose and at random configurations (:func:`random_configurations`),
and each joint's axis, as a directed line, and the end effector are compared with the
reference robot's (:func:`chain_matches`). Split from :mod:`dhlab.assignment.checks.transforms`,
which judges the rows one by one.
"""
from __future__ import annotations

import math

import numpy as np

from ..reference import TOL_DEG, TOL_POS, cache_of, dh_frames, reference

__all__ = ["N_CONFIGS", "random_configurations", "chain_matches"]

N_CONFIGS = 50


def random_configurations(n: int = N_CONFIGS, seed: int = 560, ref=None) -> np.ndarray:
    """The configurations the chain is compared at: home, then n random ones (radians for a
    revolute joint, anywhere in ±180°; metres for a prismatic one, within its stroke)."""
    ref = ref or reference()
    rng = np.random.default_rng(seed)
    Q = rng.uniform(-math.pi, math.pi, (n, ref.n))
    for j, kind in enumerate(ref.kinds):
        if kind == "P":
            Q[:, j] = rng.uniform(*ref.qlim[j], n)
    return np.vstack([np.zeros(ref.n), Q])


def _robot_motion(ref, Q) -> tuple:
    """The robot at configurations ``Q``: ``(Q, its frames, its axes' points, their directions)``;
    at the default configurations, computed once per robot (every chain is compared there)."""
    if Q is not None:
        Q = np.atleast_2d(Q)
        return (Q, ref.frames(Q), *ref.axes_at(Q))
    cache = cache_of(ref)
    if "motion" not in cache:
        cache["motion"] = _robot_motion(ref, random_configurations(ref=ref))
    return cache["motion"]


def _student_rows_numeric(rows) -> tuple:
    """The student's rows as ``(sign, joint index, θ0, d0, a, α)`` (radians, metres) and their
    kinds ('R' where q is in θ, 'P' where it is in d), for :func:`~dhlab.assignment.reference.dh_frames`."""
    out, kinds = [], ""
    for row in rows:
        joint, sign, where = row.joint
        out.append((sign, joint - 1, math.radians(row.theta.const), row.d.const, row.a, math.radians(row.alpha)))
        kinds += "P" if where == "d" else "R"
    return out, kinds


def chain_matches(rows, Q=None, ref=None) -> dict:
    """Compare a chain with the reference robot at configurations ``Q`` (default: home + 50 random).

    For each joint, whether its axis — a directed line: the axis of joint i is z_{i-1},
    pointing the way that a positive q_i turns by the right-hand rule (or slides) — is the
    robot's at every configuration (a sliding joint's axis: its direction only, the line
    is the student's choice); whether the end effector is at the same place; and whether
    the last frame's z lies along the last joint's axis.
    """
    ref = ref or reference()
    Q, R, points, directions = _robot_motion(ref, Q)
    numeric, kinds = _student_rows_numeric(rows)
    F = dh_frames(numeric, kinds, Q)
    cos_tol = math.cos(math.radians(TOL_DEG))
    axes_ok = []
    for k, row in enumerate(rows):
        d_st = row.joint[1] * F[:, k, :3, 2]
        p_st = F[:, k, :3, 3]
        d_ref, p_ref = directions[:, k], points[:, k]
        same_dir = np.einsum("ij,ij->i", d_st, d_ref) >= cos_tol
        v = p_ref - p_st
        off = np.linalg.norm(v - np.einsum("ij,ij->i", v, d_st)[:, None] * d_st, axis=1)
        on_line = off <= TOL_POS if ref.kinds[k] == "R" else True
        axes_ok.append(bool(np.all(same_dir & on_line)))
    ee = np.linalg.norm(F[:, -1, :3, 3] - R[:, -1, :3, 3], axis=1)
    last_z = np.abs(np.einsum("ij,ij->i", F[:, -1, :3, 2], R[:, -1, :3, 2])) >= cos_tol
    return {"axes": axes_ok, "end_effector": bool(np.all(ee <= TOL_POS)), "last_z": bool(np.all(last_z)),
            "configurations": len(Q), "frames": F}
