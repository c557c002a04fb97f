"""A teach panel in a real browser: JupyterLab (ipympl, and the default: the canvas backend) and Voilà (both).

Each test opens ``teach_demo.ipynb``, runs it, moves the SSRMS's sliders with
the keyboard (typing into a slider's readout, and arrow keys on a slider's
handle), then checks that the end-effector readout shows what ``robot.fk``
computes for the slider values the page shows, and that the figure's pixels changed.
"""
from __future__ import annotations

import io
import re
import shutil
import time
from pathlib import Path

import numpy as np
import pytest

import dhlab
from labdriver import close_notebook, open_notebook, run_all

HERE = Path(__file__).parent
TIMEOUT_MS = 120_000
# "inline": the notebook's default backend, where dhlab's panels use the canvas backend
FIGURE = {"widget": ".jupyter-matplotlib-canvas-container canvas", "inline": "canvas.dhlab-canvas"}


def notebook_for(backend: str, folder):
    """The demo notebook, with its backend line set to ``backend``."""
    text = (HERE / "teach_demo.ipynb").read_text(encoding="utf-8")
    path = folder / "teach_demo.ipynb"
    path.write_text(text.replace("%matplotlib widget", f"%matplotlib {backend}"), encoding="utf-8")
    return path


def screenshot(locator) -> np.ndarray:
    from PIL import Image

    return np.asarray(Image.open(io.BytesIO(locator.screenshot())).convert("RGB")).astype(int)


def settled(locator, timeout: float = 20.0) -> np.ndarray:
    """The element's pixels once two screenshots 0.4 s apart are the same."""
    deadline = time.monotonic() + timeout
    last = screenshot(locator)
    while time.monotonic() < deadline:
        time.sleep(0.4)
        now = screenshot(locator)
        if now.shape == last.shape and (now == last).all():
            return now
        last = now
    raise AssertionError("the figure kept changing for 20 s")


def readout_numbers(text: str) -> dict:
    return {k: float(v) for k, v in re.findall(r"\b(x|y|z|roll|pitch|yaw) = (-?[\d.]+)", text)}


def wait_for_text_change(locator, old: str, timeout: float = 20.0) -> str:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        text = locator.inner_text()
        if text != old:
            return text
        time.sleep(0.1)
    raise AssertionError(f"the readout did not change from: {old!r}")


def slider_values(page) -> list:
    """The values the page shows beside the sliders (degrees for the SSRMS)."""
    return [float(t) for t in page.locator(".widget-slider .widget-readout").all_inner_texts()]


def check_panel(page, backend: str):
    robot = dhlab.robots.ssrms()
    readout = page.locator(".widget-html", has_text="End effector").first
    readout.wait_for(timeout=TIMEOUT_MS)
    figure = page.locator(FIGURE[backend]).first
    figure.wait_for(timeout=TIMEOUT_MS)
    before_pixels = settled(figure)
    before_text = readout.inner_text()
    assert readout_numbers(before_text)["x"] == pytest.approx(24.0)     # SSRMS at zero: (24, 0, -10.5)

    # 1. type a value into joint 2's readout (the keyboard route to an exact value)
    box = page.locator(".widget-slider .widget-readout").nth(1)
    box.click()
    page.keyboard.press("Control+A")
    page.keyboard.type("30")
    page.keyboard.press("Enter")
    text = wait_for_text_change(readout, before_text)
    # 2. arrow keys on joint 1's handle
    handle = page.locator(".widget-slider .noUi-handle").nth(0)
    handle.focus()
    for _ in range(10):
        page.keyboard.press("ArrowRight")
    text = wait_for_text_change(readout, text)
    time.sleep(1.0)                                   # let the last key's update arrive
    text = readout.inner_text()

    shown = slider_values(page)[:robot.n]          # the joint sliders come first (then e.g. a zoom)
    assert shown[1] == pytest.approx(30.0) and shown[0] > 0
    T = robot.fk(np.radians(shown))
    got = readout_numbers(text)
    assert [got["x"], got["y"], got["z"]] == pytest.approx(list(T[:3, 3]), abs=2e-3)
    assert [got["roll"], got["pitch"], got["yaw"]] == pytest.approx(list(np.degrees(dhlab.rpy(T))), abs=2e-2)

    after_pixels = settled(figure)
    assert after_pixels.shape == before_pixels.shape
    changed = (np.abs(after_pixels - before_pixels).max(axis=2) > 40).mean()
    assert changed > 0.001, f"only {changed:.4%} of the figure's pixels changed"
    error_boxes = page.locator(".widget-html", has_text="Error while updating")
    assert error_boxes.count() == 0


@pytest.mark.parametrize("backend", ["widget", "inline"])
def test_teach_panel_in_jupyterlab(lab_page, lab_root, results_dir, backend):
    folder = lab_root / "teach"
    folder.mkdir(exist_ok=True)
    notebook_for(backend, folder)
    path = folder / f"teach_demo_{backend}.ipynb"
    (folder / "teach_demo.ipynb").rename(path)
    page = lab_page
    try:
        open_notebook(page, f"teach/{path.name}")
        run_all(page)
        check_panel(page, backend)
        page.screenshot(path=str(results_dir / f"teach_demo-{backend}.png"))   # to look at
    except Exception:
        page.screenshot(path=str(results_dir / f"teach_demo-{backend}-failure.png"))
        raise
    finally:
        close_notebook(page)


@pytest.mark.parametrize("backend", ["widget", "inline"])
def test_teach_panel_in_voila(browser, start_server, tmp_path, backend):
    if shutil.which("voila") is None and not _has_module("voila"):
        pytest.skip("pip install voila")
    notebook_for(backend, tmp_path)
    server = start_server(["voila", "teach_demo.ipynb", "--Voila.ip=127.0.0.1"],
                    tmp_path, "/", timeout=120)
    page = browser.new_page(viewport={"width": 1500, "height": 1100})
    try:
        page.goto(server.url + "/", timeout=TIMEOUT_MS)
        check_panel(page, backend)
        page.screenshot(path=str(tmp_path / "final.png"))
    except Exception:
        page.screenshot(path=str(tmp_path / "failure.png"))
        raise
    finally:
        page.close()


def _has_module(name):
    import importlib.util

    return importlib.util.find_spec(name) is not None


@pytest.mark.parametrize("backend", ["widget", "inline"])
def test_teach_panel_keeps_its_size_in_a_narrow_column(browser, lab_server, lab_root, results_dir, backend):
    """JupyterLab 1000 px wide with the file browser open (as a teacher opens the course): the
    figure is shown whole (the canvas is never squeezed, which cut the 3D box at its left
    edge) and the panel's size does not change while joint 2 sweeps its range."""
    from labdriver import open_lab

    folder = lab_root / "narrow"
    folder.mkdir(exist_ok=True)
    notebook_for(backend, folder)
    path = folder / f"teach_narrow_{backend}.ipynb"
    (folder / "teach_demo.ipynb").rename(path)
    page = open_lab(browser, lab_server, width=1000, height=900)
    try:
        open_notebook(page, f"narrow/{path.name}")
        run_all(page)
        figure = page.locator(FIGURE[backend]).first
        figure.wait_for(timeout=TIMEOUT_MS)
        settled(figure)
        panel = page.locator(".widget-hbox", has=page.locator(FIGURE[backend])).first
        width = figure.evaluate("e => e.getBoundingClientRect().width")
        natural = figure.evaluate("e => e.width || e.naturalWidth")     # canvas / img pixels
        ratio = figure.evaluate("() => window.devicePixelRatio")
        assert width == pytest.approx(natural / ratio, abs=2), f"the figure is squeezed: {width} px of {natural}"
        sizes = set()
        handle = page.locator(".widget-slider .noUi-handle").nth(1)
        handle.focus()
        for key in ["End"] + ["PageDown"] * 6 + ["Home"]:
            page.keyboard.press(key)
            time.sleep(0.4)
            box = panel.bounding_box()
            sizes.add((round(box["width"]), round(box["height"])))
        page.screenshot(path=str(results_dir / f"teach_narrow-{backend}.png"))
        assert len(sizes) == 1, f"the panel changed size while a slider moved: {sorted(sizes)}"
    except Exception:
        page.screenshot(path=str(results_dir / f"teach_narrow-{backend}-failure.png"))
        raise
    finally:
        page.close()
