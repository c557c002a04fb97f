"""The one error dhlab raises for bad input: :class:`DHLabError`.

It lives on the ground floor, below every other module, so that the language module
(:mod:`dhlab.i18n`), the checks (:mod:`dhlab.validation`) and the maths can all raise it
without importing each other. Students meet it as ``dhlab.DHLabError`` (or
``dhlab.validation.DHLabError``, its older home, which still works).

>>> raise DHLabError("d = 'x' is not a number: pass a plain number such as 0.5.")
Traceback (most recent call last):
...
dhlab.validation.DHLabError: d = 'x' is not a number: pass a plain number such as 0.5.
"""
from __future__ import annotations

__all__ = ["DHLabError"]


class DHLabError(ValueError):
    """Bad input to dhlab: the message says what was wrong and how to fix it."""


# Tracebacks say ``dhlab.validation.DHLabError``, as they always have: the notebooks' saved
# outputs and the doctests show that name, and ``dhlab.validation`` still exports the class.
DHLabError.__module__ = "dhlab.validation"
