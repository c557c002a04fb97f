"""Exercise checks for the DH notebooks: 5 (the convention), 6 (worked examples), 7 (the SSRMS).

Built on :mod:`dhlab.exercises` (its :class:`~dhlab.exercises.Feedback`,
:class:`~dhlab.exercises.Exercise`, ``check_matrix`` and ``check_value``), with
the checks that need the geometry of DH frames. The feedback names the joint
and the quantity that is off ("joint 2: your α1 is -90°, but z0 and z1 are
parallel"). DH frames are not unique (seed 002 lists the free choices), so a
table is never compared with one answer key: :func:`check_table` compares what
every valid answer shares, the joint axes as directed lines in space and the
end effector's position, at q = 0 and at 50 random configurations.

>>> ex = exercise("5.1")
>>> ex.check({1: "skew", 2: "parallel", 3: "intersect"})
✓ Exercise 5.1: correct: the cases of x1 … x3 are right.
>>> check_table([("q1", 0.5, 0.2, -90), ("q2 - 90", 0, 0.5, -90), ("q3", 0, 0, -90), ("q4", 0.5, 0, 0)])
✗ your table is not right yet: fix this first (the joints after it are checked next).
  • joint 3: your α2 is -90°, but z1 and z2 (the axes of joints 2 and 3) are parallel: α2 must be 0° or 180°.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import sympy as sp

from .. import robots
from ..dh import DHRobot
from .exercises import NOT_ANSWERED, Exercise, Feedback, check_matrix, check_value
from ..lines import Line, closest_points, relation
from ..transforms import Rx, Rz, dh_matrix, trans
from ..validation import DHLabError

__all__ = [
    "exercise", "available",
    "Relation", "axis_relation", "four_axis_arm", "show_axes",
    "check_x_cases", "row_exercise_frames", "check_dh_row", "check_table", "compare_robots",
    "link_exercise_robot", "check_link_matrix", "WRIST_Q_DEG", "check_wrist_centre",
    "thlist_slot", "check_thlist_slots", "parallel_pairs", "check_parallel_pairs",
    "printed_key_position", "check_key_jump",
]

ANGLE_TOL = 0.5          # degrees: typed answers are read to half a degree


# --- feedback in the style of dhlab.exercises ------------------------------------------------
def _blank(x) -> bool:
    """Not answered: None or ``...`` (also inside a list, tuple or dict)."""
    if x is None or x is Ellipsis:
        return True
    if isinstance(x, (list, tuple)):
        return any(_blank(v) for v in x)
    if isinstance(x, dict):
        return any(v is Ellipsis for v in x.values())
    return False


def _unanswered(name: str) -> Feedback:
    return Feedback("unanswered", f"{name}: {NOT_ANSWERED}")


def _right(name: str, items=()) -> Feedback:
    return Feedback("correct", f"correct: {name} {'are' if name.startswith('the cases') else 'is'} right.",
                    items)


def _wrong(name: str, items, why: str = "") -> Feedback:
    verb = "are" if name.startswith("the cases") else "is"
    return Feedback("wrong", f"{name} {verb} not right yet" + (f": {why}" if why else "."), items)


def _num(x: float, digits: int = 4) -> str:
    """A number for a message: 0.2, -90, 12 (no -0)."""
    text = f"{round(float(x), digits) + 0.0:.{digits}f}"
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return "0" if text == "-0" else text


def _vec(v, digits: int = 3) -> str:
    return "(" + ", ".join(_num(x, digits) for x in v) + ")"


def _read_numbers(answer, count: int, what: str):
    """``count`` finite floats, or (None, the reason they cannot be read)."""
    if isinstance(answer, str):
        return None, f"give {count} numbers {what}, not text."
    try:
        values = [float(v) for v in answer]
    except (TypeError, ValueError):
        return None, f"give {count} numbers {what}, got {answer!r}."
    if len(values) != count or not all(math.isfinite(v) for v in values):
        return None, f"give {count} finite numbers {what}, got {answer!r}."
    return values, ""


# --- lines in space (the geometry is dhlab.lines) ----------------------------------------------
@dataclass(frozen=True)
class Relation:
    """How two lines lie: ``kind`` is 'intersect', 'parallel', 'skew' or 'coincident';
    ``distance`` is the length of their common normal, ``angle`` the angle between
    their directions in degrees (0…180: 180 means parallel but opposite).
    :func:`dhlab.lines.relation`'s result, rounded for messages."""
    kind: str
    distance: float
    angle: float

    @property
    def is_parallel(self) -> bool:
        return self.kind in ("parallel", "coincident")


def axis_relation(p1, u1, p2, u2, tol: float = 1e-9) -> Relation:
    """The relation of line 1 (through ``p1``, direction ``u1``) and line 2, by
    :func:`dhlab.lines.relation`. ``tol`` is relative: lines closer than ``tol`` times
    the size of the coordinates (at least 1) meet; directions less than 1e-9 rad apart
    are parallel.

    >>> axis_relation([0, 0, 0], [0, 0, 1], [1, 0, 5], [0, 0, -1])
    Relation(kind='parallel', distance=1.0, angle=180.0)
    >>> axis_relation([0, 0, 0], [0, 0, 1], [0.2, 0, 0.5], [0, 1, 0]).kind
    'skew'
    """
    a, b = Line(p1, u1), Line(p2, u2)
    scale = max(1.0, float(np.abs(a.point).max()), float(np.abs(b.point).max()))
    rel = relation(a, b, tol=tol * scale, angle_tol=1e-9)
    return Relation(rel.kind, round(rel.distance, 12) + 0.0, round(rel.angle, 9) + 0.0)


def _axes_of(robot, q):
    """Joint axes of ``robot`` at ``q``: points (n,3) and unit directions (n,3); joint k is z_(k-1)."""
    F = np.asarray(robot.frames(q), dtype=float)
    return F[:-1, :3, 3], F[:-1, :3, 2]


def _row_of(robot, i: int):
    """(θ, d, a, α) of link i at q = 0, read from its numeric matrix (angles in degrees)."""
    A = np.asarray(robot.A(i, 0.0), dtype=float)
    theta = math.atan2(A[1, 0], A[0, 0])
    a = A[0, 3] * math.cos(theta) + A[1, 3] * math.sin(theta)
    return math.degrees(theta), float(A[2, 3]), float(a), math.degrees(math.atan2(A[2, 1], A[2, 2]))


# --- the exercise robot of notebook 5 --------------------------------------------------------
def four_axis_arm() -> DHRobot:
    """Notebook 5's exercise arm: four revolute joints whose consecutive axes show the
    three cases of x_i (skew, parallel, intersecting). Lengths in metres."""
    return DHRobot.from_table([("q1", 0.5, 0.2, -90), ("q2 - 90", 0, 0.5, 0), ("q3", 0, 0, -90),
                               ("q4", 0.5, 0, 0)], name="4-axis arm (exercise)", unit="m")


def show_axes(axes, tool=None, ax=None, length: float = 0.3, title: str = ""):
    """Draw joint axes ``(point, direction, kind)`` as arrows in 3D, labelled with the joint
    number; the positive sense is along the arrow (right-hand rule for a revolute joint).
    ``tool``: the end-effector point (or 4x4 pose), drawn as a star. Returns the Axes."""
    import matplotlib.pyplot as plt

    if ax is None:
        ax = plt.figure(figsize=(4.5, 3.6), dpi=72).add_subplot(projection="3d")
    points = [np.asarray(p, float) for p, _, _ in axes]
    for k, (p, u, kind) in enumerate(axes, start=1):
        p, u = np.asarray(p, float), np.asarray(u, float) / np.linalg.norm(u)
        ax.plot(*np.array([p - length * u, p + 1.6 * length * u]).T, ":", color="0.5")
        ax.quiver(*p, *(length * u), color="tab:blue", arrow_length_ratio=0.3, lw=2)
        ax.text(*(p + 1.15 * length * u), f" {k}", fontsize=9, color="tab:blue", weight="bold")
    if tool is not None:
        tool = np.asarray(tool, float)
        tool = tool[:3, 3] if tool.shape == (4, 4) else tool
        ax.plot(*tool[:, None], "*", color="darkorange", mec="k", ms=14)
        points.append(tool)
    P = np.array(points)
    centre = (P.min(axis=0) + P.max(axis=0)) / 2
    half = (P.max(axis=0) - P.min(axis=0)) / 2 + length
    half = np.maximum(half, 0.6 * half.max())            # no side much thinner than the others
    lo, hi = centre - half, centre + half
    ax.set(xlim=(lo[0], hi[0]), ylim=(lo[1], hi[1]), zlim=(lo[2], hi[2]), xlabel="x", ylabel="y",
           zlabel="z", title=title)
    ax.tick_params(labelsize=7)
    ax.locator_params(nbins=4)
    ax.set_box_aspect(hi - lo)
    return ax


# --- 5.1: the case of each x_i ------------------------------------------------------------------
_CASE_WORDS = (("intersec", "intersect"), ("corta", "intersect"), ("parallel", "parallel"),
               ("parale", "parallel"), ("skew", "skew"), ("cruza", "skew"), ("coinciden", "coincident"),
               ("same line", "coincident"))
_SAID = {"intersect": "the axes intersect", "parallel": "they are parallel", "skew": "they are skew",
         "coincident": "they are the same line"}
_FIX = {"intersect": "case 1: x{i} = ±(z{p} × z{i}), with O{i} at the intersection",
        "parallel": "case 2: x{i} lies on a common normal you choose (there are infinitely many)",
        "skew": "case 3: x{i} lies on their unique common normal",
        "coincident": "x{i} is any direction perpendicular to the line"}


def _read_case(value):
    """'intersect' / 'parallel' / 'skew' / 'coincident' from a word, 'case 2' or a number."""
    if isinstance(value, (int, np.integer)) and not isinstance(value, bool):
        return {1: "intersect", 2: "parallel", 3: "skew"}.get(int(value))
    text = str(value).strip().lower()
    for stem, kind in _CASE_WORDS:
        if stem in text:
            return kind
    for number, kind in (("1", "intersect"), ("2", "parallel"), ("3", "skew")):
        if text in (number, f"case {number}", f"caso {number}"):
            return kind
    return None


def _relation_text(rel: Relation, a: str, b: str) -> str:
    if rel.kind == "intersect":
        return f"{a} and {b} intersect (they meet in one point)"
    if rel.kind == "parallel":
        return f"{a} and {b} are parallel, {_num(rel.distance)} apart"
    if rel.kind == "skew":
        return (f"{a} and {b} are skew: they never meet and are not parallel (their common normal is "
                f"{_num(rel.distance)} long)")
    return f"{a} and {b} are the same line"


def check_x_cases(answer, robot=None) -> Feedback:
    """Check which case places x_i, i = 1 … n−1: ``{i: 'intersect' | 'parallel' | 'skew'}``
    (or 'case 1' …, or a list in the order x1, x2, …). Default robot: :func:`four_axis_arm`."""
    robot = four_axis_arm() if robot is None else robot
    count = robot.n - 1
    name = f"the cases of x1 … x{count}"
    if _blank(answer):
        return _unanswered(name)
    if isinstance(answer, (list, tuple)):
        answer = dict(enumerate(answer, start=1))
    if not isinstance(answer, dict):
        return _wrong(name, [f"give a dict {{i: case}} for i = 1 … {count}, not a {type(answer).__name__}."])
    missing = [i for i in range(1, count + 1) if i not in answer]
    if missing:
        return _wrong(name, [f"say the case of every x_i, i = 1 … {count}: x{missing[0]} is missing."])
    points, dirs = _axes_of(robot, robot.qz)
    items = []
    for i in range(1, count + 1):
        said = _read_case(answer[i])
        if said is None:
            items.append(f"x{i}: cannot read {answer[i]!r}: write 'intersect', 'parallel' or 'skew'.")
            continue
        rel = axis_relation(points[i - 1], dirs[i - 1], points[i], dirs[i])
        if rel.kind == "coincident" and said in ("coincident", "parallel", "intersect"):
            continue
        if said != rel.kind:
            items.append(f"x{i}: you said {_SAID[said]}, but {_relation_text(rel, f'z{i - 1}', f'z{i}')}. "
                         f"That is {_FIX[rel.kind].format(i=i, p=i - 1)}.")
    return _wrong(name, items) if items else _right(name)


# --- 5.2: one DH row from two frames ---------------------------------------------------------------
ROW_EXERCISE = (120.0, 0.3, 0.4, -90.0)       # θ, d, a, α of the hidden link (degrees, metres)


def row_exercise_frames():
    """The two frames of exercise 5.2: ({S_(i-1)}, {S_i}) in the world, 4x4 each."""
    theta, d, a, alpha = ROW_EXERCISE
    before = Rz(math.radians(30)) @ trans(0.2, -0.1, 0.3) @ Rx(math.radians(90))
    return before, before @ dh_matrix(math.radians(theta), d, a, math.radians(alpha))


def _angle_diff(a: float, b: float) -> float:
    """a − b in degrees, wrapped into (−180, 180]."""
    d = (a - b) % 360.0
    return d - 360.0 if d > 180.0 else d


def _true_row(before, after):
    A = np.linalg.solve(before, after)
    theta = math.atan2(A[1, 0], A[0, 0])
    alpha = math.atan2(A[2, 1], A[2, 2])
    a = A[0, 3] * math.cos(theta) + A[1, 3] * math.sin(theta)
    if not np.allclose(dh_matrix(theta, A[2, 3], a, alpha), A, atol=1e-9):
        raise DHLabError("these two frames are not related by a DH link: x_i must cross z_(i-1) at a "
                         "right angle.")
    return math.degrees(theta), float(A[2, 3]), float(a), math.degrees(alpha)


def check_dh_row(answer, frames=None) -> Feedback:
    """Check a DH row ``(θ, d, a, α)`` (angles in **degrees**) that carries ``frames[0]`` =
    {S_(i-1)} onto ``frames[1]`` = {S_i} (default: :func:`row_exercise_frames`)."""
    name = "your row (θ, d, a, α)"
    before, after = row_exercise_frames() if frames is None else frames
    if _blank(answer):
        return _unanswered(name)
    values, problem = _read_numbers(answer, 4, "(θ, d, a, α), angles in degrees")
    if problem:
        return _wrong(name, [problem])
    theta, d, a, alpha = values
    t_theta, t_d, t_a, t_alpha = _true_row(before, after)
    scale = max(1.0, abs(t_d), abs(t_a))
    near = lambda x, y: abs(x - y) <= 1e-3 * scale
    same_angle = lambda x, y: abs(_angle_diff(x, y)) <= ANGLE_TOL
    if not (near(d, t_d) and near(a, t_a)) and near(d, t_a) and near(a, t_d):
        return _wrong(name, ["d and a are swapped: the columns are θ, d, a, α; d is measured along "
                             "z_(i−1), a along x_i."])
    items = []
    if not same_angle(theta, t_theta):
        hint = ""
        if same_angle(theta, -t_theta):
            hint = " Check the sense: positive is counter-clockwise seen from the tip of z_(i−1)."
        elif same_angle(theta + 180, t_theta):
            hint = " It is 180° off: your x_i points the other way."
        items.append(f"θ: turning x_(i−1) by your θ = {_num(theta)}° about z_(i−1) does not make it "
                     f"parallel to x_i (rule 10).{hint}")
    if not near(d, t_d):
        hint = " The sign: d is positive towards +z_(i−1)." if near(d, -t_d) else ""
        items.append(f"d: your d = {_num(d)} is not the distance along z_(i−1) from O_(i−1) to the "
                     f"point where x_i crosses z_(i−1) (rule 11).{hint}")
    if not near(a, t_a):
        hint = (" The sign: a is measured along +x_i, from z_(i−1) to O_i (a negative a means x_i points "
                "from O_i back towards z_(i−1), note 002-n1)." if near(a, -t_a) else "")
        items.append(f"a: your a = {_num(a)} is not the distance along x_i from z_(i−1) to O_i "
                     f"(rule 12).{hint}")
    if not same_angle(alpha, t_alpha):
        if same_angle(t_alpha, 0) or same_angle(t_alpha, 180):
            items.append(f"α: your α is {_num(alpha)}°, but z_(i−1) and z_i are parallel: α is 0° or "
                         "180° (0° when they point the same way).")
        elif same_angle(alpha, 0) or same_angle(alpha, 180):
            items.append(f"α: your α is {_num(alpha)}°, which keeps z_i parallel to z_(i−1), but they "
                         f"are at {_num(abs(t_alpha), 1)}° to each other.")
        elif same_angle(alpha, -t_alpha):
            items.append("α: the size is right but not the sign: turning z_(i−1) by α about x_i "
                         "(right-hand rule: counter-clockwise seen from the tip of x_i) must bring it "
                         "onto z_i (rule 13).")
        else:
            items.append(f"α: turning z_(i−1) by your α = {_num(alpha)}° about x_i does not bring it "
                         "onto z_i (rule 13).")
    if items:
        return _wrong(name, items)
    return _right(name, ["Rz(θ)·Tz(d)·Tx(a)·Rx(α) carries {S_(i−1)} exactly onto {S_i}."])


# --- 5.3 and 6.3: a whole table, checked fairly --------------------------------------------------
_TABLE_EXERCISES = {"arm": four_axis_arm, "seed002_4dof": robots.seed002_4dof}


def compare_robots(student, reference, samples: int = 50, seed: int = 0) -> list:
    """What is wrong with ``student`` (a DHRobot) as a model of ``reference``, as messages
    (empty when right). Compared: each joint axis as a directed line, and the end-effector
    position, at q = 0 and ``samples`` random configurations within the reference's limits.
    A prismatic joint's axis is compared as a direction only: where its line lies is a free
    choice (ERRATA 002-n2). Only the first wrong joint is explained: the later ones hang from it."""
    n = reference.n
    if student.n != n:
        return [f"your table has {student.n} rows, but the robot has {n} joints: one row per joint."]
    for k, (s, r) in enumerate(zip(student.links, reference.links), start=1):
        if s.is_revolute != r.is_revolute:
            want, var, got = ("revolute (R)", "θ", "d") if r.is_revolute else ("prismatic (P)", "d", "θ")
            return [f"joint {k} is {want}: its variable belongs in {var}{k}, but your row {k} makes "
                    f"{got}{k} the variable."]
    rng = np.random.default_rng(seed)
    lo, hi = reference.qlim.T
    Q = np.vstack([np.zeros(n), lo + (hi - lo) * rng.random((samples, n))])
    tol = 1e-6 * max(1.0, reference.reach())
    for q in Q:
        sp_, su = _axes_of(student, q)
        rp, ru = _axes_of(reference, q)
        for k in range(1, n + 1):
            # a prismatic axis is a direction: where its line lies is free (ERRATA 002-n2)
            off_line = 0.0 if reference.links[k - 1].is_prismatic else \
                Line(rp[k - 1], ru[k - 1]).distance_to_point(sp_[k - 1])
            if su[k - 1] @ ru[k - 1] < 1 - 1e-9 or off_line > tol:
                return [_diagnose_axis(student, reference, k, q, tol)]
        p_s = np.asarray(student.fk(q), dtype=float)[:3, 3]
        p_r = np.asarray(reference.fk(q), dtype=float)[:3, 3]
        if np.linalg.norm(p_s - p_r) > tol:
            return [f"every joint axis is right, but the end effector is at {_vec(p_s)} {_at(q)}, not at "
                    f"{_vec(p_r)}: check the last row (θ{n}'s offset, d{n}, a{n})."]
    return []


def _at(q) -> str:
    if not np.any(q):
        return "at q = 0"
    return "at q = " + _vec([math.degrees(v) for v in q], 1) + " (revolute joints in degrees)"


def _diagnose_axis(student, reference, k: int, q, tol: float) -> str:
    """Why joint k's axis (z_(k-1), placed by row k-1) is not where it should be."""
    i = k - 1
    if i == 0:
        return "joint 1: z0 must lie on joint 1's axis, as drawn."
    _, _, a, alpha = _row_of(student, i)
    rp, ru = _axes_of(reference, q)
    sp_, su = _axes_of(student, q)
    ref = axis_relation(rp[i - 1], ru[i - 1], rp[i], ru[i])
    ref_angle = _num(min(ref.angle, 180 - ref.angle), 1)
    axes_name = f"z{i - 1} and z{i} (the axes of joints {i} and {k})"
    yours = f"joint {k}: your α{i} is {_num(alpha)}°"
    stu_parallel = abs(math.sin(math.radians(alpha))) < 1e-6
    if ref.is_parallel and not stu_parallel:
        return f"{yours}, but {axes_name} are parallel: α{i} must be 0° or 180°."
    if not ref.is_parallel and stu_parallel:
        return f"{yours}, which keeps z{i} parallel to z{i - 1}, but {axes_name} are at {ref_angle}° to each other."
    stu_angle = abs(alpha) if abs(alpha) <= 180 else 360 - abs(alpha)
    if min(abs(stu_angle - ref.angle), abs(stu_angle - (180 - ref.angle))) > ANGLE_TOL:
        return (f"{yours}: it turns z{i} {_num(stu_angle, 1)}° away from z{i - 1}, but {axes_name} "
                f"are at {ref_angle}° to each other.")
    if su[i] @ ru[i] < 0:
        return (f"joint {k}: z{i} points against joint {k}'s positive sense (the way its variable grows): change the "
                f"sign of α{i}, or turn x{i} the other way (θ{i} + 180° and a{i} → −a{i}).")
    if abs(abs(a) - ref.distance) > tol:
        what = f"they intersect, so a{i} = 0" if ref.kind in ("intersect", "coincident") \
            else f"they are {_num(ref.distance)} apart"
        return f"joint {k}: your a{i} = {_num(a)} puts {axes_name} {_num(abs(a))} apart, but {what}."
    if not ref.is_parallel:
        # where the common normal of z_(i-1) and z_i meets z_(i-1): student's vs reference's
        foot_ref, _ = closest_points(Line(rp[i - 1], ru[i - 1]), Line(rp[i], ru[i]))
        foot_stu, _ = closest_points(Line(sp_[i - 1], su[i - 1]), Line(sp_[i], su[i]))
        if abs(float((foot_stu - foot_ref) @ ru[i - 1])) > tol:
            also = ""
            if i >= 2 and axis_relation(rp[i - 2], ru[i - 2], rp[i - 1], ru[i - 1]).is_parallel:
                also = (f" (or d{i - 1}: z{i - 2} ∥ z{i - 1}, so d{i - 1} and d{i} slide along the same "
                        "direction and only their sum is fixed)")
            return (f"joint {k}: the axis has the right direction and distance from joint {i}'s axis, "
                    f"but sits at the wrong place along z{i - 1} {_at(q)}: check d{i}{also}.")
    theta = "θ" if student.links[i - 1].is_revolute else "the constant θ"
    return (f"joint {k}: the axis has the right direction and distance from joint {i}'s axis, but is "
            f"turned about z{i - 1} {_at(q)}: check {theta}{i} (its offset: at q = 0 the robot must be "
            f"in the pictured pose) and the sign of a{i}.")


def _same_table(student, reference) -> bool:
    return all(np.allclose(_row_of(student, i), _row_of(reference, i), atol=1e-9)
               for i in range(1, reference.n + 1))


def check_table(rows, exercise: str = "arm", params=None, different: bool = False) -> Feedback:
    """Check a DH table typed as on the slides, rows ``(θ, d, a, α)`` in degrees with the
    joint variables by name (``"q2 - 90"``, ``"d3"``), against an exercise robot:
    ``'arm'`` (:func:`four_axis_arm`) or ``'seed002_4dof'`` (seed 002's R-P-P-R).
    ``params``: numbers for length symbols such as ``l1`` (default: the robot's own).
    ``different=True``: the exercise asks for a table other than the robot's own."""
    if exercise not in _TABLE_EXERCISES:
        raise DHLabError(f"exercise must be one of {sorted(_TABLE_EXERCISES)}, got {exercise!r}.")
    reference = _TABLE_EXERCISES[exercise]()
    name = "your table"
    if _blank(rows):
        return _unanswered(name)
    if isinstance(rows, str) or not isinstance(rows, (list, tuple)):
        return _wrong(name, [f"give a list of rows (θ, d, a, α), one per joint, not a {type(rows).__name__}."])
    try:
        student = DHRobot.from_table([tuple(r) for r in rows], params={**reference.params, **(params or {})})
    except (DHLabError, TypeError) as exc:
        return _wrong(name, [str(exc)])
    problems = compare_robots(student, reference)
    if problems:
        return _wrong(name, problems, "fix this first (the joints after it are checked next).")
    if different and _same_table(student, reference):
        return _wrong(name, ["this is the slide's own table (it is right): the exercise asks for another "
                             "valid one, with at least one free choice made the other way."])
    return _right(name, ["Every joint axis and the end effector are where they should be, at q = 0 and "
                         "at 50 random configurations. Another valid table may differ from yours: DH "
                         "frames are not unique (seed 002)."])


# --- 6.1: one link matrix by hand ---------------------------------------------------------------------
_SUP = str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹")
_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def _to_robot_symbols(M, robot):
    """C4 / S4 written as symbols become cos(q4) / sin(q4) of ``robot``'s joint 4."""
    swap = {}
    for s in M.free_symbols:
        text = str(s)
        if text[:1] in "CS" and text[1:].isdigit() and 1 <= int(text[1:]) <= robot.n:
            q = robot.q_symbols[int(text[1:]) - 1]
            swap[s] = sp.cos(q) if text[0] == "C" else sp.sin(q)
    return M.xreplace(swap)


def link_exercise_robot() -> DHRobot:
    """Exercise 6.1's two-link table: its row 2, (q2 + 90°, l2, 0, −90°), has an offset and
    a negative twist."""
    return DHRobot.from_table([("q1", "l1", 0, 90), ("q2 + 90", "l2", 0, -90)], name="exercise 6.1 table",
                              params={"l1": 1.0, "l2": 0.5})


def check_link_matrix(M, i: int = 2, robot=None) -> Feedback:
    """Check a hand-written ^{i−1}A_i (4x4; C2 / S2 as symbols or cos(q2) / sin(q2)) against
    link ``i`` of ``robot`` (default: :func:`link_exercise_robot`)."""
    robot = link_exercise_robot() if robot is None else robot
    name = f"your {str(i - 1).translate(_SUP)}A{str(i).translate(_SUB)}"
    if _blank(M):
        return _unanswered(name)
    if isinstance(M, sp.MatrixBase):
        M = _to_robot_symbols(sp.Matrix(M), robot)
    link, q = robot.links[i - 1], robot.q_symbols[i - 1]
    mistakes = []
    if link.is_revolute:
        theta, d = q + link.offset, link.d
        if link.offset != 0:
            degrees = math.degrees(float(link.offset))
            mistakes.append((dh_matrix(q, d, link.a, link.alpha),
                             f"you left out the offset: θ{i} = {q} {'+' if degrees > 0 else '−'} "
                             f"{_num(abs(degrees))}°, so the entries hold cos and sin of the whole θ{i}."))
    else:
        theta, d = link.theta, q + link.offset
    mistakes.append((dh_matrix(theta, d, link.a, -link.alpha),
                     f"the sign of α{i} is flipped: it is {_num(math.degrees(float(link.alpha)))}°."))
    mistakes.append((dh_matrix(theta, d, link.a, link.alpha).T,
                     "you wrote the rows as columns: the whole matrix is transposed."))
    return check_matrix(M, robot.A(i), name=name, mistakes=mistakes, index_style="math")


# --- 6.2: the wrist centre ----------------------------------------------------------------------------
WRIST_Q_DEG = (30, -45, 60, 90, -30, 45)


def check_wrist_centre(p, q_deg=WRIST_Q_DEG, robot=None) -> Feedback:
    """Check the wrist centre (x, y, z) of a 6-DOF arm with a spherical wrist (the axes of
    joints 4, 5, 6 meet in O4 = O5) at joint angles ``q_deg`` (degrees).
    Default robot: seed 002's 6-DOF arm."""
    robot = robots.seed002_6dof() if robot is None else robot
    q = np.radians(np.asarray(q_deg, dtype=float))
    F = np.asarray(robot.frames(q), dtype=float)
    T = np.asarray(robot.fk(q), dtype=float)
    centre, p_end, a = F[4, :3, 3], T[:3, 3], T[:3, 2]
    l4 = float(np.linalg.norm(p_end - centre))
    mistakes = [(p_end, f"that is the end effector p: the wrist centre is l4 = {_num(l4)} back from p "
                        "along the approach vector a (the third column of T): p_w = p − l4·a."),
                (p_end + l4 * a, "you went the wrong way along a: p_w = p − l4·a, not p + l4·a.")]
    for k in (1, 2, 3, 6):
        if np.linalg.norm(F[k, :3, 3] - centre) > 1e-6:
            mistakes.append((F[k, :3, 3], f"that is the origin of frame {k}: the wrist centre is where "
                                          "the axes of joints 4, 5 and 6 meet (O4 = O5)."))
    return check_value(p, centre, name="your wrist centre", components=("x", "y", "z"), mistakes=mistakes)


# --- notebook 7: the SSRMS's C++ keyboard control, and its parallel axes ------------------------------
def thlist_slot(joint: int) -> int:
    """Index in seed 000's ``THList`` of joint ``joint``'s Tz[θ, d] factor (the base has slots 0, 1)."""
    return 2 * joint


def check_thlist_slots(slots, robot=None) -> Feedback:
    """Check ``{joint: THList index}``: the slot a key must overwrite to move each SSRMS joint."""
    robot = robots.ssrms() if robot is None else robot
    name = "your THList slots"
    if _blank(slots):
        return _unanswered(name)
    if not isinstance(slots, dict):
        return _wrong(name, [f"give a dict {{joint: index}} for joints 1 … {robot.n}, not a "
                             f"{type(slots).__name__}."])
    items = []
    for joint in range(1, robot.n + 1):
        if joint not in slots:
            items.append(f"joint {joint}: missing.")
            continue
        try:
            given = int(slots[joint])
        except (TypeError, ValueError):
            items.append(f"joint {joint}: {slots[joint]!r} is not an index.")
            continue
        right = thlist_slot(joint)
        if given == right:
            continue
        if given == right + 1:
            why = (f"THList[{given}] is link {joint}'s Tx[α, a] factor, which never changes; the joint turns "
                   f"the Tz[θ, d] factor just before it")
        elif given == right - 2:
            owner = "the base" if joint == 1 else f"joint {joint - 1}"
            why = (f"THList[{given}] is the Tz factor of {owner}: slots 0 and 1 are the base's (the "
                   "identity), so joint k's pair is 2k, 2k+1")
        else:
            why = "the list holds two factors per link, Tz then Tx, and the base's pair comes first"
        items.append(f"joint {joint}: not THList[{given}]: {why}.")
    return _wrong(name, items) if items else _right(
        name, ["Joint k's key overwrites THList[2k], its Tz[θ_k, d_k] factor."])


def parallel_pairs(robot=None, samples: int = 200, seed: int = 0) -> set:
    """Pairs (j, k), j < k, of joints whose axes are parallel at zero and at every one of
    ``samples`` random configurations within the joint limits.

    >>> sorted(parallel_pairs())                 # the SSRMS
    [(3, 4), (3, 5), (4, 5)]
    """
    robot = robots.ssrms() if robot is None else robot
    rng = np.random.default_rng(seed)
    lo, hi = robot.qlim.T
    Q = np.vstack([np.zeros(robot.n), lo + (hi - lo) * rng.random((samples, robot.n))])
    Z = np.asarray(robot.frames(Q), dtype=float)[:, :-1, :3, 2]      # (N, n, 3): axis of joint k = z_(k-1)
    return {(j + 1, k + 1) for j in range(robot.n) for k in range(j + 1, robot.n)
            if np.all(np.linalg.norm(np.cross(Z[:, j], Z[:, k]), axis=1) < 1e-9)}


def _counterexample(robot, j: int, k: int):
    """One joint at 30° (degrees, others 0) where the axes of joints j and k are not parallel."""
    for m in range(robot.n):
        q = np.zeros(robot.n)
        q[m] = 30.0
        F = np.asarray(robot.frames(np.radians(q)), dtype=float)
        if np.linalg.norm(np.cross(F[j - 1, :3, 2], F[k - 1, :3, 2])) > 1e-6:
            return q
    return None


def check_parallel_pairs(pairs, robot=None) -> Feedback:
    """Check the set of joint pairs (j, k) whose axes stay parallel at every configuration
    (default robot: the SSRMS)."""
    robot = robots.ssrms() if robot is None else robot
    name = "your set of parallel pairs"
    if _blank(pairs):
        return _unanswered(name)
    try:
        given = {tuple(sorted(int(v) for v in pair)) for pair in pairs}
    except (TypeError, ValueError):
        return _wrong(name, ["give pairs of joint numbers, e.g. {(1, 2), (2, 5)}."])
    if any(len(p) != 2 or p[0] == p[1] or not all(1 <= v <= robot.n for v in p) for p in given):
        return _wrong(name, [f"each pair must be two different joint numbers from 1 to {robot.n}."])
    right = parallel_pairs(robot)
    F0 = np.asarray(robot.frames(robot.qz), dtype=float)
    items = []
    for j, k in sorted(given - right):
        at_zero = np.linalg.norm(np.cross(F0[j - 1, :3, 2], F0[k - 1, :3, 2])) < 1e-9
        q = _counterexample(robot, j, k)
        shown = "" if q is None else f": at θ = {_vec(q, 0)}° they are not"
        items.append(f"joints {j} and {k}: " + ("parallel at θ = 0, but not at every configuration"
                     if at_zero else "their axes are not parallel") + shown + ".")
    for j, k in sorted(right - given):
        items.append(f"joints {j} and {k}: missing: z{j - 1} and z{k - 1} stay parallel whatever the "
                     "joints do.")
    return _wrong(name, items) if items else _right(
        name, ["Exactly these pairs stay parallel: " + ", ".join(f"({j}, {k})" for j, k in sorted(right)) + "."])


def printed_key_position(joints, robot=None) -> np.ndarray:
    """Where the SSRMS's end effector would be, all joints at 0, after one press of the key of
    each joint in ``joints`` (one joint number or several) with the seed's printed handler
    (``THList[2k] = THx``, erratum 000-2).

    At that moment THx holds the last Tx that ``configurarTH`` built, the gripper's
    Tx[0, 0] = identity: joint k's factor Tz[θ_k, d_k] becomes the identity.

    >>> printed_key_position(1).round(6).tolist()
    [24.0, 0.0, -13.0]
    """
    robot = robots.ssrms() if robot is None else robot
    pressed = {int(joints)} if np.ndim(joints) == 0 else {int(j) for j in joints}
    T = np.eye(4)
    for k in range(1, robot.n + 1):
        A = np.asarray(robot.A(k, 0.0), dtype=float)
        if k in pressed:
            A = np.linalg.solve(trans(0, 0, float(robot.links[k - 1].d)), A)   # only Tx[α_k, a_k] is left
        T = T @ A
    return T[:3, 3].round(12) + 0.0


def check_key_jump(position, joints=(2, 5), robot=None) -> Feedback:
    """Check where the end effector ends up when the keys of ``joints`` are pressed once each
    with the printed (wrong) handler of seed 000, all joints at 0."""
    robot = robots.ssrms() if robot is None else robot
    joints = (joints,) if np.ndim(joints) == 0 else tuple(joints)
    correct = np.asarray(robot.fk(robot.qz), dtype=float)[:3, 3]
    mistakes = [(correct, "that is where the correct code (THz) puts it. With the printed THx, slot "
                          "THList[2k] receives the identity: the last Tx that configurarTH built is the "
                          "gripper's Tx[0, 0].")]
    if len(joints) > 1:
        for k in joints:
            mistakes.append((printed_key_position(k, robot), f"that is the jump of joint {k}'s key alone: "
                             "each pressed key overwrites its own slot, and the slots stay overwritten."))
    feedback = check_value(position, printed_key_position(joints, robot), name="your position",
                           components=("x", "y", "z"), mistakes=mistakes)
    if feedback.ok:
        lost = ", ".join(f"d{k} = {_num(float(robot.links[k - 1].d))}" for k in joints)
        feedback.items.append(f"The factors Tz[θk, dk] of joints {', '.join(map(str, joints))} became the "
                              f"identity: those joints are frozen and their offsets ({lost}) are lost.")
    return feedback


# --- the exercises of notebooks 5-7, with their hints ---------------------------------------------------
def _rows_hint_arm():
    return ["Draw x1 first: z0 and z1 are skew, so x1 is their common normal, from z0 towards z1. "
            "Then d1, a1 and α1 follow from rules 11-13.",
            "z1 ∥ z2: α2 is 0° or 180°; x2 runs along a common normal from z1 to z2. At q = 0, x1 and x2 "
            "are not parallel, so θ2 has an offset.",
            "Frame 4 sits at the star, with z4 along z3 (rule 9)."]


_COURSE = {
    "5.1": lambda: Exercise("5.1", "the case of each x_i", check_x_cases, [
        "Look at z_(i−1) and z_i (the axes of joints i and i+1): do they meet, are they parallel, or neither?",
        "Skew lines are not parallel and never meet: their common normal is unique (case 3)."]),
    "5.2": lambda: Exercise("5.2", "a DH row from two frames", check_dh_row, [
        "Work in frame i−1: A = inv(S_prev) @ S_next is the link's matrix; compare it with the closed "
        "form of rule 14.",
        "θ = atan2(A[1,0], A[0,0]), α = atan2(A[2,1], A[2,2]), d = A[2,3]; then a from A[0,3] = a·cos θ.",
        "Give the angles in degrees."]),
    "5.3": lambda: Exercise("5.3", "the table of the 4-axis arm", lambda rows: check_table(rows, "arm"),
                            _rows_hint_arm()),
    "6.1": lambda: Exercise("6.1", "¹A₂ by hand", lambda M: check_link_matrix(M, 2), [
        "Put θ2 = q2 + 90° and α2 = −90° into the general A of rule 14.",
        "cos(q2 + 90°) = −S2, sin(q2 + 90°) = C2, cos(−90°) = 0, sin(−90°) = −1."]),
    "6.2": lambda: Exercise("6.2", "the wrist centre", check_wrist_centre, [
        "The axes of joints 4, 5 and 6 meet in one point, O4 = O5: the wrist centre.",
        "From T = robot.fk(q): p_w = p − l4·a, with a = T[:3, 2] and l4 = 4."]),
    "6.3": lambda: Exercise("6.3", "another valid table of the R-P-P-R robot",
                            lambda rows: check_table(rows, "seed002_4dof", different=True), [
        "z1 and z2 intersect: x2 = ±(z1 × z2). Choose the other sign than the slide.",
        "Turning x2 by 180° changes θ2 by 180° and the sign of α2; the next row's θ3 then changes by 180°.",
        "Or use note 002-n2: joint 3 is prismatic, so the line z2 may be moved sideways (a2 ≠ 0), "
        "if row 3 moves the origin back (a3 = −a2)."]),
    "7.1": lambda: Exercise("7.1", "the THList slot of each joint", check_thlist_slots, [
        "configurarTH pushes two matrices per link (THz, then THx), starting with the base's pair.",
        "Key '1' (code 97) writes THList[2] for joint 1."]),
    "7.2": lambda: Exercise("7.2", "which joint axes stay parallel", check_parallel_pairs, [
        "Not only consecutive joints: if z2 ∥ z3 and z3 ∥ z4, then z2 ∥ z4.",
        "A pair that is parallel at θ = 0 must stay parallel when any joint turns."]),
    "7.3": lambda: Exercise("7.3", "where the printed key handler sends the arm", check_key_jump, [
        "As printed, the key of joint k sets THList[2k] = THx, and THx is the identity at that moment.",
        "Both slots stay overwritten: multiply the 14 factors with Tz[θ2, 6] and Tz[θ5, 6] replaced by "
        "the identity, all joints at 0."]),
}


def available() -> list:
    """The keys of the exercises of notebooks 5-7."""
    return list(_COURSE)


def exercise(key: str) -> Exercise:
    """A fresh :class:`~dhlab.exercises.Exercise` of notebooks 5-7, e.g. ``exercise("5.3")``."""
    if key not in _COURSE:
        raise KeyError(f"no exercise {key!r} in notebooks 5-7; there are {', '.join(_COURSE)}.")
    return _COURSE[key]()
