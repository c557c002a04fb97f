"""sympy on demand: is a value a sympy object? answered without importing sympy.

sympy takes longer to import than all of numpy and dhlab's maths together, and most
work (a numeric pose, a slider) never needs it. A value can only be a sympy object if
sympy has already been imported (its class comes from there), so these checks look in
``sys.modules`` and answer False while sympy is not loaded; the modules that *make*
sympy objects (``sp.Matrix``, ``sp.pi``) import sympy inside the function that makes them.

>>> is_sympy(0.5), is_matrix([[1, 0], [0, 1]])
(False, False)
>>> import sympy as sp
>>> is_sympy(sp.pi), is_expr(sp.pi), has_symbols(sp.Symbol("q") + 1), is_matrix(sp.eye(2))
(True, True, True, True)
"""
from __future__ import annotations

import sys

__all__ = ["loaded", "is_sympy", "is_expr", "is_matrix", "is_symbol", "has_symbols"]


def loaded():
    """The sympy module if it has been imported, else None."""
    return sys.modules.get("sympy")


def is_sympy(x) -> bool:
    """True when ``x`` is a sympy object (a number, an expression, a matrix, ...)."""
    sp = loaded()
    return sp is not None and isinstance(x, sp.Basic)


def is_expr(x) -> bool:
    """True when ``x`` is a sympy expression (a number, a symbol, a formula)."""
    sp = loaded()
    return sp is not None and isinstance(x, sp.Expr)


def is_matrix(x) -> bool:
    """True when ``x`` is a sympy matrix."""
    sp = loaded()
    return sp is not None and isinstance(x, sp.MatrixBase)


def is_symbol(x) -> bool:
    """True when ``x`` is a sympy symbol."""
    sp = loaded()
    return sp is not None and isinstance(x, sp.Symbol)


def has_symbols(x) -> bool:
    """True when ``x`` is a sympy object with free symbols (``q1 + 1``, not ``pi/2``)."""
    return is_sympy(x) and bool(x.free_symbols)
