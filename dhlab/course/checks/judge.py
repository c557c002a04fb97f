"""The ladder every check climbs before it diagnoses: right as typed, right to the decimals typed, a known mistake.

:func:`~dhlab.course.checks.matrix.check_matrix`, :func:`~dhlab.course.checks.values.check_value` and
:func:`~dhlab.course.checks.values.check_solutions` compare in their own way (a matrix sampled at random
symbols, a vector, solutions in any order); what they then say is the same, and said here once.

>>> judge("p", lambda slack: slack > 0, decimals=2)
✓ correct: p is right.
  • right to the 2 decimals you typed. Keep 3 or more when a result is used again:
    rounding errors grow when matrices are multiplied.
>>> judge("p", lambda slack: False, decimals=3, mistakes=[(lambda slack: True, "that is the fixed-frame order.")])
✗ p is not right yet.
  • that is the fixed-frame order.
>>> judge("p", lambda slack: False, decimals=3) is None      # none of the rungs: the check diagnoses
True
"""
from __future__ import annotations

from ...i18n import _
from .feedback import Feedback, correct, wrong
from .reading import rounding_slack

__all__ = ["judge", "rounding_note"]


def judge(name, matches, decimals, mistakes=()) -> Feedback | None:
    """The verdict of the first rungs, or None when the answer is none of them (then the check diagnoses).
    Test the result with ``is None``: a :class:`Feedback` that says "wrong" is falsy.

    ``matches(slack)``: is the answer the right one, within the check's tolerance plus ``slack``? It is asked
    with 0 (as typed), then with the rounding of the ``decimals`` typed. ``mistakes``: ``(matches, message)``
    pairs for the known wrong answers, asked with that rounding; the first that matches gives its message.
    """
    if matches(0.0):
        return correct(name)
    slack = rounding_slack(decimals)
    if matches(slack):
        note = rounding_note(decimals)
        return correct(name, note) if decimals >= 2 else wrong(name, [note])
    for is_this_mistake, message in mistakes:
        if is_this_mistake(slack):
            return wrong(name, [message])
    return None


def rounding_note(decimals) -> str:
    """What to say about an answer right only to the decimals typed (2 or more: accepted)."""
    if decimals >= 2:
        return _("right to the {decimals} decimals you typed. Keep 3 or more when a result is used again: "
                 "rounding errors grow when matrices are multiplied.").format(decimals=decimals)
    return (_("right to the {decimals} decimal you typed, but that is too coarse to tell a right answer from a "
              "near miss: give 3 decimals.") if decimals == 1 else
            _("right to the {decimals} decimals you typed, but that is too coarse to tell a right answer from a "
              "near miss: give 3 decimals.")).format(decimals=decimals)
