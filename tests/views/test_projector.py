"""dhlab.projector(): the lecture-hall switch (text, code, widgets, figures larger together).

What the browser shows is measured by tests/browser/test_decks_browser.py (body text in px,
slides that fit 1920x1080); here: the CSS it shows, the figures it scales, and that it undoes.
"""
from __future__ import annotations

import re

import pytest

import dhlab
from dhlab.errors import DHLabError
from dhlab.views import figures
from dhlab.views import projector as projector_module
from dhlab.views.figures import new_figure
from dhlab.views.panels import panel
from dhlab.views.projector import DEFAULT_SCALE, PAGE_PX, SLIDE_FIGURE_PX, WIDGETS_PX, stylesheet, widgets_scale

WIDGET_TEXT_PX = 13          # ipywidgets' text at normal size: what the panels' em widths are measured in


@pytest.fixture(autouse=True)
def projector_off():
    yield
    dhlab.projector(False)


def css_sizes(css: str) -> dict:
    return {name: float(px) for name, px in re.findall(r"(--[\w-]+): ([\d.]+)px;", css)}


def test_dhlab_projector_is_the_lecture_hall_switch():
    assert dhlab.projector is projector_module.projector


def test_the_default_makes_body_text_at_least_24_px():
    sizes = css_sizes(stylesheet(DEFAULT_SCALE))
    assert sizes["--jp-content-font-size1"] >= 24
    assert sizes["--jp-code-font-size"] >= 22 and sizes["--jp-widgets-font-size"] >= 19


@pytest.mark.parametrize("scale", [1.25, 1.75, 2.5])
def test_every_size_grows_by_the_scale(scale):
    sizes = css_sizes(stylesheet(scale))
    for name, px in PAGE_PX.items():
        assert sizes[name] == pytest.approx(px * scale, rel=1e-4), name
    grow = widgets_scale(scale)
    assert 1 < grow < scale                  # widgets grow too, less than the text (a panel must fit)
    for name, px in WIDGETS_PX.items():
        assert sizes[name] == pytest.approx(px * grow, rel=1e-4), name
    # a widget row grows by its text only: taller than before, less than the widgets' scale
    assert 28 < sizes["--jp-widgets-inline-height"] < 28 * grow


def test_normal_size_is_the_themes_own():
    assert stylesheet(1.0) == ""


def test_figures_made_afterwards_grow_and_projector_false_restores():
    assert dhlab.projector() == DEFAULT_SCALE
    small = new_figure((6, 3))                      # 300 px tall: grows by the whole scale
    assert small.dpi == pytest.approx(figures.MIN_DPI * DEFAULT_SCALE)
    assert dhlab.projector(False) == 1.0
    assert new_figure((6, 3)).dpi == pytest.approx(figures.MIN_DPI)


def test_a_tall_figure_grows_only_as_far_as_a_slide_allows():
    dhlab.projector()
    tall = new_figure((6, 6))                       # 600 px tall: 1050 px at 1.75 would not fit
    height_px = tall.get_size_inches()[1] * tall.dpi
    assert height_px == pytest.approx(SLIDE_FIGURE_PX)
    assert tall.dpi > figures.MIN_DPI
    huge = new_figure((6, 9))                       # taller than the slide even at normal size
    assert huge.dpi == pytest.approx(figures.MIN_DPI)   # never smaller than normal


def test_a_teach_panel_made_under_the_projector_is_larger_and_fits():
    robot = dhlab.robots.ssrms()
    normal = dhlab.teach(robot, backend="image")
    dhlab.projector()
    large = dhlab.teach(robot, backend="image")
    grown = large.figure.dpi / normal.figure.dpi
    assert 1.2 < grown <= DEFAULT_SCALE
    assert large.figure.get_size_inches()[1] * large.figure.dpi <= SLIDE_FIGURE_PX + 0.5


def test_panel_controls_made_afterwards_are_as_wide_as_their_text():
    """A panel's sliders and the column beside its figure are 330 and 370 px at normal size (as
    before) and grow with the widgets' text under the projector, so readouts are not squeezed."""
    robot = dhlab.robots.ssrms()
    assert dhlab.teach(robot, backend="image").sliders[0].layout.width == "330px"
    dhlab.projector()
    grow = widgets_scale(DEFAULT_SCALE)
    large = dhlab.teach(robot, backend="image")
    assert large.sliders[0].layout.width == f"{330 * grow:g}px"
    side = large.children[1]
    assert side.layout.width == f"{370 * grow:g}px"
    dhlab.projector(False)
    assert panel.control_width(panel.SIDE_PX) == "370px"


@pytest.mark.parametrize("on, scale", [("yes", 1.5), (True, 10), (True, 0), (True, "big"), (True, float("nan"))])
def test_bad_input_is_refused_with_a_clear_message(on, scale):
    with pytest.raises(DHLabError, match="projector|scale"):
        dhlab.projector(on, scale=scale)
    assert figures.projector_scale() == 1.0            # nothing half-switched


def test_in_a_notebook_it_shows_one_style_updated_everywhere(monkeypatch):
    """In a kernel, each call displays the stylesheet with one display id and updates the
    earlier ones, so the last call wins wherever its cell is; outside one it shows nothing."""
    import IPython
    import IPython.display

    shown = []
    monkeypatch.setattr(IPython.display, "display",
                        lambda data, raw, display_id: shown.append(("display", data["text/html"], display_id)))
    monkeypatch.setattr(IPython.display, "update_display",
                        lambda data, raw, display_id: shown.append(("update", data["text/html"], display_id)))

    dhlab.projector()
    assert shown == []                                  # plain Python: nothing displayed

    monkeypatch.setattr(IPython, "get_ipython", lambda: object())
    dhlab.projector(scale=2)
    dhlab.projector(False)
    kinds = [kind for kind, _, _ in shown]
    assert kinds == ["display", "update", "display", "update"]
    assert {display_id for _, _, display_id in shown} == {projector_module.DISPLAY_ID}
    assert css_sizes(shown[0][1])["--jp-content-font-size1"] == pytest.approx(28)
    assert shown[-1][1] == "<style>\n</style>"          # off: the theme's own sizes again
