"""Each lecture notebook as a slide deck, at projector scale, in JupyterLab.

For each lecture notebook (02-07) under ``%matplotlib widget`` (ipympl panels) and under the
inline backend (panels as images), in a 1920x1080 window: a copy whose set-up cell also runs
``dhlab.projector()`` is Run All, the deck is started from the toolbar's deck button at the
first cell, and Space is pressed to the last screen. On every step the test checks that

* no error output and no "Error while updating" shows on screen;
* no ``notes`` or ``skip`` cell is on screen;
* the screen fits the window: no cell past its top, bottom or right edge, nothing to scroll;
* body text (markdown paragraphs, lists, tables) is at least 24 px;

and that every screen (each slide and sub-slide) was reached; on the first panel (a slider and
a figure in one output) it moves the slider with the keyboard inside the deck and checks that
the figure's pixels change. It measures the words of prose per screen and the body text's size
(``results/decks.json``) and keeps screenshots of a few slides (``results/deck-*.jpg``). The
SSRMS deck's teach-panel slide is the README's picture ``notebooks/images/deck_ssrms.png``
(written only with ``DHLAB_UPDATE_SCREENSHOTS=1``, like test_readme_picture.py).

Run one notebook while working: ``python -m pytest tests/browser/test_decks_browser.py --browser
-p no:xdist -k "05 and widget"``.
"""
from __future__ import annotations

import importlib.util
import io
import json
import os
import shutil
import sys
from pathlib import Path

import pytest

from deckdriver import DECK_HEIGHT, DECK_WIDTH, check_deck, save_json, stop_deck, with_projector
from labdriver import close_notebook, open_lab, open_notebook, outputs_report, problems, run_all, with_backend

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
sys.path.insert(0, str(ROOT / "tests"))
from support import deck_rules  # noqa: E402

LECTURES = [ROOT / "notebooks" / f"{stem}.ipynb" for stem in deck_rules.LECTURE_NOTEBOOKS]
BACKENDS = ["widget", "inline"]
PICTURE = ROOT / "notebooks" / "images" / "deck_ssrms.png"
MEASURED = {}                     # notebook-backend -> measurements, written to results/decks.json


@pytest.fixture(scope="module")
def deck_page(browser, lab_server):
    """JupyterLab in a 1920x1080 window (a projector), for the module's decks."""
    page = open_lab(browser, lab_server, width=DECK_WIDTH, height=DECK_HEIGHT)
    yield page
    page.close()


@pytest.fixture(scope="module")
def deck_folder(lab_root):
    folder = lab_root / "decks"
    folder.mkdir(exist_ok=True)
    images = ROOT / "notebooks" / "images"
    if images.is_dir() and not (folder / "images").exists():
        shutil.copytree(images, folder / "images")
    return folder


@pytest.fixture(scope="module", autouse=True)
def write_measurements(results_dir):
    yield
    if MEASURED:
        path = results_dir / "decks.json"
        old = json.loads(path.read_text()) if path.exists() else {}
        save_json(path, {**old, **MEASURED})


def projected_copy(notebook: Path, folder: Path, backend: str) -> Path:
    copy = with_backend(notebook, folder / f"{notebook.stem}-{backend}.ipynb", backend)
    copy.write_text(json.dumps(with_projector(json.loads(copy.read_text())), indent=1))
    return copy


def readme_picture(page, results_dir: Path) -> Path:
    """The SSRMS teach-panel slide, 1280 px wide, as a PNG of at most 256 colours."""
    from PIL import Image

    page.mouse.move(DECK_WIDTH - 60, 5)
    image = Image.open(io.BytesIO(page.screenshot())).convert("RGB")
    image = image.resize((1280, round(image.height * 1280 / image.width)), Image.LANCZOS)
    out = results_dir / "deck_ssrms.png"
    image.quantize(colors=256, dither=0).save(out, format="PNG", optimize=True)
    if os.environ.get("DHLAB_UPDATE_SCREENSHOTS"):
        shutil.copyfile(out, PICTURE)
    return out


def present(page, copy: Path, name: str, results_dir: Path) -> dict:
    """Run the copy, walk its deck (deckdriver.check_deck); what was measured, failures included."""
    open_notebook(page, f"decks/{copy.name}")
    try:
        run_all(page)
        before = [f"before the deck: {p}" for p in problems(outputs_report(page), excerpts=False)
                  if "px wide" not in p]          # width is checked on each slide, at 1920 px
        readme = {}

        def on_panel(output):
            if name == "07_ssrms-widget" and output.locator(".widget-html", has_text="End effector").count():
                readme["picture"] = str(readme_picture(page, results_dir))

        measured = check_deck(page, name, results_dir, on_panel=on_panel)
    except Exception:
        page.screenshot(path=str(results_dir / f"deck-{name}-failure.png"))
        raise
    finally:
        stop_deck(page)
        close_notebook(page)
    measured["failures"] = before + measured["failures"]
    measured["readme picture"] = readme.get("picture")
    return measured


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("notebook", LECTURES, ids=[p.stem for p in LECTURES])
def test_deck_at_projector_scale(deck_page, deck_folder, results_dir, notebook, backend):
    copy = projected_copy(notebook, deck_folder, backend)
    name = f"{notebook.stem}-{backend}"
    measured = present(deck_page, copy, name, results_dir)
    MEASURED[name] = {k: v for k, v in measured.items() if k != "failures"} | {"failures": measured["failures"][:40]}
    failures = measured["failures"]
    has_panel = any("application/vnd.jupyter.widget-view+json" in o.get("data", {})
                    for c in json.loads(notebook.read_text())["cells"] for o in c.get("outputs", []))
    if has_panel and measured["slider moved: figure pixels changed"] is None:
        failures.append("no panel (a slider and a figure) was found on any slide")
    assert not failures, f"{name}: {len(failures)} problems in the deck:\n  " + "\n  ".join(failures[:40])


# --- the switch itself, outside a deck: JupyterLab (on, then off) and Voilà --------------------

SWITCH_JS = """() => { const size = (selector) => { const e = document.querySelector(selector);
    return e ? parseFloat(getComputedStyle(e).fontSize) : null; };
  return {body: size('.jp-RenderedMarkdown p'), code: size('.jp-Cell .cm-content'),
          label: size('.widget-slider .widget-label'), readout: size('.widget-slider .widget-readout')}; }"""


def switch_notebook(folder: Path, cells: list) -> Path:
    """A small notebook: a paragraph, then the code cells ``cells``."""
    notebook = {"cells": [{"cell_type": "markdown", "id": "p", "metadata": {},
                           "source": "Body text of the page, measured before and after the switch."}]
                + [{"cell_type": "code", "execution_count": None, "id": f"c{i}", "metadata": {}, "outputs": [],
                    "source": source} for i, source in enumerate(cells)],
                "metadata": {"kernelspec": {"display_name": "Python 3", "language": "python", "name": "python3"}},
                "nbformat": 4, "nbformat_minor": 5}
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "projector_switch.ipynb"
    path.write_text(json.dumps(notebook))
    return path


def test_projector_switch_in_jupyterlab(deck_page, lab_root, results_dir):
    """dhlab.projector() makes the page's text, code and widgets larger at once (no re-run), and
    projector(False) in a later cell restores every size, the earlier style included."""
    switch_notebook(lab_root / "switch", ["import dhlab\nfrom dhlab.views.panels.teach import teach\n"
                                          "panel = teach(dhlab.robots.ssrms(), backend='image')\npanel",
                                          "dhlab.projector()", "dhlab.projector(False)"])
    page = deck_page
    open_notebook(page, "switch/projector_switch.ipynb")
    try:
        run = """async (n) => { const app = window.jupyterapp, nb = (window.__dhlabNotebook).content;
            nb.activeCellIndex = n; await app.commands.execute('notebook:run-cell'); }"""
        page.evaluate(run, 1)
        page.wait_for_selector(".widget-slider .widget-readout", timeout=120_000)
        normal = page.evaluate(SWITCH_JS)
        page.evaluate(run, 2)
        page.wait_for_function("() => parseFloat(getComputedStyle(document.querySelector('.jp-RenderedMarkdown p'))"
                               ".fontSize) > 20", timeout=60_000)
        large = page.evaluate(SWITCH_JS)
        page.screenshot(path=str(results_dir / "projector-on.jpg"), type="jpeg", quality=70)
        page.evaluate(run, 3)
        page.wait_for_function("() => parseFloat(getComputedStyle(document.querySelector('.jp-RenderedMarkdown p'))"
                               ".fontSize) < 20", timeout=60_000)
        restored = page.evaluate(SWITCH_JS)
    finally:
        close_notebook(page)
    MEASURED["projector switch in JupyterLab (px)"] = {"normal": normal, "on": large, "off again": restored}
    assert normal["body"] == 14 and large["body"] >= 24
    assert large["code"] > normal["code"] and large["label"] > normal["label"] and large["readout"] > normal["readout"]
    assert restored == normal


def test_projector_in_voila(browser, start_server, tmp_path, results_dir):
    """In Voilà (no deck) the switch is harmless: the page's text and the panel grow, nothing breaks."""
    if importlib.util.find_spec("voila") is None:
        pytest.skip("pip install voila")
    switch_notebook(tmp_path, ["import dhlab\nfrom dhlab.views.panels.teach import teach\ndhlab.projector()",
                               "panel = teach(dhlab.robots.ssrms(), backend='image')\npanel"])
    server = start_server(["voila", "projector_switch.ipynb", "--Voila.ip=127.0.0.1"], tmp_path, "/", timeout=120)
    page = browser.new_page(viewport={"width": DECK_WIDTH, "height": DECK_HEIGHT})
    try:
        page.goto(server.url + "/", timeout=240_000)
        page.wait_for_selector(".widget-slider .widget-readout", timeout=240_000)
        sizes = page.evaluate(SWITCH_JS)
        errors = page.locator(".jp-OutputArea-output[data-mime-type='application/vnd.jupyter.stderr']").count()
        page.screenshot(path=str(results_dir / "projector-voila.jpg"), type="jpeg", quality=70)
    finally:
        page.close()
    MEASURED["projector in Voilà (px)"] = sizes
    assert sizes["body"] >= 24 and sizes["label"] > 13 and sizes["readout"] > 13
    assert errors == 0
