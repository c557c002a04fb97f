"""Notebook 06's row-by-row figure (dhlab.course.lessons.figures_dh_examples) and the lettered triad."""
import numpy as np
import pytest

import dhlab
from dhlab.course.lessons.figures_dh_examples import clip_segment, frame_pairs_figure, row_title
from dhlab.errors import DHLabError
from dhlab.views import framing
from dhlab.views.layout import drawn_texts
from dhlab.views.triads import LETTERS, draw_triad


def test_one_picture_per_row_with_both_frames_inside_its_box():
    robot = dhlab.robots.seed003_6dof()
    fig = frame_pairs_figure(robot)
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    F = robot.frames(robot.qz)
    assert len(fig.axes) == robot.n
    for i, ax in enumerate(fig.axes, start=1):
        lo = np.array([ax.get_xlim()[0], ax.get_ylim()[0], ax.get_zlim()[0]])
        hi = np.array([ax.get_xlim()[1], ax.get_ylim()[1], ax.get_zlim()[1]])
        for T in F[i - 1:i + 1]:                  # both frames' origins inside the box
            assert np.all(T[:3, 3] >= lo) and np.all(T[:3, 3] <= hi)
        letters = [t.get_text() for t in ax.texts if t.get_text() in LETTERS]
        assert sorted(letters) == sorted(LETTERS * 2)          # x, y, z of both frames
        labels = [t.get_text() for t in ax.texts if "S_" in t.get_text()]
        assert labels == [rf"$\{{S_{{{i - 1}}}\}}$", rf"$\{{S_{{{i}}}\}}$"]
        assert ax.get_title() == row_title(robot, i)
        for text in drawn_texts(ax):                             # nothing cut at the figure's edge
            box = text.get_window_extent(renderer)
            assert box.x0 >= -1 and box.y0 >= -1 and box.x1 <= fig.bbox.x1 + 1 and box.y1 <= fig.bbox.y1 + 1
        where = np.array([t.get_position_3d() for t in ax.texts])       # letters and labels, in their own axes
        pixels = framing.projected(ax, where)
        assert np.all(pixels >= [ax.bbox.x0, ax.bbox.y0]) and np.all(pixels <= [ax.bbox.x1, ax.bbox.y1])


def test_row_titles_carry_the_offsets():
    robot = dhlab.robots.seed003_6dof()
    titles = [row_title(robot, i) for i in range(1, robot.n + 1)]
    assert titles[1] == "row 2:  θ2 = q2 + 90°" and titles[2] == "row 3:  θ3 = q3 − 90°"
    assert titles[0] == "row 1:  θ1 = q1"


def test_clip_segment():
    np.testing.assert_allclose(clip_segment([-1, 0, 0], [3, 0, 0], [0, -1, -1], [1, 1, 1]), [[0, 0, 0], [1, 0, 0]])
    assert clip_segment([2, 2, 2], [3, 3, 3], [0, 0, 0], [1, 1, 1]) is None


@pytest.mark.parametrize("kwargs", [dict(length="a"), dict(length=-1), dict(length=float("nan")),
                                    dict(titles=["a"]), dict(titles="abc"), dict(q=[1, 2])])
def test_bad_options_are_refused_clearly(kwargs):
    with pytest.raises(DHLabError):
        frame_pairs_figure(dhlab.robots.seed003_6dof(), **kwargs)


@pytest.mark.parametrize("T, length", [("x", 1), (np.eye(3), 1), (np.full((4, 4), np.nan), 1),
                                       (np.eye(4), 0), (np.eye(4), -1), (np.eye(4), "1"), (np.eye(4), None)])
def test_draw_triad_refuses_bad_poses_and_lengths(T, length):
    fig = dhlab.views.figures.new_figure()
    ax = fig.add_subplot(projection="3d")
    with pytest.raises(DHLabError):
        draw_triad(ax, T, length)


def test_draw_triad_letters_sit_past_the_tips():
    fig = dhlab.views.figures.new_figure()
    ax = fig.add_subplot(projection="3d")
    T = dhlab.Rz(0.4) @ dhlab.trans(1, 2, 3)
    artists = draw_triad(ax, T, 2.0, label="$S$")
    letters = {t.get_text(): np.array(t.get_position_3d())
               for t in artists if hasattr(t, "get_text") and t.get_text() in LETTERS}
    for k, name in enumerate(LETTERS):
        expected = T[:3, 3] + 1.2 * 2.0 * T[:3, k]
        np.testing.assert_allclose(letters[name], expected, atol=1e-9)
