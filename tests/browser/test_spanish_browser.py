"""The Spanish edition as a student sees it: a Spanish notebook in JupyterLab + Chromium, Run All.

One notebook of ``notebooks/es/`` (the first with a live panel: the smallest built notebook other
than the sources, which has none) is opened as a student opens it, from a folder ``es/`` beside
the course's ``images/`` (its links and pictures point one folder up). The test checks that

* every code cell ran and none shows an error, a figure as text or a widget that failed;
* the page shows the Spanish text (the notebook's first heading, from its catalog);
* the kernel speaks Spanish (``dhlab.get_language()`` is 'es' after the set-up cell);
* a panel moves: its first slider, moved with the keyboard, changes its figure and shows no error.

It skips, saying why, when no Spanish notebook has been built yet, and the panel part when no
built Spanish notebook has a panel. A screenshot and a JSON report are left in
tests/browser/results/es-<notebook>.png / .json.
"""
from __future__ import annotations

import json
import shutil
from pathlib import Path

import nbformat
import pytest

from labdriver import (
    MIN_CHANGED,
    NOTEBOOK_JS,
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

ROOT = Path(__file__).resolve().parents[2]
SPANISH = ROOT / "notebooks" / "es"
NO_PANEL = {"09_sources_and_errata"}          # the sources and errata: text and three printed computations


def spanish_notebook():
    """The Spanish notebook to open: the smallest built one with panels, else any built one."""
    built = sorted(SPANISH.glob("[0-9][0-9]_*.ipynb"), key=lambda p: p.stat().st_size)
    with_panels = [p for p in built if p.stem not in NO_PANEL]
    return (with_panels or built or [None])[0]


def first_heading(path: Path) -> str:
    for cell in nbformat.read(path, as_version=4).cells:
        if cell.cell_type == "markdown":
            for line in cell.source.splitlines():
                if line.startswith("#"):
                    return line.lstrip("#").strip().replace("*", "").replace("`", "")
    return ""


def kernel_language(page) -> str:
    """What ``dhlab.get_language()`` says in the notebook's kernel (asked directly, no cell added)."""
    return page.evaluate(f"""async () => {{
        const kernel = {NOTEBOOK_JS}.sessionContext.session.kernel;
        let text = '';
        const future = kernel.requestExecute({{code: 'import dhlab; print(dhlab.get_language(), end="")',
                                               silent: false, store_history: false}});
        future.onIOPub = (msg) => {{ if (msg.header.msg_type === 'stream') text += msg.content.text; }};
        await future.done;
        return text;
    }}""")


def test_a_spanish_notebook_runs_and_its_panel_moves(lab_page, lab_root, results_dir):
    source = spanish_notebook()
    if source is None:
        pytest.skip("no Spanish notebook built yet (python -m tools.edition build)")
    folder = lab_root / "spanish"
    if not (folder / "images").exists():
        shutil.copytree(ROOT / "notebooks" / "images", folder / "images")
    with_backend(source, folder / "es" / source.name, None)
    page = lab_page
    try:
        open_notebook(page, f"spanish/es/{source.name}")
        run_all(page)
        report = outputs_report(page)
        failures = problems(report)
        failures += [f"cell {c['index']}: did not run" for c in report["cells"]
                     if c["executed"] is None and c["source"].strip()]
        heading = first_heading(source)
        shown = page.locator(".jp-Notebook .jp-MarkdownOutput h1, .jp-Notebook .jp-MarkdownOutput h2").first
        if heading not in shown.inner_text():
            failures.append(f"the page does not show the Spanish title {heading!r} (it shows {shown.inner_text()!r})")
        language = kernel_language(page)
        if language != "es":
            failures.append(f"dhlab.get_language() is {language!r} in the Spanish notebook's kernel")
        found = panels(page)
        moved = []
        for index, output in found[:2]:
            changed, error = move_first_slider(page, output)
            moved.append(changed)
            if changed < MIN_CHANGED:
                failures.append(f"cell {index}: moving the panel's first slider changed only {changed:.3%} "
                                "of its figure")
            if error:
                failures.append(f"cell {index}: the panel shows {error!r}")
        failures += [f"after the slider moves: {line}" for line in problems(outputs_report(page))
                     if line not in problems(report)]
        full_page_screenshot(page, results_dir / f"es-{source.stem}.png")
        (results_dir / f"es-{source.stem}.json").write_text(json.dumps(
            {"notebook": f"es/{source.name}", "kernel_language": language, "panels_found": len(found),
             "changed_fractions": [round(c, 5) for c in moved], "failures": failures}, indent=1))
    finally:
        close_notebook(page)
    assert not failures, f"notebooks/es/{source.name}:\n  " + "\n  ".join(failures)
    if not found:
        pytest.skip(f"notebooks/es/{source.name} ran cleanly in Spanish, but no built Spanish notebook has "
                    "a panel yet: the panel check waits for one (build a notebook with a panel)")
