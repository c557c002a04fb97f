"""The rules a lecture notebook keeps so that it presents as a deck.

A deck is the notebook itself, cut into slides by each cell's
``metadata.slideshow.slide_type`` (the standard Jupyter slideshow metadata that
jupyterlab-slideshow, RISE and nbconvert read):

- ``slide`` / ``subslide`` start a new screen; ``fragment`` adds to the current one
  on the next key press; a cell without a slide type (no ``slideshow`` key: what
  JupyterLab's property inspector writes for "-") continues the current screen. The
  literal ``"-"`` is refused: jupyterlab-slideshow 0.3.4 never shows such a cell
  (measured in the browser; its presenter has no case for it); ``skip`` and ``notes``
  cells are not on screen in the deck (``notes`` are the lecturer's notes, ``skip`` is
  self-study text) but a student reading the notebook sees them as usual.
- On one screen: at most ``MAX_WORDS`` words of prose (markdown outside math,
  code spans, HTML tags and link targets) and at most ``MAX_CODE_LINES`` lines
  of code whose source is shown (``metadata.jupyter.source_hidden`` hides it).
- The first cell starts a slide.

Run ``python tests/support/deck_rules.py notebooks/05_dh_convention.ipynb`` to list the
screens with their word and code-line counts and every rule broken.
"""
from __future__ import annotations

import json
import re
import sys
from pathlib import Path

MAX_WORDS = 40
MAX_CODE_LINES = 15
TYPES = {"slide", "subslide", "fragment", "skip", "notes", None}     # None: continue the screen
ON_SCREEN = {"slide", "subslide", "fragment", None}
LECTURE_NOTEBOOKS = ["02_homogeneous_matrices", "03_robot_no_tan_elemental", "04_pr_mechanism_and_spaces",
                     "05_dh_convention", "06_dh_examples", "07_ssrms"]

_MATH = re.compile(r"\$\$.*?\$\$|\$[^$\n]+\$|\\\[.*?\\\]|\\\(.*?\\\)", re.S)
_CODE = re.compile(r"```.*?```|`[^`\n]*`", re.S)
_TAG = re.compile(r"<[^>]+>")
_LINK_TARGET = re.compile(r"\]\([^)]*\)")
_WORD = re.compile(r"[^\W\d_]+(?:['’-][^\W\d_]+)*")


def source(cell) -> str:
    text = cell.get("source", "")
    return "".join(text) if isinstance(text, list) else text


def prose_words(markdown: str) -> int:
    """Words a reader reads on screen: markdown without math, code, HTML tags or link targets."""
    for pattern in (_MATH, _CODE, _TAG, _LINK_TARGET):
        markdown = pattern.sub(" ", markdown)
    return len(_WORD.findall(markdown))


def shown_code_lines(cell) -> int:
    if cell.get("metadata", {}).get("jupyter", {}).get("source_hidden"):
        return 0
    return len([line for line in source(cell).splitlines() if line.strip()])


def slide_type(cell) -> str | None:
    return cell.get("metadata", {}).get("slideshow", {}).get("slide_type") or None


def screens(nb) -> list[dict]:
    """The deck's screens in order: each with its first cell's index, cell ids, words and code lines."""
    out: list[dict] = []
    for index, cell in enumerate(nb["cells"]):
        kind = slide_type(cell)
        if kind not in ON_SCREEN:
            continue
        if kind in ("slide", "subslide") or not out:
            out.append({"first": index, "ids": [], "words": 0, "code_lines": 0})
        screen = out[-1]
        screen["ids"].append(cell.get("id"))
        if cell["cell_type"] == "markdown":
            screen["words"] += prose_words(source(cell))
        elif cell["cell_type"] == "code":
            screen["code_lines"] += shown_code_lines(cell)
    return out


def problems(nb) -> list[str]:
    """Every rule the notebook breaks, one line each (empty when it presents as a deck)."""
    found = []
    for index, cell in enumerate(nb["cells"]):
        kind = slide_type(cell)
        if kind == "-":
            found.append(f"cell {index} ({cell.get('id')}): slide_type '-' is never shown by jupyterlab-slideshow: "
                         "delete the cell's 'slideshow' metadata instead (no key = continue the screen)")
        elif kind not in TYPES:
            found.append(f"cell {index} ({cell.get('id')}): slide_type {kind!r}, expected slide, subslide, "
                         "fragment, skip, notes or none (continue the screen)")
    first = slide_type(nb["cells"][0]) if nb["cells"] else None
    if first != "slide":
        found.append(f"cell 0: the first cell must start a slide, not {first!r} (the deck treats it as one anyway)")
    for screen in screens(nb):
        where = f"screen at cell {screen['first']} ({screen['ids'][0]})"
        if screen["words"] > MAX_WORDS:
            found.append(f"{where}: {screen['words']} words of prose (at most {MAX_WORDS})")
        if screen["code_lines"] > MAX_CODE_LINES:
            found.append(f"{where}: {screen['code_lines']} lines of code shown (at most {MAX_CODE_LINES})")
    return found


def main(paths) -> int:
    bad = 0
    for path in paths:
        nb = json.loads(Path(path).read_text(encoding="utf-8"))
        shown = screens(nb)
        print(f"{path}: {len(shown)} screens")
        for screen in shown:
            print(f"  cell {screen['first']:3d} {str(screen['ids'][0]):24s} {screen['words']:3d} words "
                  f"{screen['code_lines']:3d} code lines")
        for line in problems(nb):
            print("  PROBLEM:", line)
            bad += 1
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
