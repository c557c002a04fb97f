"""Reading a student's answer: into a sympy matrix or a vector of numbers, or a clear refusal.

Whatever a student types must come back as something a check can compare, or as a
:class:`Refused` whose message says what is wrong with it: text where a number is
expected, ``None`` or ``True`` inside a vector, NaN, infinity, a complex number,
sympy's ``zoo``, an integral or an undefined function in a matrix, a number too
large for a float, rows of different lengths.

Symbols are compared by the name the student meant (:func:`canon`): ``θ_0``,
``theta_{0}`` and ``theta0`` are the same symbol. :class:`Sampler` evaluates both
sides at the same values of their symbols, angles over a whole turn.

The decimals the student typed are read too (:func:`typed_decimals`): an answer
right to the precision typed is not blamed for its rounding.

>>> to_vector([0.5, None], "p", 2)
Traceback (most recent call last):
...
dhlab.course.checks.reading.Refused: None is not a number (component 2).
>>> typed_decimals([[0.87, -0.5], [1, 1.73]])
2
"""
from __future__ import annotations

import math
import numbers
import re

import numpy as np
import sympy as sp
from sympy.core.function import AppliedUndef

from ...i18n import N_, _

__all__ = ["Refused", "is_unanswered", "canon", "Sampler", "close", "to_sympy_matrix", "to_vector",
           "typed_decimals", "rounding_slack"]

SAMPLES = 12             # points at which symbolic answers are compared
BIGGEST = 1e12           # larger numbers are no answer to a kinematics exercise
MAX_NESTING = 8          # lists inside lists: a matrix has 2 levels; far deeper is no answer


class Refused(Exception):
    """The answer cannot be compared at all: the message says why, in the student's terms."""


# --- unanswered: the ... of the exercise cell ---------------------------------------------------------
def _has_ellipsis(x, depth=0) -> bool:
    if x is Ellipsis:
        return True
    if depth > 4:
        return False
    if isinstance(x, (list, tuple)):
        return any(_has_ellipsis(v, depth + 1) for v in x)
    if isinstance(x, dict):
        return any(_has_ellipsis(v, depth + 1) for v in x.values())
    if isinstance(x, np.ndarray) and x.dtype == object:
        return any(v is Ellipsis for v in x.flat)
    return False


def is_unanswered(x) -> bool:
    """``...`` (anywhere inside) or ``None``: the cell has not been filled in yet."""
    return x is None or _has_ellipsis(x)


# --- symbols: the same name whatever way it was typed -------------------------------------------
_GREEK = {"θ": "theta", "α": "alpha", "β": "beta", "γ": "gamma", "φ": "phi", "ψ": "psi", "ℓ": "l"}


def canon(symbol) -> str:
    """'θ_0', 'theta_{0}', 'Theta0' -> 'theta0': the name a student meant."""
    name = str(symbol)
    for greek, latin in _GREEK.items():
        name = name.replace(greek, latin)
    for junk in ("\\", "_", "{", "}", " "):
        name = name.replace(junk, "")
    return name.lower()


ANGLES = (-math.pi, math.pi)   # a whole turn: cos θ and √(1 − sin²θ) agree only on half of it
LENGTHS = (0.1, 3.0)           # l1, d, a2, …: a link's length is positive


def _is_length(name: str) -> bool:
    """'l1', 'l', 'd3', 'd', 'a2' (canonical names) are lengths; 'theta0', 'q2', 'alpha', 'a' are not."""
    return bool(re.fullmatch(r"[ld]\d*|a\d+", name))


class Sampler:
    """Values for symbols, by canonical name, the same on every run: angles over a whole turn,
    lengths over (0.1, 3). Each symbol gets one value in each of ``samples`` equal slices of its
    range, in random order, so no part of the turn is left out."""

    def __init__(self, names, samples: int = SAMPLES):
        rng = np.random.default_rng(20240607)
        self.values = {}
        for n in sorted(names):
            lo, hi = LENGTHS if _is_length(n) else ANGLES
            slices = rng.permutation(samples) + rng.random(samples)
            self.values[n] = lo + (hi - lo) * slices / samples
        self.samples = samples

    def evaluate(self, M) -> np.ndarray:
        """``M`` (a sympy Matrix) at every sample: shape (samples, rows, cols); NaN where undefined."""
        symbols = sorted(M.free_symbols, key=str)
        out = np.full((self.samples, *M.shape), np.nan)
        try:
            f = sp.lambdify(symbols, M, modules="numpy")
        except Exception:                  # sympy cannot turn it into numpy code: compare nothing
            return out
        with np.errstate(all="ignore"):
            for k in range(self.samples):
                try:
                    value = np.asarray(f(*[self.values[canon(s)][k] for s in symbols]), dtype=complex)
                except Exception:          # undefined at this sample (or not numeric at all): NaN
                    continue
                value = np.where(np.abs(value.imag) < 1e-12, value.real, np.nan)
                out[k] = np.broadcast_to(value, M.shape)
        return out


def close(a, b, tol, slack: float = 0.0) -> bool:
    """Every entry of ``a`` finite and within ``tol`` (relative and absolute) of ``b``, or within
    ``slack`` (the rounding of the decimals the student typed)."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    if a.shape != b.shape and a.size != b.size:
        return False
    error = np.abs(a - b)
    return bool(np.all(np.isfinite(a)) and np.all((error <= tol * (1 + np.abs(b))) | (error <= slack + 1e-12)))


# --- one entry -------------------------------------------------------------------------------------------
_UNEVALUATED = (sp.Integral, sp.Derivative, sp.Limit, sp.Sum, sp.Product)
NOT_FINITE = N_("{where} is {v}: not a finite number (NaN or infinity). A pose has finite entries: look at what "
                "produced it (an arcsin of more than 1? a division by 0?).")
TOO_LARGE = N_("{where} is {v}, far too large to be a length or an angle here.")
NOT_AN_EXPRESSION = N_("{v} is not a number or a sympy expression ({where}).")


def _entry(v, where: str) -> sp.Expr:
    """One number or expression of an answer, as sympy, or a :class:`Refused` saying why not."""
    if v is None or isinstance(v, (bool, np.bool_)):
        raise Refused(_("{v!r} is not a number ({where}).").format(v=v, where=where))
    if isinstance(v, str):
        raise Refused(_("{text!r} is text, not a number ({where}): write the number itself, without quotes.").format(
            text=v[:30], where=where))
    if isinstance(v, (list, tuple, dict, set, np.ndarray, sp.MatrixBase)):
        raise Refused(_("{where} is itself a list ({v}): one number is expected there.").format(
            where=where, v=_short(v)))
    if isinstance(v, (float, complex, np.floating, np.complexfloating)) and not np.isfinite(v):
        raise Refused(_(NOT_FINITE).format(where=where, v=repr(v)))
    if isinstance(v, numbers.Integral) and abs(int(v)) > BIGGEST:
        raise Refused(_(TOO_LARGE).format(where=where, v=_short(v)))
    try:
        e = sp.sympify(v, strict=True)
    except Exception:                      # any object sympy cannot read (its own methods may raise anything)
        raise Refused(_(NOT_AN_EXPRESSION).format(v=_short(v), where=where)) from None
    if not isinstance(e, sp.Expr):
        raise Refused(_(NOT_AN_EXPRESSION).format(v=_short(v), where=where))
    if e.has(sp.zoo, sp.oo, -sp.oo) or (e.is_number and e.has(sp.nan)) or e is sp.nan:
        raise Refused(_("{where} is {value}: an infinite or undefined value (a division by zero, a tan of 90°, …?). "
                        "A pose has finite entries.").format(where=where, value=sp.sstr(e)))
    undefined = sorted({str(f.func) for f in e.atoms(AppliedUndef)})
    if undefined:
        raise Refused(_("{where} uses {functions}(…), a function sympy does not know: write it with sp.cos, "
                        "sp.sin, sp.sqrt, … and the symbols of the exercise.").format(
                            where=where, functions=", ".join(undefined)))
    if e.atoms(*_UNEVALUATED):
        kind = type(next(iter(e.atoms(*_UNEVALUATED)))).__name__
        raise Refused(_("{where} is an unevaluated {kind}: call .doit() on it, or write the result.").format(
            where=where, kind=kind))
    if not e.free_symbols:
        try:
            value = complex(sp.N(e))
        except (TypeError, ValueError, OverflowError):
            raise Refused(_("{where} ({value}) has no numeric value.").format(where=where, value=sp.sstr(e)[:30])) \
                from None
        if not (math.isfinite(value.real) and math.isfinite(value.imag)):
            raise Refused(_(NOT_FINITE).format(where=where, v=_short(v)))
        if abs(value.imag) > 1e-12:
            raise Refused(_("{where} is complex ({v}): positions and angles are real numbers (a square root or "
                            "arcsin of something out of range?).").format(where=where, v=_short(v)))
        if abs(value.real) > BIGGEST:
            raise Refused(_(TOO_LARGE).format(where=where, v=_short(v)))
    return e


def _short(v) -> str:
    try:
        text = sp.sstr(v) if isinstance(v, sp.Basic) else repr(v)
    except Exception:                      # a repr that fails (too deep, or a broken __repr__)
        text = _("<a {type} that cannot be printed>").format(type=type(v).__name__)
    return text if len(text) <= 40 else text[:37] + "…"


def _rows(x):
    """A nested answer as a list of lists (2D) or raise Refused."""
    if isinstance(x, sp.MatrixBase):
        return x.tolist()
    if isinstance(x, np.ndarray):
        if x.ndim != 2:
            raise Refused((_("it has {n} dimension") if x.ndim == 1 else _("it has {n} dimensions")).format(n=x.ndim))
        return x.tolist()
    if not isinstance(x, (list, tuple)) or not all(isinstance(r, (list, tuple, np.ndarray, sp.MatrixBase))
                                                   for r in x) or not x:
        raise Refused(_("it is not a list of rows"))
    rows = [list(r) if not isinstance(r, sp.MatrixBase) else list(r) for r in x]
    if len({len(r) for r in rows}) != 1:
        raise Refused(_("its rows have different lengths ({lengths})").format(
            lengths=", ".join(str(len(r)) for r in rows)))
    return rows


# --- matrices -----------------------------------------------------------------------------------------------
def to_sympy_matrix(x, name: str) -> sp.Matrix:
    """A matrix answer as a sympy Matrix, or :class:`Refused`."""
    if isinstance(x, str):
        raise Refused(_("{name} is text ({text!r}): give a matrix, e.g. sp.Matrix([[...], ...]) or "
                        "np.array([[...], ...]).").format(name=name, text=x[:30]))
    try:
        rows = _rows(x)
    except Refused as why:
        raise Refused(_("{name} must be a matrix: rows of equal length, e.g. sp.Matrix([[...], ...]) or "
                        "np.array([[...], ...]) ({why}).").format(name=name, why=why)) from None
    if not rows[0]:
        raise Refused(_("{name} is empty.").format(name=name))
    entries = [[_entry(v, _("row {i}, column {j}").format(i=i + 1, j=j + 1)) for j, v in enumerate(row)]
               for i, row in enumerate(rows)]
    return sp.Matrix(entries)


# --- vectors ---------------------------------------------------------------------------------------------------
def _flatten(x, depth: int = 0) -> list:
    if isinstance(x, sp.MatrixBase):
        return list(x)
    if isinstance(x, np.ndarray):
        return list(x.ravel()) if x.ndim else [x.item()]
    if isinstance(x, (list, tuple)):
        if depth > MAX_NESTING:
            raise Refused(_("your answer is lists inside lists more than {n} deep: give the numbers as a flat "
                            "list [a, b, …] (or rows of a matrix).").format(n=MAX_NESTING))
        out = []
        for v in x:
            if isinstance(v, (list, tuple, np.ndarray, sp.MatrixBase)):
                out.extend(_flatten(v, depth + 1))
            else:
                out.append(v)
        return out
    if isinstance(x, (dict, set)):
        raise Refused(_("a {type} is not a list of numbers: give [a, b, …] in the order asked.").format(
            type=type(x).__name__))
    return [x]


def _shape_of(x):
    try:
        if isinstance(x, sp.MatrixBase):
            return x.shape
        if isinstance(x, (list, tuple, np.ndarray)):
            arr = np.asarray(x, dtype=object)
            return arr.shape
    except (ValueError, TypeError):
        return None
    return None


def to_vector(x, name: str, n: int):
    """An answer of ``n`` numbers as a float array, or a list of sympy expressions if it has symbols;
    or :class:`Refused` saying what is wrong (the count, a homogeneous 4-vector, a whole pose, …)."""
    if isinstance(x, str):
        raise Refused((_("{name} is text ({text!r}): give a number.") if n == 1 else
                       _("{name} is text ({text!r}): give {n} numbers.")).format(name=name, text=x[:30], n=n))
    items = _flatten(x)
    if len(items) != n:
        raise Refused(_count_problem(x, items, name, n))
    exprs = [_entry(v, _("component {k}").format(k=k + 1) if n > 1 else _("it")) for k, v in enumerate(items)]
    if any(e.free_symbols for e in exprs):
        return exprs
    return np.array([complex(sp.N(e)).real for e in exprs], dtype=float)


def _count_problem(x, items, name, n) -> str:
    shape = _shape_of(x)
    if shape == (4, 4) and n in (2, 3):
        return (_("{name} is a 4×4 matrix, a whole pose: the position is its last column, T[:3, 3] (and here "
                  "only x and y).") if n == 2 else
                _("{name} is a 4×4 matrix, a whole pose: the position is its last column, T[:3, 3].")).format(name=name)
    values = []
    for v in items:
        try:
            values.append(float(v))
        except Exception:                  # not a plain number: it cannot be the trailing 1 or 0
            values.append(None)
    if len(items) == n + 1 and n == 3 and values[-1] == 1.0:
        return _("your answer has 4 numbers; a position has 3: drop the trailing 1 of the homogeneous form.")
    if len(items) == 4 and n == 2 and values[-1] == 1.0 and values[-2] == 0.0:
        return _("your answer has 4 numbers (x, y, 0, 1), the homogeneous form of a point in space: drop the "
                 "trailing 1, and z too: the mechanism is planar, give (x, y).")
    if n == 2 and len(items) == 3 and values[-1] == 0.0:
        return _("your answer has 3 numbers (x, y, 0); the mechanism is planar: give (x, y), without z.")
    if n == 3 and len(items) == 2:
        return _("{name} must be 3 numbers; you gave 2: a position has 3 coordinates (x, y, z), z included.").format(
            name=name)
    return (_("{name} must be one number; you gave {k}.") if n == 1 else
            _("{name} must be {n} numbers; you gave {k}.")).format(name=name, n=n, k=len(items))


# --- the decimals the student typed --------------------------------------------------------------------------
def _decimals(v) -> int | None:
    """Decimals of a typed float (shortest repr); None for exact numbers (int, sympy exact)."""
    if isinstance(v, (bool, np.bool_)) or isinstance(v, numbers.Integral):
        return None
    if isinstance(v, sp.Basic):
        if not v.atoms(sp.Float):
            return None
        floats = [float(f) for f in v.atoms(sp.Float)]
        return max((d for d in (_decimals(f) for f in floats) if d is not None), default=None)
    if isinstance(v, (float, np.floating)):
        f = float(v)
        if not math.isfinite(f):
            return None
        text = repr(f)
        if "e" in text or "E" in text:
            mantissa, exponent = text.lower().split("e")
            places = len(mantissa.split(".")[1]) if "." in mantissa else 0
            return max(places - int(exponent), 0)
        return len(text.split(".")[1]) if "." in text else 0
    return None


def typed_decimals(x) -> int | None:
    """The most decimals typed in any number of the answer (its evident precision); None if
    every number is exact (integers, π/6, sqrt(3)/2, …)."""
    try:
        items = x.tolist() if isinstance(x, (np.ndarray, sp.MatrixBase)) else x
        flat = _flatten(items) if isinstance(items, (list, tuple)) else [items]
    except Refused:
        return None
    found = [d for d in (_decimals(v) for v in flat) if d is not None]
    return max(found) if found else None


def rounding_slack(decimals) -> float:
    """Half a unit of the last decimal typed: the error rounding to that many decimals may make."""
    return 0.0 if decimals is None or decimals > 15 else 0.5 * 10.0 ** -decimals
