"""Driving a notebook in JupyterLab from Playwright: run it, read what it shows.

The browser tests use these helpers; everything is read from the page itself
(the notebook model that JupyterLab holds and the DOM it renders), so a check
sees what a student sees.

* :func:`lab_command`, :func:`write_lab_settings`: JupyterLab with every cell
  kept in the DOM (``windowingMode: none``), so that outputs far down the
  notebook are laid out and can be measured;
* :func:`open_notebook`, :func:`run_all`: open a notebook, wait for its kernel,
  Run All and wait until every cell has run and every widget is drawn;
* :func:`outputs_report`: per cell, the error outputs, figures shown as text,
  widgets that failed to display and outputs wider than the notebook column;
* :func:`panels`, :func:`settled`: the interactive panels (a slider and a
  figure in one output) and their pixels;
* :func:`full_page_screenshot`: the whole notebook in one picture.
"""
from __future__ import annotations

import io
import json
import os
import re
import time
from pathlib import Path

import numpy as np

TIMEOUT_MS = 240_000
WIDTH = 1400                     # the window width the course promises to fit
HEIGHT = 1000
# ipympl's canvas, the image backend's <img>, the canvas backend's <canvas> (the default in a kernel)
FIGURE_SELECTOR = ".jupyter-matplotlib-canvas-container canvas, .widget-image, canvas.dhlab-canvas"
FIGURE_TEXT = re.compile(r"<(?:matplotlib\.figure\.)?Figure size [\d.]+x[\d.]+ with \d+ Axes>")

# JupyterLab settings for a tested server: no news pop-ups, every cell in the DOM
LAB_SETTINGS = {
    "@jupyterlab/apputils-extension/notification.jupyterlab-settings":
        {"fetchNews": "false", "checkForUpdates": False},
    "@jupyterlab/notebook-extension/tracker.jupyterlab-settings": {"windowingMode": "none"},
}


def lab_command(root: Path) -> list:
    """The arguments of ``python -m`` that start JupyterLab on ``root`` (for ``start_server``)."""
    return ["jupyter", "lab", "--ServerApp.ip=127.0.0.1", "--IdentityProvider.token={token}",
            "--ServerApp.allow_root=True", "--LabApp.expose_app_in_browser=True",
            f"--ServerApp.root_dir={root}"]


def write_lab_settings(root: Path) -> None:
    for name, value in LAB_SETTINGS.items():
        path = root / ".settings" / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(json.dumps(value))


def with_backend(source: Path, target: Path, backend: str | None) -> Path:
    """A copy of the notebook ``source`` at ``target``, without stored outputs, run
    under ``backend``: ``"widget"`` puts ``%matplotlib widget`` at the top of its
    first code cell, ``"inline"`` leaves the default backend (both replace a
    ``%matplotlib`` line the notebook has): dhlab's panels then use the canvas backend;
    ``"image"`` is the inline backend with dhlab's panels forced to PNG images
    (``%env DHLAB_BACKEND=image``, the fallback where anywidget cannot load)."""
    notebook = json.loads(source.read_text(encoding="utf-8"))
    if backend is not None:
        for cell in notebook["cells"]:
            if cell["cell_type"] != "code":
                continue
            text = "".join(cell["source"])
            if backend == "image":
                text = "%env DHLAB_BACKEND=image\n" + text
                backend = "inline"
            if re.search(r"^%matplotlib\b.*$", text, flags=re.M):
                text = re.sub(r"^%matplotlib\b.*$", f"%matplotlib {backend}", text, flags=re.M)
            elif backend != "inline":           # inline is the default: nothing to add
                text = f"%matplotlib {backend}\n" + text
            cell["source"] = text
            break
    for cell in notebook["cells"]:          # start from a clean page: no stored outputs
        if cell["cell_type"] == "code":
            cell["outputs"], cell["execution_count"] = [], None
    target.parent.mkdir(parents=True, exist_ok=True)
    target.write_text(json.dumps(notebook, indent=1), encoding="utf-8")
    return target


# the notebook being tested (JupyterLab's NotebookPanel), as the page's JavaScript sees it
NOTEBOOK_JS = "(window.__dhlabNotebook || window.jupyterapp.shell.currentWidget)"


def ssrms_panel_notebook(folder: Path, backend: str, prefix: str) -> Path:
    """A one-cell notebook ``<folder>/<prefix>_<backend>.ipynb`` showing the SSRMS teach panel
    with ``backend`` (the keys and screen-rate tests open it)."""
    code = f"import dhlab\npanel = dhlab.teach(dhlab.robots.ssrms(), backend={backend!r})\npanel"
    notebook = {"cells": [{"cell_type": "code", "execution_count": None, "id": "panel", "metadata": {},
                           "outputs": [], "source": code}],
                "metadata": {"kernelspec": {"display_name": "Python 3 (ipykernel)", "language": "python",
                                            "name": "python3"}},
                "nbformat": 4, "nbformat_minor": 5}
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / f"{prefix}_{backend}.ipynb"
    path.write_text(json.dumps(notebook), encoding="utf-8")
    return path


def open_lab(browser, server, width: int = WIDTH, height: int = HEIGHT, ratio: float = 1):
    """A new page with JupyterLab (a fresh, empty workspace), once the app is ready, at device
    pixel ratio ``ratio``. One page serves many notebooks: loading JupyterLab takes seconds."""
    page = browser.new_page(viewport={"width": width, "height": height}, device_scale_factor=ratio)
    page.goto(f"{server.url}/lab/workspaces/tier{os.urandom(4).hex()}?reset&token={server.token}",
              timeout=TIMEOUT_MS)
    page.wait_for_function("() => window.jupyterapp !== undefined", timeout=TIMEOUT_MS)
    page.evaluate("() => window.jupyterapp.restored")
    return page


def open_notebook(page, relative_path: str) -> None:
    """Open a notebook (path relative to the server's root) in the page, and wait
    until its kernel is idle; it becomes the notebook the other helpers look at."""
    page.evaluate("""async (path) => {
        const app = window.jupyterapp;
        const panel = await app.commands.execute('docmanager:open', {path, factory: 'Notebook'});
        window.__dhlabNotebook = panel;
        await panel.context.ready;
        await panel.sessionContext.ready;
        app.shell.activateById(panel.id);
    }""", relative_path)
    page.wait_for_function(
        f"() => {{ const w = {NOTEBOOK_JS}; const s = w.sessionContext.session;"
        " return s && s.kernel && s.kernel.status === 'idle'; }", timeout=TIMEOUT_MS)


def close_notebook(page) -> None:
    """Shut the notebook's kernel down (it would hold memory for the rest of the
    session) and close its tab, without saving."""
    page.evaluate(f"""async () => {{ const w = {NOTEBOOK_JS};
        window.__dhlabNotebook = null;
        if (!w) return;
        try {{ await w.sessionContext.shutdown(); }} finally {{ w.dispose(); }} }}""")


def run_all(page, timeout_ms: int = TIMEOUT_MS) -> float:
    """Run All, and wait until every cell has run (or the run stopped at an
    error) and no widget is still loading. Returns the seconds it took."""
    start = time.monotonic()
    page.evaluate("() => { window.__dhlabRunDone = false;"
                  " window.jupyterapp.commands.execute('notebook:run-all-cells')"
                  "   .finally(() => { window.__dhlabRunDone = true; }); }")
    page.wait_for_function(
        "() => window.__dhlabRunDone && (() => {"
        f" const nb = {NOTEBOOK_JS}.content;"
        " return nb.widgets.every(c => c.model.type !== 'code' || c.model.executionState !== 'running')"
        f"   && {NOTEBOOK_JS}.sessionContext.session.kernel.status === 'idle'; }})()",
        timeout=timeout_ms, polling=250)
    # widgets render after their output arrives: wait for the last "Loading widget..."
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline and page.locator(".jp-OutputArea-output", has_text="Loading widget").count():
        time.sleep(0.25)
    time.sleep(1.0)                     # last images decoded, MathJax typeset
    return time.monotonic() - start


# One pass over the notebook in the page: for each code cell, its outputs as
# JupyterLab's model holds them and as the DOM shows them.
_REPORT_JS = r"""
(figureText) => {
  const figurePattern = new RegExp(figureText);
  // what a reader sees: pictures, formulas, tables, text blocks (their right edge must be in the column)
  const VISIBLE = 'img, canvas, svg, mjx-container, table, pre, '
    + '.widget-html-content, .widget-label, .widget-image, .jp-RenderedText';
  const nb = NOTEBOOK.content;
  const column = nb.node.querySelector('.jp-Cell-outputArea, .jp-OutputArea');
  const cells = [];
  nb.widgets.forEach((cell, index) => {
    if (cell.model.type !== 'code') return;
    const source = cell.model.sharedModel.getSource();
    const report = {index, source: source.slice(0, 160), executed: cell.model.executionCount,
                    errors: [], stderr: [], figure_text: [], widget_failures: [], too_wide: []};
    const outputs = cell.model.outputs.toJSON();
    for (const out of outputs) {
      if (out.output_type === 'error') report.errors.push(`${out.ename}: ${out.evalue}`);
      if (out.output_type === 'stream' && out.name === 'stderr') report.stderr.push(String(out.text).slice(0, 400));
      const data = out.data || {};
      const plain = String(data['text/plain'] || '');
      const shown = Object.keys(data).some(k => k.startsWith('image/')
                                         || k === 'application/vnd.jupyter.widget-view+json');
      if (figurePattern.test(plain) && !shown) report.figure_text.push(plain.slice(0, 100));
    }
    const area = cell.outputArea ? cell.outputArea.node : null;
    if (area) {
      area.querySelectorAll('.jp-OutputArea-output').forEach((node) => {
        const text = node.innerText || '';
        if (/Error displaying widget|Widget Javascript not detected|Loading widget/.test(text)
            && !node.querySelector('.widget-html, .widget-label'))
          report.widget_failures.push(text.trim().slice(0, 120));
        if (node.dataset.mimeType === 'application/vnd.jupyter.widget-view+json') {
          const box = node.getBoundingClientRect();
          if (!node.querySelector('.jupyter-widgets') || box.height < 2)
            report.widget_failures.push(`a widget view of ${Math.round(box.width)}x${Math.round(box.height)} px`);
        }
        if (figurePattern.test(text) && !node.querySelector('img, canvas'))
          if (!report.figure_text.includes(text.trim())) report.figure_text.push(text.trim().slice(0, 100));
        // wider than the column: the output itself, or anything inside it that scrolls or clips
        const limit = node.clientWidth;
        const measured = [[node, node.scrollWidth]];    // the output itself scrolls: wider than the column
        const left = node.getBoundingClientRect().left;
        node.querySelectorAll('*').forEach((el) => {
          // a slider's inner parts are translated past its track by design; form fields scroll their text
          if (el.matches('input, textarea, select, option') || el.closest('.widget-slider, .widget-readout')) return;
          if (el.closest('mjx-assistive-mml, .MJX_Assistive_MathML')) return;
          // content hidden or scrolled to the right of an element: it reaches past the element's right edge
          if (el.clientWidth > 0 && el.scrollWidth > el.clientWidth + 1)
            measured.push([el, el.getBoundingClientRect().right - left + el.scrollWidth - el.clientWidth]);
          if (el.matches(VISIBLE)) {
            const right = el.getBoundingClientRect().right - left;
            if (right > limit + 1) measured.push([el, right]);
          }
        });
        let worst = null;
        for (const [el, width] of measured) if (width > limit + 1 && (!worst || width > worst[1])) worst = [el, width];
        if (worst) {
          const el = worst[0];
          report.too_wide.push({width: Math.round(worst[1]), column: limit,
                                element: el.tagName.toLowerCase() + (el.className && typeof el.className === 'string'
                                         ? '.' + el.className.split(' ').filter(Boolean).slice(0, 2).join('.') : ''),
                                text: (node.innerText || '').trim().slice(0, 80)});
        }
      });
    }
    cells.push(report);
  });
  return {cells, column: column ? column.clientWidth : null};
}
"""


def outputs_report(page) -> dict:
    """What each code cell shows: ``{"cells": [...], "column": px}``; each cell has
    ``errors``, ``stderr``, ``figure_text``, ``widget_failures``, ``too_wide``."""
    return page.evaluate(_REPORT_JS.replace("NOTEBOOK", NOTEBOOK_JS), FIGURE_TEXT.pattern)


def problems(report: dict, excerpts: bool = True) -> list:
    """One line per failure (errors, figures as text, widgets not shown, outputs too
    wide); ``excerpts=False`` leaves out the text quoted from an output too wide."""
    lines = []
    for cell in report["cells"]:
        where = f"cell {cell['index']} ({_first_line(cell['source'])})"
        lines += [f"{where}: error output {e}" for e in cell["errors"]]
        lines += [f"{where}: figure shown as text {t!r}" for t in cell["figure_text"]]
        lines += [f"{where}: widget not shown: {w}" for w in cell["widget_failures"]]
        lines += [f"{where}: output {w['width'] if excerpts else 'too'} px wide in a {w['column']} px column"
                  + (f" ({w['element']}: {w['text']!r})" if excerpts else "") for w in cell["too_wide"]]
    return lines


def _first_line(source: str) -> str:
    lines = [line for line in source.splitlines() if line.strip() and not line.startswith("# NBVAL")]
    return (lines[0] if lines else "")[:60]


# --- panels and their pixels -------------------------------------------------------

def panels(page, timeout: float = 20.0) -> list:
    """The outputs that hold an interactive panel: a slider and a figure in one
    output. Returns ``(cell index, output locator)`` pairs.

    A box widget draws its children after itself, one by one: the list is read
    again until it holds still for a second and no output shows a slider
    without its figure yet (under load a panel's picture can come seconds after
    its slider), or ``timeout`` seconds have passed."""
    script = """() => {
      const found = [], waiting = [];
      document.querySelectorAll('.jp-Notebook .jp-Cell').forEach((cell, i) => {
        const ks = [];
        cell.querySelectorAll('.jp-OutputArea-output').forEach((out, k) => {
          const slider = out.querySelector('.widget-slider'), figure = out.querySelector(%r);
          if (slider && figure) ks.push(k);
          else if (slider) waiting.push(i);
        });
        if (ks.length) found.push([i, ks]);
      });
      return {found, waiting};
    }""" % FIGURE_SELECTOR
    deadline, last, since = time.monotonic() + timeout, None, time.monotonic()
    while True:
        seen = page.evaluate(script)
        if seen != last:
            last, since = seen, time.monotonic()
        if (not seen["waiting"] and time.monotonic() - since >= 1.0) or time.monotonic() > deadline:
            break
        time.sleep(0.25)
    cells = page.locator(".jp-Notebook .jp-Cell")
    return [(i, cells.nth(i).locator(".jp-OutputArea-output").nth(k))
            for i, outputs in last["found"] for k in outputs]


def pixels(locator) -> np.ndarray:
    from PIL import Image

    return np.asarray(Image.open(io.BytesIO(locator.screenshot())).convert("RGB")).astype(np.int16)


def settled(locator, timeout: float = 20.0, pause: float = 0.3) -> np.ndarray:
    """The element's pixels once two screenshots ``pause`` seconds apart agree."""
    deadline = time.monotonic() + timeout
    last = pixels(locator)
    while time.monotonic() < deadline:
        time.sleep(pause)
        now = pixels(locator)
        if now.shape == last.shape and (now == last).all():
            return now
        last = now
    raise AssertionError(f"the figure kept changing for {timeout:.0f} s")


def changed_fraction(before: np.ndarray, after: np.ndarray) -> float:
    """The fraction of pixels that changed clearly (1.0 when the size changed)."""
    if before.shape != after.shape:
        return 1.0
    return float((np.abs(after - before).max(axis=2) > 40).mean())


# --- pictures ----------------------------------------------------------------------


MIN_CHANGED = 0.0005           # a moved slider must change at least this fraction of the figure's pixels


def keys_until_changed(page, handle, changed) -> float:
    """Arrow keys on a slider's ``handle`` until ``changed()`` (the fraction of the figure's pixels
    changed since the start) reaches :data:`MIN_CHANGED`; that fraction. A slider at its maximum
    only moves left; a step-through whose first motion is null (θ = 0) changes nothing until the
    next motion: End takes it to the last one."""
    fraction = 0.0
    for key, presses in (("ArrowRight", 12), ("ArrowLeft", 12), ("End", 1)):
        handle.focus()
        for _ in range(presses):
            page.keyboard.press(key)
        time.sleep(0.3)
        fraction = changed()
        if fraction >= MIN_CHANGED:
            break
    return fraction


def full_page_screenshot(page, path: Path, max_height: int = 30_000) -> Path:
    """The whole notebook in one picture (PNG; JPEG for a ``.jpg`` path, though a
    page of text is smaller as PNG): the window is made as tall as the notebook
    (its width, and so the layout across, is kept), then put back."""
    path.parent.mkdir(parents=True, exist_ok=True)
    scroller = ".jp-NotebookPanel:not(.lm-mod-hidden) .jp-WindowedPanel-outer"
    size = page.viewport_size
    extra = page.evaluate(f"""() => {{ const s = document.querySelector('{scroller}');
        return s ? s.scrollHeight - s.clientHeight : 0; }}""")
    height = int(min(size["height"] + max(extra, 0) + 20, max_height))
    page.set_viewport_size({"width": size["width"], "height": height})
    try:
        page.evaluate(f"() => {{ const s = document.querySelector('{scroller}'); if (s) s.scrollTop = 0; }}")
        time.sleep(0.8)
        if path.suffix.lower() in (".jpg", ".jpeg"):
            page.screenshot(path=str(path), type="jpeg", quality=80)
        else:
            page.screenshot(path=str(path))
    finally:
        page.set_viewport_size(size)
    return path


def move_first_slider(page, output) -> tuple:
    """Arrow keys on the first slider of a panel; (fraction of the figure's pixels
    that changed, what the page showed wrong or '')."""
    figure = output.locator(FIGURE_SELECTOR).first
    figure.scroll_into_view_if_needed()
    before = settled(figure, pause=0.2)
    handle = output.locator(".widget-slider .noUi-handle").first
    changed = keys_until_changed(page, handle, lambda: changed_fraction(before, settled(figure, pause=0.2)))
    errors = output.locator(".widget-html", has_text="Error while updating")
    return changed, (errors.first.inner_text()[:300] if errors.count() else "")
