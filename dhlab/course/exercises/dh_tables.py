"""Exercises of notebook 5 (and the table of 6.3): the exercise arm, and a whole DH table checked fairly.
The case of each x_i (5.1) and a DH row from two frames (5.2) are in :mod:`~dhlab.course.exercises.dh_rules`.

DH frames are not unique (seed 002 lists the free choices), so a table is never compared with one
answer key: :func:`check_table` compares what every valid answer shares, the joint axes as
directed lines in space, the end effector's position and its z axis (rule 9: z_n along z_(n−1)),
at q = 0 and at 50 random configurations.
"""
from __future__ import annotations

import math

import numpy as np
import sympy as sp

from ... import robots
from ...dh import DHRobot
from ...errors import DHLabError
from ...i18n import N_, _
from ...lines import Line, closest_points
from ...mdh import MDHRobot, to_standard
from ...validation import (
    as_flag,
    as_length,
    as_matrix4,
    as_sequence,
    as_text,
    as_vector,
    check_length_size,
    describe,
    with_decimal_comma_note,
)
from ..checks.feedback import Exercise, Feedback, unanswered
from ..checks.reading import is_unanswered
from .dh_common import (
    ANGLE_TOL,
    as_robot,
    as_samples,
    axes_of,
    axis_relation,
    number_text,
    quoted,
    right_answer,
    row_at_zero,
    vector_text,
    wrong_answer,
)

__all__ = ["four_axis_arm", "show_axes", "compare_robots", "check_table"]


# --- the exercise robot of notebook 5 --------------------------------------------------------
def four_axis_arm() -> DHRobot:
    """Notebook 5's exercise arm: four revolute joints whose consecutive axes show the
    three cases of x_i (skew, parallel, intersecting). Lengths in metres."""
    return DHRobot.from_table([("q1", 0.5, 0.2, -90), ("q2 - 90", 0, 0.5, 0), ("q3", 0, 0, -90),
                               ("q4", 0.5, 0, 0)], name=_("4-axis arm (exercise)"), unit="m")


def show_axes(axes, tool=None, ax=None, length: float = 0.3, title: str = ""):
    """Draw joint axes ``(point, direction, kind)`` as arrows in 3D, labelled with the joint
    number; the positive sense is along the arrow (right-hand rule for a revolute joint).
    ``tool``: the end-effector point (or 4x4 pose), drawn as a star. Returns the Axes
    (its ``.figure`` is a :func:`~dhlab.views.figures.new_figure`: the last line of a cell shows it)."""
    from ...views.figures import new_figure  # a picture on a first Run All, readable on a projector

    axes, tool = _drawn_axes(axes), _drawn_tool(tool)
    length, title = as_length(length, "length"), as_text(title, "title")
    if not 0 < length <= 1e6:
        raise DHLabError(_("length (of the drawn arrows) must be a positive number, got {value}.").format(
            value=describe(length)))
    if ax is None:
        ax = new_figure((6.0, 4.8)).add_subplot(projection="3d")
    elif not hasattr(ax, "quiver") or getattr(ax, "name", "") != "3d":
        raise DHLabError(_("ax must be a 3D matplotlib Axes (fig.add_subplot(projection='3d')), got {value}.").format(
            value=describe(ax)))
    points = [axis[0] for axis in axes]
    for k, (p, u, _kind) in enumerate(axes, start=1):
        ax.plot(*np.array([p - length * u, p + 1.6 * length * u]).T, ":", color="0.5")
        ax.quiver(*p, *(length * u), color="tab:blue", arrow_length_ratio=0.3, lw=2)
        ax.text(*(p + 1.15 * length * u), f" {k}", fontsize=12, color="tab:blue", weight="bold")
    if tool is not None:
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


def _drawn_axes(axes) -> list:
    """show_axes' ``axes``: (point, direction, kind) triples, points and nonzero directions of 3 numbers."""
    items = as_sequence(axes, "axes", _("a list of (point, direction, kind), e.g. [((0, 0, 0), (0, 0, 1), 'R')]"))
    if not items:
        raise DHLabError(_("axes is empty: give at least one (point, direction, kind)."))
    out = []
    for k, item in enumerate(items):
        if not isinstance(item, (tuple, list)) or len(item) != 3:
            raise DHLabError(_("axes[{k}] must be (point, direction, kind), got {value}.").format(
                k=k, value=describe(item)))
        p = as_vector(item[0], f"axes[{k}] point", 3)
        u = as_vector(item[1], f"axes[{k}] direction", 3)
        for v, what in ((p, "point"), (u, "direction")):
            check_length_size(float(np.abs(v).max()), f"axes[{k}] {what}")
        if not np.linalg.norm(u) > 0:
            raise DHLabError(_("axes[{k}] direction is (0, 0, 0): an axis needs a direction.").format(k=k))
        out.append((p, u / np.linalg.norm(u), item[2]))
    return out


def _drawn_tool(tool):
    """show_axes' ``tool``: None, a point (x, y, z), or a 4x4 pose (its position is drawn)."""
    if tool is None:
        return None
    try:
        point = as_vector(tool, "tool (a point (x, y, z) or a 4x4 pose)", 3)
    except DHLabError:
        point = as_matrix4(tool, "tool (a point (x, y, z) or a 4x4 pose)")[:3, 3]
    check_length_size(float(np.abs(point).max()), "tool")
    return point


# --- 5.3 and 6.3: a whole table, checked fairly --------------------------------------------------
_TABLE_EXERCISES = {"arm": four_axis_arm, "seed002_4dof": robots.seed002_4dof}
NOT_A_NUMBER_OR_NAME = N_("row {k}, {column}: {value} is not a number or a name.")


def compare_robots(student, reference, samples: int = 50, seed: int = 0) -> list:
    """What is wrong with ``student`` (a DHRobot) as a model of ``reference``, as messages
    (empty when right). Compared: each joint axis as a directed line, the end-effector
    position and its z axis (z_n, rule 9), at q = 0 and ``samples`` random configurations within
    the reference's limits.
    A prismatic joint's axis is compared as a direction only: where its line lies is a free
    choice (ERRATA 002-n2). Only the first wrong joint is explained: the later ones hang from it."""
    student, reference = as_robot(student, "student"), as_robot(reference, "reference")
    samples, seed = as_samples(samples, seed)
    n = reference.n
    if student.n != n:
        return [_("your table has {rows} rows, but the robot has {n} joints: one row per joint.").format(
            rows=student.n, n=n)]
    for k, (s, r) in enumerate(zip(student.links, reference.links), start=1):
        if s.is_revolute != r.is_revolute:
            message = (_("joint {k} is revolute (R): its variable belongs in θ{k}, but your row {k} makes d{k} the "
                         "variable.") if r.is_revolute else
                       _("joint {k} is prismatic (P): its variable belongs in d{k}, but your row {k} makes θ{k} the "
                         "variable."))
            return [message.format(k=k)]
    rng = np.random.default_rng(seed)
    lo, hi = reference.qlim.T
    Q = np.vstack([np.zeros(n), lo + (hi - lo) * rng.random((samples, n))])
    tol = 1e-6 * max(1.0, reference.reach())
    for q in Q:
        sp_, su = axes_of(student, q)
        rp, ru = axes_of(reference, q)
        for k in range(1, n + 1):
            # a prismatic axis is a direction: where its line lies is free (ERRATA 002-n2)
            off_line = 0.0 if reference.links[k - 1].is_prismatic else \
                Line(rp[k - 1], ru[k - 1]).distance_to_point(sp_[k - 1])
            if su[k - 1] @ ru[k - 1] < 1 - 1e-9 or off_line > tol:
                return [_diagnose_axis(student, reference, k, q, tol)]
        T_s, T_r = np.asarray(student.fk(q), dtype=float), np.asarray(reference.fk(q), dtype=float)
        p_s, p_r = T_s[:3, 3], T_r[:3, 3]
        if np.linalg.norm(p_s - p_r) > tol:
            return [_("every joint axis is right, but the end effector is at {got} {at}, not at {right}: check the "
                      "last row (θ{n}'s offset, d{n}, a{n}).").format(got=vector_text(p_s), at=_at(q),
                                                                       right=vector_text(p_r), n=n)]
        if T_s[:3, 2] @ T_r[:3, 2] < 1 - 1e-9:
            return [_diagnose_last_z(student, T_r[:3, 2] @ ru[n - 1] > 1 - 1e-9, n)]
    return []


def _diagnose_last_z(student, along_previous: bool, n: int) -> str:
    """Why z_n, the end effector's own z axis (placed by α_n), points the wrong way."""
    alpha = number_text(row_at_zero(student, n)[3])
    if along_previous:
        return _("every joint axis and the end effector's position are right, but your α{n} = {alpha}° turns z{n} "
                 "away from z{p}: rule 9 puts z{n} along z{p} (the axis of joint {n}).").format(
                     n=n, p=n - 1, alpha=alpha)
    return _("every joint axis and the end effector's position are right, but z{n}, the end effector's z axis, "
             "points the wrong way: check α{n} (yours is {alpha}°).").format(n=n, alpha=alpha)


def _at(q) -> str:
    if not np.any(q):
        return _("at q = 0")
    return _("at q = {q} (revolute joints in degrees)").format(q=vector_text([math.degrees(v) for v in q], 1))


def _diagnose_axis(student, reference, k: int, q, tol: float) -> str:
    """Why joint k's axis (z_(k-1), placed by row k-1) is not where it should be."""
    i = k - 1
    if i == 0:
        return _("joint 1: z0 must lie on joint 1's axis, as drawn.")
    a, alpha = row_at_zero(student, i)[2:]
    rp, ru = axes_of(reference, q)
    sp_, su = axes_of(student, q)
    ref = axis_relation(rp[i - 1], ru[i - 1], rp[i], ru[i])
    ref_angle = number_text(min(ref.angle, 180 - ref.angle), 1)
    fields = dict(i=i, k=k, p=i - 1, alpha=number_text(alpha), angle=ref_angle, at=_at(q))
    fields["axes"] = _("z{p} and z{i} (the axes of joints {i} and {k})").format(**fields)
    stu_parallel = abs(math.sin(math.radians(alpha))) < 1e-6
    if ref.is_parallel and not stu_parallel:
        return _("joint {k}: your α{i} is {alpha}°, but {axes} are parallel: α{i} must be 0° or 180°.").format(
            **fields)
    if not ref.is_parallel and stu_parallel:
        return _("joint {k}: your α{i} is {alpha}°, which keeps z{i} parallel to z{p}, but {axes} are at {angle}° "
                 "to each other.").format(**fields)
    stu_angle = abs(alpha) if abs(alpha) <= 180 else 360 - abs(alpha)
    if min(abs(stu_angle - ref.angle), abs(stu_angle - (180 - ref.angle))) > ANGLE_TOL:
        return _("joint {k}: your α{i} is {alpha}°: it turns z{i} {turn}° away from z{p}, but {axes} are at "
                 "{angle}° to each other.").format(turn=number_text(stu_angle, 1), **fields)
    if su[i] @ ru[i] < 0:
        return _("joint {k}: z{i} points against joint {k}'s positive sense (the way its variable grows): change the "
                 "sign of α{i}, or turn x{i} the other way (θ{i} + 180° and a{i} → −a{i}).").format(**fields)
    if abs(abs(a) - ref.distance) > tol:
        what = _("they intersect, so a{i} = 0").format(i=i) if ref.kind in ("intersect", "coincident") \
            else _("they are {distance} apart").format(distance=number_text(ref.distance))
        return _("joint {k}: your a{i} = {a} puts {axes} {size} apart, but {what}.").format(
            a=number_text(a), size=number_text(abs(a)), what=what, **fields)
    if not ref.is_parallel:
        # where the common normal of z_(i-1) and z_i meets z_(i-1): student's vs reference's
        foot_ref = closest_points(Line(rp[i - 1], ru[i - 1]), Line(rp[i], ru[i]))[0]
        foot_stu = closest_points(Line(sp_[i - 1], su[i - 1]), Line(sp_[i], su[i]))[0]
        if abs(float((foot_stu - foot_ref) @ ru[i - 1])) > tol:
            also = ""
            if i >= 2 and axis_relation(rp[i - 2], ru[i - 2], rp[i - 1], ru[i - 1]).is_parallel:
                also = _(" (or d{p}: z{pp} ∥ z{p}, so d{p} and d{i} slide along the same direction and only their "
                         "sum is fixed)").format(p=i - 1, pp=i - 2, i=i)
            return _("joint {k}: the axis has the right direction and distance from joint {i}'s axis, but sits at "
                     "the wrong place along z{p} {at}: check d{i}{also}.").format(also=also, **fields)
    message = (_("joint {k}: the axis has the right direction and distance from joint {i}'s axis, but is turned "
                 "about z{p} {at}: check θ{i} (its offset: at q = 0 the robot must be in the pictured pose) and the "
                 "sign of a{i}.") if student.links[i - 1].is_revolute else
               _("joint {k}: the axis has the right direction and distance from joint {i}'s axis, but is turned "
                 "about z{p} {at}: check the constant θ{i} (its offset: at q = 0 the robot must be in the pictured "
                 "pose) and the sign of a{i}."))
    return message.format(**fields)


def _same_table(student, reference) -> bool:
    return all(np.allclose(row_at_zero(student, i), row_at_zero(reference, i), atol=1e-9)
               for i in range(1, reference.n + 1))


def _row_problem(rows) -> str:
    """What makes ``rows`` unreadable as a DH table typed as on the slides ('' when nothing)."""
    for k, row in enumerate(rows, start=1):
        if isinstance(row, (str, dict, set)) or not isinstance(row, (list, tuple, np.ndarray)):
            return _("row {k} must be a tuple (θ, d, a, α), not {type} {value}.").format(
                k=k, type=type(row).__name__, value=quoted(row))
        if len(row) != 4:
            return with_decimal_comma_note(
                _("row {k} has {n} entries; a DH row has 4: (θ, d, a, α).").format(k=k, n=len(row)), row, 4)
        for column, value in zip("θdaα", row):
            if isinstance(value, str):
                continue                      # a joint variable or a length by name, read by from_table
            if isinstance(value, (bool, np.bool_)) or value is None:
                return _(NOT_A_NUMBER_OR_NAME).format(k=k, column=column, value=repr(value))
            try:
                number = complex(value)
            except (TypeError, ValueError, OverflowError):
                if isinstance(value, sp.Basic) and not value.has(sp.zoo, sp.oo, sp.nan, -sp.oo):
                    continue                  # a sympy expression such as q2 - pi/2: from_table reads it
                return _(NOT_A_NUMBER_OR_NAME).format(k=k, column=column, value=quoted(value))
            if number.imag != 0 or not math.isfinite(number.real):
                return _("row {k}, {column}: {value} is not a finite real number (NaN, infinity or complex).").format(
                    k=k, column=column, value=quoted(value))
            if abs(number.real) > 1e6:
                return _("row {k}, {column}: {value} is far too large for a length or an angle.").format(
                    k=k, column=column, value=quoted(value))
    return ""


# The column orders a table from Craig's convention comes in: the course's (θ, d, a, α), Craig's own
# (α_(i−1), a_(i−1), d_i, θ_i), and the Robotics Toolbox's printout (a_(i−1), α_(i−1), θ_i, d_i).
_MODIFIED_ORDERS = (("", lambda r: (r[0], r[1], r[2], r[3])),
                    (N_(" in Craig's column order (α_(i−1), a_(i−1), d_i, θ_i)"),
                     lambda r: (r[3], r[2], r[1], r[0])),
                    (N_(" in the column order (a_(i−1), α_(i−1), θ_i, d_i)"), lambda r: (r[2], r[3], r[0], r[1])))


def _modified_reading(rows, reference, params) -> str:
    """Why ``rows`` is a right table of ``reference`` in modified DH (Craig), or ''."""
    for order, reorder in _MODIFIED_ORDERS:
        try:
            student = to_standard(MDHRobot.from_table([reorder(tuple(r)) for r in rows], params=params))
            if compare_robots(student, reference):
                continue
        except DHLabError:
            continue
        return _("this table is in modified DH (Craig){order}: each row i holds a_(i−1) and α_(i−1), the "
                 "common normal from the axis of joint i−1, and A_i = Rx(α_(i−1))·Tx(a_(i−1))·Rz(θ_i)·Tz(d_i). "
                 "In that convention it describes this robot. The course uses standard DH: row i holds a_i and "
                 "α_i, measured along and about x_i from z_(i−1) to z_i, and A_i = Rz(θ_i)·Tz(d_i)·Tx(a_i)·Rx(α_i). "
                 "θ_i and d_i stay as they are; move the a and α columns up one row (the last row takes the "
                 "end effector's a_n, α_n), and write each row as (θ, d, a, α).").format(order=_(order))
    return ""


def check_table(rows, exercise: str = "arm", params=None, different: bool = False) -> Feedback:
    """Check a DH table typed as on the slides, rows ``(θ, d, a, α)`` in degrees with the
    joint variables by name (``"q2 - 90"``, ``"d3"``), against an exercise robot:
    ``'arm'`` (:func:`four_axis_arm`) or ``'seed002_4dof'`` (seed 002's R-P-P-R).
    ``params``: numbers for length symbols such as ``l1`` (default: the robot's own).
    ``different=True``: the exercise asks for a table other than the robot's own."""
    if not isinstance(exercise, str) or exercise not in _TABLE_EXERCISES:
        raise DHLabError(_("exercise must be one of {choices}, got {value!r}.").format(
            choices=sorted(_TABLE_EXERCISES), value=exercise))
    if params is not None and not isinstance(params, dict):
        raise DHLabError(_("params must be a dict {{name: number}}, e.g. {{'l1': 1.0}}, got {value}.").format(
            value=describe(params)))
    different = as_flag(different, "different")
    reference = _TABLE_EXERCISES[exercise]()
    name = _("your table")
    if is_unanswered(rows):
        return unanswered(name)
    if isinstance(rows, str) or not isinstance(rows, (list, tuple)):
        return wrong_answer(name, [_("give a list of rows (θ, d, a, α), one per joint, not a {type}.").format(
            type=type(rows).__name__)])
    problem = _row_problem(rows)
    if problem:
        return wrong_answer(name, [problem])
    try:
        student = DHRobot.from_table([tuple(r) for r in rows], params={**reference.params, **(params or {})})
    except DHLabError as exc:
        other = _modified_reading(rows, reference, {**reference.params, **(params or {})})
        return wrong_answer(name, [other or str(exc)])
    except Exception as exc:       # anything from_table could not read: still feedback, never a traceback
        return wrong_answer(name, [_("the table could not be read ({error}): each row is (θ, d, a, α), numbers or "
                                     "names such as \"q2 - 90\" or \"l1\".").format(error=type(exc).__name__)])
    problems = compare_robots(student, reference)
    if problems:
        other = _modified_reading(rows, reference, {**reference.params, **(params or {})})
        if other:
            return wrong_answer(name, [other])
        return wrong_answer(name, problems, _("fix this first (the joints after it are checked next)."))
    if different and _same_table(student, reference):
        return wrong_answer(name, [_("this is the slide's own table (it is right): the exercise asks for another "
                                     "valid one, with at least one free choice made the other way.")])
    return right_answer(name, [_("Every joint axis and the end effector are where they should be, at q = 0 and "
                                 "at 50 random configurations. Another valid table may differ from yours: DH "
                                 "frames are not unique (seed 002).")])


# --- the exercises of this module, by key: dhlab.course.exercises.exercise(key) makes them -------------
def _rows_hint_arm():
    return [N_("Draw x1 first: z0 and z1 are skew, so x1 is their common normal, from z0 towards z1. "
               "Then d1, a1 and α1 follow from rules 11-13."),
            N_("z1 ∥ z2: α2 is 0° or 180°; x2 runs along a common normal from z1 to z2. At q = 0, x1 and x2 "
               "are not parallel, so θ2 has an offset."),
            N_("Frame 4 sits at the star, with z4 along z3 (rule 9).")]


EXERCISES = {
    "5.3": lambda: Exercise("5.3", N_("the table of the 4-axis arm"), lambda rows: check_table(rows, "arm"),
                            _rows_hint_arm()),
    "6.3": lambda: Exercise("6.3", N_("another valid table of the R-P-P-R robot"),
                            lambda rows: check_table(rows, "seed002_4dof", different=True), [
        N_("z1 and z2 intersect: x2 = ±(z1 × z2). Choose the other sign than the slide."),
        N_("Turning x2 by 180° changes θ2 by 180° and the sign of α2; the next row's θ3 then changes by 180°."),
        N_("Or use note 002-n2: joint 3 is prismatic, so the line z2 may be moved sideways (a2 ≠ 0), "
           "if row 3 moves the origin back (a3 = −a2).")]),
}
