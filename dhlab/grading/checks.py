"""Fair checks of the PUMA assignment, with feedback that names the joint and the quantity.

DH frames are not unique, so nothing here compares a table with one answer key.
The checks compare what every valid answer shares (see :mod:`dhlab.grading.puma`):

* part 1 (the sketch): counts, joint types, and how each pair of consecutive joint
  axes meets — facts of the robot, computed from the reference's axes;
* part 2 (each link in its own frame): the link's points must land on the robot's
  points when placed by *a valid DH frame of that link* — the frame your part-3
  transformations build when that frame is valid, any valid one otherwise;
* part 3 (the transformations): each ``T_i`` is judged on its own: placed on a
  valid frame i−1, it must give a valid frame i and turn joint i the pictured way.
  Every valid choice (signs of the axes, origins along parallel axes, the last
  frame's x) passes; one wrong ``T_i`` costs only that item. Then the whole chain is
  compared with the PUMA at random configurations: every joint axis as a directed
  line and the end-effector position.

>>> from dhlab.grading.answers import parse_answers
>>> report = check_all(parse_answers({}))
>>> report.score, report.max_score
(0.0, 10)
>>> print(report.parts[0].lines()[0])
Part 1 (the sketch): 0/2 points, not answered
"""
from __future__ import annotations

import html
import math
from dataclasses import dataclass, field

import numpy as np

from . import puma
from .answers import NOT_ANSWERED, Answers, Row, Unreadable

__all__ = ["POINTS", "Item", "PartResult", "Report", "check_part1", "check_part2", "check_part3",
           "check_all", "random_configurations", "chain_matches"]

POINTS = {"part1": 2, "part2": 3, "part3": 5}
TITLES = {"part1": "the sketch", "part2": "each link in its own frame",
          "part3": "the transformations and their chain"}
N_CONFIGS = 50


@dataclass
class Item:
    """One thing checked: ``ok`` True, False, or None (not answered)."""
    label: str
    ok: bool | None
    message: str = ""


@dataclass
class PartResult:
    key: str
    items: list
    notes: list = field(default_factory=list)    # not scored: context for the student

    @property
    def points(self) -> int:
        return POINTS[self.key]

    @property
    def title(self) -> str:
        return TITLES[self.key]

    @property
    def answered(self) -> bool:
        return any(item.ok is not None for item in self.items)

    @property
    def score(self) -> float:
        good = sum(1 for item in self.items if item.ok)
        return round(self.points * good / len(self.items), 2) if self.items else 0.0

    @property
    def full_marks(self) -> bool:
        return all(item.ok for item in self.items)

    def lines(self) -> list:
        number = self.key[-1]
        head = f"Part {number} ({self.title}): {_num(self.score)}/{self.points} points"
        if not self.answered:
            return [head + ", not answered"]
        out = [head]
        for item in self.items:
            mark = {True: "✓", False: "✗", None: "·"}[item.ok]
            out.append(f"  {mark} {item.label}: {item.message}" if item.message else f"  {mark} {item.label}")
        out += [f"  {note}" for note in self.notes]
        return out

    def text(self) -> str:
        return "\n".join(self.lines())

    def html(self) -> str:
        rows = []
        for line in self.lines()[1:] if self.answered else []:
            color = "#1a7f37" if "✓" in line[:4] else "#b3261e" if "✗" in line[:4] else "#555"
            rows.append(f'<li style="color:{color};list-style:none">{html.escape(line.strip())}</li>')
        head = html.escape(self.lines()[0])
        return f"<div><b>{head}</b><ul style='margin:0.2em 0'>{''.join(rows)}</ul></div>"

    def __repr__(self):
        return self.text()

    def _repr_html_(self):
        return self.html()


@dataclass
class Report:
    parts: list

    @property
    def score(self) -> float:
        return round(sum(p.score for p in self.parts), 2)

    @property
    def max_score(self) -> int:
        return sum(p.points for p in self.parts)

    def part(self, key: str) -> PartResult:
        return next(p for p in self.parts if p.key == key)

    def text(self) -> str:
        blocks = [f"PUMA 560 assignment: {_num(self.score)}/{self.max_score} points"]
        blocks += [p.text() for p in self.parts]
        return "\n\n".join(blocks) + "\n"

    def __repr__(self):
        return self.text()


def _num(x: float) -> str:
    return f"{x:g}"


def _vec(v, digits: int = 4) -> str:
    return "(" + ", ".join(f"{x + 0.0:.{digits}f}" for x in np.asarray(v, float)) + ")"


def random_configurations(n: int = N_CONFIGS, seed: int = 560) -> np.ndarray:
    """The configurations the chain is compared at: home, then n random ones (radians)."""
    rng = np.random.default_rng(seed)
    Q = rng.uniform(-math.pi, math.pi, (n, puma.reference().n))
    return np.vstack([np.zeros(puma.reference().n), Q])


# --- part 1: the sketch ----------------------------------------------------------------

def _relation_text(ref, i: int) -> str:
    """How z_{i-1} and z_i (the axes of joints i and i+1) meet, in words."""
    rel = puma.relation(ref.axes[i - 1], ref.axes[i])
    a, b = f"z{i - 1}", f"z{i}"
    if rel.kind == "intersect":
        return f"{a} and {b} intersect, at {_vec(rel.foot)} m at home"
    if rel.kind == "parallel":
        return f"{a} and {b} are parallel, {rel.distance:.4g} m apart"
    if rel.kind == "skew":
        return (f"{a} and {b} are skew: not parallel ({rel.acute:.0f}° apart) and they miss "
                f"each other by {rel.distance:.4g} m")
    return f"{a} and {b} coincide"


def check_part1(answers: Answers) -> PartResult:
    ref = puma.reference()
    n = ref.n
    items = []

    def count(label, value, expected, rule):
        if value is NOT_ANSWERED:
            items.append(Item(label, None, "not answered"))
        elif isinstance(value, Unreadable):
            items.append(Item(label, False, value.why))
        elif value == expected:
            items.append(Item(f"{label} = {value}", True))
        else:
            items.append(Item(label, False, f"you wrote {value}; {rule}"))

    count("n_links", answers.n_links, n + 1,
          f"the links are the base (link 0) and one link moved by each joint, so a robot with "
          f"n joints has n + 1 links (seed 000, paso 0)")
    count("n_joints", answers.n_joints, n,
          "count the joints (articulaciones) between the base and the gripper: each has its own axis in the picture")
    kinds = ["R" if link.is_revolute else "P" for link in ref.robot.links]
    types = answers.joint_types
    if isinstance(types, list) and types != kinds:
        wrong = [f"joint {j + 1} is {'revolute (R)' if k == 'R' else 'prismatic (P)'}"
                 for j, k in enumerate(kinds) if j >= len(types) or types[j] != k]
        extra = f"; you gave {len(types)} letters for {n} joints" if len(types) != n else ""
        items.append(Item("joint_types", False, "; ".join(wrong[:3]) + extra))
    else:
        count("joint_types", "".join(types) if isinstance(types, list) else types, "".join(kinds), "")
    cases = answers.x_cases
    for i in range(1, n):
        label = f"x{i}"
        expected = puma.relation(ref.axes[i - 1], ref.axes[i]).kind
        if cases is NOT_ANSWERED or (isinstance(cases, list) and (i > len(cases) or cases[i - 1] is None)):
            items.append(Item(label, None, "not answered"))
        elif isinstance(cases, Unreadable):
            items.append(Item(label, False, cases.why))
        elif cases[i - 1] == expected:
            items.append(Item(f"{label}: {expected}", True))
        else:
            items.append(Item(label, False, f"{_relation_text(ref, i)}; you wrote {cases[i - 1]!r}"))
    part = PartResult("part1", items)
    if isinstance(cases, list) and len(cases) != n - 1:
        part.notes.append(f"(x_cases has {len(cases)} entries: give one for each i = 1…{n - 1}; "
                          f"the last frame's x{n} is the special case of paso 0)")
    return part


# --- part 3: the transformations ---------------------------------------------------------

def _rows(answers: Answers) -> list:
    """T_1…T_n: the T_i variable, or the chain's i-th factor when T_i is missing."""
    rows = []
    chain = answers.chain if isinstance(answers.chain, list) else []
    for i, value in enumerate(answers.T):
        if not isinstance(value, Row) and i < len(chain):
            value = chain[i]
        rows.append(value)
    return rows


def _matrix(row: Row, q: float = 0.0) -> np.ndarray:
    """T_i at joint value q (radians; q only enters where the row's variable is)."""
    theta = math.radians(row.theta.const) + (row.theta.sign * q if row.theta.joint is not None else 0.0)
    d = row.d.const + (row.d.sign * q if row.d.joint is not None else 0.0)
    return puma.dh_frames([(1, None, theta, d, row.a, math.radians(row.alpha))], np.zeros((1, 1)))[0, 1]


@dataclass
class _Analysis:
    rows: list
    items: list
    frames: list        # the student's frame k at home (4x4) or None, k = 0…n
    valid: list         # whether that frame is a valid DH frame of link k
    structural_ok: bool


def _analyse(answers: Answers) -> _Analysis:
    ref = puma.reference()
    n = ref.n
    rows = _rows(answers)
    frames, valid = [np.eye(4)], [True]
    items = []
    V = np.eye(4)                        # a valid frame i-1 to place T_i on
    structural_ok = True
    for i, row in enumerate(rows, start=1):
        label = f"T{i}"
        if not isinstance(row, Row):
            structural_ok = False
            items.append(Item(label, None if row is NOT_ANSWERED else False,
                              "not answered" if row is NOT_ANSWERED else row.why))
            frames.append(None)
            valid.append(False)
            V = ref.home_frames[i]
            continue
        problems = []
        joint, sign, where = row.joint
        if joint is None:
            problems.append(f"θ{i} has no joint variable: joint {i} turns, so write θ{i} = q{i} + (a constant angle)")
        elif where == "d":
            problems.append(f"q{i} is in d{i}, which would make joint {i} slide (prismatic); "
                            f"the PUMA's joint {i} turns: put q{i} in θ{i}")
        elif joint != i:
            problems.append(f"θ{i} uses q{joint}; each T_i carries its own joint's variable, q{i}")
        if problems:
            structural_ok = False
        F = V @ _matrix(row)
        along = float(V[:3, 2] @ ref.axes[i - 1].direction) > 0
        if not problems and (sign > 0) != along:
            problems.append(_sense_message(i, row, along))
        C, angle, dist = puma.nearest_valid_frame(ref, i, F)
        ok_frame = angle <= puma.TOL_DEG and dist <= puma.TOL_POS
        if not ok_frame:
            problems.append(_diagnose(ref, i, V, F, row))
        frames.append(F)
        valid.append(ok_frame)
        items.append(Item(f"{label} = {row.text()}", not problems, "; ".join(problems)))
        V = F if ok_frame else C
    return _Analysis(rows, items, frames, valid, structural_ok)


def _sense_message(i: int, row: Row, z_along_arrow: bool) -> str:
    if z_along_arrow:
        return (f"joint {i}: a positive q{i} turns the arm the wrong way: your z{i - 1} points along the "
                f"drawn positive sense of joint {i}, so θ{i} must grow with q{i}; write θ{i} = q{i} + (constant), "
                f"not {row.theta.text('°')}")
    return (f"joint {i}: a positive q{i} turns the arm the wrong way: your z{i - 1} points against the "
            f"drawn positive sense of joint {i}, so θ{i} = {row.theta.text('°')} turns it opposite to the "
            f"curled arrow; write θ{i} = -q{i} + (constant), or let z{i - 1} point along the arrow")


def _line_word(angle: float) -> str:
    if angle < puma.TOL_DEG:
        return "parallel to"
    if abs(angle - 90) < puma.TOL_DEG:
        return "perpendicular to"
    return f"at {angle:.1f}° to"


def _diagnose(ref, i: int, V, F, row: Row) -> str:
    """Why frame i = (valid frame i-1)·T_i is not a valid DH frame: the DH quantity at fault."""
    n = ref.n
    z_prev, z = V[:3, 2], F[:3, 2]
    o = F[:3, 3]
    alpha_hint = ""
    if abs(row.alpha) <= 2 * math.pi + 1e-9 and row.alpha not in (0, 0.0):
        alpha_hint = " (α is in degrees; this looks like radians)"
    if i == n:
        target = ref.axes[n - 1]
        if abs(float(z @ target.direction)) < math.cos(math.radians(puma.TOL_DEG)):
            return (f"z{n} should lie along z{n - 1} (the axis of joint {n}: the last frame's z is aligned "
                    f"with the previous one, seed 000 paso 0); your α{n} = {row.alpha:g}° turns it{alpha_hint}")
        miss = float(np.linalg.norm(o - ref.wrist_centre))
        return (f"end effector: frame {n}'s origin should be at the wrist centre W = {_vec(ref.wrist_centre)} m, "
                f"where the axes of joints 4, 5 and 6 meet; yours is {miss:.4f} m away, at {_vec(o)}: "
                f"check d{n} = {row.d.text()} and a{n} = {row.a:g}")
    L_prev, L_next = ref.axes[i - 1], ref.axes[i]
    rel = puma.relation(L_prev, L_next)
    ang_st = math.degrees(math.acos(min(1.0, abs(float(z_prev @ z)))))
    joint = f"joint {i + 1}"
    if abs(ang_st - rel.acute) > puma.TOL_DEG:
        verb = "leaves it parallel" if ang_st < puma.TOL_DEG else "turns it"
        return (f"{joint}: z{i} should be {_line_word(rel.acute)} z{i - 1}; your α{i} = {row.alpha:g}° "
                f"{verb}{alpha_hint} (the axis of {joint} is {_line_word(rel.acute)} the axis of joint {i})")
    if abs(float(z @ L_next.direction)) < math.cos(math.radians(puma.TOL_DEG)):
        return (f"{joint}: z{i} is {_line_word(rel.acute)} z{i - 1} as it should be, but points the wrong way "
                f"at the home pose: x{i} must lie along the common normal of z{i - 1} and z{i} "
                f"(at home, along ±{_vec(rel.normal, 3)}); check the constant in θ{i} "
                f"(yours: {row.theta.const:g}°) and the sign of α{i}")
    if abs(abs(row.a) - rel.distance) > puma.TOL_POS:
        should = (f"should meet z{i - 1} (a{i} = 0)" if rel.kind == "intersect" else
                  f"should be {rel.distance:.4g} m from z{i - 1} (the length of their common normal, |a{i}|)")
        return f"{joint}: z{i} {should}; your a{i} = {row.a:g}"
    if rel.kind in ("parallel", "skew") and float(row.a * F[:3, 0] @ rel.normal) < 0:
        return (f"{joint}: z{i} is {rel.distance:.4g} m from z{i - 1} as it should be, but on the wrong side "
                f"at the home pose: x{i} points from z{i - 1} towards z{i}; check the constant in θ{i} "
                f"(yours: {row.theta.const:g}°) or the sign of a{i}")
    # right direction and distance: x_i crosses z_{i-1} at the wrong height (d_i)
    crossing = o - row.a * F[:3, 0]
    target = rel.foot - (rel.distance * rel.normal if rel.kind == "skew" else 0.0)
    shift = float((target - crossing) @ z_prev)
    free = ""
    if puma.frame_family(ref, i - 1).shift:
        free = (f" — or d{i - 1}: the origin of frame {i - 1} may slide along z{i - 1} (its axes are parallel), "
                f"but then d{i} must follow it")
    return (f"{joint}: x{i} must cross z{i - 1} where the common normal of z{i - 1} and z{i} does; yours "
            f"crosses it {abs(shift):.4g} m {'short of' if shift > 0 else 'past'} that point (along z{i - 1}): "
            f"check d{i} (yours: {row.d.text()}){free}")


def _student_rows_numeric(rows) -> list:
    """(sign, joint index, θ0, d, a, α) in radians for :func:`puma.dh_frames`."""
    out = []
    for row in rows:
        out.append((row.theta.sign, row.theta.joint - 1, math.radians(row.theta.const), row.d.const,
                    row.a, math.radians(row.alpha)))
    return out


def chain_matches(rows, Q=None) -> dict:
    """Compare a chain with the PUMA at configurations ``Q`` (default: home + 50 random).

    For each joint, whether its axis — a directed line: the axis of joint i is z_{i-1},
    pointing the way that a positive q_i turns by the right-hand rule — is the PUMA's
    at every configuration; and whether the end effector is at the same place.
    """
    ref = puma.reference()
    Q = random_configurations() if Q is None else np.atleast_2d(Q)
    F = puma.dh_frames(_student_rows_numeric(rows), Q)
    R = ref.frames(Q)
    cos_tol = math.cos(math.radians(puma.TOL_DEG))
    axes_ok = []
    for k, row in enumerate(rows):
        d_st = row.theta.sign * F[:, k, :3, 2]
        p_st = F[:, k, :3, 3]
        d_ref, p_ref = R[:, k, :3, 2], R[:, k, :3, 3]
        same_dir = np.einsum("ij,ij->i", d_st, d_ref) >= cos_tol
        v = p_ref - p_st
        off = np.linalg.norm(v - np.einsum("ij,ij->i", v, d_st)[:, None] * d_st, axis=1)
        axes_ok.append(bool(np.all(same_dir & (off <= puma.TOL_POS))))
    ee = np.linalg.norm(F[:, -1, :3, 3] - R[:, -1, :3, 3], axis=1)
    return {"axes": axes_ok, "end_effector": bool(np.all(ee <= puma.TOL_POS)), "configurations": len(Q),
            "frames": F}


def _chain_item(answers: Answers, rows) -> Item:
    """The chain must be the product of your T1…Tn, in this order (a factor stands for
    T_k when the variable T_k itself is missing)."""
    n = puma.reference().n
    chain = answers.chain
    example = " @ ".join(f"T{i}" for i in range(1, n + 1))
    if chain is NOT_ANSWERED:
        return Item("chain", None, f"not answered (write chain = {example})")
    if isinstance(chain, Unreadable):
        return Item("chain", False, chain.why)
    if len(chain) != n:
        return Item("chain", False, f"it has {len(chain)} transformations; the PUMA's chain has {n}: {example}")
    given = {k: row for k, row in enumerate(answers.T, start=1) if isinstance(row, Row)}
    for k, factor in enumerate(chain, start=1):
        if k in given and factor != given[k]:
            other = [j for j, row in given.items() if row == factor]
            what = f"your T{other[0]}" if other else factor.text()
            return Item("chain", False, f"its factor {k} is {what}, not your T{k}; the chain multiplies "
                                        f"in order: chain = {example}")
    return Item(f"chain = {example}", True)


def check_part3(answers: Answers, _analysis: _Analysis | None = None) -> PartResult:
    ref = puma.reference()
    analysis = _analysis or _analyse(answers)
    items = analysis.items + [_chain_item(answers, analysis.rows)]
    part = PartResult("part3", items)
    if analysis.structural_ok:
        match = chain_matches(analysis.rows)
        good_axes = [k + 1 for k, ok in enumerate(match["axes"]) if ok]
        m = match["configurations"]
        if all(match["axes"]) and match["end_effector"]:
            part.notes.append(f"Your chain moves like the PUMA: all {ref.n} joint axes (as directed lines) and "
                              f"the end effector match at the home pose and {m - 1} random configurations.")
        else:
            bad = [k + 1 for k, ok in enumerate(match["axes"]) if not ok]
            axes = (f"{_joints(good_axes)} {'match' if len(good_axes) > 1 else 'matches'}" if good_axes
                    else "no joint axis matches")
            if bad and good_axes:
                axes += f", {_joints(bad)} {'do' if len(bad) > 1 else 'does'} not"
            elif not bad:
                axes = "every joint axis matches"
            part.notes.append(f"Compared with the PUMA at the home pose and {m - 1} random configurations: "
                              f"{axes}; the end effector {'matches' if match['end_effector'] else 'does not'}.")
            if all(item.ok for item in analysis.items):      # cannot happen: the checks disagree
                part.notes.append("(internal check failed: please report this answer to the course authors)")
    return part


def _list(numbers) -> str:
    return ", ".join(str(k) for k in numbers)


def _joints(numbers) -> str:
    return f"the axes of joints {_list(numbers)}" if len(numbers) > 1 else f"the axis of joint {numbers[0]}"


# --- part 2: each link in its own frame ----------------------------------------------------

def check_part2(answers: Answers, _analysis: _Analysis | None = None) -> PartResult:
    """Each link's points, in its own DH frame. When every T_i of part 3 is right, the
    frame is the one the student's transformations build (so that the chain draws the
    robot without touching the models); otherwise any valid DH frame of the link is
    accepted (a mistake in part 3 costs marks in part 3 only)."""
    ref = puma.reference()
    analysis = _analysis or _analyse(answers)
    value = answers.link_points
    chain_right = bool(analysis.items) and all(item.ok for item in analysis.items)
    items = []
    for k in range(ref.n + 1):
        label = f"link {k} ({puma.LINK_NAMES[k]})"
        if value is NOT_ANSWERED:
            items.append(Item(label, None, "not answered"))
            continue
        if isinstance(value, Unreadable):
            items.append(Item(label, False, value.why))
            continue
        points = value[k] if k < len(value) else NOT_ANSWERED
        if points is NOT_ANSWERED:
            items.append(Item(label, None, "not answered"))
        elif isinstance(points, Unreadable):
            items.append(Item(label, False, points.why))
        else:
            frame = analysis.frames[k] if chain_right else None
            items.append(_check_link(ref, k, label, np.array(points, float), frame))
    part = PartResult("part2", items)
    if part.answered and not chain_right and any(isinstance(r, Row) for r in analysis.rows):
        part.notes.append("(your transformations are not all right yet, so each link was checked against the "
                          "DH rules alone; once part 3 is right, each link must fit the frame your chain builds)")
    if isinstance(value, list) and len(value) > ref.n + 1:
        part.notes.append(f"(link_points has {len(value)} links; the PUMA has {ref.n + 1}: links 0…{ref.n})")
    return part


def _check_link(ref, k: int, label: str, P, frame) -> Item:
    names = [name for name, _ in ref.points[k]]
    W = ref.world_points(k)
    if len(P) != len(W):
        return Item(label, False, f"give the {len(W)} points {', '.join(names)} in this order; you gave {len(P)}")
    shape = _shape_problem(names, P, W)
    if shape:
        return Item(label, False, shape)
    if frame is not None:
        placed = P @ frame[:3, :3].T + frame[:3, 3]
        miss = np.linalg.norm(placed - W, axis=1)
        if miss.max() <= puma.TOL_POS:
            return Item(label, True, f"fits your frame {k}")
        _, err = puma.fit_link(ref, k, P)
        j = int(np.argmax(miss))
        if err <= puma.TOL_POS:
            return Item(label, False, f"drawn in a valid DH frame {k}, but not in the frame {k} your "
                                      f"transformations build (T1···T{k}): assembled, point {names[j]} lands at "
                                      f"{_vec(placed[j])} instead of {_vec(W[j])}")
        return Item(label, False, _frame_problem(ref, k, names, P, W))
    _, err = puma.fit_link(ref, k, P)
    if err <= puma.TOL_POS:
        return Item(label, True, f"in a valid DH frame {k}" if k else "in frame 0")
    return Item(label, False, _frame_problem(ref, k, names, P, W))


def _shape_problem(names, P, W) -> str:
    """A message if the points cannot be the link at all (distances between them differ)."""
    worst, pair = 0.0, None
    for a in range(len(P)):
        for b in range(a + 1, len(P)):
            diff = abs(np.linalg.norm(P[a] - P[b]) - np.linalg.norm(W[a] - W[b]))
            if diff > worst:
                worst, pair = diff, (a, b)
    if worst <= puma.TOL_POS:
        return ""
    a, b = pair
    return (f"these points are not the link's shape: {names[a]}–{names[b]} is "
            f"{np.linalg.norm(P[a] - P[b]):.4f} m apart in your answer and {np.linalg.norm(W[a] - W[b]):.4f} m "
            f"on the robot (a coordinate mixed up, or points out of order?)")


def _frame_problem(ref, k: int, names, P, W) -> str:
    """The link has the right shape but no valid DH frame k puts it there: say why."""
    n = ref.n
    if k == 0:
        return "link 0 is given in frame 0, the world frame at the shoulder: its points are the table's"
    G = _rigid_fit(P, W)
    if G is not None and np.linalg.norm(P @ G[:3, :3].T + G[:3, 3] - W, axis=1).max() > puma.TOL_POS:
        return ("your coordinates are a mirror image of the link: is your frame right-handed "
                f"(dextrógiro, y{k} = z{k} × x{k})?")
    if G is not None:
        R, o = G[:3, :3], G[:3, 3]
        axis = ref.axes[k] if k < n else ref.axes[n - 1]
        local = R.T @ axis.direction
        which = int(np.argmax(np.abs(local)))
        joint = k + 1 if k < n else n
        if abs(local[2]) < math.cos(math.radians(puma.TOL_DEG)):
            where = f"along your local {'xyz'[which]} axis" if abs(local[which]) > 0.999 else "tilted from your z axis"
            return (f"in its own DH frame the axis of joint {joint} must be the z axis (z{k}: "
                    f"seed 000, figures 11–12); in your model it lies {where}")
        if k == n:
            miss = float(np.linalg.norm(o - ref.wrist_centre))
            return (f"frame {n}'s origin is the wrist centre W (the end effector); in your model the "
                    f"origin is {miss:.4f} m from W")
        off = axis.distance_to_point(o)
        if off > puma.TOL_POS:
            return (f"z{k} runs along the axis of joint {k + 1}, but your frame's origin is {off:.4f} m off "
                    f"that axis; the origin of frame {k} lies on it")
        rel = puma.relation(ref.axes[k - 1], ref.axes[k])
        return (f"your x{k} must lie along the common normal of the axes of joints {k} and {k + 1} "
                f"({rel.kind}: x{k} ⟂ both, crossing the axis of joint {k}); in your model it does not")
    C, _ = puma.fit_link(ref, k, P)
    expected = (W - C[:3, 3]) @ C[:3, :3]
    j = int(np.argmax(np.linalg.norm(expected - P, axis=1)))
    return (f"no valid DH frame {k} gives these coordinates; in the valid frame {k} nearest to your answer, "
            f"point {names[j]} would be at {_vec(expected[j])}, yours is {_vec(P[j])}")


def _rigid_fit(P, W):
    """The rigid motion G with G·P ≈ W (Kabsch), or None when P is (nearly) collinear."""
    Pc, Wc = P - P.mean(axis=0), W - W.mean(axis=0)
    if np.linalg.svd(Pc, compute_uv=False)[1] < 1e-6:
        return None
    U, _, Vt = np.linalg.svd(Pc.T @ Wc)
    D = np.diag([1, 1, np.sign(np.linalg.det(Vt.T @ U.T))])
    R = Vt.T @ D @ U.T
    G = np.eye(4)
    G[:3, :3], G[:3, 3] = R, W.mean(axis=0) - R @ P.mean(axis=0)
    return G


# --- all parts ---------------------------------------------------------------------------

def check_all(answers: Answers) -> Report:
    """Every scored part (1–3; part 4, the teach panel, is not scored)."""
    analysis = _analyse(answers)
    return Report([check_part1(answers), check_part2(answers, analysis), check_part3(answers, analysis)])
