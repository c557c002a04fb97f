"""Exercises of notebook 5 (and the table of 6.3): the case of each x_i, a DH row from two frames,
a whole DH table checked fairly.

DH frames are not unique (seed 002 lists the free choices), so a table is never compared with one
answer key: :func:`check_table` compares what every valid answer shares, the joint axes as
directed lines in space and the end effector's position, at q = 0 and at 50 random configurations.
"""
from __future__ import annotations

import math

import numpy as np
import sympy as sp

from .. import robots
from ..dh import DHRobot
from ..lines import Line, closest_points
from ..transforms import Rx, Rz, dh_matrix, trans
from ..validation import DHLabError
from .exercises import Feedback
from .exercises_dh_common import (ANGLE_TOL, Relation, _axes_of, _blank, _num, _read_numbers, _right,
                                  _row_of, _unanswered, _vec, _whole_number, _wrong, axis_relation)

__all__ = ["four_axis_arm", "show_axes", "check_x_cases", "ROW_EXERCISE", "row_exercise_frames",
           "check_dh_row", "compare_robots", "check_table"]


# --- the exercise robot of notebook 5 --------------------------------------------------------
def four_axis_arm() -> DHRobot:
    """Notebook 5's exercise arm: four revolute joints whose consecutive axes show the
    three cases of x_i (skew, parallel, intersecting). Lengths in metres."""
    return DHRobot.from_table([("q1", 0.5, 0.2, -90), ("q2 - 90", 0, 0.5, 0), ("q3", 0, 0, -90),
                               ("q4", 0.5, 0, 0)], name="4-axis arm (exercise)", unit="m")


def show_axes(axes, tool=None, ax=None, length: float = 0.3, title: str = ""):
    """Draw joint axes ``(point, direction, kind)`` as arrows in 3D, labelled with the joint
    number; the positive sense is along the arrow (right-hand rule for a revolute joint).
    ``tool``: the end-effector point (or 4x4 pose), drawn as a star. Returns the Axes
    (its ``.figure`` is a :func:`~dhlab.views.figures.new_figure`: the last line of a cell shows it)."""
    from ..views.figures import new_figure        # a picture on a first Run All, readable on a projector

    if ax is None:
        ax = new_figure((6.0, 4.8)).add_subplot(projection="3d")
    points = [np.asarray(p, float) for p, _, _ in axes]
    for k, (p, u, kind) in enumerate(axes, start=1):
        p, u = np.asarray(p, float), np.asarray(u, float) / np.linalg.norm(u)
        ax.plot(*np.array([p - length * u, p + 1.6 * length * u]).T, ":", color="0.5")
        ax.quiver(*p, *(length * u), color="tab:blue", arrow_length_ratio=0.3, lw=2)
        ax.text(*(p + 1.15 * length * u), f" {k}", fontsize=12, color="tab:blue", weight="bold")
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
    ax.tick_params(labelsize=9)
    ax.locator_params(nbins=4)
    ax.set_box_aspect(hi - lo, zoom=0.85)              # room for the tick and axis labels
    return ax


# --- 5.1: the case of each x_i ------------------------------------------------------------------
_CASE_WORDS = (("intersec", "intersect"), ("corta", "intersect"), ("parallel", "parallel"),
               ("parale", "parallel"), ("skew", "skew"), ("cruza", "skew"), ("coinciden", "coincident"),
               ("same line", "coincident"))
_SAID = {"intersect": "z{p} and z{i} intersect", "parallel": "z{p} and z{i} are parallel",
         "skew": "z{p} and z{i} are skew", "coincident": "z{p} and z{i} are the same line"}


def _read_case(value):
    """'intersect' / 'parallel' / 'skew' / 'coincident' from a word (English or Spanish),
    'case 2', 'caso 2' or a whole number 1-3; None when it cannot be read."""
    number = _whole_number(value)
    if number is not None:
        return {1: "intersect", 2: "parallel", 3: "skew"}.get(number)
    if not isinstance(value, str):
        return None
    text = value.strip().lower()
    for stem, kind in _CASE_WORDS:
        if stem in text:
            return kind
    for digit, kind in (("1", "intersect"), ("2", "parallel"), ("3", "skew")):
        if text in (digit, f"case {digit}", f"caso {digit}"):
            return kind
    return None


def _refutation(said: str, rel: Relation) -> str:
    """Why the relation the student said is not the one of z_(i-1) and z_i, without naming the
    right one (that is the exercise): the test their claim fails."""
    if said in ("intersect", "coincident"):
        return f"they do not meet: the shortest distance between the two lines is {_num(rel.distance)}, not 0."
    if said == "parallel":
        return (f"they do not point the same way: their directions are "
                f"{_num(min(rel.angle, 180 - rel.angle), 1)}° apart.")
    return "they lie in one plane, and skew lines never do (look at their directions, then at whether they meet)."


def _case_key(key):
    """A key of the answer dict as the number i of x_i: 1, '1', 'x1' -> 1; None otherwise."""
    number = _whole_number(key)
    if number is not None:
        return number
    if isinstance(key, str):
        text = key.strip().lower().lstrip("x").strip("_ ")
        return int(text) if text.isdigit() else None
    return None


def check_x_cases(answer, robot=None) -> Feedback:
    """Check which case places x_i, i = 1 … n−1: ``{i: 'intersect' | 'parallel' | 'skew'}``
    (or 'case 1' …, or a list in the order x1, x2, …). Default robot: :func:`four_axis_arm`.

    A wrong case is refuted (the test the claimed relation fails), not corrected: the
    feedback never states the right case.
    """
    robot = four_axis_arm() if robot is None else robot
    count = robot.n - 1
    name = f"the cases of x1 … x{count}"
    if _blank(answer):
        return _unanswered(name)
    if isinstance(answer, (list, tuple)):
        answer = dict(enumerate(answer, start=1))
    if not isinstance(answer, dict):
        return _wrong(name, [f"give a dict {{i: case}} for i = 1 … {count}, e.g. {{1: 'parallel', …}}, "
                             f"not a {type(answer).__name__}."])
    given = {}
    for key, value in answer.items():
        i = _case_key(key)
        if i is None or not 1 <= i <= count:
            return _wrong(name, [f"{key!r} is not one of the x_i asked: the keys are 1 … {count}."])
        given[i] = value
    missing = [i for i in range(1, count + 1) if i not in given]
    if missing:
        return _wrong(name, [f"say the case of every x_i, i = 1 … {count}: x{missing[0]} is missing."])
    points, dirs = _axes_of(robot, robot.qz)
    items = []
    for i in range(1, count + 1):
        said = _read_case(given[i])
        if said is None:
            shown = repr(given[i])
            shown = shown if len(shown) <= 40 else shown[:37] + "…"
            items.append(f"x{i}: cannot read {shown}: write 'intersect', 'parallel' or 'skew' "
                         "(or 'case 1', 'case 2', 'case 3').")
            continue
        rel = axis_relation(points[i - 1], dirs[i - 1], points[i], dirs[i])
        if rel.kind == "coincident" and said in ("coincident", "parallel", "intersect"):
            continue
        if said != rel.kind:
            items.append(f"x{i}: you said {_SAID[said].format(p=i - 1, i=i)}, but "
                         f"{_refutation(said, rel)}")
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


def _row_problem(rows) -> str:
    """What makes ``rows`` unreadable as a DH table typed as on the slides ('' when nothing)."""
    for k, row in enumerate(rows, start=1):
        if isinstance(row, (str, dict, set)) or not isinstance(row, (list, tuple, np.ndarray)):
            return f"row {k} must be a tuple (θ, d, a, α), not {type(row).__name__} {_short(row)}."
        if len(row) != 4:
            return f"row {k} has {len(row)} entries; a DH row has 4: (θ, d, a, α)."
        for column, value in zip("θdaα", row):
            if isinstance(value, str):
                continue                      # a joint variable or a length by name, read by from_table
            if isinstance(value, (bool, np.bool_)) or value is None:
                return f"row {k}, {column}: {value!r} is not a number or a name."
            try:
                number = complex(value)
            except (TypeError, ValueError, OverflowError):
                if isinstance(value, sp.Basic) and not value.has(sp.zoo, sp.oo, sp.nan, -sp.oo):
                    continue                  # a sympy expression such as q2 - pi/2: from_table reads it
                return f"row {k}, {column}: {_short(value)} is not a number or a name."
            if number.imag != 0 or not math.isfinite(number.real):
                return (f"row {k}, {column}: {_short(value)} is not a finite real number (NaN, infinity "
                        "or complex).")
            if abs(number.real) > 1e6:
                return f"row {k}, {column}: {_short(value)} is far too large for a length or an angle."
    return ""


def _short(value) -> str:
    text = repr(value)
    return text if len(text) <= 40 else text[:37] + "…"


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
    problem = _row_problem(rows)
    if problem:
        return _wrong(name, [problem])
    try:
        student = DHRobot.from_table([tuple(r) for r in rows], params={**reference.params, **(params or {})})
    except DHLabError as exc:
        return _wrong(name, [str(exc)])
    except Exception as exc:       # anything from_table could not read: still feedback, never a traceback
        return _wrong(name, [f"the table could not be read ({type(exc).__name__}): each row is "
                             "(θ, d, a, α), numbers or names such as \"q2 - 90\" or \"l1\"."])
    problems = compare_robots(student, reference)
    if problems:
        return _wrong(name, problems, "fix this first (the joints after it are checked next).")
    if different and _same_table(student, reference):
        return _wrong(name, ["this is the slide's own table (it is right): the exercise asks for another "
                             "valid one, with at least one free choice made the other way."])
    return _right(name, ["Every joint axis and the end effector are where they should be, at q = 0 and "
                         "at 50 random configurations. Another valid table may differ from yours: DH "
                         "frames are not unique (seed 002)."])
