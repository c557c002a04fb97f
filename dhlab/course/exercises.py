"""Exercise checks with specific feedback: what is wrong, and where.

A check compares a student's answer with the right one and says *what* is
wrong and *where*: which entry of a matrix, which component of a vector, a
sign, a transposed rotation, degrees where radians are expected, or a known
slip of the seeds (an erratum). Any equivalent form of a right answer passes:
symbolic answers are compared by evaluating both sides at random values of
their symbols, so ``sin(a + b)`` and ``sin(a)·cos(b) + cos(a)·sin(b)`` are
the same answer, and ``theta0``, ``theta_0`` and ``θ0`` are the same symbol.

The generic checks, usable from any notebook:

* :func:`check_matrix`: a matrix, symbolic or numeric;
* :func:`check_value`: a number or a vector (a position, joint values);
* :func:`check_solutions`: several solutions in any order (inverse kinematics);
* :func:`check_choice` and :func:`check_terms`: a choice, or words (a glossary);
* :func:`check_function`: a function the student wrote, called on test inputs.

Each returns a :class:`Feedback`: "✓ …" or "✗ …" and the list of problems.
A known wrong answer can be given with its own message (``mistakes=``): the
student who copies a matrix of the seeds as printed is told which erratum it is.

>>> import sympy as sp
>>> th = sp.Symbol("theta")
>>> R = sp.Matrix([[sp.cos(th), -sp.sin(th)], [sp.sin(th), sp.cos(th)]])
>>> check_matrix(R, R, name="R")
✓ correct: R is right.
>>> check_matrix(R.T, R, name="R")
✗ R is not right yet.
  • your rotation block is the transpose of the right one: that is the rotation the other way (by −θ instead of θ).

An :class:`Exercise` bundles a check with hints; the exercises of the course's
notebooks are made by :func:`exercise`:

>>> ex = exercise("1.1")
>>> ex.check([45, -90])
✗ Exercise 1.1: your q is not right yet.
  • θ0: you gave 45, which is the angle in degrees: the API takes radians. Write deg(45) (or 45·π/180).
  • θ1: you gave -90, which is the angle in degrees: the API takes radians. Write deg(-90) (or -90·π/180).
  Stuck? Call .hint() on this exercise (2 hints).
>>> ex.check(deg([45, -90]))
✓ Exercise 1.1: correct: your q is right.
"""
from __future__ import annotations

import html
import itertools
import math
import unicodedata

import numpy as np
import sympy as sp

from ..transforms import Rx, Ry, Rz, inv, trans
from ..units import deg

__all__ = ["Feedback", "Exercise", "check_matrix", "check_value", "check_solutions", "check_choice",
           "check_terms", "check_function", "exercise", "available", "seed001_DefinirTHz"]

MAX_ITEMS = 4            # entries listed one by one; beyond that, "… and k more"
SAMPLES = 6              # random points at which symbolic answers are compared
TRANSPOSED_ROTATION = ("your rotation block is the transpose of the right one: that is the rotation "
                       "the other way (by −θ instead of θ).")
NOT_ANSWERED = "not answered yet: replace the ... with your answer, then run the cell again."


# --- what a check returns ---------------------------------------------------------------------
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
            raise ValueError(f"status must be one of {sorted(self.MARKS)}, got {status!r}.")
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


def _correct(name):
    return Feedback("correct", f"correct: {name} is right.")


def _wrong(name, items):
    return Feedback("wrong", f"{name} is not right yet.", items)


def _unanswered(name):
    return Feedback("unanswered", f"{name}: {NOT_ANSWERED}")


class _Refused(Exception):
    """The answer cannot be compared at all (wrong type or shape): the message says why."""


def _has_ellipsis(x) -> bool:
    if x is Ellipsis:
        return True
    if isinstance(x, (list, tuple)):
        return any(_has_ellipsis(v) for v in x)
    if isinstance(x, dict):
        return any(_has_ellipsis(v) for v in x.values())
    if isinstance(x, np.ndarray) and x.dtype == object:
        return any(v is Ellipsis for v in x.flat)
    return False


def _unanswered_value(x) -> bool:
    return x is None or _has_ellipsis(x)


# --- symbols: the same name whatever way it was typed -------------------------------------------
_GREEK = {"θ": "theta", "α": "alpha", "β": "beta", "γ": "gamma", "φ": "phi", "ψ": "psi", "ℓ": "l"}


def _canon(symbol) -> str:
    """'θ_0', 'theta_{0}', 'Theta0' -> 'theta0': the name a student meant."""
    name = str(symbol)
    for greek, latin in _GREEK.items():
        name = name.replace(greek, latin)
    for junk in ("\\", "_", "{", "}", " "):
        name = name.replace(junk, "")
    return name.lower()


def _shown(names) -> str:
    return ", ".join(sorted(names))


class _Sampler:
    """Random values for symbols, by canonical name, the same on every run."""

    def __init__(self, names, samples: int = SAMPLES):
        rng = np.random.default_rng(20240607)
        self.values = {n: rng.uniform(-1.6, 1.6, samples) for n in sorted(names)}
        self.samples = samples

    def evaluate(self, M) -> np.ndarray:
        """``M`` (a sympy Matrix) at every sample: shape (samples, rows, cols); NaN where undefined."""
        symbols = sorted(M.free_symbols, key=str)
        f = sp.lambdify(symbols, M, modules="numpy")
        out = np.empty((self.samples, *M.shape))
        with np.errstate(all="ignore"):
            for k in range(self.samples):
                value = np.asarray(f(*[self.values[_canon(s)][k] for s in symbols]), dtype=complex)
                value = np.where(np.abs(value.imag) < 1e-12, value.real, np.nan)
                out[k] = np.broadcast_to(value, M.shape)
        return out


def _close(a, b, tol) -> bool:
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return bool(np.all(np.isfinite(a)) and np.all(np.abs(a - b) <= tol * (1 + np.abs(b))))


# --- reading answers -------------------------------------------------------------------------------
def _to_sympy_matrix(x, name: str) -> sp.Matrix:
    if isinstance(x, str):
        raise _Refused(f"{name} is text ({x[:30]!r}): give a matrix, e.g. sp.Matrix([[...], ...]) "
                       "or np.array([[...], ...]).")
    if isinstance(x, sp.MatrixBase):
        return sp.Matrix(x)
    try:
        arr = np.array(x, dtype=object)
    except (ValueError, TypeError):
        arr = None
    if arr is None or arr.ndim != 2:
        shape = "" if arr is None else f" (it has {arr.ndim} dimension{'s' if arr.ndim != 1 else ''})"
        raise _Refused(f"{name} must be a matrix: rows of equal length, e.g. "
                       f"sp.Matrix([[...], ...]) or np.array([[...], ...]){shape}.")
    try:
        return sp.Matrix([[sp.sympify(v, strict=True) for v in row] for row in arr.tolist()])
    except (sp.SympifyError, TypeError):
        raise _Refused(f"{name} has entries that are not numbers or sympy expressions.") from None


def _trig_in_degrees(M) -> list:
    """Entries like cos(90): sympy's trig functions take radians."""
    found = []
    for f in sorted(M.atoms(sp.sin, sp.cos, sp.tan), key=str):
        arg = f.args[0]
        if not arg.free_symbols and arg.is_real and abs(float(arg)) > 2 * math.pi + 1e-9:
            found.append(f"{f} takes radians: {sp.sstr(arg)} rad is more than a full turn. If you meant "
                         f"{sp.sstr(arg)}°, write sp.pi*{sp.sstr(arg)}/180 (or use dhlab.deg).")
    return found


def _symbol_problems(student: sp.Matrix, expected_names, allowed, name) -> list:
    """Symbols the student used that the exercise does not have."""
    unknown = sorted({str(s) for s in student.free_symbols if _canon(s) not in allowed})
    if not unknown:
        return []
    return [f"{name} uses {', '.join(unknown)}, which {'is' if len(unknown) == 1 else 'are'} not "
            f"a symbol of this exercise: use {_shown(expected_names) or 'numbers only'}."]


# --- describing places ------------------------------------------------------------------------------
def _where(i, j, shape, index_style) -> str:
    text = f"row {i + 1}, column {j + 1}"
    if index_style == "cpp":
        text += f" (aij[{i}][{j}])"
    elif index_style == "python":
        text += f" ([{i}, {j}])"
    if shape == (4, 4):
        if i < 3 and j < 3:
            text += ", rotation block"
        elif i < 3:
            text += f", translation column ({'xyz'[i]})"
        else:
            text += ", last row"
    return text


def _entry_text(value) -> str:
    if isinstance(value, sp.Basic) and value.free_symbols:
        return sp.sstr(value)
    return _num(float(sp.N(value)) if isinstance(value, sp.Basic) else float(value))


def _num(v: float) -> str:
    v = float(v) + 0.0                      # -0.0 -> 0.0
    return f"{v:.6g}"


# --- matrices ----------------------------------------------------------------------------------------
def check_matrix(student, expected, *, name: str = "your matrix", symbols=(), tol: float = 1e-3,
                 mistakes=(), index_style: str = "python") -> Feedback:
    """Compare a student's matrix with ``expected`` (both symbolic, or both numeric).

    ``symbols``: extra symbols the student may use (the expected matrix's own are
    always allowed). ``mistakes``: ``(wrong_matrix, message)`` pairs, checked first:
    a student's answer equal to a known wrong one gets that message.
    ``index_style``: how entries are named besides "row r, column c": 'python'
    (``[0, 3]``), 'cpp' (``aij[0][3]``) or 'math' (nothing more).

    >>> import numpy as np
    >>> from dhlab.transforms import Rz, trans
    >>> right = Rz(np.pi / 2) @ trans(2, 0, 0)
    >>> check_matrix(trans(2, 0, 0) @ Rz(np.pi / 2), right, name="T", mistakes=[
    ...     (trans(2, 0, 0) @ Rz(np.pi / 2), "that is the fixed-frame order (pre-multiplied).")])
    ✗ T is not right yet.
      • that is the fixed-frame order (pre-multiplied).
    """
    if _unanswered_value(student):
        return _unanswered(name)
    expected = _to_sympy_matrix(expected, "the expected matrix")
    try:
        got = _to_sympy_matrix(student, name)
    except _Refused as refusal:
        return _wrong(name, [str(refusal)])
    shape_problem = _shape_problem(got.shape, expected.shape, name)
    if shape_problem:
        return _wrong(name, [shape_problem])

    expected_names = {_canon(s) for s in expected.free_symbols}
    allowed = expected_names | {_canon(s) for s in symbols}
    problems = _trig_in_degrees(got)
    if expected_names and not got.free_symbols:
        problems.append(f"{name} has only numbers, but the answer is symbolic: write it with the "
                        f"symbols {_shown(str(s) for s in expected.free_symbols)} (for every value of them).")
    elif got.free_symbols and not expected_names:
        problems.append(f"{name} still has the symbols {_shown(str(s) for s in got.free_symbols)}: "
                        "the answer is numeric, substitute the numbers.")
    else:
        problems += _symbol_problems(got, {str(s) for s in expected.free_symbols}, allowed, name)
    if problems:
        return _wrong(name, problems)

    known = [(_to_sympy_matrix(wrong, "a known mistake"), message) for wrong, message in mistakes]
    names = allowed | {_canon(s) for s in got.free_symbols}
    sampler = _Sampler(names.union(*({_canon(s) for s in W.free_symbols} for W, _ in known)))
    E, S = sampler.evaluate(expected), sampler.evaluate(got)
    if _close(S, E, tol):
        return _correct(name)
    for W, message in known:
        if W.shape == got.shape and _close(S, sampler.evaluate(W), tol):
            return _wrong(name, [message])
    items = _matrix_diagnosis(got, expected, S, E, sampler, tol, index_style)
    used = {_canon(g) for g in got.free_symbols}
    missing = sorted(str(s) for s in expected.free_symbols if _canon(s) not in used)
    if missing and got.free_symbols:
        substituted = any(not float(f).is_integer() for f in got.atoms(sp.Float))
        items.insert(0, f"{name} does not use {', '.join(missing)}, but the right matrix does"
                     + (": keep the parameters as symbols (the answer must hold for every value), "
                        "do not substitute numbers." if substituted else "."))
    return _wrong(name, items)


def _shape_problem(got, expected, name):
    if got == expected:
        return ""
    if expected == (4, 4) and got == (3, 3):
        return (f"{name} is 3×3, but a homogeneous transformation matrix is 4×4: "
                "[[R, p], [0, 0, 0, 1]], the 3×3 rotation R, the position p, and the row 0 0 0 1.")
    if expected == (3, 3) and got == (4, 4):
        return f"{name} is 4×4: here only the 3×3 rotation block is asked for."
    return f"{name} has shape {got[0]}×{got[1]}; it must be {expected[0]}×{expected[1]}."


def _matrix_diagnosis(got, expected, S, E, sampler, tol, index_style) -> list:
    """What is wrong, from the whole matrix down to single entries."""
    items, explained = [], np.zeros(E.shape[1:], dtype=bool)
    rows, cols = E.shape[1:]
    homogeneous = (rows, cols) == (4, 4) and _close(E[:, 3], np.broadcast_to([0, 0, 0, 1], E[:, 3].shape), 1e-9)
    if homogeneous and not _close(S[:, :3, :3], E[:, :3, :3], tol):
        inverse = np.array([np.linalg.inv(e) for e in E])
        if _close(S, inverse, tol):
            if _close(E[:, :3, 3], np.zeros_like(E[:, :3, 3]), 1e-12):
                return [TRANSPOSED_ROTATION]
            return ["this is the inverse of the right matrix: it maps the other way round "
                    "(the two frames' roles are swapped)."]
    if rows == cols and _close(S, np.swapaxes(E, 1, 2), tol):
        if _close(np.einsum("kji,kjl->kil", E, E), np.broadcast_to(np.eye(rows), E.shape), 1e-9):
            return [TRANSPOSED_ROTATION]
        return ["you wrote the rows as columns: the whole matrix is transposed."]
    if homogeneous:
        if not _close(S[:, 3], E[:, 3], tol):
            items.append(f"the last row must be 0 0 0 1; yours is "
                         f"{' '.join(_entry_text(v) for v in got[3, :])}.")
            explained[3] = True
        RS, RE = S[:, :3, :3], E[:, :3, :3]
        if not _close(RS, RE, tol) and _close(RS, np.swapaxes(RE, 1, 2), tol):
            items.append(TRANSPOSED_ROTATION)
            explained[:3, :3] = True
        pS, pE = S[:, :3, 3], E[:, :3, 3]
        every_component_used = bool(np.all(np.abs(pE).max(axis=0) > 1e-9))
        if every_component_used and not _close(pS, pE, tol) and _close(pS, -pE, tol):
            items.append("the whole translation column has the wrong sign.")
            explained[:3, 3] = True
    if rows == cols == 3 or homogeneous:
        items += _rotation_problems(got, S, tol)
    wrong = [(i, j) for i in range(rows) for j in range(cols)
             if not explained[i, j] and not _close(S[:, i, j], E[:, i, j], tol)]
    for i, j in wrong[:MAX_ITEMS]:
        items.append(f"{_where(i, j, (rows, cols), index_style)}: "
                     + _entry_problem(got[i, j], expected[i, j], S[:, i, j], E[:, i, j], sampler, tol))
    if len(wrong) > MAX_ITEMS:
        items.append(f"… and {len(wrong) - MAX_ITEMS} more entries are not right.")
    return items or ["it does not match the right matrix."]


def _rotation_problems(got, S, tol) -> list:
    """A rotation block that is not a rotation (det ≠ 1 or not orthonormal)."""
    R = S[:, :3, :3]
    dets = np.linalg.det(R)
    orthonormal = _close(np.einsum("kji,kjl->kil", R, R), np.broadcast_to(np.eye(3), R.shape), 1e-6)
    if orthonormal and _close(dets, np.ones_like(dets), 1e-6):
        return []
    if got.free_symbols:
        det = sp.trigsimp(sp.simplify(got[:3, :3].det()))
        what = f"det R = {sp.sstr(det)}"
    else:
        what = f"det R = {_num(dets[0])}"
    return [f"your rotation block is not a rotation: {what}, but a rotation has det R = +1 and "
            "orthonormal columns (RᵀR = I)."
            + (" A negative determinant is a mirror image." if np.all(dets < -1e-9) else "")]


def _entry_problem(student, expected, s, e, sampler, tol) -> str:
    mine = _entry_text(student)
    if _close(e, np.zeros_like(e), 1e-12):
        return f"you have {mine}; this entry is 0."
    if _close(s, -e, tol):
        return f"you have {mine}: the sign is wrong."
    if isinstance(student, sp.Basic) and student.free_symbols:
        swapped = student.replace(lambda x: isinstance(x, (sp.sin, sp.cos)),
                                  lambda x: (sp.cos if isinstance(x, sp.sin) else sp.sin)(x.args[0]))
        value = sampler.evaluate(sp.Matrix([swapped]))[:, 0, 0]
        if _close(value, e, tol):
            return f"you have {mine}: cos and sin are swapped."
        if _close(value, -e, tol):
            return f"you have {mine}: cos and sin are swapped, and the sign is wrong."
        slip = _wrong_symbol(student, expected, e, sampler, tol)
        if slip:
            return f"you have {mine}: {slip}"
    return f"you have {mine}, which is not right."


def _wrong_symbol(student, expected, e, sampler, tol) -> str:
    """One symbol typed for another in one term (l1 for l2, θ1 for θ0), if that explains the entry."""
    wanted = sorted({_canon(x) for x in getattr(expected, "free_symbols", ())})
    terms = sp.Add.make_args(sp.expand(student))
    for k, term in enumerate(terms):
        for mine, other in itertools.product(sorted(term.free_symbols, key=str), wanted):
            if _canon(mine) == other:
                continue
            fixed = sp.Add(*terms[:k], term.xreplace({mine: sp.Symbol(other)}), *terms[k + 1:])
            if _close(sampler.evaluate(sp.Matrix([fixed]))[:, 0, 0], e, tol):
                where = "" if len(terms) == 1 else f" in the term {sp.sstr(term)}"
                return f"{mine} is the wrong symbol{where}: it should be {other}."
    return ""


# --- numbers and vectors -------------------------------------------------------------------------------
def _as_units(unit, n):
    if isinstance(unit, (list, tuple)):
        if len(unit) != n:
            raise ValueError(f"unit must give one unit per component ({n}), got {unit!r}.")
        return list(unit)
    return [unit] * n


def _with_unit(value, unit):
    if unit == "°":
        return f"{_num(value)}°"
    return _num(value) + (f" {unit}" if unit and unit != "rad" else (" rad" if unit == "rad" else ""))


def _to_vector(x, name, n) -> np.ndarray | list:
    """A numeric answer as a float vector, or a list of sympy expressions if it has symbols."""
    if isinstance(x, str):
        raise _Refused(f"{name} is text ({x[:30]!r}): give a number.")
    if isinstance(x, sp.MatrixBase):
        x = list(x)
    items = list(np.ravel(np.array(x, dtype=object))) if np.ndim(np.array(x, dtype=object)) else [x]
    if len(items) != n:
        what = "one number" if n == 1 else f"{n} numbers"
        raise _Refused(f"{name} must be {what}; you gave {len(items)}.")
    exprs = []
    for v in items:
        try:
            exprs.append(sp.sympify(v, strict=True))
        except (sp.SympifyError, TypeError):
            raise _Refused(f"{name} must be numbers; {v!r} is not one.") from None
    if any(e.free_symbols for e in exprs):
        return exprs
    try:
        return np.array([complex(sp.N(e)).real if abs(complex(sp.N(e)).imag) < 1e-12 else np.nan
                         for e in exprs], dtype=float)
    except (TypeError, ValueError):
        raise _Refused(f"{name} must be numbers.") from None


def check_value(student, expected, *, name: str = "your value", components=None, unit="",
                tol: float = 1e-3, mistakes=()) -> Feedback:
    """Compare a number, or a vector of numbers, with ``expected``.

    ``components``: names of the vector's entries, e.g. ``("x", "y", "z")``.
    ``unit``: one unit for all, or one per component. 'rad' and '°' turn on the
    degrees-vs-radians diagnosis. ``tol``: relative-and-absolute tolerance (answers
    typed with 3–4 decimals pass). ``mistakes``: ``(wrong_value, message)`` pairs.
    ``expected`` may be symbolic (sympy expressions): then the answer must be too.

    >>> import math
    >>> check_value(math.degrees(0.5), 0.5, name="q2", unit="rad")
    ✗ q2 is not right yet.
      • you gave 28.6479, which is the angle in degrees: the API takes radians. Write deg(28.6479) (or 28.6479·π/180).
    >>> check_value([0.866, 0.5, 0], [math.sqrt(3) / 2, 0.5, 0], name="p", components="xyz")
    ✓ correct: p is right.
    """
    if _unanswered_value(student):
        return _unanswered(name)
    scalar = np.ndim(np.array(expected, dtype=object)) == 0 and not isinstance(expected, sp.MatrixBase)
    exp_items = [expected] if scalar else list(np.ravel(np.array(expected, dtype=object)))
    n = len(exp_items)
    components = list(components) if components is not None else (
        [name] if scalar else [f"component {k + 1}" for k in range(n)])
    units = _as_units(unit, n)
    try:
        got = _to_vector(student, name, n)
    except _Refused as refusal:
        return _wrong(name, [str(refusal)])
    exp_exprs = [sp.sympify(e) for e in exp_items]
    if any(e.free_symbols for e in exp_exprs) or isinstance(got, list):
        feedback = check_matrix(sp.Matrix([got if isinstance(got, list) else list(got)]),
                                sp.Matrix([exp_exprs]), name=name, tol=tol, mistakes=[
                                    (sp.Matrix([list(np.ravel(np.array(w, dtype=object)))]), m)
                                    for w, m in mistakes], index_style="math")
        if not feedback.ok and feedback.status == "wrong":
            feedback.items = [_component_names(i, components) for i in feedback.items]
        return feedback
    exp = np.array([float(sp.N(e)) for e in exp_exprs])
    if _close(got, exp, tol):
        return _correct(name)
    for wrong, message in mistakes:
        w = np.ravel(np.array(wrong, dtype=float))
        if w.shape == got.shape and _close(got, w, tol):
            return _wrong(name, [message])
    return _wrong(name, _vector_diagnosis(got, exp, components, units, tol, scalar))


def _component_names(item: str, components) -> str:
    """check_matrix speaks of 'row 1, column k': for a vector, name the component."""
    for k, comp in enumerate(components):
        prefix = f"row 1, column {k + 1}: "
        if item.startswith(prefix):
            return f"{comp}: " + item[len(prefix):]
    return item


def _vector_diagnosis(got, exp, components, units, tol, scalar) -> list:
    n = len(exp)
    if n > 1:
        if _close(got, -exp, tol) and not _close(exp, np.zeros(n), 1e-12):
            return ["every component has the wrong sign."]
        for perm in itertools.permutations(range(n)):
            if list(perm) != list(range(n)) and _close(got[list(perm)], exp, tol):
                return [f"the right numbers, in the wrong order: the order is ({', '.join(components)})."]
    items = []
    for k in range(n):
        if _close(got[k], exp[k], tol):
            continue
        label = "" if scalar else f"{components[k]}: "
        items.append(label + _number_problem(got[k], exp[k], units[k], tol))
    return items


def _number_problem(g, e, unit, tol) -> str:
    nonzero = not math.isclose(e, 0, abs_tol=1e-12)
    if unit == "rad" and nonzero and math.isclose(g, math.degrees(e), rel_tol=tol, abs_tol=tol):
        return (f"you gave {_num(g)}, which is the angle in degrees: the API takes radians. "
                f"Write deg({_num(g)}) (or {_num(g)}·π/180).")
    if unit == "°" and nonzero and math.isclose(g, math.radians(e), rel_tol=tol, abs_tol=tol):
        return f"you gave {_num(g)}, which is the angle in radians: here it is asked in degrees."
    if unit in ("rad", "°"):
        turn = 2 * math.pi if unit == "rad" else 360.0
        if math.isclose((g - e) / turn, round((g - e) / turn), abs_tol=tol) and round((g - e) / turn):
            return f"you gave {_with_unit(g, unit)}: the same direction, but give it within one turn (±180°)."
    if not math.isclose(e, 0, abs_tol=1e-12) and math.isclose(g, -e, rel_tol=tol, abs_tol=tol):
        return f"you gave {_with_unit(g, unit)}: the sign is wrong."
    if math.isclose(g, e, rel_tol=20 * tol, abs_tol=20 * tol):
        return f"you gave {_with_unit(g, unit)}: close, but rounded too much; give at least 4 decimals."
    if math.isclose(e, 0, abs_tol=1e-12):
        return f"you gave {_with_unit(g, unit)}; it is 0."
    return f"you gave {_with_unit(g, unit)}, which is not right."


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
      • missing: the solution (q1, q2) = (1.2, 2.4981 rad).
    """
    if _unanswered_value(student):
        return _unanswered(name)
    expected = [np.ravel(np.array(e, dtype=float)) for e in expected]
    n = len(expected[0]) if expected else 0
    components = list(components) if components is not None else [f"component {k + 1}" for k in range(n)]
    units = _as_units(unit, n)
    try:
        sols = [np.asarray(_to_vector(s, f"solution {k + 1}", n), dtype=float)
                for k, s in enumerate(list(student))]
    except (_Refused, TypeError) as refusal:
        return _wrong(name, [str(refusal) if isinstance(refusal, _Refused) else
                             f"{name} must be a list of solutions, each ({', '.join(components)})."])
    period = np.array([2 * math.pi if u == "rad" else 360.0 if u == "°" else 0.0 for u in units])

    def same(a, b):
        diff = a - b
        wrapped = np.where(period > 0, diff - period * np.round(diff / np.where(period > 0, period, 1)), diff)
        return bool(np.all(np.abs(wrapped) <= tol * (1 + np.abs(b))))

    unmatched = list(range(len(expected)))
    extra = []
    for s in sols:
        hit = next((k for k in unmatched if same(s, expected[k])), None)
        if hit is None:
            extra.append(s)
        else:
            unmatched.remove(hit)
    if not unmatched and not extra:
        return _correct(name)
    items = []
    if len(sols) != len(expected):
        items.append(f"there {'is' if len(expected) == 1 else 'are'} {len(expected)} solution"
                     f"{'' if len(expected) == 1 else 's'}; you gave {len(sols)}.")
    for s in extra:
        message = next((m for w, m in mistakes if same(s, np.ravel(np.array(w, dtype=float)))), None)
        if message:
            items.append(message)
            continue
        if any(same(s, e) for e in expected):
            items.append(f"{_solution_text(s, components, units)} is given twice.")
            continue
        text = f"{_solution_text(s, components, units)} is not a solution"
        if unmatched:
            closest = min(unmatched, key=lambda k: np.abs(s - expected[k]).sum())
            details = _vector_diagnosis(s, expected[closest], components, units, tol, False)
            if details:
                text += ": " + "; ".join(d.rstrip(".") for d in details)
        items.append(text + ".")
    if len(sols) < len(expected):
        for k in unmatched[:len(expected) - len(sols)]:
            items.append(f"missing: the solution {_solution_text(expected[k], components, units)}.")
    return _wrong(name, items)


def _solution_text(s, components, units):
    return (f"({', '.join(components)}) = ("
            + ", ".join(_with_unit(v, u) for v, u in zip(s, units)) + ")")


# --- words --------------------------------------------------------------------------------------------
def _words(text) -> str:
    """'End-Effector ' -> 'end effector'; accents dropped ('eslabón' -> 'eslabon')."""
    text = unicodedata.normalize("NFKD", str(text))
    text = "".join(ch for ch in text if not unicodedata.combining(ch)).casefold()
    for sep in ("-", "_", "/"):
        text = text.replace(sep, " ")
    words = text.split()
    if words and words[0] in ("the", "a", "an", "el", "la", "los", "las"):
        words = words[1:]
    return " ".join(words)


def check_choice(student, correct, *, name: str = "your answer", accepted=(), explanations=None) -> Feedback:
    """A choice or a short word answer: ``correct`` (or one of ``accepted``) passes.

    Text is compared without case, accents, hyphens or a leading article.
    ``explanations`` maps wrong answers to what is wrong with them.

    >>> check_choice("Red", "green", name="the colour of y", explanations={"red": "red is the x axis."})
    ✗ the colour of y is not right yet.
      • red is the x axis.
    """
    if _unanswered_value(student):
        return _unanswered(name)
    norm = _words if isinstance(correct, str) else (lambda v: v)
    right = {norm(correct), *(norm(a) for a in accepted)}
    if norm(student) in right:
        return _correct(name)
    for wrong, why in (explanations or {}).items():
        if norm(student) == norm(wrong):
            return _wrong(name, [why])
    return _wrong(name, [f"you answered {student!r}, which is not right."])


def check_terms(student: dict, expected: dict, *, name: str = "your glossary") -> Feedback:
    """Words for terms, e.g. Spanish -> English: ``expected`` maps each term to its
    answer (or a tuple of accepted answers). Says which terms are wrong, missing,
    or given the answer of another term.

    >>> check_terms({"eslabón": "joint", "articulación": "joint"},
    ...             {"eslabón": "link", "articulación": "joint"}, name="the glossary")
    ✗ the glossary is not right yet.
      • eslabón: you wrote 'joint', which is the English for articulación.
    """
    if not isinstance(student, dict):
        return _unanswered(name) if _unanswered_value(student) else _wrong(
            name, [f"{name} must be a dict {{term: answer, …}}."])
    accepted = {term: {_words(a) for a in (v if isinstance(v, (tuple, list, set)) else (v,))}
                for term, v in expected.items()}
    given = {_words(k): v for k, v in student.items()}
    items, unanswered = [], 0
    for term, answers in accepted.items():
        value = given.get(_words(term))
        if value is None or value is Ellipsis or str(value).strip() in ("", "..."):
            unanswered += 1
            continue
        if _words(value) in answers:
            continue
        other = next((t for t, a in accepted.items() if t != term and _words(value) in a), None)
        items.append(f"{term}: you wrote {value!r}, which is the English for {other}." if other
                     else f"{term}: you wrote {value!r}, which is not right.")
    if unanswered == len(accepted):
        return _unanswered(name)
    if unanswered:
        items.append(f"{unanswered} term{'s are' if unanswered > 1 else ' is'} still empty (...).")
    return _correct(name) if not items else _wrong(name, items)


# --- functions ----------------------------------------------------------------------------------------
def check_function(student_fn, reference, cases, *, name: str = "your function", check=check_matrix,
                   describe=None, mistakes=(), **options) -> Feedback:
    """Call the student's function on every case (a tuple of arguments) and compare
    with ``reference``; report the first case that fails, with ``check``'s details.

    ``mistakes``: ``(wrong_function, message)`` pairs: a student's function giving the
    same results as a known wrong one on every case gets that message. ``options``
    go to ``check`` (e.g. ``index_style='cpp'``).
    """
    if _unanswered_value(student_fn):
        return _unanswered(name)
    if not callable(student_fn):
        return _wrong(name, [f"{name} must be a function (def …), got {type(student_fn).__name__}."])
    describe = describe or (lambda args: ", ".join(map(repr, args)))
    results = []
    for args in cases:
        try:
            results.append(student_fn(*args))
        except Exception as exc:                     # the student's code: any error is feedback
            return _wrong(name, [f"calling it with {describe(args)} raised {type(exc).__name__}: {exc}"])
    for wrong_fn, message in mistakes:
        if all(check(r, wrong_fn(*args), **options).ok for r, args in zip(results, cases)):
            return _wrong(name, [message])
    failures = []
    for result, args in zip(results, cases):
        feedback = check(result, reference(*args), name="the result", **options)
        if not feedback.ok:
            failures.append((args, feedback))
    if not failures:
        return _correct(name)
    # the case that shows the most problems tells the most (at θ = 0 a wrong sin is invisible)
    args, feedback = max(failures, key=lambda f: len(f[1].items))
    return _wrong(name, [f"for {describe(args)}:"] + feedback.items)


# --- exercises with hints -----------------------------------------------------------------------------
class Exercise:
    """An exercise: a check (answer -> :class:`Feedback`) and hints.

    ``check(answer)`` shows the feedback; ``hint()`` shows the next hint
    (call it again for the following one), ``hint(k)`` the k-th.
    """

    def __init__(self, key: str, title: str, check, hints=()):
        self.key, self.title, self._check, self.hints = key, title, check, list(hints)
        self._next_hint = 0

    def check(self, answer) -> Feedback:
        feedback = self._check(answer)
        feedback.title = f"Exercise {self.key}: {feedback.title}"
        if feedback.status == "wrong" and self.hints:
            n = len(self.hints)
            feedback.tip = f"Stuck? Call .hint() on this exercise ({n} hint{'s' if n > 1 else ''})."
        return feedback

    def hint(self, k: int | None = None) -> Feedback:
        if not self.hints:
            return Feedback("hint", f"Exercise {self.key} has no hints.")
        if k is None:
            k = min(self._next_hint, len(self.hints) - 1) + 1
            self._next_hint = min(self._next_hint + 1, len(self.hints))
        if not 1 <= k <= len(self.hints):
            raise ValueError(f"hint number must be 1…{len(self.hints)}, got {k}.")
        more = " (call .hint() again for the next)" if k < len(self.hints) else ""
        return Feedback("hint", f"Hint {k} of {len(self.hints)} for exercise {self.key}{more}:",
                        [self.hints[k - 1]])

    def __repr__(self):
        return f"<Exercise {self.key}: {self.title}>"


# ======================================================================================================
# The exercises of notebooks 1-4. The right answers live here, not in the notebooks.
# ======================================================================================================
TH, THETA0, THETA1, L1, L2 = sp.symbols("theta theta0 theta1 l1 l2")


def _ex_1_1():
    return Exercise("1.1", "a joint vector for the API", lambda a: check_value(
        a, [math.radians(45), math.radians(-90)], name="your q", components=("θ0", "θ1"), unit="rad"),
        ["The sliders show degrees; robot.fk takes radians: dhlab.deg converts (it also takes a list).",
         "q lists the joints from the base: [θ0, θ1]."])


def _ex_1_2():
    return Exercise("1.2", "glossary", lambda a: check_terms(a, {
        "eslabón": "link", "articulación": "joint", "efector final": ("end effector", "end-effector"),
        "dextrógiro": ("right-handed", "right handed"), "grados de libertad": ("degrees of freedom", "dof"),
    }, name="the glossary"), ["The glossary table above has every term."])


def _ex_1_3():
    return Exercise("1.3", "colour of z", lambda a: check_choice(
        a, "blue", name="the colour of the z axis",
        explanations={"red": "red is the x axis.", "green": "green is the y axis."}),
        ["x, y, z are drawn in the order of the colours of RGB."])


def _ex_2_1():
    right = Rz(TH)
    return Exercise("2.1", "Rz(θ) by hand", lambda a: check_matrix(a, right, name="your Rz(θ)", mistakes=[
        (Rx(TH), "that is the rotation about x (it leaves x fixed): Rz leaves z fixed, so its third row "
                 "and column are those of the identity."),
        (Ry(TH), "that is the rotation about y (it leaves y fixed): Rz leaves z fixed.")]),
        ["A rotation about z leaves z fixed: the third row and column are 0 0 1 (and the 4th those of the identity).",
         "Its first column is where x goes: (cos θ, sin θ, 0). The second is where y goes: 90° further on."])


def _ex_2_2():
    right = Rz(math.radians(30)) @ trans(2, 0, 0)
    by_hand_in_degrees = np.array([[math.cos(30), -math.sin(30), 0, 2 * math.cos(30)],
                                   [math.sin(30), math.cos(30), 0, 2 * math.sin(30)],
                                   [0, 0, 1, 0], [0, 0, 0, 1]])
    return Exercise("2.2", "compose in the moving frame", lambda a: check_matrix(
        a, right, name="your ⁰T₁", mistakes=[
            (trans(2, 0, 0) @ Rz(math.radians(30)),
             "that is Tr(2,0,0)·Rz(30°): the move along the FIXED x0 axis (pre-multiplied, fixed-frame order). "
             "Moving along the new x axis means post-multiplying: Rz(30°)·Tr(2,0,0)."),
            (by_hand_in_degrees, "cos(30) and sin(30) were computed with 30 radians: "
                                 "use the angle in radians, deg(30) = π/6."),
            (Rz(math.radians(30)), "that is only the rotation: the move of 2 along the new x is missing.")]),
        ["Moving frame: multiply on the right, in the order the motions happen.",
         "Rz(deg(30)) @ trans(2, 0, 0): the new origin is 2·(cos 30°, sin 30°, 0)."])


def _ex_2_3():
    T = trans(1, 2, 0) @ Rz(math.pi / 2)
    R, p = T[:3, :3], T[:3, 3]
    keep_p = np.eye(4)
    keep_p[:3, :3], keep_p[:3, 3] = R.T, p
    minus_p = keep_p.copy()
    minus_p[:3, 3] = -p
    return Exercise("2.3", "the inverse", lambda a: check_matrix(a, inv(T), name="your T⁻¹", mistakes=[
        (keep_p, "the rotation block (Rᵀ) is right, but the translation of the inverse is −Rᵀ·p, not p."),
        (minus_p, "the rotation block (Rᵀ) is right, but the translation of the inverse is −Rᵀ·p: "
                  "−p alone forgets to turn it into the other frame."),
        (T, "that is T itself: the inverse undoes it, T⁻¹·T = I.")]),
        ["T⁻¹ = [[Rᵀ, −Rᵀ·p], [0 0 0 1]].", "Check yours: T⁻¹ @ T must be the identity."])


def seed001_DefinirTHz(dtheta, d):
    """Seed 001's ``DefinirTHz`` listing, transcribed line by line into Python, bugs included.

    ``dtheta`` in radians (the C++ ``AplicarTHz`` converts degrees first), ``d`` = (x, y, z).
    """
    THz = np.zeros((4, 4))
    THz[0][0] = -math.cos(dtheta)
    THz[0][1] = -math.sin(dtheta)
    THz[0][2] = 0
    THz[0][3] = -d[0]
    THz[1][0] = math.sin(dtheta)
    THz[1][1] = math.cos(dtheta)
    THz[1][2] = 0
    THz[1][3] = -d[1]
    THz[2][0] = 0
    THz[2][1] = 0
    THz[2][2] = 1
    THz[2][3] = -d[2]
    THz[3][0] = 0
    THz[3][1] = 0
    THz[3][2] = 0
    THz[3][3] = 1
    return THz


def _seed000_DefinirTHz(dtheta, d):
    """The right listing (seed 000, the author's repository): Tr(d)·Rz(θ)."""
    return trans(*d) @ Rz(dtheta)


def _ex_2_4():
    def only_cos_fixed(dtheta, d):
        M = seed001_DefinirTHz(dtheta, d)
        M[0][0] = math.cos(dtheta)
        return M

    def only_d_fixed(dtheta, d):
        M = seed001_DefinirTHz(dtheta, d)
        M[:3, 3] = d
        return M

    cases = [(0.0, (0.0, 0.0, 2.5)), (math.radians(30), (0.0, 0.0, 2.5)),
             (math.radians(45), (1.0, 2.0, 3.0)), (2.0, (0.5, -1.0, 0.0))]
    return Exercise("2.4", "spot the bug in DefinirTHz", lambda f: check_function(
        f, _seed000_DefinirTHz, cases, name="your DefinirTHz", index_style="cpp",
        describe=lambda a: f"dtheta = {math.degrees(a[0]):g}°, d = {a[1]}",
        mistakes=[(seed001_DefinirTHz, "this is still seed 001's listing, unchanged: it has two bugs. "
                                       "Compare each line with Rz(θ) and with a translation by d."),
                  (only_cos_fixed, "aij[0][0] is fixed, but the translation column still has −d.x, −d.y, "
                                   "−d.z: the frame moves to the wrong side (erratum 001-2)."),
                  (only_d_fixed, "the translation column is fixed, but aij[0][0] is still −cos(dtheta): "
                                 "det R = −cos 2θ, a mirror at θ = 0 and flat at 45° (erratum 001-1).")]),
        ["Compare each line with the matrix Rz(θ) of this notebook: one entry of the rotation block differs.",
         "Seed 000 prints the same listing with d.x, d.y, d.z: which sign does a translation by d have?"])


def _robot1_H1_eq3():
    """⁰H₁ as printed in seed 004's eq. (3) (erratum 004-1)."""
    c, s = sp.cos(THETA0), sp.sin(THETA0)
    return sp.Matrix([[c, -s, 0, -L1 * c], [s, c, 0, L1 * s], [0, 0, 1, 0], [0, 0, 0, 1]])


def _ex_3_1():
    right = Rz(THETA0) * trans(0, L1, 0)
    mistakes = [
        (_robot1_H1_eq3(), "your translation column is (−l1·cos θ0, l1·sin θ0, 0): that is eq. (3) as printed, "
                           "erratum 004-1. At θ0 = 0 it puts {S1} at (−l1, 0) instead of (0, l1): link 1 lies "
                           "along y0."),
        (trans(0, L1, 0) * Rz(THETA0), "your translation column is (0, l1, 0) for every θ0: that is "
                                       "Tr(0,l1,0)·Rz(θ0), the link does not turn with the joint. The joint turns "
                                       "first, then the link carries {S1} along the NEW y axis: "
                                       "Rz(θ0)·Tr(0,l1,0)."),
    ]
    return Exercise("3.1", "⁰H₁ of the first robot",
                    lambda a: check_matrix(a, right, name="your ⁰H₁", mistakes=mistakes),
                    ["Two motions, in the moving frame: turn by θ0 about z0, then move l1 along the new y axis.",
                     "The translation column is Rz(θ0) applied to (0, l1, 0)."])


def _ex_3_2():
    H1, H2 = Rz(THETA0) * trans(L1, 0, 0), Rz(THETA1) * trans(L2, 0, 0)
    right = H1 * H2
    seed_robot = Rz(THETA0) * trans(0, L1, 0) * H2
    c0, s0, c1, s1 = sp.cos(THETA0), sp.sin(THETA0), sp.cos(THETA1), sp.sin(THETA1)
    link2_alone = right.copy()
    link2_alone[0, 3], link2_alone[1, 3] = L1 * c0 + L2 * c1, L1 * s0 + L2 * s1
    return Exercise("3.2", "⁰H₂ of the variant with link 1 along x0", lambda a: check_matrix(
        a, right, name="your ⁰H₂", mistakes=[
            (seed_robot, "that is ⁰H₂ of seed 004's robot, whose link 1 lies along y0; in this variant link 1 "
                         "lies along x0: ⁰H₁ = Rz(θ0)·Tr(l1, 0, 0)."),
            (H2 * H1, "that is ¹H₂·⁰H₁, the product in the wrong order: ⁰H₂ = ⁰H₁·¹H₂ (the upper and lower "
                      "indices chain: 0→1, then 1→2)."),
            (link2_alone, "the rotation block is right, but link 2 points at θ0 + θ1 from x0, not θ1: its "
                          "terms are l2·cos(θ0+θ1) and l2·sin(θ0+θ1) (angles add along a planar chain).")]),
        ["⁰H₁ = Rz(θ0)·Tr(l1, 0, 0) and ¹H₂ = Rz(θ1)·Tr(l2, 0, 0); multiply them in this order.",
         "At θ0 = θ1 = 0 the pen must be at (l1 + l2, 0, 0); the rotation block is Rz(θ0 + θ1)."])


def _robot1_position(t0, t1, l1=0.70, l2=0.30):
    return np.array([l2 * math.cos(t0 + t1) - l1 * math.sin(t0), l2 * math.sin(t0 + t1) + l1 * math.cos(t0), 0.0])


def _ex_3_3():
    t0, t1 = math.radians(30), math.radians(45)
    eq3 = np.array(_robot1_H1_eq3().subs({THETA0: t0, L1: 0.70}).evalf(), dtype=float) @ (
        Rz(t1) @ trans(0.30, 0, 0))
    return Exercise("3.3", "the pen at θ0 = 30°, θ1 = 45°", lambda a: check_value(
        a, _robot1_position(t0, t1), name="your pen position", components=("x", "y", "z"), unit="m",
        mistakes=[(_robot1_position(30, 45), "those are the values for θ0 = 30 rad and θ1 = 45 rad: "
                                            "convert the angles, deg(30) and deg(45)."),
                  (_robot1_position(t1, t0), "you swapped θ0 and θ1: θ0 = 30° is the base joint."),
                  (eq3[:3, 3], "that is the position with ⁰H₁ of eq. (3) as printed (erratum 004-1): "
                               "use ⁰H₁ = Rz(θ0)·Tr(0, l1, 0).")]),
        ["robot.fk(deg([30, 45])) gives the whole pose; its last column is the position.",
         "By the formula: x = l2·cos(θ0+θ1) − l1·sin θ0, y = l2·sin(θ0+θ1) + l1·cos θ0."])


def _ex_3_4():
    l, x, y = 0.70, -0.6, 0.6
    reach = math.hypot(x, y)
    right = [math.radians(45), reach - l]
    return Exercise("3.4", "reach (−0.6, 0.6) with the second robot", lambda a: check_value(
        a, right, name="your (θ, d)", components=("θ", "d"), unit=("rad", "m"),
        mistakes=[([math.radians(45), reach], "d = 0.8485 is the whole distance l + d from the base: the "
                                              "fixed link l = 0.70 is not part of the joint value d."),
                  ([45, reach - l], "θ = 45 is in degrees: the API takes radians, deg(45)."),
                  ([-math.radians(45), reach - l], "with θ = −45° the pen goes to (+0.6, 0.6): x = −(l+d)·sin θ, "
                                                   "so x < 0 needs θ > 0 (counter-clockwise).")]),
        ["The pen is at (−(l+d)·sin θ, (l+d)·cos θ): its distance from the base is l + d.",
         "Distance √(0.6² + 0.6²) = l + d, and the direction gives θ."])


def _pr_fk(q1, q2, l1=1.0, l2=0.5):
    return np.array([q1 + l1 + l2 * math.cos(q2), l2 * math.sin(q2)])


def _ex_4_1():
    q1, q2 = 0.5, math.radians(60)
    return Exercise("4.1", "forward kinematics of the P-R mechanism", lambda a: check_value(
        a, _pr_fk(q1, q2), name="your (x, y)", components=("x", "y"), mistakes=[
            (_pr_fk(q1, 60), "that is q2 = 60 rad: the angle must be in radians, deg(60)."),
            (_pr_fk(q1, q2) - [1.0, 0], "x is missing l1 = 1: the arm's joint sits at q1 + l1 along x."),
            ([q1 + 1.0 + 0.5 * math.sin(q2), 0.5 * math.cos(q2)], "cos and sin are swapped: q2 is measured "
                                                                    "from the x axis, so x gets l2·cos q2.")]),
        ["x = q1 + l1 + l2·cos q2, y = l2·sin q2, with l1 = 1, l2 = 0.5."])


def _ex_4_2():
    x, y, l1, l2 = 1.8, 0.3, 1.0, 0.5
    root = l2 * math.sqrt(1 - (y / l2) ** 2)
    q2a = math.asin(y / l2)
    right = [[x - l1 - root, q2a], [x - l1 + root, math.pi - q2a]]
    return Exercise("4.2", "both inverse-kinematics solutions", lambda a: check_solutions(
        a, right, name="your list of solutions", components=("q1", "q2"), unit=("", "rad"), mistakes=[
            ([x - l1 - root, math.pi - q2a], "(q1A, q2B) is not a solution: q2B needs its own slider value "
                                             "q1B = x − l1 + l2·√(1 − (y/l2)²). The slide gives only q1A "
                                             "(erratum 003-1)."),
            ([x - l1 - root, math.degrees(q2a)], "q2 = 36.87 is in degrees: give radians."),
            ([x - l1 + root, math.degrees(math.pi - q2a)], "q2 = 143.13 is in degrees: give radians.")]),
        ["q2A = arcsin(y/l2) and q2B = π − arcsin(y/l2).",
         "Then q1 = x − l1 − l2·cos q2 for each branch: cos q2B = −cos q2A."])


def _ex_4_3():
    return Exercise("4.3", "how many solutions", lambda a: check_value(
        a, [1, 0, 2], name="your list of counts", components=("(1.5, −0.5)", "(1.5, 0.7)", "(2.5, 0.1)"),
        tol=1e-9), ["|y| < l2: two; |y| = l2: one (the branches meet); |y| > l2: none. Here l2 = 0.5."])


def _rrr_position(q1, q2, q3, l1=1.0, l2=2.0, l3=1.5):
    r = l2 * math.cos(q2) + l3 * math.cos(q2 + q3)
    return np.array([l1 + l2 * math.sin(q2) + l3 * math.sin(q2 + q3), r * math.cos(q1), r * math.sin(q1)])


def _ex_4_4():
    q = [math.radians(v) for v in (90, 30, 60)]
    return Exercise("4.4", "the 3R example by the geometric method", lambda a: check_value(
        a, _rrr_position(*q), name="your (x, y, z)", components=("x", "y", "z"), mistakes=[
            (_rrr_position(90, 30, 60), "those are the formulas at 90, 30, 60 radians: convert, deg(...)."),
            (_rrr_position(q[0], q[1], q[1] + q[2]), "q3 is relative to link 2: the angle of link 3 is "
                                                      "q2 + q3 (use cos(q2 + q3), not cos(q2 + q2 + q3)).")]),
        ["r = l2·cos q2 + l3·cos(q2 + q3), then y = r·cos q1, z = r·sin q1.",
         "With q3 = 60° and q2 = 30°, link 3 points along x: cos 90° = 0."])


_COURSE = {f.__name__[4:].replace("_", "."): f for f in (
    _ex_1_1, _ex_1_2, _ex_1_3, _ex_2_1, _ex_2_2, _ex_2_3, _ex_2_4,
    _ex_3_1, _ex_3_2, _ex_3_3, _ex_3_4, _ex_4_1, _ex_4_2, _ex_4_3, _ex_4_4)}


def available() -> list:
    """The keys of the course's exercises, e.g. ['1.1', '1.2', …]."""
    return list(_COURSE)


def exercise(key: str) -> Exercise:
    """A fresh :class:`Exercise` of the course by its key, e.g. ``exercise("3.1")``."""
    if key not in _COURSE:
        raise KeyError(f"no exercise {key!r}; there are {', '.join(_COURSE)}.")
    return _COURSE[key]()
