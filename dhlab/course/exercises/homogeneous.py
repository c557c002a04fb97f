"""The exercises of notebook 2 (homogeneous matrices): Rz by hand, composing, the inverse, seed 001's listing.

:func:`seed001_DefinirTHz` is seed 001's C++ listing transcribed into Python, bugs included: notebook 2
finds its bugs (exercise 2.4), notebook 7 and the sources notebook run it.
"""
from __future__ import annotations

import math

import numpy as np
import sympy as sp

from ...i18n import N_
from ...transforms import Rx, Ry, Rz, inv, trans
from ...validation import as_angle, as_vector, check_length_size
from ..checks.feedback import Exercise
from ..checks.matrix import check_function, check_matrix
from ..checks.values import check_value

TH = sp.Symbol("theta")


def _ex_2_1():
    right = Rz(TH)
    return Exercise("2.1", N_("Rz(θ) by hand"), lambda a: check_matrix(a, right, name=N_("your Rz(θ)"), mistakes=[
        (Rx(TH), N_("that is the rotation about x (it leaves x fixed): Rz leaves z fixed, so its third row "
                    "and column are those of the identity.")),
        (Ry(TH), N_("that is the rotation about y (it leaves y fixed): Rz leaves z fixed."))]),
        [N_("A rotation about z leaves z fixed: the third row and column are 0 0 1 "
            "(and the 4th those of the identity)."),
         N_("Its first column is where x goes: (cos θ, sin θ, 0). The second is where y goes: 90° further on.")])


def _ex_2_2():
    right = Rz(math.radians(30)) @ trans(2, 0, 0)
    by_hand_in_degrees = np.array([[math.cos(30), -math.sin(30), 0, 2 * math.cos(30)],
                                   [math.sin(30), math.cos(30), 0, 2 * math.sin(30)],
                                   [0, 0, 1, 0], [0, 0, 0, 1]])
    return Exercise("2.2", N_("compose in the moving frame"), lambda a: check_matrix(
        a, right, name=N_("your ⁰T₁"), mistakes=[
            (trans(2, 0, 0) @ Rz(math.radians(30)),
             N_("that is Tr(2,0,0)·Rz(30°): the move along the FIXED x0 axis (pre-multiplied, fixed-frame order). "
                "Moving along the new x axis means post-multiplying: Rz(30°)·Tr(2,0,0).")),
            (by_hand_in_degrees, N_("cos(30) and sin(30) were computed with 30 radians: "
                                    "use the angle in radians, deg2rad(30) = π/6.")),
            (Rz(math.radians(30)), N_("that is only the rotation: the move of 2 along the new x is missing."))]),
        [N_("Moving frame: multiply on the right, in the order the motions happen."),
         N_("Rz(deg2rad(30)) @ trans(2, 0, 0): the new origin is 2·(cos 30°, sin 30°, 0).")])


def _ex_2_3():
    T = trans(1, 2, 0) @ Rz(math.pi / 2)
    R, p = T[:3, :3], T[:3, 3]
    keep_p = np.eye(4)
    keep_p[:3, :3], keep_p[:3, 3] = R.T, p
    minus_p = keep_p.copy()
    minus_p[:3, 3] = -p
    return Exercise("2.3", N_("the inverse"), lambda a: check_matrix(a, inv(T), name=N_("your T⁻¹"), mistakes=[
        (keep_p, N_("the rotation block (Rᵀ) is right, but the translation of the inverse is −Rᵀ·p, not p.")),
        (minus_p, N_("the rotation block (Rᵀ) is right, but the translation of the inverse is −Rᵀ·p: "
                     "−p alone forgets to turn it into the other frame.")),
        (T, N_("that is T itself: the inverse undoes it, T⁻¹·T = I."))]),
        [N_("T⁻¹ = [[Rᵀ, −Rᵀ·p], [0 0 0 1]]."), N_("Check yours: T⁻¹ @ T must be the identity.")])


def _ex_2_5():
    right = (Rz(math.pi / 2) @ trans(1, 0, 0))[:3, 3]
    return Exercise("2.5", N_("predict: turn 90° about z, then move 1 along the new x"), lambda a: check_value(
        a, right, name=N_("your predicted origin of {S1}"), components=("x", "y", "z"), mistakes=[
            ((trans(1, 0, 0) @ Rz(math.pi / 2))[:3, 3],
             N_("that is the move along the FIXED x0 axis. In the moving frame the move follows the frame's own "
                "x axis, which the turn has already carried somewhere else: where does x point after the turn?")),
            ([0, -1, 0], N_("the turn is +90°, counter-clockwise seen from +z: x goes to where y was, not to −y."))]),
        [N_("After a turn of +90° about z, the frame's x axis points where y0 points."),
         N_("Then move 1 along that new x axis.")])


def seed001_DefinirTHz(dtheta, d):
    """Seed 001's ``DefinirTHz`` listing, transcribed line by line into Python, bugs included.

    ``dtheta`` in radians (the C++ ``AplicarTHz`` converts degrees first), ``d`` = (x, y, z).
    """
    dtheta, d = as_angle(dtheta, "dtheta (radians)"), as_vector(d, "d = (x, y, z)", 3)
    for k, v in enumerate(d):
        check_length_size(abs(v), f"d[{k}]")
    THz = np.zeros((4, 4))
    THz[0][0] = -math.cos(dtheta)
    THz[0][1] = -math.sin(dtheta)
    THz[0][2] = 0
    THz[0][3] = -d[0]
    THz[1][0] = math.sin(dtheta)
    THz[1][1] = math.cos(dtheta)
    THz[1][2] = 0
    THz[1][3] = -d[1]
    THz[2][0] = 0
    THz[2][1] = 0
    THz[2][2] = 1
    THz[2][3] = -d[2]
    THz[3][0] = 0
    THz[3][1] = 0
    THz[3][2] = 0
    THz[3][3] = 1
    return THz


def seed000_DefinirTHz(dtheta, d):
    """The right listing (seed 000, the author's repository): Tr(d)·Rz(θ)."""
    return trans(*d) @ Rz(dtheta)


def _rz_then_translate(dtheta, d):
    """A plausible wrong fix of the listing: the two factors in the other order."""
    return Rz(dtheta) @ trans(*d)


def _ex_2_4():
    def only_cos_fixed(dtheta, d):
        M = seed001_DefinirTHz(dtheta, d)
        M[0][0] = math.cos(dtheta)
        return M

    def only_d_fixed(dtheta, d):
        M = seed001_DefinirTHz(dtheta, d)
        M[:3, 3] = d
        return M

    cases = [(0.0, (0.0, 0.0, 2.5)), (math.radians(30), (0.0, 0.0, 2.5)),
             (math.radians(45), (1.0, 2.0, 3.0)), (2.0, (0.5, -1.0, 0.0))]
    return Exercise("2.4", N_("spot the bug in DefinirTHz"), lambda f: check_function(
        f, seed000_DefinirTHz, cases, name=N_("your DefinirTHz"), index_style="cpp",
        describe=lambda a: f"dtheta = {math.degrees(a[0]):g}°, d = {a[1]}",
        mistakes=[(seed001_DefinirTHz, N_("this is still seed 001's listing, unchanged: it has two bugs. "
                                          "Compare each line with Rz(θ) and with a translation by d.")),
                  (only_cos_fixed, N_("aij[0][0] is fixed, but the translation column still has −d.x, −d.y, "
                                      "−d.z: the frame moves to the wrong side (erratum 001-2).")),
                  (only_d_fixed, N_("the translation column is fixed, but aij[0][0] is still −cos(dtheta): "
                                    "det R = −cos 2θ, a mirror at θ = 0 and flat at 45° (erratum 001-1).")),
                  (_rz_then_translate, N_("your function builds Rz(θ)·Tr(d): the frame turns first, so the "
                                          "translation is turned too (its column is Rz(θ)·d, not d). Both agree "
                                          "only when d lies along z. DefinirTHz moves by d, then turns: "
                                          "Tr(d)·Rz(θ)."))]),
        [N_("Compare each line with the matrix Rz(θ) of this notebook: one entry of the rotation block differs."),
         N_("Seed 000 prints the same listing with d.x, d.y, d.z: which sign does a translation by d have?")])


# The exercises of this notebook, by key: dhlab.course.exercises.exercise(key) makes them.
EXERCISES = {"2.1": _ex_2_1, "2.2": _ex_2_2, "2.3": _ex_2_3, "2.4": _ex_2_4, "2.5": _ex_2_5}
