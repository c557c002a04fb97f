"""dh_from_axes: DH frames placed by rules 1–9 from the joint axes, checked against known robots.

The axes always come from a robot whose kinematics we trust (its frames at some
configuration); the rebuilt robot must have the same forward kinematics for every q.
"""
import math
import re

import numpy as np
import pytest
import sympy as sp

from dhlab import DHLabError, DHRobot, PrismaticDH, RevoluteDH, deg2rad, robots
from dhlab.dh_frames import dh_assignment, dh_from_axes, joint_axes
from dhlab.transforms import Rx, trans

RNG = np.random.default_rng(20260505)


# --------------------------------------------------------------------------------------
# helpers
# --------------------------------------------------------------------------------------
def random_q(robot, count, rng=RNG):
    lo, hi = robot.qlim.T
    return lo + (hi - lo) * rng.random((count, robot.n))


def random_rigid(rng=RNG, spread=1.0):
    """A random proper rigid transform (rotation from a random unit quaternion)."""
    w, x, y, z = rng.normal(size=4) / 1.0
    norm = math.sqrt(w * w + x * x + y * y + z * z)
    w, x, y, z = w / norm, x / norm, y / norm, z / norm
    R = np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                  [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                  [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = R, rng.uniform(-spread, spread, 3)
    return T


def num(value, params=None):
    return float(sp.sympify(value).subs(params or {}))


def rows(robot):
    """(θ or θ offset, d or d offset, a, α) per link, as floats (radians)."""
    out = []
    num = lambda value: float(sp.sympify(value).subs(robot.params))
    for link in robot.links:
        if link.is_revolute:
            out.append((num(link.offset), num(link.d), num(link.a), num(link.alpha)))
        else:
            out.append((num(link.theta), num(link.offset), num(link.a), num(link.alpha)))
    return np.array(out)


def wrap(angle):
    """Angles in (−π, π]."""
    return -((-np.asarray(angle) + np.pi) % (2 * np.pi) - np.pi)


def assert_same_fk(new, old, count=120, signs=None, q0=None, atol=1e-9, position_only=False):
    """new.fk(q) == old.fk(q0 + signs·q) at random q (within both robots' limits)."""
    signs = np.ones(new.n) if signs is None else np.asarray(signs, dtype=float)
    q0 = np.zeros(new.n) if q0 is None else np.asarray(q0, dtype=float)
    Q = random_q(new, count)
    Q_old = q0 + signs * Q
    A, B = new.fk(Q), old.fk(Q_old)
    if position_only:
        A, B = A[:, :3, 3], B[:, :3, 3]
    np.testing.assert_allclose(A, B, atol=atol, rtol=0)


def assert_on_axes(robot, axes):
    """At q = 0 each z_{i-1} of robot lies on joint i's given line, with the given direction."""
    F = robot.frames(robot.qz)
    for i, (p, u, _) in enumerate(axes):
        u = np.asarray(u, float) / np.linalg.norm(u)
        w = F[i][:3, 3] - np.asarray(p, float)
        assert np.linalg.norm(w - (w @ u) * u) < 1e-9 * max(1.0, np.linalg.norm(p)), f"O{i} off joint {i + 1}'s axis"
        np.testing.assert_allclose(F[i][:3, 2], u, atol=1e-12, err_msg=f"z{i} is not joint {i + 1}'s direction")


# --------------------------------------------------------------------------------------
# SSRMS and PUMA 560: the tables rebuilt from their axes
# --------------------------------------------------------------------------------------
@pytest.mark.parametrize("case1", ["z_prev x z", "z x z_prev", "nearest"])
@pytest.mark.parametrize("factory", [robots.ssrms, robots.puma560, lambda: robots.puma560(floor=True)],
                         ids=["ssrms", "puma560", "puma560_floor"])
def test_rebuilt_fk_equals_original(factory, case1):
    original = factory()
    axes, tool = joint_axes(original)
    rebuilt = dh_from_axes(axes, tool, case1=case1, qlim=original.qlim)
    assert isinstance(rebuilt, DHRobot)
    assert_on_axes(rebuilt, axes)
    np.testing.assert_allclose(rebuilt.fk(rebuilt.qz), tool, atol=1e-12)
    assert_same_fk(rebuilt, original, count=150)


EXACT = [(robots.ssrms, "z x z_prev"), (robots.ssrms, "nearest"),
         (robots.puma560, "nearest"), (lambda: robots.puma560(floor=True), "nearest")]


@pytest.mark.parametrize("factory, case1", EXACT,
                         ids=["ssrms-seed000", "ssrms-nearest", "puma-nearest", "puma_floor-nearest"])
def test_table_reproduced_exactly(factory, case1):
    """With the original's sign for x_i in case 1 and the origins at the joints (seed rule 6),
    every entry of the table comes back, offsets included."""
    original = factory()
    rebuilt = dh_from_axes(*joint_axes(original), case1=case1)
    np.testing.assert_allclose(rows(rebuilt), rows(original), atol=1e-12)
    assert str(rebuilt.table()).replace("q", "θ") == str(original.table()).replace("q", "θ")
    np.testing.assert_array_equal(rebuilt.base, original.base)
    np.testing.assert_array_equal(rebuilt.tool, np.eye(4))


@pytest.mark.parametrize("factory", [robots.ssrms, robots.puma560], ids=["ssrms", "puma560"])
def test_default_table_agrees_up_to_the_free_choices(factory):
    """Default sign x_i = z_{i-1} × z_i: |a|, |d| and |α| are forced by the geometry; α's sign
    and θ's offset may change only where x_i's sign was free (case 1, and frame n)."""
    original = factory()
    rebuilt = dh_from_axes(*joint_axes(original), case1="z_prev x z")
    new, old = rows(rebuilt), rows(original)
    np.testing.assert_allclose(np.abs(new[:, 1:3]), np.abs(old[:, 1:3]), atol=1e-12)   # |d|, |a|
    np.testing.assert_allclose(np.abs(new[:, 3]), np.abs(old[:, 3]), atol=1e-12)       # |α|
    steps = rebuilt.assignment.steps
    for i in range(1, rebuilt.n + 1):
        if steps[i].case in (2, 3):                       # x_i forced: from z_{i-1} towards z_i
            assert new[i - 1, 2] > 0 and np.isclose(new[i - 1, 3], old[i - 1, 3])
        if steps[i].case == 1:                            # the default sign: sin α_i > 0
            assert math.sin(new[i - 1, 3]) > 0
    # offsets differ by 0 or 180° only (x_i reversed or not)
    turn = np.abs(wrap(new[:, 0] - old[:, 0]))
    assert np.all(np.isclose(turn, 0) | np.isclose(turn, np.pi))


def test_ssrms_seed_claims():
    """Seed 000: case 1 for x1, x2, x5, x6; case 2 for x3, x4; case 3 never — at q = 0 and
    at random configurations (the relations between axes do not depend on q)."""
    ssrms = robots.ssrms()
    for q in [ssrms.qz] + list(random_q(ssrms, 25)):
        report = dh_assignment(*joint_axes(ssrms, q))
        assert report.cases == [1, 1, 2, 2, 1, 1]
        relations = [s.relation for s in report.steps[1:-1]]
        assert relations == ["intersecting"] * 2 + ["parallel"] * 2 + ["intersecting"] * 2
        assert 3 not in report.cases
        assert report.steps[-1].relation == "coincident"          # the end effector on z6 (d7 = a7 = 0)
        np.testing.assert_allclose(rows(report.robot)[:, 2], [0, 0, 12, 12, 0, 0, 0], atol=1e-9)


def test_puma_has_one_skew_pair():
    """The PUMA's z2 and z3 are skew (a3 = 0.0203 and d3 = 0.15005 from their common normal)."""
    report = dh_assignment(*joint_axes(robots.puma560()))
    assert report.cases == [1, 2, 3, 1, 1]
    assert report.steps[3].relation == "skew"
    assert "skew" in report.steps[3].why and "0.0203" in report.steps[3].why


def test_zero_d_choice_for_parallel_axes():
    """parallel='zero_d': the common normal through O_{i-1}, so d3 = d4 = 0 and the SSRMS's
    6 + 1 + 6 along the parallel axes collects in d5 = 13."""
    rebuilt = dh_from_axes(*joint_axes(robots.ssrms()), parallel="zero_d", case1="z x z_prev")
    d = rows(rebuilt)[:, 1]
    np.testing.assert_allclose(d, [2.5, 6, 0, 0, 13, 6, 0], atol=1e-12)
    assert "d3 = 0" in rebuilt.assignment.steps[3].origin_choice
    assert_same_fk(rebuilt, robots.ssrms())


# --------------------------------------------------------------------------------------
# The given direction is the positive sense of the new joint variable
# --------------------------------------------------------------------------------------
def test_reversed_direction_negates_that_joint():
    puma = robots.puma560()
    axes, tool = joint_axes(puma)
    flipped = [(p, -u if i in (1, 4) else u, k) for i, (p, u, k) in enumerate(axes)]
    rebuilt = dh_from_axes(flipped, tool)
    assert_on_axes(rebuilt, flipped)
    signs = [1, -1, 1, 1, -1, 1]
    assert_same_fk(rebuilt, puma, signs=signs)
    with pytest.raises(AssertionError):        # and not with the original senses
        assert_same_fk(rebuilt, puma, count=20)
    # a positive q2 on the new robot turns about the reversed axis: the right-hand rule about -z1
    q = np.zeros(6)
    q[1] = 0.3
    np.testing.assert_allclose(rebuilt.fk(q), puma.fk(-q), atol=1e-12)


def test_points_anywhere_on_the_axis_and_any_direction_length():
    ssrms = robots.ssrms()
    axes, tool = joint_axes(ssrms)
    moved = [(p + RNG.uniform(-30, 30) * u, RNG.uniform(0.01, 100) * u, k) for p, u, k in axes]
    for parallel in ("at_joint", "zero_d"):
        rebuilt = dh_from_axes(moved, tool, parallel=parallel)
        assert_on_axes(rebuilt, moved)
        assert_same_fk(rebuilt, ssrms, atol=1e-8)
        assert rebuilt.assignment.cases == [1, 1, 2, 2, 1, 1]


def test_puma_in_another_world_frame():
    """Move every point, direction and the tool by a random rigid G: same rows after the
    first (only frame 0 depends on the world frame), and fk = G · original fk."""
    puma = robots.puma560()
    axes, tool = joint_axes(puma)
    reference = dh_from_axes(axes, tool, case1="z_prev x z")
    for _ in range(5):
        G = random_rigid(spread=3.0)
        R, t = G[:3, :3], G[:3, 3]
        moved = [(R @ p + t, R @ u, k) for p, u, k in axes]
        rebuilt = dh_from_axes(moved, G @ tool, case1="z_prev x z")
        assert_on_axes(rebuilt, moved)
        np.testing.assert_allclose(rows(rebuilt)[1:], rows(reference)[1:], atol=1e-9)
        Q = random_q(puma, 100)
        np.testing.assert_allclose(rebuilt.fk(Q), G @ puma.fk(Q), atol=1e-9)
        assert rebuilt.assignment.cases == [1, 2, 3, 1, 1]


# --------------------------------------------------------------------------------------
# Every robot of the catalogue (DH or not) goes to DH form
# --------------------------------------------------------------------------------------
@pytest.mark.parametrize("name", sorted(robots.catalogue()))
def test_catalogue_robot_rebuilt(name):
    original = robots.catalogue()[name]()
    q0 = random_q(original, 1)[0] * 0.5
    for q_at in (original.qz, q0):
        axes, tool = joint_axes(original, q_at)
        rebuilt = dh_from_axes(axes, tool)
        assert_on_axes(rebuilt, axes)
        assert_same_fk(rebuilt, original, q0=q_at, count=100)
        point_only = dh_from_axes(axes, tool[:3, 3])
        assert_same_fk(point_only, original, q0=q_at, count=50, position_only=True)


def test_seed002_4dof_table_reproduced():
    """R-P-P-R: z0 = z1 and z2 = z3 are the same lines; origins at the joints give the seed's table."""
    robot = robots.seed002_4dof()
    rebuilt = dh_from_axes(*joint_axes(robot))
    np.testing.assert_allclose(rows(rebuilt), rows(robot), atol=1e-12)
    steps = rebuilt.assignment.steps
    assert [s.relation for s in steps[1:]] == ["coincident", "intersecting", "coincident", "coincident"]
    assert [link.is_prismatic for link in rebuilt.links] == [False, True, True, False]
    assert "002-n2" in " ".join(steps[2].notes)


# --------------------------------------------------------------------------------------
# Random robots, revolute and prismatic, with special and generic geometry
# --------------------------------------------------------------------------------------
def random_dh_robot(rng, n):
    links = []
    for _ in range(n):
        special = rng.random() < 0.5
        alpha = rng.choice([0.0, np.pi / 2, -np.pi / 2, np.pi]) if special else rng.uniform(-np.pi, np.pi)
        a = 0.0 if rng.random() < 0.35 else rng.uniform(-1, 1)
        d = 0.0 if rng.random() < 0.35 else rng.uniform(-1, 1)
        angle = rng.choice([0.0, np.pi / 2]) if special else rng.uniform(-np.pi, np.pi)
        if rng.random() < 0.3:
            links.append(PrismaticDH(theta=angle, a=a, alpha=alpha, offset=d, qlim=(-0.8, 0.8)))
        else:
            links.append(RevoluteDH(d=d, a=a, alpha=alpha, offset=angle))
    return DHRobot(links, base=random_rigid(rng), tool=random_rigid(rng, 0.5))


@pytest.mark.parametrize("seed", range(40))
def test_random_robots(seed):
    rng = np.random.default_rng(seed)
    original = random_dh_robot(rng, int(rng.integers(1, 8)))
    q_at = random_q(original, 1, rng)[0] * 0.5
    axes, tool = joint_axes(original, q_at)
    signs = np.where(rng.random(original.n) < 0.3, -1.0, 1.0)
    given = [(p + rng.uniform(-2, 2) * u, s * rng.uniform(0.05, 20) * u, k)
             for (p, u, k), s in zip(axes, signs)]
    case1 = ["z_prev x z", "z x z_prev", "nearest"][seed % 3]
    parallel = ["at_joint", "zero_d"][seed % 2]
    prismatic = ["given", "through_origin"][(seed // 2) % 2]
    report = dh_assignment(given, tool, case1=case1, parallel=parallel, prismatic=prismatic)
    rebuilt = report.robot
    assert rebuilt.assignment is report
    assert [l.is_revolute for l in rebuilt.links] == [l.is_revolute for l in original.links]
    if prismatic == "given":
        assert_on_axes(rebuilt, given)
    np.testing.assert_allclose(rebuilt.fk(rebuilt.qz), tool, atol=1e-9)
    # new q within ±π (revolute) or ±0.8 (prismatic) of the pose the axes were taken at
    lim = np.array([np.pi if l.is_revolute else 0.8 for l in original.links])
    Q = rng.uniform(-lim, lim, (100, original.n))
    np.testing.assert_allclose(rebuilt.fk(Q), original.fk(q_at + signs * Q), atol=1e-8)
    # the report: one step per frame, a row per joint, cases only for frames 1 … n-1
    assert len(report.steps) == original.n + 1 and all(s.row for s in report.steps[1:])
    assert report.steps[0].case is None and report.steps[-1].case is None
    assert all(c in (1, 2, 3) for c in report.cases)
    # rows with x_i forced (cases 2, 3 off the same line) have a_i > 0
    for step, link in zip(report.steps[1:-1], rebuilt.links):
        if step.relation in ("parallel", "skew"):
            assert num(link.a) > 0
        if step.relation in ("intersecting", "coincident"):
            assert num(link.a) == 0


def test_prismatic_lines_may_lie_anywhere():
    """Only a prismatic axis's direction matters (002-n2): its given point may be off the true
    line; 'through_origin' puts the line through the previous origin instead."""
    robot = robots.seed002_4dof()
    axes, tool = joint_axes(robot, [0.3, 0.2, 0.4, -0.5])
    shifted = [(p + (np.array([0.5, -0.2, 0.1]) if k == "P" else 0), u, k) for p, u, k in axes]   # off the line
    assert_same_fk(dh_from_axes(shifted, tool), robot, q0=[0.3, 0.2, 0.4, -0.5])
    rebuilt = dh_from_axes(shifted, tool, prismatic="through_origin")
    F = rebuilt.frames(rebuilt.qz)
    # z1 (joint 2, prismatic) passes through O0; z2 (joint 3) through O1
    for i in (1, 2):
        w = F[i - 1][:3, 3] - F[i][:3, 3]
        assert np.linalg.norm(np.cross(w, F[i][:3, 2])) < 1e-12
    assert "through the previous origin" in " ".join(rebuilt.assignment.steps[2].notes)
    assert_same_fk(rebuilt, robot, q0=[0.3, 0.2, 0.4, -0.5])


# --------------------------------------------------------------------------------------
# The end effector (rule 9) and the tool transform
# --------------------------------------------------------------------------------------
def test_tool_point_off_the_last_axis():
    axes = [((0, 0, 0), (0, 0, 1), "R"), ((1, 0, 0), (0, 0, 1), "R")]
    report = dh_assignment(axes, (1.5, 0.2, 0.3))
    link = report.robot.links[-1]
    assert report.steps[-1].relation == "parallel"
    assert num(link.a) == pytest.approx(math.hypot(0.5, 0.2)) and num(link.d) == pytest.approx(0.3)
    np.testing.assert_allclose(report.robot.fk([0, 0])[:3, 3], [1.5, 0.2, 0.3], atol=1e-12)


def test_tool_pose_not_along_the_last_axis_becomes_the_tool_transform():
    puma = robots.puma560()
    puma.tool = Rx(0.4) @ trans(0.01, 0.02, 0.1)
    axes, tool = joint_axes(puma)
    rebuilt = dh_from_axes(axes, tool)
    assert not np.allclose(rebuilt.tool, np.eye(4))
    assert "robot.tool" in " ".join(rebuilt.assignment.steps[-1].notes)
    assert_same_fk(rebuilt, puma)


def test_exact_angles_and_clean_numbers():
    rebuilt = dh_from_axes(*joint_axes(robots.puma560()), case1="nearest")
    assert rebuilt.links[0].alpha == sp.pi / 2 and rebuilt.links[2].alpha == -sp.pi / 2
    assert rebuilt.links[1].a == 0.4318 and rebuilt.links[0].d == 0
    ssrms = dh_from_axes(*joint_axes(robots.ssrms()), case1="z_prev x z")
    assert ssrms.links[0].offset == sp.pi        # the default sign turns x1 round: θ1 = q1 + 180°
    assert "q1 + 180°" in str(ssrms.table())


# --------------------------------------------------------------------------------------
# The report
# --------------------------------------------------------------------------------------
def test_report_text_and_html():
    robot = dh_from_axes(*joint_axes(robots.ssrms()), case1="z_prev x z")
    report = robot.assignment
    text = str(report)
    assert text.count("case 1") == 4 and text.count("case 2") == 2 and "case 3" not in text
    assert "x1 = z0 × z1" in text and "case1='z_prev x z'" in text
    assert "joint 4's given point" in text
    assert "row 3: θ = q3 + 180°, d = 6, a = 12, α = 0°" in text
    assert "rule 5" in text and "rule 9" in text
    html = report._repr_html_()
    assert html.startswith("<table>") and html.count("<tr>") == robot.n + 2
    assert "z2 ∥ z3" in html
    assert report.table().rows == robot.table().rows
    assert report.frames.shape == (8, 4, 4)
    assert report.check[0] < 1e-12 and report.check[1] < 1e-12


def test_report_marks_nearly_parallel_axes():
    axes = [((0, 0, 0), (0, 0, 1), "R"), ((1, 0, 0), (1e-6, 0, 1), "R")]
    report = dh_assignment(axes, (1, 0, 1))
    assert report.cases == [1]          # they do meet, a million units below
    assert "nearly parallel" in " ".join(report.steps[1].notes)
    relaxed = dh_assignment(axes, (1, 0, 1), tol=1e-5)
    assert relaxed.cases == [2]


# --------------------------------------------------------------------------------------
# Bad input: a clear DHLabError each
# --------------------------------------------------------------------------------------
GOOD = [((0, 0, 0), (0, 0, 1), "R"), ((0, 0, 1), (0, 1, 0), "R")]
TOOL = (0, 0, 2)


@pytest.mark.parametrize("axes, tool, message", [
    ([((0, 0, 0), (0, 0, 0), "R")], TOOL, "non-zero direction"),
    ([((0, 0, 0), (0, 0, 1), "r")], TOOL, "capitals: 'R'"),
    ([((0, 0, 0), (0, 0, 1), "p")], TOOL, "capitals: 'P'"),
    ([((0, 0, 0), (0, 0, 1), "revolute")], TOOL, "kind must be 'R' or 'P'"),
    ([((0, 0, 0), (0, 0, 1), 1)], TOOL, "kind must be 'R' or 'P'"),
    ([((0, 0), (0, 0, 1), "R")], TOOL, "3 numbers (x, y, z)"),
    ([((0, 0, 0), (0, 0, 1, 0), "R")], TOOL, "3 numbers (x, y, z)"),
    ([((0, np.nan, 0), (0, 0, 1), "R")], TOOL, "finite number"),
    ([((0, 0, 0), (0, np.inf, 1), "R")], TOOL, "finite number"),
    ([((0, "a", 0), (0, 0, 1), "R")], TOOL, "must be numbers"),
    ([((0, sp.Symbol("l1"), 0), (0, 0, 1), "R")], TOOL, "must be numbers"),
    ([], TOOL, "one (point, direction, kind) per joint"),
    ("RRR", TOOL, "one (point, direction, kind) per joint"),
    ([((0, 0, 0), (0, 0, 1))], TOOL, "must be (point, direction, kind)"),
    (GOOD, None, "tool is missing"),
    (GOOD, (0, 0), "pose (4x4) or point (x, y, z)"),
    (GOOD, np.eye(3), "pose (4x4) or point (x, y, z)"),
    (GOOD, (0, np.nan, 0), "finite number"),
    (GOOD, np.full((4, 4), np.nan), "not a finite number"),
    (GOOD, np.diag([1.0, 1.0, -1.0, 1.0]), "reflection"),
    (GOOD, np.diag([2.0, 1.0, 1.0, 1.0]), "not orthonormal"),
])
def test_bad_input(axes, tool, message):
    with pytest.raises(DHLabError, match=re.escape(message)):
        dh_from_axes(axes, tool)


@pytest.mark.parametrize("options, message", [
    (dict(qlim=[(-270, 270), (-1, 1)]), "more than one full turn"),
    (dict(qlim=[(-1, 1)]), "one (low, high) per joint"),
    (dict(qlim=[(1, -1), (-1, 1)]), "low < high"),
    (dict(case1="z1 x z0"), "case1 must be one of"),
    (dict(parallel="middle"), "parallel must be one of"),
    (dict(prismatic="anywhere"), "prismatic must be one of"),
    (dict(tol=0), "tol must be a small positive number"),
    (dict(tol="big"), "tol must be a small positive number"),
])
def test_bad_options(options, message):
    with pytest.raises(DHLabError, match=re.escape(message)):
        dh_from_axes(GOOD, TOOL, **options)


def test_the_unicode_cross_is_accepted():
    a = dh_from_axes(GOOD, TOOL, case1="z x z_prev")
    b = dh_from_axes(GOOD, TOOL, case1="z × z_prev")
    np.testing.assert_array_equal(rows(a), rows(b))


def test_degenerate_but_valid_axes_are_chosen_and_reported():
    """Coincident and parallel axes need a choice: not an error, a reported choice."""
    same_line = [((0, 0, 0), (0, 0, 1), "R"), ((0, 0, 5), (0, 0, 2), "R"), ((0, 0, 1), (0, 0, -1), "P")]
    report = dh_assignment(same_line, (0, 0, 3))
    assert [s.relation for s in report.steps[1:]] == ["coincident", "coincident", "coincident"]
    assert "same line" in report.steps[1].why and "opposite directions" in report.steps[2].why
    assert num(report.robot.links[1].alpha) == pytest.approx(math.pi)
    for q in RNG.uniform(-1, 1, (10, 3)):               # the point slides down z as q3 grows
        np.testing.assert_allclose(report.robot.fk(q)[:3, 3], [0, 0, 3 - q[2]], atol=1e-12)
    parallel = [((0, 0, 0), (0, 0, 1), "R"), ((2, 0, 7), (0, 0, 1), "R")]
    report = dh_assignment(parallel, (2, 0, 7))
    assert report.cases == [2] and "one is chosen" in report.steps[1].why


# --------------------------------------------------------------------------------------
# options of the wrong kind: refused by name, not by a raw TypeError
# --------------------------------------------------------------------------------------
@pytest.mark.parametrize("options, message", [
    (dict(tol="1e-9"), "tol must be a small positive number"),       # text was read by float()
    (dict(tol=True), "tol must be a small positive number"),
    (dict(tol=None), "tol must be a small positive number"),
    (dict(case1=["nearest"]), "case1 must be one of"),               # was TypeError: unhashable
    (dict(parallel={"a": 1}), "parallel must be one of"),
    (dict(qlim=np.array(5)), "one (low, high) per joint"),           # was TypeError: len() of 0-d
])
def test_options_of_the_wrong_kind_are_refused(options, message):
    with pytest.raises(DHLabError, match=re.escape(message)):
        dh_from_axes(GOOD, TOOL, **options)


def test_a_prismatic_joints_limits_made_with_deg_are_refused():
    axes = [((0, 0, 0), (0, 0, 1), "R"), ((1, 0, 0), (1, 0, 0), "P")]
    with pytest.raises(DHLabError, match=r"qlim\[1\] \(joint 2, prismatic\).*deg2rad\(\)"):
        dh_from_axes(axes, (2, 0, 0), qlim=[(-1, 1), (0.0, deg2rad(30))])
    assert dh_from_axes(axes, (2, 0, 0), qlim=[(deg2rad(-90), deg2rad(90)), (0.0, 0.5)]).qlim[1].tolist() == [0.0, 0.5]


def test_huge_coordinates_are_refused_and_huge_directions_normalised():
    with pytest.raises(DHLabError, match=r"axes\[0\] \(joint 1\) point = 1e\+308 is too large for a length"):
        dh_from_axes([((1e308, 0, 0), (0, 0, 1), "R")], (1, 0, 0))
    with pytest.raises(DHLabError, match="tool = 1e.308 is too large for a length"):
        dh_from_axes([((0, 0, 0), (0, 0, 1), "R")], (1e308, 0, 0))
    far = np.eye(4)
    far[0, 3] = 1e200
    with pytest.raises(DHLabError, match=r"tool \(its position\) = 1e\+200 is too large"):
        dh_from_axes([((0, 0, 0), (0, 0, 1), "R")], far)
    robot = dh_from_axes([((0, 0, 0), (0, 0, 1e308), "R")], (1, 0, 0))   # a direction: only its sense counts
    np.testing.assert_allclose(robot.fk(robot.qz), trans(1, 0, 0), atol=1e-12)
    assert np.isfinite(robot.fk([0.3])).all()
