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

It leaves a screenshot of the whole notebook (``<notebook>-<backend>.png``), a
JSON report (every check per cell, and where the time went) and, for an output
too wide, a picture of that output, in ``tests/browser/results/``.
"""
from __future__ import annotations

import json
import shutil
import time
from pathlib import Path

import pytest

from labdriver import (
    MIN_CHANGED,
    close_notebook,
    full_page_screenshot,
    move_first_slider,
    open_notebook,
    outputs_report,
    panels,
    problems,
    run_all,
    with_backend,
)

HERE = Path(__file__).resolve().parent
NOTEBOOKS = sorted((HERE.parents[1] / "notebooks").glob("*.ipynb"))
BACKENDS = ["inline", "widget"]


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


def check_notebook(page, relative_path: str, name: str, results_dir: Path) -> list:
    """Open, Run All, check, move one slider per panel, screenshot; one line per
    failure found. Leaves ``<name>.json`` and ``<name>.png`` in ``results_dir``."""
    clock = [time.monotonic()]
    try:
        open_notebook(page, relative_path)
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
        seen = set(problems(report, excerpts=False))
        failures += [f"after the slider moves: {line}" for line, short in
                     zip(problems(after), problems(after, excerpts=False)) if short not in seen]
        clock.append(time.monotonic())
        for cell in after["cells"]:          # a close look at each output too wide, for the report
            if cell["too_wide"]:
                page.locator(".jp-Notebook .jp-Cell").nth(cell["index"]).locator(".jp-Cell-outputWrapper") \
                    .screenshot(path=str(results_dir / f"{name}-cell{cell['index']}-too-wide.png"))
        full_page_screenshot(page, results_dir / f"{name}.png")
        clock.append(time.monotonic())
        report.update(notebook=relative_path, panels=moved, failures=failures,
                      seconds=dict(zip(["open", "run_all", "panels", "screenshot"],
                                       [round(b - a, 1) for a, b in zip(clock, clock[1:])])))
        (results_dir / f"{name}.json").write_text(json.dumps(report, indent=1))
    except Exception:
        page.screenshot(path=str(results_dir / f"{name}.png"))     # what the window showed then
        raise
    finally:
        close_notebook(page)
    return failures


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("notebook", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_notebook_in_jupyterlab(lab_page, notebook_folders, results_dir, notebook, backend):
    copy = with_backend(notebook, notebook_folders / backend / notebook.name, backend)
    failures = check_notebook(lab_page, f"{backend}/{copy.name}", f"{notebook.stem}-{backend}", results_dir)
    assert not failures, f"{notebook.name} ({backend}):\n  " + "\n  ".join(failures)


def test_the_checks_can_fail(lab_page, lab_root, results_dir):
    """A notebook made to fail every check (``faulty_demo.ipynb``): each failure is found."""
    copy = with_backend(HERE / "faulty_demo.ipynb", lab_root / "faulty" / "faulty_demo.ipynb", "inline")
    failures = "\n".join(check_notebook(lab_page, f"faulty/{copy.name}", "faulty_demo", results_dir))
    for expected in ["error output ValueError: a mistake made on purpose",
                     "figure shown as text '<Figure size 640x480 with 1 Axes>'",
                     "widget not shown: Error displaying widget",
                     "px wide in a",
                     "moving the panel's first slider changed only 0.000%"]:
        assert expected in failures, f"not found: {expected!r} in:\n{failures}"
