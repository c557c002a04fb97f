"""Symbolic kinematics the way the slides print it: C1 = cos q1, S23 = sin(q2 + q3).

Two ideas make the symbolic product both fast and compact:

1. **Exact constants.** A twist of 90° typed as ``deg2rad(90)`` is the float
   1.5707963...; sympy would print ``6.1e-17`` for its cosine. :func:`exact`
   turns such floats back into ``pi/2`` (and lengths like 2.5 into 5/2).
2. **No trigonometric simplification at all.** Joints whose axes are parallel
   (DH α = 0) are merged *before* multiplying: their product is written
   directly with the sums of angles (see ``DHRobot``). Every remaining cos/sin
   is then a plain symbol, each appears in one factor only, so the product is
   a polynomial that needs no simplifying, only a choice of the shortest
   layout (nested as multiplied, or expanded) per entry. Element-wise
   ``sympy.simplify`` searches for what this construction knows in advance.

>>> import sympy as sp
>>> q1, q2 = sp.symbols("q1 q2")
>>> compact(sp.Matrix([[sp.cos(q1 + q2), sp.sin(q1)]]), (q1, q2))
Matrix([[C12, S1]])
"""
from __future__ import annotations

import math
import time
import warnings
from fractions import Fraction

import numpy as np
import sympy as sp
from sympy.simplify.fu import TR10i
from sympy.utilities.exceptions import SymPyDeprecationWarning

from .errors import DHLabError
from .i18n import _
from .validation import as_angle, as_length, as_number, describe

__all__ = ["exact", "exact_angle", "exact_length", "chain_product", "simplify_chain", "compact", "legend",
           "check_finite_entries", "count_ops", "tree_size"]

GREEK = {"theta": "θ", "alpha": "α", "phi": "φ", "psi": "ψ", "beta": "β", "gamma": "γ"}
_NICE = [(sp.Integer(0), 0.0), (sp.Integer(1), 1.0), (sp.Rational(1, 2), 0.5),
         (sp.sqrt(2) / 2, math.sqrt(2) / 2), (sp.sqrt(3) / 2, math.sqrt(3) / 2)]


def exact_angle(value):
    """A radian value as an exact multiple of π when it is a whole number of degrees."""
    value = as_angle(value, "the angle (radians)", symbolic=True, turns=100)
    if isinstance(value, sp.Basic):
        return value
    degrees = math.degrees(float(value))
    if abs(degrees - round(degrees)) < 1e-9:
        return sp.Rational(round(degrees), 180) * sp.pi
    return sp.Float(float(value))


def exact_length(value):
    """A number as a small fraction when it is one (2.5 -> 5/2), else a float."""
    value = as_length(value, "the length", symbolic=True)
    if isinstance(value, sp.Basic):
        return value
    frac = Fraction(float(value)).limit_denominator(100)
    if abs(float(frac) - float(value)) < 1e-12:
        return sp.Rational(frac.numerator, frac.denominator)
    return sp.Float(float(value))


def _snap(x: sp.Float):
    """A matrix entry like 6.1e-17 or 0.7071067811865476 -> 0 or sqrt(2)/2."""
    v = float(x)
    for exact_value, approx in _NICE:
        if abs(abs(v) - approx) < 1e-12:
            return exact_value if v >= 0 else -exact_value
    return exact_length(v)


def exact(M):
    """``M`` (a sympy Matrix or expression) with near-exact floats made exact."""
    def fix(e):
        e = sp.sympify(e)
        floats = e.atoms(sp.Float)
        return e.xreplace({f: _snap(f) for f in floats}) if floats else e
    return M.applyfunc(fix) if isinstance(M, sp.MatrixBase) else fix(M)


def count_ops(M) -> int:
    """Operation count of a matrix or expression (sympy.count_ops summed over entries)."""
    if isinstance(M, sp.MatrixBase):
        return sum(sp.count_ops(e) for e in M)
    return sp.count_ops(M)


def _joint_trig(expr, q_symbols) -> set:
    qs = set(q_symbols)
    return {f for f in expr.atoms(sp.cos, sp.sin) if f.free_symbols & qs}


def chain_product(matrices, deadline=None):
    """The product of sympy matrices, in order, as multiplied (entries not expanded).

    Written entry by entry, ``Σ_k T[i,k]·A[k,j]`` skipping the zeros: sympy
    expressions share their common parts, so a 12-joint chain takes a fraction of
    a second (``sympy.Matrix.__mul__`` checks and simplifies every dot product,
    which costs minutes on long chains). ``deadline``: see :func:`simplify_chain`.
    """
    T = matrices[0]
    for A in matrices[1:]:
        _check_time(deadline)
        # (B023) sympy calls the lambda at once, with this turn's T and A: no late binding to fear
        T = sp.Matrix(T.rows, A.cols, lambda i, j: sp.Add(
            *[T[i, k] * A[k, j] for k in range(T.cols) if T[i, k] != 0 and A[k, j] != 0]))  # noqa: B023
    return T


def _deadline(timeout):
    """The ``time.monotonic()`` instant at which work with this timeout (seconds) must stop."""
    return None if timeout is None else time.monotonic() + timeout


def _check_time(deadline):
    if deadline is not None and time.monotonic() > deadline:
        raise DHLabError(_(
            "fk_sym(simplify=True) stopped: it ran out of time (the timeout option, in seconds). "
            "Pass a larger timeout (or timeout=None for no limit), use simplify=False, which is fast "
            "for any chain, or work numerically with robot.fk(q)."
        ))


def tree_size(e, _memo=None) -> int:
    """How many nodes ``e`` has written out as a tree (shared parts counted each time),
    computed in time proportional to its distinct parts."""
    memo = {} if _memo is None else _memo
    key = id(e)
    if key not in memo:
        memo[key] = 1 + sum(tree_size(a, memo) for a in e.args)
    return memo[key]


EXPAND_LIMIT = 1_000   # entries larger than this (as a tree) stay as multiplied: the catalogue's largest is 86


def simplify_chain(blocks, base, tool, sum_angles: bool = False, timeout=None):
    """Compact product ``base · blocks[0] ··· blocks[-1] · tool`` (sympy matrices).

    The blocks should already carry the sums of angles of parallel joints (so
    each cos/sin of a joint angle appears in one block only); the product is
    then formed and each entry laid out in its shortest form. ``sum_angles=True``
    also collapses ``C1·C2 − S1·S2`` into ``C12`` afterwards, with sympy's targeted
    rule TR10i: for small chains not written in DH form.

    Long general chains have entries with hundreds of thousands of terms once
    expanded: an entry larger than ``EXPAND_LIMIT`` nodes stays as multiplied
    (already its shortest form). After ``timeout`` seconds (None: no limit) a
    DHLabError stops the work; the kernel's stop button always works too.
    """
    deadline = _deadline(timeout)
    T = chain_product([base] + list(blocks) + [tool], deadline)
    memo = {}
    out = []
    for e in T:
        _check_time(deadline)
        if tree_size(e, memo) <= EXPAND_LIMIT:
            e = _shortest(TR10i(sp.expand(e)) if sum_angles else e)
        out.append(e)
    return sp.Matrix(T.rows, T.cols, out)


def _shortest(e):
    """The shortest of an entry's layouts: as multiplied, expanded, or with common factors out."""
    expanded = sp.expand(e)
    return min((e, expanded, sp.factor_terms(expanded)), key=sp.count_ops)


def _index(symbol) -> str:
    """The label of a joint symbol in C/S names: q12 -> '12', theta0 -> '0', theta -> 'θ'."""
    digits = "".join(ch for ch in str(symbol) if ch.isdigit())
    return digits or GREEK.get(str(symbol), str(symbol))


def _compact_name(f, q_symbols):
    """cos(q2 + q3) -> 'C23'; None when the argument is not a plain sum of joints."""
    arg = f.args[0]
    terms = sp.Add.make_args(arg)
    if not all(t in q_symbols for t in terms):
        return None
    order = sorted(terms, key=q_symbols.index)
    labels = [_index(t) for t in order]
    joiner = "," if any(len(l) > 1 for l in labels) else ""
    return ("C" if isinstance(f, sp.cos) else "S") + joiner.join(labels)


def check_finite_entries(M, who: str) -> None:
    """Refuse a matrix or expression holding nan, zoo or ±oo, naming the first such entry."""
    bad = (sp.nan, sp.zoo, sp.oo, -sp.oo)
    if not M.has(*bad):
        return
    if isinstance(M, sp.MatrixBase):
        i, j = next((i, j) for i in range(M.rows) for j in range(M.cols) if M[i, j].has(*bad))
        where = f"M[{i}, {j}] = {describe(M[i, j])}"
    else:
        where = f"M = {describe(M)}"
    raise DHLabError(_("{who}: {where} is not finite: every entry of M must be a finite expression "
                       "(no nan, oo or zoo; check for a division by zero, e.g. 1/cos(q) at q = pi/2).").format(
                           who=who, where=where))


def _joint_arguments(M, q_symbols, who: str):
    """``M`` as a sympy object and the joint symbols as the symbols of ``M`` (names accepted)."""
    if isinstance(M, (str, bytes)) or isinstance(M, bool) or M is np.ma.masked or isinstance(M, np.ma.MaskedArray):
        raise DHLabError(_("{who}: M must be a sympy Matrix or expression (e.g. robot.fk_sym()), got {got}.").format(
            who=who, got=describe(M)))
    try:
        with warnings.catch_warnings():          # sympy only warns about a list inside a Matrix entry
            warnings.simplefilter("error", SymPyDeprecationWarning)
            M = sp.Matrix(M) if isinstance(M, (list, tuple)) else sp.sympify(M, strict=True)
    except (sp.SympifyError, TypeError, ValueError, SymPyDeprecationWarning):
        raise DHLabError(_("{who}: M must be a sympy Matrix or expression (e.g. robot.fk_sym()), got {got}.").format(
            who=who, got=describe(M))) from None
    entries = M if isinstance(M, sp.MatrixBase) else [M]
    if not isinstance(M, (sp.Expr, sp.MatrixBase)) or not all(isinstance(e, sp.Expr) for e in entries):
        raise DHLabError(_("{who}: M must be a sympy Matrix or expression, got {got}.").format(
            who=who, got=describe(M)))
    if isinstance(M, sp.MatrixBase) and not M:
        raise DHLabError(_("{who}: M is an empty matrix: pass a sympy Matrix such as robot.fk_sym().").format(who=who))
    check_finite_entries(M, who)
    for k, e in enumerate(entries):      # real: a pose has no imaginary part, and a float overflows no entry
        as_number(e, f"{who}: M[{k}]" if isinstance(M, sp.MatrixBase) else f"{who}: M", symbolic=True)
    q_symbols = list(q_symbols) if isinstance(q_symbols, (list, tuple)) else [q_symbols]
    by_name = {s.name: s for s in M.free_symbols if isinstance(s, sp.Symbol)}
    out = []
    for q in q_symbols:
        name = q.name if isinstance(q, sp.Symbol) else q
        if not isinstance(name, str):
            raise DHLabError(_("{who}: the joint variables must be symbols or names such as 'q1', got {got}.").format(
                who=who, got=describe(q)))
        out.append(by_name.get(name, sp.Symbol(name)))      # absent from M: harmless
    if by_name and not set(out) & set(by_name.values()):
        raise DHLabError(_("{who}: none of the joint variables {names} appears in M (its symbols are {symbols}): "
                           "pass the robot's joint symbols, e.g. robot.q_symbols.").format(
                               who=who, names=[str(q) for q in out], symbols=sorted(by_name)))
    return M, tuple(out)


def compact(M, q_symbols):
    """Replace cos/sin of (sums of) joint variables by the slides' C1, S23, C345 ….

    The result is for reading: its symbols are names, not functions. The joint
    variables may be given as symbols or by name (``['q1', 'q2']``).
    """
    M, q_symbols = _joint_arguments(M, q_symbols, "compact")
    atoms = set()
    for e in (M if isinstance(M, sp.MatrixBase) else [M]):
        atoms |= _joint_trig(e, q_symbols)
    names = {f: _compact_name(f, q_symbols) for f in atoms}
    return M.xreplace({f: sp.Symbol(n) for f, n in names.items() if n})


def legend(M, q_symbols) -> str:
    """The definitions behind :func:`compact`'s names, e.g. 'C1 = cos(q1), S23 = sin(q2 + q3)'."""
    M, q_symbols = _joint_arguments(M, q_symbols, "legend")
    atoms = set()
    for e in (M if isinstance(M, sp.MatrixBase) else [M]):
        atoms |= _joint_trig(e, q_symbols)
    named = sorted(((_compact_name(f, q_symbols), f) for f in atoms if _compact_name(f, q_symbols)),
                   key=lambda t: (len(t[0]), t[0][1:], t[0][0]))
    return ", ".join(f"{n} = {_greek(str(f))}" for n, f in named)


def _greek(text: str) -> str:
    """'cos(theta0)' -> 'cos(θ0)': the symbols as the slides write them."""
    for name, char in GREEK.items():
        text = text.replace(name, char)
    return text
