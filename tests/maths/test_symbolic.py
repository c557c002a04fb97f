"""Symbolic kinematics: the slides' A matrices and compact products."""
import json
import re
import subprocess
import sys

import pytest
import sympy as sp

from dhlab import robots, symbolic
from dhlab.symbolic import exact
from support.seeddata import DATA

PRINTED = json.loads((DATA / "seed002_printed_A.json").read_text(encoding="utf-8"))


def parse_bmatrix(latex, q_symbols, params):
    """Parse a slide's \\begin{bmatrix} ... \\end{bmatrix} with C_i, S_i, l_i, d_i."""
    body = latex.replace(r"\begin{bmatrix}", "").replace(r"\end{bmatrix}", "")
    index = {re.sub(r"\D", "", str(s)): s for s in q_symbols}
    rows = []
    for row in body.split(r"\\"):
        entries = []
        for cell in row.split("&"):
            text = cell.strip()
            text = re.sub(r"([CS])_(\d)",
                          lambda m: f"{'cos' if m.group(1) == 'C' else 'sin'}({index[m.group(2)]})", text)
            text = re.sub(r"([ld])_(\d)", r"\1\2", text)
            text = re.sub(r"(\w)\s+(\w)", r"\1*\2", text)
            local = {str(s): s for s in q_symbols} | {k: sp.Symbol(k) for k in params}
            entries.append(sp.sympify(text, locals=local))
        rows.append(entries)
    return sp.Matrix(rows)


@pytest.mark.parametrize("table,factory", [("4dof", robots.seed002_4dof), ("6dof", robots.seed002_6dof)])
def test_every_printed_A_matrix_of_seed002(table, factory):
    robot = factory()
    assert len(PRINTED[table]) == robot.n
    for key, entry in PRINTED[table].items():
        i = int(key.split("A")[1])
        printed = parse_bmatrix(entry["latex"], robot.q_symbols, robot.params)
        ours = robot.A(i)
        assert ours == printed or sp.expand(ours - printed) == sp.zeros(4), (key, ours, printed)
        # and exactly: no float residue like 6e-17, no unevaluated angle offsets
        assert not ours.atoms(sp.Float), key


def test_A_is_exact_for_degree_tables():
    """α = 90° typed in degrees gives exact 0/1 entries, not 6.1e-17."""
    A = robots.ssrms().A(1)
    assert A[2, 1] == -1 and A[1, 1] == 0 and A[2, 3] == sp.Rational(5, 2)


def test_ssrms_is_built_and_moved_without_sympy_and_made_exact_on_first_symbolic_use():
    """The browser edition's first slider waits for what building the SSRMS imports: its table is all
    numbers, so building it, moving it and printing its table import no sympy; A(i) then does, exactly."""
    code = ("import sys, dhlab\n"
            "arm = dhlab.robots.ssrms()\n"
            "arm.fk(arm.qz), arm.frames(arm.qz), arm.A(1, 0.5), str(arm.table()), arm.reach()\n"
            "assert 'sympy' not in sys.modules, 'building or moving the SSRMS imported sympy'\n"
            "print(arm.A(1)[2, 3], arm.A(1)[2, 1])\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["5/2", "-1"]


VERIFIED_SSRMS_P = {   # VERIFIED_MATH.md §6.4, written with C/S names
    "px": "12*S1*S3 + 12*S1*S34 + 6*S1*C345 - 6*S1 - 13*S2*C1 - 6*S345*C1*C2 + 12*C1*C2*C3 + 12*C1*C2*C34",
    "py": "-13*S1*S2 - 6*S1*S345*C2 + 12*S1*C2*C3 + 12*S1*C2*C34 - 12*S3*C1 - 12*S34*C1 - 6*C1*C345 + 6*C1",
    "pz": "6*S2*S345 - 12*S2*C3 - 12*S2*C34 - 13*C2 + 5/2",
}


def test_ssrms_compact_position_matches_verified_math():
    robot = robots.ssrms()
    T = symbolic.compact(robot.fk_sym(simplify=True), robot.q_symbols)
    for k, name in enumerate(("px", "py", "pz")):
        expected = sp.sympify(VERIFIED_SSRMS_P[name])
        assert sp.expand(T[k, 3] - expected) == 0, name
    names = {str(s) for s in T.free_symbols}
    assert {"C345", "S345", "C34", "S34", "C3", "S3"} <= names
    assert not names & {"C4", "S4", "C5", "S5"}, "parallel joints must appear only as sums"


def test_seed003_compact_uses_c23():
    robot = robots.seed003_6dof()
    T = symbolic.compact(robot.fk_sym(simplify=True), robot.q_symbols)
    l1, l2, l3, l4 = sp.symbols("l1 l2 l3 l4")
    C2, C23, C5, S23, S4, S5 = sp.symbols("C2 C23 C5 S23 S4 S5")
    assert sp.expand(T[2, 3] - (l1 + l2 * C2 + l3 * C23 + l4 * (S4 * S5 * S23 + C5 * C23))) == 0
    assert "C3" not in {str(s) for s in T.free_symbols}


@pytest.mark.parametrize("factory", [robots.puma560, robots.ssrms])
def test_simplified_is_compact(factory):
    """No more operations than sympy.simplify leaves (measured: 287 PUMA, 372 SSRMS)."""
    robot = factory()
    ops = symbolic.count_ops(robot.fk_sym(simplify=True))
    assert ops <= {"PUMA 560": 287, "SSRMS (seed 000)": 372}[robot.name]
    assert ops < symbolic.count_ops(robot.fk_sym(simplify=False))


def test_compact_names_and_legend():
    q1, q2, q3 = sp.symbols("q1 q2 q3")
    M = sp.Matrix([[sp.cos(q1), sp.sin(q2 + q3)], [sp.cos(q1 - q2), sp.sin(2 * q1)]])
    out = symbolic.compact(M, (q1, q2, q3))
    assert out[0, 0] == sp.Symbol("C1") and out[0, 1] == sp.Symbol("S23")
    assert out[1, 0] == sp.cos(q1 - q2) and out[1, 1] == sp.sin(2 * q1)   # not sums of joints: left as is
    assert symbolic.legend(M, (q1, q2, q3)) == "C1 = cos(q1), S23 = sin(q2 + q3)"


def test_seed004_robot1_compact():
    robot = robots.robot_no_tan_elemental_1()
    T = symbolic.compact(robot.fk_sym(simplify=True), robot.q_symbols)
    C01, S01, S0, C0 = sp.symbols("C01 S01 S0 C0")
    l1, l2 = sp.symbols("l1 l2")
    assert sp.expand(T[0, 3] - (l2 * C01 - l1 * S0)) == 0
    assert sp.expand(T[1, 3] - (l2 * S01 + l1 * C0)) == 0


@pytest.mark.parametrize("name", sorted(robots.catalogue()))
def test_fk_sym_is_the_plain_matrix_product(name):
    """fk_sym() multiplies entry by entry (fast on long chains): the very matrix sympy's product gives."""
    robot = robots.catalogue()[name]()
    mats = [exact(sp.Matrix(robot.base))] + robot.link_matrices_sym() + [exact(sp.Matrix(robot.tool))]
    product = mats[0]
    for A in mats[1:]:
        product = product * A
    assert robot.fk_sym() == product
