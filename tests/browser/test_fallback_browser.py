"""A JupyterLab that cannot run dhlab's canvas module still shows a working panel.

Where the kernel has anywidget but the page does not (a hub whose JupyterLab runs in another
environment than the course's kernel), the canvas backend's widget cannot be drawn: the page shows
ipywidgets' error box instead of the figure. The kernel notices (canvas.js never says "loaded",
dhlab/views/live/canvas.py ``watch_front_end``) and puts a PNG figure (the "image" backend) in its
place. Here: a second JupyterLab with anywidget's front end disabled (``page_config.json``, as
``jupyter labextension disable anywidget`` writes it), the SSRMS teach panel run in it: within
seconds the figure is a picture of the robot, and a slider key changes it.
"""
from __future__ import annotations

import json
import time

import numpy as np
from conftest import Server

import labdriver
from labdriver import close_notebook, open_notebook, run_all


def test_a_page_without_anywidget_gets_the_png_figure(browser, tmp_path, results_dir, monkeypatch):
    root = tmp_path / "lab"
    root.mkdir()
    config = tmp_path / "config"
    (config / "labconfig").mkdir(parents=True)
    (config / "labconfig" / "page_config.json").write_text(json.dumps({"disabledExtensions": {"anywidget": True}}))
    monkeypatch.setenv("JUPYTER_CONFIG_DIR", str(config))
    server = Server(labdriver.lab_command(root), root, "/api/status?token={token}")
    page = labdriver.open_lab(browser, server)
    try:
        labdriver.ssrms_panel_notebook(root / "rate", "canvas", "fallback")
        open_notebook(page, "rate/fallback_canvas.ipynb")
        run_all(page)
        output = page.locator(".jp-OutputArea-output", has=page.locator(".widget-slider")).first
        figure = output.locator("img.widget-image").first
        figure.wait_for(timeout=30_000)            # FRONT_END_S after the cell ran
        time.sleep(1.0)
        page.screenshot(path=str(results_dir / "fallback_no_anywidget.png"))
        assert output.locator("canvas.dhlab-canvas").count() == 0
        box = figure.bounding_box()
        assert box["width"] > 400 and box["height"] > 400, box
        before = labdriver.settled(figure)
        assert (before.std(axis=(0, 1)) > 10).any(), "the figure is blank"
        handle = output.locator(".widget-slider .noUi-handle").nth(1)
        handle.focus()
        for _ in range(6):
            page.keyboard.press("ArrowRight")
        after = labdriver.settled(figure)
        changed = int((np.abs(after.astype(int) - before.astype(int)).max(axis=2) > 0).sum())
        assert changed > 1000, f"the PNG figure did not follow the slider ({changed} pixels changed)"
    finally:
        close_notebook(page)
        page.close()
        server.stop()
