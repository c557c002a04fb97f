"""Symbolic matrices that fit the notebook column.

A product of six DH matrices printed by sympy is about 2000 px wide; JupyterLab's
column at a 1400 px window is about 950 px, so the right of it is cut off.
:func:`show_matrix` writes the matrix the way the slides do — ``C1 = cos q1``,
``S23 = sin(q2 + q3)`` (:func:`dhlab.compact`) — and, when it is still too wide,
splits it: by groups of columns first, then each entry on its own line, a long
entry broken between its terms. The full expression stays one attribute away
(``.full``; ``.compact`` is the matrix of C/S names).

The width is *estimated* from the LaTeX: each glyph is given its width in em
(a letter 0.5 em, a capital 0.7, a binary ``+`` with its spaces 1.0, …),
sub/superscripts count 0.7 of their size, a matrix is the sum of its widest
column entries plus 1 em between columns, and :data:`PX_PER_EM` turns em into
pixels. ``PX_PER_EM`` was measured on JupyterLab 4 (MathJax 3, Chromium, 1400 px
window) from four outputs whose rendered widths were measured in the browser
(1172, 2025, 1082 and 1338 px; tests/views/test_matrices.py keeps the estimate
between 3 % narrower and 12 % wider than each; it errs wide on purpose).

>>> import sympy as sp
>>> q1, q2 = sp.symbols("q1 q2")
>>> M = sp.Matrix([[sp.cos(q1 + q2), -sp.sin(q1 + q2)], [sp.sin(q1 + q2), sp.cos(q1 + q2)]])
>>> shown = show_matrix(M, (q1, q2), name="R")
>>> shown.compact
Matrix([
[C12, -S12],
[S12,  C12]])
>>> shown.legend
'C12 = cos(q1 + q2), S12 = sin(q1 + q2)'
>>> len(shown.pieces), shown.width_px < 900
(1, True)
"""
from __future__ import annotations

import re

import sympy as sp

from ..errors import DHLabError
from ..i18n import _
from ..symbolic import check_finite_entries, compact, legend
from ..validation import as_number, as_text

__all__ = ["show_matrix", "ShownMatrix", "latex_width_px", "PX_PER_EM", "COLUMN_PX"]

PX_PER_EM = 20.3      # rendered px per em of the estimate: the largest ratio measured, so the estimate errs wide
COLUMN_PX = 950       # JupyterLab's output column at a 1400 px window

# widths in em of what MathJax draws (Computer Modern, text size)
_BINARY = 1.0         # "+" or "-" with its medium spaces
_RELATION = 1.34      # "=" with its thick spaces
_SCRIPT = 0.7         # sub/superscripts are drawn at 70 %
_COLSEP = 1.0         # space between the columns of a matrix
_BRACKETS = 1.0       # both brackets of a matrix with their padding
_WORDS = {"cos", "sin", "tan", "atan", "log", "exp", "sqrt", "operatorname"}


def _group(s: str, i: int):
    """The text of the brace group (or single token) starting at ``s[i]``, and the index after it."""
    while i < len(s) and s[i] == " ":
        i += 1
    if i >= len(s):
        return "", i
    if s[i] != "{":
        m = re.match(r"\\[A-Za-z]+|\\.|.", s[i:])
        return m.group(0), i + len(m.group(0))
    depth = 0
    for j in range(i, len(s)):
        depth += {"{": 1, "}": -1}.get(s[j], 0)
        if depth == 0:
            return s[i + 1:j], j + 1
    return s[i + 1:], len(s)


def _split_top(body: str, sep: str) -> list:
    """``body`` split at ``sep`` where it is not inside braces or a nested environment."""
    parts, depth, start, i = [], 0, 0, 0
    while i < len(body):
        if body.startswith(r"\begin", i) or body[i] == "{":
            depth += 1
        elif body.startswith(r"\end", i) or body[i] == "}":
            depth -= 1
        elif depth == 0 and body.startswith(sep, i):
            parts.append(body[start:i])
            start = i + len(sep)
            i = start
            continue
        i += 2 if body[i] == "\\" else 1        # a backslash escapes the next character (\{, \\)
    parts.append(body[start:])
    return parts


def _matrix_em(body: str) -> float:
    """Width of a ``matrix`` environment's body: widest entry of each column, plus spacing."""
    rows = [[_linear_em(cell) for cell in _split_top(row, "&")] for row in _split_top(body, r"\\") if row.strip()]
    if not rows:
        return _BRACKETS
    ncols = max(len(r) for r in rows)
    widths = [max((r[c] for r in rows if c < len(r)), default=0.0) for c in range(ncols)]
    return _BRACKETS + sum(widths) + _COLSEP * (ncols - 1)


def _linear_em(s: str) -> float:
    """Width in em of a LaTeX formula (matrices inside it included)."""
    w, i = 0.0, 0
    while i < len(s):
        c = s[i]
        if c == "\\":
            m = re.match(r"\\([A-Za-z]+|.)", s[i:])
            cmd, i = m.group(1), i + len(m.group(0))
            if cmd == "begin":
                env, i = _group(s, i)
                end = s.find(r"\end{" + env + "}", i)
                end = len(s) if end < 0 else end
                body = s[i:end]
                if "matrix" in env:
                    w += _matrix_em(body)
                else:                    # aligned, gathered: lines one under the other, & aligned
                    columns = len(_split_top(_split_top(body, r"\\")[0], "&"))     # the first line's, between its &s
                    w += _matrix_em(body) - _BRACKETS - _COLSEP * columns + _COLSEP
                i = end + len(r"\end{" + env + "}")
            elif cmd == "frac":
                num, i = _group(s, i)
                den, i = _group(s, i)
                w += 0.8 * max(_linear_em(num), _linear_em(den)) + 0.2
            elif cmd in ("left", "right"):
                delim, i = _group(s, i)
                w += 0 if delim == "." else 0.4
            elif cmd in ("text", "mathrm", "textrm"):
                txt, i = _group(s, i)
                w += 0.5 * len(txt)
            elif cmd in ("mathbf", "boldsymbol", "mathit", "operatorname"):
                txt, i = _group(s, i)
                w += _linear_em(txt) * (1.1 if cmd != "operatorname" else 1.0)
            elif cmd in _WORDS:
                w += 0.42 * len(cmd) + 0.17
            elif cmd in ("displaystyle", "textstyle", "!", "limits"):
                pass
            elif cmd == ",":
                w += 0.17
            elif cmd in (";", ":", " "):
                w += 0.28
            elif cmd == "quad":
                w += 1.0
            elif cmd == "qquad":
                w += 2.0
            elif cmd in ("cdot", "times", "pm"):
                w += _BINARY
            elif cmd in ("leq", "geq", "neq", "approx", "equiv", "to", "rightarrow", "mapsto"):
                w += _RELATION
            elif cmd == "circ":
                w += 0.5
            elif cmd in ("{", "}", "|"):
                w += 0.5
            elif len(cmd) == 1:          # \\, \& …
                w += 0.0 if cmd == "\\" else 0.5
            else:                        # greek letters and other symbols
                w += 0.6
        elif c in "_^":
            sub, i = _group(s, i + 1)
            w += _SCRIPT * _linear_em(sub)
        elif c == "{":
            inner, i = _group(s, i)
            w += _linear_em(inner)
        elif c in "+-":
            w += _BINARY
            i += 1
        elif c in "=<>":
            w += _RELATION
            i += 1
        elif c in ",;":
            w += 0.45
            i += 1
        elif c in "()[]|/":
            w += 0.39
            i += 1
        elif c in " &}$":
            i += 1
        elif c.isupper():
            w += 0.72
            i += 1
        else:
            w += 0.52
            i += 1
    return w


def latex_width_px(latex: str) -> float:
    """Estimated rendered width in px of a LaTeX formula in JupyterLab's MathJax.

    >>> latex_width_px("x + y") < latex_width_px("x + y + z")
    True
    """
    if not isinstance(latex, str):
        raise DHLabError(_("latex_width_px: expected a LaTeX string, got {type}.").format(type=type(latex).__name__))
    return _linear_em(latex) * PX_PER_EM


def _symbols_of(symbols, M) -> tuple:
    """The joint symbols: given, taken from a robot (``.q_symbols``), or those inside cos/sin."""
    if symbols is None:
        found = set()
        for e in M:
            for f in sp.sympify(e).atoms(sp.cos, sp.sin):
                found |= f.free_symbols
        return tuple(sorted(found, key=lambda s: (re.sub(r"\d+$", "", s.name),
                                                  int(re.sub(r"^\D*", "", s.name) or 0))))
    if hasattr(symbols, "q_symbols"):
        return tuple(symbols.q_symbols)
    if isinstance(symbols, sp.Symbol):
        return (symbols,)
    try:
        symbols = tuple(symbols)
    except TypeError:
        raise DHLabError(_("show_matrix: symbols must be the joint symbols (e.g. robot.q_symbols) or a robot, got "
                           "{type}.").format(type=type(symbols).__name__)) from None
    if not all(isinstance(s, sp.Symbol) for s in symbols):
        raise DHLabError(_("show_matrix: symbols must all be sympy Symbols, e.g. sympy.symbols('q1:7')."))
    return symbols


def _as_matrix(M) -> sp.Matrix:
    if isinstance(M, sp.MatrixBase):
        M = sp.Matrix(M)
    elif isinstance(M, (sp.Expr, int, float)) and not isinstance(M, bool):
        M = sp.Matrix([[sp.sympify(M)]])          # one expression: shown without brackets
    else:
        try:
            M = sp.Matrix(M)
        except Exception:      # sympy raises several kinds for things that are not matrices
            raise DHLabError(_("show_matrix: expected a sympy Matrix (or a nested list of expressions), got "
                               "{type}.").format(type=type(M).__name__)) from None
    check_finite_entries(M, "show_matrix")     # no nan, zoo or oo, the entry named
    return M


class ShownMatrix:
    """A matrix laid out to fit the column; displays itself in Jupyter.

    Attributes: ``full`` (the matrix as given), ``compact`` (with C/S names),
    ``legend`` (what the names mean), ``pieces`` (the LaTeX blocks shown, each
    estimated narrower than ``max_width_px``), ``width_px`` (the estimated width
    of the compact matrix in one piece).
    """

    def __init__(self, M, symbols=None, *, name=None, max_width_px=900):
        self.scalar = isinstance(M, (sp.Expr, int, float)) and not isinstance(M, bool)
        self.full = _as_matrix(M)
        self.max_width_px = as_number(max_width_px, "max_width_px")
        if not self.max_width_px > 100:
            raise DHLabError(_("show_matrix: max_width_px must be a number of pixels above 100, got {value!r}.").format(
                value=max_width_px))
        self.name = None if name is None else as_text(name, "name")
        q = _symbols_of(symbols, self.full)
        self.compact = compact(self.full, q) if q else self.full
        self.legend = legend(self.full, q) if q else ""
        self._head = (name + " = ") if name else ""
        if self.scalar:
            self.full, self.compact = self.full[0, 0], self.compact[0, 0]
            one = self._head + sp.latex(self.compact)
            self.width_px = latex_width_px(one)
            self.pieces = [one] if self._fits(one) else [self._broken(self._head, self.compact)]
            return
        one = self._head + sp.latex(self.compact)
        self.width_px = latex_width_px(one)
        self.pieces = [one] if self.width_px <= self.max_width_px else self._split()

    # --- splitting ---------------------------------------------------------------
    def _fits(self, latex: str) -> bool:
        return latex_width_px(latex) <= self.max_width_px

    def _label(self, what: str) -> str:
        base = self.name if self.name else "M"
        return rf"{base}\ \text{{{what}}} = "

    def _split(self) -> list:
        """Groups of whole columns that fit; a column too wide alone is shown entry by entry."""
        M = self.compact
        groups, current = [], []
        for c in range(M.cols):
            if current and self._fits(self._column_piece(current + [c])):
                current = current + [c]
            else:
                if current:
                    groups.append(current)
                current = [c]
        groups.append(current)
        pieces = []
        for g in groups:
            piece = self._column_piece(g)
            pieces += [piece] if self._fits(piece) else self._entries(g[0])
        return pieces

    def _column_piece(self, cols) -> str:
        one = [c + 1 for c in cols]
        what = (_("column {k}").format(k=one[0]) if len(one) == 1 else
                _("columns {first}–{last}").format(first=one[0], last=one[-1]))
        if len(cols) == self.compact.cols:
            return self._head + sp.latex(self.compact)
        return self._label(what) + sp.latex(self.compact[:, cols])

    def _entries(self, c: int) -> list:
        """The entries of column ``c`` one per line (a long one broken between its terms);
        the 0 0 0 1 of a homogeneous matrix's last row is left out."""
        M, base = self.compact, (self.name if self.name else "M")
        rows = range(M.rows)
        if M.shape == (4, 4) and list(M[3, :]) == [0, 0, 0, 1]:
            rows = range(3)
        pieces = []
        for r in rows:
            index = f"{r + 1}" if M.cols == 1 else f"{r + 1}{c + 1}"
            pieces.append(self._broken(rf"\left[{base}\right]_{{{index}}} = ", M[r, c]))
        return pieces

    def _broken(self, head: str, e) -> str:
        """``head + e`` on several lines, cut between terms, when it is too wide for one."""
        if self._fits(head + sp.latex(e)):
            return head + sp.latex(e)
        terms = e.as_ordered_terms() if isinstance(e, sp.Add) else [e]
        lines, current = [], []
        for t in terms:
            trial = current + [t]
            line = (head if not lines else head + r"\quad ") + _sum_latex(trial, continued=bool(lines))
            if current and not self._fits(line):
                lines.append(current)
                current = [t]
            else:
                current = trial
        lines.append(current)
        first = head.rstrip(" =") + " &= " if head else "& "
        body = [(first if k == 0 else r"&\quad ") + _sum_latex(ts, continued=k > 0)
                for k, ts in enumerate(lines)]
        return r"\begin{aligned}" + r"\\ ".join(body) + r"\end{aligned}"

    # --- display -------------------------------------------------------------------
    def _repr_markdown_(self) -> str:
        blocks = [f"$$\n{p}\n$$" for p in self.pieces]
        if self.legend:
            blocks.append(f"<small>{self.legend}</small>")
        if len(self.pieces) > 1:
            blocks.append(_("<small>(split to fit the page; the whole matrix: <code>.full</code>, "
                            "in C/S names: <code>.compact</code>)</small>"))
        return "\n\n".join(blocks)

    def _repr_latex_(self) -> str:
        return r"$\displaystyle \begin{gathered}" + r"\\ ".join(self.pieces) + r"\end{gathered}$"

    def __repr__(self) -> str:
        """For a terminal: the matrix drawn when it fits 100 characters, else one entry a line."""
        head = f"{self.name} = " if self.name else ""
        text = head + sp.pretty(self.compact, use_unicode=True, wrap_line=False)
        if self.scalar:
            text = head + sp.sstr(self.compact)
        elif max(len(line) for line in text.splitlines()) > 100:
            base = self.name or "M"
            text = "\n".join(f"{base}[{r + 1},{c + 1}] = {sp.sstr(self.compact[r, c])}"
                              for c in range(self.compact.cols) for r in range(self.compact.rows))
        return text + (f"\n{self.legend}" if self.legend else "")


def _sum_latex(terms, continued: bool = False) -> str:
    """LaTeX of a sum of terms in the given order; a continued line starts with its sign."""
    text = ""
    for k, t in enumerate(terms):
        neg = t.could_extract_minus_sign()
        body = sp.latex(-t if neg else t)
        if k == 0 and not continued:
            text = ("- " if neg else "") + body
        else:
            text += (" - " if neg else " + ") + body
    return text


def show_matrix(M, symbols=None, *, name=None, max_width_px=900) -> ShownMatrix:
    """``M`` in the slides' C/S notation, split to fit the notebook column.

    ``symbols`` are the joint variables (``robot.q_symbols``, or the robot
    itself); by default, every symbol found inside a cos or sin. ``name`` is
    LaTeX for the left-hand side, e.g. ``r"{}^0T_6"``. Display the result (last
    line of a cell, or ``display(...)``); ``.full`` is the matrix as given.

    >>> import sympy as sp
    >>> q = sp.symbols("q1:7")
    >>> long = sp.Matrix([[sum(sp.cos(qi) * sp.sin(qj) for qi in q for qj in q)]])
    >>> shown = show_matrix(long, q, name="t")
    >>> len(shown.pieces) == 1 and shown.width_px > 900     # one entry, broken over lines
    True
    >>> latex_width_px(shown.pieces[0]) <= 900
    True
    """
    return ShownMatrix(M, symbols, name=name, max_width_px=max_width_px)
