"""Regression tests for probe 14's defects A–E (/work/notes/probe14_report.md, section 2):
Link.A checks q, a Factor's sign is a real ±1 kept as an int, params go through the angle and
length checks, a ragged qlim is refused, and a 0-d numpy array in a joint vector is a number."""
import datetime
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest
import sympy as sp

from dhlab import DHLabError, Link, Move, PrismaticDH, RevoluteDH, Robot, Rot, deg2rad, robots
from dhlab.dh import DHRobot
from dhlab.transforms import Rx, Rz, trans

Q1 = sp.Symbol("q1")


# --- A: Link.A / RevoluteDH.A / PrismaticDH.A check q at the entry -----------------------------------
def _revolute_link():
    return Link([Rot("z", joint=True)])


BAD_Q = [
    ("None", lambda: RevoluteDH().A(None), "None"),
    ("text", lambda: RevoluteDH().A("0.5"), "text"),
    ("huge int, prismatic", lambda: PrismaticDH().A(10**400), "too large"),
    ("True", lambda: _revolute_link().A(True), "True/False"),
    ("list", lambda: RevoluteDH().A([0.1]), "list"),
    ("tuple", lambda: PrismaticDH().A((0.1,)), "tuple"),
    ("dict", lambda: RevoluteDH().A({}), "dict"),
    ("set", lambda: RevoluteDH().A({0.1}), "set"),
    ("date", lambda: RevoluteDH().A(datetime.date(2024, 1, 1)), "date"),
    ("datetime64", lambda: RevoluteDH().A(np.datetime64("2024-01-01")), "date"),
    ("sp.Matrix", lambda: RevoluteDH().A(sp.Matrix([1])), "Matrix"),
    ("generator", lambda: RevoluteDH().A(x for x in [1])),
    ("Ellipsis", lambda: RevoluteDH().A(...), "an ellipsis"),
    ("huge Fraction", lambda: RevoluteDH().A(Fraction(10**400, 1)), "too large"),
    ("Decimal nan", lambda: RevoluteDH().A(Decimal("nan")), "nan"),
    ("degrees as radians", lambda: RevoluteDH().A(90), "deg2rad(90)"),
    ("an angle as a length", lambda: PrismaticDH().A(deg2rad(30)), "angle"),
]


@pytest.mark.parametrize("case", BAD_Q, ids=[c[0] for c in BAD_Q])
def test_link_A_refuses_a_bad_q_naming_q(case):
    _, call, *words = case
    with pytest.raises(DHLabError, match=r"^q \(") as info:
        call()
    for word in words:
        assert word in str(info.value)


def test_link_A_takes_a_decimal_as_the_number_it_is():
    np.testing.assert_allclose(RevoluteDH().A(Decimal("0.25")), Rz(0.25), atol=1e-15)


def test_link_A_stays_symbolic_for_a_symbol():      # a guard: symbolic q keeps working
    assert RevoluteDH().A(Q1) == Rz(Q1)
    d = sp.Symbol("d")
    assert PrismaticDH().A(d + 1) == trans(0, 0, d + 1)


def test_link_A_offset_plus_q_beyond_a_turn_is_the_same_rotation():
    # each is within a turn; their sum is not, and is still a valid pose
    np.testing.assert_allclose(RevoluteDH(offset=deg2rad(90)).A(6.0), Rz(6.0 + np.pi / 2 - 2 * np.pi), atol=1e-12)


# --- B: the sign of Rot / Move ------------------------------------------------------------------------
@pytest.mark.parametrize("sign", [1 + 0j, np.complex128(1), np.array([1, 2])],
                         ids=["complex", "np.complex128", "array"])
@pytest.mark.parametrize("make", [Rot, Move], ids=["Rot", "Move"])
def test_sign_refuses_complex_and_arrays(make, sign):
    with pytest.raises(DHLabError, match="sign must be"):
        make("z", joint=True, sign=sign)


@pytest.mark.parametrize("sign", [True, 2, 0.5, "1", None])
def test_sign_still_refuses_what_it_refused(sign):      # a guard of the rewritten check
    with pytest.raises(DHLabError, match="sign must be"):
        Rot("z", joint=True, sign=sign)


@pytest.mark.parametrize("sign", [sp.Integer(-1), Fraction(-1), np.int64(-1), np.float64(-1.0), -1.0,
                                  Decimal(-1), np.array(-1)],
                         ids=["sp.Integer", "Fraction", "np.int64", "np.float64", "float", "Decimal", "0-d array"])
def test_sign_of_any_numeric_type_is_kept_as_an_int(sign):
    rot = Rot("z", joint=True, sign=sign)
    assert rot.sign == -1 and type(rot.sign) is int
    np.testing.assert_allclose(Robot([Link([rot])]).fk([0.3]), Rz(-0.3), atol=1e-15)
    move = Move("x", joint=True, sign=sign)
    np.testing.assert_allclose(Robot([Link([move])]).fk([0.3]), trans(-0.3, 0, 0), atol=1e-15)


# --- C: values given in params go through the angle and length checks -----------------------------
def test_params_angle_in_degrees_is_refused_with_the_fix():
    robot = lambda: DHRobot([RevoluteDH(a=1.0, alpha=sp.Symbol("al"))], params={"al": 90})  # noqa: E731
    with pytest.raises(DHLabError, match=r"al from params.*more than a full turn.*deg2rad\(90\)"):
        robot()


def test_params_huge_angle_is_refused():
    with pytest.raises(DHLabError, match="more than a full turn"):
        Robot([Link([Rot("z", joint=True), Rot("x", sp.Symbol("t"))])], params={"t": 1e308})


def test_params_angle_used_as_a_length_is_refused():
    with pytest.raises(DHLabError, match=r"length.*l = deg2rad\(30\)"):
        DHRobot([RevoluteDH(a=sp.Symbol("l"))], params={"l": deg2rad(30)})


def test_params_length_beyond_the_largest_is_refused():
    with pytest.raises(DHLabError, match="too large for a length"):
        DHRobot([RevoluteDH(a=sp.Symbol("l"))], params={"l": 1e200})


def test_params_good_values_still_work():      # a guard: deg2rad() params now keep their mark
    robot = DHRobot([RevoluteDH(a=sp.Symbol("l"), alpha=sp.Symbol("al"))], params={"l": 0.5, "al": deg2rad(90)})
    np.testing.assert_allclose(robot.fk([0.0]), trans(0.5, 0, 0) @ Rx(np.pi / 2), atol=1e-15)
    assert robot.params == {"l": 0.5, "al": deg2rad(90)}


# --- D: a ragged qlim ------------------------------------------------------------------------------------
def test_ragged_qlim_is_refused_naming_qlim():
    with pytest.raises(DHLabError, match="qlim"):
        RevoluteDH(qlim=(0, [1]))


def test_ragged_d_max_is_refused_naming_it():
    with pytest.raises(DHLabError, match="qlim|d_max"):
        robots.robot_no_tan_elemental_2(d_max=[0.5])


def test_prismatic_limits_beyond_the_largest_length_are_refused():
    # section 4's judgement call: such a range overflowed reach() and made is_planar refuse its own samples
    with pytest.raises(DHLabError, match="qlim.*too large for a length"):
        PrismaticDH(qlim=(0, 1e308))
    assert PrismaticDH(qlim=(0, 1e150)).qlim == (0.0, 1e150)


# --- E: a 0-d numpy array inside a joint vector ------------------------------------------------------
def test_A_takes_a_0d_array():
    puma = robots.puma560()
    np.testing.assert_allclose(puma.A(1, np.array(0.1)), puma.A(1, 0.1), atol=0)


def test_fk_takes_0d_arrays_inside_the_vector():
    puma = robots.puma560()
    q = [0.1, 0.2, 0, 0, 0, 0]
    np.testing.assert_allclose(puma.fk([np.array(0.1), np.float64(0.2), 0, 0, 0, 0]), puma.fk(q), atol=0)
    np.testing.assert_allclose(puma.fk([q, [np.array(0.1), 0.2, 0, 0, 0, 0]]), puma.fk([q, q]), atol=0)


def test_a_1d_array_inside_the_vector_is_still_ragged():      # a guard of the E fix
    with pytest.raises(DHLabError, match="ragged"):
        robots.puma560().fk([np.array([0.1]), 0, 0, 0, 0, 0])


def test_A_refuses_a_ragged_q_without_a_raw_error():
    with pytest.raises(DHLabError, match="one number"):
        robots.puma560().A(1, [0, [1]])


def test_a_deg_parameter_in_a_degree_table_is_refused_not_converted_twice():
    with pytest.raises(DHLabError, match=r"al = deg2rad\(90\).*degrees.*al=90"):
        DHRobot.from_table([("q1", 0, 1, "al")], params={"al": deg2rad(90)})
    by_degrees = DHRobot.from_table([("q1", 0, 1, "al")], params={"al": 90})
    by_radians = DHRobot.from_table([("q1", 0, 1, "al")], params={"al": deg2rad(90)}, angles="rad")
    assert np.allclose(by_degrees.fk([0.0]), by_radians.fk([0.0]))
    assert np.allclose(by_degrees.fk([0.0])[:3, 2], [0, -1, 0])
