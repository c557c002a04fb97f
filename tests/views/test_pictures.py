"""Lecture-grade pictures, measured on what is really drawn.

The teach panel of every catalogue robot is drawn headless at its start pose
and at random poses within the joint limits, at normal and at projector
scale, and measured:

* nothing clipped: every text (title, axis labels, tick labels, frame labels)
  and the end-effector star lie inside the figure;
* no two labels of frames at different places overlap (screen-space boxes),
  and frames at one place share one label;
* the robot's frame origins span at least 60 % of the axes' width or height at
  the start pose, at least 40 % at random poses;
* every text at least 12 px; every figure at least 450 px wide and 100 dpi.

The measurements use matplotlib's own extents of the drawn artists, not the
numbers the views compute for themselves.
"""
import itertools

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest
from matplotlib.text import Text
from mpl_toolkits.mplot3d import proj3d

from dhlab import robots
from dhlab.views import framing
from dhlab.views.figures import new_figure
from dhlab.views.figures import set_figure_scale as projector
from dhlab.views.panels.teach import teach

CATALOGUE = robots.catalogue()
RANDOM_POSES = 10


def draw(panel):
    """Render the panel's figure as it is shown (the PNG its widget gets)."""
    panel.live.png()
    return panel.figure.canvas.get_renderer()


def origins_in_pixels(view, points=None):
    ax, points = view.ax, view.frames[:, :3, 3] if points is None else points
    if ax.name == "3d":
        x, y, _ = proj3d.proj_transform(*points.T, ax.M)
        return ax.transData.transform(np.column_stack([x, y]))
    return ax.transData.transform(points[:, :2])


def extent(view):
    """How much of its axes the drawn robot spans: its links' corners (the frame origins and,
    in the mechanism drawing, the knees where d ends and a starts)."""
    pixels = origins_in_pixels(view, view.framed_points())
    span = pixels.max(axis=0) - pixels.min(axis=0)
    return max(span[0] / view.ax.bbox.width, span[1] / view.ax.bbox.height)


def label_boxes(view):
    """Screen boxes (x0, y0, x1, y1) of the frame labels as drawn: each outline's
    extent, placed at its offset."""
    labels = view.labels
    offsets = labels.get_offset_transform().transform(labels.get_offsets())
    boxes = []
    for path, offset in zip(labels.get_paths(), offsets):
        ext = path.get_extents(labels.get_transform())
        boxes.append([ext.x0 + offset[0], ext.y0 + offset[1], ext.x1 + offset[0], ext.y1 + offset[1]])
    return np.array(boxes)


def visible_texts(figure):
    """Every Text that is drawn: the figure's texts and titles, and the tick labels
    each axis really drew at the last draw (without asking the axis to update its
    ticks, which would move the labels of a 3D axis)."""
    tick_labels, drawn = set(), []
    for ax in figure.axes:
        for axis in ax._axis_map.values():
            for tick in [*axis.majorTicks, *axis.minorTicks]:
                tick_labels.update({id(tick.label1), id(tick.label2)})
            locs = axis.get_majorticklocs()
            lo, hi = sorted(axis.get_view_interval())
            eps = 1e-9 * max(abs(lo), abs(hi), 1)
            for tick in axis.majorTicks[:len(locs)]:
                if lo - eps <= tick.get_loc() <= hi + eps:
                    drawn += [t for t in (tick.label1, tick.label2) if t.get_visible() and t.get_text()]
    others = [t for t in figure.findobj(Text) if id(t) not in tick_labels
              and t.get_visible() and t.get_text().strip()]
    return others + drawn


def problems(panel, start: bool):
    """What is wrong with the panel's picture now, as a list of sentences."""
    view, figure = panel.view, panel.figure
    renderer = draw(panel)
    found = []
    fig_box = figure.bbox
    width_px = fig_box.width
    if width_px < 450 or figure.dpi < 100:
        found.append(f"figure {width_px:.0f} px at {figure.dpi:.0f} dpi")
    for text in visible_texts(figure):
        size_px = text.get_fontsize() * figure.dpi / 72
        if size_px < 12 - 1e-6:
            found.append(f"text {text.get_text()!r} is {size_px:.1f} px")
        box = text.get_window_extent(renderer)
        if box.x0 < fig_box.x0 - 1 or box.y0 < fig_box.y0 - 1 or box.x1 > fig_box.x1 + 1 or box.y1 > fig_box.y1 + 1:
            found.append(f"text {text.get_text()!r} clipped: {np.round(box.extents)} in {np.round(fig_box.extents)}")
    # the end-effector star, with its marker size
    star = origins_in_pixels(view)[-1]
    radius = view.ee_marker.get_markersize() * figure.dpi / 72 / 2
    if (star - radius < fig_box.p0).any() or (star + radius > fig_box.p1).any():
        found.append(f"end-effector star clipped at {star.round()}")
    # labels: one per place, none overlapping, at least 12 px, inside the figure
    boxes = label_boxes(view)
    points = view.frames[:, :3, 3]
    scale = max(np.ptp(points, axis=0).max(), 1e-9)
    places = len({tuple(np.round(p / (1e-6 * scale))) for p in points})
    if len(boxes) != places:
        found.append(f"{len(boxes)} labels for {places} frame places")
    for (i, a), (j, b) in itertools.combinations(enumerate(boxes), 2):
        if min(a[2], b[2]) - max(a[0], b[0]) > 0.5 and min(a[3], b[3]) - max(a[1], b[1]) > 0.5:
            found.append(f"labels {view.labels.texts[i]} and {view.labels.texts[j]} overlap")
    if len(boxes) and ((boxes[:, :2] < fig_box.p0 - 1).any() or (boxes[:, 2:] > fig_box.p1 + 1).any()):
        found.append("a frame label is clipped")
    if view.labels.fontsize * figure.dpi / 72 < 12:
        found.append("frame labels under 12 px")
    # the 3D box (its panes and edges) inside the figure
    if view.ax.name == "3d":
        corners = framing.projected(view.ax, framing.box_corners(view.ax))   # as matplotlib draws the box
        if (corners < fig_box.p0 - 1).any() or (corners > fig_box.p1 + 1).any():
            found.append(f"the 3D box is cut at the figure's edge: corners {corners.min(axis=0).round()}…"
                         f"{corners.max(axis=0).round()} in {np.round(fig_box.extents)}")
    # the robot fills its view
    fraction = extent(view)
    if fraction < (0.6 if start else 0.4):
        found.append(f"the robot spans {fraction:.0%} of its axes")
    return found


def poses(robot, n, seed):
    rng = np.random.default_rng(seed)
    lo, hi = robot.qlim.T
    return lo + (hi - lo) * rng.random((n, robot.n))


@pytest.fixture(params=[1.0, 1.5], ids=["normal", "projector"])
def scale(request):
    projector(request.param != 1.0, scale=request.param)
    yield request.param
    projector(False)


@pytest.mark.parametrize("name", sorted(CATALOGUE))
def test_teach_panel_pictures_are_lecture_grade(name, scale):
    robot = CATALOGUE[name]()
    panel = teach(robot, backend="image")
    assert panel.figure.dpi == pytest.approx(100 * scale)
    found = [f"start: {p}" for p in problems(panel, start=True)]
    for k, q in enumerate(poses(robot, RANDOM_POSES, seed=len(name))):
        panel.set_q(q)
        found += [f"pose {k}: {p}" for p in problems(panel, start=False)]
    panel.close()
    assert not found, "\n".join(found)


@pytest.mark.parametrize("figsize", [(3.2, 3.2), (3.6, 3.4), (4.2, 4.0)])
def test_small_figsize_of_the_notebooks_is_clamped(figsize):
    panel = teach(robots.puma560(), figsize=figsize, backend="image")
    width, height = panel.figure.canvas.get_width_height()
    assert width >= 450 and panel.figure.dpi >= 100
    assert height / width == pytest.approx(figsize[1] / figsize[0], rel=0.01)    # shape kept
    assert not problems(panel, start=True)


def test_two_robots_in_one_figure_keep_their_own_titles():
    """Notebook 04's figure: each view titles its own axes (no figure suptitle)."""
    from dhlab.views.view import robot_view

    figure = new_figure((8, 3.8))
    for k, robot in enumerate([robots.prr_example(), robots.rrr_example()]):
        ax = figure.add_subplot(1, 2, k + 1, projection="3d")
        robot_view(robot, ax=ax, planar=False).setup_axes(ax)
    assert figure.get_suptitle() == ""
    assert [ax.get_title() for ax in figure.axes] == [robots.prr_example().name, robots.rrr_example().name]


def test_new_figure_displays_as_a_picture_without_pyplot():
    """IPython's formatter gives image/png for a course figure (a bare Agg figure
    gives only the text '<Figure size ...>' when pyplot was never imported)."""
    from IPython.core.formatters import DisplayFormatter

    figure = new_figure((8, 4))
    figure.add_subplot().plot([0, 1], [1, 0])
    data, _ = DisplayFormatter().format(figure)
    assert "image/png" in data
    import base64
    import io

    from PIL import Image

    picture = Image.open(io.BytesIO(base64.b64decode(data["image/png"])))
    assert picture.size[0] >= 800 and figure.dpi >= 100


def test_new_figure_enforces_the_minimums_and_the_projector():
    figure = new_figure((2, 1), dpi=50)
    assert figure.dpi == 100 and figure.get_size_inches()[0] * figure.dpi >= 450
    ax = figure.add_subplot()
    ax.set_title("tiny", fontsize=4)
    ax.tick_params(labelsize=3)
    figure.canvas.draw()
    sizes = [t.get_fontsize() * figure.dpi / 72 for t in figure.findobj(Text) if t.get_text()]
    assert min(sizes) >= 12 - 1e-9
    projector(scale=1.5)
    try:
        assert new_figure((6, 4)).dpi == pytest.approx(150)
    finally:
        projector(False)
    assert new_figure((6, 4)).dpi == pytest.approx(100)


def text_problems(figure):
    """Texts under 12 px or sticking out of the figure; a figure under 450 px or 100 dpi."""
    found = []
    if figure.bbox.width < 450 or figure.dpi < 100:
        found.append(f"figure {figure.bbox.width:.0f} px at {figure.dpi:.0f} dpi")
    renderer = figure.canvas.get_renderer()
    fig_box = figure.bbox
    for text in visible_texts(figure):
        if text.get_fontsize() * figure.dpi / 72 < 12 - 1e-6:
            found.append(f"text {text.get_text()!r} under 12 px")
        box = text.get_window_extent(renderer)
        if box.x0 < -1 or box.y0 < -1 or box.x1 > fig_box.x1 + 1 or box.y1 > fig_box.y1 + 1:
            found.append(f"text {text.get_text()!r} clipped")
    return found


def test_spaces_and_stepthrough_pictures_at_the_notebooks_sizes(scale):
    import functools

    import dhlab
    from dhlab.views.panels.spaces import spaces
    from dhlab.views.panels.stepthrough import stepthrough_link

    pr = robots.pr_mechanism()
    panel = spaces(pr, ik=functools.partial(dhlab.ik.pr_mechanism_ik, pr), q=[0.566987, dhlab.deg2rad(30)],
                   figsize=(7.8, 3.3), backend="image")
    panel.live.png()
    found = text_problems(panel.figure)
    step = stepthrough_link(robots.seed002_6dof(), 3, figsize=(4.2, 4.2), backend="image")
    step.live.png()
    found += text_problems(step.figure)
    assert not found, "\n".join(found)
