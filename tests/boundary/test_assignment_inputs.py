"""Bad input into the assignment's tools (notebook 8, ``dhlab.assignment``): the number readers of
Tz/Tx, JointTerm arithmetic, joint_variables(n) and check_part, DHTransform.matrix(q), DHChain's
joint vectors, a joint variable where a number is expected. Every bad input gives a DHLabError that
names the value; valid inputs keep giving what the grader reads (a negated joint term keeps +0)."""
from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp

import dhlab
from dhlab import assignment as A
from dhlab.assignment import answers as ans
from dhlab.chain import Link, Robot, Rot
from dhlab.errors import DHLabError

q1, q2 = A.joint_variables(2)
q3 = A.joint_variables(3)[2]


def _T():
    return A.Tz(q1, 0) @ A.Tx(0, 1)


def _chain():
    return (A.Tz(q1, 0) @ A.Tx(0, 1)) @ (A.Tz(q2, 0) @ A.Tx(0, 1))


def _raises(make, words):
    with pytest.raises(DHLabError, match=words):
        make()


# --- the number readers of Tz / Tx -----------------------------------------------------------

@pytest.mark.parametrize("make, words", [
    (lambda: A.Tx("90", "0.5"), r"α in Tx\[α, a\] = '90' .*text"),
    (lambda: A.Tx(True, 0), r"α in Tx\[α, a\] = True .*True/False"),
    (lambda: A.Tx(10**400, 0), r"α in Tx\[α, a\] = .*too large"),
    (lambda: A.Tx(np.complex128(90 + 5j), 0), r"α in Tx\[α, a\] = .*complex"),
    (lambda: A.Tx(0, "0.5"), r"a in Tx\[α, a\] = '0.5' .*text"),
    (lambda: A.Tz(q1, True), r"d in Tz\[θ, d\] = True"),
], ids=["text", "bool", "huge-int", "complex", "text-a", "bool-d"])
def test_tz_tx_refuse_what_is_not_a_number(make, words):
    _raises(make, words)


# --- what Tz / Tx accept, the grader can read ------------------------------------------------

@pytest.mark.parametrize("make, words", [
    (lambda: (A.Tz(q1, 0) @ A.Tx(1e300, 0)).matrix(0.1), r"α in Tx\[α, a\] = 1e\+300 is too large.*degrees"),
    (lambda: (A.Tz("q0", 0) @ A.Tx(0, 1)).matrix(0.1), r"joint number .* from 1 to 50, got 0"),
    (lambda: (A.Tz(q1 + float("nan"), 0) @ A.Tx(0, 1)).matrix(0.1), r"added to q1 is nan"),
    (lambda: A.Tz(q1, 1e151), r"d in Tz\[θ, d\] = 1e\+151 is too large.*metres"),
    (lambda: A.Tx(0, 1e308), r"a in Tx\[α, a\] = 1e\+308 is too large"),
    (lambda: A.Tz("q99", 0), r"from 1 to 50, got 99"),
    (lambda: A.Tx(sp.Float("1e400"), 0), r"α in Tx\[α, a\] = .*too large"),
    (lambda: q1 + 1e7, r"added to q1 = 1e\+07 is too large: no angle \(degrees\) or length"),
    (lambda: q1 + 6e5 + 6e5, r"constant of q1 = 1\.2e\+06 is too large"),
    (lambda: A.Tz(q1, "q2 + 9999999"), r"constant of q2 = 1e\+07 is too large"),
], ids=["alpha-1e300", "q0", "q1+nan", "d-1e151", "a-1e308", "q99", "sympy-1e400", "const-1e7", "sum-1.2e6",
        "text-1e7"])
def test_tz_tx_refuse_what_the_grader_cannot_read(make, words):
    _raises(make, words)


def test_a_changed_field_gives_a_dhlaberror_not_an_attributeerror():
    T = _T()
    T.x.alpha = 1e300                   # past the checks of Tx: the grader's reader refuses it
    with pytest.raises(DHLabError, match="cannot be read: .*no length .* or angle"):
        T.matrix(0.1)


def test_every_accepted_answer_is_read_by_the_grader():
    T = A.Tz(-q2 + 1e6, -1e6) @ A.Tx(dhlab.deg2rad(-90), np.float32(0.5))
    row = ans.answers_from_namespace({"T1": T}).T[0]
    assert isinstance(row, ans.Row)
    assert (row.theta.const, row.theta.sign, row.d.const, row.alpha, row.a) == (1e6, -1, -1e6, -90.0,
                                                                                float(np.float32(0.5)))


# --- JointTerm ----------------------------------------------------------------------------

@pytest.mark.parametrize("make, words", [
    (lambda: q1 + 10**400, r"added to q1 = .*too large"),
    (lambda: q1 * np.array([1, 2]), r"cannot be multiplied by array"),
    (lambda: q1 * True, r"cannot be multiplied by True"),
    (lambda: A.JointTerm("a"), r"joint number .* whole number from 1 to 50, got 'a'"),
    (lambda: A.JointTerm(1.7), r"joint number .* whole number from 1 to 50, got 1.7"),
    (lambda: A.JointTerm(1, sign=2), r"sign must be 1 .* or -1"),
    (lambda: A.JointTerm(1, const="90"), r"constant of q1 = '90' .*text"),
], ids=["add-huge", "mul-array", "mul-bool", "joint-text", "joint-float", "sign-2", "const-text"])
def test_joint_terms_are_checked(make, words):
    _raises(make, words)


def test_valid_joint_term_arithmetic_is_unchanged():
    assert [repr(t) for t in (q2 + 90, -q1, 90 - q2, q1 * -1, -1 * q1, q1 * 1.0, q1 * sp.Integer(-1),
                              q1 + dhlab.deg2rad(90), q2 - 90)] == \
        ["q2 + 90", "-q1", "-q2 + 90", "-q1", "-q1", "q1", "-q1", "q1 + 90", "q2 - 90"]


# --- joint_variables(n) and check_part(part, ...) -------------------------------------------

@pytest.mark.parametrize("n", [2.5, "a", None, -1, 0, True], ids=repr)
def test_joint_variables_needs_a_whole_number_of_joints(n):
    _raises(lambda: A.joint_variables(n), r"n \(the number of joint variables\)")


@pytest.mark.parametrize("part", [np.array([1, 2]), True, 1.0], ids=repr)
def test_check_part_needs_part_1_2_or_3(part):
    _raises(lambda: A.check_part(part, {}), r"parts 1, 2 and 3")


def test_valid_counts_and_parts_still_work():
    assert len(A.joint_variables(np.int64(4))) == 4
    assert A.check_part(np.int64(1), {}).points == 2
    _raises(lambda: A.check_part(4, {}), r"parts 1, 2 and 3")


# --- DHTransform.matrix(q) -----------------------------------------------------------------

@pytest.mark.parametrize("q, words", [
    ("abc", r"q = 'abc' .*text"),
    ([0.5], r"q = \[0.5\] is not a valid number"),
    (float("nan"), r"q is nan"),
    (float("inf"), r"q is inf"),
    (90, r"q = 90 rad is more than a full turn.*deg2rad\(90\)"),
    ("0.5", r"q = '0.5' .*text"),
    (True, r"q = True .*True/False"),
    (1j, r"q = 1j .*complex"),
    (10**400, r"q = .*too large"),
    (sp.Symbol("x"), r"q = x .*symbols"),
], ids=["abc", "list", "nan", "inf", "degrees", "text", "bool", "complex", "huge", "symbol"])
def test_matrix_checks_the_joint_value(q, words):
    _raises(lambda: _T().matrix(q), words)


def test_a_sliding_joint_value_is_a_length():
    T = A.Tz(0, q1) @ A.Tx(0, 0)
    _raises(lambda: T.matrix(dhlab.deg2rad(30)), r"q is a length, but you gave an angle")
    assert T.matrix(2.0)[2, 3] == 2.0            # a length may be more than 2π


def test_valid_values_still_give_the_pose():
    T = A.Tz(q1, 0.15005) @ A.Tx(-90, 0.0203)
    assert np.allclose(T.matrix(0)[:3, 3], [0.0203, 0, 0.15005])
    assert np.allclose(T.matrix(dhlab.deg2rad(90)), T.matrix(math.pi / 2))
    assert np.allclose(T.matrix(np.float32(0.5)), T.matrix(0.5), atol=1e-7)


# --- DHChain.frames(q) / .matrix(q) --------------------------------------------------------

@pytest.mark.parametrize("q, words", [
    ([0.5], r"q must hold 2 joint values .*got shape \(1,\)"),
    ([], r"q must hold 2 joint values .*got shape \(0,\)"),
    ([0, 0, 0], r"q must hold 2 joint values .*got shape \(3,\)"),
    (None, r"q = None .*missing"),
    ([float("nan"), 0], r"q\[0\] is nan"),
    ("abc", r"q = 'abc' .*text"),
    ([1j, 0], r"q\[0\] = 1j .*complex"),
    ([[0, 0], [0, 0]], r"one pose, not a batch"),
    (["0", "0"], r"q\[0\] = '0' .*text"),
    ([True, False], r"q\[0\] = True"),
    ([90, 0], r"q\[0\] \(joint 1, revolute\) is 90 rad.*deg2rad\(90\)"),
], ids=["one-value", "empty", "three-values", "None", "nan", "text", "complex", "batch", "text-items",
        "bools", "degrees"])
@pytest.mark.parametrize("method", ["frames", "matrix"])
def test_chain_checks_its_joint_vector(q, words, method):
    _raises(lambda: getattr(_chain(), method)(q), words)


def test_valid_joint_vectors_still_work():
    ch = _chain()
    assert np.allclose(ch.frames([0.5, 0.0])[-1][:3, 3], [2 * math.cos(0.5), 2 * math.sin(0.5), 0])
    assert np.allclose(ch.matrix([dhlab.deg2rad(30), 0.1]), ch.frames(np.array([math.pi / 6, 0.1]))[-1])
    sliding = (A.Tz(q1, 0) @ A.Tx(0, 1)) @ (A.Tz(0, q2) @ A.Tx(0, 0))
    assert sliding.frames([0.0, 3.0])[-1][2, 3] == 3.0
    _raises(lambda: sliding.frames([0.0, dhlab.deg2rad(30)]),
            r"q\[1\] = deg2rad\(30\) is an angle, but joint 2 is prismatic")


def test_public_constructors_refuse_other_objects():
    _raises(lambda: A.DHTransform(1, 2), r"DHTransform\(z, x\) takes a Tz and a Tx")
    _raises(lambda: A.DHChain(5), r"a chain is a list of transformations")
    _raises(lambda: A.DHChain([1]), r"a chain is a list of transformations")


# --- the negation of a joint term keeps a constant of +0 ------------------------

@pytest.mark.parametrize("make", [lambda: -q1, lambda: -(q1 - 0), lambda: q1 * -1, lambda: A.Tz(-q1, 0).theta,
                                  lambda: A.JointTerm(1, -1, -0.0)],
                         ids=["-q1", "-(q1-0)", "q1*-1", "Tz(-q1)", "JointTerm(-0.0)"])
def test_negation_keeps_a_constant_of_plus_zero(make):
    assert math.copysign(1.0, make().const) == 1.0


def test_the_grader_reads_plus_zero():
    row = ans.answers_from_namespace({"T1": A.Tz(-q1, 0) @ A.Tx(-0.0, -0.0)}).T[0]
    assert [math.copysign(1.0, v) for v in (row.theta.const, row.alpha, row.a)] == [1.0, 1.0, 1.0]


# --- a joint variable where a number is expected, two joint variables in one factor --------------------
@pytest.mark.parametrize("make, words", [
    (lambda: A.Tz("q1", "q2"), r"two joint variables"),
    (lambda: A.Tz(q1, q2), r"two joint variables"),
    (lambda: np.eye(4) - q1, r"is not a valid number"),
    (lambda: np.ma.masked - q1, r"masked"),
], ids=["tz-two-text", "tz-two-terms", "array-minus-q", "masked-minus-q"])
def test_refused_where_the_value_enters(make, words):
    with pytest.raises(DHLabError, match=words):
        make()


def test_valid_uses_are_unchanged():
    chain = (A.Tz(q1, 0.5) @ A.Tx(-90, 0)) @ (A.Tz(q2 - 90, 0) @ A.Tx(0, 0.4)) @ (A.Tz(0, q3) @ A.Tx(0, 0))
    assert len(chain) == 3
    assert Robot([Link([Rot("z", joint=True)])], joint_symbols=["theta1"]).q_symbols[0].name == "theta1"
    assert repr(A.Tz(q1 + 400, 0)) == "Tz[q1 + 400, 0]"      # the grader reads any offset (same rotation)
    # a chain that moves one q_i in two links is a slip the grader scores (one item), not refused here
    assert len((A.Tz(q1, 0) @ A.Tx(0, 1)) @ (A.Tz(q1 + 90, 0) @ A.Tx(0, 1))) == 2
