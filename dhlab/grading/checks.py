"""Fair checks of the DH assignment, with feedback that names the joint and the quantity.

DH frames are not unique, so nothing here compares a table with one answer key.
The checks compare what every valid answer shares (see :mod:`dhlab.grading.puma`):

* part 1 (the sketch): counts, joint types, and how each pair of consecutive joint
  axes meets — facts of the robot, computed from the reference's axes;
* part 2 (each link in its own frame): the link's points must land on the robot's
  points when placed by *a valid DH frame of that link* (the DH rules alone: part 2
  never changes with part 3; a note says when the links are not drawn in the frames
  the student's own transformations build);
* part 3 (the transformations, :mod:`dhlab.grading.part3`): each ``T_i`` is judged
  against the frame the student evidently intended, so one slip costs one item and
  the feedback names the parameter at fault. Every valid choice (signs of the axes,
  origins along parallel axes, the last frame's x) passes. When every ``T_i`` is
  right, the whole chain is also compared with the robot at random configurations:
  every joint axis as a directed line and the end-effector position.

The robot is a parameter (``ref``): the PUMA 560 of :func:`dhlab.grading.puma.reference`
(the default), or a student's own robot, an
:class:`~dhlab.course.family_model.AssignmentRobot` (:mod:`dhlab.grading.variants`).

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
from .part3 import Analysis, Item, analyse, chain_matches, matrix, random_configurations, rows_of

__all__ = ["POINTS", "Item", "PartResult", "Report", "check_part1", "check_part2", "check_part3",
           "check_all", "random_configurations", "chain_matches"]

POINTS = {"part1": 2, "part2": 3, "part3": 5}
TITLES = {"part1": "the sketch", "part2": "each link in its own frame",
          "part3": "the transformations and their chain"}


@dataclass
class PartResult:
    key: str
    items: list
    notes: list = field(default_factory=list)    # not scored: context for the student
    unread: str = ""                              # why the grader could not read the answers (their cell failed)

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
            return [head + (f", not read: {self.unread}" if self.unread else ", not answered")]
        out = [head]
        for item in self.items:
            mark = {True: "✓", False: "✗", None: "·"}[item.ok]
            out.append(f"  {mark} {item.label}: {item.message}" if item.message else f"  {mark} {item.label}")
        out += [f"  {note}" for note in self.notes]
        if self.unread:
            out.append(f"  (not all read: {self.unread})")
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
    robot: str = "PUMA 560"        # the name of the robot the answers were checked against
    n: int = 6                     # its number of joints

    @property
    def score(self) -> float:
        return round(sum(p.score for p in self.parts), 2)

    @property
    def max_score(self) -> int:
        return sum(p.points for p in self.parts)

    def part(self, key: str) -> PartResult:
        return next(p for p in self.parts if p.key == key)

    def text(self) -> str:
        blocks = [f"{self.robot} assignment: {_num(self.score)}/{self.max_score} points"]
        blocks += [p.text() for p in self.parts]
        return "\n\n".join(blocks) + "\n"

    def __repr__(self):
        return self.text()


def _num(x: float) -> str:
    return f"{x:g}"


def _vec(v, digits: int = 4) -> str:
    """A point as '(x, y, z)'; rounded first, so that -0.00001 prints as 0.0000, not -0.0000."""
    return "(" + ", ".join(f"{round(x, digits) + 0.0:.{digits}f}" for x in np.asarray(v, float).tolist()) + ")"


# --- part 1: the sketch ----------------------------------------------------------------

def check_part1(answers: Answers, ref=None) -> PartResult:
    """Counts, joint types and the case of each x_i. Wrong answers get a hint of where
    to look, never the answer itself."""
    ref = ref or puma.reference()
    n = ref.n
    items = []

    def count(label, value, expected, hint):
        if value is NOT_ANSWERED:
            items.append(Item(label, None, "not answered"))
        elif isinstance(value, Unreadable):
            items.append(Item(label, False, value.why))
        elif value == expected:
            items.append(Item(f"{label} = {value}", True))
        else:
            items.append(Item(label, False, f"you wrote {value}; {hint}" if hint else f"you wrote {value}"))

    count("n_links", answers.n_links, n + 1,
          "count every link (eslabón), the fixed base too: it is link 0 (seed 000, paso 0)")
    count("n_joints", answers.n_joints, n,
          "count the joints (articulaciones) between the base and the gripper: each has its own axis in the picture")
    kinds = list(ref.kinds)
    types = answers.joint_types
    if isinstance(types, list) and types != kinds:
        wrong = [f"joint {j + 1}" for j, k in enumerate(kinds) if j >= len(types) or types[j] != k]
        extra = f"; you gave {len(types)} letters for {n} joints" if len(types) != n else ""
        items.append(Item("joint_types", False, f"look again at how the figure draws {', '.join(wrong[:3])} "
                                                f"(a curled arrow: it turns; a straight one: it slides){extra}"))
    else:
        count("joint_types", "".join(types) if isinstance(types, list) else types, "".join(kinds), "")
    cases = answers.x_cases
    for i in range(1, n):
        label = f"x{i}"
        expected = puma.relation(ref.axes[i - 1], ref.axes[i]).kind
        accepted = {expected, "parallel"} if expected == "coincident" else {expected}   # case 2 covers both
        if "P" in ref.kinds[i - 1:i + 1]:      # a sliding joint's axis may be drawn on any line parallel to it:
            if expected == "parallel":          # on the other axis,
                accepted.add("coincident")
            elif expected in ("intersect", "skew"):
                accepted |= {"intersect", "skew"}   # through the other axis or past it
        if cases is NOT_ANSWERED or (isinstance(cases, list) and (i > len(cases) or cases[i - 1] is None)):
            items.append(Item(label, None, "not answered"))
        elif isinstance(cases, Unreadable):
            items.append(Item(label, False, cases.why))
        elif cases[i - 1] in accepted:
            items.append(Item(f"{label}: {cases[i - 1]}", True))
        else:
            items.append(Item(label, False, f"you wrote {cases[i - 1]!r}: look again at the axes of joints {i} and "
                                            f"{i + 1} (z{i - 1} and z{i}) in the table: are their directions "
                                            f"parallel and, if not, do the two lines meet?"))
    part = PartResult("part1", items)
    if isinstance(cases, list) and len(cases) != n - 1:
        part.notes.append(f"(x_cases has {len(cases)} entries: give one for each i = 1…{n - 1}; "
                          f"the last frame's x{n} is the special case of paso 0)")
    return part


# --- part 3: the transformations (the analysis is in part3.py) ------------------------------

_rows, _matrix = rows_of, matrix


def _analyse(answers: Answers, ref=None) -> Analysis:
    return analyse(answers, ref)


def _chain_item(answers: Answers, rows, n: int) -> Item:
    """The chain must be the product of your T1…Tn, in this order (a factor stands for
    T_k when the variable T_k itself is missing)."""
    chain = answers.chain
    example = " @ ".join(f"T{i}" for i in range(1, n + 1))
    if chain is NOT_ANSWERED:
        return Item("chain", None, f"not answered (write chain = {example})")
    if isinstance(chain, Unreadable):
        return Item("chain", False, chain.why)
    if len(chain) != n:
        return Item("chain", False, f"it has {len(chain)} transformations; the robot's chain has {n}: {example}")
    given = {k: row for k, row in enumerate(answers.T[:n], start=1) if isinstance(row, Row)}
    for k, factor in enumerate(chain, start=1):
        if k in given and factor != given[k]:
            other = [j for j, row in given.items() if row == factor]
            what = f"your T{other[0]}" if other else factor.text()
            return Item("chain", False, f"its factor {k} is {what}, not your T{k}; the chain multiplies "
                                        f"in order: chain = {example}")
    return Item(f"chain = {example}", True)


def check_part3(answers: Answers, _analysis: Analysis | None = None, ref=None) -> PartResult:
    """Each T_i against the frame the student meant (:mod:`dhlab.grading.part3`), and the chain."""
    analysis = _analysis or analyse(answers, ref)
    ref = analysis.ref
    items = analysis.items + [_chain_item(answers, analysis.rows, ref.n)]
    part = PartResult("part3", items)
    if analysis.structural_ok and all(item.ok for item in analysis.items):
        match = chain_matches(analysis.rows, ref=ref)
        m = match["configurations"]
        if all(match["axes"]) and match["end_effector"] and match["last_z"]:
            part.notes.append(f"Your T1…T{ref.n} move like the {ref.name}: all {ref.n} joint axes (as directed "
                              f"lines) and the end effector match at the home pose and {m - 1} random configurations.")
        else:                                       # cannot happen: the two checks disagree
            part.notes.append("(internal check failed: please report this answer to the course authors)")
    return part


# --- part 2: each link in its own frame ----------------------------------------------------

def check_part2(answers: Answers, _analysis: Analysis | None = None, ref=None) -> PartResult:
    """Each link's points, in a valid DH frame of that link (the DH rules alone, so a
    mistake in part 3 never changes part 2's score, and part 2 is scored the same
    whichever valid frames part 3 uses). When the links are valid but are not drawn in
    the frames the student's own T_1…T_k build, a note (not scored) says which."""
    ref = ref or (_analysis.ref if _analysis else None) or puma.reference()
    value = answers.link_points
    items, fitted = [], []
    for k in range(ref.n + 1):
        label = f"link {k} ({ref.link_names[k]})"
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
            items.append(_check_link(ref, k, label, np.array(points, float)))
            if items[-1].ok:
                fitted.append((k, np.array(points, float)))
    part = PartResult("part2", items)
    if isinstance(value, list) and len(value) > ref.n + 1:
        part.notes.append(f"(link_points has {len(value)} links; the robot has {ref.n + 1}: links 0…{ref.n})")
    if _analysis is not None and _analysis.structural_ok and all(item.ok for item in _analysis.items):
        apart = []
        for k, P in fitted:
            F = _analysis.frames[k]
            if np.linalg.norm(P @ F[:3, :3].T + F[:3, 3] - ref.world_points(k), axis=1).max() > puma.TOL_POS:
                apart.append(k)
        if apart:
            which = ", ".join(str(k) for k in apart)
            part.notes.append(f"(not scored) link{'s' if len(apart) > 1 else ''} {which}: drawn in a valid DH frame, "
                              f"but not in the one your T1…T{ref.n} build, so your assembled robot (the figure "
                              f"below) will not draw the {ref.name}; use the same frames in parts 2 and 3")
    return part


def _check_link(ref, k: int, label: str, P) -> Item:
    names = [name for name, _ in ref.points[k]]
    W = ref.world_points(k)
    if len(P) != len(W):
        return Item(label, False, f"give the {len(W)} points {', '.join(names)} in this order; you gave {len(P)}")
    shape = _shape_problem(names, P, W)
    if shape:
        return Item(label, False, shape)
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
        return "link 0 is given in frame 0, the world frame drawn in the figure: its points are the table's"
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
            miss = float(np.linalg.norm(o - ref.end_point))
            return (f"frame {n}'s origin (the end effector's) is {ref.end_text}; in your model the "
                    f"origin is {miss:.4f} m from it")
        off = axis.distance_to_point(o)
        if ref.kinds[k] == "R" and off > puma.TOL_POS:
            return (f"z{k} runs along the axis of joint {k + 1}, but your frame's origin is {off:.4f} m off "
                    f"that axis; the origin of frame {k} lies on it")
        rel = puma.relation(ref.axes[k - 1], ref.axes[k])
        if "P" in ref.kinds[k - 1:k + 1]:
            return (f"your x{k} must be square to the axes of joints {k} and {k + 1} and cross the line you "
                    f"chose for z{k - 1} (a sliding joint's axis may be drawn on any line parallel to it, but "
                    f"x{k} then follows it); in your model it does not")
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

def check_all(answers: Answers, ref=None) -> Report:
    """Every scored part (1–3; part 4, the teach panel, is not scored), against the
    reference robot ``ref`` (default: the PUMA 560)."""
    analysis = analyse(answers, ref)
    ref = analysis.ref
    parts = [check_part1(answers, ref), check_part2(answers, analysis, ref), check_part3(answers, analysis)]
    return Report(parts, ref.name, ref.n)
