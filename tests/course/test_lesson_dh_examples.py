"""Notebook 06's lesson helpers (dhlab.course.lessons.lesson_dh_examples): the slides' matrices are read
faithfully, the verified cases and the table read off the frames are reported truthfully, and the
wrist centre behaves as a spherical wrist's must (checked here from the frames, independently)."""
import re

import numpy as np
import pytest
import sympy as sp

import dhlab
from dhlab.course.lessons.lesson_dh_examples import (
    check_cases,
    compare_with_slide,
    elbow_flipped,
    fmt,
    from_slide,
    hand_derived_003,
    read_rows_at_zero,
    signed_angle,
    wrist_centre,
    wrist_centre_check,
    wrist_centre_panel,
)
from dhlab.data import load as load_data
from dhlab.errors import DHLabError

PRINTED = load_data("seed002_printed_A")


@pytest.fixture(scope="module")
def arm3():
    return dhlab.robots.seed003_6dof()


@pytest.fixture(scope="module")
def arm6():
    return dhlab.robots.seed002_6dof()


def test_fmt_rounds_and_drops_trailing_zeros_and_negative_zero():
    assert fmt([0.5, -1e-12, 3.0, -2.1234567]) == "(0.5, 0, 3, -2.123457)"


@pytest.mark.parametrize("robot_name, key", [("seed002_4dof", "4dof"), ("seed002_6dof", "6dof")])
def test_every_printed_matrix_reads_as_the_tables_link_matrix(robot_name, key):
    robot = getattr(dhlab.robots, robot_name)()
    for i in range(1, robot.n + 1):
        slide = from_slide(PRINTED[key][f"{i - 1}A{i}"]["latex"], robot)
        assert sp.simplify(slide - robot.A(i)) == sp.zeros(4, 4), (key, i)


def test_from_slide_reads_the_slides_names():
    rppr = dhlab.robots.seed002_4dof()
    q1 = rppr.q_symbols[0]
    M = from_slide(r"\begin{bmatrix} C_1 & -S_1 & 0 & l_1 \\ S_1 & C_1 & 0 & 0 \\ 0 & 0 & 1 & d_2 \\ 0 & 0 & 0 & 1"
                   r"\end{bmatrix}", rppr)
    assert M[0, 0] == sp.cos(q1) and M[1, 0] == sp.sin(q1) and M[2, 3] == rppr.q_symbols[1]


@pytest.mark.parametrize("bad", ["C_1 & S_1", 42, None])
def test_from_slide_refuses_what_is_not_a_slide_matrix(bad):
    with pytest.raises(DHLabError, match="bmatrix"):
        from_slide(bad, dhlab.robots.seed002_4dof())


def test_compare_with_slide_notices_a_misprint(capsys):
    rppr = dhlab.robots.seed002_4dof()
    printed = {k: dict(v) for k, v in PRINTED["4dof"].items()}
    compare_with_slide(rppr, printed)
    assert capsys.readouterr().out.count(": True") == 4
    printed["1A2"]["latex"] = printed["1A2"]["latex"].replace("d_2", "d_3", 1)
    assert "d_3" in printed["1A2"]["latex"]
    compare_with_slide(rppr, printed)
    assert "1A2: computed == printed on the slide: False" in capsys.readouterr().out
    with pytest.raises(DHLabError, match="3A4"):
        compare_with_slide(rppr, {k: v for k, v in printed.items() if k != "3A4"})


def test_compare_with_slide_compares_every_link_but_displays_only_those_asked(monkeypatch, capsys):
    import IPython.display
    shown = []
    monkeypatch.setattr(IPython.display, "display", lambda *objects: shown.extend(objects))
    arm6 = dhlab.robots.seed002_6dof()
    compare_with_slide(arm6, PRINTED["6dof"], show=[3])
    assert len(shown) == 1 and shown[0].data.startswith("{}^2A_3")
    assert capsys.readouterr().out.count("computed == printed on the slide: True") == 6
    for bad in ([7], "x", 3):
        with pytest.raises(DHLabError, match="link numbers"):
            compare_with_slide(arm6, PRINTED["6dof"], show=bad)


def test_check_cases_reports_the_verified_poses_and_a_wrong_robot(arm3, arm6):
    cases = [c for c in load_data("seed_cases")["cases"] if c["id"].startswith("003_6dof")]
    report = check_cases(arm3, "003_6dof").splitlines()
    assert len(report) == len(cases) and all(line.endswith("True") for line in report)
    for line, case in zip(report, cases):
        assert fmt(case["expected_position"]) in line
    assert "False" in check_cases(arm6, "003_6dof")          # the other arm does not reach seed 003's poses
    with pytest.raises(DHLabError, match="no case"):
        check_cases(arm3, "999_nothing")


def test_signed_angle_follows_the_right_hand_rule():
    assert signed_angle([1, 0, 0], [0, 1, 0], [0, 0, 1]) == pytest.approx(90)
    assert signed_angle([1, 0, 0], [0, 1, 0], [0, 0, -1]) == pytest.approx(-90)
    assert signed_angle([1, 0, 0], [-1, 0, 0], [0, 0, 1]) == pytest.approx(180)


@pytest.mark.parametrize("robot_name", ["seed003_6dof", "seed002_6dof"])
def test_rows_read_off_the_frames_are_the_tables_rows(robot_name):
    robot = getattr(dhlab.robots, robot_name)()
    lines = read_rows_at_zero(robot).splitlines()
    assert len(lines) == robot.n and all(line.endswith("the slide's row: True") for line in lines)
    for i, line in enumerate(lines, start=1):
        link = robot.links[i - 1]
        offset = np.degrees(float(link.offset))
        expected = f"q{i}" + (f" {'+' if offset > 0 else '−'} {abs(offset):g}°" if abs(offset) > 1e-9 else "")
        assert f"so ({expected}, " in line
        assert line.split("so (")[1].split(")")[0].endswith(f"{np.degrees(float(link.alpha)) + 0:g}°")


def test_hand_derived_matrices_are_the_tables(arm3):
    by_hand = hand_derived_003(arm3)
    assert sorted(by_hand) == [1, 2, 3, 4, 5, 6]
    for i, A in by_hand.items():
        assert sp.simplify(arm3.A(i) - A) == sp.zeros(4, 4)
    with pytest.raises(DHLabError, match="6-DOF"):
        hand_derived_003(dhlab.robots.seed002_4dof())


@pytest.mark.parametrize("robot_name", ["seed003_6dof", "seed002_6dof"])
def test_the_wrist_centre_ignores_the_wrist_and_is_p_minus_l4_a(robot_name):
    robot = getattr(dhlab.robots, robot_name)()
    rng = np.random.default_rng(11)
    for arm_deg in rng.uniform(-180, 180, size=(5, 3)):
        centre = wrist_centre(robot, arm_deg)
        for wrist_deg in rng.uniform(-180, 180, size=(4, 3)):
            T = robot.fk(np.radians(np.concatenate([arm_deg, wrist_deg])))
            np.testing.assert_allclose(T[:3, 3] - robot.params["l4"] * T[:3, 2], centre, atol=1e-12)
    with pytest.raises(DHLabError, match="three joint angles"):
        wrist_centre(robot, [0, 30])


def test_the_flipped_elbow_reaches_the_same_wrist_centre_another_way(arm3):
    for q in [(0, 30, 30), (180, -30, -30), (20, 10, 70)]:
        flipped = elbow_flipped(arm3, q)
        np.testing.assert_allclose(wrist_centre(arm3, flipped), wrist_centre(arm3, q), atol=1e-9)
        assert flipped[0] == q[0] and abs(flipped[1] - q[1]) > 1


def test_wrist_centre_check_reports_what_the_frames_show(arm3, arm6):
    lines = wrist_centre_check((arm3, arm6), arm_poses=5, wrist_poses=4).splitlines()
    assert [line.split(":")[0] for line in lines] == [arm3.name, arm6.name]
    for line in lines:
        assert line.count("True") == 3
        hand_move = float(re.search(r"moves up to ([\d.]+)", line).group(1))
        assert 0 < hand_move <= 2 * 4 + 1e-9                           # at most a diameter of radius l4


def test_the_panels_wrist_centre_stays_when_the_wrist_moves_and_follows_the_shoulder(arm3):
    panel, line = wrist_centre_panel(arm3, q=np.radians([0, 30, 30, 0, 0, 0]))
    before = line.value
    expected = arm3.frames(panel.q)[4][:3, 3]
    assert fmt(expected, 3).strip("()").split(", ")[0] in before.replace("-0.000", "0.000")
    panel.sliders[4].value = 45                        # q5: the wrist
    assert line.value == before
    panel.sliders[0].value = 40                        # q1: the shoulder
    assert line.value != before
    centre = arm3.frames(panel.q)[4][:3, 3]
    assert f"({centre[0]:.3f}, {centre[1]:.3f}, {centre[2]:.3f})" in line.value
