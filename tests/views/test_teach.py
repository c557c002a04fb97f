"""The teach panel: sliders in display units, live readouts, errors shown, no pile-up."""
import re

import matplotlib

matplotlib.use("Agg")

import ipywidgets as widgets
import matplotlib.pyplot as plt
import numpy as np
import pytest
from ipywidgets.widgets.widget import _instances

import dhlab
from dhlab import robots
from dhlab.views.live import notebook_cell
from dhlab.views.panels.teach import teach


def numbers(html, *names):
    """The values printed as 'name = value' in a readout."""
    return [float(re.search(rf"\b{name} = (-?[\d.]+)", html).group(1)) for name in names]


def test_sliders_are_in_display_units_within_limits_and_labelled():
    robot = robots.seed002_4dof()            # R-P-P-R: degrees and lengths
    panel = teach(robot)
    assert [s.description for s in panel.sliders] == robot.joint_labels == ["q1", "d2", "d3", "q4"]
    for slider, link in zip(panel.sliders, robot.links):
        lo, hi = link.qlim
        if link.is_revolute:
            assert (slider.min, slider.max) == pytest.approx((np.degrees(lo), np.degrees(hi)))
        else:
            assert (slider.min, slider.max) == pytest.approx((lo, hi))
    units = [row.children[1].value for row in panel.children[1].children[1:5]]
    assert units == ["°", "length", "length", "°"]


def test_degree_sliders_give_radians_and_move_the_figure():
    robot = robots.ssrms()
    panel = teach(robot)
    panel.sliders[1].value = 30.0
    panel.sliders[3].value = -45.5
    q = np.radians([0, 30, 0, -45.5, 0, 0, 0])
    np.testing.assert_allclose(panel.q, q, atol=1e-12)
    np.testing.assert_allclose(panel.view.frames[:8], robot.frames(q), atol=1e-12)
    T = robot.fk(q)
    np.testing.assert_allclose(numbers(panel.readout.value, "x", "y", "z"), T[:3, 3], atol=6e-4)
    np.testing.assert_allclose(numbers(panel.readout.value, "roll", "pitch", "yaw"),
                               np.degrees(dhlab.rpy(T)), atol=6e-3)
    shown = [float(v) for v in re.findall(r">(-?\d+\.\d{4})<", panel.matrix.value)]
    np.testing.assert_allclose(np.reshape(shown, (4, 4)), T, atol=6e-5)


def test_seed004_cases_on_the_readout():
    panel = teach(robots.robot_no_tan_elemental_1())
    panel.sliders[0].value, panel.sliders[1].value = -60, 90         # segundo caso
    assert numbers(panel.readout.value, "x", "y", "z") == pytest.approx([0.866, 0.5, 0.0], abs=1e-3)
    assert numbers(panel.readout.value, "yaw") == pytest.approx([30.0])
    panel2 = teach(robots.robot_no_tan_elemental_2())                 # θ = −π/2, d = d_max
    panel2.sliders[0].value, panel2.sliders[1].value = -90, panel2.sliders[1].max
    assert panel2.sliders[1].max == pytest.approx(0.30)
    assert numbers(panel2.readout.value, "x", "y") == pytest.approx([1.0, 0.0], abs=1e-3)


def test_prismatic_slider_moves_only_its_joint():
    robot = robots.seed002_4dof()
    panel = teach(robot, [0.3, 0.2, 0.1, 0.4])
    before = panel.q.copy()
    panel.sliders[2].value = 0.75                          # d3, a length
    after = panel.q
    assert after[2] == pytest.approx(0.75)
    np.testing.assert_array_equal(np.delete(after, 2), np.delete(before, 2))
    np.testing.assert_allclose(panel.view.frames, robot.frames(after), atol=1e-12)
    # d3 slides frame 3 along z2 by the change in d3
    moved = panel.view.frames[3, :3, 3] - robot.frames(before)[3, :3, 3]
    np.testing.assert_allclose(moved, (0.75 - 0.1) * robot.frames(before)[2, :3, 2], atol=1e-12)


def test_set_q_moves_all_sliders_and_redraws_once():
    robot = robots.puma560()
    panel = teach(robot)
    calls = []
    panel.on_change = calls.append
    q = dhlab.deg2rad([10, 20, -30, 40, -50, 60])
    panel.set_q(q)
    np.testing.assert_allclose(panel.q, q, atol=1e-12)
    assert len(calls) == 1
    np.testing.assert_allclose(panel.view.frames, robot.frames(q), atol=1e-12)


def test_one_draw_per_update_with_on_change_before_it():
    robot = robots.puma560()
    events = []
    panel = teach(robot, on_change=lambda q: events.append("on_change"))
    draw = panel.view.live.refresh
    panel.view.live.refresh = lambda: (events.append("draw"), draw())[1]
    events.clear()
    panel.sliders[2].value = 25
    assert events == ["on_change", "draw"]
    np.testing.assert_allclose(panel.view.frames[-1], robot.fk(panel.q), atol=1e-12)


def test_image_backend_shows_each_update():
    panel = teach(robots.pr_mechanism(), backend="image")
    assert isinstance(panel.children[0], widgets.Image)
    first = panel.children[0].value
    panel.sliders[0].value = 1.2
    assert bytes(panel.children[0].value) != bytes(first)
    assert bytes(panel.children[0].value).startswith(b"\x89PNG")


def test_ipympl_backend_builds_a_canvas_widget():
    from ipympl.backend_nbagg import Canvas

    panel = teach(robots.pr_mechanism(), backend="ipympl")
    assert isinstance(panel.children[0], Canvas) and panel.figure.canvas is panel.children[0]
    panel.sliders[1].value = 45
    np.testing.assert_allclose(panel.view.frames, panel.robot.frames(panel.q), atol=1e-12)
    assert plt.get_fignums() == []


def test_callback_errors_are_shown_then_cleared():
    def check(q):
        if q[0] > 0.5:
            raise RuntimeError("joint 1 went too far for this exercise")

    panel = teach(robots.robot_no_tan_elemental_1(), on_change=check)
    with pytest.raises(RuntimeError):               # set from code: the caller sees it too
        panel.sliders[0].value = 40
    assert isinstance(panel.error, RuntimeError)
    assert "joint 1 went too far" in panel.error_box.value and "color:#b00020" in panel.error_box.value
    panel.sliders[0].value = 10                     # a good update clears the message
    assert panel.error is None and panel.error_box.value == ""


def test_bad_start_pose_gets_a_clear_error():
    with pytest.raises(ValueError, match=r"q must hold 7 joint values"):
        teach(robots.ssrms(), [0, 0])
    with pytest.raises(ValueError, match=r"outside joint 2's limits.*dhlab.deg2rad"):
        teach(robots.robot_no_tan_elemental_2(), [0.0, 0.5])


def test_200_slider_updates_keep_widgets_figures_and_artists_constant():
    panel = teach(robots.ssrms())
    fig, ax = panel.figure, panel.view.ax
    counts = (len(_instances), len(fig.get_children()), len(ax.get_children()))
    for i in range(200):
        panel.sliders[i % 7].value = (i * 37) % 540 - 270
    assert (len(_instances), len(fig.get_children()), len(ax.get_children())) == counts
    assert plt.get_fignums() == []


def test_rerunning_a_cell_closes_the_panels_of_its_previous_run(monkeypatch):
    run = {"count": 1}
    monkeypatch.setattr(notebook_cell, "current_cell", lambda: ("cell-a", run["count"]))
    monkeypatch.setattr(notebook_cell, "_made_by_cell", {})
    first = teach(robots.pr_mechanism())
    same_run = teach(robots.pr_mechanism())         # two panels in one cell: both stay
    assert first.comm is not None and same_run.comm is not None
    n_widgets = len(_instances)
    run["count"] = 2                                # the cell runs again
    second = teach(robots.pr_mechanism())
    assert first.comm is None and same_run.comm is None and first.sliders[0].comm is None
    assert second.comm is not None
    assert len(_instances) <= n_widgets   # the old widgets were released


def test_panel_repr_is_short_and_stable():
    panel = teach(robots.ssrms())
    assert repr(panel) == "<dhlab teach panel: SSRMS (seed 000), 7 joints>"
    bundle = panel._repr_mimebundle_()
    assert bundle["image/png"] and "application/vnd.jupyter.widget-view+json" in bundle
