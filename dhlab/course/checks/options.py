"""The checks of what a *teacher* gives a check: the right answer, the tolerance, the names and units
of the components, the accepted words, the test cases of a function.

A student's answer is never refused with an error (a check turns it into feedback, see
:mod:`~dhlab.course.checks.reading`). What the notebook's author passes is checked here, where it enters
:func:`~dhlab.course.exercises.check_matrix` and the other checks, so that a slip in a notebook cell
(a tolerance of ``'1e-3'``, three component names for two numbers, a NaN in the right answer) is a
clear :class:`~dhlab.validation.DHLabError`, never a traceback from numpy nor a check that passes
anything.

>>> names(("x", "y"), 2, "components")
['x', 'y']
>>> names("xyz", 2, "components")
Traceback (most recent call last):
...
dhlab.validation.DHLabError: components must name the 2 components (e.g. ('x', 'y')), got 'xyz'.
"""
from __future__ import annotations

import numpy as np
import sympy as sp

from ...errors import DHLabError
from ...i18n import N_, _
from ...validation import as_sequence, as_text, as_tolerance, describe
from .reading import Refused, to_sympy_matrix, to_vector

__all__ = ["tolerance", "names", "units", "expected_matrix", "expected_vector", "expected_solutions",
           "symbol_names", "accepted_answers", "explanations", "glossary", "cases", "function", "mistakes", "name"]


def tolerance(tol) -> float:
    """The tolerance of a comparison: a small number > 0, at most 0.5."""
    return as_tolerance(tol, "tol", upper=0.5)


def names(value, n: int, what: str) -> list:
    """``n`` names (of components): a list of n texts, or one text of n letters ("xyz");
    one text names a single component."""
    if isinstance(value, str) and (len(value) == n or n == 1):
        return [value] if n == 1 else list(value)
    items = None if isinstance(value, str) else as_sequence(value, what, _("{n} names, e.g. ('x', 'y')").format(n=n))
    if items is None or len(items) != n or not all(isinstance(v, str) for v in items):
        message = (_("{what} must name the {n} component (e.g. ('q1',)), got {value}.") if n == 1 else
                   _("{what} must name the {n} components (e.g. ('x', 'y')), got {value}."))
        raise DHLabError(message.format(what=what, n=n, value=describe(value)))
    return list(items)


def units(unit, n: int) -> list:
    """One unit for all ``n`` components (a text such as 'm', 'rad', '°'), or one per component."""
    if isinstance(unit, str):
        return [unit] * n
    items = as_sequence(unit, "unit", _("a text such as 'rad', or one per component ({n})").format(n=n))
    if len(items) != n or not all(isinstance(u, str) for u in items):
        raise DHLabError(_("unit must give one unit per component ({n}), as text, got {value}.").format(
            n=n, value=describe(unit)))
    return list(items)


def expected_matrix(value, what: str = "") -> sp.Matrix:
    """The right matrix of a check (numbers or symbols, every entry finite)."""
    what = what or _("the expected matrix")
    try:
        return to_sympy_matrix(value, what)
    except Refused as why:
        text = str(why)
        raise DHLabError(text if text.startswith(what) else f"{what}: {text}") from None


def expected_vector(value, what: str = "") -> list:
    """The right number or numbers of a check: a list of sympy numbers or expressions (finite, real)."""
    what = what or _("the expected value")
    if isinstance(value, (bytes, bytearray, memoryview, str)) or value is np.ma.masked or (
            isinstance(value, np.ma.MaskedArray) and np.ma.is_masked(value)):
        raise DHLabError(_("{what} must be a number or a list of numbers, got {value}.").format(
            what=what, value=describe(value)))
    items = [value] if np.ndim(np.array(value, dtype=object)) == 0 and not isinstance(value, sp.MatrixBase) \
        else None
    if items is None:
        try:
            flat = np.ravel(np.array(value, dtype=object))
        except (ValueError, TypeError):      # ragged beyond what numpy can hold
            raise DHLabError(_("{what} must be a number or a flat list of numbers, got {value}.").format(
                what=what, value=describe(value))) from None
        items = list(flat)
    if not items:
        raise DHLabError(_("{what} is empty: give the right number(s).").format(what=what))
    try:
        values = to_vector(items, what, len(items))
    except Refused as why:
        raise DHLabError(f"{what}: {why}") from None
    return [sp.sympify(v) for v in values]


def expected_solutions(value) -> list:
    """The right solutions of :func:`~dhlab.course.checks.values.check_solutions`: a list of vectors
    of one length, every entry a finite number."""
    items = as_sequence(value, "expected", _("a list of solutions, each a list of numbers"))
    if not items:
        return []
    if not all(isinstance(s, (list, tuple, np.ndarray, sp.MatrixBase)) and np.ndim(s) == 1 for s in items):
        raise DHLabError(_("expected must be a list of solutions, each a list of numbers, e.g. [[0.4, 0.64]], "
                           "got {value}.").format(value=describe(value)))
    try:
        rows = [np.ravel(np.array(to_vector(s, _("expected solution {k}").format(k=k + 1),
                                            np.size(np.array(s, dtype=object))), dtype=float))
                for k, s in enumerate(items)]
    except (Refused, TypeError, ValueError) as why:
        raise DHLabError(_("expected must be a list of solutions of numbers: {why}").format(why=why)) from None
    if len({len(r) for r in rows}) != 1 or not len(rows[0]):
        raise DHLabError(_("expected: every solution must have the same number of components, got {value}.").format(
            value=describe(value)))
    return rows


def symbol_names(symbols) -> list:
    """Extra symbols a student may use: sympy symbols or their names."""
    items = as_sequence(symbols, "symbols", _("a list of sympy symbols or names, e.g. ('l1', 'l2')"))
    for s in items:
        if not isinstance(s, (str, sp.Symbol)):
            raise DHLabError(_("symbols must be sympy symbols or names such as 'l1', got {value}.").format(
                value=describe(s)))
    return items


def accepted_answers(accepted) -> list:
    """Other answers that pass: a list (one text alone is one answer, not its letters)."""
    if isinstance(accepted, str):
        return [accepted]
    return as_sequence(accepted, "accepted", _("a list of answers that also pass, e.g. ('azul',)"))


def explanations(value) -> dict:
    """Wrong answers and what is wrong with each: a dict {answer: text}, or None."""
    if value is None:
        return {}
    if not isinstance(value, dict) or not all(isinstance(v, str) for v in value.values()):
        raise DHLabError(_("explanations must be a dict {{wrong answer: why, …}} of texts, got {value}.").format(
            value=describe(value)))
    return value


def glossary(expected) -> dict:
    """check_terms' ``expected``: {term: answer, or a tuple of accepted answers}, all text."""
    if not isinstance(expected, dict) or not expected:
        raise DHLabError(_("expected must be a dict {{term: answer}} with at least one term, got {value}.").format(
            value=describe(expected)))
    for term, answer in expected.items():
        answers = answer if isinstance(answer, (tuple, list, set, frozenset)) else (answer,)
        if not isinstance(term, str) or not answers or not all(isinstance(a, str) for a in answers):
            raise DHLabError(_("expected: term {term} must be text with a text answer (or a tuple of them), got "
                               "{answer}.").format(term=describe(term), answer=describe(answer)))
    return expected


def cases(value) -> list:
    """The test cases of check_function: a non-empty list of argument tuples."""
    items = as_sequence(value, "cases", _("a list of argument tuples, e.g. [(0.1, 0.5), (1.0, 0.0)]"))
    if not items or not all(isinstance(c, (tuple, list)) for c in items):
        raise DHLabError(_("cases must be a non-empty list of argument tuples, e.g. [(0.1, 0.5)], got {value}.").format(
            value=describe(value)))
    return [tuple(c) for c in items]


def function(value, what: str):
    """A function the check calls (the reference, or the check applied to each result)."""
    if not callable(value):
        raise DHLabError(_("{what} must be a function, got {value}.").format(what=what, value=describe(value)))
    return value


def mistakes(value) -> list:
    """Known wrong answers and their messages: a list of (wrong answer, text) pairs."""
    items = as_sequence(value, "mistakes", _("a list of (wrong answer, message) pairs"))
    for item in items:
        if not isinstance(item, (tuple, list)) or len(item) != 2 or not isinstance(item[1], str):
            raise DHLabError(_("mistakes must be (wrong answer, message) pairs, got {value}.").format(
                value=describe(item)))
    return items


# the names the checks give an answer by default (and a notebook's own): translated, like every name the
# catalog has (see :func:`name`)
DEFAULT_NAMES = (N_("your answer"), N_("your value"), N_("your matrix"), N_("your solutions"),
                 N_("your glossary"), N_("your function"), N_("your angle"))


def name(value) -> str:
    """How the feedback calls the answer ('your matrix', 'q2'), in the language of the messages when the
    catalog has it (the English name of a notebook cell then reads right in either edition)."""
    return _(as_text(value, "name"))
