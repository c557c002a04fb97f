"""The fair checks of the DH assignment, with feedback that names the joint and the quantity.

DH frames are not unique, so nothing here compares a table with one answer key. The checks
compare what every valid answer shares, computed from the robot being graded
(:mod:`dhlab.assignment.reference`: the PUMA 560's joint axes, links and tolerances;
:mod:`dhlab.assignment.valid_frames`: every valid DH frame of each link). The notebook's
immediate feedback and the grader run these same checks on the same data
(:mod:`dhlab.assignment.answers`).

The map of the checks:

* **this module** — :func:`check_all` and the three parts' results (:class:`Report`,
  :class:`PartResult`); part 1 (the sketch: counts, joint types, and how each pair of
  consecutive joint axes meets) is checked here, :func:`check_part1`;
* :mod:`~dhlab.assignment.checks.analysis` — what parts 2 and 3 share: :class:`Item`, the
  :class:`~dhlab.assignment.checks.analysis.Analysis` (the frames the student meant), one row
  on one frame (``fits``), the slips students make;
* :mod:`~dhlab.assignment.checks.transforms` — part 3: each ``T_i`` judged against the frame
  the student evidently intended, so one slip costs one item and the feedback names the
  parameter at fault; every valid choice (signs of the axes, origins along parallel axes, the
  last frame's x) passes;
* :mod:`~dhlab.assignment.checks.offsets` — which offset d_k to name along a run of parallel axes;
* :mod:`~dhlab.assignment.checks.chain_motion` — when every ``T_i`` is right, the whole chain
  compared with the robot at random configurations (every joint axis as a directed line, and
  the end effector);
* :mod:`~dhlab.assignment.checks.links` — part 2: each link's points must land on the robot's
  when placed by a valid DH frame of that link, the one the student's own transformations
  build (a row part 3 already charges is not charged again here).

The robot is a parameter (``ref``): the PUMA 560 of :func:`dhlab.assignment.reference.reference`
(the default), or a student's own robot, an :class:`~dhlab.assignment.model.AssignmentRobot`
(:mod:`dhlab.assignment.variants`).

>>> from dhlab.assignment.answers import parse_answers
>>> report = check_all(parse_answers({}))
>>> report.score, report.max_score
(0.0, 10)
>>> print(report.parts[0].lines()[0])
Part 1 (the sketch): 0/2 points, not answered
"""
from __future__ import annotations

import html
import re
from dataclasses import dataclass, field

from ...i18n import N_, _, case_word
from ..answers import NOT_ANSWERED, Answers, Row, Unreadable, written_case
from ..family import shown_name
from ..reference import reference, relation
from .analysis import Analysis, Item, matrix, rows_of
from .chain_motion import chain_matches, random_configurations
from .links import link_items
from .transforms import analyse

__all__ = ["POINTS", "TITLES", "Item", "PartResult", "Report", "check_part1", "check_part2", "check_part3",
           "check_all", "reading", "analysis_of", "rows_of", "matrix", "random_configurations", "chain_matches"]

LETTER = re.compile(r"[^\W\d_]")        # a word, not a case's number
POINTS = {"part1": 2, "part2": 3, "part3": 5}
TITLES = {"part1": N_("the sketch"), "part2": N_("each link in its own frame"),
          "part3": N_("the transformations and their chain")}


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
        return _(TITLES[self.key])

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
        head = _("Part {number} ({title}): {score}/{points} points").format(
            number=number, title=self.title, score=_num(self.score), points=self.points)
        if not self.answered:
            return [head + (_(", not read: {why}").format(why=self.unread) if self.unread else _(", not answered"))]
        out = [head]
        for item in self.items:
            mark = {True: "✓", False: "✗", None: "·"}[item.ok]
            out.append(f"  {mark} {item.label}: {item.message}" if item.message else f"  {mark} {item.label}")
        out += [f"  {note}" for note in self.notes]
        if self.unread:
            out.append("  " + _("(not all read: {why})").format(why=self.unread))
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
        blocks = [_("{robot} assignment: {score}/{max_score} points").format(
            robot=shown_name(self.robot), score=_num(self.score), max_score=self.max_score)]
        blocks += [p.text() for p in self.parts]
        return "\n\n".join(blocks) + "\n"

    def __repr__(self):
        return self.text()


def _num(x: float) -> str:
    return f"{x:g}"


# --- part 1: the sketch ----------------------------------------------------------------

def check_part1(answers: Answers, ref=None) -> PartResult:
    """Counts, joint types and the case of each x_i. Wrong answers get a hint of where
    to look, never the answer itself."""
    ref = ref or reference()
    n = ref.n
    items = []

    def count(label, value, expected, hint):
        if value is NOT_ANSWERED:
            items.append(Item(label, None, _("not answered")))
        elif isinstance(value, Unreadable):
            items.append(Item(label, False, value.why))
        elif value == expected:
            items.append(Item(f"{label} = {value}", True))
        else:
            wrote = _("you wrote {value}").format(value=value)
            items.append(Item(label, False, f"{wrote}; {hint}" if hint else wrote))

    count("n_links", answers.n_links, n + 1,
          _("count every link (eslabón), the fixed base too: it is link 0 (seed 000, paso 0)"))
    count("n_joints", answers.n_joints, n,
          _("count the joints (articulaciones) between the base and the gripper: each has its own axis in the picture"))
    kinds = list(ref.kinds)
    types = answers.joint_types
    if isinstance(types, list) and types != kinds:
        wrong = [_("joint {j}").format(j=j + 1) for j, k in enumerate(kinds) if j >= len(types) or types[j] != k]
        extra = _("; you gave {count} letters for {n} joints").format(count=len(types), n=n) if len(types) != n else ""
        look = _("look again at how the figure draws {joints} (a curled arrow: it turns; a straight one: it "
                 "slides)").format(joints=", ".join(wrong[:3]))
        items.append(Item("joint_types", False, look + extra))
    else:
        count("joint_types", "".join(types) if isinstance(types, list) else types, "".join(kinds), "")
    cases = answers.x_cases
    for i in range(1, n):
        label = f"x{i}"
        expected = relation(ref.axes[i - 1], ref.axes[i]).kind
        accepted = {expected, "parallel"} if expected == "coincident" else {expected}   # case 2 covers both
        if "P" in ref.kinds[i - 1:i + 1]:      # a sliding joint's axis may be drawn on any line parallel to it:
            if expected == "parallel":          # on the other axis,
                accepted.add("coincident")
            elif expected in ("intersect", "skew"):
                accepted |= {"intersect", "skew"}   # through the other axis or past it
        if cases is NOT_ANSWERED or (isinstance(cases, list) and (i > len(cases) or cases[i - 1] is None)):
            items.append(Item(label, None, _("not answered")))
        elif isinstance(cases, Unreadable):
            items.append(Item(label, False, cases.why))
        elif isinstance(cases[i - 1], Unreadable):     # one word not read: this item's slip, not the list's
            items.append(Item(label, False, cases[i - 1].why))
        elif cases[i - 1] in accepted:         # the student's own words, quoted back (a number: the case's)
            wrote = written_case(cases[i - 1])
            shown = wrote if LETTER.search(wrote) else case_word(cases[i - 1])
            items.append(Item(f"{label}: {shown}", True))
        else:
            items.append(Item(label, False, _("you wrote {case!r}: look again at the axes of joints {i} and {next} "
                                              "(z{previous} and z{i}) in the table: are their directions parallel and, "
                                              "if not, do the two lines meet?").format(
                case=written_case(cases[i - 1]), i=i, next=i + 1, previous=i - 1)))
    part = PartResult("part1", items)
    if isinstance(cases, list) and len(cases) != n - 1:
        part.notes.append(_("(x_cases has {count} entries: give one for each i = 1…{last}; the last frame's x{n} "
                            "is the special case of paso 0)").format(count=len(cases), last=n - 1, n=n))
    return part


# --- part 3: the transformations (the analysis is in transforms.py) ------------------------------

def analysis_of(answers: Answers, ref=None) -> Analysis:
    """Part 3's reading of the rows, as :func:`check_all` makes it (the one the links of part 2
    agree with): the frames the student meant, for the notebook's pictures too."""
    return reading(answers, analyse(answers, ref))



def _chain_item(answers: Answers, n: int) -> Item:
    """The chain must be the product of your T1…Tn, in this order (a factor stands for
    T_k when the variable T_k itself is missing)."""
    chain = answers.chain
    example = " @ ".join(f"T{i}" for i in range(1, n + 1))
    if chain is NOT_ANSWERED:
        return Item("chain", None, _("not answered (write chain = {example})").format(example=example))
    if isinstance(chain, Unreadable):
        return Item("chain", False, chain.why)
    if len(chain) != n:
        return Item("chain", False, _("it has {count} transformations; the robot's chain has {n}: {example}").format(
            count=len(chain), n=n, example=example))
    given = {k: row for k, row in enumerate(answers.T[:n], start=1) if isinstance(row, Row)}
    for k, factor in enumerate(chain, start=1):
        if k in given and factor != given[k]:
            other = [j for j, row in given.items() if row == factor]
            what = _("your T{j}").format(j=other[0]) if other else factor.text()
            return Item("chain", False, _("its factor {k} is {what}, not your T{k}; the chain multiplies in order: "
                                          "chain = {example}").format(k=k, what=what, example=example))
    return Item(f"chain = {example}", True)


def check_part3(answers: Answers, analysis: Analysis | None = None, ref=None) -> PartResult:
    """Each T_i against the frame the student meant (:mod:`~dhlab.assignment.checks.transforms`),
    and the chain."""
    analysis = analysis or analysis_of(answers, ref)
    ref = analysis.ref
    items = analysis.items + [_chain_item(answers, ref.n)]
    part = PartResult("part3", items)
    if analysis.structural_ok and all(item.ok for item in analysis.items):
        match = chain_matches(analysis.rows, ref=ref)
        m = match["configurations"]
        if all(match["axes"]) and match["end_effector"] and match["last_z"]:
            part.notes.append(_("Your T1…T{n} move like the {robot}: all {n} joint axes (as directed lines) and the "
                                "end effector match at the home pose and {m} random configurations.").format(
                n=ref.n, robot=shown_name(ref.name), m=m - 1))
        else:                                       # cannot happen: the two checks disagree
            part.notes.append(_("(internal check failed: please report this answer to the course authors)"))
    return part


# --- part 2: each link in its own frame (the checks are in links.py) ----------------------------

def reading(answers: Answers, analysis: Analysis) -> Analysis:
    """Of the readings of part 3 that charge as many rows (the best and its alternatives), the one
    in whose frames the most links of part 2 are drawn: a slip in T5 that part 3 may equally read
    as a flip of frame 4 is read as the links say (one slip, one item, in both parts)."""
    best, most = analysis, None
    for candidate in [analysis] + analysis.alternatives:
        good = sum(1 for item in link_items(answers, candidate, candidate.ref)[0] if item.ok)
        if most is None or good > most:
            best, most = candidate, good
        if most == candidate.ref.n + 1:
            break
    return best


def check_part2(answers: Answers, analysis: Analysis | None = None, ref=None) -> PartResult:
    """Each link's points, in the frame the student's own T_1…T_k give that link
    (:mod:`~dhlab.assignment.checks.links`): one item per link; a slip already charged in part 3
    is not charged again here."""
    analysis = analysis or analysis_of(answers, ref)
    items, notes = link_items(answers, analysis, analysis.ref)
    return PartResult("part2", items, notes)


# --- all parts ---------------------------------------------------------------------------

def check_all(answers: Answers, ref=None) -> Report:
    """Every scored part (1–3; part 4, the teach panel, is not scored), against the
    reference robot ``ref`` (default: the PUMA 560)."""
    analysis = analysis_of(answers, ref)
    ref = analysis.ref
    parts = [check_part1(answers, ref), check_part2(answers, analysis, ref), check_part3(answers, analysis)]
    return Report(parts, ref.name, ref.n)
