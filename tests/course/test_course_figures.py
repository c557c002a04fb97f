"""The notebooks' own figures (notebooks 2, 5, 7: dhlab.course.lessons.figures_*), measured on what is drawn.

* the two-step figure of notebook 2 draws step 1 as the turn in place, Rz(90°), and step 2 as
  Rz(90°)·Tr(1,0,0) (moving frame) or Tr(1,0,0)·Rz(90°) (fixed frame), and has a legend;
* exercise 5.1's picture: the axes asked about (skew, parallel) do not look as if they crossed; after the
  answer, the common normal drawn between z0 and z1 is 0.2 long, as computed here from the lines;
* notebook 7: the arm built with seed 001's THz lies inside its axes, the legend off the drawing;
  each link's triad is drawn on top of its wider skeleton;
* every figure: every text inside the figure, at least 12 px, the figure at least 450 px wide.
"""
import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest

from dhlab import robots
from dhlab.course.exercises import (
    four_axis_arm,
    row_exercise_frames,
    seed001_DefinirTHz,
)
from dhlab.course.lessons import figures_dh, figures_homogeneous, figures_ssrms
from dhlab.dh_frames import joint_axes
from dhlab.transforms import Rx, trans
from dhlab.views.framing import projected
from support.drawn_text import drawn, text_box, visible_texts

ROT90 = np.array([[0.0, -1.0], [1.0, 0.0]])        # Rz(90°) in the plane, written out


def ssrms_with_001():
    """Notebook 7's chain with seed 001's DefinirTHz, at zero (n+1 frames)."""
    rows = [(2.5, -90, 0), (6, -90, 0), (6, 0, 12), (1, 0, 12), (6, -90, 0), (6, -90, 0), (0, 0, 0)]
    frames = [np.eye(4)]
    for d, alpha, a in rows:
        frames.append(frames[-1] @ seed001_DefinirTHz(0.0, (0, 0, d)) @ trans(a, 0, 0) @ Rx(np.radians(alpha)))
    return np.array(frames)


ARM_AXES, ARM_TOOL = joint_axes(four_axis_arm())
FIGURES = {
    "two steps": lambda: figures_homogeneous.two_step_figure(),
    "three cases": lambda: figures_dh.cases_figure(
        (np.zeros(3), np.array([0, 0, 1.0])),
        {"case 1": (np.array([0, 0, 1.0]), np.array([0, 1.0, 0])),
         "case 2": (np.array([1.0, 0, 0.5]), np.array([0, 0, 1.0])),
         "case 3": (np.array([1.0, 0, 0.5]), np.array([0, 1.0, 0]))}),
    "DH parameters": lambda: figures_dh.dh_parameters_figure(),
    "exercise 5.1": lambda: figures_dh.exercise_axes_figure(ARM_AXES, ARM_TOOL),
    "common normals": lambda: figures_dh.common_normals_figure(ARM_AXES, ARM_TOOL),
    "exercise 5.2": lambda: figures_dh.row_frames_figure(*row_exercise_frames()),
    "SSRMS links": lambda: figures_ssrms.links_figure(robots.ssrms()),
    "Rot_x(-90)": lambda: figures_ssrms.rot_x_figure(),
    "seed 001's arm": lambda: figures_ssrms.seed001_figure(robots.ssrms(), ssrms_with_001()),
}


@pytest.mark.parametrize("name", list(FIGURES))
def test_every_text_is_inside_the_figure_and_readable(name):
    fig = FIGURES[name]()
    renderer = drawn(fig)
    assert fig.bbox.width >= 450 and fig.dpi >= 100
    texts = visible_texts(fig)
    assert texts, "a figure of the course says what it shows"
    for text in texts:
        box = text_box(text, renderer)
        assert box.x0 >= 0 and box.y0 >= 0 and box.x1 <= fig.bbox.width and box.y1 <= fig.bbox.height, \
            f"{name}: {text.get_text()!r} is cut at the figure's edge ({box})"
        assert text.get_fontsize() * fig.dpi / 72 >= 12 - 1e-9, f"{name}: {text.get_text()!r} is too small"


# --- notebook 2 -------------------------------------------------------------------------------------------
def line_by_gid(fig, gid):
    lines = [line for ax in fig.axes for line in ax.lines if line.get_gid() == gid]
    assert len(lines) == 1, gid
    return np.column_stack(lines[0].get_data())


@pytest.mark.parametrize("reading, final_origin", [("moving", ROT90 @ [1, 0]), ("fixed", np.array([1.0, 0]))])
def test_two_step_figure_draws_the_turn_in_place_then_the_move(reading, final_origin):
    fig = figures_homogeneous.two_step_figure()
    step1_x, step1_y = (line_by_gid(fig, f"{reading}:step 1:{a}") for a in "xy")
    # after step 1 the frame is turned 90° about z and has not moved: Rz(90°)
    assert np.allclose(step1_x[0], [0, 0]) and np.allclose(step1_y[0], [0, 0])
    for segment, column in ((step1_x, 0), (step1_y, 1)):
        direction = (segment[1] - segment[0]) / np.linalg.norm(segment[1] - segment[0])
        assert np.allclose(direction, ROT90[:, column])
    # after step 2: moved by 1 (along the new x, or along x0), same orientation
    step2_x = line_by_gid(fig, f"{reading}:step 2:x")
    assert np.allclose(step2_x[0], final_origin)
    assert np.linalg.norm(step2_x[0] - step1_x[0]) == pytest.approx(1.0)
    assert np.allclose((step2_x[1] - step2_x[0]) / np.linalg.norm(step2_x[1] - step2_x[0]), ROT90[:, 0])


def test_two_step_figure_has_a_legend_and_letters_at_the_tips():
    fig = figures_homogeneous.two_step_figure()
    assert fig.legends and len(fig.legends[0].get_texts()) >= 3
    words = {t.get_text() for t in visible_texts(fig)}
    assert {"$x_{0}$", "$y_{0}$", "$x'$", "$y'$", "$x_{1}$", "$y_{1}$"} <= words


def test_two_steps_refuses_an_unknown_reading():
    with pytest.raises(ValueError, match="moving"):
        figures_homogeneous.two_steps("sideways")


# --- notebook 5 -------------------------------------------------------------------------------------------
def segment_distance_px(A, B, samples=400):
    """Smallest distance between two drawn 2D segments (pixels), by sampling both."""
    t = np.linspace(0, 1, samples)[:, None]
    P, Q = A[0] + t * (A[1] - A[0]), B[0] + t * (B[1] - B[0])
    return float(np.min(np.linalg.norm(P[:, None] - Q[None], axis=2)))


def test_exercise_51_figure_shows_no_false_crossing():
    fig = figures_dh.exercise_axes_figure(ARM_AXES, ARM_TOOL)
    drawn(fig)
    ax = fig.axes[0]
    dotted = [line for line in ax.lines if line.get_linestyle() == ":"]
    assert len(dotted) == 4
    pixels = [projected(ax, np.column_stack(line.get_data_3d())) for line in dotted]
    for i in (0, 1):                 # z0, z1 are skew; z1, z2 parallel: their drawings must not touch
        assert segment_distance_px(pixels[i], pixels[i + 1]) > 15, f"z{i} and z{i + 1} look as if they met"
    renderer = fig.canvas.get_renderer()
    boxes = [text_box(t, renderer) for t in visible_texts(fig) if t.get_text().startswith("$z_")]
    assert len(boxes) == 4
    for i in range(4):
        for j in range(i + 1, 4):
            assert not boxes[i].overlaps(boxes[j]), "two axis names overlap"


def test_common_normal_drawn_is_the_distance_between_the_lines():
    (p0, u0, _), (p1, u1, _) = ARM_AXES[:2]
    n = np.cross(u0, u1)
    distance = abs(np.dot(np.asarray(p1) - p0, n)) / np.linalg.norm(n)     # |w · (u0 × u1)| / |u0 × u1|
    assert distance == pytest.approx(0.2)
    fig = figures_dh.common_normals_figure(ARM_AXES, ARM_TOOL)
    ax = fig.axes[0]
    normals = [np.column_stack(line.get_data_3d()) for line in ax.lines if line.get_color() == "black"]
    lengths = sorted(float(np.linalg.norm(s[1] - s[0])) for s in normals)
    assert lengths[0] == pytest.approx(distance)
    assert any(t.get_text() == f"{distance:g} m" for t in ax.texts)


def test_common_normals_wait_for_the_answer(capsys):
    assert figures_dh.common_normals_after(..., ARM_AXES, ARM_TOOL) is None
    assert "Answer exercise 5.1 first" in capsys.readouterr().out
    assert figures_dh.common_normals_after({1: "skew"}, ARM_AXES, ARM_TOOL) is not None


def test_dh_parameters_figure_names_the_axes_and_the_parameters():
    words = {t.get_text() for t in visible_texts(figures_dh.dh_parameters_figure())}
    assert {"$z_{i-1}$", "$z_{i}$", "$x_{i}$", "$x_{i-1}$", "$O_i$", "$O_{i-1}$", r"$\theta_i$", "$d_i$",
            "$a_i$", r"$\alpha_i$"} <= words


# --- notebook 7 -------------------------------------------------------------------------------------------
def test_seed001_figure_holds_both_arms_with_the_legend_off_the_drawing():
    ssrms = robots.ssrms()
    fig = figures_ssrms.seed001_figure(ssrms, ssrms_with_001())
    drawn(fig)
    ax = fig.axes[0]
    points = np.vstack([ssrms_with_001()[:, :3, 3], ssrms.frames(ssrms.qz)[:, :3, 3]])
    pixels = projected(ax, points)
    box = ax.bbox
    margin = 10
    assert np.all((pixels[:, 0] > box.x0 + margin) & (pixels[:, 0] < box.x1 - margin)
                  & (pixels[:, 1] > box.y0 + margin) & (pixels[:, 1] < box.y1 - margin)), "an arm leaves its axes"
    legend = fig.legends[0].get_window_extent()
    assert not any(legend.contains(*p) for p in pixels), "the legend covers the arm"
    assert not legend.overlaps(ax.get_tightbbox().shrunk(0.999, 0.999)) or legend.y1 <= pixels[:, 1].min()


def test_each_link_skeleton_is_d_then_a_and_under_its_triad():
    ssrms = robots.ssrms()
    for link in range(1, ssrms.n + 1):
        hang, corner, origin = figures_ssrms.link_skeleton(ssrms, link)
        assert np.allclose(origin, 0)
        assert np.allclose(corner[1:], 0), "the last leg runs along the link's own x axis"
        assert abs(corner[0]) == pytest.approx(abs(float(ssrms.links[link - 1].a)))
        assert np.linalg.norm(corner - hang) == pytest.approx(abs(float(ssrms.links[link - 1].d)))
    fig = figures_ssrms.links_figure(ssrms)
    for ax in fig.axes[1:]:
        assert ax.computed_zorder is False
        widths = [line.get_linewidth() for line in ax.lines]
        skeleton = widths.index(max(widths))
        green = [k for k, line in enumerate(ax.lines) if line.get_color() == "tab:green"]
        assert green and all(k > skeleton for k in green), "the triad is drawn after (over) the skeleton"
        assert max(widths) > 2 * ax.lines[green[0]].get_linewidth()


def test_rot_x_label_is_off_the_arc():
    fig = figures_ssrms.rot_x_figure()
    drawn(fig)
    ax = fig.axes[0]
    label = next(t for t in ax.texts if t.get_text().startswith("x (towards"))
    arc = next(line for line in ax.lines if len(line.get_xdata()) > 10)
    pixels = ax.transData.transform(np.column_stack(arc.get_data()))
    assert not any(label.get_window_extent().contains(*p) for p in pixels)


def test_frame_panel_triads_follow_the_sliders_and_have_a_legend():
    panel = figures_homogeneous.frame_panel()
    theta, a, alpha = panel.sliders
    theta.value, a.value, alpha.value = 90.0, 1.0, 0.0
    ax = panel.live.figure.axes[0]
    solid_x = next(line for line in ax.lines if line.get_color() == "tab:red" and line.get_linewidth() == 3)
    start, tip = np.column_stack(solid_x.get_data_3d())
    assert np.allclose(start, [0, 1, 0])            # Rz(90°)·Tr(1,0,0): moved along the turned x, onto y0
    assert np.allclose((tip - start) / np.linalg.norm(tip - start), [0, 1, 0])
    letters = [t for t in ax.texts if t.get_text() == "$x$"]
    assert any(np.allclose(t.get_position_3d(), start + 0.98 * (tip - start) / 0.8) for t in letters)
    assert panel.live.figure.legends and len(panel.live.figure.legends[0].get_texts()) == 3
