"""The robot views draw what the kinematics say, move in place, and do not pile up."""
import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
import numpy as np
import pytest

import dhlab
from dhlab import robots
from dhlab.views.live.livefigure import LiveFigure, encode_png
from dhlab.views.view import RobotView2D, RobotView3D, robot_view, triad_segments, workspace_box

ROBOTS_3D = [robots.ssrms, robots.puma560, robots.seed002_4dof, robots.seed003_6dof, robots.rrr_example]
ROBOTS_2D = [robots.robot_no_tan_elemental_1, robots.robot_no_tan_elemental_2, robots.pr_mechanism]


def random_q(robot, rng):
    lo, hi = robot.qlim.T
    return lo + (hi - lo) * rng.random(robot.n)


def drawn_3d(line):
    """The points a Line3D holds, NaN separators dropped."""
    pts = np.column_stack(line.get_data_3d())
    return pts[~np.isnan(pts).any(axis=1)]


def drawn_2d(line):
    pts = np.column_stack(line.get_data())
    return pts[~np.isnan(pts).any(axis=1)]


def pixels(view):
    return np.asarray(view.live.figure.canvas.buffer_rgba()).copy()


@pytest.mark.parametrize("make", ROBOTS_3D, ids=lambda f: f.__name__)
def test_3d_view_draws_the_robot_frames(make):
    robot = make()
    view = robot_view(robot, style="stick")
    assert isinstance(view, RobotView3D)
    rng = np.random.default_rng(1)
    for _ in range(3):
        q = random_q(robot, rng)
        view.update(q)
        F = robot.frames(q)
        origins = F[:, :3, 3]
        np.testing.assert_allclose(drawn_3d(view.link_line), origins, atol=1e-12)
        for k, line in enumerate(view.axis_lines):              # x, y, z triads
            pts = drawn_3d(line).reshape(-1, 2, 3)
            np.testing.assert_allclose(pts[:, 0], origins, atol=1e-12)
            np.testing.assert_allclose((pts[:, 1] - pts[:, 0]) / view.triad_length, F[:, :3, k], atol=1e-12)
        np.testing.assert_allclose(drawn_3d(view.ee_marker)[0], robot.fk(q)[:3, 3], atol=1e-12)
        np.testing.assert_allclose(view.labels.get_points(), origins, atol=1e-12)


@pytest.mark.parametrize("make", ROBOTS_2D, ids=lambda f: f.__name__)
def test_planar_view_draws_the_robot_frames(make):
    robot = make()
    view = robot_view(robot, style="stick")
    assert isinstance(view, RobotView2D)
    rng = np.random.default_rng(2)
    for _ in range(3):
        q = random_q(robot, rng)
        view.update(q)
        F = robot.frames(q)
        np.testing.assert_allclose(drawn_2d(view.link_line), F[:, :2, 3], atol=1e-12)
        for k, line in enumerate(view.axis_lines):
            pts = drawn_2d(line).reshape(-1, 2, 2)
            np.testing.assert_allclose((pts[:, 1] - pts[:, 0]) / view.triad_length, F[:, :2, k], atol=1e-12)
        # z of every frame points out of the page for these robots: a blue ⊙ at each origin
        np.testing.assert_allclose(drawn_2d(view.out_marks[2]), F[:, :2, 3], atol=1e-12)
        assert len(drawn_2d(view.in_marks[2])) == 0
        np.testing.assert_allclose(drawn_2d(view.ee_marker)[0], robot.fk(q)[:2, 3], atol=1e-12)


def test_seed004_second_case_on_the_figure():
    """Segundo caso (θ0 = −60°, θ1 = 90°): the end effector is drawn at (0.866025, 0.5)."""
    robot = robots.robot_no_tan_elemental_1()
    view = robot_view(robot, dhlab.deg2rad([-60, 90]))
    np.testing.assert_allclose(drawn_2d(view.ee_marker)[0], [0.866025, 0.5], atol=1e-6)
    np.testing.assert_allclose(drawn_2d(view.link_line)[1], [0.606218, 0.35], atol=1e-6)


def test_tool_frame_is_drawn_and_marked():
    robot = dhlab.DHRobot([dhlab.RevoluteDH(a=1.0), dhlab.RevoluteDH(a=0.5, alpha=dhlab.deg2rad(90))],
                          tool=dhlab.trans(0, 0, 0.2), name="with tool")
    view = robot_view(robot, planar=False)
    q = dhlab.deg2rad([20, 40])
    view.update(q)
    assert view.frame_labels[-1] == r"$\{E\}$" and len(view.frame_labels) == robot.n + 2
    np.testing.assert_allclose(drawn_3d(view.ee_marker)[0], robot.fk(q)[:3, 3], atol=1e-12)
    np.testing.assert_allclose(drawn_3d(view.link_line)[-1], robot.fk(q)[:3, 3], atol=1e-12)


def test_triad_segments_are_right_handed_axes():
    T = dhlab.Rz(0.3) @ dhlab.Rx(-1.1) @ dhlab.trans(1, 2, 3)
    x, y, z = (s.reshape(-1, 3, 3)[0] for s in triad_segments(T[None], 2.0))
    ax_x, ax_y, ax_z = x[1] - x[0], y[1] - y[0], z[1] - z[0]
    np.testing.assert_allclose(np.cross(ax_x, ax_y), 2.0 * ax_z, atol=1e-12)
    assert np.isnan(x[2]).all()                                   # the separator


def test_fixed_framing_keeps_the_workspace_box():
    robot = robots.puma560()
    view = robot_view(robot, framing="fixed")
    lo, hi = workspace_box(robot)
    limits = [view.ax.get_xlim(), view.ax.get_ylim(), view.ax.get_zlim()]
    np.testing.assert_allclose(np.array(limits), np.column_stack([lo, hi]))
    aspect = view.ax.get_box_aspect()              # equal scaling
    np.testing.assert_allclose(aspect / aspect.max(), (hi - lo) / (hi - lo).max(), rtol=1e-6)
    rng = np.random.default_rng(7)                                # other poses than the box's
    for _ in range(50):
        q = random_q(robot, rng)
        view.update(q, draw=False)
        origins = robot.frames(q)[:, :3, 3]
        assert (origins >= lo - 1e-9).all() and (origins <= hi + 1e-9).all()
    assert [view.ax.get_xlim(), view.ax.get_ylim(), view.ax.get_zlim()] == limits   # never jumps


@pytest.mark.parametrize("make", ROBOTS_3D + ROBOTS_2D, ids=lambda f: f.__name__)
def test_follow_framing_fills_the_view_with_hysteresis(make):
    """The robot fills its view; small moves keep the frame (no full redraw), a
    large move re-frames (one full redraw); equal scaling always."""
    robot = make()
    view = robot_view(robot, backend="image")
    view.live.png()
    assert view.extent_fraction() >= 0.6
    full_draws = []
    view.figure.canvas.mpl_connect("draw_event", lambda event: full_draws.append(1))
    limits = [view.ax.get_xlim(), view.ax.get_ylim()]
    q = view.q.copy()
    k = int(np.argmax([link.qlim[1] - link.qlim[0] for link in robot.links]))
    step = 0.01 * (robot.links[k].qlim[1] - robot.links[k].qlim[0])
    q[k] = np.clip(q[k] + step, *robot.links[k].qlim)
    view.update(q)                                          # a small move
    assert [view.ax.get_xlim(), view.ax.get_ylim()] == limits and not full_draws
    rng = np.random.default_rng(2)
    for _ in range(8):                                      # large moves
        view.update(random_q(robot, rng))
        assert view.extent_fraction() >= 0.4
    if view.ax.name == "3d":
        ranges = np.array([np.ptp(view.ax.get_xlim()), np.ptp(view.ax.get_ylim()), np.ptp(view.ax.get_zlim())])
        aspect = view.ax.get_box_aspect()
        np.testing.assert_allclose(aspect / aspect.max(), ranges / ranges.max(), rtol=1e-6)
    else:
        assert view.ax.get_aspect() == 1.0


def test_frames_at_one_place_share_one_label_and_labels_can_hide():
    view = robot_view(robots.puma560(), backend="image")          # spherical wrist: S4 = S5 = S6
    view.live.png()
    assert "$\\{S_{4},S_{5},S_{6}\\}$" in view.labels.texts
    view.show_labels(False)
    hidden = pixels(view)
    view.show_labels(True)
    assert (pixels(view) != hidden).any()


def test_joint_axes_are_dashed_lines_along_z_of_each_joint():
    robot = robots.ssrms()
    view = robot_view(robot, joint_axes=True, backend="image")
    points = np.column_stack(view.joint_axes_line.get_data_3d())
    pieces = np.split(points, np.where(np.isnan(points).any(axis=1))[0])
    pieces = [p[~np.isnan(p).any(axis=1)] for p in pieces if len(p[~np.isnan(p).any(axis=1)]) == 2]
    assert len(pieces) == robot.n
    for (a, b), frame in zip(pieces, view.frames[:robot.n]):
        direction = (b - a) / np.linalg.norm(b - a)
        assert abs(abs(direction @ frame[:3, 2]) - 1) < 1e-9        # along z_(i-1)
        assert np.linalg.norm(np.cross(frame[:3, 3] - a, direction)) < 1e-6   # through origin i-1
    assert view.joint_axes_line.get_linestyle() == "--"


def test_camera_presets_and_zoom():
    view = robot_view(robots.puma560(), backend="image")
    for preset, (elev, azim) in {"front": (0, -90), "side": (0, 0), "top": (90, -90)}.items():
        view.set_camera(preset)
        assert (view.ax.elev, view.ax.azim) == (elev, azim)
    view.set_camera("iso")
    before = view.extent_fraction()
    view.set_zoom(1.5)
    assert view.extent_fraction() == pytest.approx(1.5 * before, rel=0.05)
    with pytest.raises(dhlab.DHLabError):
        view.set_camera("bottom")
    with pytest.raises(dhlab.DHLabError):
        view.set_zoom(0)


def test_default_camera_reads_every_triad():
    from dhlab.views.camera import triad_readability

    for make in ROBOTS_3D:
        view = robot_view(make(), backend="image")
        assert triad_readability(view.frames, view.ax.elev, view.ax.azim).min() >= 1


def test_update_really_draws_and_leaves_no_trail():
    view = robot_view(robots.ssrms(), framing="fixed")
    qa, qb = dhlab.deg2rad([10, 20, 30, 0, 0, 0, 0]), dhlab.deg2rad([-40, 60, 10, 20, 30, 0, 0])
    view.update(qa)
    first = pixels(view)
    view.update(qb)
    assert (pixels(view) != first).any(), "moving the robot changed no pixel"
    view.update(qa)
    np.testing.assert_array_equal(pixels(view), first)    # background restored: no ghost of qb


def test_blitted_frame_shows_the_robot_like_a_full_render():
    """What blitting paints equals a full redraw of the same figure, pixel for pixel
    except where the robot's strokes overlap the axes decorations' antialiasing."""
    view = robot_view(robots.puma560(), backend="image", framing="fixed")
    view.update(dhlab.deg2rad([30, -40, 20, 10, 50, 0]))
    blitted = pixels(view).astype(int)
    for artist in view.live.moving:
        artist.set_animated(False)
    view.live.figure.canvas.draw()
    full = np.asarray(view.live.figure.canvas.buffer_rgba()).astype(int)
    differ = np.abs(blitted - full).max(axis=2) > 60
    assert differ.mean() < 0.001, f"{differ.mean():.4%} of the pixels differ"   # the robot covers ~0.5 %


def test_200_updates_keep_figures_and_artists_constant():
    before_figs = plt.get_fignums()
    view = robot_view(robots.ssrms())
    fig, ax = view.figure, view.ax
    counts = (len(fig.get_children()), len(ax.get_children()), len(view.live.moving))
    rng = np.random.default_rng(3)
    for _ in range(200):
        view.update(random_q(view.robot, rng))
    assert (len(fig.get_children()), len(ax.get_children()), len(view.live.moving)) == counts
    assert plt.get_fignums() == before_figs       # never registered with pyplot


def test_many_views_do_not_warn_about_open_figures(recwarn):
    for _ in range(25):                           # pyplot warns past 20 open figures
        robot_view(robots.pr_mechanism()).update([0.5, 0.2])
    assert not [w for w in recwarn if "figures" in str(w.message)]
    assert plt.get_fignums() == []


def test_encode_png_round_trips():
    from io import BytesIO

    from PIL import Image

    rgba = np.random.default_rng(0).integers(0, 256, (7, 5, 4), dtype=np.uint8)
    image = np.asarray(Image.open(BytesIO(encode_png(rgba))).convert("RGB"))
    np.testing.assert_array_equal(image, rgba[..., :3])


def test_live_figure_refuses_unknown_backend():
    with pytest.raises(ValueError, match="backend must be"):
        LiveFigure(backend="qt")


def test_ipympl_diff_frames_rebuild_the_picture():
    """What the browser gets (a full PNG, then diffs with unchanged pixels transparent),
    composited in order, is exactly the figure's pixels after every update."""
    from io import BytesIO

    from PIL import Image

    view = robot_view(robots.ssrms(), backend="ipympl")
    canvas = view.live.figure.canvas
    canvas.syncing_data_url = False                 # as with a browser attached
    received = []
    canvas.send_binary = received.append
    screen = None
    for q in (np.zeros(7), dhlab.deg2rad([30, 0, 0, 0, 0, 0, 0]), dhlab.deg2rad([30, 45, -20, 0, 0, 10, 0])):
        view.update(q)
        frame = np.asarray(Image.open(BytesIO(received[-1])).convert("RGBA"))
        if canvas._current_image_mode == "full" or screen is None:
            screen = frame.copy()
        else:
            changed = frame[..., 3] > 0
            screen[changed] = frame[changed]
        np.testing.assert_array_equal(screen, np.asarray(canvas.buffer_rgba()))
    assert len(received) >= 3
