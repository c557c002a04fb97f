"""The mechanism drawing: links along their d and a segments, joints by type, a gripper,
triads with letters, the colour-blind palette (dhlab.views.mechanism, dhlab.views.triads)."""
import numpy as np
import pytest

import dhlab
from dhlab import robots
from dhlab.errors import DHLabError
from dhlab.views import triads
from dhlab.views.mechanism import CYLINDER_HALF, Mechanism
from dhlab.views.view import robot_view

DH_ROBOTS = [robots.ssrms, robots.puma560, robots.seed002_4dof, robots.seed002_6dof, robots.seed003_6dof,
             robots.prr_example, robots.rrr_example]


def random_q(robot, rng):
    lo, hi = robot.qlim.T
    return lo + (hi - lo) * rng.random(robot.n)


def segments(path):
    """The pieces of a NaN-broken path: a list of (k, 3) arrays."""
    pieces, current = [], []
    for p in path:
        if np.isnan(p).any():
            if current:
                pieces.append(np.array(current))
            current = []
        else:
            current.append(p)
    if current:
        pieces.append(np.array(current))
    return pieces


@pytest.mark.parametrize("make", DH_ROBOTS, ids=lambda f: f.__name__)
def test_dh_links_run_along_d_then_a(make):
    """Link i is drawn O_(i-1) → O_(i-1) + d_i z_(i-1) → O_i, the last leg along x_i with length |a_i|."""
    robot = make()
    view = robot_view(robot)
    rng = np.random.default_rng(3)
    for _ in range(3):
        q = random_q(robot, rng)
        view.update(q)
        F = robot.frames(q)
        pieces = segments(view.shape.path)
        assert len(pieces) == robot.n
        for i, piece in enumerate(pieces, start=1):
            np.testing.assert_allclose(piece[0], F[i - 1][:3, 3], atol=1e-9)
            np.testing.assert_allclose(piece[-1], F[i][:3, 3], atol=1e-9)
            # the knee: where d ends and a starts
            A = np.linalg.inv(F[i - 1]) @ F[i]
            d, a = A[2, 3], np.hypot(A[0, 3], A[1, 3])
            knee = F[i - 1][:3, 3] + d * F[i - 1][:3, 2]
            on_path = np.min(np.linalg.norm(piece - knee, axis=1))
            assert on_path < 1e-9, f"link {i}: the knee O_(i-1) + d z_(i-1) is not on the drawn path"
            np.testing.assert_allclose(np.linalg.norm(F[i][:3, 3] - knee), a, atol=1e-9)


@pytest.mark.parametrize("make", DH_ROBOTS, ids=lambda f: f.__name__)
def test_revolute_joints_are_cylinders_on_their_axes(make):
    robot = make()
    size = 2.0
    m = Mechanism(robot, size)
    q = random_q(robot, np.random.default_rng(4))
    F = robot.frames(q)
    shape = m.shape(F, q)
    per = m.faces_per_joint
    for j in range(robot.n):
        if not robot.links[j].is_revolute:
            continue
        solid = shape.faces[j * per:(j + 1) * per]
        corners = solid.reshape(-1, 3)
        centre = solid[-2:].reshape(-1, 3).mean(axis=0)           # between the two end caps
        axis = F[j][:3, 2]
        np.testing.assert_allclose(centre, F[j][:3, 3], atol=1e-9)        # centred on O_(j)
        along = (corners - centre) @ axis
        np.testing.assert_allclose(np.abs(along).max(), CYLINDER_HALF * size, rtol=1e-9)


def test_prismatic_joint_carriage_shows_the_joint_value():
    """seed 002's R-P-P-R: the carriage of joint 2 sits at O_1 + d2 z_1, and moves with q2."""
    robot = robots.seed002_4dof()
    m = Mechanism(robot, 1.0)
    per = m.faces_per_joint
    for q2 in (robot.links[1].qlim[0], np.mean(robot.links[1].qlim), robot.links[1].qlim[1]):
        q = np.array([0.3, q2, np.mean(robot.links[2].qlim), 0.2])
        F = robot.frames(q)
        shape = m.shape(F, q)
        carriage = shape.faces[per + 6:per + 8, :4].reshape(-1, 3).mean(axis=0)   # its two end caps
        A = np.linalg.inv(F[1]) @ F[2]
        np.testing.assert_allclose(carriage, F[1][:3, 3] + A[2, 3] * F[1][:3, 2], atol=1e-9)
        sleeve = shape.faces[per:per + 2, :4]                     # its two end caps: at O_1 and at the knee
        np.testing.assert_allclose(sleeve[0].mean(axis=0), F[1][:3, 3], atol=1e-9)
        np.testing.assert_allclose(sleeve[1].mean(axis=0), F[1][:3, 3] + A[2, 3] * F[1][:3, 2], atol=1e-9)


def test_gripper_points_along_the_approach_vector():
    robot = robots.ssrms()
    view = robot_view(robot, dhlab.deg2rad([10, 20, 30, 40, 50, 60, 70]))
    g = view.shape.gripper
    end = view.frames[-1]
    stem = g[1] - g[0]
    np.testing.assert_allclose(g[0], end[:3, 3], atol=1e-12)
    np.testing.assert_allclose(stem / np.linalg.norm(stem), end[:3, 2], atol=1e-9)   # a = z_7


def test_stick_style_stays_one_option_away():
    view = robot_view(robots.puma560(), style="stick")
    assert view.mechanism is None and view.joint_solids is None
    with pytest.raises(DHLabError, match="style"):
        robot_view(robots.puma560(), style="cylinders")


def test_letters_sit_past_the_tips_and_follow_the_labels():
    robot = robots.puma560()
    view = robot_view(robot)
    for k, mark in enumerate(view.letter_marks):
        pts = np.column_stack(mark.get_data_3d())
        tips = view.frames[:, :3, 3] + view.triad_length * view.frames[:, :3, k]
        assert np.all(np.linalg.norm(pts - tips, axis=1) > 0.1 * view.triad_length)
        assert mark.get_visible()
    view.show_labels(False)
    assert not any(m.get_visible() for m in view.letter_marks)


def test_colorblind_palette():
    try:
        triads.set_palette("colorblind")
        view = robot_view(robots.puma560())
        assert [line.get_color() for line in view.axis_lines] == list(triads.PALETTES["colorblind"])
        assert robot_view(robots.puma560(), palette="seed").colors == triads.PALETTES["seed"]
    finally:
        triads.set_palette("seed")
    with pytest.raises(DHLabError, match="palette"):
        triads.set_palette("rainbow")


def test_triads_are_sized_from_the_robot():
    small, big = robots.puma560(), robots.ssrms()
    assert robot_view(big).triad_length > 10 * robot_view(small).triad_length


@pytest.mark.parametrize("name", ["ssrms", "puma560", "seed002_4dof", "seed003_6dof", "pr_mechanism",
                                  "robot_no_tan_elemental_2"])
def test_frame_labels_keep_off_the_joints(name):
    """No frame label is drawn over a joint's solid or the gripper (their outline points)."""
    from dhlab.views import framing
    from dhlab.views.panels.teach import teach

    robot = robots.catalogue()[name]()
    panel = teach(robot, backend="image")
    lo, hi = robot.qlim.T
    rng = np.random.default_rng(5)
    for k in range(3):
        if k:
            panel.set_q(lo + (hi - lo) * rng.random(robot.n))
        view = panel.view
        view.live.png()
        boxes = view.labels.boxes()
        pts = (framing.projected(view.ax, view.shape.outline) if view.ax.name == "3d"
               else view.ax.transData.transform(view.shape.outline[:, :2]))
        covered = ((pts[:, None, 0] > boxes[None, :, 0]) & (pts[:, None, 0] < boxes[None, :, 2])
                   & (pts[:, None, 1] > boxes[None, :, 1]) & (pts[:, None, 1] < boxes[None, :, 3]))
        assert not covered.any(), f"pose {k}: a label covers {int(covered.any(axis=1).sum())} points of the joints"
    panel.close()
