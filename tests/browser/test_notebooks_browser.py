"""Every course notebook, as a student sees it: JupyterLab in Chromium, a 1400 px window, Run All.

For each notebook in ``notebooks/`` (found at collection time, so a new notebook
is tested without editing this file), under the default inline backend and
under ``%matplotlib widget`` (ipympl), the test checks that

* no cell shows an error output, and every code cell ran;
* no widget failed to display ("Error displaying widget", an empty widget view);
* no figure is shown as text (``<Figure size ... with N Axes>`` without an image);
* no output is wider than the notebook column (the output's, or anything
  inside it that scrolls or sticks out, e.g. a MathJax matrix, scrollWidth
  against the column's clientWidth);
* in every panel (a slider and a figure in one output), moving the first slider
  with the keyboard changes the figure's pixels and shows no "Error while updating".

It leaves a screenshot of the whole notebook and a JSON report per notebook and
backend in ``tests/browser/results/``.
"""
from __future__ import annotations

import json
import shutil
import time
from pathlib import Path

import pytest

from labdriver import (FIGURE_SELECTOR, changed_fraction, close_notebook, full_page_screenshot,
                       open_notebook, outputs_report, panels, problems, run_all, settled, with_backend)

NOTEBOOKS = sorted((Path(__file__).resolve().parents[2] / "notebooks").glob("*.ipynb"))
BACKENDS = ["inline", "widget"]
MIN_CHANGED = 0.0005           # a moved slider must change at least this fraction of the figure's pixels


@pytest.fixture(scope="session")
def notebook_folders(lab_root):
    """``lab_root/<backend>/``: one folder per backend, with the notebooks' images beside them."""
    images = NOTEBOOKS[0].parent / "images" if NOTEBOOKS else None
    for backend in BACKENDS:
        folder = lab_root / backend
        folder.mkdir(exist_ok=True)
        if images is not None and images.is_dir() and not (folder / "images").exists():
            shutil.copytree(images, folder / "images")
    return lab_root


def move_first_slider(page, output) -> tuple:
    """Arrow keys on the first slider of a panel; (fraction of the figure's pixels
    that changed, what the page showed wrong or '')."""
    figure = output.locator(FIGURE_SELECTOR).first
    figure.scroll_into_view_if_needed()
    before = settled(figure)
    handle = output.locator(".widget-slider .noUi-handle").first
    changed = 0.0
    for key in ("ArrowRight", "ArrowLeft"):        # a slider at its maximum only moves left
        handle.focus()
        for _ in range(12):
            page.keyboard.press(key)
        time.sleep(0.3)
        changed = changed_fraction(before, settled(figure))
        if changed >= MIN_CHANGED:
            break
    errors = output.locator(".widget-html", has_text="Error while updating")
    return changed, (errors.first.inner_text()[:300] if errors.count() else "")


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("notebook", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_notebook_in_jupyterlab(lab_page, notebook_folders, results_dir, notebook, backend):
    copy = with_backend(notebook, notebook_folders / backend / notebook.name, backend)
    page = lab_page
    name = f"{notebook.stem}-{backend}"
    clock = [time.monotonic()]
    try:
        open_notebook(page, f"{backend}/{copy.name}")
        clock.append(time.monotonic())
        run_all(page)
        clock.append(time.monotonic())
        report = outputs_report(page)
        failures = problems(report)
        failures += [f"cell {c['index']}: did not run (Run All stopped before it)"
                     for c in report["cells"] if c["executed"] is None and c["source"].strip()]
        moved = []
        for index, output in panels(page):
            changed, error = move_first_slider(page, output)
            moved.append({"cell": index, "changed": round(changed, 5), "error": error})
            if changed < MIN_CHANGED:
                failures.append(f"cell {index}: moving the panel's first slider changed only "
                                f"{changed:.3%} of its figure's pixels")
            if error:
                failures.append(f"cell {index}: the panel shows {error!r}")
        after = outputs_report(page)                     # errors raised by the slider moves
        failures += [f"after the slider moves: {line}" for line in problems(after)
                     if line not in problems(report)]
        clock.append(time.monotonic())
        for cell in after["cells"]:          # a close look at each output too wide, for the report
            if cell["too_wide"]:
                page.locator(".jp-Notebook .jp-Cell").nth(cell["index"]).locator(".jp-Cell-outputWrapper") \
                    .screenshot(path=str(results_dir / f"{name}-cell{cell['index']}-too-wide.png"))
        full_page_screenshot(page, results_dir / f"{name}.png")
        clock.append(time.monotonic())
        report.update(notebook=notebook.name, backend=backend, panels=moved, failures=failures,
                      seconds=dict(zip(["open", "run_all", "panels", "screenshot"],
                                       [round(b - a, 1) for a, b in zip(clock, clock[1:])])))
        (results_dir / f"{name}.json").write_text(json.dumps(report, indent=1))
    except Exception:
        page.screenshot(path=str(results_dir / f"{name}.png"))     # what the window showed then
        raise
    finally:
        close_notebook(page)
    assert not failures, f"{notebook.name} ({backend}):\n  " + "\n  ".join(failures)
