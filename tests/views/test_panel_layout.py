"""A panel holds still while its sliders move.

Headless: every slider of each panel is swept across its range; nothing that decides the
panel's layout may change: the widget tree (which widgets, in which order), every widget's
``layout`` and ``style``, and the *shape* of every readout whose text changes. A readout
whose text changes keeps its size only if it is a box of fixed height, or its numbers
sit in table cells of fixed width (``table-layout:fixed``, each ``<td>`` with a width)
with the same rows, and the same text around the table. The browser tier measures the
panel's box itself (tests/browser/test_screen_rate_browser.py).
"""
import functools
import re

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest

import dhlab
from dhlab.views.panels.spaces import spaces
from dhlab.views.panels.stepthrough import stepthrough
from dhlab.views.panels.teach import teach


def tree(widget, path="panel"):
    """(path, widget) for the widget and every widget under it."""
    yield path, widget
    for k, child in enumerate(getattr(widget, "children", ())):
        yield from tree(child, f"{path}/{k}:{type(child).__name__}")


def layout_of(panel) -> dict:
    """What decides the layout: each widget's type, layout and style traits."""
    shape = {}
    for path, widget in tree(panel):
        parts = {}
        for name in ("layout", "style"):
            part = getattr(widget, name, None)
            if part is not None and hasattr(part, "get_state"):
                parts[name] = {k: v for k, v in part.get_state().items() if not k.startswith("_")}
        shape[path] = (type(widget).__name__, parts)
    return shape


def readouts(panel) -> dict:
    return {path: w.value for path, w in tree(panel) if type(w).__name__ in ("HTML", "Label")}


def fixed_shape(html: str):
    """The readout with its numbers taken out of fixed-width cells: what must not change.
    Raises AssertionError when a table that holds changing text is not of fixed layout."""
    tables = re.findall(r"<table[^>]*>.*?</table>", html, flags=re.S)
    outside = re.sub(r"<table[^>]*>.*?</table>", "<table/>", html, flags=re.S)
    # a line that never wraps is one line, whatever it says
    outside = re.sub(r'(<div style="white-space:nowrap">).*?(</div>)', r"\1…\2", outside, flags=re.S)
    shapes = []
    for table in tables:
        assert "table-layout:fixed" in table, f"a readout table without a fixed layout: {table[:120]}"
        rows = re.findall(r"<tr[^>]*>(.*?)</tr>", table, flags=re.S)
        cells = [re.findall(r"<td([^>]*)>", row) for row in rows]
        assert all("width:" in attrs or "width:" in table.split(">")[0] for row in cells for attrs in row), \
            f"a readout cell without a fixed width: {table[:160]}"
        shapes.append([len(row) for row in cells])
    return outside, shapes


def check_still(panel, sliders, values=9):
    """Sweep each slider of ``sliders`` over ``values`` values of its range (and back)."""
    layout, texts = layout_of(panel), readouts(panel)
    changed = set()
    for slider in sliders:
        start = slider.value
        for value in [*np.linspace(slider.min, slider.max, values), start]:
            slider.value = float(value)
            assert layout_of(panel) == layout, f"the layout changed at {slider.description} = {value}"
            now = readouts(panel)
            assert now.keys() == texts.keys()
            changed |= {path for path in now if now[path] != texts[path]}
            for path in changed:
                widget = dict(tree(panel))[path]
                if widget.layout.height:                       # a box of fixed height
                    continue
                assert fixed_shape(now[path]) == fixed_shape(texts[path]), \
                    f"readout {path} changed its shape at {slider.description} = {value}: {now[path][:200]}"
    assert panel.error is None
    return changed


@pytest.mark.parametrize("name", ["ssrms", "puma560", "pr_mechanism", "rrr_example"])
def test_teach_panel_holds_still(name):
    panel = teach(dhlab.robots.catalogue()[name](), backend="image")
    changed = check_still(panel, panel.sliders, values=7)
    assert len(changed) >= 2, "the pose and the matrix did not change: the sweep moved nothing"


def test_stepthrough_panel_holds_still():
    panel = stepthrough(90, 1.5, 2.0, -90, unit="m", backend="image")
    changed = check_still(panel, [panel.slider], values=17)
    assert changed, "the sweep changed no readout"
    assert panel.text.layout.height, "the step's text has no fixed box"


def test_spaces_panel_holds_still():
    robot = dhlab.robots.pr_mechanism()
    panel = spaces(robot, ik=functools.partial(dhlab.ik.pr_mechanism_ik, robot), backend="image")
    changed = check_still(panel, [*panel.sliders, *panel.target_sliders], values=7)
    assert changed, "the sweep changed no readout"


def test_fixed_shape_sees_a_cell_that_grows():
    """The check can fail: a table of auto layout, or a row more, is a change of shape."""
    from dhlab.views.panels.teach import matrix_html

    assert fixed_shape(matrix_html(np.eye(4))) == fixed_shape(matrix_html(-30 * np.ones((4, 4))))
    with pytest.raises(AssertionError):
        fixed_shape("<table><tr><td>1.0</td></tr></table>")
    assert fixed_shape(matrix_html(np.eye(4))) != fixed_shape(matrix_html(np.eye(4)) + "<br>note")
