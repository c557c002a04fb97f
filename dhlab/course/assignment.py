"""The PUMA 560 assignment (notebook 8): the pieces its cells use.

Seed 000 ends with an exercise: do the DH configuration of the PUMA robot, graded
in three points — the sketch, the link models drawn in their own frames, and the
transformations ``T_i = Tz[θ_i, d_i]·Tx[α_i, a_i]``. This module gives the
notebook the robot to look at, the two factors to write the transformations with,
a teach panel for the student's own robot, and immediate feedback after each part
(the same checks, on the same plain data, as the grader: :mod:`dhlab.grading`).

The transformations are written as in the seed (angles in **degrees**, lengths in
metres), with the joint variables q1…q6:

>>> q1, q2, q3, q4, q5, q6 = joint_variables(6)
>>> T3 = Tz(q3, 0.15005) @ Tx(-90, 0.0203)
>>> T3
Tz[q3, 0.15005]·Tx[-90°, 0.0203]
>>> T3.matrix(0).round(5)[:3, 3].tolist()        # numeric at q3 = 0 (radians)
[0.0203, 0.0, 0.15005]
>>> chain = T3 @ T3
>>> len(chain)
2
>>> Tx(90, 0) @ Tz(q1, 0)
Traceback (most recent call last):
...
dhlab.validation.DHLabError: only the form Tz[θ, d]·Tx[α, a] is allowed (seed 000): write Tz(...) @ Tx(...), Tz first.
"""
from __future__ import annotations

import math
import numbers
import re

import numpy as np

from ..grading import answers as _answers
from ..grading import checks as _checks
from ..grading import puma as _puma
from ..units import is_angle
from ..validation import DHLabError

__all__ = ["joint_variables", "Tz", "Tx", "JointTerm", "ZFactor", "XFactor", "DHTransform", "DHChain",
           "check_part1", "check_part2", "check_part3", "check_part", "Feedback",
           "axes_table", "points_table", "puma_figure", "robot_of", "teach", "my_robot_figure", "Note"]


# --- the joint variables and the two factors -------------------------------------------------

def _degrees(value, what: str) -> float:
    """A number typed in degrees (a value made by dhlab.deg() is converted back)."""
    if is_angle(value):
        return math.degrees(float(value))
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        try:
            value = float(value)            # numpy / sympy numbers
        except (TypeError, ValueError):
            raise DHLabError(f"{what} must be a number of degrees, got {value!r}.") from None
    if not math.isfinite(float(value)):
        raise DHLabError(f"{what} must be a finite number of degrees, got {value!r}.")
    return float(value)


def _length(value, what: str) -> float:
    if is_angle(value):
        raise DHLabError(f"{what} is a length, but you gave an angle ({value!r}): give metres.")
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        try:
            value = float(value)
        except (TypeError, ValueError):
            raise DHLabError(f"{what} must be a number (metres), got {value!r}.") from None
    if not math.isfinite(float(value)):
        raise DHLabError(f"{what} must be a finite length, got {value!r}.")
    return float(value)


class JointTerm:
    """``±q_j + constant``: a joint variable with a constant offset (degrees for θ, metres for d).

    >>> q1, q2 = joint_variables(2)
    >>> q2 + 90, -q1, 90 - q2
    (q2 + 90, -q1, -q2 + 90)
    """

    def __init__(self, joint: int, sign: int = 1, const: float = 0.0):
        self.joint, self.sign, self.const = int(joint), int(sign), float(const)

    def _shift(self, number, sign_of_number=1):
        if isinstance(number, JointTerm):
            raise DHLabError("θ_i holds one joint variable, q_i, plus a constant: "
                             f"{self!r} and {number!r} cannot be added.")
        if is_angle(number):
            number = math.degrees(float(number))
        if isinstance(number, bool) or not isinstance(number, numbers.Real):
            raise DHLabError(f"add a number (degrees) to {self!r}, not {number!r}.")
        return JointTerm(self.joint, self.sign, self.const + sign_of_number * float(number))

    def __add__(self, number):
        return self._shift(number)

    __radd__ = __add__

    def __sub__(self, number):
        return self._shift(number, -1)

    def __rsub__(self, number):
        return (-self)._shift(number)

    def __neg__(self):
        return JointTerm(self.joint, -self.sign, -self.const)

    def __pos__(self):
        return self

    def __mul__(self, factor):
        if factor in (1, -1):
            return self if factor == 1 else -self
        raise DHLabError(f"θ_i = ±q_i + constant: the joint variable cannot be multiplied by {factor!r}.")

    __rmul__ = __mul__

    def __repr__(self):
        var = ("-" if self.sign < 0 else "") + f"q{self.joint}"
        if self.const == 0:
            return var
        return f"{var} {'-' if self.const < 0 else '+'} {abs(self.const):g}"


def joint_variables(n: int = 6) -> tuple:
    """The joint variables q1…qn (physical joint angles, measured from the home pose)."""
    return tuple(JointTerm(j) for j in range(1, n + 1))


_TERM_TEXT = re.compile(r"^\s*(?:(?P<c1>[+-]?\s*\d+(?:\.\d*)?)\s*)?(?P<s>[+-])?\s*q(?P<j>\d+)\s*"
                        r"(?:(?P<c2>[+-]\s*\d+(?:\.\d*)?)\s*)?$")


def _term_from_text(value, what: str):
    """'q2 + 90', '-q3', '90 - q2' (or a sympy expression printed so) -> JointTerm."""
    text = str(value).replace("−", "-").replace("°", "")
    m = _TERM_TEXT.match(text)
    if not m or (m["c1"] and m["c2"]) or (m["c1"] and not m["s"]):
        raise DHLabError(f"{what} must be a number or ±q_i + a constant, like q2 + 90, got {value!r}.")
    const = float((m["c1"] or m["c2"] or "0").replace(" ", ""))
    return JointTerm(int(m["j"]), -1 if m["s"] == "-" else 1, const)


def _is_text(value) -> bool:
    return isinstance(value, str) or (hasattr(value, "free_symbols") and bool(value.free_symbols))


class ZFactor:
    """``Tz[θ, d]``: rotate θ about z, move d along z (seed 000's ``AplicarTHz``).

    θ may also be typed as text, as on the slides: ``Tz("q2 + 90", 0)``.
    """

    def __init__(self, theta, d):
        if _is_text(theta):
            theta = _term_from_text(theta, "θ in Tz[θ, d]")
        if _is_text(d):
            d = _term_from_text(d, "d in Tz[θ, d]")
        self.theta = theta if isinstance(theta, JointTerm) else _degrees(theta, "θ in Tz[θ, d]")
        self.d = d if isinstance(d, JointTerm) else _length(d, "d in Tz[θ, d]")

    def __matmul__(self, other):
        if isinstance(other, XFactor):
            return DHTransform(self, other)
        raise DHLabError("only the form Tz[θ, d]·Tx[α, a] is allowed (seed 000): a Tz is followed by a Tx.")

    __mul__ = __matmul__          # the seed writes the product with *

    def __repr__(self):
        theta = self.theta if isinstance(self.theta, JointTerm) else f"{self.theta:g}°"
        return f"Tz[{theta}, {self.d if isinstance(self.d, JointTerm) else format(self.d, 'g')}]"


class XFactor:
    """``Tx[α, a]``: rotate α about x, move a along x (seed 000's ``AplicarTHx``)."""

    def __init__(self, alpha, a):
        if isinstance(alpha, JointTerm) or isinstance(a, JointTerm):
            raise DHLabError("α and a are constants of the link: the joint variable goes in Tz "
                             "(in θ for a revolute joint).")
        self.alpha, self.a = _degrees(alpha, "α in Tx[α, a]"), _length(a, "a in Tx[α, a]")

    def __matmul__(self, other):
        raise DHLabError("only the form Tz[θ, d]·Tx[α, a] is allowed (seed 000): "
                         "write Tz(...) @ Tx(...), Tz first.")

    __mul__ = __matmul__

    def __repr__(self):
        return f"Tx[{self.alpha:g}°, {self.a:g}]"


def Tz(theta, d) -> ZFactor:
    """Seed 000's ``Tz[θ, d]``: θ in degrees (e.g. ``q2 + 90``), d in metres."""
    return ZFactor(theta, d)


def Tx(alpha, a) -> XFactor:
    """Seed 000's ``Tx[α, a]``: α in degrees, a in metres."""
    return XFactor(alpha, a)


class DHTransform:
    """One ``T_i = Tz[θ_i, d_i]·Tx[α_i, a_i]``; ``T_i @ T_j`` starts a chain."""

    def __init__(self, z: ZFactor, x: XFactor):
        self.z, self.x = z, x

    def __matmul__(self, other):
        if isinstance(other, (DHTransform, DHChain)):
            return DHChain([self]) @ other
        raise DHLabError("a transformation T_i is multiplied by another T_j (write T1 @ T2 @ ...).")

    __mul__ = __matmul__

    def matrix(self, q=None):
        """The 4x4 matrix: numeric at joint value ``q`` (radians), symbolic in q_i when omitted."""
        from .. import transforms
        theta, d = self.z.theta, self.z.d
        if q is None:
            import sympy as sp

            def exact(x):                   # 90 -> 90, 0.4318 -> 0.4318 (no 1.0 factors)
                return sp.Integer(int(x)) if float(x).is_integer() else sp.Float(x)

            def sym(part, unit):
                if isinstance(part, JointTerm):
                    return part.sign * sp.Symbol(f"q{part.joint}", real=True) + exact(part.const) * unit
                return exact(part) * unit
            return transforms.Tz(sym(theta, sp.pi / 180), sym(d, 1)) * transforms.Tx(
                sym(self.x.alpha, sp.pi / 180), sym(self.x.a, 1))
        return _checks._matrix(self._row(), float(q))

    def _row(self):
        return _answers.parse_answers({"T1": _answers.to_plain(self)}).T[0]

    def __repr__(self):
        return f"{self.z!r}·{self.x!r}"


class DHChain:
    """The chain ``T1·T2···Tn`` (the seed's ``THList`` product)."""

    def __init__(self, transforms):
        self.transforms = list(transforms)

    def __matmul__(self, other):
        if isinstance(other, DHTransform):
            return DHChain(self.transforms + [other])
        if isinstance(other, DHChain):
            return DHChain(self.transforms + other.transforms)
        raise DHLabError("a chain is multiplied by transformations T_i (write T1 @ T2 @ ...).")

    __mul__ = __matmul__

    def __len__(self):
        return len(self.transforms)

    def __getitem__(self, k):
        return self.transforms[k]

    def frames(self, q) -> np.ndarray:
        """Every frame 0…n at joint values ``q`` (radians), shape (n+1, 4, 4)."""
        rows = [t._row() for t in self.transforms]
        return _frames_of(rows, q)

    def matrix(self, q) -> np.ndarray:
        """The product at joint values ``q`` (radians)."""
        return self.frames(q)[-1]

    def __repr__(self):
        return " · ".join(f"({t!r})" for t in self.transforms)


def _frames_of(rows, q) -> np.ndarray:
    q = np.asarray(q, float)
    F = [np.eye(4)]
    for row in rows:
        j = row.joint[0]
        value = q[j - 1] if j is not None and j <= len(q) else 0.0
        F.append(F[-1] @ _checks._matrix(row, value))
    return np.array(F)


# --- immediate feedback ---------------------------------------------------------------------

class Feedback:
    """The result of checking one part: shown as a list of ✓/✗ lines; ``score`` and
    ``points`` are numbers (nbgrader reads ``score`` as the part's partial credit)."""

    def __init__(self, part, also=(), note: str = ""):
        self.part, self.also, self.note = part, list(also), note

    @property
    def score(self) -> float:
        return self.part.score

    @property
    def points(self) -> int:
        return self.part.points

    @property
    def full_marks(self) -> bool:
        return self.part.full_marks

    def text(self) -> str:
        blocks = [self.part.text()] + ([self.note] if self.note else [])
        blocks += [p.text() for p in self.also]
        return "\n".join(blocks)

    def __repr__(self):
        return self.text()

    def _repr_html_(self):
        import html
        note = f"<div><i>{html.escape(self.note)}</i></div>" if self.note else ""
        return self.part.html() + note + "".join(p.html() for p in self.also)


def check_part(part: int, namespace) -> Feedback:
    """Check part 1, 2 or 3 of the assignment from the notebook's variables
    (``namespace``: pass ``globals()``). The answers are read by name — n_links,
    n_joints, joint_types, x_cases (part 1), link_points (part 2), T1…T6 and chain
    (part 3) — exactly as the grader reads them."""
    if part not in (1, 2, 3):
        raise DHLabError(f"the assignment has parts 1, 2 and 3 to check, not {part!r}.")
    if not hasattr(namespace, "keys"):
        raise DHLabError("pass the notebook's variables: check_part(1, globals()).")
    answers = _answers.answers_from_namespace(namespace)       # exactly as the grader reads them
    if part == 1:
        return Feedback(_checks.check_part1(answers))
    if part == 2:
        return Feedback(_checks.check_part2(answers))
    analysis = _checks._analyse(answers)
    part3 = _checks.check_part3(answers, analysis)
    notes = [n for n in _checks.check_part2(answers, analysis).notes if n.startswith("(not scored)")]
    return Feedback(part3, note="\n".join(notes))


def check_part1(namespace) -> Feedback:
    """Part 1, the sketch: ``check_part1(globals())``."""
    return check_part(1, namespace)


def check_part2(namespace) -> Feedback:
    """Part 2, each link in its own frame: ``check_part2(globals())``."""
    return check_part(2, namespace)


def check_part3(namespace) -> Feedback:
    """Part 3, the transformations and the chain: ``check_part3(globals())``."""
    return check_part(3, namespace)


# --- what the student reads: axes and points at the home pose ---------------------------------

class _Table:
    """A small table shown as HTML in Jupyter and as aligned text elsewhere."""

    def __init__(self, title, header, rows):
        self.title, self.header, self.rows = title, header, rows

    def __repr__(self):
        widths = [max(len(str(r[c])) for r in [self.header, *self.rows]) for c in range(len(self.header))]
        lines = [self.title] + [" | ".join(str(v).ljust(w) for v, w in zip(r, widths)).rstrip()
                                for r in [self.header, *self.rows]]
        return "\n".join(lines)

    def _repr_html_(self):
        import html
        head = "".join(f"<th>{html.escape(str(h))}</th>" for h in self.header)
        body = "".join("<tr>" + "".join(f"<td>{html.escape(str(v))}</td>" for v in r) + "</tr>"
                       for r in self.rows)
        return (f"<div><b>{html.escape(self.title)}</b><table><thead><tr>{head}</tr></thead>"
                f"<tbody>{body}</tbody></table></div>")


def _xyz(v) -> str:
    return "(" + ", ".join(f"{round(x, 9) + 0.0:.5g}" for x in np.asarray(v, float)) + ")"


def axes_table() -> _Table:
    """The joint axes at the home pose, in the world frame (frame 0): a point on each
    and the direction of its drawn arrow (positive q_i turns by the right-hand rule)."""
    ref = _puma.reference()
    points = {name: p for link in ref.points for name, p in link}
    anchors = ["S", "S", "E", "K", "W", "W"]
    rows = []
    for i, axis in enumerate(ref.axes, start=1):
        name = anchors[i - 1]
        rows.append((f"joint {i}", f"{name} = {_xyz(points[name])}", _xyz(axis.direction)))
    return _Table("Joint axes at the home pose (world frame 0 at the shoulder, metres)",
                  ("joint", "passes through", "positive direction"), rows)


def points_table() -> _Table:
    """The points that draw each link, in the world frame at the home pose (metres)."""
    ref = _puma.reference()
    rows = []
    for k, link in enumerate(ref.points):
        for name, p in link:
            rows.append((f"{k} ({_puma.LINK_NAMES[k]})", name, _xyz(p)))
    return _Table("Link points at the home pose (world frame 0, metres): give them, in this order, "
                  "in each link's own DH frame", ("link", "point", "world (x, y, z)"), rows)


# --- figures ----------------------------------------------------------------------------------

def _new_axes(figsize=(7.5, 6.5), ncols: int = 1):
    """A course figure (a picture on a first Run All, inline or with ipympl) with 3D axes."""
    from ..views.figures import new_figure

    fig = new_figure(figsize=figsize, layout=None)       # the layout is set by hand (3D axes)
    axes = [fig.add_subplot(1, ncols, c + 1, projection="3d") for c in range(ncols)]
    return fig, axes


def _square(ax, lo=(-0.35, -0.45, -0.7), hi=(0.65, 0.25, 0.6)):
    ax.set(xlim=(lo[0], hi[0]), ylim=(lo[1], hi[1]), zlim=(lo[2], hi[2]),
           xlabel="$x_0$ [m]", ylabel="$y_0$ [m]", zlabel="$z_0$ [m]")
    ax.set_box_aspect(np.array(hi) - np.array(lo))
    ax.view_init(elev=18, azim=-65)
    from matplotlib.ticker import MaxNLocator
    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):          # a few ticks: no labels piled up
        axis.set_major_locator(MaxNLocator(4))


def _arc(axis_point, w, radius, start_dir):
    """Points of a 300° arc around direction ``w`` at ``axis_point``, turning by the right-hand rule."""
    u = start_dir - (start_dir @ w) * w
    u = u / np.linalg.norm(u)
    v = np.cross(w, u)
    t = np.radians(np.linspace(0, 300, 40))
    return axis_point + radius * (np.outer(np.cos(t), u) + np.outer(np.sin(t), v))


def _draw_links(ax, ref, links, label_points: bool, fontsize=8):
    seen = set()
    for k in links:
        P = ref.world_points(k)
        ax.plot(*P.T, "-o", color=f"C{k}", lw=4, ms=4, label=f"link {k}: {_puma.LINK_NAMES[k]}")
        for name, p in ref.points[k]:
            if label_points and name not in seen:
                seen.add(name)
                ax.text(*(p + np.array([0.006, 0.0, 0.006])), name, fontsize=fontsize, color="0.15")


def _draw_axis(ax, ref, i: int, anchor, size: float):
    """Joint i's axis: a dashed line, an arrow for its positive direction, a curled
    arrow for its positive sense of turning (right-hand rule), and its name."""
    axis = ref.axes[i - 1]
    w = axis.direction
    c = axis.point + ((anchor - axis.point) @ w) * w
    a, b = c - 0.5 * size * w, c + 0.8 * size * w
    ax.plot(*np.array([a, b]).T, "--", color="0.1", lw=1.2)
    ax.quiver(*b, *(0.25 * size * w), color="0.1", arrow_length_ratio=0.45, lw=1.5)
    arc = _arc(c + 0.6 * size * w, w, 0.14 * size, np.array([1.0, 0.35, 0.25]))
    ax.plot(*arc.T, "-", color="purple", lw=1.5)
    ax.quiver(*arc[-2], *((arc[-1] - arc[-2]) * 5), color="purple", arrow_length_ratio=1.0, lw=1.5)
    ax.text(*(b + 0.3 * size * w), f"J{i}", fontsize=11, color="purple", weight="bold")


def puma_figure():
    """The PUMA 560 at its home pose, whole (left) and its wrist (right): the links, the
    labelled points, each joint axis (dashed) with its positive direction (arrow) and
    positive sense of turning (curled arrow, right-hand rule), and the world frame 0 at
    the shoulder. No DH frames: placing them is the exercise."""
    ref = _puma.reference()
    fig, (whole, wrist) = _new_axes(figsize=(12, 6.2), ncols=2)
    points = {name: p for link in ref.points for name, p in link}
    _draw_links(whole, ref, range(ref.n + 1), label_points=True)
    for i, anchor in zip((1, 2, 3, 4), ("B", "A", "E", "K")):
        _draw_axis(whole, ref, i, points[anchor], 0.25)
    for k, color in enumerate(("tab:red", "tab:green", "tab:blue")):
        e = np.eye(3)[k]
        whole.quiver(0, 0, 0, *(0.1 * e), color=color, lw=2.5, arrow_length_ratio=0.3)
        whole.text(*(0.13 * e), f"${'xyz'[k]}_0$", color=color, fontsize=11)
    _square(whole)
    whole.set_title("home pose (q = 0), world frame 0 at the shoulder S", fontsize=10)
    _draw_links(wrist, ref, (4, 5, 6), label_points=True, fontsize=9)
    M = points["M"]
    wrist.plot(*np.array([M - [0, 0, 0.1], M]).T, "-", color="C3", lw=4)       # the forearm's top
    for i, anchor in zip((4, 5, 6), ("M", "N", "F")):
        _draw_axis(wrist, ref, i, points[anchor], 0.09)
    W = ref.wrist_centre
    _square(wrist, lo=W - np.array([0.1, 0.12, 0.13]), hi=W + np.array([0.1, 0.08, 0.15]))
    wrist.set_title("the wrist: axes 4, 5, 6 meet at W", fontsize=10)
    fig.legend(*whole.get_legend_handles_labels(), loc="lower center", ncol=7, fontsize=8, frameon=False)
    fig.suptitle("PUMA 560: joint axes J1…J6, their positive directions and senses (right-hand rule)")
    fig.subplots_adjust(left=0.0, right=0.97, bottom=0.07, top=0.92, wspace=0.05)
    return fig


# --- the student's robot: a dhlab Robot, a figure, a teach panel ------------------------------

def _rows_from(namespace):
    answers = _answers.answers_from_namespace(namespace)
    rows = _checks._rows(answers)
    missing = [f"T{i}" for i, row in enumerate(rows, start=1) if not isinstance(row, _answers.Row)]
    if missing:
        raise DHLabError(f"answer part 3 first: {', '.join(missing)} "
                         f"{'is not a transformation' if len(missing) == 1 else 'are not transformations'} "
                         "Tz(...) @ Tx(...) yet.")
    points = answers.link_points if isinstance(answers.link_points, list) else []
    return rows, points


def robot_of(namespace):
    """Your robot, from T1…T6 (or chain) in ``namespace``, as a :class:`dhlab.Robot`
    whose joint i is your q_i (limits: the PUMA's)."""
    from ..chain import Link, Move, Robot, Rot
    from ..robots import PUMA_QLIM_DEG

    rows, _ = _rows_from(namespace)
    links = []
    for i, row in enumerate(rows, start=1):
        _, sign, where = row.joint
        theta = math.radians((row.theta.const + 180) % 360 - 180)
        alpha = math.radians((row.alpha + 180) % 360 - 180)
        if where == "theta":
            first = [Rot("z", theta, joint=True, sign=sign), Move("z", row.d.const)]
            qlim = tuple(math.radians(v) for v in PUMA_QLIM_DEG[i - 1]) if i <= len(PUMA_QLIM_DEG) else None
        elif where == "d":
            first = [Rot("z", theta), Move("z", row.d.const, joint=True, sign=sign)]
            qlim = None
        else:
            raise DHLabError(f"T{i} has no joint variable: write θ{i} = q{i} + (constant).")
        links.append(Link(first + [Move("x", row.a), Rot("x", alpha)], name=f"T{i}", qlim=qlim))
    return Robot(links, name="your PUMA 560", unit="m")


def _link_lines(frames, points) -> np.ndarray:
    """Your link points placed by your frames: one polyline per link, NaN rows between."""
    chunks = []
    for k, P in enumerate(points):
        if k < len(frames) and isinstance(P, list) and P:
            P = np.array(P, float)
            chunks += [P @ frames[k][:3, :3].T + frames[k][:3, 3], np.full((1, 3), np.nan)]
    return np.vstack(chunks) if chunks else np.zeros((0, 3))


class Note:
    """A short message shown in place of a figure or a panel that cannot be made yet."""

    def __init__(self, text: str):
        self.text = text

    def __repr__(self):
        return self.text

    def _repr_html_(self):
        import html
        return f'<div style="color:#8a5300"><b>{html.escape(self.text)}</b></div>'


def my_robot_figure(namespace, q=None):
    """Your links (part 2) assembled by your transformations (part 3), over the PUMA
    in grey, at the home pose and at ``q`` (radians; default a test configuration).
    Before part 3 is answered: a :class:`Note` saying so."""
    try:
        rows, points = _rows_from(namespace)
        robot = robot_of(namespace)
        ref = _puma.reference()
        q = np.radians([30, 20, -40, 45, 60, 90]) if q is None else np.asarray(q, float)
        return _my_robot_figure(robot, points, ref, q)
    except DHLabError as e:
        return Note(str(e))
    except (ValueError, ArithmeticError, IndexError, TypeError) as e:   # an answer matplotlib cannot draw
        return Note(f"your robot cannot be drawn ({type(e).__name__}: {e}); check your answers first")


def _my_robot_figure(robot, points, ref, q):
    fig, axs = _new_axes(figsize=(11, 5.5), ncols=2)
    for ax, pose, title in zip(axs, (np.zeros(6), q), ("home pose", "q = " + _xyz(np.degrees(q)) + "°")):
        R = ref.frames(pose[None])[0]
        ghost = _link_lines(R, [ref.local_points(k).tolist() for k in range(ref.n + 1)])
        ax.plot(*ghost.T, "-", color="0.75", lw=6, label="the PUMA 560")
        F = robot.frames(pose)
        mine = _link_lines(F, points)
        if len(mine):
            ax.plot(*mine.T, "-o", color="C3", lw=2, ms=3, label="your links, assembled by your T1…T6")
        ax.plot(*F[:, :3, 3].T, ":", color="C0", lw=1, label="your frame origins")
        _square(ax)
        ax.set_title(title)
    fig.legend(*axs[0].get_legend_handles_labels(), loc="lower center", ncol=3, fontsize=9, frameon=False)
    fig.subplots_adjust(left=0.0, right=0.97, bottom=0.1, top=0.93, wspace=0.05)
    return fig


def teach(namespace, **options):
    """A teach panel (sliders in degrees) for your robot: your links assembled by your
    transformations, with your DH frames (x red, y green, z blue). Not scored.
    Before part 3 is answered: a :class:`Note` saying so."""
    from ..views.teach import teach as _teach

    try:
        _, points = _rows_from(namespace)
        robot = robot_of(namespace)
    except DHLabError as e:
        return Note(str(e))
    state = {}

    def draw_links(q):          # runs before the panel draws: only move the line
        line = state.get("line")
        if line is not None:
            line.set_data_3d(*_link_lines(robot.frames(q), points).T)

    options.setdefault("planar", False)          # the PUMA is drawn in 3D, even when your answer is planar
    try:
        panel = _teach(robot, on_change=draw_links, **options)
        state["line"], = panel.view.ax.plot([], [], [], "-", color="C3", lw=3, alpha=0.8)
        panel.view.live.add_moving(state["line"])
        panel.set_q(panel.q)
    except DHLabError as e:
        return Note(f"your robot cannot be shown in a teach panel: {e}")
    except (ValueError, ArithmeticError, IndexError, TypeError) as e:   # an answer the views cannot draw
        return Note(f"your robot cannot be shown in a teach panel ({type(e).__name__}: {e}); "
                    "check your T1…T6 with check_part3 first")
    return panel
