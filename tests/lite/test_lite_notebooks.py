"""Every notebook of the course in the browser edition, as a student runs it.

For each notebook, in a cold browser (fresh context: empty cache and storage): open it in the
built JupyterLite site, clear the stored outputs, run the cells from the top, and when the first
slider appears, move it and check that its figure changes; then run the rest and compare every
``nbval-check-output`` cell's outputs with the stored ones (as nbval does, with
notebooks/sanitize.cfg), and fail on any error output or any stderr the stored notebook does not
have. A request for anything but the local site fails the test (conftest's ``visit``).

The SSRMS notebook also measures: the time from opening the site to a working slider, the
median time a slider move takes to redraw the figure, the bytes downloaded, and how much
slower a sympy-heavy computation is than in a local kernel.
"""
from __future__ import annotations

import io
import statistics
import subprocess
import sys
import time
import zipfile
from pathlib import Path

import pytest

import litedriver as driver

NOTEBOOKS = sorted(p.name for p in driver.NOTEBOOKS.glob("*.ipynb"))
SSRMS = "07_ssrms.ipynb"
SLIDER = ".widget-slider"
SCREENSHOTS = Path(__file__).resolve().parents[2] / "build" / "lite-screenshots"   # the first panel of each notebook
FIGURE = ".widget-image, .jupyter-matplotlib-canvas-container canvas, canvas.dhlab-canvas"
BOX_INSIDE = """
from dhlab.views import framing
ax = panel.view.ax
corners = framing.projected(ax, framing.box_corners(ax))
box = ax.figure.bbox
inside = (corners[:, 0] >= box.x0 - 1).all() and (corners[:, 0] <= box.x1 + 1).all() and \\
    (corners[:, 1] >= box.y0 - 1).all() and (corners[:, 1] <= box.y1 + 1).all()
print("inside" if inside else corners.round().tolist())
"""
MOVES = 11                                    # slider moves timed on the SSRMS (median reported)
# Watch the panel's image: the time of the Enter key that sets a slider, and of the next new picture.
JS_ARM = """(img) => {
  window.__pressed = null; window.__redrawn = null;
  const observer = new MutationObserver(() => {
    if (window.__pressed !== null && window.__redrawn === null) {
      window.__redrawn = performance.now();
      observer.disconnect();
    }
  });
  observer.observe(img, {attributes: true, attributeFilter: ['src']});
  const onKey = (event) => {
    if (event.key === 'Enter') {
      window.__pressed = performance.now();
      document.removeEventListener('keydown', onKey, true);
    }
  };
  document.addEventListener('keydown', onKey, true);
}"""
# sympy-heavy work, timed the same way in the browser and in a local Python: the course's own
# simplification (the SSRMS's compact forward kinematics) and sympy's generic simplify (the PUMA's
# position); each prints the best of two runs, in seconds
SYMPY_BENCH = ("import time as _time, dhlab as _dhlab, sympy as _sp, sympy.core.cache as _cache\n"
               "for _work in (lambda: _dhlab.robots.ssrms().fk_sym(simplify=True),\n"
               "              lambda: _sp.simplify(_dhlab.robots.puma560().fk_sym()[:3, 3])):\n"
               "    _times = []\n"
               "    for _ in range(2):\n"
               "        _cache.clear_cache()          # sympy's own cache would make the second run free\n"
               "        _start = _time.perf_counter(); _work()\n"
               "        _times.append(_time.perf_counter() - _start)\n"
               "    print(min(_times))\n")


def pixels(locator):
    import numpy as np
    from PIL import Image

    return np.asarray(Image.open(io.BytesIO(locator.screenshot())).convert("RGB")).astype(int)


def first_panel(page):
    """The output area that holds the first slider, or None."""
    if page.locator(SLIDER).count() == 0:
        return None
    return page.locator(".jp-OutputArea-output", has=page.locator(SLIDER)).first


def move_slider(page, panel, timeout_s=60.0, fraction: float = 1 / 12) -> float:
    """Type a new value into the readout of the panel's first slider (the keyboard route a student
    takes to an exact value), ``fraction`` of its range away from where it is, up or else down;
    return the seconds from the Enter key to the figure's redraw."""
    figure = panel.locator(FIGURE).first
    handle = panel.locator(f"{SLIDER} .noUi-handle").first
    now, low, high = (float(handle.get_attribute(f"aria-value{k}")) for k in ("now", "min", "max"))
    step = (high - low) * fraction
    value = round(now + step if now + step <= high else now - step, 2)
    readout = panel.locator(f"{SLIDER} .widget-readout").first
    readout.click()
    page.keyboard.press("Control+A")
    page.keyboard.type(f"{value:g}")
    if figure.evaluate("e => e.tagName") == "IMG":
        figure.evaluate(JS_ARM)
        page.keyboard.press("Enter")
        page.wait_for_function("window.__redrawn !== null", timeout=timeout_s * 1000)
        return page.evaluate("(window.__redrawn - window.__pressed) / 1000")
    # an ipympl canvas: no attribute changes; poll its pixels
    before, start = pixels(figure), time.monotonic()
    page.keyboard.press("Enter")
    while time.monotonic() - start < timeout_s:
        if (pixels(figure) != before).any():
            return time.monotonic() - start
        time.sleep(0.05)
    raise AssertionError("the figure did not change after a slider move")


def run_until_slider(page, code_cells):
    """Run code cells one by one from the top until a slider shows; the index run last, or None."""
    for index in code_cells:
        driver.run_through(page, index, only_this=True)
        if page.locator(SLIDER).count():
            return index
    return None


def check_slider_keys(page, panel):
    """Arrow keys, Home and End on a focused slider handle move that slider, and the notebook's own
    shortcuts (move to the next heading / cell) do not take them (lite/overrides.json)."""
    handle = panel.locator(f"{SLIDER} .noUi-handle").first
    low, high = (float(handle.get_attribute(f"aria-value{k}")) for k in ("min", "max"))
    handle.focus()
    page.keyboard.press("Home")
    page.wait_for_function("(h) => Number(h.getAttribute('aria-valuenow')) === Number(h.getAttribute('aria-valuemin'))",
                           arg=handle.element_handle(), timeout=10_000)
    for _ in range(3):
        page.keyboard.press("ArrowRight")
    time.sleep(0.5)
    moved = float(handle.get_attribute("aria-valuenow"))
    assert moved > low, "ArrowRight on a slider's handle did not move it: the notebook took the key"
    assert handle.evaluate("e => e === document.activeElement"), "the focus left the slider"
    page.keyboard.press("End")
    time.sleep(0.5)
    assert float(handle.get_attribute("aria-valuenow")) == pytest.approx(high)
    driver.wait_idle(page)


def local_seconds(code: str) -> list[float]:
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    return [float(x) for x in result.stdout.split()]


@pytest.mark.parametrize("name", NOTEBOOKS)
def test_notebook_in_the_browser(name, site, visit, measurements):
    if not (site / "files" / name).exists():
        pytest.fail(f"{name} is not in the site: it was built before the notebook existed; run `make lite`")
    stored = driver.stored_cells_of(site / "files" / name)
    v = visit()
    page = v.page
    start = time.monotonic()
    driver.open_notebook(page, v.base_url, name)
    kernel_ready = time.monotonic() - start
    cells = driver.cells(page)
    assert [c["source"] for c in cells] == ["".join(c["source"]) for c in stored], \
        "the site's notebook differs from the one it was built from: rebuild the site"
    code = [i for i, c in enumerate(cells) if c["type"] == "code" and c["source"].strip()]

    last = run_until_slider(page, code)
    if last is not None:
        working = None
        panel = first_panel(page)
        figure = panel.locator(FIGURE).first
        figure.wait_for(timeout=60_000)
        before = pixels(figure)
        # half the range: a step-through whose first motion is null (θ = 0) shows a change only
        # once the slider reaches the next motion
        first_move = move_slider(page, panel, fraction=0.5)
        working = time.monotonic() - start
        driver.wait_idle(page)
        time.sleep(0.5)
        assert (pixels(figure) != before).any(), "moving the slider did not change the figure"
        # the figure is shown whole: a squeezed canvas or image cuts the 3D box at its left edge
        shown = figure.evaluate("e => e.getBoundingClientRect().width")
        natural = figure.evaluate("e => (e.width || e.naturalWidth) / window.devicePixelRatio")
        assert shown == pytest.approx(natural, abs=2), f"the panel's figure is squeezed: {shown} px of {natural}"
        SCREENSHOTS.mkdir(parents=True, exist_ok=True)
        panel.screenshot(path=str(SCREENSHOTS / name.replace(".ipynb", ".png")))    # to look at
        if name == SSRMS:           # the 3D box as this matplotlib draws it, inside the figure
            box = driver.execute(page, BOX_INSIDE).split()
            assert box == ["inside"], f"the teach panel's 3D box leaves its figure: {box}"
            check_slider_keys(page, panel)
            measurements["ssrms: open -> kernel ready [s]"] = round(kernel_ready, 1)
            measurements["ssrms: open -> first slider move redrawn [s]"] = round(working, 1)
            moves = [move_slider(page, panel) for _ in range(MOVES)]
            measurements["ssrms: slider move -> new figure, median [ms]"] = round(1000 * statistics.median(moves))
            measurements["ssrms: slider move -> new figure, max [ms]"] = round(1000 * max(moves))
            measurements["ssrms: first slider move [ms]"] = round(1000 * first_move)
        rest = [i for i in code if i > last]
        if rest:
            driver.run_through(page, rest[-1], first=rest[0])
    elif code:                      # (the course home, index.ipynb, is markdown only)
        driver.run_through(page, code[-1])
    cells = driver.cells(page)

    rules = driver.sanitizers()
    problems = []
    for index, (cell, old) in enumerate(zip(cells, stored)):
        if cell["type"] != "code":
            continue
        errors = [o for o in cell["outputs"] if o["output_type"] == "error"]
        new_stderr = [o["text"] for o in cell["outputs"] if o.get("name") == "stderr"
                      and o not in [p for p in old.get("outputs", []) if p.get("name") == "stderr"]]
        if errors:
            problems.append(f"cell {index}: {errors[0]['ename']}: {errors[0]['evalue']}")
        if new_stderr:
            problems.append(f"cell {index} wrote to stderr: {''.join(new_stderr)[:300]!r}")
        if "nbval-check-output" in old.get("metadata", {}).get("tags", []):
            got, expected = driver.comparable(cell["outputs"], rules), driver.comparable(old["outputs"], rules)
            if got != expected:
                problems.append(f"cell {index}: outputs differ from the stored ones\n  got:      {got}\n"
                                f"  expected: {expected}")
    problems += [f"JavaScript: {error[:400]}" for error in v.console_errors]
    assert not problems, f"{name} in the browser:\n" + "\n".join(problems)

    if name == SSRMS:
        measurements["ssrms: cold visit downloaded [MB]"] = round(v.downloaded_bytes(site) / 1e6, 1)
        browser = [float(x) for x in driver.execute(page, SYMPY_BENCH).split()]
        local = local_seconds(SYMPY_BENCH)
        for label, browser_s, local_s in zip(["ssrms.fk_sym(simplify=True)", "sympy.simplify(puma T[:3, 3])"],
                                             browser, local):
            measurements[f"sympy {label}: browser / local [s]"] = \
                f"{browser_s:.2f} / {local_s:.2f} = {browser_s / local_s:.1f}x"


def test_site_size(site, measurements):
    """The size of the published folder, and what it holds beside the notebooks."""
    total = sum(p.stat().st_size for p in site.rglob("*") if p.is_file())
    pyodide = sum(p.stat().st_size for p in (site / "static" / "pyodide").rglob("*") if p.is_file())
    measurements["site folder [MB]"] = round(total / 1e6, 1)
    measurements["site folder: Pyodide and its packages [MB]"] = round(pyodide / 1e6, 1)
    assert (site / "files" / "01_start_here.ipynb").exists()
    assert not (site / "files" / "source").exists(), "the assignment's source (its answers) must not ship"
    wheels = list(site.rglob("dhlab-*.whl"))
    assert wheels, "the site has no dhlab wheel"
    # no file of the course holds the solutions (dhlab-assign solutions computes them): never on a site
    for wheel in wheels:
        with zipfile.ZipFile(wheel) as archive:
            leaked = [n for n in archive.namelist()
                      if n.endswith(".ipynb") and b"BEGIN SOLUTION" in archive.read(n)]
        assert not leaked, f"{wheel.name} ships the assignment's solutions: {leaked}"
