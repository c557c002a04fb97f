"""Driving a notebook's slide deck (jupyterlab-slideshow 0.3.4) from Playwright, and measuring it.

Used by tests/browser/test_decks_browser.py (JupyterLab) and tests/lite/test_lite_decks.py (the
browser edition): both have JupyterLab's application object as ``window.jupyterapp``.

* :func:`with_projector`: a copy of a notebook whose set-up cell also runs ``dhlab.projector()``;
* :func:`start_deck`, :func:`stop_deck`: the deck from the notebook's toolbar button, from the
  first cell (the deck starts at the selected cell);
* :func:`screen`: what the deck shows now, measured in the page: which cells are on screen,
  whether they fit the window (no scrolling), the body text's size, the words of prose, error
  outputs, and whether a notes or skip cell shows;
* :func:`walk`: Space, Space, ... to the end, calling back on every step.
"""
from __future__ import annotations

import io
import json
import re
import time
from pathlib import Path

DECK_WIDTH, DECK_HEIGHT = 1920, 1080          # a projector
NOTEBOOK_JS = "(window.__dhlabNotebook || window.jupyterapp.shell.currentWidget)"
FIGURE_SELECTOR = ".jupyter-matplotlib-canvas-container canvas, .widget-image, canvas.dhlab-canvas"
PROJECTOR_LINE = "dhlab.projector()"


def with_projector(notebook: dict) -> dict:
    """The notebook (as JSON) with ``dhlab.projector()`` after ``dhlab.set_language(...)`` (or
    after ``import dhlab``) in its first code cell, as a lecturer switches it on."""
    for cell in notebook["cells"]:
        if cell["cell_type"] != "code":
            continue
        text = "".join(cell["source"])
        anchor = re.search(r"^dhlab\.set_language\(.*\)$", text, flags=re.M) or \
            re.search(r"^import dhlab$", text, flags=re.M)
        if anchor is None:
            raise AssertionError("the first code cell does not import dhlab: cannot switch the projector on")
        cell["source"] = text[:anchor.end()] + "\n" + PROJECTOR_LINE + text[anchor.end():]
        return notebook
    raise AssertionError("the notebook has no code cell")


def start_deck(page, timeout_ms: int = 20_000) -> bool:
    """Select the first cell, then the deck button of the notebook's toolbar (``deck:toggle``).
    If the keyboard's focus is then nowhere (the browser edition's JupyterLab 4.4 leaves it on the
    page's body, where Space does nothing), click the slide, as a lecturer would; True if needed."""
    page.evaluate(f"() => {{ const nb = {NOTEBOOK_JS}.content; nb.mode = 'command'; nb.activeCellIndex = 0; }}")
    button = page.locator(".jp-NotebookPanel:not(.lm-mod-hidden) .jp-NotebookPanel-toolbar "
                          "[data-command='deck:toggle']").first
    button.click()
    page.wait_for_function("() => document.body.dataset.jpDeckMode === 'presenting'", timeout=timeout_ms)
    page.wait_for_function(f"() => {NOTEBOOK_JS}.content.activeCellIndex === 0 &&"
                           f" {NOTEBOOK_JS}.content.widgets[0].node.classList.contains('jp-deck-mod-onscreen')",
                           timeout=timeout_ms)
    time.sleep(1.0)                           # side panels collapse, the slide is laid out
    if page.evaluate("() => document.activeElement === document.body"):
        page.locator(".jp-deck-mod-onscreen").first.click(position={"x": 20, "y": 10})
        time.sleep(0.3)
        return True
    return False


def stop_deck(page) -> None:
    page.evaluate("() => document.body.dataset.jpDeckMode === 'presenting'"
                  " && window.jupyterapp.commands.execute('deck:stop')")


def slide_types(page) -> list:
    """Each cell's slide type, as the notebook model holds it (None: continue the screen)."""
    return page.evaluate(f"""() => {NOTEBOOK_JS}.content.widgets.map(c => {{
        const s = c.model.getMetadata('slideshow'); return (s && s.slide_type) || null; }})""")


# What the deck shows now. Every number comes from the page: the cells on screen (class
# jp-deck-mod-onscreen: the screen's cells, its fragments still to come included), their box
# against the window, the scrolling element of the notebook, and what they hold.
_SCREEN_JS = r"""
([figureSelector]) => {
  const panel = NOTEBOOK, nb = panel.content;
  const WORD = /[\p{L}]+(?:['’-][\p{L}]+)*/gu;
  const cells = nb.widgets.map((cell, index) => ({cell, index}))
    .filter(({cell}) => cell.node.classList.contains('jp-deck-mod-onscreen'));
  const box = {top: Infinity, bottom: -Infinity, left: Infinity, right: -Infinity};
  let words = 0, bodyPx = [], errors = [], panels = 0, wide = [];
  for (const {cell, index} of cells) {
    const r = cell.node.getBoundingClientRect();
    box.top = Math.min(box.top, r.top); box.bottom = Math.max(box.bottom, r.bottom);
    // what sticks out to the right: any element of the cell past the window's edge
    cell.node.querySelectorAll('*').forEach(el => {
      if (el.closest('.widget-slider, .widget-readout, mjx-assistive-mml')) return;
      const e = el.getBoundingClientRect();
      if (e.width > 0 && e.right > innerWidth + 1)
        wide.push(`cell ${index}: ${el.tagName.toLowerCase()} to ${Math.round(e.right)} px`);
    });
    if (cell.model.type === 'markdown') {
      const md = cell.node.querySelector('.jp-RenderedMarkdown');
      if (md) {
        const copy = md.cloneNode(true);
        copy.querySelectorAll('mjx-container, code, pre, script, style, .MathJax, .jp-InternalAnchorLink')
          .forEach(e => e.remove());
        words += (copy.textContent.match(WORD) || []).length;
        md.querySelectorAll('p, li, td').forEach(e => {
          if (e.closest('table') && e.tagName !== 'TD') return;
          if ((e.textContent || '').trim()) bodyPx.push(parseFloat(getComputedStyle(e).fontSize));
        });
      }
    }
    if (cell.model.type === 'code') {
      for (const out of cell.model.outputs.toJSON())
        if (out.output_type === 'error') errors.push(`cell ${index}: ${out.ename}: ${out.evalue}`);
      cell.node.querySelectorAll('.jp-OutputArea-output').forEach(o => {
        if (o.querySelector('.widget-slider') && o.querySelector(figureSelector)) panels += 1;
        const text = (o.innerText || '').trim();
        if (/Error while updating|Error displaying widget/.test(text))
          errors.push(`cell ${index}: ${text.slice(0, 160)}`);
      });
    }
  }
  const scroller = panel.node.querySelector('.jp-WindowedPanel-outer') || nb.node;
  const types = nb.widgets.map(c => {
    const s = c.model.getMetadata('slideshow'); return (s && s.slide_type) || null; });
  const hiddenShown = cells.filter(({index}) => types[index] === 'notes' || types[index] === 'skip')
    .map(({index}) => `cell ${index} (${types[index]})`);
  return {active: nb.activeCellIndex, cells: cells.map(c => c.index),
          top: box.top, bottom: box.bottom, width: innerWidth, height: innerHeight,
          scroll_overflow: scroller.scrollHeight - scroller.clientHeight, wide: wide.slice(0, 5),
          words, body_px: bodyPx.length ? Math.min(...bodyPx) : null, errors, panels, hidden_shown: hiddenShown};
}
"""


def screen(page) -> dict:
    """What the deck shows now (see ``_SCREEN_JS``), with ``overflow``: the px by which the
    screen's cells pass the window's top or bottom (the deck scrolls a slide that is too tall:
    its top or bottom leaves the window). ``scroll_overflow`` is only recorded: JupyterLab 4.4
    (the browser edition) keeps the notebook's full height scrollable behind the deck."""
    found = page.evaluate(_SCREEN_JS.replace("NOTEBOOK", NOTEBOOK_JS), [FIGURE_SELECTOR])
    found["overflow"] = round(max(0.0, -found["top"], found["bottom"] - found["height"]), 1)
    return found


def step(page, wait_s: float = 3.0) -> bool:
    """Space: the next fragment, sub-slide or slide. False at the end of the deck."""
    before = page.evaluate(f"() => {NOTEBOOK_JS}.content.activeCellIndex")
    page.keyboard.press("Space")
    deadline = time.monotonic() + wait_s
    while time.monotonic() < deadline:
        if page.evaluate(f"() => {NOTEBOOK_JS}.content.activeCellIndex") != before:
            time.sleep(0.4)                   # the fragment fades in, the outputs are laid out
            return True
        time.sleep(0.1)
    return False


def walk(page, on_step, max_steps: int = 400) -> int:
    """From the deck's first screen to its last with Space, calling ``on_step(k)`` on each
    step (k = 0 first); returns the number of steps."""
    k = 0
    on_step(k)
    while k < max_steps and step(page):
        k += 1
        on_step(k)
    return k + 1


def screen_starts(types: list) -> list:
    """The cells that start a screen in the deck: the first, and each slide or sub-slide."""
    return [i for i, t in enumerate(types) if i == 0 or t in ("slide", "subslide")]


def save_json(path: Path, data) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(data, indent=1))


# --- the whole deck, checked --------------------------------------------------------------

MIN_BODY_PX = 24                  # body text on a 1920x1080 projector
MIN_CHANGED = 0.0005              # a moved slider changes at least this fraction of its figure


def slide_picture(page, path: Path) -> None:
    """The window as a JPEG (a slide is mostly flat colour: small), the mouse out of the way
    (over a heading it shows the heading's link mark, over an edge the side bars)."""
    page.mouse.move(DECK_WIDTH - 60, 5)
    page.screenshot(path=str(path), type="jpeg", quality=70)


def figure_pixels(page, figure):
    """The figure's pixels, cut from a screenshot of the window (an element's own screenshot waits
    for it to be "stable", which a figure in the browser edition's deck never is for Playwright)."""
    import numpy as np
    from PIL import Image

    box = figure.bounding_box()
    clip = {"x": max(box["x"], 0), "y": max(box["y"], 0),
            "width": max(box["width"], 1), "height": max(box["height"], 1)}
    png = page.screenshot(clip=clip)
    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB")).astype(np.int16)


def settled_pixels(page, figure, timeout: float = 20.0):
    """The figure's pixels once two looks 0.3 s apart agree."""
    deadline = time.monotonic() + timeout
    last = figure_pixels(page, figure)
    while time.monotonic() < deadline:
        time.sleep(0.3)
        now = figure_pixels(page, figure)
        if now.shape == last.shape and (now == last).all():
            return now
        last = now
    raise AssertionError(f"the figure kept changing for {timeout:.0f} s")


def move_slider_in_deck(page, output) -> float:
    """Keys on the panel's first slider, inside the deck; the fraction of the figure's pixels changed."""
    from labdriver import changed_fraction, keys_until_changed

    figure = output.locator(FIGURE_SELECTOR).first
    before = settled_pixels(page, figure)
    handle = output.locator(".widget-slider .noUi-handle").first
    return keys_until_changed(page, handle, lambda: changed_fraction(before, settled_pixels(page, figure)))


def drag_slider_in_deck(page, output) -> float:
    """The panel's first slider dragged with the mouse, inside the deck, as a lecturer does; the
    fraction of the figure's pixels changed. The focus stays on the slider's handle: the walk's next
    Space must still go on (it did not while the panel kept its sliders marked for good:
    see dhlab/views/live/keys.js)."""
    from labdriver import changed_fraction

    figure = output.locator(FIGURE_SELECTOR).first
    before = settled_pixels(page, figure)
    handle = output.locator(".widget-slider .noUi-handle").first
    changed = 0.0
    for dx in (90, -180):                     # right, or left when the slider is at its maximum
        box = handle.bounding_box()
        x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
        page.mouse.move(x, y)
        page.mouse.down()
        page.mouse.move(x + dx, y, steps=8)
        page.mouse.up()
        time.sleep(0.3)
        changed = changed_fraction(before, settled_pixels(page, figure))
        if changed >= MIN_CHANGED:
            break
    return changed


def check_deck(page, name: str, results_dir: Path, on_panel=None, slider_by: str = "keys") -> dict:
    """Start the deck of the notebook in front (run already), press Space to its end and check
    every step (see tests/browser/test_decks_browser.py); on the first panel, ``on_panel(output)``
    then a slider moved with the keys (``slider_by="mouse"``: dragged, see
    :func:`drag_slider_in_deck`), the deck staying on its screen. Screenshots
    ``deck-<name>-{first,panel,last}.jpg`` (and ``-overflow-cell<N>``) in ``results_dir``.
    Returns the measurements and ``failures``."""
    failures, steps, visited = [], [], set()
    state = {"moved": None}
    types = slide_types(page)
    clicked = start_deck(page)

    def on_step(k):
        now = screen(page)
        steps.append({key: now[key] for key in ("active", "words", "body_px", "overflow", "panels")})
        visited.add(now["cells"][0] if now["cells"] else None)
        where = f"step {k} (cell {now['active']})"
        failures.extend(f"{where}: {e}" for e in now["errors"])
        failures.extend(f"{where}: {h} is on screen in the deck" for h in now["hidden_shown"])
        failures.extend(f"{where}: {w} (window {now['width']} px)" for w in now["wide"])
        if now["overflow"] > 1:
            picture = f"deck-{name}-overflow-cell{now['active']}.jpg"
            failures.append(f"{where}: the slide does not fit the {now['width']}x{now['height']} window "
                            f"(by {now['overflow']:.0f} px; {picture})")
            slide_picture(page, results_dir / picture)
        if now["body_px"] is not None and now["body_px"] < MIN_BODY_PX:
            failures.append(f"{where}: body text {now['body_px']:.1f} px (at least {MIN_BODY_PX})")
        if k == 0:
            slide_picture(page, results_dir / f"deck-{name}-first.jpg")
        if now["panels"] and state["moved"] is None:
            output = page.locator(".jp-deck-mod-onscreen .jp-OutputArea-output",
                                  has=page.locator(".widget-slider")).filter(
                                      has=page.locator(FIGURE_SELECTOR)).first
            slide_picture(page, results_dir / f"deck-{name}-panel.jpg")
            if on_panel is not None:
                on_panel(output)
            try:
                output.locator(FIGURE_SELECTOR).first.wait_for(state="visible", timeout=30_000)
                screen_before = set(now["cells"])
                move = drag_slider_in_deck if slider_by == "mouse" else move_slider_in_deck
                state["moved"] = move(page, output)
                after = screen(page)
                if after["active"] not in screen_before:
                    failures.append(f"{where}: moving the slider took the deck to cell {after['active']}")
            except Exception as error:
                state["moved"] = 0.0
                found = page.evaluate("""(sel) => [...document.querySelectorAll(
                    '.jp-deck-mod-onscreen .jp-OutputArea-output')]
                    .map(o => [!!o.querySelector('.widget-slider'), [...o.querySelectorAll(sel)].map(
                      f => f.tagName + ' ' + JSON.stringify(f.getBoundingClientRect()))])""", FIGURE_SELECTOR)
                mode = page.evaluate(f"() => [document.body.dataset.jpDeckMode || 'not presenting',"
                                     f" {NOTEBOOK_JS}.content.activeCellIndex]")
                failures.append(f"{where}: the panel's figure cannot be used: {str(error).splitlines()[0]}; "
                                f"outputs on screen (slider, figures): {found}; deck, active cell: {mode}")
            if state["moved"] < MIN_CHANGED:
                failures.append(f"{where}: a slider moved in the deck changed only {state['moved']:.3%} "
                                "of its figure's pixels")

    count = walk(page, on_step)
    slide_picture(page, results_dir / f"deck-{name}-last.jpg")
    missed = [i for i in screen_starts(types) if types[i] not in ("skip", "notes") and i not in visited]
    if missed:
        failures.append(f"screens never reached with Space: cells {missed[:10]}")
    words = [s["words"] for s in steps]
    body = [s["body_px"] for s in steps if s["body_px"] is not None]
    return {"failures": failures, "steps": count, "screens": len(visited),
            "a click on the slide was needed before Space": clicked,
            "max words on a screen": max(words, default=0),
            "body text px (min, max)": [min(body, default=None), max(body, default=None)],
            "largest overflow px": max((s["overflow"] for s in steps), default=0),
            "slider moved: figure pixels changed": state["moved"]}
