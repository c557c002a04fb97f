"""The README's picture: the SSRMS teach panel as JupyterLab shows it, made by the browser.

``make screenshots`` (which sets ``DHLAB_UPDATE_SCREENSHOTS=1``) writes it to
``notebooks/images/teach_ssrms.png``; an ordinary run of the tier makes it only in
``tests/browser/results/`` (a test run never edits the repository) and checks it.
"""
from __future__ import annotations

import io
import os
import shutil
from pathlib import Path

import numpy as np
from test_latency_browser import execute

from labdriver import close_notebook, open_notebook, run_all, with_backend

HERE = Path(__file__).parent
PICTURE = HERE.parents[1] / "notebooks" / "images" / "teach_ssrms.png"
MAX_BYTES = 300_000
POSE_DEG = [30, 40, -80, 50, 30, -20, 0]     # an arm that shows its elbow and wrist
MARGIN = 12                                    # px of white kept around the panel


def cropped_png(png: bytes) -> bytes:
    """The screenshot cut to what is not background (plus a margin), as a small PNG."""
    from PIL import Image

    image = Image.open(io.BytesIO(png)).convert("RGB")
    ink = np.asarray(image).min(axis=2) < 245
    ink[ink.mean(axis=1) > 0.9] = False         # a rule across the whole width (a cell's border) is not the panel
    rows, cols = np.flatnonzero(ink.any(axis=1)), np.flatnonzero(ink.any(axis=0))
    box = (max(cols[0] - MARGIN, 0), max(rows[0] - MARGIN, 0),
           min(cols[-1] + MARGIN + 1, image.width), min(rows[-1] + MARGIN + 1, image.height))
    image = image.crop(box)
    out = io.BytesIO()
    image.save(out, format="PNG", optimize=True)
    if out.tell() > MAX_BYTES:                  # a palette of 256 colours: the lines stay sharp
        out = io.BytesIO()
        image.quantize(colors=256, dither=0).save(out, format="PNG", optimize=True)
    return out.getvalue()


def test_readme_picture(lab_page, lab_root, results_dir):
    copy = with_backend(HERE / "teach_demo.ipynb", lab_root / "picture" / "teach_demo.ipynb", "inline")
    page = lab_page
    try:
        open_notebook(page, f"picture/{copy.name}")
        run_all(page)
        moved = execute(page, f"panel.set_q(dhlab.deg2rad({POSE_DEG})); print(panel.error)")
        assert moved.strip() == "None", moved
        output = page.locator(".jp-OutputArea-output", has=page.locator(".widget-slider")).first
        readout = output.locator(".widget-html", has_text="End effector").first
        page.wait_for_function("(el) => !/x = 24\\.000/.test(el.innerText)", arg=readout.element_handle(),
                               timeout=20_000)          # the panel shows the new pose
        page.wait_for_timeout(1000)                      # its new image decoded
        panel = output.locator(".widget-hbox").first              # the panel: figure and controls
        panel.scroll_into_view_if_needed()
        png = cropped_png(panel.screenshot())
    finally:
        close_notebook(page)
    (results_dir / "teach_ssrms.png").write_bytes(png)
    if os.environ.get("DHLAB_UPDATE_SCREENSHOTS"):
        PICTURE.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(results_dir / "teach_ssrms.png", PICTURE)

    from PIL import Image

    image = Image.open(io.BytesIO(png))
    assert len(png) < MAX_BYTES, f"the picture is {len(png)} bytes"
    assert image.width >= 600 and image.height >= 300, f"the picture is only {image.size}"
