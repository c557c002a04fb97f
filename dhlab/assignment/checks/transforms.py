"""Part 3 of the assignment: each ``T_i`` judged against the frame the student evidently intended.

A DH frame can be valid and still not be the one the student meant: a wrong sign of
α1 flips z1, a forgotten +180° in θ1 flips x1, and the frame is as valid as before
(the DH rules let z and x point either way). Every later ``T_j`` the student wrote
for the intended frame then fails on the flipped one. Charging all of them would
make one slip cost five items, and the feedback would point at the wrong rows.

So the checks look for the **cheapest explanation** of the whole chain, the way a
teacher reads a page of working:

* ``T_i`` is placed on the student's frame i−1 (the one their own ``T_1 … T_{i−1}``
  build). If it gives a valid frame i that turns joint i the pictured way, it is right.
* If it fails there but passes on that frame with its z or x (or both) flipped,
  the student meant the flipped frame: ``T_{i−1}``, the row that made the flip, is
  charged once, with the parameter that flips it (α_{i−1}, θ_{i−1}'s offset), and
  the checks carry on from the intended frame.
* After a row that is wrong anyway (already charged), the next row may be placed on
  any valid frame i−1: the one the student meant cannot be known, and charging the
  same row twice would cost nothing more.
* That freedom lasts along a run of parallel axes (UR5 joints 2–4, a SCARA's column):
  frames that may slide along their axes stay free to slide together until a later row
  pins them (:func:`_slides`), so a wrong offset in the charged row is not charged again
  to the row where the run ends.

Among all such readings, the one that charges the fewest rows wins (the others that charge
as many are kept, ``Analysis.alternatives``: the links of part 2, drawn in the frames the
student meant, may say which one it is, :func:`dhlab.assignment.checks.reading`); among those, the
one whose charges change the fewest parameters (a wrong sign of α is one parameter; a
forgotten 180° in θ with the α and a that go with it, two or three; a row wrong in
itself counts as more than any flip), then the one whose charged rows come first. A
search over the few frames possible at each step (a small dynamic programme) finds
it. So one slip costs one item, whatever it leaves valid downstream.

The robot being graded is a parameter (``ref``, a :class:`dhlab.assignment.reference.Reference`),
never hard-wired. What part 2 shares with this module (:class:`Item`, :class:`Analysis`,
:func:`fits` …) is in :mod:`dhlab.assignment.checks.analysis`; the whole chain, moving, in
:mod:`dhlab.assignment.checks.chain_motion`.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...i18n import _
from ..answers import NOT_ANSWERED, Answers, Row
from ..reference import TOL_DEG, TOL_POS, reference, relation
from ..valid_frames import is_valid_frame, nearest_valid_frame, valid_frames_near
from . import offsets
from .analysis import Analysis, Item, along_arrow, fits, matrix, point_text, rows_of, slips_of

__all__ = ["analyse", "diagnose", "FLIPS"]

MAX_STATES = 24
MAX_READINGS = 8          # readings as cheap as the best, kept for part 2 (the links may tell which one is meant)
FAIL_EDITS = 3            # a row wrong in itself counts as a bigger edit than any flip of its frame

# the three ways a right-handed frame can be turned over and stay on the same axes
FLIPS = {
    "z": np.diag([1.0, -1.0, -1.0, 1.0]),      # z (and y) the other way: Rx(180°)
    "x": np.diag([-1.0, -1.0, 1.0, 1.0]),      # x (and y) the other way: Rz(180°)
    "xz": np.diag([-1.0, 1.0, -1.0, 1.0]),     # x and z the other way: Ry(180°)
}


# --- one row on one frame ----------------------------------------------------------------------

def _structure(ref, i: int, row: Row) -> list:
    """What is wrong with T_i whatever the frames: the joint variable's place (θ_i for a
    joint that turns, d_i for one that slides)."""
    joint, _sign, where = row.joint
    slides = ref.kinds[i - 1] == "P"
    if joint is None:
        if slides:
            return [_("d{i} has no joint variable: joint {i} slides, "
                      "so write d{i} = q{i} + (a constant length)").format(i=i)]
        return [_("θ{i} has no joint variable: joint {i} turns, "
                  "so write θ{i} = q{i} + (a constant angle)").format(i=i)]
    if where == "d" and not slides:
        return [_("q{i} is in d{i}, which would make joint {i} slide (prismatic); the robot's joint {i} turns: "
                  "put q{i} in θ{i}").format(i=i)]
    if where == "theta" and slides:
        return [_("q{i} is in θ{i}, which would make joint {i} turn; the robot's joint {i} slides (prismatic): "
                  "put q{i} in d{i}, and a constant angle in θ{i}").format(i=i)]
    if joint != i:
        return [_("{param}{i} uses q{joint}; each T_i carries its own joint's variable, q{i}").format(
            param="d" if slides else "θ", i=i, joint=joint)]
    return []


def _problems(ref, i: int, V, row: Row, A, rows=None) -> list:
    """What is wrong with T_i placed on frame V (nothing when it :func:`fits`); ``rows`` (all the
    student's) let the message name the offset the student changed along a run of parallel axes."""
    F = V @ A
    problems = []
    along = along_arrow(ref, i, V)
    if (row.joint[1] > 0) != along:
        problems.append(_sense_message(i, row, along))
    if not is_valid_frame(ref, i, F):
        problems.append(diagnose(ref, i, V, F, row, rows))
    return problems


# --- the search ------------------------------------------------------------------------------

@dataclass
class _State:
    V: np.ndarray               # frame i (home pose) the next row is placed on
    cost: int                   # rows charged so far
    charged: tuple              # which rows, in order
    items: list                 # Item per row so far
    frames: list
    own: list                   # whether frame k is the one the student's T_k built
    edits: int = 0              # how many parameters the charges change (a smaller fix is likelier)
    slack: int | None = None    # a charged row whose frame (and the frames after it) may still slide

    def key(self):
        return tuple(np.round(self.V, 4).ravel()), self.charged[-1:] == (len(self.items),)

    def rank(self):
        return self.cost, self.edits, self.charged


def _flip_fixes(i: int, row: Row, how: str) -> list:
    """The parameters of T_i that change when its frame is turned over ``how``."""
    theta, alpha, a = row.theta.const, row.alpha, row.a
    if how == "z":
        return [_("α{i} = {new}° instead of {old}°").format(i=i, new=_angle(alpha + 180), old=_angle(alpha))]
    new_alpha = -alpha if how == "x" else 180 - alpha
    fixes = [_("θ{i}'s offset {new}° instead of {old}°").format(i=i, new=_angle(theta + 180), old=_angle(theta))]
    if _angle(new_alpha) != _angle(alpha):
        fixes.append(f"α{i} = {_angle(new_alpha)}°")
    if abs(a) > 1e-12:
        fixes.append(f"a{i} = {-a:g}")
    return fixes


def _flip_message(i: int, row: Row, how: str, n: int) -> str:
    """T_i is right up to a flip of its frame, which the rows after it (up to T_n) undo: name the parameter."""
    axis = {"z": f"z{i}", "x": f"x{i}", "xz": _("x{i} and z{i}").format(i=i)}[how]
    param = f"α{i}" if how == "z" else _("θ{i}'s offset").format(i=i)
    later = _later_rows(i, n)
    fixes = ", ".join(_flip_fixes(i, row, how))
    if i + 1 == n:
        return _("{param}: your T{i} builds a valid frame {i}, but your {later} is written for frame {i} with {axis} "
                 "pointing the other way; with {fixes} it fits (one slip: only T{i} is charged)").format(
            param=param, i=i, later=later, axis=axis, fixes=fixes)
    return _("{param}: your T{i} builds a valid frame {i}, but your {later} are written for frame {i} with {axis} "
             "pointing the other way; with {fixes} they fit (one slip: only T{i} is charged)").format(
        param=param, i=i, later=later, axis=axis, fixes=fixes)


def _later_rows(i: int, n: int) -> str:
    """The rows after T_i, up to the robot's last, T_n: 'T6', 'T5 and T6', 'T3…T6'."""
    if i + 1 >= n:
        return f"T{n}"
    if i + 2 == n:
        return _("T{i} and T{n}").format(i=i + 1, n=n)
    return f"T{i + 1}…T{n}"


def _angle(x: float) -> str:
    x = (x + 180) % 360 - 180
    return _g(180.0 if abs(x + 180) < 1e-9 else x)


def _g(x: float) -> str:
    """x as the messages print it (:g), never '-0' (-0.0 + 0.0 is 0.0): a sign change of zero,
    as in θ3 = -(q3 + 0), means nothing."""
    return f"{float(x) + 0.0:g}"


def analyse(answers: Answers, ref=None) -> Analysis:
    """Judge every T_i (see the module's doc): the items, and the frames the student meant."""
    ref = ref or reference()
    n = ref.n
    rows = rows_of(answers, n)
    states = [_State(np.eye(4), 0, (), [], [np.eye(4)], [True])]
    structural_ok = True
    for i, row in enumerate(rows, start=1):
        if not isinstance(row, Row):
            structural_ok = False
            item = Item(f"T{i}", None if row is NOT_ANSWERED else False,
                        _("not answered") if row is NOT_ANSWERED else row.why)
            states = _dedupe([_State(ref.home_frames[i], s.cost + 1, s.charged + (i,), s.items + [item],
                                     s.frames + [ref.home_frames[i]], s.own + [False], s.edits, slack=i)
                              for s in states])
            continue
        structural_ok = structural_ok and not _structure(ref, i, row)
        A = matrix(row)
        states = _dedupe([new for s in states for new in _expand(ref, i, rows, A, s)])
    best, *others = sorted(states, key=_State.rank)
    alternatives = [Analysis(rows, s.items, s.frames, s.own, structural_ok, ref)
                    for s in others if s.cost == best.cost][:MAX_READINGS]
    return Analysis(rows, best.items, best.frames, best.own, structural_ok, ref, alternatives)


def _expand(ref, i: int, rows, A, s: _State) -> list:
    """The states after T_i, from state ``s``: T_i right on the frame as it is, on a
    flipped frame (charging T_{i−1}), on any valid frame (when T_{i−1} is charged
    anyway), or T_i wrong."""
    row = rows[i - 1]
    label = f"T{i} = {row.text()}"
    broken = _structure(ref, i, row)
    out = []
    passed_free = False
    if not broken:
        prev_charged = i - 1 in s.charged
        candidates = [("", s.V, 0)]
        if i > 1:                                   # frame 0 is given: it never turns over
            extra = 0 if prev_charged else 1
            candidates += [(how, s.V @ g, extra) for how, g in FLIPS.items()]
            if prev_charged:                        # T_{i-1} is wrong anyway: any valid frame i-1
                inverse = np.linalg.inv(A)
                for _how, V, _extra in list(candidates):
                    for G, _angle_off, _dist in valid_frames_near(ref, i, V @ A):     # the nearest first
                        W = G @ inverse
                        if is_valid_frame(ref, i - 1, W):
                            candidates.append(("any", W, 0))
        if s.slack is not None and s.slack < i - 1 and not fits(ref, i, s.V, row, A):
            candidates += _slides(ref, i, s, A)
        for how, V, extra in candidates:
            if not fits(ref, i, V, row, A):
                continue
            F = V @ A
            passed_free = passed_free or not extra
            items, charged, edits = list(s.items), s.charged, s.edits
            if extra:
                items[i - 2] = Item(items[i - 2].label, False, _flip_message(i - 1, rows[i - 2], how, ref.n))
                charged = charged + (i - 1,)
                edits += len(_flip_fixes(i - 1, rows[i - 2], how))
            frames = s.frames[:-1] + [V]                # the frame i-1 the student meant
            own = s.own[:-1] + [s.own[-1] and not how]
            if how == "slide":                          # the frames since the charged row, moved with it
                move = V @ np.linalg.inv(s.V)
                frames = [move @ f if k >= s.slack else f for k, f in enumerate(s.frames)]
                own = [o and k < s.slack for k, o in enumerate(s.own)]
            out.append(_State(F, s.cost + extra, charged, items + [Item(label, True)], frames + [F], own + [True],
                              edits, s.slack))
    if passed_free:                     # a row that fits is never charged for itself
        return out
    # T_i wrong: diagnosed on the frame as it is; carry on from the nearest valid frame i
    F = s.V @ A
    problems = _problems(ref, i, s.V, row, A, rows)
    if broken:                    # the variable is misplaced: its sense means nothing yet
        problems = broken + [p for p in problems if not isinstance(p, SenseProblem)]
    C, _angle_off, _dist = nearest_valid_frame(ref, i, F)
    edits = FAIL_EDITS if broken or not _one_edit_fits(ref, i, s.V, row) else 1
    out.append(_State(C, s.cost + 1, s.charged + (i,), s.items + [Item(label, False, "; ".join(problems))],
                      s.frames + [C], s.own + [False], s.edits + edits, slack=i))
    return out


def _slides(ref, i: int, s: _State, A) -> list:
    """Frame i−1 moved, with every frame since the charged row ``s.slack``, by the translation that
    brings T_i to a valid frame i, when each moved frame stays valid (the frames of a run of
    parallel axes slide along them): [("slide", the moved frame i−1, 0)]."""
    F = s.V @ A
    out = []
    for G, _angle_off, _dist in valid_frames_near(ref, i, F)[:4]:
        move = np.eye(4)
        move[:3, 3] = G[:3, 3] - F[:3, 3]
        if np.linalg.norm(move[:3, 3]) > 1e-9 and all(is_valid_frame(ref, k, move @ s.frames[k])
                                                        for k in range(s.slack, i)):
            out.append(("slide", move @ s.V, 0))
    return out


def _one_edit_fits(ref, i: int, V, row: Row) -> bool:
    """Whether changing one parameter of T_i the way students slip makes it fit frame V: then
    "T_i is wrong" is as small an explanation as a flip of the frame before."""
    return any(fits(ref, i, V, new) for new in slips_of(row))


def _dedupe(states) -> list:
    best = {}
    for s in states:
        k = s.key()
        if k not in best or s.rank() < best[k].rank():
            best[k] = s
    kept = sorted(best.values(), key=_State.rank)
    low = kept[0].cost
    return [s for s in kept if s.cost <= low + 1][:MAX_STATES]


# --- the messages -------------------------------------------------------------------------------

class SenseProblem(str):
    """A message about a joint's positive sense (dropped when the joint variable itself is misplaced)."""


def _sense_message(i: int, row: Row, z_along_arrow: bool) -> str:
    if row.joint[2] == "d":
        return SenseProblem(_slide_sense_message(i, row, z_along_arrow))
    if z_along_arrow:
        return SenseProblem(_(
            "joint {i}: a positive q{i} turns the arm the wrong way: your z{previous} points along the drawn positive "
            "sense of joint {i}, so θ{i} must grow with q{i}; write θ{i} = q{i} + (constant), not {theta}").format(
            i=i, previous=i - 1, theta=row.theta.text("°")))
    return SenseProblem(_(
        "joint {i}: a positive q{i} turns the arm the wrong way: your z{previous} points against the drawn positive "
        "sense of joint {i}, so θ{i} = {theta} turns it opposite to the curled arrow; write θ{i} = -q{i} + "
        "(constant), or let z{previous} point along the arrow").format(i=i, previous=i - 1, theta=row.theta.text("°")))


def _slide_sense_message(i: int, row: Row, z_along_arrow: bool) -> str:
    if z_along_arrow:
        return _("joint {i}: a positive q{i} slides the arm the wrong way: your z{previous} points along the drawn "
                 "positive direction of joint {i}, so d{i} must grow with q{i}; write d{i} = q{i} + (constant), "
                 "not {d}").format(i=i, previous=i - 1, d=row.d.text())
    return _("joint {i}: a positive q{i} slides the arm the wrong way: your z{previous} points against the drawn "
             "positive direction of joint {i}, so d{i} = {d} moves it opposite to the arrow; write d{i} = -q{i} + "
             "(constant), or let z{previous} point along the arrow").format(i=i, previous=i - 1, d=row.d.text())


def _line_word(angle: float) -> str:
    if angle < TOL_DEG:
        return _("parallel to")
    if abs(angle - 90) < TOL_DEG:
        return _("perpendicular to")
    return _("at {angle}° to").format(angle=f"{angle:.1f}")


def diagnose(ref, i: int, V, F, row: Row, rows=None) -> str:
    """Why frame i = (frame i-1)·T_i is not a valid DH frame: the DH quantity at fault."""
    n = ref.n
    z_prev, z = V[:3, 2], F[:3, 2]
    o = F[:3, 3]
    alpha_hint = ""
    if abs(row.alpha) <= 2 * math.pi + 1e-9 and row.alpha not in (0, 0.0):
        alpha_hint = " " + _("(α is in degrees; this looks like radians)")
    if i == n:
        target = ref.axes[n - 1]
        if abs(float(z @ target.direction)) < math.cos(math.radians(TOL_DEG)):
            return _("z{n} should lie along z{previous} (the axis of joint {n}: the last frame's z is aligned with the "
                     "previous one, seed 000 paso 0); your α{n} = {alpha}° turns it").format(
                n=n, previous=n - 1, alpha=_g(row.alpha)) + alpha_hint
        miss = float(np.linalg.norm(o - ref.end_point))
        along = float((ref.end_point - o) @ z_prev)
        check = _("check d{n} = {d} and a{n} = {a}").format(n=n, d=row.d.text(), a=_g(row.a))
        if miss - abs(along) <= TOL_POS and len(offsets.parallel_run(ref, n)) > 1:     # off along z_{n-1} only
            check = offsets.advice(ref, n, row, rows, along)
        return _("end effector: frame {n}'s origin should be at {end}, {point} m; yours is {miss} m away, at "
                 "{yours}: {check}").format(n=n, end=ref.end_text, point=point_text(ref.end_point), miss=f"{miss:.4f}",
                                            yours=point_text(o), check=check)
    L_prev, L_next = ref.axes[i - 1], ref.axes[i]
    rel = relation(L_prev, L_next)
    ang_st = math.degrees(math.acos(min(1.0, abs(float(z_prev @ z)))))
    joint = _("joint {j}").format(j=i + 1)
    if abs(ang_st - rel.acute) > TOL_DEG:
        verb = _("leaves it parallel") if ang_st < TOL_DEG else _("turns it")
        return _("{joint}: z{i} should be {line} z{previous}; your α{i} = {alpha}° {verb}{hint} (the axis of {joint} "
                 "is {line} the axis of joint {i})").format(joint=joint, i=i, line=_line_word(rel.acute),
                                                            previous=i - 1, alpha=_g(row.alpha), verb=verb,
                                                            hint=alpha_hint)
    if abs(float(z @ L_next.direction)) < math.cos(math.radians(TOL_DEG)):
        return _("{joint}: z{i} is {line} z{previous} as it should be, but points the wrong way at the home pose: "
                 "x{i} must lie along the common normal of z{previous} and z{i} (at home, along ±{normal}); check "
                 "the constant in θ{i} (yours: {theta}°) and the sign of α{i}").format(
            joint=joint, i=i, line=_line_word(rel.acute), previous=i - 1, normal=point_text(rel.normal, 3),
            theta=_g(row.theta.const))
    if "P" in ref.kinds[i - 1:i + 1]:             # a sliding joint's line is the student's: no distances
        return _sliding_problem(ref, i, F, row)
    if abs(abs(row.a) - rel.distance) > TOL_POS:
        should = (_("should meet z{previous} (a{i} = 0)").format(previous=i - 1, i=i) if rel.kind == "intersect" else
                  _("should be {distance} m from z{previous} (the length of their common normal, |a{i}|)").format(
                      distance=f"{rel.distance:.4g}", previous=i - 1, i=i))
        return _("{joint}: z{i} {should}; your a{i} = {a}").format(joint=joint, i=i, should=should, a=_g(row.a))
    turned = math.degrees(math.acos(min(1.0, abs(float(F[:3, 0] @ rel.normal)))))     # x_i's line and the normal's
    if rel.kind in ("parallel", "skew") and turned > TOL_DEG:
        return _("{joint}: x{i} must lie along the common normal of z{previous} and z{i} (at home, along ±{normal}); "
                 "yours is turned {turned}° from it about z{previous}: check the constant in θ{i} (yours: "
                 "{theta}°)").format(joint=joint, i=i, previous=i - 1, normal=point_text(rel.normal, 3),
                                     turned=f"{turned:.0f}", theta=_g(row.theta.const))
    if rel.kind in ("parallel", "skew") and float(row.a * F[:3, 0] @ rel.normal) < 0:
        return _("{joint}: z{i} is {distance} m from z{previous} as it should be, but on the wrong side at the home "
                 "pose: x{i} points from z{previous} towards z{i}; check the constant in θ{i} (yours: {theta}°) or "
                 "the sign of a{i}").format(joint=joint, i=i, distance=f"{rel.distance:.4g}", previous=i - 1,
                                            theta=_g(row.theta.const))
    # right direction and distance: x_i crosses z_{i-1} at the wrong height (d_i)
    crossing = o - row.a * F[:3, 0]
    target = rel.foot - (rel.distance * rel.normal if rel.kind == "skew" else 0.0)
    shift = float((target - crossing) @ z_prev)
    if abs(shift) <= TOL_POS:                # no distance to quote: the frame is off in another way
        return _("frame {i} is not a valid DH frame for {joint}: check the constant in θ{i} (yours: {theta}°) and "
                 "α{i} (yours: {alpha}°)").format(i=i, joint=joint, theta=_g(row.theta.const), alpha=_g(row.alpha))
    where = _("short of") if shift > 0 else _("past")
    return _("{joint}: x{i} must cross z{previous} where the common normal of z{previous} and z{i} does; yours "
             "crosses it {shift} m {where} that point (along z{previous}): {advice}").format(
        joint=joint, i=i, previous=i - 1, shift=f"{abs(shift):.4g}", where=where,
        advice=offsets.advice(ref, i, row, rows, shift))


def _sliding_problem(ref, i: int, F, row: Row) -> str:
    """Why frame i, next to a sliding joint and with z_i in the right direction, is not valid."""
    joint = _("joint {j}").format(j=i + 1)
    off = ref.axes[i].distance_to_point(F[:3, 3])
    if ref.kinds[i] == "R" and off > TOL_POS:
        before = ""
        if ref.kinds[i - 1] == "P" and i > 1:       # T_{i-1} placed the sliding line: its d and a move it too
            before = " — " + _("or d{previous} and a{previous}: they place the line of sliding joint {i} (any line "
                               "parallel to its axis is valid), and z{i} moves with it").format(previous=i - 1, i=i)
        return _("{joint}: z{i} must lie on the axis of {joint}, the line it turns about; yours is {off} m from it at "
                 "the home pose: check a{i} (yours: {a}), d{i} (yours: {d}) and the constant in θ{i} (yours: "
                 "{theta}°)").format(joint=joint, i=i, off=f"{off:.4g}", a=_g(row.a), d=row.d.text(),
                                     theta=_g(row.theta.const)) + before
    return _("frame {i} is not a valid DH frame: x{i} must be square to z{previous} and z{i} (the directions of the "
             "axes of joints {i} and {next}) and z{i} along the axis of {joint}; check θ{i} and α{i}").format(
        i=i, previous=i - 1, next=i + 1, joint=joint)
