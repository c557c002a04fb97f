"""Every lecture notebook (02-07) presents as a slide deck, checked on the stored notebooks.

The rules are tests/support/deck_rules.py (words and code lines per screen, a slide type on every
cell). Beside them, what the presenting tool (jupyterlab-slideshow 0.3.4) and the lecture hall
need: no cell the tool would hide by mistake, the set-up cell out of sight, each live panel on a
screen of its own with at most a line or two of prose, a deck of a lecture's length, and a
lecture plan per notebook. What the browser shows is tests/browser/test_decks_browser.py.
"""
from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from support import deck_rules

ROOT = Path(__file__).resolve().parents[2]
NOTEBOOKS = ROOT / "notebooks"
PLANS = ROOT / "docs" / "lecturers"        # the lecturers' pages of the docs site
WIDGET = "application/vnd.jupyter.widget-view+json"
MIN_SCREENS, MAX_SCREENS = 12, 36        # a 90-minute lecture: about 15-25 screens, at least 2.5 min each
PANEL_SCREEN_WORDS = 25                  # a panel's screen: at most a line or two of prose
MAX_PLAN_WORDS = 1000                    # "about 900 words"


def notebook(stem: str) -> dict:
    return json.loads((NOTEBOOKS / f"{stem}.ipynb").read_text(encoding="utf-8"))


@pytest.fixture(params=deck_rules.LECTURE_NOTEBOOKS)
def lecture(request):
    return request.param, notebook(request.param)


def test_the_deck_rules_hold(lecture):
    stem, nb = lecture
    found = deck_rules.problems(nb)
    assert not found, f"{stem}: {len(found)} problems (python tests/support/deck_rules.py notebooks/{stem}.ipynb):\n" \
                      + "\n".join(found[:25])


@pytest.mark.parametrize("stem", deck_rules.LECTURE_NOTEBOOKS)
def test_the_spanish_decks_keep_the_rules_too(stem):
    """The Spanish edition is lectured from as well: its translations (longer than the English,
    as Spanish is) must still fit a screen."""
    path = NOTEBOOKS / "es" / f"{stem}.ipynb"
    if not path.exists():
        pytest.skip(f"no Spanish edition of {stem} yet")
    found = deck_rules.problems(json.loads(path.read_text(encoding="utf-8")))
    command = f"python tests/support/deck_rules.py notebooks/es/{stem}.ipynb"
    assert not found, f"es/{stem}: {len(found)} problems ({command}):\n" + "\n".join(found[:25])


def test_no_cell_is_lost_by_the_presenting_tool(lecture):
    """jupyterlab-slideshow 0.3.4 reads ``slide_type or null`` and knows only null, slide,
    subslide, fragment, skip and notes: a cell marked with the string "-" is never shown in the
    deck (measured in the browser). A cell that continues a screen
    carries no slide type (JupyterLab's own "-"), which every tool reads as "continue"."""
    stem, nb = lecture
    dashed = [f"cell {i} ({c.get('id')})" for i, c in enumerate(nb["cells"])
              if deck_rules.slide_type(c) == "-"]
    assert not dashed, f"{stem}: {len(dashed)} cells marked '-' would not be shown in the deck: {dashed[:10]}"


def test_the_set_up_cell_is_out_of_sight_and_sets_the_language(lecture):
    stem, nb = lecture
    first = next(c for c in nb["cells"] if c["cell_type"] == "code")
    lines = deck_rules.source(first).splitlines()
    assert "import dhlab" in lines, f"{stem}: the first code cell does not import dhlab"
    after = lines[lines.index("import dhlab") + 1].strip()
    assert after == 'dhlab.set_language("en")', \
        f"{stem}: the line after `import dhlab` is {after!r}, not dhlab.set_language(\"en\")"
    kind = deck_rules.slide_type(first)
    assert kind == "skip", f"{stem}: the set-up cell is {kind!r}, not skip"
    assert first["metadata"].get("jupyter", {}).get("source_hidden") is True, f"{stem}: the set-up cell's source shows"


def test_a_lecture_length_deck(lecture):
    stem, nb = lecture
    count = len(deck_rules.screens(nb))
    assert MIN_SCREENS <= count <= MAX_SCREENS, f"{stem}: {count} screens (a lecture: {MIN_SCREENS}-{MAX_SCREENS})"


def test_each_live_panel_has_a_screen_of_its_own(lecture):
    """A panel (a widget output) fits a 1920x1080 slide only with its heading and a line or two:
    one panel per screen, at most PANEL_SCREEN_WORDS words of prose beside it."""
    stem, nb = lecture
    by_id = {c.get("id"): c for c in nb["cells"]}
    found = []
    for screen in deck_rules.screens(nb):
        panels = [i for i in screen["ids"]
                  if any(WIDGET in o.get("data", {}) for o in by_id[i].get("outputs", []))]
        if len(panels) > 1:
            found.append(f"screen at {screen['ids'][0]}: {len(panels)} panels {panels}")
        if panels and screen["words"] > PANEL_SCREEN_WORDS:
            found.append(f"screen at {screen['ids'][0]}: a panel with {screen['words']} words of prose")
    assert not found, f"{stem}:\n" + "\n".join(found)


def test_each_lecture_has_a_plan(lecture):
    stem, _ = lecture
    plan = PLANS / f"{stem}.md"
    assert plan.exists(), f"no lecture plan {plan.relative_to(ROOT)}"
    text = plan.read_text(encoding="utf-8")
    words = len(text.split())
    assert words <= MAX_PLAN_WORDS, f"{plan.name}: {words} words (about 900 at most)"
    assert re.search(r"\b\d+\s*[–-]\s*\d+\b", text), f"{plan.name}: no timings (e.g. 0–5 min)"


def test_the_index_lists_every_plan():
    index = (PLANS / "index.md").read_text(encoding="utf-8")
    for stem in deck_rules.LECTURE_NOTEBOOKS:
        assert f"({stem}.md)" in index, f"docs/lecturers/index.md does not link {stem}.md"
    for link in re.findall(r"\]\(([^)#]+)\)", index):
        if not link.startswith("http"):
            assert (PLANS / link).resolve().exists(), f"docs/lecturers/index.md links {link}, which does not exist"
