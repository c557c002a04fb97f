"""The family of assignment robots: published tables, drawn axes, link points, valid answers.

The ground truth is the published DH table run by dhlab's own DHRobot (an implementation
independent of the family's batched product); every other model — the reference solution
with frame 0 the world frame, dh_from_axes on the drawn axes, random valid DH frames —
must move like it: the same joint axes (as lines) and the same end point at random q.
"""
import math

import numpy as np
import pytest

from dhlab import DHLabError
from dhlab.assignment import family as fam
from dhlab.assignment import reference as puma
from dhlab.assignment.model import build, physical_frames, random_frames_from_axes, rows_from_frames
from dhlab.assignment.reference import dh_frames
from dhlab.dh import DHRobot
from dhlab.dh_frames import dh_from_axes
from support.robot_motion import assert_same_motion, random_q

KEYS = fam.family_names()


@pytest.mark.parametrize("key", KEYS)
def test_published_table_is_what_dhrobot_computes(key):
    """The family's batched product equals dhlab's DHRobot on the published table (typed as rows)."""
    s = fam.spec(key)
    table = []
    for j, (kind, theta, d, a, alpha) in enumerate(s.rows, start=1):
        table.append((f"q{j} + {theta}", d, a, alpha) if kind == "R" else (theta, f"q{j}", a, alpha))
    published = DHRobot.from_table(table)
    rows = [(1, j, math.radians(th), d, a, math.radians(al)) for j, (_, th, d, a, al) in enumerate(s.rows)]
    rng = np.random.default_rng(1)
    Q = rng.uniform(-1.5, 1.5, (10, s.n))
    for j, kind in enumerate(s.kinds):
        if kind == "P":
            Q[:, j] = rng.uniform(*s.qlim[j], 10)
    ours = dh_frames(rows, s.kinds, Q)[:, -1]
    np.testing.assert_allclose(ours, np.array([published.fk(q) for q in Q]), atol=1e-12)


def test_plain_puma_is_the_seed_exercise():
    """The family's PUMA at its defaults is the PUMA of the existing assignment."""
    ours, ref = build("puma560"), puma.reference()
    for a, b in zip(ours.axes, ref.axes):
        assert a.distance_to_point(b.point) < 1e-12
        np.testing.assert_allclose(a.direction, b.direction, atol=1e-12)
    np.testing.assert_allclose(ours.end_point, ref.wrist_centre, atol=1e-12)
    np.testing.assert_allclose(ours.world_points(0), ref.world_points(0), atol=1e-12)  # the pedestal


@pytest.mark.parametrize("key", KEYS)
def test_reference_solution_moves_like_the_published_robot(key):
    robot = build(key)
    Q = random_q(robot, np.random.default_rng(2))
    truth = physical_frames(robot, Q)
    np.testing.assert_allclose(robot.home_frames[0], np.eye(4))            # frame 0 = the world frame
    assert_same_motion(robot, truth, robot.frames(Q), robot.kinds)
    P, D = robot.axes_at(Q)                                                  # drawn senses included
    np.testing.assert_allclose(np.sum(D * truth[:, :-1, :3, 2], axis=2), robot._geometry.senses[None] *
                               np.ones((len(Q), 1)), atol=1e-9)


@pytest.mark.parametrize("key", KEYS)
def test_dh_from_axes_on_the_drawn_axes_reproduces_the_robot(key):
    """What the student is given (the axes table) is enough: dh_from_axes builds a valid DH model
    whose forward kinematics is the published table's, for every choice of its options."""
    robot = build(key)
    Q = random_q(robot, np.random.default_rng(3))
    truth = physical_frames(robot, Q)
    axes = [(ax.point, ax.direction, kind) for ax, kind in zip(robot.axes, robot.kinds)]
    for options in ({}, {"case1": "z_prev x z"}, {"case1": "z x z_prev", "parallel": "zero_d"},
                    {"prismatic": "through_origin"}):
        rebuilt = dh_from_axes(axes, robot.end_point, **options)
        frames = np.array([rebuilt.frames(q) for q in Q])
        assert_same_motion(robot, truth, frames, robot.kinds)


@pytest.mark.parametrize("key", KEYS)
def test_every_valid_assignment_moves_the_same(key):
    """Random valid DH frames (z reversed, x the other way, origins slid, prismatic lines moved,
    the last x turned): their rows, with joint signs, give the same axes, end point and link points."""
    robot = build(key)
    rng = np.random.default_rng(4)
    Q = random_q(robot, rng, 10)
    truth = physical_frames(robot, Q)
    ref_frames = robot.frames(Q)
    for _ in range(25):
        frames = random_frames_from_axes(robot, rng)
        rows = rows_from_frames(robot, frames)
        mine = dh_frames(rows, robot.kinds, Q)
        assert_same_motion(robot, truth, mine, robot.kinds)
        for k in range(robot.n + 1):                    # link k's points ride on its frame k
            local = (robot.world_points(k) - frames[k][:3, 3]) @ frames[k][:3, :3]
            placed = np.einsum("nij,pj->npi", mine[:, k, :3, :3], local) + mine[:, k, None, :3, 3]
            ref_local = robot.local_points(k)
            ref_placed = np.einsum("nij,pj->npi", ref_frames[:, k, :3, :3], ref_local) + ref_frames[:, k, None, :3, 3]
            np.testing.assert_allclose(placed, ref_placed, atol=1e-9)


def test_a_wrong_row_is_caught():
    """The checks above can fail: a frame chain with one α flipped does not move like the robot."""
    robot = build("kr5")
    Q = random_q(robot, np.random.default_rng(5), 10)
    rows = list(robot.rows)
    sign, j, th, d, a, al = rows[2]
    rows[2] = (sign, j, th, d, a, -al)
    with pytest.raises(AssertionError):
        assert_same_motion(robot, physical_frames(robot, Q), dh_frames(rows, robot.kinds, Q), robot.kinds)


@pytest.mark.parametrize("key", KEYS)
def test_links_points_and_tables(key):
    robot = build(key)
    assert len(robot.points) == robot.n + 1 == len(robot.link_names)
    assert all(len(link) >= 2 for link in robot.points)
    labels = {}
    for link in robot.points:                           # one label, one place
        for name, p in link:
            assert np.allclose(labels.setdefault(name, p), p)
    table = robot.axes_table()
    assert len(table.rows) == robot.n + 1 and "joint 1" in repr(table) and "<table>" in table._repr_html_()
    for (_, _, where, _), axis in zip(table.rows, robot.axes):           # the named point is on the axis
        xyz = np.array([float(v) for v in where.split("(")[1].rstrip(")").split(",")])
        assert axis.distance_to_point(xyz) < 1e-5
    assert len(robot.points_table().rows) == sum(len(link) for link in robot.points)


def test_figure_is_a_picture():
    fig = build("cobra600").figure()
    assert fig.axes and fig.axes[0].name == "3d"
    texts = {t.get_text() for t in fig.axes[0].texts}
    assert {"J1", "J2", "J3", "J4"} <= texts


def test_unknown_robot_is_a_clear_error():
    with pytest.raises(DHLabError, match="no robot 'puma'.*choose one of puma560"):
        fam.spec("puma")
