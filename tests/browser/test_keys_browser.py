"""Keys reach a focused slider, and the inline figure is not dragged away (issue 23).

JupyterLab's shortcuts read a key before the page's widgets: the panel's invisible
``SliderKeys`` widget (dhlab/views/keys.py + keys.js) puts ``data-lm-suppress-shortcuts``
on its sliders, so no shortcut applies to a key typed on one. The test checks the
attribute is there on every slider of the SSRMS teach panel, that a slider *clicked with
the mouse* then takes ArrowRight, ArrowUp, PageUp, ArrowLeft, PageDown, Home and End
while the focus stays on it, and — in a notebook whose shortcuts would take → (a binding
like the browser edition's and the decks', added for the test) — that the slider still
gets the key. The inline backend's ``<img>`` is not draggable.
"""
from __future__ import annotations

import time

import pytest

import labdriver
from labdriver import TIMEOUT_MS, close_notebook, open_notebook, run_all

FIGURE = ".widget-image, .jupyter-matplotlib-canvas-container canvas"
# The browser edition's JupyterLab (4.4) reads every key in the capture phase, before the focused
# widget: emulated here in the course's JupyterLab (4.6, which reads keys after the widgets), with a
# shortcut on the slider's keys for any focused element of a notebook in command mode (what 4.4's
# notebook, "next heading", and jupyterlab-slideshow, "next slide", bind).
GREEDY_BINDING = """() => {
  const app = window.jupyterapp;
  window.__dhlabTaken = 0;
  if (!app.commands.hasCommand('dhlab-test:take-key')) {
    document.addEventListener('keydown', (event) => app.commands.processKeydownEvent(event), true);
    app.commands.addCommand('dhlab-test:take-key', {execute: () => { window.__dhlabTaken += 1; }});
    for (const key of ['ArrowRight', 'ArrowLeft', 'ArrowUp', 'ArrowDown', 'PageUp', 'PageDown', 'Home', 'End'])
      app.commands.addKeyBinding({command: 'dhlab-test:take-key', keys: [key],
                                  selector: '.jp-Notebook.jp-mod-commandMode :focus'});
  }
}"""




def value(handle) -> float:
    return float(handle.get_attribute("aria-valuenow"))


@pytest.mark.parametrize("backend", ["image", "ipympl"])
def test_a_clicked_slider_takes_its_keys_even_where_a_shortcut_wants_them(lab_page, lab_root, backend):
    page = lab_page
    path = labdriver.ssrms_panel_notebook(lab_root / "keys", backend, "keys")
    try:
        open_notebook(page, f"keys/{path.name}")
        run_all(page)
        output = page.locator(".jp-OutputArea-output", has=page.locator(".widget-slider")).first
        output.locator(FIGURE).first.wait_for(timeout=TIMEOUT_MS)
        sliders = output.locator(".widget-slider")
        page.wait_for_function("(n) => document.querySelectorAll("
                               "'.widget-slider[data-lm-suppress-shortcuts]').length >= n",
                               arg=sliders.count(), timeout=20_000)
        page.evaluate(GREEDY_BINDING)
        page.evaluate("() => window.jupyterapp.commands.execute('notebook:enter-command-mode')")
        handle = output.locator(".widget-slider .noUi-handle").nth(1)
        handle.scroll_into_view_if_needed()
        box = handle.bounding_box()
        page.mouse.click(box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
        time.sleep(0.3)
        low, high = (float(handle.get_attribute(f"aria-value{k}")) for k in ("min", "max"))
        moves = []
        for key in ("Home", "ArrowRight", "ArrowUp", "PageUp", "ArrowLeft", "PageDown", "End"):
            before = value(handle)
            page.keyboard.press(key)
            time.sleep(0.3)
            moves.append((key, before, value(handle)))
        taken = page.evaluate("() => window.__dhlabTaken")
        focused = handle.evaluate("e => e === document.activeElement")
        if backend == "image":
            image = output.locator("img.widget-image").first
            assert image.evaluate("e => e.draggable") is False, "the figure's picture can be dragged"
            assert image.evaluate("e => getComputedStyle(e).webkitUserDrag") == "none"
    finally:
        close_notebook(page)
    assert taken == 0, f"a notebook shortcut took {taken} keys typed on the slider: {moves}"
    assert moves[0][2] == pytest.approx(low) and moves[-1][2] == pytest.approx(high), moves
    for key, before, after in moves[1:-1]:
        assert (after > before) if key in ("ArrowRight", "ArrowUp", "PageUp") else (after < before), moves
    assert focused, "the focus left the slider"
