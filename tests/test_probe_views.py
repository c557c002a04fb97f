"""Probe 14, defects L–P: the views' options and values are checked where they enter
(stepthrough, SpacesPanel.set_target and its ik, teach / robot_view, show_matrix)."""
import functools
from decimal import Decimal

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
import sympy as sp  # noqa: E402

import dhlab  # noqa: E402
from dhlab import deg2rad  # noqa: E402

DHLabError = dhlab.DHLabError


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


@pytest.fixture(scope="module")
def puma():
    return dhlab.robots.puma560()


# --- L: stepthrough(theta_deg, d, a, alpha_deg, unit=…) --------------------------------------
@pytest.mark.parametrize("value", [sp.Rational(1, 2), sp.Float(0.5), Decimal("0.5")])
@pytest.mark.parametrize("which", ["d", "a"])
def test_stepthrough_takes_sympy_and_decimal_lengths(which, value):
    panel = dhlab.stepthrough(**{which: value}, backend="image")
    position = panel.frame_at(4)[:3, 3]
    assert position[2 if which == "d" else 0] == pytest.approx(0.5)
    assert panel.length == pytest.approx(0.15)


def test_stepthrough_takes_sympy_degrees():
    panel = dhlab.stepthrough(theta_deg=sp.Integer(90), alpha_deg=sp.pi / 4, backend="image")
    assert panel.frame_at(4)[:3, 0] == pytest.approx([0, 1, 0], abs=1e-12)


@pytest.mark.parametrize("options, match", [
    (dict(d=deg2rad(30)), r"d is a length, but you gave an angle"),                 # L3
    (dict(a=deg2rad(30)), r"a is a length, but you gave an angle"),
    (dict(theta_deg=deg2rad(90)), r"theta_deg = deg2rad\(90\) is already in radians"),   # L4
    (dict(alpha_deg=deg2rad(90)), r"alpha_deg = deg2rad\(90\) is already in radians"),
    (dict(theta_deg=1e300), r"theta_deg = 1e\+300° is more than a full turn.*degrees"),   # L5
    (dict(alpha_deg=-400), r"alpha_deg = -400° is more than a full turn"),
    (dict(d=1e308), r"^d = 1e\+308 is too large for a length"),                 # L6
    (dict(a=-1e200), r"^a = 1e\+200 is too large for a length"),
    (dict(d=1.0, unit=None), r"unit must be text"),                             # L7
    (dict(d=1.0, unit=5), r"unit must be text"),
    (dict(d=1.0, unit=["m"]), r"unit must be text"),
    (dict(d=1.0, unit=b"m"), r"unit must be text"),
])
def test_stepthrough_refuses_mixed_up_values(options, match):
    with pytest.raises(DHLabError, match=match):
        dhlab.stepthrough(**options, backend="image")


def test_stepthrough_still_takes_plain_degrees():
    panel = dhlab.stepthrough(theta_deg=90, d=1.0, a=0.5, alpha_deg=-90, i=2, unit="m", backend="image")
    assert panel.frame_at(2)[:3, 3].round(6).tolist() == [0.0, 0.0, 1.0]
    assert panel.unit == "m"


# --- M: SpacesPanel.set_target(x, y) -------------------------------------------------------
@pytest.fixture(scope="module")
def pr():
    return dhlab.robots.pr_mechanism()


@pytest.fixture
def spaces_panel(pr):
    return dhlab.spaces(pr, ik=functools.partial(dhlab.ik.pr_mechanism_ik, pr), backend="image")


@pytest.mark.parametrize("x, y, match", [
    ("abc", 0.2, r"target x = 'abc' is not a valid number"),
    (None, 0.2, r"target x = None is not a valid number"),
    (1j, 0.2, r"target x = 1j is not a valid number"),
    ([0.5], 0.2, r"target x = \[0.5\] is not a valid number"),
    (10**400, 0.2, r"target x = .* too large"),
    ("1.2", True, r"target x = '1.2' is not a valid number"),
    (1.2, True, r"target y = True is not a valid number"),
    (1.2, deg2rad(10), r"target y is a length, but you gave an angle"),
    (float("nan"), 0.2, r"target x is nan"),
])
def test_set_target_refuses_what_is_not_a_length(spaces_panel, x, y, match):
    with pytest.raises(DHLabError, match=match):
        spaces_panel.set_target(x, y)


def test_set_target_takes_any_real_number(spaces_panel):
    spaces_panel.set_target(Decimal("2.0"), sp.Rational(1, 4))
    assert spaces_panel.target == (2.0, 0.25)
    assert spaces_panel.q.round(6).tolist() == [0.566987, 0.523599]


# --- N: spaces(…, ik=f): what the ik must be and return --------------------------------------
@pytest.mark.parametrize("ik, match", [
    (lambda x, y: [[0.1]], r"ik must return a list of joint vectors.*must hold 2 joint values"),
    (lambda x, y: None, r"ik must return a list of joint vectors.*returned None"),
    (lambda x, y: "abc", r"ik must return a list of joint vectors.*returned 'abc'"),
    (lambda x, y: [[1j, 0]], r"ik must return a list of joint vectors.*complex"),
    (lambda x, y: [0.1, 0.2], r"ik must return a list of joint vectors.*\[\[0.1, 0.2\]\]"),
    (lambda x, y: np.float64(0.1), r"ik must return a list of joint vectors"),
    (lambda x, y: [[0.1, 400]], r"more than a full turn"),
    (lambda x, y: 1 / 0, r"ik\(.*\) failed: ZeroDivisionError"),
    (lambda: [], r"ik must be a function ik\(x, y\)"),
    (lambda x: [], r"ik must be a function ik\(x, y\)"),
])
def test_spaces_says_what_the_ik_must_return(pr, ik, match):
    with pytest.raises(DHLabError, match=match):
        dhlab.spaces(pr, ik=ik, backend="image")


def test_spaces_takes_an_ik_with_defaults_or_tuples(pr):
    panel = dhlab.spaces(pr, ik=lambda x, y, extra=None: ((0.5, 0.0),), backend="image")
    assert [s.tolist() for s in panel.solutions] == [[0.5, 0.0]]
    panel = dhlab.spaces(pr, ik=lambda x, y: [], backend="image")
    assert panel.solutions == []
    panel = dhlab.spaces(pr, ik=lambda *args: np.zeros((0, 2)), backend="image")
    assert panel.solutions == []


# --- O: teach / robot_view options ---------------------------------------------------------
@pytest.mark.parametrize("options, match", [
    (dict(color="notacolor"), r"color must be a matplotlib colour"),
    (dict(color=5), r"color must be a matplotlib colour"),
    (dict(color=(2, 0, 0)), r"color must be a matplotlib colour"),
    (dict(alpha=5), r"alpha must be from 0 \(invisible\) to 1"),
    (dict(alpha=-1), r"alpha must be from 0"),
    (dict(alpha="0.5"), r"alpha = '0.5' is not a valid number"),
    (dict(ax=5), r"ax must be a matplotlib 3D Axes"),
    (dict(live="live"), r"live must be a dhlab LiveFigure"),
    (dict(title=["t"]), r"title must be text"),
    (dict(title=5), r"title must be text"),
])
def test_robot_view_checks_its_options(puma, options, match):
    with pytest.raises(DHLabError, match=match):
        dhlab.robot_view(puma, backend="image", **options)


def test_robot_view_refuses_a_2d_axes_for_a_3d_view(puma):
    with pytest.raises(DHLabError, match=r"ax must be a matplotlib 3D Axes.*projection='3d'"):
        dhlab.robot_view(puma, ax=plt.figure().add_subplot(), backend="image")
    planar = dhlab.robots.pr_mechanism()
    with pytest.raises(DHLabError, match=r"ax must be a matplotlib 2D Axes"):
        dhlab.robot_view(planar, ax=plt.figure().add_subplot(projection="3d"), planar=True)


@pytest.mark.parametrize("options, match", [
    (dict(color="notacolor"), r"color must be a matplotlib colour"),
    (dict(controls="no"), r"controls must be True or False"),
    (dict(controls=None), r"controls must be True or False"),
    (dict(controls=2), r"controls must be True or False"),
    (dict(controls=[]), r"controls must be True or False"),
])
def test_teach_checks_its_options(puma, options, match):
    with pytest.raises(DHLabError, match=match):
        dhlab.teach(puma, backend="image", **options)


def test_view_options_that_work_keep_working(puma):
    view = dhlab.robot_view(puma, color=(0.2, 0.4, 0.6), alpha=0.5, title="PUMA", backend="image")
    assert view.ax.get_title() == "PUMA"
    assert dhlab.robot_view(puma, title=False, backend="image").ax.get_title() == ""
    fig = plt.figure()
    ax = fig.add_subplot(projection="3d")
    assert dhlab.robot_view(puma, ax=ax).ax is ax
    assert len(dhlab.teach(puma, controls=False, backend="image").children) == 2


def test_update_draw_is_a_flag(puma):
    view = dhlab.robot_view(puma, backend="image")
    with pytest.raises(DHLabError, match=r"draw must be True or False"):
        view.update(puma.qz, draw="yes")
    view.update(puma.qz, draw=0)


def test_robot_view_refuses_a_pose_outside_the_limits_as_teach_does(puma):
    q = deg2rad([0, 0, 0, 0, 0, 300])
    with pytest.raises(DHLabError) as refused_by_teach:
        dhlab.teach(puma, q, backend="image")
    with pytest.raises(DHLabError) as refused_by_view:
        dhlab.robot_view(puma, q, backend="image")
    assert str(refused_by_view.value) == str(refused_by_teach.value)
    assert "outside joint 6's limits" in str(refused_by_view.value)


# --- P: show_matrix options ------------------------------------------------------------------
@pytest.fixture(scope="module")
def M():
    return dhlab.robots.rrr_example().fk_sym()


@pytest.mark.parametrize("options, match", [
    (dict(name=5), r"name must be text"),
    (dict(name=["T"]), r"name must be text"),
    (dict(max_width_px=10**400), r"max_width_px = .* too large"),
    (dict(max_width_px=float("inf")), r"max_width_px is inf"),
    (dict(max_width_px=True), r"max_width_px = True is not a valid number"),
    (dict(max_width_px="900"), r"max_width_px = '900' is not a valid number"),
    (dict(max_width_px=50), r"max_width_px must be a number of pixels above 100"),
])
def test_show_matrix_checks_its_options(M, options, match):
    with pytest.raises(DHLabError, match=match):
        dhlab.show_matrix(M, **options)


def test_show_matrix_options_that_work_keep_working(M):
    shown = dhlab.show_matrix(M, name=r"{}^0T_3", max_width_px=np.int64(600))
    assert shown.max_width_px == 600.0 and shown.pieces[0].startswith(r"{}^0T_3")
    assert dhlab.show_matrix(M, name=None, max_width_px=Decimal(900)).max_width_px == 900.0


def test_stepthrough_link_refuses_a_pose_outside_the_joint_limits_as_teach_does():
    import dhlab
    puma = dhlab.robots.puma560()
    with pytest.raises(dhlab.DHLabError, match=r"q\[5\] = 300° is outside joint 6's limits"):
        dhlab.stepthrough_link(puma, 1, dhlab.deg2rad([0, 0, 0, 0, 0, 300]), backend="image")
    dhlab.stepthrough_link(puma, 1, dhlab.deg2rad([0, 0, 0, 0, 0, 30]), backend="image")
