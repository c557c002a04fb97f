"""Random junk into every public maths entry point: a DHLabError or a correct result, nothing else.

Hypothesis draws values of every kind a student or a script can pass by mistake —
None, True, text, complex numbers, Decimals, dates, huge integers, nan and inf,
sympy's nan/zoo/I and symbols, ragged and nested lists, numpy arrays of every
dtype (masked, complex, boolean, dates), deg2rad() values — alone or mixed with good
values. Every call must either raise :class:`dhlab.DHLabError` or return a result
that passes a check of its own (right shape, finite, rigid …). Any other
exception, or a numpy warning (turned into an error here), fails the test.
"""
import datetime
import warnings
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import dhlab
from dhlab import DHLabError, deg2rad, rad2deg, robots
from dhlab.chain import Link, Move, Robot, Rot
from dhlab.transforms import Rx, Ry, Rz, Tx, Tz, dh_matrix, inv, is_rigid, rpy, trans

FAST = settings(max_examples=30, deadline=None, suppress_health_check=list(HealthCheck), database=None)

# --- the junk ------------------------------------------------------------------------------
finite = st.floats(-10, 10, allow_nan=False)
numbers = st.one_of(
    finite, st.integers(-10, 10), st.floats(allow_nan=True, allow_infinity=True),
    st.integers(min_value=-10**400, max_value=10**400), st.just(deg2rad(30)), st.just(-deg2rad(45)),
    st.sampled_from([np.float32(0.5), np.int64(2), np.float64(np.nan), Fraction(1, 3), Decimal("0.25"),
                     Decimal("NaN"), sp.Integer(500), sp.Float(90), sp.Rational(1, 2), sp.pi / 4]),
)
oddities = st.sampled_from([
    None, True, False, np.bool_(True), "1", "abc", "", b"1", 1 + 2j, np.complex128(1), datetime.date(2020, 1, 1),
    datetime.timedelta(1), np.datetime64("2020-01-01"), sp.nan, sp.zoo, sp.oo, sp.I, sp.Symbol("x"),
    sp.Symbol("q1") + 1, {}, {"a": 1}, set(), object(), np.ma.masked, [], [[]], sp.Matrix([1, 2]),
])
scalars = st.one_of(numbers, oddities)


def arrays_of(shape):
    """numpy arrays of a shape, of several dtypes, sometimes masked or marked as angles."""
    good = st.lists(finite, min_size=int(np.prod(shape)), max_size=int(np.prod(shape))).map(
        lambda v: np.array(v, dtype=float).reshape(shape))
    return st.one_of(
        good,
        good.map(lambda a: a.astype(complex)),
        good.map(lambda a: a > 0),
        good.map(lambda a: np.ma.array(a, mask=np.zeros(a.shape, bool) | (a > 5))),
        good.map(lambda a: a.astype(object)),
        good.map(lambda a: np.array(a, dtype="datetime64[s]") if a.size else a),
        good.map(deg2rad),
        good.map(lambda a: np.where(a > 5, np.nan, a)),
    )


def vectors(n):
    """Joint vectors of n values (or nearly: n ± 1), batches, nested lists, mixed junk."""
    return st.one_of(
        st.lists(scalars, min_size=max(n - 1, 0), max_size=n + 1),
        st.lists(st.lists(finite, min_size=n, max_size=n), min_size=0, max_size=3),
        st.lists(st.lists(scalars, min_size=n, max_size=n), min_size=1, max_size=2),
        st.lists(st.one_of(finite, st.just(deg2rad(10))), min_size=n, max_size=n).map(np.array),
        arrays_of((n,)), arrays_of((2, n)), arrays_of((0, n)), scalars,
    )


matrices = st.one_of(
    arrays_of((4, 4)), arrays_of((3, 3)), arrays_of((4, 4, 1)), scalars,
    st.lists(st.lists(scalars, min_size=4, max_size=4), min_size=4, max_size=4),
    st.sampled_from([sp.eye(3), sp.eye(5), sp.eye(4), sp.diag(2, 1, 1, 1), sp.eye(4) * sp.Symbol("x"),
                     sp.Matrix(4, 4, lambda i, j: sp.zoo if i == j == 0 else int(i == j)),
                     np.eye(4), Rz(0.3) @ trans(1, 2, 3)]),
)


def outcome(fn, *args, **kwargs):
    """Call fn: its result, or None when it refused with a DHLabError. Anything else fails the test."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")        # numpy's overflow or complex-to-real warnings are bugs here
        try:
            return fn(*args, **kwargs)
        except DHLabError as error:
            assert str(error), "a DHLabError must say what went wrong"
            return None


def assert_pose(T):
    T = np.asarray(T, dtype=float)
    assert T.shape[-2:] == (4, 4) and np.isfinite(T).all()
    for M in T.reshape(-1, 4, 4):
        assert is_rigid(M, tol=1e-6)


# --- numbers and transforms ----------------------------------------------------------------------
@FAST
@given(st.one_of(scalars, st.lists(scalars, max_size=3), st.lists(st.lists(finite, max_size=2), max_size=3)))
def test_deg_and_rad(x):
    for fn in (deg2rad, rad2deg):
        out = outcome(fn, x)
        if out is not None and not isinstance(out, sp.Basic):
            assert np.isfinite(out).all()


@FAST
@given(scalars)
def test_rotations(angle):
    for fn in (Rx, Ry, Rz):
        out = outcome(fn, angle)
        if out is not None:
            M = np.array(sp.Matrix(out).evalf(subs={s: 0.1 for s in out.free_symbols}), dtype=float) \
                if isinstance(out, sp.MatrixBase) else out
            assert_pose(M)
            if not isinstance(angle, sp.Basic):
                assert abs(float(angle)) <= 2 * np.pi + 1e-9


@FAST
@given(scalars, scalars, scalars, scalars)
def test_translations_and_dh_matrix(a, b, c, d):
    for fn, args in ((trans, (a, b, c)), (Tz, (a, b)), (Tx, (a, b)), (dh_matrix, (a, b, c, d))):
        out = outcome(fn, *args)
        if out is not None and not isinstance(out, sp.MatrixBase):
            assert_pose(out)
        if isinstance(out, sp.MatrixBase):
            assert not out.has(sp.nan, sp.zoo, sp.oo, sp.I)
            assert not any(isinstance(s, sp.Symbol) and s.name in ("1", "abc") for s in out.free_symbols)


@FAST
@given(matrices, st.one_of(st.just(1e-9), scalars))
def test_matrix_functions(T, tol):
    out = outcome(inv, T)
    if out is not None:
        if isinstance(out, sp.MatrixBase):
            assert out.shape == (4, 4)
            if not out.free_symbols:
                np.testing.assert_allclose(np.array((out * sp.Matrix(T)).evalf(), dtype=float), np.eye(4), atol=1e-9)
        else:
            np.testing.assert_allclose(out @ np.asarray(T, dtype=float), np.eye(4), atol=1e-9)
    rigid = outcome(is_rigid, T, tol)
    assert rigid in (None, True, False)
    checked = outcome(dhlab.check_rigid, T)
    if checked is not None:
        assert_pose(checked)
    angles = outcome(rpy, T)
    if angles is not None:
        assert len(angles) == 3 and np.isfinite(angles).all()


# --- robots -----------------------------------------------------------------------------------------
ROBOTS = {name: factory() for name, factory in robots.catalogue().items()}


@FAST
@given(st.sampled_from(sorted(ROBOTS)), st.data())
def test_fk_and_frames(name, data):
    robot = ROBOTS[name]
    q = data.draw(vectors(robot.n))
    for fn in (robot.fk, robot.frames):
        out = outcome(fn, q)
        if out is not None:
            assert_pose(out)
            Q = np.asarray(q, dtype=float)
            assert out.shape[:-2] == Q.shape[:-1] + ((robot.n + 1,) if fn == robot.frames else ())


@FAST
@given(st.sampled_from(sorted(ROBOTS)), scalars, st.one_of(st.none(), scalars, st.lists(scalars, max_size=2)))
def test_link_matrix(name, i, q):
    out = outcome(ROBOTS[name].A, i, q)
    if out is not None and not isinstance(out, sp.MatrixBase):
        assert_pose(out)


@FAST
@given(scalars, scalars, scalars, scalars, st.one_of(st.none(), st.tuples(scalars, scalars), scalars))
def test_dh_links_and_robots(d, a, alpha, offset, qlim):
    for cls, kwargs in ((dhlab.RevoluteDH, dict(d=d, a=a, alpha=alpha, offset=offset, qlim=qlim)),
                        (dhlab.PrismaticDH, dict(theta=d, a=a, alpha=alpha, offset=offset, qlim=qlim))):
        link = outcome(cls, **kwargs)
        if link is None:
            continue
        lo, hi = link.qlim
        assert np.isfinite([lo, hi]).all() and lo < hi
        if link.is_revolute:
            assert max(abs(lo), abs(hi)) <= 2 * np.pi + 1e-9
        robot = outcome(dhlab.DHRobot, [link])
        if robot is not None:
            assert_pose(robot.fk(robot.qz))


@FAST
@given(st.one_of(st.none(), scalars, st.lists(st.lists(st.one_of(scalars, st.sampled_from(
    ["q1", "q2", "q1 + 90", "l1", "-l1", "1/0", "1e400", "q1 q2", "__import__('os')", "θ2 − 90"])),
    min_size=3, max_size=5), max_size=3)),
    st.sampled_from(["deg", "rad", None, "degrees", 5]),
    st.one_of(st.none(), st.lists(st.tuples(scalars, scalars), max_size=3), scalars),
    st.one_of(st.none(), st.just({"l1": 1.0}), st.just("abc"), st.just({"l1": "x"}), st.just({5: 1})))
def test_from_table(rows, angles, qlim, params):
    robot = outcome(dhlab.DHRobot.from_table, rows, angles=angles, qlim=qlim, params=params)
    if robot is not None:
        assert_pose(robot.fk(robot.qz))
        assert len(set(robot.q_symbols)) == robot.n
        str(robot.table())


@FAST
@given(st.one_of(st.none(), scalars, st.lists(st.one_of(scalars, st.just(dhlab.RevoluteDH())), max_size=3)),
       st.one_of(st.none(), scalars, st.lists(scalars, max_size=3)),
       st.one_of(st.none(), matrices), st.one_of(st.none(), scalars, st.just({"l1": 2})))
def test_robot_constructors(links, joint_symbols, base, params):
    robot = outcome(dhlab.DHRobot, links, joint_symbols=joint_symbols, base=base, params=params)
    if robot is not None:
        assert_pose(robot.fk(robot.qz))
        assert len(set(robot.q_symbols)) == robot.n


@FAST
@given(st.sampled_from(["x", "y", "z", "w", None, 1]), scalars, st.one_of(st.booleans(), scalars),
       st.one_of(st.sampled_from([1, -1]), scalars), st.one_of(st.none(), st.tuples(scalars, scalars), scalars))
def test_chain_api(axis, value, joint, sign, qlim):
    for factory in (Rot, Move):
        factor = outcome(factory, axis, value, joint=joint, sign=sign)
        if factor is None:
            continue
        fixed = outcome(factory, "z", value)
        factors = [factor] + ([Rot("z", joint=True)] if not factor.joint else [])
        link = outcome(Link, factors + ([fixed] if fixed is not None else []), qlim=qlim)
        if link is None:
            continue
        robot = outcome(Robot, [link], params={"l1": 0.5})
        if robot is not None:
            assert_pose(robot.fk(robot.qz))
            assert_pose(robot.fk(robot.qlim[:, 1]))


# --- symbolic, tables, inverse kinematics, axes --------------------------------------------------------
@FAST
@given(st.one_of(st.none(), scalars, st.just(ROBOTS["puma560"].A(1)), st.just(sp.Matrix([[sp.cos(sp.Symbol("q1"))]]))),
       st.one_of(st.none(), scalars, st.lists(st.sampled_from(["q1", "q2", 5, None, sp.Symbol("q1")]), max_size=2)))
def test_compact_and_legend(M, q):
    for fn in (dhlab.compact, dhlab.legend):
        outcome(fn, M, q)


@FAST
@given(st.one_of(st.booleans(), scalars), st.one_of(st.none(), scalars))
def test_fk_sym_options(simplify, timeout):
    out = outcome(ROBOTS["robot_no_tan_elemental_1"].fk_sym, simplify=simplify, timeout=timeout)
    if out is not None:
        assert out.shape == (4, 4)


@FAST
@given(st.one_of(st.none(), scalars, st.sampled_from(list(ROBOTS.values())),
                 st.just({"l1": 1.0, "l2": 0.5}), st.just({"l1": 1.0})), scalars, scalars,
       st.one_of(st.just(1e-12), scalars))
def test_pr_mechanism_ik(robot, x, y, tol):
    sols = outcome(dhlab.ik.pr_mechanism_ik, robot, x, y, tol=tol)
    if sols is not None:
        pr = robots.pr_mechanism(**({"l1": 1.0, "l2": 0.5} if isinstance(robot, dict) else robot.params))
        for q in sols:
            np.testing.assert_allclose(pr.fk(q)[:2, 3], [float(x), float(y)], atol=1e-6)


@FAST
@given(st.one_of(st.none(), scalars, st.sampled_from(list(ROBOTS.values()))), st.data())
def test_joint_axes_and_tables(robot, data):
    q = data.draw(st.one_of(st.none(), vectors(robot.n if isinstance(robot, Robot) else 2)))
    out = outcome(dhlab.joint_axes, robot, q)
    if out is not None:
        axes, tool = out
        assert len(axes) == robot.n
        assert_pose(tool)
    outcome(dhlab.DHTable, robot)


def test_a_long_chain_is_fast_and_bounded():
    """Long general chains symbolically, in seconds (speed is measured in
    benchmarks/bench_symbolic.py); simplify stops with a clear DHLabError when its time runs out."""
    chain = dhlab.DHRobot([dhlab.RevoluteDH(a=0.1, alpha=deg2rad(30))] * 7)
    q = np.linspace(-1, 1, chain.n)
    for T in (chain.fk_sym(), chain.fk_sym(simplify=True)):
        f = sp.lambdify(chain.q_symbols, T, cse=True)
        np.testing.assert_allclose(np.array(f(*q), dtype=float), chain.fk(q), atol=1e-9)
    long_chain = dhlab.DHRobot([dhlab.RevoluteDH(a=0.1, alpha=deg2rad(30))] * 12)
    assert long_chain.fk_sym().shape == (4, 4)
    with pytest.raises(DHLabError, match="ran out of time.*timeout"):
        long_chain.fk_sym(simplify=True, timeout=1e-9)
