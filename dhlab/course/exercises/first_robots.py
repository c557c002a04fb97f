"""The exercises of notebook 3 (seed 004's two robots): ⁰H₁ and ⁰H₂ by hand, where the pen goes, reaching a point."""
from __future__ import annotations

import math

import numpy as np
import sympy as sp

from ...i18n import N_
from ...transforms import Rz, trans
from ..checks.feedback import Exercise
from ..checks.matrix import check_matrix
from ..checks.values import check_value

THETA0, THETA1, L1, L2 = sp.symbols("theta0 theta1 l1 l2")


def _robot1_H1_eq3():
    """⁰H₁ as printed in seed 004's eq. (3) (erratum 004-1)."""
    c, s = sp.cos(THETA0), sp.sin(THETA0)
    return sp.Matrix([[c, -s, 0, -L1 * c], [s, c, 0, L1 * s], [0, 0, 1, 0], [0, 0, 0, 1]])


def _ex_3_1():
    right = Rz(THETA0) * trans(0, L1, 0)
    mistakes = [
        (_robot1_H1_eq3(), N_("your translation column is (−l1·cos θ0, l1·sin θ0, 0): that is eq. (3) as printed, "
                              "erratum 004-1. At θ0 = 0 it puts {S1} at (−l1, 0) instead of (0, l1): link 1 lies "
                              "along y0.")),
        (trans(0, L1, 0) * Rz(THETA0), N_("your translation column is (0, l1, 0) for every θ0: that is "
                                          "Tr(0,l1,0)·Rz(θ0), the link does not turn with the joint. The joint turns "
                                          "first, then the link carries {S1} along the NEW y axis: "
                                          "Rz(θ0)·Tr(0,l1,0).")),
    ]
    return Exercise("3.1", N_("⁰H₁ of the first robot"),
                    lambda a: check_matrix(a, right, name=N_("your ⁰H₁"), mistakes=mistakes),
                    [N_("Two motions, in the moving frame: turn by θ0 about z0, then move l1 along the new y axis."),
                     N_("The translation column is Rz(θ0) applied to (0, l1, 0).")])


def _ex_3_2():
    H1, H2 = Rz(THETA0) * trans(L1, 0, 0), Rz(THETA1) * trans(L2, 0, 0)
    right = H1 * H2
    seed_robot = Rz(THETA0) * trans(0, L1, 0) * H2
    c0, s0, c1, s1 = sp.cos(THETA0), sp.sin(THETA0), sp.cos(THETA1), sp.sin(THETA1)
    link2_alone = right.copy()
    link2_alone[0, 3], link2_alone[1, 3] = L1 * c0 + L2 * c1, L1 * s0 + L2 * s1
    return Exercise("3.2", N_("⁰H₂ of the variant with link 1 along x0"), lambda a: check_matrix(
        a, right, name=N_("your ⁰H₂"), mistakes=[
            (seed_robot, N_("that is ⁰H₂ of seed 004's robot, whose link 1 lies along y0; in this variant link 1 "
                            "lies along x0: ⁰H₁ = Rz(θ0)·Tr(l1, 0, 0).")),
            (H2 * H1, N_("that is ¹H₂·⁰H₁, the product in the wrong order: ⁰H₂ = ⁰H₁·¹H₂ (the upper and lower "
                         "indices chain: 0→1, then 1→2).")),
            (link2_alone, N_("the rotation block is right, but link 2 points at θ0 + θ1 from x0, not θ1: its "
                             "terms are l2·cos(θ0+θ1) and l2·sin(θ0+θ1) (angles add along a planar chain)."))]),
        [N_("⁰H₁ = Rz(θ0)·Tr(l1, 0, 0) and ¹H₂ = Rz(θ1)·Tr(l2, 0, 0); multiply them in this order."),
         N_("At θ0 = θ1 = 0 the pen must be at (l1 + l2, 0, 0); the rotation block is Rz(θ0 + θ1).")])


def _robot1_position(t0, t1, l1=0.70, l2=0.30):
    return np.array([l2 * math.cos(t0 + t1) - l1 * math.sin(t0), l2 * math.sin(t0 + t1) + l1 * math.cos(t0), 0.0])


def _variant_position(t0, t1, l1=0.70, l2=0.30):
    """The pen if link 1 lay along x0 at rest (the variant of exercise 3.2)."""
    return np.array([l1 * math.cos(t0) + l2 * math.cos(t0 + t1), l1 * math.sin(t0) + l2 * math.sin(t0 + t1), 0.0])


def _ex_3_3():
    t0, t1 = math.radians(30), math.radians(45)
    eq3 = np.array(_robot1_H1_eq3().subs({THETA0: t0, L1: 0.70}).evalf(), dtype=float) @ (
        Rz(t1) @ trans(0.30, 0, 0))
    return Exercise("3.3", N_("the pen at θ0 = 30°, θ1 = 45°"), lambda a: check_value(
        a, _robot1_position(t0, t1), name=N_("your pen position"), components=("x", "y", "z"), unit="m",
        mistakes=[(_robot1_position(30, 45), N_("those are the values for θ0 = 30 rad and θ1 = 45 rad: "
                                               "convert the angles, deg2rad(30) and deg2rad(45).")),
                  (_robot1_position(t1, t0), N_("you swapped θ0 and θ1: θ0 = 30° is the base joint.")),
                  (eq3[:3, 3], N_("that is the position with ⁰H₁ of eq. (3) as printed (erratum 004-1): "
                                  "use ⁰H₁ = Rz(θ0)·Tr(0, l1, 0).")),
                  (_variant_position(t0, t1),
                   N_("that is the pen of the variant with link 1 along x0 (exercise 3.2). In seed 004's robot "
                      "link 1 lies along y0 at rest: ⁰H₁ = Rz(θ0)·Tr(0, l1, 0), so l1 contributes "
                      "(−l1·sin θ0, l1·cos θ0)."))]),
        [N_("robot.fk(deg2rad([30, 45])) gives the whole pose; its last column is the position."),
         N_("By the formula: x = l2·cos(θ0+θ1) − l1·sin θ0, y = l2·sin(θ0+θ1) + l1·cos θ0.")])


def _ex_3_4():
    l, x, y = 0.70, -0.6, 0.6
    reach = math.hypot(x, y)
    right = [math.radians(45), reach - l]
    return Exercise("3.4", N_("reach (−0.6, 0.6) with the second robot"), lambda a: check_value(
        a, right, name=N_("your (θ, d)"), components=("θ", "d"), unit=("rad", "m"),
        mistakes=[([math.radians(45), reach], N_("d = 0.8485 is the whole distance l + d from the base: the "
                                                 "fixed link l = 0.70 is not part of the joint value d.")),
                  ([45, reach - l], N_("θ = 45 is in degrees: the API takes radians, deg2rad(45).")),
                  ([-math.radians(45), reach - l], N_("with θ = −45° the pen goes to (+0.6, 0.6): x = −(l+d)·sin θ, "
                                                      "so x < 0 needs θ > 0 (counter-clockwise)."))]),
        [N_("The pen is at (−(l+d)·sin θ, (l+d)·cos θ): its distance from the base is l + d."),
         N_("Distance √(0.6² + 0.6²) = l + d, and the direction gives θ.")])


def _robot2_position(theta, d, l=0.70):
    return np.array([-(l + d) * math.sin(theta), (l + d) * math.cos(theta), 0.0])


def _ex_3_5():
    d_max = 0.30
    right = _robot2_position(-math.pi / 2, d_max)
    title = N_("predict: the reader's exercise of seed 004 (θ = −π/2, d = d_max)")
    return Exercise("3.5", title, lambda a: check_value(
        a, right, name=N_("your predicted pen position"), components=("x", "y", "z"), unit="m", mistakes=[
            (_robot2_position(math.pi / 2, d_max), N_("that is θ = +π/2, counter-clockwise: a negative angle turns "
                                                      "clockwise, so the arm leaves +y0 the other way.")),
            (_robot2_position(-math.pi / 2, 0.0), N_("that is d = 0: at d = d_max the prismatic joint is fully "
                                                     "extended, the pen is l + d_max from the base.")),
            (_robot2_position(-math.pi / 2, 0.0, l=d_max), N_("that is d_max alone: the fixed link l = 0.70 is still "
                                                              "there, the pen is l + d from the base.")),
            (_robot2_position(-90.0, d_max), N_("that is θ = −90 rad: the angle is −π/2 rad = −90°.")),
            (_robot2_position(0.0, d_max), N_("that is θ = 0: the arm still points along +y0; turn it by −π/2."))]),
        [N_("At θ = 0 the arm points along +y0, and the pen is at distance l + d from the base."),
         N_("A negative θ turns clockwise (seen from +z): by −90° the +y0 direction goes to +x0.")])


# The exercises of this notebook, by key: dhlab.course.exercises.exercise(key) makes them.
EXERCISES = {"3.1": _ex_3_1, "3.2": _ex_3_2, "3.3": _ex_3_3, "3.4": _ex_3_4, "3.5": _ex_3_5}
