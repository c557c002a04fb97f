"""dhlab's forward kinematics against an established library, roboticstoolbox-python,
building the same DH tables. Runs when that toolbox is installed (``make bench RTB=1``
installs it); skipped otherwise."""
import numpy as np
import pytest
import sympy as sp

from dhlab import robots

rtb = pytest.importorskip("roboticstoolbox")


def rtb_copy(robot):
    """The same DH table, link by link, as a Robotics Toolbox DHRobot."""
    def num(v):     # a table entry as a number, the robot's parameters substituted
        return float(v.subs({s: robot.params[str(s)] for s in v.free_symbols})) if isinstance(v, sp.Basic) else float(v)

    links = []
    for link in robot.links:
        if link.is_revolute:
            links.append(rtb.RevoluteDH(d=num(link.d), a=num(link.a), alpha=num(link.alpha), offset=num(link.offset)))
        else:
            links.append(rtb.PrismaticDH(theta=num(link.theta), a=num(link.a), alpha=num(link.alpha),
                                         offset=num(link.offset), qlim=list(link.qlim)))
    return rtb.DHRobot(links, base=robot.base, tool=robot.tool)


@pytest.mark.parametrize("factory", [f for f in robots.catalogue().values()
                                     if f.__name__ in {"puma560", "ssrms", "seed002_4dof", "seed002_6dof",
                                                       "seed003_6dof", "prr_example", "rrr_example"}])
def test_same_poses_as_robotics_toolbox(factory):
    robot = factory()
    other = rtb_copy(robot)
    rng = np.random.default_rng(7)
    lo, hi = robot.qlim.T
    for q in lo + (hi - lo) * rng.random((100, robot.n)):
        np.testing.assert_allclose(robot.fk(q), other.fkine(q).A, atol=1e-10)


def test_puma560_matches_the_toolbox_model():
    ours, theirs = robots.puma560(floor=True), rtb.models.DH.Puma560()
    rng = np.random.default_rng(8)
    for q in rng.uniform(-2, 2, (100, 6)):
        np.testing.assert_allclose(ours.fk(q), theirs.fkine(q).A, atol=1e-10)
