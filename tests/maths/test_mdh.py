"""Modified DH (Craig): the link matrix, robots built from modified tables, converting tables both
ways (same end-effector pose at every configuration), checked against Craig's closed-form PUMA
and, when roboticstoolbox-python is installed, against its RevoluteMDH links and MDH models."""
import numpy as np
import pytest
import sympy as sp

import dhlab
from dhlab import DHLabError, DHRobot, MDHRobot, PrismaticMDH, RevoluteMDH, robots, to_modified, to_standard
from dhlab.dh import PrismaticDH, RevoluteDH
from dhlab.mdh import mdh_matrix, to_modified_rows, to_standard_rows

RNG = np.random.default_rng(19)


def _dh_robots():
    """Every DH-table robot of the catalogue (the others are products of motions, not tables)."""
    out = [(name, f()) for name, f in robots.catalogue().items()]
    return [(name, r) for name, r in out if isinstance(r, DHRobot)]


def _poses(robot, count=100):
    lo, hi = robot.qlim.T
    return lo + (hi - lo) * RNG.random((count, robot.n))


# --- the link matrix -----------------------------------------------------------------------------
def test_link_matrix_is_craigs_closed_form():
    """Craig (Introduction to Robotics, eq. 3.6), typed independently of the code."""
    th, d, a, al = sp.symbols("theta d a alpha", real=True)
    c, s, ca, sa = sp.cos(th), sp.sin(th), sp.cos(al), sp.sin(al)
    craig = sp.Matrix([[c, -s, 0, a], [s * ca, c * ca, -sa, -sa * d], [s * sa, c * sa, ca, ca * d], [0, 0, 0, 1]])
    assert sp.simplify(mdh_matrix(th, d, a, al) - craig) == sp.zeros(4, 4)


def test_symbolic_link_matrices_of_a_modified_robot():
    l1, l2 = sp.symbols("l1 l2")
    robot = MDHRobot([RevoluteMDH(d=l1), RevoluteMDH(a=l2, alpha=sp.pi / 2, offset=sp.pi / 2)],
                     params={"l1": 0.7, "l2": 0.3})
    q1, q2 = robot.q_symbols
    assert sp.simplify(robot.A(1) - mdh_matrix(q1, l1, 0, 0)) == sp.zeros(4, 4)
    assert sp.simplify(robot.A(2) - mdh_matrix(q2 + sp.pi / 2, 0, l2, sp.pi / 2)) == sp.zeros(4, 4)
    T = robot.fk_sym()
    q = np.array([0.4, -1.1])
    numeric = np.array(T.subs({q1: q[0], q2: q[1], l1: 0.7, l2: 0.3}).evalf(), dtype=float)
    np.testing.assert_allclose(numeric, robot.fk(q), atol=1e-12)
    simple = robot.fk_sym(simplify=True)
    np.testing.assert_allclose(np.array(simple.subs({q1: q[0], q2: q[1], l1: 0.7, l2: 0.3}).evalf(), dtype=float),
                               robot.fk(q), atol=1e-12)


def test_prismatic_link_moves_along_its_own_z():
    link = PrismaticMDH(theta=0.3, a=0.2, alpha=-0.5)
    np.testing.assert_allclose(link.A(0.4), mdh_matrix(0.3, 0.4, 0.2, -0.5), atol=1e-15)


# --- converting: the same end effector at every configuration ------------------------------------
@pytest.mark.parametrize("name, robot", _dh_robots(), ids=[n for n, _ in _dh_robots()])
def test_every_catalogue_robot_converts_both_ways(name, robot):
    modified = to_modified(robot)
    assert isinstance(modified, MDHRobot) and all(isinstance(l, (RevoluteMDH, PrismaticMDH)) for l in modified.links)
    Q = _poses(robot)
    np.testing.assert_allclose(modified.fk(Q), robot.fk(Q), atol=1e-9)
    back = to_standard(modified)
    np.testing.assert_allclose(back.fk(Q), robot.fk(Q), atol=1e-9)
    # joint i's axis is z_(i−1) in standard DH and z_i in modified DH: the same lines
    F_std, F_mod = robot.frames(Q[:10]), modified.frames(Q[:10])
    np.testing.assert_allclose(F_mod[:, 1:, :3, 2], F_std[:, :-1, :3, 2], atol=1e-9)
    assert [str(l.qlim) for l in modified.links] == [str(l.qlim) for l in robot.links]


def _random_dh_robot(n):
    links = []
    for _ in range(n):
        d, a = RNG.uniform(-1, 1, 2)
        alpha, angle = RNG.uniform(-np.pi, np.pi, 2)
        links.append(RevoluteDH(d=d, a=a, alpha=alpha, offset=angle) if RNG.random() < 0.7
                     else PrismaticDH(theta=angle, a=a, alpha=alpha, offset=d))
    base = dhlab.Rz(RNG.uniform(-3, 3)) @ dhlab.trans(*RNG.uniform(-1, 1, 3)) @ dhlab.Rx(RNG.uniform(-3, 3))
    tool = dhlab.Ry(RNG.uniform(-3, 3)) @ dhlab.trans(*RNG.uniform(-1, 1, 3))
    return DHRobot(links, base=base, tool=tool)


@pytest.mark.parametrize("n", [1, 2, 3, 5, 7])
def test_random_tables_with_base_and_tool_convert_both_ways(n):
    for _ in range(5):
        robot = _random_dh_robot(n)
        modified = to_modified(robot)
        Q = _poses(robot, 30)
        np.testing.assert_allclose(modified.fk(Q), robot.fk(Q), atol=1e-9)
        # and from the modified side: a modified robot whose a_0, α_0 are not 0 (the base takes them)
        shifted = MDHRobot([RevoluteMDH(d=0.2, a=0.4, alpha=0.9)] + list(modified.links[1:]),
                           base=robot.base, tool=robot.tool)
        np.testing.assert_allclose(to_standard(shifted).fk(Q), shifted.fk(Q), atol=1e-9)


def test_the_leftover_goes_into_the_tool_and_the_base():
    robot = DHRobot([RevoluteDH(a=1.0), RevoluteDH(a=0.5, alpha=np.pi / 2)])
    modified = to_modified(robot)
    np.testing.assert_allclose(modified.tool, dhlab.trans(0.5, 0, 0) @ dhlab.Rx(np.pi / 2), atol=1e-15)
    np.testing.assert_allclose(modified.base, np.eye(4))
    first = MDHRobot([RevoluteMDH(a=0.3, alpha=0.2), RevoluteMDH(d=0.1)])
    np.testing.assert_allclose(to_standard(first).base, dhlab.Rx(0.2) @ dhlab.trans(0.3, 0, 0), atol=1e-15)


def test_typed_rows_convert_both_ways():
    rows = [("q1", "l1", 0, 90), ("q2 + 90", 0, "l2", 0), ("q3 - 90", 0, 0, -90), ("q4 - 90", "l3", 0, -90),
            ("q5", 0, 0, 90), ("q6", "l4", 0.1, 30)]
    params = {"l1": 1.0, "l2": 2.0, "l3": 3.0, "l4": 4.0}
    standard = DHRobot.from_table(rows, params=params)
    modified_rows, (a_n, alpha_n) = to_modified_rows(rows)
    assert (a_n, alpha_n) == (0.1, 30)
    tool = dhlab.trans(0.1, 0, 0) @ dhlab.Rx(dhlab.deg2rad(30))
    modified = MDHRobot.from_table(modified_rows, params=params, tool=tool)
    Q = _poses(standard)
    np.testing.assert_allclose(modified.fk(Q), standard.fk(Q), atol=1e-9)
    back, leftover = to_standard_rows(modified_rows)
    assert leftover == (0, 0)
    assert back[:-1] == rows[:-1] and back[-1] == ("q6", "l4", 0, 0)


def test_modified_table_display():
    robot = to_modified(robots.seed002_4dof())
    text = str(robot.table())
    assert text.splitlines()[0].split("|")[3].strip() == "a_(i−1)"
    assert "modified DH" in repr(robot.table()) and "modified DH" in robot.table()._repr_html_()
    assert "d2" in text and "q4" in text


# --- Craig's PUMA 560 (modified DH, Introduction to Robotics, sec. 3.7): the closed form -----------
A2, A3, D3, D4 = 0.4318, 0.0203, 0.15005, 0.4318


def _craig_puma():
    """Craig's table (α_(i−1), a_(i−1), d_i, θ_i), typed here in the course's column order."""
    return MDHRobot.from_table([("q1", 0, 0, 0), ("q2", 0, 0, -90), ("q3", D3, A2, 0), ("q4", D4, A3, -90),
                                ("q5", 0, 0, 90), ("q6", 0, 0, -90)], name="PUMA 560 (Craig)")


def _craig_T06(q):
    """⁰T₆ as printed by Craig (eq. 3.14 and the r_ij before it)."""
    c = lambda *k: np.cos(sum(q[i - 1] for i in k))
    s = lambda *k: np.sin(sum(q[i - 1] for i in k))
    c1, s1, c2, s2, c4, s4, c5, s5, c6, s6 = c(1), s(1), c(2), s(2), c(4), s(4), c(5), s(5), c(6), s(6)
    c23, s23 = c(2, 3), s(2, 3)
    r11 = c1 * (c23 * (c4 * c5 * c6 - s4 * s6) - s23 * s5 * c6) + s1 * (s4 * c5 * c6 + c4 * s6)
    r21 = s1 * (c23 * (c4 * c5 * c6 - s4 * s6) - s23 * s5 * c6) - c1 * (s4 * c5 * c6 + c4 * s6)
    r31 = -s23 * (c4 * c5 * c6 - s4 * s6) - c23 * s5 * c6
    r12 = c1 * (c23 * (-c4 * c5 * s6 - s4 * c6) + s23 * s5 * s6) + s1 * (c4 * c6 - s4 * c5 * s6)
    r22 = s1 * (c23 * (-c4 * c5 * s6 - s4 * c6) + s23 * s5 * s6) - c1 * (c4 * c6 - s4 * c5 * s6)
    r32 = -s23 * (-c4 * c5 * s6 - s4 * c6) + c23 * s5 * s6
    r13 = -c1 * (c23 * c4 * s5 + s23 * c5) - s1 * s4 * s5
    r23 = -s1 * (c23 * c4 * s5 + s23 * c5) + c1 * s4 * s5
    r33 = s23 * c4 * s5 - c23 * c5
    px = c1 * (A2 * c2 + A3 * c23 - D4 * s23) - D3 * s1
    py = s1 * (A2 * c2 + A3 * c23 - D4 * s23) + D3 * c1
    pz = -A3 * s23 - A2 * s2 - D4 * c23
    return np.array([[r11, r12, r13, px], [r21, r22, r23, py], [r31, r32, r33, pz], [0, 0, 0, 1]])


def test_craigs_puma_table_gives_craigs_closed_form():
    robot = _craig_puma()
    for q in RNG.uniform(-np.pi, np.pi, (50, 6)):
        np.testing.assert_allclose(robot.fk(q), _craig_T06(q), atol=1e-12)


def test_craigs_puma_in_standard_dh_has_the_same_poses():
    modified = _craig_puma()
    standard = to_standard(modified)
    Q = RNG.uniform(-np.pi, np.pi, (50, 6))
    np.testing.assert_allclose(standard.fk(Q), np.array([_craig_T06(q) for q in Q]), atol=1e-12)


# --- wrong input: a clear error -------------------------------------------------------------------
def test_conventions_are_not_mixed():
    with pytest.raises(DHLabError, match="modified-DH .*MDHRobot"):
        DHRobot([RevoluteDH(a=1), RevoluteMDH(a=1)])
    with pytest.raises(DHLabError, match="standard DH link.*to_modified"):
        MDHRobot([RevoluteDH(a=1)])
    with pytest.raises(DHLabError, match="already in the other convention"):
        to_modified(to_modified(robots.puma560()))
    with pytest.raises(DHLabError, match="already in the other convention"):
        to_standard(robots.puma560())
    for junk in (None, "puma", [RevoluteMDH()], robots.pr_mechanism()):
        with pytest.raises(DHLabError):
            to_modified(junk)
        with pytest.raises(DHLabError):
            to_standard(junk)


@pytest.mark.parametrize("rows", [None, "q1 0 0 0", [], [("q1", 0, 0)], [("q1", 0, 0, 0, 0)], 5, {"a": 1}])
def test_bad_rows_are_refused(rows):
    for fn in (to_modified_rows, to_standard_rows, MDHRobot.from_table):
        with pytest.raises(DHLabError, match="row|table"):
            fn(rows)


@pytest.mark.parametrize("kwargs", [{"d": float("nan")}, {"a": "l1"}, {"alpha": 90}, {"offset": 1 + 2j},
                                    {"a": dhlab.deg2rad(30)}, {"qlim": (1, 0)}, {"d": None}])
def test_bad_link_parameters_are_refused(kwargs):
    with pytest.raises(DHLabError):
        RevoluteMDH(**kwargs)


# --- the Robotics Toolbox (skipped when roboticstoolbox-python is not installed) --------------------
def _rtb_modified_copy(rtb, robot):
    """The same modified table, link by link, as Robotics Toolbox RevoluteMDH / PrismaticMDH links."""
    num = lambda v: float(v.subs({s: robot.params[str(s)] for s in v.free_symbols})) if isinstance(v, sp.Basic) \
        else float(v)
    links = []
    for link in robot.links:
        if link.is_revolute:
            links.append(rtb.RevoluteMDH(d=num(link.d), a=num(link.a), alpha=num(link.alpha), offset=num(link.offset)))
        else:
            links.append(rtb.PrismaticMDH(theta=num(link.theta), a=num(link.a), alpha=num(link.alpha),
                                          offset=num(link.offset), qlim=list(link.qlim)))
    return rtb.DHRobot(links, base=robot.base, tool=robot.tool)


@pytest.mark.parametrize("name, robot", _dh_robots(), ids=[n for n, _ in _dh_robots()])
def test_converted_robots_match_the_toolbox_mdh_links(name, robot):
    rtb = pytest.importorskip("roboticstoolbox")
    modified = to_modified(robot)
    theirs = _rtb_modified_copy(rtb, modified)
    assert theirs.mdh
    for q in _poses(robot, 50):
        np.testing.assert_allclose(modified.fk(q), theirs.fkine(q).A, atol=1e-10)


@pytest.mark.parametrize("model", ["Panda", "AL5D"])
def test_toolbox_mdh_models_built_from_their_tables(model):
    rtb = pytest.importorskip("roboticstoolbox")
    theirs = getattr(rtb.models.DH, model)()
    assert theirs.mdh
    ours = MDHRobot([RevoluteMDH(d=l.d, a=l.a, alpha=l.alpha, offset=l.offset) for l in theirs.links],
                    base=theirs.base.A, tool=theirs.tool.A)
    for q in RNG.uniform(-np.pi, np.pi, (50, theirs.n)):
        np.testing.assert_allclose(ours.fk(q), theirs.fkine(q).A, atol=1e-10)
        np.testing.assert_allclose(to_standard(ours).fk(q), theirs.fkine(q).A, atol=1e-10)


# --- the DH checkers recognise a modified-DH answer and say so ----------------------------------------
from dhlab.course.exercises import (  # noqa: E402
    check_dh_row,
    check_link_matrix,
    check_table,
    link_exercise_robot,
    row_exercise_frames,
)

ARM = [("q1", 0.5, 0.2, -90), ("q2 - 90", 0, 0.5, 0), ("q3", 0, 0, -90), ("q4", 0.5, 0, 0)]


@pytest.mark.parametrize("exercise, rows", [("arm", ARM), ("seed002_4dof", [("q1", "l1", 0, 0), (90, "d2", 0, 90),
                                                                         (0, "d3", 0, 0), ("q4", "l4", 0, 0)])])
def test_check_table_names_a_modified_table(exercise, rows):
    modified, leftover = to_modified_rows(rows)
    assert leftover == (0, 0)                       # both robots' end effectors need no tool
    orders = {"": lambda r: r, "Craig's column order": lambda r: (r[3], r[2], r[1], r[0]),
              "(a_(i−1), α_(i−1), θ_i, d_i)": lambda r: (r[2], r[3], r[0], r[1])}
    for words, reorder in orders.items():
        feedback = check_table([reorder(r) for r in modified], exercise)
        assert feedback.status == "wrong"
        text = " ".join(feedback.items)
        assert "modified DH (Craig)" in text and "standard DH" in text and words in text


def test_check_table_keeps_its_own_feedback_for_other_mistakes():
    wrong = [("q1", 0.5, 0.2, -90), ("q2 - 90", 0, 0.5, 0), ("q3", 0, 0, 90), ("q4", 0.5, 0, 0)]
    feedback = check_table(wrong)
    assert feedback.status == "wrong" and "modified" not in " ".join(feedback.items)
    modified, _ = to_modified_rows(wrong)          # a wrong table is wrong in both conventions
    assert "modified DH (Craig)" not in " ".join(check_table(modified).items)
    assert check_table(ARM).status == "correct"


def test_check_dh_row_names_a_modified_row():
    before, _ = row_exercise_frames()
    after = before @ mdh_matrix(np.pi, 0.3, 0.4, 0)      # frames a Craig row and a standard row both reach
    feedback = check_dh_row((180, 0.3, 0.4, 0), (before, after))
    assert feedback.status == "wrong" and "modified DH (Craig)" in feedback.items[0]
    assert check_dh_row((180, 0.3, -0.4, 0), (before, after)).status == "correct"
    assert "modified" not in " ".join(check_dh_row((120, 0.3, 0.4, 90)).items)


def test_check_link_matrix_names_the_modified_product():
    robot = link_exercise_robot()
    link, q = robot.links[1], robot.q_symbols[1]
    feedback = check_link_matrix(mdh_matrix(q + link.offset, link.d, link.a, link.alpha))
    assert feedback.status == "wrong" and "modified DH (Craig)" in " ".join(feedback.items)
    assert check_link_matrix(robot.A(2)).status == "correct"
