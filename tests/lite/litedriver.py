"""Drive a notebook of the browser edition (JupyterLite in Chromium) from Playwright.

The page exposes JupyterLab's application object as ``window.jupyterapp``: the driver runs cells
with its commands and reads the outputs from the notebook's model, as JSON in nbformat's shape,
so they compare with the stored notebook exactly as nbval compares them.
"""
from __future__ import annotations

import json
import re
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent.parent
NOTEBOOKS = ROOT / "notebooks"

# The JupyterLab notebook panel in front, and its kernel's state.
JS_PANEL = "() => { const w = window.jupyterapp && window.jupyterapp.shell.currentWidget;" \
           " return !!(w && w.content && w.content.model && w.sessionContext && w.sessionContext.session" \
           " && w.sessionContext.session.kernel); }"
JS_KERNEL_STATUS = "() => window.jupyterapp.shell.currentWidget.sessionContext.session.kernel.status"
JS_CELLS = """() => {
  const model = window.jupyterapp.shell.currentWidget.content.model;
  const cells = [];
  for (let i = 0; i < model.cells.length; i++) {
    const cell = model.cells.get(i);
    cells.push({type: cell.type, source: cell.sharedModel.getSource(),
                execution_count: cell.type === 'code' ? cell.executionCount : null,
                outputs: cell.type === 'code' ? cell.outputs.toJSON() : []});
  }
  return cells;
}"""
# Run cells first … last (each waits for the one before, as Shift-Enter from the top would).
JS_RUN = """async ([first, last]) => {
  const app = window.jupyterapp, notebook = app.shell.currentWidget.content;
  notebook.activeCellIndex = first;
  notebook.deselectAll();
  notebook.extendContiguousSelectionTo(last);
  await app.commands.execute('notebook:run-cell');
}"""
JS_CLEAR = "async () => { await window.jupyterapp.commands.execute('notebook:clear-all-cell-outputs'); }"
# Run code in the notebook's kernel; return what it printed.
JS_EXECUTE = """async (code) => {
  const kernel = window.jupyterapp.shell.currentWidget.sessionContext.session.kernel;
  const future = kernel.requestExecute({code, silent: false, store_history: false});
  let text = '';
  future.onIOPub = (msg) => {
    if (msg.header.msg_type === 'stream') text += msg.content.text;
    if (msg.header.msg_type === 'error') text += msg.content.ename + ': ' + msg.content.evalue;
  };
  await future.done;
  return text;
}"""


def expose_app(context, base_url: str) -> None:
    """Serve the site's jupyter-lite.json with ``exposeAppInBrowser``, for this browser context only
    (the published site does not expose JupyterLab's application object)."""
    def patch(route):
        response = route.fetch()
        config = response.json()
        config["jupyter-config-data"]["exposeAppInBrowser"] = "true"
        route.fulfill(response=response, body=json.dumps(config))
    context.route(f"{base_url}/jupyter-lite.json*", patch)


def open_notebook(page, base_url: str, name: str, timeout_s: float = 180) -> None:
    """Open ``name`` in JupyterLab, wait until its kernel is idle (Pyodide loaded), and clear the
    stored outputs and execution counts (so that what is compared later is what ran here).
    The page's context must have gone through :func:`expose_app`."""
    page.goto(f"{base_url}/lab/index.html?path={name}")
    page.wait_for_function(JS_PANEL, timeout=timeout_s * 1000)
    wait_idle(page, timeout_s)
    page.evaluate(JS_CLEAR)
    left = [c for c in cells(page) if c["type"] == "code" and (c["outputs"] or c["execution_count"] is not None)]
    assert not left, "clearing the stored outputs did not work"


def wait_idle(page, timeout_s: float = 180) -> None:
    deadline = time.monotonic() + timeout_s
    status = None
    while time.monotonic() < deadline:
        status = page.evaluate(JS_KERNEL_STATUS)
        if status == "idle":
            return
        if status == "dead":
            raise AssertionError("the kernel died")
        time.sleep(0.1)
    raise AssertionError(f"the kernel was still {status!r} after {timeout_s:.0f} s")


def cells(page) -> list[dict]:
    return page.evaluate(JS_CELLS)


def run_through(page, last: int, first: int = 0, only_this: bool = False, timeout_s: float = 600) -> None:
    """Run cells ``first`` … ``last`` (or only ``last``) and wait until every one has run."""
    first = last if only_this else first
    page.evaluate(JS_RUN, [first, last])
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline:
        ran = cells(page)[first: last + 1]
        pending = [c for c in ran if c["type"] == "code" and c["source"].strip() and c["execution_count"] is None]
        if not pending and page.evaluate(JS_KERNEL_STATUS) == "idle":
            return
        time.sleep(0.1)
    raise AssertionError(f"cells {first}…{last} had not finished after {timeout_s:.0f} s")


def execute(page, code: str) -> str:
    """Run ``code`` in the notebook's kernel (not in a cell); what it printed."""
    return page.evaluate(JS_EXECUTE, code)


# --- comparing outputs as nbval does -----------------------------------------------------------

def sanitizers() -> list[tuple[re.Pattern, str]]:
    """notebooks/sanitize.cfg's (regex, replace) pairs: what may differ between runs."""
    lines = [line for line in (NOTEBOOKS / "sanitize.cfg").read_text().splitlines()
             if line.startswith(("regex: ", "replace: "))]
    return [(re.compile(r[len("regex: "):]), s[len("replace: "):]) for r, s in zip(lines[::2], lines[1::2])]


SKIPPED_MIME = ("image/", "application/vnd.jupyter.widget-view+json")


def comparable(outputs: list[dict], rules) -> list:
    """The parts of a cell's outputs nbval compares (no images, no widget views), sanitized."""
    def clean(text):
        text = "".join(text) if isinstance(text, list) else str(text)
        for pattern, replace in rules:
            text = pattern.sub(replace, text)
        return text

    result = []
    for out in outputs:
        kind = out["output_type"]
        if kind == "stream":
            result.append((kind, out["name"], clean(out["text"])))
        elif kind in ("display_data", "execute_result"):
            data = {mime: clean(value if isinstance(value, (str, list)) else json.dumps(value, sort_keys=True))
                    for mime, value in out.get("data", {}).items() if not mime.startswith(SKIPPED_MIME)}
            result.append(("data", data))
        elif kind == "error":
            result.append((kind, out["ename"], out["evalue"]))
    # nbval joins consecutive stream outputs of one name
    merged = []
    for item in result:
        if merged and item[0] == "stream" and merged[-1][0] == "stream" and merged[-1][1] == item[1]:
            merged[-1] = ("stream", item[1], merged[-1][2] + item[2])
        else:
            merged.append(item)
    return merged


def stored_cells_of(path: Path) -> list[dict]:
    return json.loads(Path(path).read_text(encoding="utf-8"))["cells"]
