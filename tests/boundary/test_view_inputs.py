"""Bad input into the views and panels: robot first, then q, the rest keyword-only; junk input gets
a clear DHLabError, never a raw traceback. Options and values are checked where they enter
(stepthrough, SpacesPanel.set_target and its ik, teach / robot_view, show_matrix); a figsize of 0
is refused, not read as the default."""
import functools
from decimal import Decimal

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

import dhlab
from dhlab import deg2rad, robots
from dhlab.dh import DHRobot, PrismaticDH, RevoluteDH
from dhlab.views.figures import new_figure
from dhlab.views.panels.spaces import spaces
from dhlab.views.panels.stepthrough import stepthrough, stepthrough_link
from dhlab.views.panels.teach import teach
from dhlab.views.view import robot_view

DHLabError = dhlab.DHLabError


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


def test_every_panel_takes_the_robot_then_q():
    pr = robots.pr_mechanism()
    panel = spaces(pr, [0.5, dhlab.deg2rad(30)], backend="image")       # was "'list' object is not callable"
    np.testing.assert_allclose(panel.q, [0.5, np.radians(30)])
    assert teach(pr, [0.5, dhlab.deg2rad(30)], backend="image").q[0] == pytest.approx(0.5)
    assert robot_view(pr, [0.5, dhlab.deg2rad(30)], backend="image").q[0] == pytest.approx(0.5)
    with pytest.raises(DHLabError, match="ik="):                    # the old positional ik
        spaces(pr, functools.partial(dhlab.ik.pr_mechanism_ik, pr))
    with pytest.raises(TypeError):                                  # keyword-only options
        teach(pr, None, None)


@pytest.mark.parametrize("q", [None, "ab", [[0.1, 0.2], [0.3, 0.4]], [np.nan, 0.1], [1, 2, 3],
                               [0.5, 400.0], [True, 0.2]])
def test_junk_q_is_refused_clearly(q):
    pr = robots.pr_mechanism()
    if q is None:                                   # None is the default pose, not junk
        assert teach(pr, q, backend="image").q.shape == (2,)
        return
    for make in (lambda: teach(pr, q, backend="image"), lambda: robot_view(pr, q, backend="image"),
                 lambda: spaces(pr, q, backend="image")):
        with pytest.raises(DHLabError):
            make()


@pytest.mark.parametrize("robot", [None, "puma", 5, np.eye(4)])
def test_junk_robot_is_refused_clearly(robot):
    for make in (teach, robot_view, spaces, lambda r: stepthrough_link(r, 1)):
        with pytest.raises(DHLabError):
            make(robot)


@pytest.mark.parametrize("figsize", [(-1, 3), (float("nan"), 3), (0, 0), "big", (3,), (1e9, 3), (7e-189, 1.0)])
def test_junk_figsize_is_refused_clearly(figsize):
    with pytest.raises(DHLabError):
        teach(robots.puma560(), figsize=figsize, backend="image")
    with pytest.raises(DHLabError):
        new_figure(figsize)


def test_an_undrawable_prismatic_limit_is_refused():
    """Refused where it enters (the joint), before any view could try to draw its reach."""
    with pytest.raises(DHLabError, match=r"qlim \(a prismatic joint's limit\) = 1e\+308 is too large"):
        DHRobot([RevoluteDH(a=1.0), PrismaticDH(qlim=(0, 1e308))])


def test_a_robot_whose_origins_all_coincide_is_drawn():
    robot = DHRobot([RevoluteDH(), RevoluteDH(alpha=dhlab.deg2rad(90))])     # was "figure size (6, nan)"
    panel = teach(robot, backend="image")
    assert panel.live.png()[:4] == b"\x89PNG"
    assert len(panel.view.labels.texts) == 1                          # one place, one label


@pytest.mark.parametrize("i", ["1", 1.5, True, 0, 7, None])
def test_stepthrough_link_refuses_a_bad_link_number(i):
    with pytest.raises(DHLabError):
        stepthrough_link(robots.puma560(), i)


@pytest.mark.parametrize("step", [5, -1, "2", float("nan")])
def test_stepthrough_refuses_a_step_outside_0_to_4(step):          # it clamped silently
    with pytest.raises(DHLabError):
        stepthrough_link(robots.puma560(), 2, step=step)
    with pytest.raises(DHLabError):
        stepthrough(90, 1, 0, 0, step=step)


def test_set_q_needs_every_joint():
    panel = teach(robots.puma560(), backend="image")
    before = [s.value for s in panel.sliders]
    with pytest.raises(DHLabError):
        panel.set_q([0] * 5)                                          # moved 5 of 6 sliders
    assert [s.value for s in panel.sliders] == before
    with pytest.raises(DHLabError):
        panel.set_q(dhlab.deg2rad([0, 0, 0, 0, 0, 300]))                 # beyond joint 6 limits (±266°)
    assert [s.value for s in panel.sliders] == before


@pytest.mark.parametrize("option", [dict(camera="bottom"), dict(zoom=-1), dict(zoom="x"),
                                    dict(labels="yes"), dict(framing="tight"), dict(backend="qt"),
                                    dict(on_change=5)])
def test_bad_options_are_refused_clearly(option):
    with pytest.raises(DHLabError):
        teach(robots.puma560(), **option)


junk = st.one_of(st.none(), st.text(max_size=3), st.booleans(), st.integers(-10**6, 10**6),
                 st.floats(allow_nan=True, allow_infinity=True),
                 st.lists(st.one_of(st.floats(allow_nan=True), st.text(max_size=2), st.none()), max_size=4),
                 st.tuples(st.floats(allow_nan=True), st.floats(allow_nan=True)))


@settings(max_examples=40, deadline=None)
@given(q=junk, figsize=st.one_of(st.none(), junk))
def test_random_junk_gives_a_dhlab_error_or_a_panel(q, figsize):
    robot = robots.pr_mechanism()
    try:
        panel = teach(robot, q, figsize=figsize, backend="image")
    except DHLabError:
        return
    assert panel.q.shape == (2,) and np.isfinite(panel.q).all()


@pytest.fixture(scope="module")
def puma():
    return dhlab.robots.puma560()


# --- stepthrough(theta_deg, d, a, alpha_deg, unit=…) --------------------------------------
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


# --- SpacesPanel.set_target(x, y) -------------------------------------------------------
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


# --- spaces(…, ik=f): what the ik must be and return --------------------------------------
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


# --- teach / robot_view options ---------------------------------------------------------
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


# --- show_matrix options ------------------------------------------------------------------
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


# --- figsize=0, and the non-finite entries of show_matrix ----------------------------------------------------
@pytest.mark.parametrize("fn", [dhlab.teach, dhlab.robot_view])
def test_figsize_zero_is_refused_not_the_default(fn):
    with pytest.raises(DHLabError, match="figsize"):
        fn(robots.puma560(), figsize=0)


@pytest.mark.parametrize("M, where", [(sp.Matrix([[1, sp.zoo]]), r"M\[0, 1\] = zoo"),
                                      (sp.Matrix([[sp.nan, 0]]), r"M\[0, 0\] = nan"),
                                      ([[1.0, float("inf")]], r"M\[0, 1\] = oo"), (sp.oo, r"M\[0, 0\] = oo")])
def test_show_matrix_refuses_non_finite_entries(M, where):
    with pytest.raises(DHLabError, match=f"show_matrix: {where}"):
        dhlab.show_matrix(M)
