"""What an exercise check returns, and the exercise itself: :class:`Feedback` and :class:`Exercise`.

A check never raises on a student's answer: whatever is typed (a NaN, a string, a
dict, a matrix of the wrong shape, a sympy expression that cannot be evaluated) gets
a :class:`Feedback` that says what is wrong with it. :meth:`Exercise.check` keeps that
promise even for an answer no check foresaw.

>>> ex = Exercise("9.9", "one", lambda a: Feedback("correct", "fine") if a == 1 else
...               Feedback("wrong", "not yet", ["it is not 1"]), hints=["count"])
>>> ex.check(2)
✗ Exercise 9.9: not yet
  • it is not 1
  Stuck? Call .hint() on this exercise (1 hint).
>>> ex.hint()
💡 Hint 1 of 1 for exercise 9.9:
  • count
"""
from __future__ import annotations

import html

from ...dh_frames.reading import short_repr  # the checks' messages name an answer as dh_frames' errors do
from ...errors import DHLabError
from ...i18n import N_, _

__all__ = ["Feedback", "Exercise", "NOT_ANSWERED", "short_repr"]

NOT_ANSWERED = N_("not answered yet: replace the ... with your answer, then run the cell again.")


class Feedback:
    """The result of a check: ``status`` ('correct', 'wrong', 'unanswered' or 'hint'),
    a one-line ``title``, the ``items`` (one per problem found) and an optional ``tip``.

    ``bool(feedback)`` is True only when the answer is right. In a notebook it shows
    itself (plain text, or coloured HTML in JupyterLab).
    """

    MARKS = {"correct": "✓", "wrong": "✗", "unanswered": "…", "hint": "💡"}
    COLORS = {"correct": "#1b7f3b", "wrong": "#b00020", "unanswered": "#8a6d00", "hint": "#1f5fa8"}

    def __init__(self, status: str, title: str, items=(), tip: str = ""):
        if status not in self.MARKS:
            raise DHLabError(_("status must be one of {choices}, got {status!r}.").format(
                choices=sorted(self.MARKS), status=status))
        self.status, self.title, self.items, self.tip = status, title, list(items), tip

    @property
    def ok(self) -> bool:
        return self.status == "correct"

    def __bool__(self) -> bool:
        return self.ok

    def __str__(self) -> str:
        lines = [f"{self.MARKS[self.status]} {self.title}"]
        lines += [f"  • {item}" for item in self.items]
        if self.tip:
            lines.append(f"  {self.tip}")
        return "\n".join(lines)

    __repr__ = __str__

    def _repr_html_(self) -> str:
        color = self.COLORS[self.status]
        items = "".join(f"<li>{html.escape(i)}</li>" for i in self.items)
        return (f'<div style="border-left:4px solid {color};padding:.2em .8em;margin:.2em 0">'
                f'<b style="color:{color}">{self.MARKS[self.status]} {html.escape(self.title)}</b>'
                + (f'<ul style="margin:.2em 0">{items}</ul>' if items else "")
                + (f'<div style="color:#555">{html.escape(self.tip)}</div>' if self.tip else "")
                + "</div>")


def correct(name, note: str = "") -> Feedback:
    """A right answer; ``note`` (e.g. about the decimals typed) becomes its one item."""
    return Feedback("correct", _("correct: {name} is right.").format(name=name), [note] if note else [])


def wrong(name, items) -> Feedback:
    return Feedback("wrong", _("{name} is not right yet.").format(name=name), items)


def unanswered(name) -> Feedback:
    return Feedback("unanswered", f"{name}: {_(NOT_ANSWERED)}")


def _describe(answer) -> str:
    return short_repr(answer, 60)


class Exercise:
    """An exercise: a check (answer -> :class:`Feedback`) and hints.

    ``check(answer)`` shows the feedback; ``hint()`` shows the next hint
    (call it again for the following one), ``hint(k)`` the k-th.
    """

    def __init__(self, key: str, title: str, check, hints=()):
        self.key, self.title, self._check, self.hints = key, title, check, list(hints)
        self._next_hint = 0

    def check(self, answer) -> Feedback:
        try:
            feedback = self._check(answer)
        except Exception as exc:          # an answer no check foresaw: still feedback, never a traceback
            feedback = wrong(_("your answer"), [_(
                "it could not be compared with the right one ({error}): give numbers, sympy expressions or "
                "lists of them, as the comment in the cell shows. You gave {answer}.").format(
                    error=type(exc).__name__, answer=_describe(answer))])
        feedback.title = _("Exercise {key}: {title}").format(key=self.key, title=feedback.title)
        if feedback.status == "wrong" and self.hints:
            n = len(self.hints)
            feedback.tip = (_("Stuck? Call .hint() on this exercise ({n} hints).") if n > 1 else
                            _("Stuck? Call .hint() on this exercise ({n} hint).")).format(n=n)
        return feedback

    def hint(self, k: int | None = None) -> Feedback:
        if not self.hints:
            return Feedback("hint", _("Exercise {key} has no hints.").format(key=self.key))
        if k is None:
            k = min(self._next_hint, len(self.hints) - 1) + 1
            self._next_hint = min(self._next_hint + 1, len(self.hints))
        if isinstance(k, bool) or not isinstance(k, int) or not 1 <= k <= len(self.hints):
            raise DHLabError(_("hint number must be a whole number 1…{n}, got {k!r}: .hint() gives the next "
                               "one.").format(n=len(self.hints), k=k))
        title = (_("Hint {k} of {n} for exercise {key} (call .hint() again for the next):") if k < len(self.hints)
                 else _("Hint {k} of {n} for exercise {key}:"))
        return Feedback("hint", title.format(k=k, n=len(self.hints), key=self.key), [_(self.hints[k - 1])])

    def __repr__(self):
        return _("<Exercise {key}: {title}>").format(key=self.key, title=_(self.title))
