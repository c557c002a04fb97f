"""The shelf of notebook 9: every textbook the notebooks cite is on it, with a full entry, and its
"cited in" column tells the truth.

A cite is an author and a year, as the notebooks write it: "Craig (2005)", "(Spong et al. 2006; Corke 2023)".
"""
import re
from pathlib import Path

import nbformat
import pytest

NOTEBOOKS = Path(__file__).resolve().parents[2] / "notebooks"
SHELF = "09_sources_and_errata"
AUTHORS = r"Barrientos et al\.|Torres et al\.|Craig|Spong et al\.|Corke|Siciliano et al\."
CITE = re.compile(rf"({AUTHORS})\s*\(?((?:19|20)\d\d)\b")
ROW = re.compile(r"^\| ((?:[A-Z][a-z]+)(?: et al\.)? (?:19|20)\d\d) \| (.+?) \| (.+?) \| (.+?) \|$", re.M)
LINKED = re.compile(r"\]\((\d\d)_\w+\.ipynb\)")


def markdown(name) -> str:
    nb = nbformat.read(NOTEBOOKS / f"{name}.ipynb", as_version=4)
    return "\n".join(c.source for c in nb.cells if c.cell_type == "markdown")


def cites(text) -> set:
    """'Author YEAR' for every cite in a text; 'Craig (2005)' and '(Craig 2005)' are the same cite."""
    text = re.sub(r"\s+", " ", text)            # a cite may break across lines
    return {f"{author} {year}" for author, year in CITE.findall(text)}


def shelf() -> dict:
    """{short cite: (entry, used for, notebooks cited in)} from notebook 9's table."""
    rows = ROW.findall(markdown(SHELF))
    return {short: (entry, used, set(LINKED.findall(where))) for short, entry, used, where in rows}


def course() -> dict:
    return {p.stem[:2]: p.stem for p in sorted(NOTEBOOKS.glob("[0-9][0-9]_*.ipynb"))}


def test_the_cite_reader():
    assert cites("as in Craig (2005) and (Spong et al. 2006; Corke 2023)") == {
        "Craig 2005", "Spong et al. 2006", "Corke 2023"}
    assert cites("modified DH (Craig), no year") == set()
    assert cites("Barrientos\net al. (2007)") == {"Barrientos et al. 2007"}


def test_the_shelf_has_the_seeds_textbooks_and_the_standard_references():
    books = shelf()
    for short in ("Barrientos et al. 2007", "Torres et al. 2005", "Craig 2005", "Spong et al. 2006",
                  "Corke 2023", "Siciliano et al. 2009"):
        assert short in books, f"{short} is not on the shelf"


@pytest.mark.parametrize("short", sorted(shelf()))
def test_each_entry_is_full(short):
    entry, used, _ = shelf()[short]
    author, year = short.rsplit(" ", 1)
    assert entry.startswith(tuple("ABCDEFGHIJKLMNOPQRSTUVWXYZ")) and author.split()[0] in entry
    assert re.search(r"\*[^*]+\*", entry), f"{short}: no title in italics"
    assert year in entry, f"{short}: the entry's year is not {year}"
    assert len(used.split()) >= 8, f"{short}: say what the course uses it for"


@pytest.mark.parametrize("name", sorted(course().values()))
def test_every_cite_is_on_the_shelf(name):
    unknown = cites(markdown(name)) - set(shelf())
    assert not unknown, f"{name} cites {unknown}, which the shelf of notebook 9 does not list"


def test_cited_in_tells_the_truth():
    names = course()
    for short, (_, _, where) in shelf().items():
        assert where, f"{short}: 'cited in' names no notebook"
        really = {n for n, name in names.items() if name != SHELF and short in cites(markdown(name))}
        assert where == really, (f"{short}: notebook 9 says cited in {sorted(where)}, "
                                 f"the notebooks cite it in {sorted(really)}")
