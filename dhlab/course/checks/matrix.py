"""Checking a matrix answer: :func:`check_matrix`, and what it says about each kind of slip.

It compares from the whole matrix down to single entries: a transposed rotation, the
inverse, the wrong sign of the translation, a last row that is not 0 0 0 1, a
rotation block that is not a rotation, cos and sin swapped, one symbol typed for
another, degrees inside ``sp.cos``. Symbolic answers are compared by evaluating both
sides at random values of their symbols.

Rounding is never blamed: a numeric answer right to the decimals the student typed
is accepted (with a note when fewer than 3 were typed), and a rotation block is
"not a rotation" only when no rotation lies within that rounding.

>>> import math
>>> from dhlab.transforms import Rz, trans
>>> T = Rz(math.radians(30)) @ trans(2, 0, 0)
>>> check_matrix([[0.87, -0.5, 0, 1.73], [0.5, 0.87, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]], T, name="T")
✓ correct: T is right.
  • right to the 2 decimals you typed. Keep 3 or more when a result is used again:
    rounding errors grow when matrices are multiplied.
"""
from __future__ import annotations

import itertools
import math

import numpy as np
import sympy as sp

from ...i18n import N_, _
from ...validation import as_choice
from . import options as teacher
from .feedback import Feedback, correct, unanswered, wrong
from .judge import judge
from .reading import Refused, Sampler, canon, close, is_unanswered, rounding_slack, to_sympy_matrix, typed_decimals

__all__ = ["check_matrix", "TRANSPOSED_ROTATION", "num"]

MAX_ITEMS = 4            # entries listed one by one; beyond that, "… and k more"
TRANSPOSED_ROTATION = N_("your rotation block is the transpose of the right one: that is the rotation "
                         "the other way (by −θ instead of θ).")


def num(v: float) -> str:
    v = float(v) + 0.0                      # -0.0 -> 0.0
    return f"{v:.6g}"


def _shown(names) -> str:
    return ", ".join(sorted(names))


def _trig_in_degrees(M) -> list:
    """Entries like cos(90): sympy's trig functions take radians."""
    found = []
    for f in sorted(M.atoms(sp.sin, sp.cos, sp.tan), key=str):
        arg = f.args[0]
        if not arg.free_symbols and arg.is_real and abs(float(arg)) > 2 * math.pi + 1e-9:
            found.append(_("{f} takes radians: {arg} rad is more than a full turn. If you meant {arg}°, write "
                           "sp.pi*{arg}/180 (or use dhlab.deg2rad).").format(f=f, arg=sp.sstr(arg)))
    return found


def _symbol_problems(student: sp.Matrix, expected_names, allowed, name) -> list:
    """Symbols the student used that the exercise does not have."""
    unknown = sorted({str(s) for s in student.free_symbols if canon(s) not in allowed})
    if not unknown:
        return []
    message = (_("{name} uses {unknown}, which is not a symbol of this exercise: use {use}.") if len(unknown) == 1
               else _("{name} uses {unknown}, which are not symbols of this exercise: use {use}."))
    return [message.format(name=name, unknown=", ".join(unknown), use=_shown(expected_names) or _("numbers only"))]


def _where(i, j, shape, index_style) -> str:
    text = _("row {i}, column {j}").format(i=i + 1, j=j + 1)
    if index_style == "cpp":
        text += f" (aij[{i}][{j}])"
    elif index_style == "python":
        text += f" ([{i}, {j}])"
    if shape == (4, 4):
        if i < 3 and j < 3:
            text += _(", rotation block")
        elif i < 3:
            text += _(", translation column ({axis})").format(axis="xyz"[i])
        else:
            text += _(", last row")
    return text


def _entry_text(value) -> str:
    """One entry of the student's matrix as the feedback quotes it (never raises)."""
    if isinstance(value, sp.Basic) and value.free_symbols:
        return sp.sstr(value)
    try:
        z = complex(sp.N(value)) if isinstance(value, sp.Basic) else complex(value)
    except (TypeError, ValueError, OverflowError):
        return str(value)
    # a vanishing imaginary part (1e-210j) is rounding, not an answer: quote the real number
    if abs(z.imag) <= 1e-12 * max(1.0, abs(z.real)):
        return num(z.real)
    return sp.sstr(value) if isinstance(value, sp.Basic) else str(value)


def _shape_problem(got, expected, name):
    if got == expected:
        return ""
    if expected == (4, 4) and got == (3, 3):
        return _("{name} is 3×3, but a homogeneous transformation matrix is 4×4: [[R, p], [0, 0, 0, 1]], the "
                 "3×3 rotation R, the position p, and the row 0 0 0 1.").format(name=name)
    if expected == (3, 3) and got == (4, 4):
        return _("{name} is 4×4: here only the 3×3 rotation block is asked for.").format(name=name)
    return _("{name} has shape {rows}×{cols}; it must be {right_rows}×{right_cols}.").format(
        name=name, rows=got[0], cols=got[1], right_rows=expected[0], right_cols=expected[1])


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
    name, tol = teacher.name(name), teacher.tolerance(tol)
    expected = teacher.expected_matrix(expected)
    symbols, mistakes = teacher.symbol_names(symbols), teacher.mistakes(mistakes)
    index_style = as_choice(index_style, ("python", "cpp", "math"), "index_style")
    if is_unanswered(student):
        return unanswered(name)
    try:
        got = to_sympy_matrix(student, name)
    except Refused as refusal:
        return wrong(name, [str(refusal)])
    shape_problem = _shape_problem(got.shape, expected.shape, name)
    if shape_problem:
        return wrong(name, [shape_problem])

    expected_names = {canon(s) for s in expected.free_symbols}
    allowed = expected_names | {canon(s) for s in symbols}
    problems = _trig_in_degrees(got)
    if expected_names and not got.free_symbols:
        problems.append(_("{name} has only numbers, but the answer is symbolic: write it with the symbols "
                          "{symbols} (for every value of them).").format(
                              name=name, symbols=_shown(str(s) for s in expected.free_symbols)))
    elif got.free_symbols and not expected_names:
        problems.append(_("{name} still has the symbols {symbols}: the answer is numeric, substitute the "
                          "numbers.").format(name=name, symbols=_shown(str(s) for s in got.free_symbols)))
    else:
        problems += _symbol_problems(got, {str(s) for s in expected.free_symbols}, allowed, name)
    if problems:
        return wrong(name, problems)

    decimals = None if got.free_symbols else typed_decimals(student)
    slack = rounding_slack(decimals)
    known = [(teacher.expected_matrix(w, _("a known mistake")), _(message)) for w, message in mistakes]
    names = allowed | {canon(s) for s in got.free_symbols}
    sampler = Sampler(names.union(*({canon(s) for s in W.free_symbols} for W, _message in known)))
    E, S = sampler.evaluate(expected), sampler.evaluate(got)
    verdict = judge(name, lambda slack: close(S, E, tol, slack), decimals, [
        (lambda slack, W=W: W.shape == got.shape and close(S, sampler.evaluate(W), tol, slack), message)
        for W, message in known])
    if verdict is not None:
        return verdict
    items = _matrix_diagnosis(got, expected, S, E, sampler, tol, slack, index_style)
    used = {canon(g) for g in got.free_symbols}
    missing = sorted(str(s) for s in expected.free_symbols if canon(s) not in used)
    if missing and got.free_symbols:
        substituted = any(not float(f).is_integer() for f in got.atoms(sp.Float))
        items.insert(0, (_("{name} does not use {missing}, but the right matrix does: keep the parameters as "
                           "symbols (the answer must hold for every value), do not substitute numbers.")
                         if substituted else _("{name} does not use {missing}, but the right matrix does.")).format(
                             name=name, missing=", ".join(missing)))
    return wrong(name, items)


def _matrix_diagnosis(got, expected, S, E, sampler, tol, slack, index_style) -> list:
    """What is wrong, from the whole matrix down to single entries."""
    items, explained = [], np.zeros(E.shape[1:], dtype=bool)
    rows, cols = E.shape[1:]
    homogeneous = (rows, cols) == (4, 4) and close(E[:, 3], np.broadcast_to([0, 0, 0, 1], E[:, 3].shape), 1e-9)
    if homogeneous and not close(S[:, :3, :3], E[:, :3, :3], tol, slack):
        inverse = np.array([np.linalg.inv(e) for e in E])
        if close(S, inverse, tol, slack):
            if close(E[:, :3, 3], np.zeros_like(E[:, :3, 3]), 1e-12):
                return [_(TRANSPOSED_ROTATION)]
            return [_("this is the inverse of the right matrix: it maps the other way round "
                      "(the two frames' roles are swapped).")]
    if rows == cols and close(S, np.swapaxes(E, 1, 2), tol, slack):
        if close(np.einsum("kji,kjl->kil", E, E), np.broadcast_to(np.eye(rows), E.shape), 1e-9):
            return [_(TRANSPOSED_ROTATION)]
        return [_("you wrote the rows as columns: the whole matrix is transposed.")]
    if homogeneous:
        if not close(S[:, 3], E[:, 3], tol, slack):
            items.append(_("the last row must be 0 0 0 1; yours is {row}.").format(
                row=" ".join(_entry_text(v) for v in got[3, :])))
            explained[3] = True
        RS, RE = S[:, :3, :3], E[:, :3, :3]
        if not close(RS, RE, tol, slack) and close(RS, np.swapaxes(RE, 1, 2), tol, slack):
            items.append(_(TRANSPOSED_ROTATION))
            explained[:3, :3] = True
        pS, pE = S[:, :3, 3], E[:, :3, 3]
        every_component_used = bool(np.all(np.abs(pE).max(axis=0) > 1e-9))
        if every_component_used and not close(pS, pE, tol, slack) and close(pS, -pE, tol, slack):
            items.append(_("the whole translation column has the wrong sign."))
            explained[:3, 3] = True
    if rows == cols == 3 or homogeneous:
        items += _rotation_problems(got, S, slack)
    bad = [(i, j) for i in range(rows) for j in range(cols)
           if not explained[i, j] and not close(S[:, i, j], E[:, i, j], tol, slack)]
    for i, j in bad[:MAX_ITEMS]:
        items.append(f"{_where(i, j, (rows, cols), index_style)}: "
                     + _entry_problem(got[i, j], expected[i, j], S[:, i, j], E[:, i, j], sampler, tol, slack))
    if len(bad) > MAX_ITEMS:
        items.append(_("… and {k} more entries are not right.").format(k=len(bad) - MAX_ITEMS))
    return items or [_("it does not match the right matrix.")]


def _distance_to_rotations(R) -> float:
    """The largest entry-wise distance from R (one 3×3 sample) to the nearest proper rotation."""
    U, _singular, Vt = np.linalg.svd(R)
    D = np.diag([1.0, 1.0, np.sign(np.linalg.det(U @ Vt)) or 1.0])
    return float(np.abs(R - U @ D @ Vt).max())


def _rotation_problems(got, S, slack) -> list:
    """A rotation block that is not a rotation (det ≠ 1 or not orthonormal) beyond the rounding typed."""
    R = S[:, :3, :3]
    if not np.all(np.isfinite(R)):
        return []
    if max(_distance_to_rotations(r) for r in R) <= slack + 1e-6:
        return []
    dets = np.linalg.det(R)
    if got.free_symbols:
        det = sp.trigsimp(sp.simplify(got[:3, :3].det()))
        what = f"det R = {sp.sstr(det)}"
    else:
        what = f"det R = {num(dets[0])}"
    return [_("your rotation block is not a rotation: {what}, but a rotation has det R = +1 and orthonormal "
              "columns (RᵀR = I).").format(what=what)
            + (_(" A negative determinant is a mirror image.") if np.all(dets < -1e-9) else "")]


def _entry_problem(student, expected, s, e, sampler, tol, slack) -> str:
    mine = _entry_text(student)
    if close(e, np.zeros_like(e), 1e-12):
        return _("you have {mine}; this entry is 0.").format(mine=mine)
    if close(s, -e, tol, slack):
        return _("you have {mine}: the sign is wrong.").format(mine=mine)
    if isinstance(student, sp.Basic) and student.free_symbols:
        swapped = student.replace(lambda x: isinstance(x, (sp.sin, sp.cos)),
                                  lambda x: (sp.cos if isinstance(x, sp.sin) else sp.sin)(x.args[0]))
        value = sampler.evaluate(sp.Matrix([swapped]))[:, 0, 0]
        if close(value, e, tol):
            return _("you have {mine}: cos and sin are swapped.").format(mine=mine)
        if close(value, -e, tol):
            return _("you have {mine}: cos and sin are swapped, and the sign is wrong.").format(mine=mine)
        slip = _wrong_symbol(student, expected, e, sampler, tol)
        if slip:
            return f"{_('you have {mine}').format(mine=mine)}: {slip}"
    return _("you have {mine}, which is not right.").format(mine=mine)


def _wrong_symbol(student, expected, e, sampler, tol) -> str:
    """One symbol typed for another in one term (l1 for l2, θ1 for θ0), if that explains the entry."""
    wanted = sorted({canon(x) for x in getattr(expected, "free_symbols", ())})
    terms = sp.Add.make_args(sp.expand(student))
    if len(terms) > 12:                    # a long expression: too many substitutions to try
        return ""
    for k, term in enumerate(terms):
        for mine, other in itertools.product(sorted(term.free_symbols, key=str), wanted):
            if canon(mine) == other:
                continue
            fixed = sp.Add(*terms[:k], term.xreplace({mine: sp.Symbol(other)}), *terms[k + 1:])
            if close(sampler.evaluate(sp.Matrix([fixed]))[:, 0, 0], e, tol):
                message = (_("{mine} is the wrong symbol: it should be {other}.") if len(terms) == 1 else
                           _("{mine} is the wrong symbol in the term {term}: it should be {other}."))
                return message.format(mine=mine, other=other, term=sp.sstr(term))
    return ""


# --- a function the student wrote -----------------------------------------------------------------------
def check_function(student_fn, reference, cases, *, name: str = "your function", check=check_matrix,
                   describe=None, mistakes=(), **options) -> Feedback:
    """Call the student's function on every case (a tuple of arguments) and compare
    with ``reference``; report the first case that fails, with ``check``'s details.

    ``mistakes``: ``(wrong_function, message)`` pairs: a student's function giving the
    same results as a known wrong one on every case gets that message. ``options``
    go to ``check`` (e.g. ``index_style='cpp'``).
    """
    name, reference, check = teacher.name(name), teacher.function(reference, "reference"), \
        teacher.function(check, "check")
    cases, mistakes = teacher.cases(cases), teacher.mistakes(mistakes)
    for wrong_fn, _message in mistakes:
        teacher.function(wrong_fn, _("each known mistake of check_function"))
    if describe is not None:
        teacher.function(describe, "describe")
    if is_unanswered(student_fn):
        return unanswered(name)
    if not callable(student_fn):
        return wrong(name, [_("{name} must be a function (def …), got {type}.").format(
            name=name, type=type(student_fn).__name__)])
    describe = describe or (lambda args: ", ".join(map(repr, args)))
    results = []
    for args in cases:
        try:
            results.append(student_fn(*args))
        except Exception as exc:                     # the student's code: any error is feedback
            return wrong(name, [_("calling it with {args} raised {error}: {message}").format(
                args=describe(args), error=type(exc).__name__, message=exc)])
    for wrong_fn, message in mistakes:
        if all(check(r, wrong_fn(*args), **options).ok for r, args in zip(results, cases)):
            return wrong(name, [_(message)])
    failures, notes = [], set()
    for result, args in zip(results, cases):
        feedback = check(result, reference(*args), name=_("the result"), **options)
        if not feedback.ok:
            failures.append((args, feedback))
        notes.update(feedback.items if feedback.ok else ())
    if not failures:
        return correct(name, next(iter(sorted(notes)), ""))
    # the case that shows the most problems tells the most (at θ = 0 a wrong sin is invisible)
    args, feedback = max(failures, key=lambda f: len(f[1].items))
    return wrong(name, [_("for {args}:").format(args=describe(args))] + feedback.items)
