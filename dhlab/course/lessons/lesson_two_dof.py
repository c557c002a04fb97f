"""What notebook 3 (seed 004's two "robots no tan elementales") needs besides the lesson itself.

* The seed's matrices **as printed**, slips included (the notebook compares each with what
  ``dhlab`` computes): :func:`seed004_first_robot_printed` (eqs. 2, 3, 5, 6, 8) and
  :func:`seed004_second_robot_printed` (eqs. 10, 11, 13).
* :func:`link_directions`: where joint 2 and the pen are, and the direction of each link.
* The static figures: :func:`draw` (one robot at one pose, seen from above),
  :func:`perspective_figure` (seed 004's figure 34), :func:`two_cases_figure` (the first robot's
  two cases, with the triangle of l.169 and where eq. 3 would put {S₁}) and
  :func:`three_poses_figure` (the second robot's three cases).
* :func:`seed004_comparison`: the table of every case of seed 004, computed beside what the seed prints.
"""
from __future__ import annotations

import math

import numpy as np
import sympy as sp

from ...errors import DHLabError
from ...i18n import _
from ...units import deg2rad
from ...views.camera import set_camera
from ...views.figures import new_figure
from ...views.view import robot_view
from .lesson_homogeneous import fmt

__all__ = ["seed004_first_robot_printed", "seed004_second_robot_printed", "link_directions", "draw",
           "perspective_figure", "two_cases_figure", "three_poses_figure", "seed004_comparison"]


def seed004_first_robot_printed(th0, th1, l1, l2) -> dict:
    """The first robot's matrices as seed 004 prints them (symbols of the caller's choice):
    ``"eq. (2)"`` ¹H₂, ``"eq. (3)"`` ⁰H₁ (wrong translation: erratum 004-1), ``"eq. (5) second"``
    (the second factor of eq. 5, erratum 004-3), ``"eq. (6)"`` ⁰H₂ (entry (1,2) wrong: erratum 004-4)
    and ``"eq. (8)"`` ⁰H₁ (right)."""
    c0, s0, c1, s1 = sp.cos(th0), sp.sin(th0), sp.cos(th1), sp.sin(th1)
    last = [[0, 0, 1, 0], [0, 0, 0, 1]]
    return {
        "eq. (2)": sp.Matrix([[c1, -s1, 0, l2 * c1], [s1, c1, 0, l2 * s1], *last]),
        "eq. (3)": sp.Matrix([[c0, -s0, 0, -l1 * c0], [s0, c0, 0, l1 * s0], *last]),
        "eq. (5) second": sp.Matrix([[c1, -s1, 0, l1 * c0], [s1, c1, 0, l1 * s0], *last]),
        "eq. (6)": sp.Matrix([[c0 * c1 - s0 * s1, c0 * s1 - c0 * c0, 0, c0 * l2 * c1 - s0 * l2 * s1 - l1 * s0],
                              [s0 * c1 + c0 * s1, -s0 * s1 + c0 * c1, 0, s0 * l2 * c1 + c0 * l2 * s1 + l1 * c0],
                              *last]),
        "eq. (8)": sp.Matrix([[c0, -s0, 0, -l1 * s0], [s0, c0, 0, l1 * c0], *last]),
    }


def seed004_second_robot_printed(theta, d, l) -> dict:
    """The second robot's matrices as seed 004 prints them: ``"eq. (10)"`` ¹H₂, ``"eq. (11)"`` ⁰H₁
    and ``"eq. (13)"`` ⁰H₂ (all three right)."""
    ct, st = sp.cos(theta), sp.sin(theta)
    last = [[0, 0, 1, 0], [0, 0, 0, 1]]
    return {
        "eq. (10)": sp.Matrix([[1, 0, 0, 0], [0, 1, 0, d], *last]),
        "eq. (11)": sp.Matrix([[ct, -st, 0, -l * st], [st, ct, 0, l * ct], *last]),
        "eq. (13)": sp.Matrix([[ct, -st, 0, -st * d - st * l], [st, ct, 0, ct * d + ct * l], *last]),
    }


def link_directions(robot, q) -> dict:
    """Where joint 2 and the pen of a two-link planar ``robot`` are at ``q``, and the angle of each
    link from x₀ in degrees: ``{"joint 2", "pen", "link 1 [deg]", "link 2 [deg]"}``."""
    frames = robot.frames(q)
    if len(frames) != 3:
        raise DHLabError(_("link_directions needs a robot with two links; {robot} has {n}.").format(
            robot=robot, n=len(frames) - 1))
    joint2, pen = frames[1, :3, 3], frames[2, :3, 3]
    return {"joint 2": joint2, "pen": pen,
            "link 1 [deg]": math.degrees(math.atan2(joint2[1], joint2[0])),
            "link 2 [deg]": math.degrees(math.atan2(pen[1] - joint2[1], pen[0] - joint2[0]))}


def draw(ax, robot, q, title):
    """The robot at ``q`` (radians / lengths) in a static figure seen from above: links, triads,
    {S_i}, the pen (star). Returns the view."""
    view = robot_view(robot, q, ax=ax, planar=True)
    view.setup_axes(ax)
    ax.set_aspect("equal", adjustable="box")          # fixed limits: the box adapts, not the limits
    reach = robot.reach() + 1.6 * view.triad_length   # room for the pen at full reach, and its frame
    ax.set(xlim=(-reach, reach), ylim=(-reach, reach))
    ax.set_title(title)
    return view


def perspective_figure(robot, q, title=None):
    """The robot at ``q`` in 3-D, from the usual isometric camera, as seed 004's figure 34 draws it."""
    fig = new_figure((6.5, 6))
    ax = fig.add_subplot(projection="3d")
    view = robot_view(robot, q, ax=ax, planar=False)
    view.setup_axes(ax)
    set_camera(ax, "iso", frames=robot.frames(q))
    ax.set_title(_("robot 1 in perspective (seed 004, figure 34)") if title is None else title)
    return fig


def two_cases_figure(robot, q_second, wrong_S1):
    """The first robot's two cases side by side. Left, the rest pose (primer caso) with a red diamond
    where the seed's eq. (3) would put {S₁} (``wrong_S1``, x and y); right, the segundo caso
    ``q_second`` with the seed's triangle (l.169): hypotenuse the two links, legs x and y."""
    fig = new_figure((10, 5))
    axes = fig.subplots(1, 2)
    draw(axes[0], robot, [0, 0], "primer caso: θ0 = θ1 = 0")
    wx, wy = float(wrong_S1[0]), float(wrong_S1[1])
    axes[0].plot([wx], [wy], "D", mfc="none", mec="crimson", ms=10, mew=2.5)
    axes[0].annotate(_("eq. (3) puts {S1} here\n(erratum 004-1)"), (wx, wy),
                     xytext=(-10, -36), textcoords="offset points", color="crimson")
    draw(axes[1], robot, q_second, "segundo caso: θ0 = −60°, θ1 = 90°")
    px, py = (float(v) for v in robot.fk(q_second)[:2, 3])
    axes[1].fill([0, px, px], [0, 0, py], color="0.85", zorder=0)
    axes[1].plot([0, px, px], [0, 0, py], ls="--", color="0.35", lw=1.2)
    axes[1].annotate("x = (l1 + l2)·cos 30°", (px / 2, 0), xytext=(0, -16), textcoords="offset points",
                     ha="center")
    axes[1].annotate("y = (l1 + l2)·sin 30°", (px, py / 2), xytext=(6, 0), textcoords="offset points",
                     va="center")
    return fig


def three_poses_figure(robot, poses):
    """``robot`` at each of ``poses`` (a list of ``(q, title)``), side by side."""
    fig = new_figure((4 * len(poses), 4.6))
    axes = np.atleast_1d(fig.subplots(1, len(poses)))
    for ax, (q, title) in zip(axes, poses):
        draw(ax, robot, q, title)
    return fig


def seed004_comparison(robot1, robot2) -> str:
    """Every case of seed 004: the pen as computed, the seed's correct lines (its numbers, rounded to
    three decimals as printed) and the seed's summary read as printed, with the erratum it needs."""
    L1, L2 = robot1.params["l1"], robot1.params["l2"]
    Lr, D = robot2.params["l"], 0.30
    cases = [  # (case, robot, joint values, what the seed's correct lines give, the seed's summary)
        ("primer caso", robot1, [0, 0], (L2, L1, 0), "x = l2, z = o (no y)  -> erratum 004-9"),
        ("segundo caso", robot1, deg2rad([-60, 90]), (0.866 * L1 + 0.866 * L2, 0.5 * L1 + 0.5 * L2, 0),
         f"x = {L1 + L2 * 0.866:.4f}, y = {L1 + L2 * 0.5:.4f}  -> erratum 004-10"),
        ("θ = −π/4", robot2, [deg2rad(-45), D], (0.707 * D + 0.707 * Lr, 0.707 * D + 0.707 * Lr, 0),
         f"x = y = {Lr + D * 0.707:.4f}  -> erratum 004-12"),
        ("en bandera", robot2, [0, 0], (0, Lr, 0), "y = 1  -> erratum 004-14"),
        (_("reader's exercise"), robot2, [deg2rad(-90), robot2.qlim[1][1]], None, "l = d_max  -> erratum 004-15"),
    ]
    header = (_("case"), _("computed pen position"), _("seed (l.)"), _("agree"), _("seed's summary"))
    rows = ["{:18} {:32} {:22} {:6} {}".format(*header)]
    for name, robot, q, seed, summary in cases:
        pen = robot.fk(q)[:3, 3]
        agree = "-" if seed is None else str(np.allclose(pen, seed, atol=1e-3))
        seed_text = _("(not given)") if seed is None else fmt(seed, 3)
        rows.append(f"{name:18} {fmt(pen):32} {seed_text:22} {agree:6} {summary}")
    return "\n".join(rows)
