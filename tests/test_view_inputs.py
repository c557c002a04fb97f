"""Views and panels at the boundary (issue 14): robot first, then q, the rest
keyword-only; junk input gets a clear DHLabError, never a raw traceback."""
import functools

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from hypothesis import given, settings, strategies as st  # noqa: E402

import dhlab  # noqa: E402
from dhlab import robots  # noqa: E402
from dhlab.dh import DHRobot, PrismaticDH, RevoluteDH  # noqa: E402
from dhlab.views.figures import new_figure  # noqa: E402
from dhlab.views.spaces import spaces  # noqa: E402
from dhlab.views.stepthrough import stepthrough, stepthrough_link  # noqa: E402
from dhlab.views.teach import teach  # noqa: E402
from dhlab.views.view import robot_view  # noqa: E402

DHLabError = dhlab.DHLabError


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
