"""Properties over random configurations, for every robot of the catalogue."""
import numpy as np
import pytest
import sympy as sp

import dhlab
from dhlab import robots
from dhlab.transforms import Rx, Ry, Rz, dh_matrix, inv, is_rigid, trans

CATALOGUE = robots.catalogue()
RNG = np.random.default_rng(2026)


def random_q(robot, count):
    lo, hi = robot.qlim.T
    return lo + (hi - lo) * RNG.random((count, robot.n))


@pytest.fixture(params=sorted(CATALOGUE), ids=str)
def robot(request):
    return CATALOGUE[request.param]()


def test_batch_equals_one_by_one(robot):
    Q = random_q(robot, 50)
    batch = robot.fk(Q)
    assert batch.shape == (50, 4, 4)
    for q, T in zip(Q, batch):
        np.testing.assert_allclose(robot.fk(q), T, atol=1e-12)
    frames = robot.frames(Q)
    assert frames.shape == (50, robot.n + 1, 4, 4)
    for q, F in zip(Q[:5], frames[:5]):
        np.testing.assert_allclose(robot.frames(q), F, atol=1e-12)


def test_frames_are_rigid_and_chain_to_fk(robot):
    for q in random_q(robot, 20):
        F = robot.frames(q)
        assert all(is_rigid(T) for T in F)
        np.testing.assert_allclose(F[0], robot.base, atol=1e-12)
        np.testing.assert_allclose(F[-1] @ robot.tool, robot.fk(q), atol=1e-12)
        for i in range(1, robot.n + 1):      # frame i = frame i-1 · A_i(q_i)
            np.testing.assert_allclose(F[i - 1] @ robot.A(i, q[i - 1]), F[i], atol=1e-12)


DH_ROBOTS = sorted(name for name, f in CATALOGUE.items() if isinstance(f(), dhlab.DHRobot))


@pytest.mark.parametrize("name", DH_ROBOTS)
def test_dh_fk_is_product_of_dh_matrices(name):
    robot = CATALOGUE[name]()
    for q in random_q(robot, 20):
        T = robot.base.copy()
        for link, qi in zip(robot.links, q):
            num = lambda v: float(sp.sympify(v).subs({s: robot.params[str(s)] for s in sp.sympify(v).free_symbols}))
            if link.is_revolute:
                A = dh_matrix(qi + num(link.offset), num(link.d), num(link.a), num(link.alpha))
            else:
                A = dh_matrix(num(link.theta), qi + num(link.offset), num(link.a), num(link.alpha))
            T = T @ A
        np.testing.assert_allclose(robot.fk(q), T @ robot.tool, atol=1e-12)


def test_symbolic_agrees_with_numeric(robot):
    for simplify in (False, True):
        T = robot.fk_sym(simplify=simplify)
        T = T.subs({s: robot.params[str(s)] for s in T.free_symbols if str(s) in robot.params})
        assert T.free_symbols <= set(robot.q_symbols)
        f = sp.lambdify(robot.q_symbols, T, "numpy")
        for q in random_q(robot, 5):
            np.testing.assert_allclose(np.array(f(*q), dtype=float), robot.fk(q), atol=1e-10)


def test_inverse_composes_to_identity():
    for _ in range(50):
        a, b, c = RNG.uniform(-np.pi, np.pi, 3)
        T = Rz(a) @ Ry(b) @ Rx(c) @ trans(*RNG.uniform(-5, 5, 3))
        np.testing.assert_allclose(inv(T) @ T, np.eye(4), atol=1e-12)
        np.testing.assert_allclose(T @ inv(T), np.eye(4), atol=1e-12)
    th, x = sp.symbols("theta x", real=True)
    S = Rz(th) * trans(x, 1, 2)
    assert sp.simplify(inv(S) * S) == sp.eye(4)


def test_seed000_tz_tx_are_the_dh_matrix():
    th, d, a, al = sp.symbols("theta d a alpha", real=True)
    assert sp.simplify(dhlab.Tz(th, d) * dhlab.Tx(al, a) - dh_matrix(th, d, a, al)) == sp.zeros(4)
    assert dhlab.Tz(th, d) == Rz(th) * trans(0, 0, d) == trans(0, 0, d) * Rz(th)
    assert dhlab.Tx(al, a) == trans(a, 0, 0) * Rx(al) == Rx(al) * trans(a, 0, 0)
    # rule 14: the closed form printed in seeds 002/003
    C, S = sp.cos, sp.sin
    printed = sp.Matrix([[C(th), -C(al) * S(th), S(al) * S(th), a * C(th)],
                         [S(th), C(al) * C(th), -S(al) * C(th), a * S(th)],
                         [0, S(al), C(al), d], [0, 0, 0, 1]])
    assert sp.expand(dh_matrix(th, d, a, al) - printed) == sp.zeros(4)


def test_numeric_and_symbolic_transforms_agree():
    x = sp.Symbol("x")
    for f in (Rx, Ry, Rz):
        v = RNG.uniform(-3, 3)
        np.testing.assert_allclose(np.array(f(x).subs(x, v), dtype=float), f(v), atol=1e-14)


def test_rpy_roundtrip():
    for _ in range(50):
        roll, yaw = RNG.uniform(-np.pi, np.pi, 2)
        pitch = RNG.uniform(-np.pi / 2 + 1e-3, np.pi / 2 - 1e-3)
        got = dhlab.rpy(Rz(yaw) @ Ry(pitch) @ Rx(roll))
        np.testing.assert_allclose(got, (roll, pitch, yaw), atol=1e-9)


def test_compared_with_an_independent_textbook_implementation():
    """A plain-loop reference (Modern Robotics style) on random DH tables with prismatic joints."""
    for _trial in range(20):
        n = RNG.integers(1, 8)
        kinds = RNG.integers(0, 2, n)
        params = RNG.uniform(-2, 2, (n, 4))
        links = [dhlab.RevoluteDH(d=p[1], a=p[2], alpha=p[3] % 3, offset=p[0] % 3) if k else
                 dhlab.PrismaticDH(theta=p[0] % 3, a=p[2], alpha=p[3] % 3, offset=p[1]) for k, p in zip(kinds, params)]
        robot = dhlab.DHRobot(links, base=Rz(0.3) @ trans(1, 2, 3), tool=Rx(0.2) @ trans(0, 0, 0.1))
        q = RNG.uniform(-3, 3, n)
        T = robot.base.copy()
        for k, p, qi in zip(kinds, params, q):
            theta, d = (qi + p[0] % 3, p[1]) if k else (p[0] % 3, qi + p[1])
            ct, st, ca, sa = np.cos(theta), np.sin(theta), np.cos(p[3] % 3), np.sin(p[3] % 3)
            T = T @ np.array([[ct, -st * ca, st * sa, p[2] * ct], [st, ct * ca, -ct * sa, p[2] * st],
                              [0, sa, ca, d], [0, 0, 0, 1]])
        np.testing.assert_allclose(robot.fk(q), T @ robot.tool, atol=1e-12)


def test_changing_base_or_tool_changes_fk():
    robot = robots.puma560()
    q = random_q(robot, 1)[0]
    before = robot.fk(q)
    robot.tool = trans(0, 0, 0.1)
    np.testing.assert_allclose(robot.fk(q), before @ trans(0, 0, 0.1), atol=1e-12)
    robot.base = Rz(0.5)
    np.testing.assert_allclose(robot.fk(q), Rz(0.5) @ before @ trans(0, 0, 0.1), atol=1e-12)
    np.testing.assert_allclose(robot.frames(q)[0], Rz(0.5), atol=1e-12)
    with pytest.raises(dhlab.DHLabError, match="tool transform is not a proper rigid transform"):
        robot.tool = np.diag([1.0, 1, -1, 1])
