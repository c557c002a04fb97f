"""Bad input gets a clear DHLabError at the boundary: which value, what was expected, how to fix it."""
import numpy as np
import pytest
import sympy as sp

import dhlab
from dhlab import DHLabError, deg2rad, robots
from dhlab.transforms import Rz, inv, trans


@pytest.fixture
def puma():
    return robots.puma560()


def test_wrong_number_of_joint_values(puma):
    with pytest.raises(DHLabError, match=r"6 joint values \(shape \(6,\), or \(N, 6\).*got shape \(5,\)"):
        puma.fk([0, 0, 0, 0, 0])
    with pytest.raises(DHLabError, match=r"got shape \(3, 2, 6\)"):
        puma.fk(np.zeros((3, 2, 6)))
    with pytest.raises(DHLabError, match="got shape"):
        puma.frames(0.0)


def test_nan_and_inf_are_named(puma):
    with pytest.raises(DHLabError, match=r"q\[2\] is nan"):
        puma.fk([0, 0, np.nan, 0, 0, 0])
    Q = np.zeros((4, 6))
    Q[3, 1] = np.inf
    with pytest.raises(DHLabError, match=r"q\[3, 1\] is inf"):
        puma.fk(Q)


def test_not_numbers(puma):
    with pytest.raises(DHLabError, match=r"q\[0\] = 'a' is not a valid number: it is text"):
        puma.fk(["a", 0, 0, 0, 0, 0])
    with pytest.raises(DHLabError, match="not a valid number.*fk_sym"):
        puma.fk(list(sp.symbols("q1:7")))


def test_degrees_passed_as_radians_are_refused(puma):
    with pytest.raises(DHLabError, match=r"joint 2, revolute\) is 90 rad.*dhlab.deg2rad\(90\)"):
        puma.fk([0, 90, 0, 0, 0, 0])
    with pytest.raises(DHLabError, match=r"dhlab.deg2rad\(45\)"):
        Rz(45)
    with pytest.raises(DHLabError, match=r"alpha = 90 rad is more than a full turn.*dhlab.deg2rad\(90\)"):
        dhlab.RevoluteDH(alpha=90)
    # the same values in radians are fine
    puma.fk(deg2rad([0, 90, 0, 0, 0, 0]))
    Rz(deg2rad(45))


def test_prismatic_joint_given_an_angle():
    robot = robots.seed002_4dof()
    with pytest.raises(DHLabError, match=r"q\[1\] = deg2rad\(30\) is an angle, but joint 2 is prismatic"):
        robot.fk([deg2rad(10), deg2rad(30), 0.2, 0])
    with pytest.raises(DHLabError, match="made with dhlab.deg2rad\\(\\), but joint 2 is prismatic"):
        robot.fk(deg2rad([10, 30, 20, 0]))
    with pytest.raises(DHLabError, match="d is a length, but you gave an angle"):
        dhlab.RevoluteDH(d=deg2rad(30))
    robot.fk([deg2rad(10), 0.3, 0.2, deg2rad(5)])   # the right way


def test_non_rigid_matrices():
    M = np.eye(4)
    M[0, 0] = -1
    with pytest.raises(DHLabError, match="reflection"):
        dhlab.check_rigid(M)
    with pytest.raises(DHLabError, match="not orthonormal"):
        dhlab.check_rigid(np.diag([2.0, 1, 1, 1]))
    bad_row = np.eye(4)
    bad_row[3, 0] = 1
    with pytest.raises(DHLabError, match=r"last row is \[1.0, 0.0, 0.0, 1.0\]"):
        inv(bad_row)
    with pytest.raises(DHLabError, match=r"shape \(4, 4\).*got shape \(3, 3\)"):
        dhlab.is_rigid(np.eye(3))
    with pytest.raises(DHLabError, match="base transform is not a proper rigid transform"):
        dhlab.DHRobot([dhlab.RevoluteDH(a=1)], base=np.diag([1.0, 1, -1, 1]))
    with pytest.raises(DHLabError, match=r"T\[0, 3\] is nan"):
        dhlab.is_rigid(np.array([[1, 0, 0, np.nan], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1.0]]))


def test_bad_robot_definitions():
    with pytest.raises(DHLabError, match="RevoluteDH\\(...\\) or PrismaticDH"):
        dhlab.DHRobot([dhlab.RevoluteDH(), "link"])
    with pytest.raises(DHLabError, match="l2, which has no numeric value.*params="):
        dhlab.DHRobot([dhlab.RevoluteDH(a=sp.Symbol("l2"))])
    with pytest.raises(DHLabError, match="row 2 must have 4 entries"):
        dhlab.DHRobot.from_table([("q1", 0, 1, 0), ("q2", 0, 1)])
    with pytest.raises(DHLabError, match="has no joint variable"):
        dhlab.DHRobot.from_table([(0, 1, 1, 0)])
    with pytest.raises(DHLabError, match="several unknown symbols"):
        dhlab.DHRobot.from_table([("q1 + t", 0, 1, 0)])
    with pytest.raises(DHLabError, match="l1, which has no numeric value"):
        dhlab.DHRobot.from_table([("q1", "l1", 0, 0)])
    with pytest.raises(DHLabError, match="low < high"):
        dhlab.RevoluteDH(qlim=(1, -1))
    with pytest.raises(DHLabError, match="joint_symbols must name 1 joints"):
        dhlab.DHRobot([dhlab.RevoluteDH()], joint_symbols=["a", "b"])


def test_bad_parameters_and_poses():
    with pytest.raises(DHLabError, match="parameter l1 = 'long' must be a finite number"):
        robots.seed003_6dof(l1="long")
    with pytest.raises(DHLabError, match="not a proper rigid transform"):
        dhlab.rpy(np.diag([1.0, 1, -1, 1]))


def test_ik_unreachable_is_a_message_not_a_crash():
    sols = dhlab.ik.pr_mechanism_ik(robots.pr_mechanism(), 2.0, 0.6)
    assert sols == [] and "no solution" in sols.message and "0.6 > l2 = 0.5" in sols.message
    with pytest.raises(DHLabError, match="finite"):
        dhlab.ik.pr_mechanism_ik(robots.pr_mechanism(), np.nan, 0.1)


# --- known bad inputs, one by one ------------------------------------------------------------------
KNOWN_BAD_INPUTS = {
    "Move with a text amount": lambda: dhlab.Move("x", "l1"),
    "Move with None": lambda: dhlab.Move("x", None),
    "Move with a list": lambda: dhlab.Move("x", [1]),
    "Move with a dict": lambda: dhlab.Move("x", {}),
    "Move with a complex": lambda: dhlab.Move("x", 1j),
    "Move with nan": lambda: dhlab.Move("x", np.nan),
    "Rot of 90 (degrees as radians)": lambda: dhlab.Rot("x", 90),
    "qlim=(1,)": lambda: dhlab.Link([dhlab.Rot("z", joint=True)], qlim=(1,)),
    "qlim='ab'": lambda: dhlab.Link([dhlab.Rot("z", joint=True)], qlim="ab"),
    "qlim=5": lambda: dhlab.Link([dhlab.Rot("z", joint=True)], qlim=5),
    "reversed qlim": lambda: dhlab.RevoluteDH(qlim=(1, -1)),
    "infinite qlim": lambda: dhlab.RevoluteDH(qlim=(-1, np.inf)),
    "qlim of 100 rad": lambda: dhlab.RevoluteDH(qlim=(-100, 100)),
    "deg2rad() limit on a prismatic joint": lambda: dhlab.PrismaticDH(qlim=(0, deg2rad(30))),
    "table with None": lambda: dhlab.DHRobot.from_table([("q1", None, 0, 0)]),
    "table with True": lambda: dhlab.DHRobot.from_table([("q1", True, 0, 0)]),
    "table with 1/0": lambda: dhlab.DHRobot.from_table([("q1", "1/0", 0, 0)]),
    "table with 1e400": lambda: dhlab.DHRobot.from_table([("q1", "1e400", 0, 0)]),
    "qlim=[]": lambda: dhlab.DHRobot.from_table([("q1", 0, 1, 0)], qlim=[]),
    "table of None": lambda: dhlab.DHRobot.from_table(None),
    "angles='rad' with 90": lambda: dhlab.DHRobot.from_table([("q1", 0, 1, 90)], angles="rad"),
    "deg2rad(90) in a degree table": lambda: dhlab.DHRobot.from_table([("q1", 0, 1, deg2rad(90))]),
    "q1 in two rows": lambda: dhlab.DHRobot.from_table([("q1", 0, 1, 0), ("q1", 0, 1, 0)]),
    "DHRobot(None)": lambda: dhlab.DHRobot(None),
    "params='abc'": lambda: dhlab.DHRobot([dhlab.RevoluteDH()], params="abc"),
    "joint_symbols=5": lambda: dhlab.DHRobot([dhlab.RevoluteDH()], joint_symbols=5),
    "same joint symbol twice": lambda: dhlab.DHRobot([dhlab.RevoluteDH()] * 2, joint_symbols=["q", "q"]),
    "symbolic base": lambda: dhlab.DHRobot([dhlab.RevoluteDH()], base=sp.eye(4) * sp.Symbol("x")),
    "deg2rad(None)": lambda: deg2rad(None),
    "deg2rad('abc')": lambda: deg2rad("abc"),
    "ragged deg": lambda: deg2rad([[1, 2], [3]]),
    "ragged rad": lambda: dhlab.rad2deg([[1, 2], [3]]),
    "compact of None": lambda: dhlab.compact(None, ["q1"]),
    "compact with unknown names": lambda: dhlab.compact(robots.puma560().fk_sym(), ["x"]),
    "DHTable(None)": lambda: dhlab.DHTable(None),
    "inv(sp.eye(3))": lambda: inv(sp.eye(3)),
    "inv of a non-rigid sympy matrix": lambda: inv(sp.diag(2, 1, 1, 1)),
    "inv of a 5x5": lambda: inv(sp.eye(5)),
    "is_rigid(T, tol=None)": lambda: dhlab.is_rigid(np.eye(4), tol=None),
    "A('1')": lambda: robots.puma560().A("1"),
    "A(1.5)": lambda: robots.puma560().A(1.5),
    "IK with None": lambda: dhlab.ik.pr_mechanism_ik(robots.pr_mechanism(), None, 0.1),
    "IK with text": lambda: dhlab.ik.pr_mechanism_ik(robots.pr_mechanism(), "1", 0.1),
    "IK with a symbol": lambda: dhlab.ik.pr_mechanism_ik(robots.pr_mechanism(), sp.Symbol("x"), 0.1),
    "IK with tol=None": lambda: dhlab.ik.pr_mechanism_ik(robots.pr_mechanism(), 1, 0.1, tol=None),
    "IK with a negative tol": lambda: dhlab.ik.pr_mechanism_ik(robots.pr_mechanism(), 1, 0.1, tol=-1),
    "IK with a nan tol": lambda: dhlab.ik.pr_mechanism_ik(robots.pr_mechanism(), 1, 0.1, tol=np.nan),
    "IK of another robot": lambda: dhlab.ik.pr_mechanism_ik(robots.puma560(), 1, 0.1),
    "joint_axes(None)": lambda: dhlab.joint_axes(None),
    "Rz(sp.Integer(500))": lambda: Rz(sp.Integer(500)),
    "alpha=sp.Float(90)": lambda: dhlab.RevoluteDH(alpha=sp.Float(90)),
    "d=sp.nan": lambda: dhlab.RevoluteDH(d=sp.nan),
    "complex array": lambda: robots.puma560().fk(np.zeros(6, dtype=complex)),
    "datetime array": lambda: robots.puma560().fk(np.zeros(6, dtype="datetime64[s]")),
    "masked values": lambda: robots.puma560().fk(np.ma.array(np.zeros(6), mask=[0, 0, 1, 0, 0, 0])),
    "text in trans": lambda: trans(sp.Symbol("x"), "y", 0),
    "deg2rad() inside a numpy array, prismatic":
        lambda: robots.seed002_4dof().fk(np.array([deg2rad(10), deg2rad(30), 0.2, 0])),
    "negated deg2rad(), prismatic": lambda: robots.seed002_4dof().fk([deg2rad(10), -deg2rad(30), 0.2, 0]),
    "deg2rad() in a nested batch, prismatic":
        lambda: robots.seed002_4dof().fk([[0, 0.1, 0.2, 0], [0, deg2rad(3), 0, 0]]),
    "fk_sym timeout of -1": lambda: robots.puma560().fk_sym(timeout=-1),
}


@pytest.mark.parametrize("case", sorted(KNOWN_BAD_INPUTS))
def test_known_bad_inputs_are_refused_clearly(case):
    with pytest.raises(DHLabError) as error:
        KNOWN_BAD_INPUTS[case]()
    assert len(str(error.value)) > 20


def test_what_is_right_next_to_them_still_works():
    puma = robots.puma560()
    assert puma.fk(np.zeros((0, 6))).shape == (0, 4, 4)                 # an empty batch: no poses
    assert deg2rad(sp.Symbol("x")) == sp.Symbol("x") * sp.pi / 180          # symbolic degrees stay exact
    assert isinstance(-deg2rad(30), type(deg2rad(30))) and repr(-deg2rad(30)) == "deg2rad(-30)"
    assert dhlab.compact(puma.fk_sym(simplify=True), ["q1", "q2", "q3"]).has(sp.Symbol("C1"))
    assert Rz(sp.pi / 2)[0, 1] == -1                                      # sympy numbers stay exact
    np.testing.assert_allclose(puma.A(2, np.array([0.3])), puma.A(2, 0.3))
    sols = dhlab.ik.pr_mechanism_ik({"l1": 1.0, "l2": 0.5}, 2.0, 0.25, tol=0)
    assert len(sols) == 2


# --- values too large for a length: refused at the boundary, not overflowed ----------------------
@pytest.mark.parametrize("value", [1e308, -1e308, 1e200])
def test_a_prismatic_value_too_large_is_refused_not_overflowed(value):
    robot = robots.seed002_4dof()                       # joints 2 and 3 are prismatic
    with pytest.raises(DHLabError, match=r"q\[1\] \(joint 2, prismatic\) = .* too large for a length"):
        robot.fk([0.0, value, 0.0, 0.0])
    with pytest.raises(DHLabError, match="too large for a length"):
        robot.fk([[0.0, 0.1, 0.2, 0.0], [0.0, 0.1, value, 0.0]])
    np.testing.assert_allclose(robot.fk([0.0, 1e100, 0.0, 0.0])[:3, 3].max(), 1e100, rtol=1e-9)


def test_a_length_too_large_is_named():
    from dhlab.validation import LARGEST_LENGTH, as_length
    assert as_length(LARGEST_LENGTH, "d") == LARGEST_LENGTH
    for value in (1e200, -1e308, sp.Float("1e300")):
        with pytest.raises(DHLabError, match=r"^d = .* too large for a length: at most 1e\+150"):
            as_length(value, "d")
    with pytest.raises(DHLabError, match="too large for a length"):
        dhlab.RevoluteDH(a=1e308)


def test_a_decimal_too_large_for_a_float_is_named_as_such():
    from decimal import Decimal

    from dhlab.validation import as_number
    with pytest.raises(DHLabError, match=r"Decimal\('1E\+400'\) is too large"):
        as_number(Decimal("1e400"), "x")
    with pytest.raises(DHLabError, match="x is inf"):
        as_number(Decimal("Infinity"), "x")


def test_dhlab_validation_error_keeps_its_name_and_every_check_stays_importable():
    import dhlab.validation as validation
    assert DHLabError.__module__ == "dhlab.validation" and validation.DHLabError is DHLabError
    assert all(hasattr(validation, name) for name in validation.__all__)
    from dhlab.errors import DHLabError as ground_error
    from dhlab.units import Angle, has_angle_mark
    from dhlab.validation.marks import Angle as marked
    from dhlab.validation.marks import has_angle_mark as marks
    assert ground_error is DHLabError and Angle is marked and has_angle_mark is marks
