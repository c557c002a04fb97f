"""show_matrix: symbolic matrices in C/S notation, split to fit the notebook column."""
import math

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

import dhlab
from dhlab.errors import DHLabError
from dhlab.views.matrices import COLUMN_PX, latex_width_px, show_matrix

# Outputs of the stored notebooks whose rendered width was measured in JupyterLab 4 (Chromium,
# 1400 px window): (px, the LaTeX as stored).
MEASURED = {
    '03_H02_product': (1172, '$\\displaystyle {}^0H_2 = {}^0H_1\\,{}^1H_2 = \\left[\\begin{matrix}- '
                             '\\sin{\\left(\\theta_{0} \\right)} \\sin{\\left(\\theta_{1} \\right)} + '
                             '\\cos{\\left(\\theta_{0} \\right)} \\cos{\\left(\\theta_{1} \\right)} & - '
                             '\\sin{\\left(\\theta_{0} \\right)} \\cos{\\left(\\theta_{1} \\right)} - '
                             '\\sin{\\left(\\theta_{1} \\right)} \\cos{\\left(\\theta_{0} \\right)} & 0 & - l_{1} '
                             '\\sin{\\left(\\theta_{0} \\right)} - l_{2} \\sin{\\left(\\theta_{0} \\right)} '
                             '\\sin{\\left(\\theta_{1} \\right)} + l_{2} \\cos{\\left(\\theta_{0} \\right)} '
                             '\\cos{\\left(\\theta_{1} \\right)}\\\\\\sin{\\left(\\theta_{0} \\right)} '
                             '\\cos{\\left(\\theta_{1} \\right)} + \\sin{\\left(\\theta_{1} \\right)} '
                             '\\cos{\\left(\\theta_{0} \\right)} & - \\sin{\\left(\\theta_{0} \\right)} '
                             '\\sin{\\left(\\theta_{1} \\right)} + \\cos{\\left(\\theta_{0} \\right)} '
                             '\\cos{\\left(\\theta_{1} \\right)} & 0 & l_{1} \\cos{\\left(\\theta_{0} \\right)} + '
                             'l_{2} \\sin{\\left(\\theta_{0} \\right)} \\cos{\\left(\\theta_{1} \\right)} + l_{2} '
                             '\\sin{\\left(\\theta_{1} \\right)} \\cos{\\left(\\theta_{0} \\right)}\\\\0 & 0 & 1 & '
                             '0\\\\0 & 0 & 0 & 1\\end{matrix}\\right]$'),
    '06_T6': (2025, '$\\displaystyle {}^0T_6 = \\left[\\begin{matrix}C_{6} \\left(C_{1} S_{23} S_{5} + C_{5} '
                    '\\left(C_{1} C_{23} S_{4} + C_{4} S_{1}\\right)\\right) + S_{6} \\left(C_{1} C_{23} C_{4} - '
                    'S_{1} S_{4}\\right) & C_{6} \\left(C_{1} C_{23} C_{4} - S_{1} S_{4}\\right) - S_{6} '
                    '\\left(C_{1} S_{23} S_{5} + C_{5} \\left(C_{1} C_{23} S_{4} + C_{4} S_{1}\\right)\\right) & - '
                    'C_{1} C_{5} S_{23} + S_{5} \\left(C_{1} C_{23} S_{4} + C_{4} S_{1}\\right) & - C_{1} S_{2} '
                    'l_{2} - C_{1} S_{23} l_{3} + l_{4} \\left(- C_{1} C_{5} S_{23} + S_{5} \\left(C_{1} C_{23} '
                    'S_{4} + C_{4} S_{1}\\right)\\right)\\\\C_{6} \\left(C_{5} \\left(- C_{1} C_{4} + C_{23} S_{1} '
                    'S_{4}\\right) + S_{1} S_{23} S_{5}\\right) + S_{6} \\left(C_{1} S_{4} + C_{23} C_{4} '
                    'S_{1}\\right) & C_{6} \\left(C_{1} S_{4} + C_{23} C_{4} S_{1}\\right) - S_{6} \\left(C_{5} '
                    '\\left(- C_{1} C_{4} + C_{23} S_{1} S_{4}\\right) + S_{1} S_{23} S_{5}\\right) & - C_{5} '
                    'S_{1} S_{23} + S_{5} \\left(- C_{1} C_{4} + C_{23} S_{1} S_{4}\\right) & - S_{1} S_{2} l_{2} '
                    '- S_{1} S_{23} l_{3} + l_{4} \\left(- C_{5} S_{1} S_{23} + S_{5} \\left(- C_{1} C_{4} + '
                    'C_{23} S_{1} S_{4}\\right)\\right)\\\\C_{4} S_{23} S_{6} + C_{6} \\left(- C_{23} S_{5} + '
                    'C_{5} S_{23} S_{4}\\right) & C_{4} C_{6} S_{23} - S_{6} \\left(- C_{23} S_{5} + C_{5} S_{23} '
                    'S_{4}\\right) & C_{23} C_{5} + S_{23} S_{4} S_{5} & C_{2} l_{2} + C_{23} l_{3} + l_{1} + '
                    'l_{4} \\left(C_{23} C_{5} + S_{23} S_{4} S_{5}\\right)\\\\0 & 0 & 0 & 1\\end{matrix}\\right]$'),
    '06_p': (1082, '$\\displaystyle p = \\left[\\begin{matrix}- C_{1} C_{2} S_{3} l_{2} - C_{3} S_{1} l_{2} - '
                   'S_{1} l_{1} + l_{3} \\left(- C_{1} C_{2} C_{3} + S_{1} S_{3}\\right) + l_{4} \\left(- C_{5} '
                   '\\left(C_{1} C_{2} C_{3} - S_{1} S_{3}\\right) + S_{5} \\left(C_{1} S_{2} S_{4} + C_{4} '
                   '\\left(C_{1} C_{2} S_{3} + C_{3} S_{1}\\right)\\right)\\right)\\\\C_{1} C_{3} l_{2} + C_{1} '
                   'l_{1} - C_{2} S_{1} S_{3} l_{2} + l_{3} \\left(- C_{1} S_{3} - C_{2} C_{3} S_{1}\\right) + '
                   'l_{4} \\left(- C_{5} \\left(C_{1} S_{3} + C_{2} C_{3} S_{1}\\right) + S_{5} \\left(C_{4} '
                   '\\left(- C_{1} C_{3} + C_{2} S_{1} S_{3}\\right) + S_{1} S_{2} S_{4}\\right)\\right)\\\\C_{3} '
                   'S_{2} l_{3} + S_{2} S_{3} l_{2} + l_{4} \\left(C_{3} C_{5} S_{2} + S_{5} \\left(C_{2} S_{4} - '
                   'C_{4} S_{2} S_{3}\\right)\\right)\\end{matrix}\\right]$'),
    '07_product': (1338, '$\\displaystyle T = T_z[\\theta_1, \\frac{5}{2}]\\,T_x[-90^\\circ, 0]\\cdot '
                         'T_z[\\theta_2, 6]\\,T_x[-90^\\circ, 0]\\cdot T_z[\\theta_3, 6]\\,T_x[0^\\circ, 12]\\cdot '
                         'T_z[\\theta_4, 1]\\,T_x[0^\\circ, 12]\\cdot T_z[\\theta_5, 6]\\,T_x[-90^\\circ, 0]\\cdot '
                         'T_z[\\theta_6, 6]\\,T_x[-90^\\circ, 0]\\cdot T_z[\\theta_7, 0]\\,T_x[0^\\circ, 0]$'),
}


@pytest.mark.parametrize("key", sorted(MEASURED))
def test_width_estimate_matches_the_browser(key):
    px, latex = MEASURED[key]
    estimate = latex_width_px(latex)
    # never narrower than measured by more than 3 %, never wider by more than 12 %
    assert 0.97 * px <= estimate <= 1.12 * px, (key, estimate, px)


def test_width_grows_with_the_text():
    assert latex_width_px("x") < latex_width_px("x + y") < latex_width_px(r"x + y + \cos{\left(q_{1} \right)}")
    assert latex_width_px(r"\left[\begin{matrix}a & b\\c & d\end{matrix}\right]") < \
        latex_width_px(r"\left[\begin{matrix}a + a & b\\c & d\end{matrix}\right]")
    # a matrix is as wide as its widest entries, not as all its entries in a row
    assert latex_width_px(r"\left[\begin{matrix}aaaa\\bbbb\end{matrix}\right]") < latex_width_px("aaaa + bbbb")


def _robot_T(make):
    robot = make()
    return robot, robot.fk_sym(simplify=True)


@pytest.mark.parametrize("make", [dhlab.robots.seed003_6dof, dhlab.robots.seed002_6dof,
                                  dhlab.robots.ssrms, dhlab.robots.puma560])
def test_every_piece_fits(make):
    robot, T = _robot_T(make)
    for M, name in ((T, r"{}^0T_n"), (T[:3, 3], "p")):
        shown = show_matrix(M, robot, name=name)
        assert shown.pieces
        for piece in shown.pieces:
            assert latex_width_px(piece) <= 900, piece
        assert shown.full == M
        assert "$$" in shown._repr_markdown_()
        assert shown._repr_latex_().startswith("$")
        # the LaTeX form stacks the pieces: as wide as the widest, not as all of them in a row
        assert latex_width_px(shown._repr_latex_()) <= 1.05 * max(latex_width_px(p) for p in shown.pieces)
        assert repr(shown).startswith(name)


def test_wide_pose_is_split_by_columns_and_keeps_every_entry():
    robot, T = _robot_T(dhlab.robots.seed003_6dof)
    shown = show_matrix(T, robot, name=r"{}^0T_6")
    assert shown.width_px > COLUMN_PX          # the reason to split: about 2000 px in one piece
    assert len(shown.pieces) > 1
    text = " ".join(shown.pieces)
    for e in shown.compact[:3, :]:
        if e not in (0, 1):
            assert sp.latex(e) in text or all(sp.latex(t) in text for t in sp.Add.make_args(e))


def test_compact_names_and_legend():
    q1, q2 = sp.symbols("q1 q2", real=True)
    M = sp.Matrix([[sp.cos(q1 + q2), -sp.sin(q1)], [sp.sin(q1 + q2), sp.cos(q2)]])
    shown = show_matrix(M, (q1, q2))
    assert {str(s) for s in shown.compact.free_symbols} == {"C12", "S1", "S12", "C2"}
    assert "C12 = cos(q1 + q2)" in shown.legend
    # the names go back to the full expression
    back = shown.compact.subs({sp.Symbol("C12"): sp.cos(q1 + q2), sp.Symbol("S1"): sp.sin(q1),
                               sp.Symbol("S12"): sp.sin(q1 + q2), sp.Symbol("C2"): sp.cos(q2)})
    assert back == M
    # symbols=None finds q1, q2 inside cos/sin
    assert show_matrix(M).compact == shown.compact


def test_small_matrix_is_one_piece():
    shown = show_matrix(sp.eye(4), name="I")
    assert shown.pieces == ["I = " + sp.latex(sp.eye(4))]
    assert "split" not in shown._repr_markdown_()


def test_long_entry_is_broken_between_terms():
    q = sp.symbols("q1:7")
    long = sp.Matrix([[sum(sp.cos(a) * sp.sin(b) for a in q for b in q)]])
    shown = show_matrix(long, q, name="t")
    assert r"\begin{aligned}" in shown.pieces[0]
    assert latex_width_px(shown.pieces[0]) <= 900
    # the aligned lines are measured as drawn: the head, then the widest line
    assert latex_width_px(shown.pieces[0]) >= max(latex_width_px(line) for line in shown.pieces[0].split(r"\\"))


@pytest.mark.parametrize("bad, what", [("abc", "sympy Matrix"), (object(), "sympy Matrix")])
def test_bad_matrix_is_a_clear_error(bad, what):
    with pytest.raises(DHLabError, match=what):
        show_matrix(bad)


@pytest.mark.parametrize("kwargs", [{"max_width_px": -5}, {"max_width_px": "wide"}, {"max_width_px": math.nan}])
def test_bad_width_is_a_clear_error(kwargs):
    with pytest.raises(DHLabError, match="max_width_px"):
        show_matrix(sp.eye(2), **kwargs)


def test_bad_symbols_are_a_clear_error():
    with pytest.raises(DHLabError, match="symbols"):
        show_matrix(sp.eye(2), ["q1", 3])
    with pytest.raises(DHLabError, match="symbols"):
        show_matrix(sp.eye(2), 3.5)


@settings(max_examples=30, deadline=None)
@given(st.lists(st.lists(st.integers(-3, 3), min_size=1, max_size=4), min_size=1, max_size=4),
       st.integers(350, 1200))
def test_random_matrices_always_fit(rows, width):
    """Matrices of sums of short C/S products: every shown line fits the width asked for."""
    q = sp.symbols("q1:5")
    ncols = min(len(r) for r in rows)
    M = sp.Matrix([[sum(k * sp.cos(q[j % 4]) * sp.sin(q[(j + k) % 4]) * sp.Symbol(f"l{j}")
                        for j in range(abs(k) * 3 + 1)) for k in r[:ncols]] for r in rows])
    shown = show_matrix(M, q, name="M", max_width_px=width)
    for piece in shown.pieces:
        assert latex_width_px(piece) <= width, piece


def test_docstring_examples():
    import doctest

    import dhlab.views.matrices as module
    result = doctest.testmod(module, optionflags=doctest.NORMALIZE_WHITESPACE)
    assert result.attempted > 0 and result.failed == 0


def test_one_expression_is_shown_without_brackets_and_broken_when_long():
    q = sp.symbols("q1:7")
    short = show_matrix(3 * sp.cos(q[0]), q, name="x")
    assert short.pieces == ["x = 3 C_{1}"] and short.full == 3 * sp.cos(q[0]) and repr(short).startswith("x = 3*C1")
    long = show_matrix(sum(sp.cos(a) * sp.sin(b) for a in q for b in q), q, name="s")
    assert r"\begin{aligned}" in long.pieces[0] and latex_width_px(long.pieces[0]) <= 900
