"""What notebook 06 (worked DH examples) needs to read the slides, check, print and watch.

The lesson's cells stay short: they build a robot, show its table or matrices and
call one of these.

- :func:`from_slide`, :func:`compare_with_slide` — a matrix printed on seed 002's slides, read into sympy
  and compared with the one the DH table gives
- :func:`check_cases` — a robot's poses against the verified cases of ``seed_cases.json``
- :func:`read_rows_at_zero` — a DH table read off the frames at q = 0, row by row (rules 10–13)
- :func:`hand_derived_003` — seed 003's six link matrices, derived by hand, independently of the code
- :func:`wrist_centre`, :func:`wrist_centre_check`, :func:`elbow_flipped` — the spherical wrist
- :func:`wrist_centre_panel` — a teach panel with the wrist centre drawn and printed
"""
from __future__ import annotations

import numpy as np
import sympy as sp

from ...data import load as load_data
from ...errors import DHLabError
from ...i18n import _
from ...units import deg2rad
from ...validation import describe
from .lesson_dh_convention import fmt  # notebook 5's: (0.5, 0, 1), trailing zeros dropped

__all__ = ["fmt", "from_slide", "compare_with_slide", "check_cases", "signed_angle", "read_rows_at_zero",
           "hand_derived_003", "wrist_centre", "wrist_centre_check", "elbow_flipped", "wrist_centre_panel"]

WRIST = 4          # the wrist centre is the origin of frame 4 (= frame 5) on both 6-DOF arms


# --- the slides' matrices ---------------------------------------------------------------------------
def from_slide(latex: str, robot) -> sp.Matrix:
    """A bmatrix printed on a slide as a sympy Matrix in the robot's own symbols
    ($C_k$, $S_k$: cosine and sine of joint k's variable; $l_k$, $d_k$: lengths and prismatic variables)."""
    # lazy: sympy on first symbolic use
    from sympy.parsing.sympy_parser import implicit_multiplication_application, parse_expr, standard_transformations
    if not isinstance(latex, str) or r"\begin{bmatrix}" not in latex:
        raise DHLabError(f"expected a slide's matrix as LaTeX with \\begin{{bmatrix}}, got {describe(latex)}.")
    body = latex.split(r"\begin{bmatrix}")[1].split(r"\end{bmatrix}")[0]
    names = {str(s): s for A in robot.link_matrices_sym() for s in A.free_symbols}
    for k, q in enumerate(robot.q_symbols, start=1):
        names |= {f"C{k}": sp.cos(q), f"S{k}": sp.sin(q), str(q): q}
    rules = standard_transformations + (implicit_multiplication_application,)
    rows = [[parse_expr(entry.replace("_", "").strip(), local_dict=names, transformations=rules)
             for entry in row.split("&")] for row in body.split(r"\\")]
    return sp.Matrix(rows)


def compare_with_slide(robot, printed: dict, show=None) -> None:
    """Say for each ^{i-1}A_i whether the slide's matrix equals the computed one for every value of
    the symbols, and display the two side by side (``show``: the links i to display, default all;
    ``printed``: {"0A1": {"latex": ..., "lines": [...]}, ...})."""
    from IPython.display import Math, display  # lazy: the notebook's own libraries, on first display
    shown = set(range(1, robot.n + 1)) if show is None else _links(show, robot.n)
    for i in range(1, robot.n + 1):
        key = f"{i - 1}A{i}"
        if key not in printed:
            raise DHLabError(f"the slide's matrices have no {key}: found {sorted(printed)}.")
        slide = from_slide(printed[key]["latex"], robot)
        same = sp.simplify(robot.A(i) - slide) == sp.zeros(4, 4)
        if i in shown:
            display(Math(rf"{{}}^{i - 1}A_{i}:\quad \text{{slide (l.{printed[key]['lines'][0]})}}\ "
                         + printed[key]["latex"] + r"\qquad \text{computed}\ " + sp.latex(robot.compact(robot.A(i)))))
        print(_("{key}: computed == printed on the slide: {same}").format(key=key, same=same))


def _links(show, n: int) -> set[int]:
    try:
        links = {int(i) for i in show}
    except (TypeError, ValueError):
        links = None
    if links is None or not links <= set(range(1, n + 1)):
        raise DHLabError(f"show must list link numbers from 1 to {n}, e.g. show=[3], got {describe(show)}.")
    return links


# --- the verified cases -----------------------------------------------------------------------------
def check_cases(robot, prefix: str) -> str:
    """The end-effector position at every case of ``seed_cases.json`` whose id starts with ``prefix``,
    and whether the whole pose is the verified one (revolute joints shown in degrees)."""
    cases = [c for c in load_data("seed_cases")["cases"] if c["id"].startswith(prefix)]
    if not cases:
        raise DHLabError(f"no case of seed_cases.json starts with {prefix!r}; e.g. '002_4dof', '003_6dof'.")
    lines = []
    for case in cases:
        q = np.array(list(case["joint_values"].values()), dtype=float)
        T = robot.fk(q)
        shown = ", ".join(f"{np.degrees(v):g}°" if link.is_revolute else f"{v:g}" for link, v in zip(robot.links, q))
        lines.append(_("q = ({q}): p = {p}, as seed_cases.json: {same}").format(
            q=shown, p=fmt(T[:3, 3]), same=bool(np.allclose(T, case["expected_pose"], atol=1e-9))))
    return "\n".join(lines)


# --- a table read off the frames ----------------------------------------------------------------------
def signed_angle(u, v, axis) -> float:
    """The angle (degrees) that turns u onto v's direction about axis (right-hand rule)."""
    u, v, axis = (np.asarray(w, dtype=float) for w in (u, v, axis))
    return float(np.degrees(np.arctan2(np.cross(u, v) @ axis, u @ v)))


def read_rows_at_zero(robot) -> str:
    """Each row (θ_i, d_i, a_i, α_i) read between frames i-1 and i at q = 0, with the reason for θ's
    offset, and whether it is the robot's own row: θ turns x_{i-1} onto x_i about z_{i-1}, d slides
    along z_{i-1}, a along x_i, α turns z_{i-1} onto z_i about x_i (rules 10–13)."""
    F = robot.frames(robot.qz)
    lengths = {round(float(v), 9): name for name, v in robot.params.items()}
    lines = []
    for i in range(1, robot.n + 1):
        (O0, x0, z0), (O1, x1, z1) = ((T[:3, 3], T[:3, 0], T[:3, 2]) for T in F[i - 1:i + 1])
        theta, alpha = signed_angle(x0, x1, z0), signed_angle(z0, z1, x1)
        d, a = float((O1 - O0) @ z0), float((O1 - O0) @ x1)
        turned = abs(theta) > 1e-9
        offset = f"q{i}" + (f" {'+' if theta > 0 else '−'} {abs(theta):g}°" if turned else "")
        why = (_("x{a} = {xa} must turn {t:+g}° about z{a} = {za} to be parallel to x{b} = {xb}").format(
                   a=i - 1, b=i, xa=fmt(x0), t=theta, za=fmt(z0), xb=fmt(x1)) if turned
               else _("x{a} and x{b} are already parallel, {xb}").format(a=i - 1, b=i, xb=fmt(x1)))
        row = (offset, lengths.get(round(d + 0, 9), f"{d + 0:g}"), lengths.get(round(a + 0, 9), f"{a + 0:g}"),
               f"{alpha + 0:g}°")
        link = robot.links[i - 1]
        own = [float(sp.sympify(v).subs(robot.params)) for v in (link.offset, link.d, link.a, link.alpha)]
        same = np.allclose([np.radians(theta), d, a, np.radians(alpha)], own)
        lines.append(_("row {i}: {why}; so ({row}); the slide's row: {same}").format(
            i=i, why=why, row=", ".join(row), same=bool(same)))
    return "\n".join(lines)


def hand_derived_003(robot) -> dict[int, sp.Matrix]:
    """Seed 003's six link matrices ^{i-1}A_i, derived by hand from its table (rule 14), in the
    robot's symbols q1…q6, l1…l4: typed here, independently of the code that computes them."""
    q = robot.q_symbols
    if len(q) != 6:
        raise DHLabError(f"hand_derived_003 is for seed 003's 6-DOF arm, got a robot with {len(q)} joints.")
    l1, l2, l3, l4 = sp.symbols("l1:5")
    C = lambda k: sp.cos(q[k - 1])
    S = lambda k: sp.sin(q[k - 1])
    rows = {
        1: [[C(1), 0, S(1), 0], [S(1), 0, -C(1), 0], [0, 1, 0, l1]],
        2: [[-S(2), -C(2), 0, -l2 * S(2)], [C(2), -S(2), 0, l2 * C(2)], [0, 0, 1, 0]],
        3: [[S(3), 0, C(3), 0], [-C(3), 0, S(3), 0], [0, -1, 0, 0]],
        4: [[S(4), 0, C(4), 0], [-C(4), 0, S(4), 0], [0, -1, 0, l3]],
        5: [[C(5), 0, S(5), 0], [S(5), 0, -C(5), 0], [0, 1, 0, 0]],
        6: [[C(6), -S(6), 0, 0], [S(6), C(6), 0, 0], [0, 0, 1, l4]],
    }
    return {i: sp.Matrix(r + [[0, 0, 0, 1]]) for i, r in rows.items()}


# --- the spherical wrist ----------------------------------------------------------------------------
def wrist_centre(robot, q_arm_deg) -> np.ndarray:
    """The wrist centre O_4 for the arm's first three joints (degrees), the wrist at zero."""
    q = list(np.asarray(q_arm_deg, dtype=float).ravel())
    if len(q) != 3:
        raise DHLabError(f"give the arm's three joint angles (q1, q2, q3) in degrees, got {describe(q_arm_deg)}.")
    return robot.frames(deg2rad(q + [0.0] * (robot.n - 3)))[WRIST][:3, 3]


def wrist_centre_check(robots, arm_poses: int = 100, wrist_poses: int = 50, seed: int = 3) -> str:
    """For each robot: random arm poses (q1, q2, q3), each with random wrist poses (q4, q5, q6): do
    O_4 and O_5 coincide, does the wrist centre stay still, and is p = p_w + l4·a?"""
    rng = np.random.default_rng(seed)
    lines = []
    for robot in robots:
        largest_wrist_move, largest_hand_move, worst_p, together = 0.0, 0.0, 0.0, True
        for arm_q in rng.uniform(-np.pi, np.pi, size=(arm_poses, 3)):
            Q = np.column_stack([np.tile(arm_q, (wrist_poses, 1)), rng.uniform(-np.pi, np.pi, size=(wrist_poses, 3))])
            F = robot.frames(Q)
            wrist, hand = F[:, WRIST, :3, 3], F[:, 6, :3, 3]
            together &= bool(np.allclose(wrist, F[:, 5, :3, 3]))
            largest_wrist_move = max(largest_wrist_move, np.linalg.norm(wrist - wrist[0], axis=1).max())
            largest_hand_move = max(largest_hand_move, np.linalg.norm(hand - hand[0], axis=1).max())
            worst_p = max(worst_p, np.abs(hand - (wrist + robot.params["l4"] * F[:, 6, :3, 2])).max())
        lines.append(_("{name}: O4 = O5 always: {together}; the wrist centre moves less than 1e-12: {still}; "
                       "the end effector moves up to {hand:.3f}; p = p_w + l4·a: {p}").format(
            name=robot.name, together=together, still=largest_wrist_move < 1e-12, hand=largest_hand_move,
            p=worst_p < 1e-12))
    return "\n".join(lines)


def elbow_flipped(robot, q_arm_deg) -> tuple[float, float, float]:
    """The same wrist centre with the elbow bent the other way: link 2 mirrored across the line
    shoulder O_1 → wrist centre, for an arm whose joints 2 and 3 turn about parallel axes z1 ∥ z2."""
    q1, q2, q3 = (float(v) for v in np.asarray(q_arm_deg, dtype=float).ravel())
    F = robot.frames(deg2rad([q1, q2, q3] + [0.0] * (robot.n - 3)))
    shoulder, elbow, wrist, axis = F[1][:3, 3], F[2][:3, 3], F[WRIST][:3, 3], F[1][:3, 2]
    u, w = elbow - shoulder, wrist - shoulder
    u_new = 2 * (u @ w) / (w @ w) * w - u                                   # link 2, mirrored
    turn_2 = signed_angle(u, u_new, axis)                                   # how much more q2 turns
    turn_23 = signed_angle(wrist - elbow, wrist - (shoulder + u_new), axis)  # how much more q2 + q3 turns
    return (q1, q2 + turn_2, q3 + turn_23 - turn_2)


def wrist_centre_panel(robot, q=None):
    """A teach panel of ``robot`` with its wrist centre as a purple dot, and an HTML line under it
    giving the centre's coordinates; returns (panel, line). Display both: ``display(panel, line)``."""
    import ipywidgets as widgets  # lazy: the notebook's own libraries, on first display

    from ...views.panels.teach import teach  # lazy: the live views load ipywidgets and mplot3d

    line, dot = widgets.HTML(), []

    def show_wrist(q):
        centre = robot.frames(q)[WRIST][:3, 3].round(3) + 0.0
        line.value = _("<b>wrist centre</b> p<sub>w</sub> = O<sub>4</sub> = ({x:.3f}, {y:.3f}, {z:.3f})").format(
            x=centre[0], y=centre[1], z=centre[2])
        if dot:                                        # once the panel exists: move the dot too
            dot[0].set_data_3d(*centre[:, None])       # (the panel draws right after this call)

    panel = teach(robot, q=q, on_change=show_wrist)
    dot.append(panel.view.ax.plot([], [], [], "o", color="purple", ms=9)[0])
    panel.view.live.add_moving(dot[0])
    panel.set_q(panel.q)                               # first update: the dot appears
    return panel, line
