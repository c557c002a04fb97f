"""What notebook 04 (the P-R mechanism and the two spaces) needs to print, check and draw.

The lesson's cells stay short: they state the formula or call the solver, and
the bookkeeping (formatting a vector, substituting a robot's lengths, looping
over targets, laying out a figure) is here.

- :func:`fmt`, :func:`show` — a vector as ``(x, y, …)``, a matrix as LaTeX
- :func:`branch_residuals` — sympy's check of both inverse-kinematics branches (erratum 003-1)
- :func:`ik_report`, :func:`branches_within_limits` — the solver's answers for targets, checked
- :func:`workspace_report` — the stadium the P-R mechanism reaches, from its forward kinematics
- :func:`compare_methods` — seed 003's geometric formulas against matrices and a DH table
- :func:`pr_mechanism_figure` — the P-R mechanism with its joint variables and lengths labelled
- :func:`geometric_examples_figure` — the two mechanisms of the geometric method, side by side
"""
from __future__ import annotations

import numpy as np
import sympy as sp

from ...errors import DHLabError
from ...i18n import _
from ...ik import pr_mechanism_ik
from ...units import rad2deg
from ...validation import describe
from ...views.figures import new_figure
from ...views.view import robot_view
from ...views.viewbase import one_pose
from .figures_common import label, triad
from .printing import fmt, show  # fmt: fixed decimals: (0.500000, 0.000000, 1.000000)

__all__ = ["fmt", "show", "branch_residuals", "ik_report", "branches_within_limits", "workspace_report",
           "compare_methods", "pr_mechanism_figure", "geometric_examples_figure"]




def branch_residuals() -> dict:
    """FK(branch) − (x, y) for branch A, branch B and the slide's q1 paired with q2B, simplified.

    Symbols: target (x, y) real, lengths l1, l2 positive. Zero means the branch reaches
    every reachable target; the slide's formula leaves −2·√(l2² − y²) in x (erratum 003-1).
    """
    x, y = sp.symbols("x y", real=True)
    l1, l2 = sp.symbols("l1 l2", positive=True)
    root = l2 * sp.sqrt(1 - (y / l2) ** 2)            # = l2·|cos q2| on both branches
    branches = {
        "branch A": (x - l1 - root, sp.asin(y / l2)),
        "branch B": (x - l1 + root, sp.pi - sp.asin(y / l2)),
        "the slide's q1 with q2B": (x - l1 - l2 * sp.cos(sp.asin(y / l2)), sp.pi - sp.asin(y / l2)),
    }

    def fk(q1, q2):                                   # seed 003's forward kinematics
        return sp.Matrix([q1 + l1 + l2 * sp.cos(q2), l2 * sp.sin(q2)])

    return {name: tuple(sp.simplify(fk(*q) - sp.Matrix([x, y]))) for name, q in branches.items()}


def ik_report(robot, targets) -> str:
    """For each target (x, y): the solver's message, then each solution checked by the forward kinematics.

    An angle beyond ±180° is also given as the same direction within a turn.
    """
    lines = []
    for target in _targets(targets):
        solutions = pr_mechanism_ik(robot, *target)
        lines.append(_("target (x, y) = {target}: {message}").format(target=target, message=solutions.message))
        for name, q in zip("AB", solutions):
            degrees = float(rad2deg(q[1]))
            within_a_turn = (degrees + 180) % 360 - 180     # the same direction, in (−180°, 180°]
            same = _(" (the direction {angle:.6f}°)").format(angle=within_a_turn) \
                if abs(within_a_turn - degrees) > 1e-9 else ""
            lines.append(f"   {name}: q1 = {q[0]:.6f}, q2 = {q[1]:.6f} rad = {degrees:.6f}°{same}"
                         f"  -> FK = {fmt(robot.fk(q)[:2, 3])}")
    return "\n".join(lines)


def branches_within_limits(robot, x, y) -> str:
    """Each solution for (x, y) and whether its slider position q1 is within the slider's range."""
    lo, hi = robot.qlim[0]
    lines = [_("{name}: q1 = {q1:+.6f}, q2 = {q2:.2f}° -> within the slider's range [{lo:g}, {hi:g}]: {inside}")
             .format(name=name, q1=q[0], q2=float(rad2deg(q[1])), lo=lo, hi=hi, inside=bool(lo <= q[0] <= hi))
             for name, q in zip("AB", pr_mechanism_ik(robot, x, y))]
    return "\n".join(lines) or _("no solution for ({x:g}, {y:g})").format(x=x, y=y)


def workspace_report(robot, samples: tuple[int, int] = (21, 73)) -> str:
    """Where the P-R mechanism's end effector goes over its joint limits, and how far it strays from
    the segment the revolute joint slides along (at most l2: the workspace is a stadium)."""
    (lo, hi), lim2 = robot.qlim
    q1s, q2s = np.linspace(lo, hi, samples[0]), np.linspace(*lim2, samples[1])
    points = np.array([robot.fk([a, b])[:2, 3] for a in q1s for b in q2s])
    elbow_from, elbow_to = lo + robot.params["l1"], hi + robot.params["l1"]   # where the revolute joint can be
    to_segment = np.hypot(points[:, 0] - np.clip(points[:, 0], elbow_from, elbow_to), points[:, 1])
    return _("the revolute joint slides from x = {a:g} to x = {b:g}\n"
             "the end effector: x from {x0:g} to {x1:g}, y from {y0:g} to {y1:g}\n"
             "largest distance from the segment: {d:g} (= l2)").format(
        a=elbow_from, b=elbow_to, x0=points[:, 0].min(), x1=points[:, 0].max(),
        y0=points[:, 1].min(), y1=points[:, 1].max(), d=to_segment.max())


def compare_methods(matrices, dh_table, geometric, configurations) -> str:
    """Seed 003's geometric position formula (a sympy column in the robot's joint symbols and
    length names) against the matrix chain ``matrices`` and the DH table ``dh_table``: equal as
    formulas, and the three positions at each configuration (revolute joints in degrees), on one
    line when they agree to 1e-9."""
    if not isinstance(geometric, sp.MatrixBase) or geometric.shape != (3, 1):
        raise DHLabError(f"geometric must be a 3×1 sympy Matrix (x_p, y_p, z_p), got {describe(geometric)}.")
    same = sp.simplify(matrices.fk_sym(simplify=True)[:3, 3] - geometric) == sp.zeros(3, 1)
    lengths = {sp.Symbol(name): value for name, value in matrices.params.items()}
    lines = [_("lengths {params}").format(params=matrices.params),
             _("matrices' position == geometric formulas: {same}").format(same=same)]
    for q in configurations:
        by_formula = geometric.subs(lengths | dict(zip(matrices.q_symbols, q))).evalf()
        shown = ", ".join(f"{float(rad2deg(v)):g}°" if link.is_revolute else f"{float(v):g}"
                          for link, v in zip(matrices.links, q))
        positions = [np.asarray(by_formula, dtype=float).ravel(), matrices.fk(q)[:3, 3], dh_table.fk(q)[:3, 3]]
        if all(np.allclose(p, positions[0], atol=1e-9) for p in positions):   # one line when all three agree
            lines.append(_("q = ({q}): geometric = matrices = DH = {p}").format(q=shown, p=fmt(positions[0])))
        else:
            lines.append(_("q = ({q}): geometric {g}, matrices {m}, DH {d}").format(
                q=shown, g=fmt(positions[0]), m=fmt(positions[1]), d=fmt(positions[2])))
    return "\n".join(lines)


def pr_mechanism_figure(robot, q):
    """Seed 003's P-R mechanism at ``q`` = (q1, q2 in radians), seen in its plane: the slider's rail
    (its range grey), the slider, the offset l1, the revolute joint, the arm l2 and the end effector
    (x, y), each length and joint variable labelled, and the base frame {S0}."""
    q1, q2 = one_pose(robot, q)
    l1, l2 = robot.params["l1"], robot.params["l2"]
    lo, hi = robot.qlim[0]
    if not lo <= q1 <= hi:
        raise DHLabError(f"q1 = {q1:g} is outside the slider's range [{lo:g}, {hi:g}]: give a q1 within it.")
    joint = np.array([q1 + l1, 0.0])
    tip = np.asarray(robot.fk([q1, q2])[:2, 3], dtype=float)
    fig = new_figure((9, 3.8))
    ax = fig.add_subplot(1, 1, 1)
    ax.plot([lo, hi], [0, 0], color="0.82", lw=10, solid_capstyle="butt", zorder=0)            # the slider's range
    label(ax, (hi, -0.12), f"${lo:g} \\leq q_1 \\leq {hi:g}$", color="0.35", ha="right", fontsize=12)
    ax.add_patch(_rectangle((q1 - 0.12, -0.07), 0.24, 0.14))                                   # the slider
    ax.plot([q1, joint[0]], [0, 0], color="0.25", lw=5, zorder=1)                              # the offset l1
    ax.plot(*np.array([joint, tip]).T, color="0.25", lw=5, zorder=1, solid_capstyle="round")   # the arm l2
    ax.plot(*joint, "o", ms=14, mfc="#6a9fd4", mec="black", zorder=3)                          # the revolute joint
    ax.plot(*tip, "*", ms=18, mfc="orange", mec="black", zorder=3)                             # the end effector
    ax.plot([joint[0], joint[0] + 0.8 * l2], [0, 0], ":", color="0.4", lw=1.5)                 # q2 is measured from +x
    arc = np.linspace(0, q2, 30)
    ax.plot(joint[0] + 0.35 * l2 * np.cos(arc), 0.35 * l2 * np.sin(arc), color="purple", lw=2)
    label(ax, joint + 0.5 * l2 * np.array([np.cos(q2 / 2), np.sin(q2 / 2)]), "$q_2$", color="purple")
    for start, end, text in ((0.0, q1, "$q_1$"), (q1, joint[0], r"$\ell_1$")):                # dimension lines
        ax.annotate("", (end, -0.3), (start, -0.3), arrowprops=dict(arrowstyle="<->", lw=1.5))
        label(ax, ((start + end) / 2, -0.4), text)
    normal = np.array([-np.sin(q2), np.cos(q2)])
    label(ax, (joint + tip) / 2 + 0.12 * normal, r"$\ell_2$")
    label(ax, tip + np.array([0.0, 0.15]), f"$(x, y) = ({tip[0]:.3f}, {tip[1]:.3f})$")
    triad(ax, np.eye(4), 0.3, sub="0", shifts=[(0, -0.12), (0, 0), (0, 0)])
    label(ax, (-0.14, -0.12), r"$\{S_0\}$")
    ax.set_aspect("equal")
    right = max(hi, joint[0] + l2, tip[0]) + 0.3
    ax.set(xlim=(-0.35, right), ylim=(-0.55, max(l2, tip[1]) + 0.35), xticks=[], yticks=[])
    ax.set_title(_("P-R mechanism (seed 003) at $q_1 = {q1:g}$, $q_2 = {q2:g}°$").format(
        q1=q1, q2=float(rad2deg(q2))))
    for side in ax.spines.values():
        side.set_visible(False)
    return fig


def _rectangle(corner, width, height):
    from matplotlib.patches import Rectangle  # lazy: matplotlib on first picture
    return Rectangle(corner, width, height, facecolor="#c8913a", edgecolor="black", zorder=0.5)


def geometric_examples_figure(examples):
    """The mechanisms of the geometric method side by side: ``examples`` is a list of (robot, q, title)."""
    fig = new_figure((11, 5.2))
    for k, (robot, q, title) in enumerate(examples):
        ax = fig.add_subplot(1, len(examples), k + 1, projection="3d")
        view = robot_view(robot, q, ax=ax, planar=False)
        view.setup_axes(ax)
        ax.set_title(title)
    return fig


def _targets(targets) -> list[tuple[float, float]]:
    try:
        pairs = [tuple(float(v) for v in t) for t in targets]
    except (TypeError, ValueError):
        pairs = None
    if not pairs or any(len(p) != 2 for p in pairs):
        raise DHLabError(f"targets must be a list of (x, y) pairs, e.g. [(2.0, 0.25)], got {describe(targets)}.")
    return pairs
