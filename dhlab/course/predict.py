"""Predict, then check: the student writes a prediction, a checker confirms or explains, and only
then is the worked answer shown.

A :class:`Prediction` wraps one checker. ``p.check(answer)``:

* while ``answer`` is still ``...`` (the course's placeholder) it prints a prompt and nothing
  else, so a notebook stored unanswered gives nothing away;
* a wrong answer gets the checker's specific feedback, never the answer;
* a right answer gets the worked answer as well, and so does ``p.check(answer, show_me=True)``
  (or ``p.show()``): an explicit "show me" after trying.

``p.done`` is True once the answer was right or shown; :func:`reveal` uses it to hold back a
table or a figure that would give the answer away.

The ready-made predictions of notebooks 5 and 6 are built by the functions below
(:func:`row_prediction`, :func:`case_prediction`, :func:`step_prediction`,
:func:`entry_prediction`, :func:`point_prediction`); they reuse the DH checkers of
:mod:`dhlab.course.exercises.dh_rules`, so a row in modified DH (Craig) is recognised and named.
"""
from __future__ import annotations

import math

import numpy as np
import sympy as sp

from ..dh import DHRobot, parse_entry
from ..errors import DHLabError
from ..i18n import _
from ..transforms import Rx, Rz, trans
from ..validation import as_index, as_text, describe, with_decimal_comma_note
from .checks.feedback import Feedback
from .checks.reading import Refused, is_unanswered, to_vector
from .exercises.dh_common import axis_relation, number_text, row_at_zero, vector_text, wrong_answer
from .exercises.dh_rules import check_dh_row, read_case, refutation

__all__ = ["Prediction", "row_prediction", "check_row_prediction", "case_prediction", "step_prediction",
           "entry_prediction", "point_prediction", "reveal"]

STEP_NAMES = {1: "Rz(θ)", 2: "Rz(θ)·Tr_z(d)", 3: "Rz(θ)·Tr_z(d)·Tr_x(a)", 4: "Rz(θ)·Tr_z(d)·Tr_x(a)·Rx(α)"}


class Prediction:
    """One checked prediction: ``question`` (what to predict), ``checker(answer) -> Feedback`` and
    ``worked()`` -> the worked answer, as text, shown only after a right answer or ``show_me``."""

    def __init__(self, question: str, checker, worked):
        self.question = as_text(question, "question")
        if not (callable(checker) and callable(worked)):
            raise DHLabError(_("Prediction(question, checker, worked): checker and worked must be functions."))
        self._checker, self._worked, self.done = checker, worked, False

    def check(self, answer, show_me: bool = False) -> Feedback:
        """The feedback on ``answer``; the worked answer only if it is right or ``show_me=True``."""
        if not isinstance(show_me, bool):
            raise DHLabError(_("show_me must be True or False, got {got}.").format(got=describe(show_me)))
        if is_unanswered(answer):
            if show_me:
                return self.show()
            return Feedback("unanswered", _("predict first: {question}").format(question=self.question),
                            tip=_("Replace ... by your prediction and run the cell again. "
                                  "After an honest try, check(answer, show_me=True) shows the worked answer."))
        feedback = self._checker(answer)
        if feedback.ok or show_me:
            self.done = True
            feedback.tip = _("worked answer: {answer}").format(answer=self._worked())
        return feedback

    def show(self) -> Feedback:
        """The worked answer, without a check ("show me")."""
        self.done = True
        return Feedback("hint", _("shown: {question}").format(question=self.question),
                        tip=_("worked answer: {answer}").format(answer=self._worked()))

    def __repr__(self):
        return f"Prediction({self.question!r}, {'done' if self.done else 'not yet predicted'})"


def reveal(predictions, show):
    """``show()`` once every prediction is done (right or shown); until then a prompt naming the
    ones still open. Holds back a table or a figure that would give the answers away."""
    predictions = list(predictions) if isinstance(predictions, (list, tuple)) else [predictions]
    if not predictions or not all(isinstance(p, Prediction) for p in predictions):
        raise DHLabError(_("reveal takes a Prediction or a list of them, got {got}.").format(got=describe(predictions)))
    if not callable(show):
        raise DHLabError(_("reveal(predictions, show): show must be a function, got {got}.").format(
            got=describe(show)))
    open_ = [p.question for p in predictions if not p.done]
    if open_:
        return Feedback("unanswered", _("shown once you have predicted (or asked to be shown):"), open_)
    return show()


# --- a row of a DH table ------------------------------------------------------------------------
def _robot_link(robot, i):
    if not isinstance(robot, DHRobot):
        raise DHLabError(_("robot must be a dhlab.DHRobot (standard DH), got {got}.").format(got=describe(robot)))
    return as_index(i, "i (the link)", 1, robot.n)


def _at_pose(row, robot, i, q):
    """The student's row as numbers at ``q`` (a joint variable by name takes its value there;
    revolute ones in degrees, as the table's angles), or a reason."""
    if not isinstance(row, (list, tuple)) or len(row) != 4:
        return None, with_decimal_comma_note(
            _("give the row as four entries (θ, d, a, α), got {got}.").format(got=describe(row)), row, 4)
    joints = {str(s): s for s in robot.q_symbols}
    values, variable_in = [], []
    for value, column in zip(row, "θdaα"):
        try:
            entry = parse_entry(value, f"{column}", length=column in "da") if isinstance(value, str) else value
        except DHLabError as error:
            return None, str(error)
        if isinstance(entry, sp.Basic):
            unknown = {str(s) for s in entry.free_symbols} - set(joints) - set(robot.params)
            if unknown:
                return None, _("{column}: {names} is not a name of this robot (its joint variables: {joints}; "
                               "lengths: {lengths}).").format(column=column, names=", ".join(sorted(unknown)),
                                                              joints=", ".join(joints),
                                                              lengths=", ".join(robot.params))
            if any(str(s) in joints for s in entry.free_symbols):
                variable_in.append((column, entry))
            values_of = {str(s): math.degrees(v) if link.is_revolute else v
                         for s, v, link in zip(robot.q_symbols, q, robot.links)} | dict(robot.params)
            entry = entry.subs({s: values_of[str(s)] for s in entry.free_symbols})
        values.append(entry)
    mine = str(robot.q_symbols[i - 1])
    column = "θ" if robot.links[i - 1].is_revolute else "d"
    for where, entry in variable_in:
        names = {str(s) for s in entry.free_symbols}
        if names - {mine} or where != column:
            message = (_("joint {i} is revolute: its variable {mine} belongs in {column}, and no other joint's "
                         "variable belongs in row {i}.") if column == "θ" else
                       _("joint {i} is prismatic: its variable {mine} belongs in {column}, and no other joint's "
                         "variable belongs in row {i}."))
            return None, message.format(i=i, mine=mine, column=column)
    return values, ""


def _row_text(robot, i):
    line = str(robot.table()).splitlines()[i]              # line 0 is the header
    return _("row {i} of the table is {row}").format(i=i, row="|" + line.split("|", 1)[1])


def row_prediction(robot, i, q=None) -> Prediction:
    """Predict row ``i`` (θ, d, a, α) of ``robot`` from its frames drawn at ``q`` (default q = 0):
    angles in degrees, the joint variable by name (e.g. ``"q1"``; numbers at that pose pass too).
    Checked by :func:`~dhlab.course.exercises.dh_rules.check_dh_row` on {S_(i−1)}, {S_i} at ``q``."""
    i = _robot_link(robot, i)
    q = robot.qz if q is None else q
    frames = robot.frames(q)[i - 1:i + 1]              # frames() checks q: a clear error if it is bad
    q = np.asarray(q, dtype=float).reshape(-1)

    def checker(row):
        values, problem = _at_pose(row, robot, i, q)
        if problem:
            return wrong_answer(_("your row {i}").format(i=i), [problem])
        feedback = check_dh_row(values, frames=tuple(frames))
        feedback.title = feedback.title.replace(_("your row (θ, d, a, α)"),
                                                _("your row {i} (θ, d, a, α)").format(i=i))
        return feedback

    question = _("row {i} (θ{i}, d{i}, a{i}, α{i}) of {robot}").format(i=i, robot=robot.name)
    return Prediction(question, checker, lambda: _row_text(robot, i))


def check_row_prediction(robot, i, my_row, q=None, show_me: bool = False) -> Feedback:
    """One-call form of :func:`row_prediction`: ``check_row_prediction(robot, 2, my_row)``."""
    return row_prediction(robot, i, q).check(my_row, show_me=show_me)


# --- the case of x_i ----------------------------------------------------------------------------
def case_prediction(z_prev, z_next, i: int = 1) -> Prediction:
    """Predict the case of x_i for the axes ``z_prev`` = z_(i−1) and ``z_next`` = z_i, each a pair
    (point, direction): 'intersect' (case 1), 'parallel' (case 2) or 'skew' (case 3)."""
    for name, axis in (("z_prev", z_prev), ("z_next", z_next)):
        if not isinstance(axis, (list, tuple)) or len(axis) != 2:
            raise DHLabError(_("{name} must be a pair (point, direction) of a joint axis, got {got}.").format(
                name=name, got=describe(axis)))
    rel = axis_relation(*z_prev, *z_next)
    truth = "intersect" if rel.kind in ("intersect", "coincident") else rel.kind
    number = {"intersect": 1, "parallel": 2, "skew": 3}[truth]
    i = as_index(i, "i", 1, 99)

    def checker(answer):
        said, problem = read_case(answer)
        name = _("your case of x{i}").format(i=i)
        if problem:
            return wrong_answer(name, [problem])
        if said == truth or (said == "coincident" and rel.kind == "coincident"):
            return Feedback("correct", _("correct: {name} is right.").format(name=name))
        return wrong_answer(name, [refutation(said, rel)])

    def worked():
        text = {1: _("z{p} and z{i} intersect: case 1, x{i} = ±(z{p} × z{i}), through the intersection point."),
                2: _("z{p} and z{i} are parallel: case 2, x{i} on any common normal (length {length})."),
                3: _("z{p} and z{i} are skew: case 3, x{i} on the unique common normal, of length {length}.")}
        return text[number].format(p=i - 1, i=i, length=number_text(rel.distance))

    return Prediction(_("the case of x{i} (intersect, parallel or skew)").format(i=i), checker, worked)


# --- the step-through's moving frame --------------------------------------------------------------
def _moving_frame(robot, i, step):
    """The moving frame, in {S_(i−1)}, after the first ``step`` motions of row i at q = 0."""
    theta, d, a, alpha = row_at_zero(robot, i)
    motions = [Rz(math.radians(theta)), trans(0, 0, d), trans(a, 0, 0), Rx(math.radians(alpha))]
    T = np.eye(4)
    for M in motions[:step]:                 # the moving frame: each motion on the right
        T = T @ np.asarray(M, dtype=float)
    return T


def step_prediction(robot, i, step) -> Prediction:
    """Predict where the step-through of link ``i`` (at q = 0) puts the moving frame's origin after
    ``step`` motions (1–4), in the coordinates of {S_(i−1)}."""
    i = _robot_link(robot, i)
    step = as_index(step, "step", 1, 4)
    T = _moving_frame(robot, i, step)
    origin = T[:3, 3]

    def checker(answer):
        name = _("your origin after step {step}").format(step=step)
        try:
            mine = np.asarray(to_vector(answer, name, 3), dtype=float)
        except (Refused, TypeError, ValueError) as error:
            return wrong_answer(name, [str(error)])
        if np.allclose(mine, origin, atol=1e-3):
            return Feedback("correct", _("correct: {name} is right.").format(name=name))
        items = [_("{name} {mine} is not where the first {step} motion(s) of row {i} lead (in {{S_{p}}}: θ and d "
                   "move along and about z{p}, a along the turned x).").format(
                       name=name, mine=vector_text(mine), step=step, i=i, p=i - 1)]
        if step >= 3 and np.allclose(mine, _moving_frame(robot, i, 2)[:3, 3], atol=1e-3):
            items.append(_("that is the origin after step 2: step 3 moves it by a along the turned x axis."))
        return wrong_answer(name, items)

    def worked():
        return _("after {motions} the origin is at {origin} and the x axis along {x} (in {{S_{p}}}).").format(
            motions=STEP_NAMES[step], origin=vector_text(origin), x=vector_text(T[:3, 0]), p=i - 1)

    question = _("the origin of the moving frame after step {step} of row {i}, in {{S_{p}}}").format(
        step=step, i=i, p=i - 1)
    return Prediction(question, checker, worked)


# --- an entry of a link matrix --------------------------------------------------------------------
def entry_prediction(robot, i, row, col) -> Prediction:
    """Predict entry (``row``, ``col``) (0-based) of the link matrix {}^(i−1)A_i of ``robot`` as a
    sympy expression in the robot's symbols (e.g. ``sp.cos(q1)``) or a number."""
    i = _robot_link(robot, i)
    row, col = as_index(row, "row", 0, 3), as_index(col, "col", 0, 3)
    truth = sp.simplify(robot.link_matrices_sym()[i - 1][row, col])
    names = {str(s): s for s in truth.free_symbols} | {str(s): s for s in robot.q_symbols}
    where = _("entry ({row}, {col}) of {p}A{i}").format(row=row, col=col, p=i - 1, i=i)

    def checker(answer):
        name = _("your entry ({row}, {col}) of {p}A{i}").format(row=row, col=col, p=i - 1, i=i)
        try:
            mine = sp.sympify(answer, locals=names) if isinstance(answer, str) else sp.sympify(answer)
            mine = mine.subs({s: names[str(s)] for s in mine.free_symbols if str(s) in names})
            same = sp.simplify(sp.expand_trig(mine - truth)) == 0
        except (sp.SympifyError, SyntaxError, TypeError, ValueError, AttributeError):
            return wrong_answer(name, [_("cannot read {got} as an expression such as sp.cos(q1) or 0.").format(
                got=describe(answer))])
        if same:
            return Feedback("correct", _("correct: {name} is right.").format(name=name))
        return wrong_answer(name, [_("compare with the closed form of rule 14, with this row's θ, d, a, α "
                                     "put in (cos and sin of a constant angle are numbers).")])

    return Prediction(where, checker, lambda: f"{where} = {sp.sstr(truth)}.")


# --- a point --------------------------------------------------------------------------------------
def point_prediction(question: str, expected, why: str, tol: float = 1e-3) -> Prediction:
    """Predict a point (x, y, z): right within ``tol``; ``why`` explains it in the worked answer."""
    try:
        expected = np.asarray(to_vector(expected, "expected", 3), dtype=float)
    except Refused as error:
        raise DHLabError(str(error)) from None
    if not np.all(np.isfinite(expected)):
        raise DHLabError(_("expected must be 3 finite numbers, got {got}.").format(got=describe(expected)))
    why = as_text(why, "why")
    if not (isinstance(tol, (int, float)) and math.isfinite(tol) and tol > 0):
        raise DHLabError(_("tol must be a positive number, got {got}.").format(got=describe(tol)))

    def checker(answer):
        name = _("your point")
        try:
            mine = np.asarray(to_vector(answer, name, 3), dtype=float)
        except (Refused, TypeError, ValueError) as error:
            return wrong_answer(name, [str(error)])
        if np.allclose(mine, expected, atol=tol):
            return Feedback("correct", _("correct: {name} is right.").format(name=name))
        off = [c for c, m, e in zip("xyz", mine, expected) if abs(m - e) > tol]
        return wrong_answer(name, [_("your point {mine} is off in {axes}.").format(mine=vector_text(mine),
                                                                                  axes=", ".join(off))])

    return Prediction(question, checker, lambda: f"{vector_text(expected)}: {why}")
