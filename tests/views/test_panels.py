"""The DH step-through and the joint-space / Cartesian-space panel."""
import functools

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest

import dhlab
from dhlab import robots
from dhlab.views.panels.spaces import spaces, wrap_into_limits
from dhlab.views.panels.stepthrough import (
    dh_params,
    dh_partial,
    line_in_box,
    motion_text,
    stepthrough,
    stepthrough_link,
)


# --- the step-through -------------------------------------------------------------------
def test_dh_partial_applies_the_motions_in_dh_order():
    th, d, a, al = 0.7, 1.5, -0.8, -1.2
    steps = [np.eye(4), dhlab.Rz(th), dhlab.Rz(th) @ dhlab.trans(0, 0, d),
             dhlab.Rz(th) @ dhlab.trans(0, 0, d) @ dhlab.trans(a, 0, 0), dhlab.dh_matrix(th, d, a, al)]
    for k, expected in enumerate(steps):
        np.testing.assert_allclose(dh_partial(th, d, a, al, k), expected, atol=1e-12)
    # half-way through Tz: turned by θ, risen by d/2
    np.testing.assert_allclose(dh_partial(th, d, a, al, 1.5), dhlab.Rz(th) @ dhlab.trans(0, 0, d / 2), atol=1e-12)
    with pytest.raises(ValueError, match="between 0"):
        dh_partial(th, d, a, al, 4.5)


def test_dh_params_round_trip_and_refuse_non_dh_links():
    rng = np.random.default_rng(4)
    for _ in range(20):
        th, al = rng.uniform(-np.pi, np.pi, 2)
        d, a = rng.uniform(-2, 2, 2)
        np.testing.assert_allclose(dh_params(dhlab.dh_matrix(th, d, a, al)), (th, d, a, al), atol=1e-9)
    with pytest.raises(ValueError, match="not of the DH form"):
        dh_params(dhlab.Rz(0.4) @ dhlab.trans(0, 0.7, 0))     # seed 004: Rz(θ)·Tr(0, l, 0)


def test_stepthrough_of_a_robot_link_goes_from_frame_i_minus_1_to_frame_i():
    robot = robots.ssrms()
    q = dhlab.deg2rad([10, 20, 30, 40, 50, 60, 70])
    F = robot.frames(q)
    for i in (1, 3, 5):
        panel = stepthrough_link(robot, i, q)
        np.testing.assert_allclose(panel.frame, F[i - 1], atol=1e-12)
        panel.slider.value = 4
        np.testing.assert_allclose(panel.frame, F[i], atol=1e-9)
        # the moving triad is drawn where the frame is
        for k, line in enumerate(panel.moving_axes):
            start, tip = np.column_stack(line.get_data_3d())[:2]
            np.testing.assert_allclose(start, F[i][:3, 3], atol=1e-9)
            np.testing.assert_allclose((tip - start) / panel.length, F[i][:3, k], atol=1e-9)
    with pytest.raises(ValueError, match="not of the DH form"):
        stepthrough_link(robots.robot_no_tan_elemental_1(), 1)
    with pytest.raises(ValueError, match="link number i"):
        stepthrough_link(robot, 8)


def test_stepthrough_says_which_motion_is_applied():
    panel = stepthrough(theta_deg=90, d=1.0, a=0.5, alpha_deg=-90, i=2)
    expected = {0.5: "Step 1 of 4: Rz(θ)", 1.5: "Step 2 of 4: Tz(d)", 2.5: "Step 3 of 4: Tx(a)",
                3.5: "Step 4 of 4: Rx(α)", 4.0: "Done"}
    for step, words in expected.items():
        panel.slider.value = step
        assert words in panel.text.value
        np.testing.assert_allclose(panel.frame, dh_partial(np.pi / 2, 1.0, 0.5, -np.pi / 2, step), atol=1e-12)
    assert "θ = 90.0°" in motion_text(0.2, np.pi / 2, 0, 0, 0)
    panel.slider.value = 2.5
    assert "Rz(θ)·Tz(d)·Tx(0.50·a)" in panel.matrix.value


def test_line_in_box_clips_to_the_box():
    ends = line_in_box(np.array([0.2, 0.0, 0.0]), np.array([0.0, 0.0, 1.0]), -np.ones(3), np.ones(3))
    np.testing.assert_allclose(ends, [[0.2, 0, -1], [0.2, 0, 1]])


# --- joint space / Cartesian space ------------------------------------------------------
@pytest.fixture
def pr_panel():
    robot = robots.pr_mechanism()
    return spaces(robot, ik=functools.partial(dhlab.ik.pr_mechanism_ik, robot))


def test_joint_point_and_robot_move_together(pr_panel):
    pr_panel.sliders[0].value = 0.8
    pr_panel.sliders[1].value = 45
    q = np.array([0.8, np.radians(45)])
    np.testing.assert_allclose(np.ravel(pr_panel.joint_point.get_data()), [0.8, 45.0])
    ee = np.column_stack(pr_panel.view.ee_marker.get_data())[0]
    np.testing.assert_allclose(ee, [0.8 + 1 + 0.5 * np.cos(q[1]), 0.5 * np.sin(q[1])], atol=1e-12)
    # the target sliders follow the end effector
    np.testing.assert_allclose([s.value for s in pr_panel.target_sliders], ee, atol=0.01)


@pytest.mark.parametrize("case", ["003_PR_ik_2.0_0.25", "003_PR_ik_2.0_-0.4", "003_PR_ik_1.2_0.5"])
def test_every_ik_solution_is_shown(pr_panel, cases, case):
    c = cases[case]
    x, y = c["target_position"]
    pr_panel.set_target(x, y)
    expected = [np.array([s["q1"], s["q2"]]) for s in c["expected_solutions"].values()]
    expected = expected[:c["expected_solution_count"]]
    assert len(pr_panel.solutions) == len(expected)
    for got, want in zip(pr_panel.solutions, expected):
        assert got[0] == pytest.approx(want[0], abs=1e-9)
        assert np.cos(got[1] - want[1]) == pytest.approx(1.0)       # same angle, maybe a turn apart
    for k, s in enumerate(pr_panel.solutions):                       # a ghost robot per solution,
        ghost = pr_panel.ghosts[k]
        assert ghost.link_line.get_visible()
        np.testing.assert_allclose(ghost.frames[-1][:2, 3], [x, y], atol=1e-9)   # reaching the target
        mark = np.ravel(pr_panel.solution_marks[k].get_data())
        np.testing.assert_allclose(mark, [s[0], np.degrees(s[1])], atol=1e-9)
    for ghost in pr_panel.ghosts[len(expected):]:
        assert not ghost.link_line.get_visible()
    # the robot itself went to a solution within the limits
    ee = np.column_stack(pr_panel.view.ee_marker.get_data())[0]
    np.testing.assert_allclose(ee, [x, y], atol=1e-6)


def test_unreachable_target_is_reported_not_crashed(pr_panel, cases):
    x, y = cases["003_PR_ik_unreachable"]["target_position"]
    before = pr_panel.q.copy()
    pr_panel.target_sliders[1].value = y
    pr_panel.target_sliders[0].value = x
    assert pr_panel.solutions == []
    assert "no solution" in pr_panel.message.value
    assert pr_panel.target_mark.get_color() == "red"
    assert not any(g.link_line.get_visible() for g in pr_panel.ghosts)
    np.testing.assert_allclose(pr_panel.q, before)               # the robot stays where it was


def test_solution_outside_joint_limits_is_marked(pr_panel):
    pr_panel.set_target(3.2, 0.25)              # branch B needs q1 = 2.63 > 2 (the slider's max)
    assert pr_panel.solutions_ok == [True, False]
    assert "outside the joint limits" in pr_panel.message.value
    assert pr_panel.q[0] == pytest.approx(pr_panel.solutions[0][0])


def test_spaces_without_ik_and_wrong_robots():
    panel = spaces(robots.robot_no_tan_elemental_1())
    panel.sliders[0].value = -60
    panel.sliders[1].value = 90
    ee = np.column_stack(panel.view.ee_marker.get_data())[0]
    np.testing.assert_allclose(ee, [0.866025, 0.5], atol=1e-6)
    assert not panel.target_sliders and not panel.target_mark.get_visible()
    with pytest.raises(ValueError, match="needs a 2-DOF mechanism"):
        spaces(robots.ssrms())
    with pytest.raises(ValueError, match="no inverse kinematics"):
        panel.set_target(0.5, 0.5)


def test_wrap_into_limits():
    robot = robots.pr_mechanism()
    q, ok = wrap_into_limits(robot, [0.5, np.radians(233.13)])
    assert ok and q[1] == pytest.approx(np.radians(233.13 - 360))
    assert wrap_into_limits(robot, [2.5, 0.0])[1] is False


def test_moving_a_joint_never_moves_the_other_joint(pr_panel):
    """Notebook 04: dragging q1 toward 0 flipped q2 from 30° to 150°, because the
    browser echoed the (rounded) target sliders back into the IK. Here the echo is
    emulated: after every move the target sliders are set to their rounded values."""
    pr_panel.sliders[1].value = 30
    pr_panel.sliders[0].value = 0.57
    for q1 in np.linspace(0.56, 0.0, 29):
        pr_panel.sliders[0].value = float(q1)
        for slider in pr_panel.target_sliders:
            slider.value = round(slider.value / slider.step) * slider.step
        assert pr_panel.sliders[1].value == 30
    assert pr_panel.branch == "A"


def test_moving_the_target_keeps_the_branch_until_asked(pr_panel):
    pr_panel.set_target(2.0, 0.25)
    assert pr_panel.branch == "A" and np.degrees(pr_panel.q[1]) == pytest.approx(30)
    x_slider, y_slider = pr_panel.target_sliders
    for y in np.linspace(0.25, -0.4, 14):             # through y = 0 and below: still branch A
        y_slider.value = float(y)
        assert pr_panel.branch == "A"
        assert abs(np.degrees(pr_panel.q[1])) <= 90 + 1e-9
    pr_panel.branch_buttons.value = "B"              # the student asks for the other branch
    assert pr_panel.branch == "B" and abs(np.degrees(pr_panel.q[1])) > 90
    x_slider.value = 0.2                              # A needs q1 < 0 here: B stays, A is not taken
    assert pr_panel.branch == "B"


def test_stepthrough_starts_at_0_and_reads_steps_without_moving():
    panel = stepthrough(theta_deg=90, d=1.0, a=0.5, alpha_deg=-90, i=2)
    assert panel.slider.value == 0
    for step in (1, 2, 3, 4):
        np.testing.assert_allclose(panel.frame_at(step), dh_partial(np.pi / 2, 1.0, 0.5, -np.pi / 2, step))
    assert panel.slider.value == 0


class FakeBrowser:
    """What JupyterLab does with a panel's sliders, messages included.

    A slider view rounds every value the kernel sends to its step and, when that
    changed it, sends the rounded value back (so does a new view); while one of its
    own messages is unanswered it ignores the kernel's updates (ipywidgets' echo
    rule). Messages to the kernel wait in ``outbox`` until :meth:`deliver`: during
    Run All the kernel is busy with the next cells and reads them afterwards."""

    def __init__(self, sliders):
        self.sliders = list(sliders)
        self.shown, self.pending, self.outbox = {}, {}, []
        self.delivering = None
        self.sent = 0
        for slider in self.sliders:
            self.pending[id(slider)] = 0
            slider.observe(self._from_kernel, names="value")
            self._show(slider, slider.value)            # the view is made: it may round, and send

    @staticmethod
    def rounded(slider, value):
        return float(np.clip(slider.min + round((value - slider.min) / slider.step) * slider.step,
                             slider.min, slider.max))

    def _show(self, slider, value):
        shown = self.rounded(slider, value)
        self.shown[id(slider)] = shown
        if shown != value:
            self.outbox.append((slider, shown))
            self.pending[id(slider)] += 1
            self.sent += 1

    def _from_kernel(self, change):
        slider = change["owner"]
        if self.delivering == (id(slider), change["new"]):
            self.delivering = None                       # the kernel taking our own message
            return
        if self.pending[id(slider)]:
            return                                       # ignored until our message's echo
        self._show(slider, change["new"])

    def drag(self, slider, value):
        """The student moves a slider (its view shows and sends the value)."""
        self.shown[id(slider)] = value
        self.outbox.append((slider, value))
        self.pending[id(slider)] += 1
        self.sent += 1

    def deliver(self, limit=200):
        """The kernel reads the messages (each answered by its echo first), and the
        browser answers the kernel's updates, until nothing is left to send."""
        while self.outbox:
            assert self.sent <= limit, f"more than {limit} messages: the panel and the browser never settle"
            slider, value = self.outbox.pop(0)
            self.pending[id(slider)] -= 1                # echo_update: the browser shows `value`
            self.shown[id(slider)] = value
            self.delivering = (id(slider), value)
            slider.value = value
            self.delivering = None


def test_run_all_with_late_echoes_settles_where_the_code_left_it(pr_panel):
    """Notebook 04 under Run All: the panel is shown at branch A of (2, 0.25), then the next
    cell moves it twice, before the browser's roundings of the first values reach the kernel.
    In a browser the late echoes moved the robot back, set the other sliders, whose echoes
    moved it again: hundreds of messages, and the panel never showed what the code set."""
    browser = FakeBrowser([*pr_panel.sliders, *pr_panel.target_sliders])
    pr_panel.set_target(2.0, 0.25)
    start = pr_panel.q
    for target in [(2.0, -0.4), (2.0, 0.6)]:
        pr_panel.set_target(*target)
    browser.deliver()
    assert browser.sent < 20
    np.testing.assert_allclose(pr_panel.q, [0.7, np.arctan2(-0.4, 0.3)], atol=1e-9)   # where (2, -0.4) put it
    assert not np.allclose(pr_panel.q, start)
    assert pr_panel.target == (2.0, 0.6) and "no solution" in pr_panel.message.value
    # what the browser shows is what the panel holds (to the slider's step)
    for slider, value in zip(pr_panel.sliders, [0.7, np.degrees(np.arctan2(-0.4, 0.3))]):
        assert abs(browser.shown[id(slider)] - value) <= slider.step / 2 + 1e-9
    for slider, value in zip(pr_panel.target_sliders, (2.0, 0.6)):
        assert abs(browser.shown[id(slider)] - value) <= slider.step / 2 + 1e-9


def test_dragging_a_joint_with_a_real_browser_never_moves_the_other_joint(pr_panel):
    """The student drags q1 from 0.57 down to 0 at branch A, key by key; the browser's
    roundings of the target sliders come back after each move."""
    browser = FakeBrowser([*pr_panel.sliders, *pr_panel.target_sliders])
    browser.drag(pr_panel.sliders[1], 30.0)
    browser.deliver()
    q1_slider, q2_slider = pr_panel.sliders
    for q1 in np.arange(0.57, -0.001, -0.03):
        browser.drag(q1_slider, float(browser.rounded(q1_slider, q1)))
        browser.deliver(limit=10_000)
        assert q2_slider.value == 30 and np.degrees(pr_panel.q[1]) == pytest.approx(30)
        assert browser.shown[id(q2_slider)] == 30
    assert pr_panel.branch == "A" and pr_panel.q[0] == pytest.approx(0.0)
    # then the target: the robot follows on branch A, the joint sliders show where it is
    browser.drag(pr_panel.target_sliders[1], 0.4)
    browser.deliver(limit=10_000)
    assert pr_panel.branch == "A" and np.sin(pr_panel.q[1]) == pytest.approx(0.8)
    assert abs(browser.shown[id(q2_slider)] - np.degrees(pr_panel.q[1])) <= q2_slider.step / 2 + 1e-9
