"""Keys reach a focused slider, the other keys still reach JupyterLab, and the inline figure is
not dragged away.

JupyterLab's shortcuts read a key before the page's widgets: the panel's invisible
``SliderKeys`` widget (dhlab/views/live/keys.py + keys.js) puts ``data-lm-suppress-shortcuts`` on
the focused slider while one of its own keys is dispatched, so no shortcut applies to that key.
The test clicks a slider of the SSRMS teach panel *with the mouse* and checks that it then
takes ArrowRight, ArrowUp, PageUp, ArrowLeft, PageDown, Home and End while the focus stays on
it and the notebook's cursor stays on its cell — in a notebook whose shortcuts would take those
keys (a binding like the browser edition's and the decks', added for the test) — and that a
key that is not the slider's, J (command mode: next cell), still acts with the focus on the
slider, as Space (next slide) must in a deck: the attribute left on the slider stopped every
shortcut (the deck stopped at the first slider). The inline backend's ``<img>`` is not draggable.
"""
from __future__ import annotations

import json
import time

import pytest

import labdriver
from labdriver import TIMEOUT_MS, close_notebook, open_notebook, run_all

FIGURE = ".widget-image, .jupyter-matplotlib-canvas-container canvas"
# The browser edition's JupyterLab (4.4) reads every key in the capture phase, before the focused
# widget: emulated here in the course's JupyterLab (4.6, which reads keys after the widgets), with a
# shortcut on the slider's keys for any focused element of a notebook in command mode (what 4.4's
# notebook, "next heading", and jupyterlab-slideshow, "next slide", bind).
# The page is shared by the tier's later tests: the binding is removed again (UNBIND), or a plain
# slider of a later notebook (the faulty-notebook self-test's) would lose its keys.
GREEDY_BINDING = """() => {
  const app = window.jupyterapp;
  window.__dhlabTaken = 0;
  if (!app.commands.hasCommand('dhlab-test:take-key')) {
    const listener = (event) => app.commands.processKeydownEvent(event);
    document.addEventListener('keydown', listener, true);
    const undo = [() => document.removeEventListener('keydown', listener, true)];
    const command = app.commands.addCommand('dhlab-test:take-key', {execute: () => { window.__dhlabTaken += 1; }});
    undo.push(() => command.dispose());
    for (const key of ['ArrowRight', 'ArrowLeft', 'ArrowUp', 'ArrowDown', 'PageUp', 'PageDown', 'Home', 'End']) {
      const binding = app.commands.addKeyBinding({command: 'dhlab-test:take-key', keys: [key],
                                                  selector: '.jp-Notebook.jp-mod-commandMode :focus'});
      undo.push(() => binding.dispose());
    }
    window.__dhlabUnbind = () => { undo.forEach((f) => f()); window.__dhlabUnbind = null; };
  }
}"""
UNBIND = "() => { if (window.__dhlabUnbind) window.__dhlabUnbind(); }"

ACTIVE_CELL = f"() => {labdriver.NOTEBOOK_JS}.content.activeCellIndex"


def value(handle) -> float:
    return float(handle.get_attribute("aria-valuenow"))


@pytest.mark.parametrize("backend", ["image", "ipympl"])
def test_a_clicked_slider_takes_its_keys_even_where_a_shortcut_wants_them(lab_page, lab_root, backend):
    page = lab_page
    path = labdriver.ssrms_panel_notebook(lab_root / "keys", backend, "keys")
    notebook = json.loads(path.read_text())          # a cell after the panel, for J to go to
    notebook["cells"].append({"cell_type": "markdown", "id": "after", "metadata": {}, "source": "After."})
    path.write_text(json.dumps(notebook))
    try:
        open_notebook(page, f"keys/{path.name}")
        run_all(page)
        output = page.locator(".jp-OutputArea-output", has=page.locator(".widget-slider")).first
        output.locator(FIGURE).first.wait_for(timeout=TIMEOUT_MS)
        output.locator(".dhlab-keys").wait_for(state="attached", timeout=20_000)
        page.evaluate(GREEDY_BINDING)
        page.evaluate("() => window.jupyterapp.commands.execute('notebook:enter-command-mode')")
        handle = output.locator(".widget-slider .noUi-handle").nth(1)
        handle.scroll_into_view_if_needed()
        box = handle.bounding_box()
        page.mouse.click(box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
        time.sleep(0.3)
        low, high = (float(handle.get_attribute(f"aria-value{k}")) for k in ("min", "max"))
        cell_before = page.evaluate(ACTIVE_CELL)
        moves = []
        for key in ("Home", "ArrowRight", "ArrowUp", "PageUp", "ArrowLeft", "PageDown", "End"):
            before = value(handle)
            page.keyboard.press(key)
            time.sleep(0.3)
            moves.append((key, before, value(handle)))
        taken = page.evaluate("() => window.__dhlabTaken")
        focused = handle.evaluate("e => e === document.activeElement")
        cell_after_keys = page.evaluate(ACTIVE_CELL)
        left_marked = output.locator("[data-lm-suppress-shortcuts]").count()
        page.keyboard.press("j")                      # not a slider key: the notebook's "next cell"
        time.sleep(0.3)
        cell_after_j = page.evaluate(ACTIVE_CELL)
        if backend == "image":
            image = output.locator("img.widget-image").first
            assert image.evaluate("e => e.draggable") is False, "the figure's picture can be dragged"
            assert image.evaluate("e => getComputedStyle(e).webkitUserDrag") == "none"
    finally:
        page.evaluate(UNBIND)
        close_notebook(page)
    assert taken == 0, f"a notebook shortcut took {taken} keys typed on the slider: {moves}"
    assert moves[0][2] == pytest.approx(low) and moves[-1][2] == pytest.approx(high), moves
    for key, before, after in moves[1:-1]:
        assert (after > before) if key in ("ArrowRight", "ArrowUp", "PageUp") else (after < before), moves
    assert focused, "the focus left the slider"
    assert cell_before == cell_after_keys == 0, \
        f"the slider's keys moved the notebook's cursor: cell {cell_before} -> {cell_after_keys}"
    assert cell_after_j == 1, ("J typed with the focus on a slider did not reach the notebook (its cursor stayed "
                               f"on cell {cell_after_j}): the panel stops the shortcuts of keys that are not the "
                               "slider's (a deck's Space too)")
    assert left_marked == 0, f"{left_marked} elements of the panel keep data-lm-suppress-shortcuts after the keys"
