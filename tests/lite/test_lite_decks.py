"""Each lecture notebook as a slide deck in the browser edition (JupyterLite), offline.

The same deck test as tests/browser/test_decks_browser.py, on the built site (``make lite``):
in a cold browser that can reach nothing but the local site (conftest's ``visit``), a 1920x1080
window, each lecture notebook is opened, its set-up cell gets ``dhlab.projector()`` (and, for
the ipympl run, ``%matplotlib widget``; the browser edition's default is the inline backend),
every cell is run, the deck is started from the toolbar's deck button and walked with Space to
its end: no error output, no notes or skip cell on screen, every slide fits the window with body
text of at least 24 px, every screen reached, and a slider dragged inside the deck redraws its
figure. Measurements go to build/lite-measurements.json, screenshots to build/lite-screenshots/.

One notebook while working: ``python -m pytest tests/lite/test_lite_decks.py --lite -p no:xdist -k "07 and inline"``.
"""
from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

import litedriver as driver

BROWSER_TIER = Path(__file__).resolve().parents[1] / "browser"
sys.path.insert(0, str(BROWSER_TIER))
sys.path.insert(0, str(BROWSER_TIER.parent))
from deckdriver import DECK_HEIGHT, DECK_WIDTH, check_deck, stop_deck, with_projector  # noqa: E402
from support import deck_rules  # noqa: E402

SCREENSHOTS = Path(__file__).resolve().parents[2] / "build" / "lite-screenshots"
BACKENDS = ["inline", "widget"]
# set a cell's source in the notebook's model (as a lecturer editing the set-up cell would)
JS_SET_SOURCE = """([index, source]) => {
  const cell = window.jupyterapp.shell.currentWidget.content.model.cells.get(index);
  cell.sharedModel.setSource(source);
}"""


def projected_setup(cells: list, backend: str) -> tuple:
    """(index, new source) of the first code cell: with dhlab.projector(), and %matplotlib widget."""
    index = next(i for i, c in enumerate(cells) if c["type"] == "code")
    notebook = {"cells": [{"cell_type": "code", "source": cells[index]["source"]}]}
    source = "".join(with_projector(notebook)["cells"][0]["source"])
    if backend == "widget":
        source = "%matplotlib widget\n" + source
    return index, source


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("stem", deck_rules.LECTURE_NOTEBOOKS)
def test_deck_in_the_browser_edition(stem, backend, site, visit, measurements):
    name = f"{stem}.ipynb"
    if not (site / "files" / name).exists():
        pytest.fail(f"{name} is not in the site: run `make lite`")
    v = visit()
    page = v.page
    page.set_viewport_size({"width": DECK_WIDTH, "height": DECK_HEIGHT})
    driver.open_notebook(page, v.base_url, name)
    cells = driver.cells(page)
    page.evaluate(JS_SET_SOURCE, list(projected_setup(cells, backend)))
    code = [i for i, c in enumerate(cells) if c["type"] == "code" and c["source"].strip()]
    driver.run_through(page, code[-1])
    SCREENSHOTS.mkdir(parents=True, exist_ok=True)
    try:
        # the slider is dragged, then Space goes on with the focus still on it (the JupyterLab tier
        # moves it with the keys: both ways must leave Space to the deck)
        measured = check_deck(page, f"{stem}-{backend}", SCREENSHOTS, slider_by="mouse")
    finally:
        stop_deck(page)
    failures = measured.pop("failures")
    failures += [f"JavaScript: {error[:300]}" for error in v.console_errors]
    stored = driver.stored_cells_of(site / "files" / name)
    if any("application/vnd.jupyter.widget-view+json" in o.get("data", {})
           for c in stored for o in c.get("outputs", [])) and measured["slider moved: figure pixels changed"] is None:
        failures.append("no panel (a slider and a figure) was found on any slide")
    measurements[f"deck {stem} ({backend})"] = json.dumps(measured)
    assert not failures, f"{stem} ({backend}) in the browser edition's deck:\n  " + "\n  ".join(failures[:40])
