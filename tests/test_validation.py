"""Bad input gets a clear DHLabError at the boundary: which value, what was expected, how to fix it."""
import numpy as np
import pytest
import sympy as sp

import dhlab
from dhlab import DHLabError, deg, robots
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
    with pytest.raises(DHLabError, match=r"joint 2, revolute\) is 90 rad.*dhlab.deg\(90\)"):
        puma.fk([0, 90, 0, 0, 0, 0])
    with pytest.raises(DHLabError, match=r"dhlab.deg\(45\)"):
        Rz(45)
    with pytest.raises(DHLabError, match=r"alpha = 90 rad is more than a full turn.*dhlab.deg\(90\)"):
        dhlab.RevoluteDH(alpha=90)
    # the same values in radians are fine
    puma.fk(deg([0, 90, 0, 0, 0, 0]))
    Rz(deg(45))


def test_prismatic_joint_given_an_angle():
    robot = robots.seed002_4dof()
    with pytest.raises(DHLabError, match=r"q\[1\] = deg\(30\) is an angle, but joint 2 is prismatic"):
        robot.fk([deg(10), deg(30), 0.2, 0])
    with pytest.raises(DHLabError, match="made with dhlab.deg\\(\\), but joint 2 is prismatic"):
        robot.fk(deg([10, 30, 20, 0]))
    with pytest.raises(DHLabError, match="d is a length, but you gave an angle"):
        dhlab.RevoluteDH(d=deg(30))
    robot.fk([deg(10), 0.3, 0.2, deg(5)])   # the right way


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
