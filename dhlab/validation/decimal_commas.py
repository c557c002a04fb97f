"""Decimal commas: a Spanish (and European) habit Python reads as something else.

A student used to writing ``0,4`` for four tenths types it in Python too: in a tuple,
``("q1", 0,4, 0,35, 0)`` arrives as six values, ``('q1', 0, 4, 0, 35, 0)``; in quotes, ``"0,4"`` is
text. Either way the answer "has too many numbers" or "is not a number", which does not say what
went wrong. :func:`decimal_comma_note` recognises both shapes and says it: write a decimal point.
Every reader of numbers adds it to its message (:func:`~dhlab.validation.values.as_number`,
:func:`~dhlab.validation.arrays.as_sequence`, the assignment's answers): '' when the value does not
look like decimal commas, so it can always be appended.

>>> decimal_comma_note("0,4")
"'0,4' has a decimal comma: in Python write 0.4, with a decimal point (and without quotes)."
>>> print(decimal_comma_note(("q1", 0, 4, 0, 35, 0), 4)[:65])
6 values where 4 are expected: if you wrote decimal commas (0,4),
>>> decimal_comma_note((0.4, 0.35, 0), 3), decimal_comma_note("0.4"), decimal_comma_note((0.4, 0.35, 0.1, 2.5), 3)
('', '', '')
"""
from __future__ import annotations

import re

from ..i18n import _

__all__ = ["looks_like_decimal_comma", "decimal_comma_note", "with_decimal_comma_note"]

# "0,4", "-1,25", " 12,5 ": one comma between digits, nothing else (not "1,2,3", a list)
COMMA_NUMBER = re.compile(r"\s*[-+−]?\d+,\d+\s*")


def looks_like_decimal_comma(text) -> bool:
    """Whether ``text`` is a number written with a decimal comma (as text)."""
    return isinstance(text, str) and COMMA_NUMBER.fullmatch(text) is not None


def _whole(x) -> bool:
    """A whole number (what each half of a decimal comma becomes), not a bool."""
    if isinstance(x, bool):
        return False
    try:
        return float(x) == int(float(x))
    except (TypeError, ValueError, OverflowError):
        return False


def _split_by_commas(values, expected: int) -> bool:
    """Whether ``values`` (a sequence with more items than ``expected``) reads as ``expected``
    entries once some pairs of whole numbers are joined (0, 4 -> 0.4): every extra item comes
    from a comma, and each comma splits two whole numbers."""
    extra = len(values) - expected
    numbers = [v for v in values if not isinstance(v, str)]
    return 0 < extra <= expected and len(numbers) >= 2 * extra and all(_whole(v) for v in numbers)


def decimal_comma_note(value, expected: int | None = None) -> str:
    """What to tell a student whose ``value`` looks like decimal commas ('' when it does not):
    a text such as ``"0,4"``, or a sequence with more than ``expected`` items that pair up."""
    if looks_like_decimal_comma(value):
        fixed = value.strip().replace(",", ".").replace("−", "-")
        return _("{value!r} has a decimal comma: in Python write {fixed}, with a decimal point (and "
                 "without quotes).").format(value=value.strip(), fixed=fixed)
    if expected is None or isinstance(value, (str, bytes, dict)):
        return ""
    try:
        values = list(value)
    except TypeError:
        return ""
    if any(looks_like_decimal_comma(v) for v in values):
        return decimal_comma_note(next(v for v in values if looks_like_decimal_comma(v)))
    if len(values) > expected and _split_by_commas(values, expected):
        return _("{count} values where {expected} are expected: if you wrote decimal commas (0,4), write "
                 "decimal points (0.4); in Python a comma separates two values.").format(
            count=len(values), expected=expected)
    return ""


def with_decimal_comma_note(message: str, value, expected: int | None = None) -> str:
    """``message``, then :func:`decimal_comma_note` of ``value`` when it has one (and ``message``
    does not already say it): how every reader of numbers ends its complaint.

    >>> with_decimal_comma_note("x must be a number.", "0,4")[:45]
    "x must be a number. '0,4' has a decimal comma"
    >>> with_decimal_comma_note("x must be a number.", "abc")
    'x must be a number.'
    """
    note = decimal_comma_note(value, expected)
    return f"{message} {note}" if note and note not in message else message
