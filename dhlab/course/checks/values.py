"""Checking numbers and vectors: :func:`check_value` (a number, a position, joint values) and
:func:`check_solutions` (several solutions in any order, e.g. inverse kinematics).

Each wrong component is named and explained: degrees given where radians are asked
(or the other way), a sign, the right numbers in the wrong order, an angle a full
turn away. Rounding is never blamed: an answer right to the decimals typed passes.

>>> check_value([0.87, 0.5, 0], [math.sqrt(3) / 2, 0.5, 0], name="p", components="xyz")
✓ correct: p is right.
  • right to the 2 decimals you typed. Keep 3 or more when a result is used again:
    rounding errors grow when matrices are multiplied.
>>> check_value([0.866, 0.5, 0, 1], [math.sqrt(3) / 2, 0.5, 0], name="p")
✗ p is not right yet.
  • your answer has 4 numbers; a position has 3: drop the trailing 1 of the homogeneous form.
"""
from __future__ import annotations

import itertools
import math

import numpy as np
import sympy as sp

from ...i18n import _
from . import options as teacher
from .feedback import Feedback, correct, unanswered, wrong
from .judge import judge
from .matrix import check_matrix, num
from .reading import Refused, close, is_unanswered, rounding_slack, to_vector, typed_decimals

__all__ = ["check_value", "check_solutions"]


def _with_unit(value, unit):
    if unit == "°":
        return f"{num(value)}°"
    return num(value) + (f" {unit}" if unit else "")


def check_value(student, expected, *, name: str = "your value", components=None, unit="",
                tol: float = 1e-3, mistakes=()) -> Feedback:
    """Compare a number, or a vector of numbers, with ``expected``.

    ``components``: names of the vector's entries, e.g. ``("x", "y", "z")``.
    ``unit``: one unit for all, or one per component. 'rad' and '°' turn on the
    degrees-vs-radians diagnosis. ``tol``: relative-and-absolute tolerance (answers
    typed with 3–4 decimals pass; fewer decimals pass when right to the decimals typed).
    ``mistakes``: ``(wrong_value, message)`` pairs.
    ``expected`` may be symbolic (sympy expressions): then the answer must be too.

    >>> check_value(math.degrees(0.5), 0.5, name="q2", unit="rad")
    ✗ q2 is not right yet.
      • you gave 28.6479, which is the angle in degrees: the API takes radians.
        Write deg2rad(28.6479) (or 28.6479·π/180).
    """
    name, tol, mistakes = teacher.name(name), teacher.tolerance(tol), teacher.mistakes(mistakes)
    exp_exprs = teacher.expected_vector(expected)
    scalar = np.ndim(np.array(expected, dtype=object)) == 0 and not isinstance(expected, sp.MatrixBase)
    n = len(exp_exprs)
    components = teacher.names(components, n, "components") if components is not None else (
        [name] if scalar else [_("component {k}").format(k=k + 1) for k in range(n)])
    units = teacher.units(unit, n)
    if is_unanswered(student):
        return unanswered(name)
    try:
        got = to_vector(student, name, n)
    except Refused as refusal:
        return wrong(name, [str(refusal)])
    if any(e.free_symbols for e in exp_exprs) or isinstance(got, list):
        feedback = check_matrix(sp.Matrix([got if isinstance(got, list) else list(got)]),
                                sp.Matrix([exp_exprs]), name=name, tol=tol, mistakes=[
                                    (sp.Matrix([list(np.ravel(np.array(w, dtype=object)))]), _(m))
                                    for w, m in mistakes], index_style="math")
        if feedback.status == "wrong":
            feedback.items = [_component_names(i, components) for i in feedback.items]
        return feedback
    exp = np.array([float(sp.N(e)) for e in exp_exprs])
    decimals = typed_decimals(student)
    verdict = judge(name, lambda slack: close(got, exp, tol, slack), decimals, [
        (lambda slack, w=w: _is_this(got, w, tol, slack), _(message)) for w, message in mistakes])
    if verdict is not None:
        return verdict
    return wrong(name, _vector_diagnosis(got, exp, components, units, tol, scalar, decimals))


def _is_this(got, mistake, tol, slack) -> bool:
    """Is the answer ``got`` the teacher's known mistake (a number or a vector)?"""
    w = np.array([float(v) for v in teacher.expected_vector(mistake, _("a known mistake"))])
    return w.shape == got.shape and close(got, w, tol, slack)


def _component_names(item: str, components) -> str:
    """check_matrix speaks of 'row 1, column k': for a vector, name the component."""
    for k, comp in enumerate(components):
        prefix = _("row {i}, column {j}").format(i=1, j=k + 1) + ": "
        if item.startswith(prefix):
            return f"{comp}: " + item[len(prefix):]
    return item


def _vector_diagnosis(got, exp, components, units, tol, scalar, decimals=None) -> list:
    n = len(exp)
    slack = rounding_slack(decimals)
    if n > 1:
        if close(got, -exp, tol, slack) and not close(exp, np.zeros(n), 1e-12):
            return [_("every component has the wrong sign.")]
        if n <= 6:
            for perm in itertools.permutations(range(n)):
                if list(perm) != list(range(n)) and close(got[list(perm)], exp, tol, slack):
                    return [_("the right numbers, in the wrong order: the order is ({order}).").format(
                        order=", ".join(components))]
    items = []
    for k in range(n):
        if close(got[k], exp[k], tol, slack):
            continue
        label = "" if scalar else f"{components[k]}: "
        items.append(label + _number_problem(got[k], exp[k], units[k], tol, decimals))
    return items


def _number_problem(g, e, unit, tol, decimals=None) -> str:
    nonzero = not math.isclose(e, 0, abs_tol=1e-12)
    if unit == "rad" and nonzero and math.isclose(g, math.degrees(e), rel_tol=tol, abs_tol=tol):
        return _("you gave {g}, which is the angle in degrees: the API takes radians. Write deg2rad({g}) "
                 "(or {g}·π/180).").format(g=num(g))
    if unit == "°" and nonzero and math.isclose(g, math.radians(e), rel_tol=tol, abs_tol=tol):
        return _("you gave {g}, which is the angle in radians: here it is asked in degrees.").format(g=num(g))
    if unit in ("rad", "°"):
        turn = 2 * math.pi if unit == "rad" else 360.0
        turns = (g - e) / turn
        if abs(turns) < 1e6 and math.isclose(turns, round(turns), abs_tol=tol) and round(turns):
            return _("you gave {g}: the same direction, but give it within one turn (±180°).").format(
                g=_with_unit(g, unit))
    if nonzero and math.isclose(g, -e, rel_tol=tol, abs_tol=tol + rounding_slack(decimals)):
        return _("you gave {g}: the sign is wrong.").format(g=_with_unit(g, unit))
    if decimals is not None and math.isclose(g, e, abs_tol=3 * rounding_slack(decimals)):
        return (_("you gave {g}: close, but not right to the {decimals} decimal you typed; check the last digit "
                  "(round to the nearest, do not just cut the digits off).") if decimals == 1 else
                _("you gave {g}: close, but not right to the {decimals} decimals you typed; check the last digit "
                  "(round to the nearest, do not just cut the digits off).")).format(
                      g=_with_unit(g, unit), decimals=decimals)
    return _("you gave {g}, which is not right.").format(g=_with_unit(g, unit))


def check_solutions(student, expected, *, name: str = "your solutions", components=None, unit="",
                    tol: float = 1e-3, mistakes=()) -> Feedback:
    """Compare a list of solutions (vectors), in any order, with ``expected``.

    Angles (components whose unit is 'rad' or '°') are compared modulo a full turn.
    ``mistakes``: ``(wrong_solution, message)`` pairs, one wrong *solution* each:
    if any of the student's solutions equals one, its message is given.

    >>> check_solutions([[0.4, 0.6435]], [[0.4, 0.6435], [1.2, 2.4981]], name="IK",
    ...                 components=("q1", "q2"), unit=("", "rad"))
    ✗ IK is not right yet.
      • there are 2 solutions; you gave 1.
      • missing: 1 more solution: every branch of the inverse kinematics gives one.
    """
    name, tol, mistakes = teacher.name(name), teacher.tolerance(tol), teacher.mistakes(mistakes)
    expected = teacher.expected_solutions(expected)
    n = len(expected[0]) if expected else 0
    components = teacher.names(components, n, "components") if components is not None else \
        [_("component {k}").format(k=k + 1) for k in range(n)]
    units = teacher.units(unit, n)
    if is_unanswered(student):
        return unanswered(name)
    if not expected:             # the point is out of reach: the right answer is the empty list
        return correct(name) if isinstance(student, (list, tuple)) and not student else wrong(
            name, [_("there is no solution (the target is out of reach): {name} must be the empty list [].").format(
                name=name)])
    read = _read_solutions(student, n, name, components)
    if isinstance(read, Feedback):
        return read
    student, sols = read
    decimals = typed_decimals(student)
    period = np.array([2 * math.pi if u == "rad" else 360.0 if u == "°" else 0.0 for u in units])
    typed_slack = rounding_slack(decimals)         # what rounding to the decimals typed may cost

    def same(a, b, slack=typed_slack):
        diff = a - b
        wrapped = np.where(period > 0, diff - period * np.round(diff / np.where(period > 0, period, 1)), diff)
        return bool(np.all((np.abs(wrapped) <= tol * (1 + np.abs(b))) | (np.abs(wrapped) <= slack + 1e-12)))

    unmatched, extra = list(range(len(expected))), []
    for s in sols:
        hit = next((k for k in unmatched if same(s, expected[k])), None)
        if hit is None:
            extra.append(s)
        else:
            unmatched.remove(hit)
    matched = not unmatched and not extra
    verdict = judge(name, lambda slack: matched and all(any(same(s, e, slack) for e in expected) for s in sols),
                    decimals)
    if verdict is not None:
        return verdict
    items = []
    if len(sols) != len(expected):
        items.append((_("there is {n} solution; you gave {k}.") if len(expected) == 1 else
                      _("there are {n} solutions; you gave {k}.")).format(n=len(expected), k=len(sols)))
    items += [_extra_problem(s, expected, unmatched, mistakes, same, components, units, tol, decimals) for s in extra]
    if len(sols) < len(expected):
        k = len(expected) - len(sols)
        message = (_("missing: {k} more solutions: every branch of the inverse kinematics gives one.") if k > 1
                   else _("missing: {k} more solution: every branch of the inverse kinematics gives one."))
        items.append(message.format(k=k))
    return wrong(name, items)


def _read_solutions(student, n, name, components):
    """(the answer as a list, its solutions as arrays of ``n`` numbers each), or the :class:`Feedback` saying why
    they cannot be read."""
    if isinstance(student, (str, dict, set)) or not hasattr(student, "__iter__") or (
            isinstance(student, np.ndarray) and student.ndim == 0):
        return wrong(name, [_("{name} must be a list of solutions, each ({components}).").format(
            name=name, components=", ".join(components))])
    student = list(student)
    if len(student) == n and not any(hasattr(s, "__iter__") and not isinstance(s, str) for s in student):
        return wrong(name, [_("{name} must be a list of solutions, [[{components}], …]: you gave one list of "
                              "numbers; put each solution in its own brackets.").format(
                                  name=name, components=", ".join(components))])
    try:
        return student, [np.asarray(to_vector(s, _("solution {k}").format(k=k + 1), n), dtype=float)
                         for k, s in enumerate(student)]
    except (Refused, TypeError, ValueError) as refusal:
        return wrong(name, [str(refusal) if isinstance(refusal, Refused) else
                            _("{name}: each solution must be numbers ({components}), not symbols.").format(
                                name=name, components=", ".join(components))])


def _extra_problem(s, expected, unmatched, mistakes, same, components, units, tol, decimals) -> str:
    """What is wrong with ``s``, a solution the student gave that matches no remaining right one."""
    message = next((m for w, m in mistakes
                    if same(s, np.array([float(v) for v in teacher.expected_vector(w, _("a known mistake"))]))),
                   None)
    if message:
        return _(message)
    if any(same(s, e) for e in expected):
        return _("{solution} is given twice.").format(solution=_solution_text(s, components, units))
    text = _("{solution} is not a solution").format(solution=_solution_text(s, components, units))
    if unmatched:
        closest = min(unmatched, key=lambda k: np.abs(s - expected[k]).sum())
        details = _vector_diagnosis(s, expected[closest], components, units, tol, False, decimals)
        if details:
            text += ": " + "; ".join(d.rstrip(".") for d in details)
    return text + "."


def _solution_text(s, components, units):
    return (f"({', '.join(components)}) = ("
            + ", ".join(_with_unit(v, u) for v, u in zip(s, units)) + ")")
