"""Notebook 9, "Sources and errata": every erratum of the teachers' list has its own section, every
seed is named, and every link between the notebooks lands on a heading that exists.

The teachers' errata list and the seeds live beside the repository (``../shared``), not in a clone:
the tests that read them are skipped where it is absent.
"""
import re
from pathlib import Path

import nbformat
import pytest

ROOT = Path(__file__).resolve().parents[2]
NOTEBOOKS = ROOT / "notebooks"
SHARED = ROOT.parent / "shared"
ERRATA = SHARED / "reference" / "ERRATA.md"
SEEDS = SHARED / "seeds"
SOURCES = "09_sources_and_errata"
LINK = re.compile(r"\]\((?:<([0-9]{2}_\w+\.ipynb)(?:#([^>]*))?>|([0-9]{2}_\w+\.ipynb)(?:#([^)\s]*))?)\)")


def links(text):
    """(notebook, fragment) of every markdown link to a notebook of the course, <…> form included."""
    return [(a or c, b or d) for a, b, c, d in LINK.findall(text)]


def _notebook(name):
    path = NOTEBOOKS / f"{name}.ipynb"
    if not path.exists():
        pytest.skip(f"{path.name} not present")
    return nbformat.read(path, as_version=4)


def _markdown(nb) -> str:
    return "\n".join(c.source for c in nb.cells if c.cell_type == "markdown")


def anchors(nb) -> set:
    """The ids JupyterLab gives the notebook's headings: the heading's text (code and emphasis
    marks removed), spaces as '-'."""
    ids = set()
    for line in _markdown(nb).splitlines():
        if re.match(r"#{1,6} ", line):
            text = re.sub(r"[`*]", "", line.lstrip("#").strip())
            ids.add(text.replace(" ", "-"))
    return ids


def test_the_link_reader():
    text = "[a](<08_x.ipynb#Part-3-(5-points)>) [b](05_y.ipynb#Recap) [c](06_z.ipynb)"
    assert links(text) == [("08_x.ipynb", "Part-3-(5-points)"), ("05_y.ipynb", "Recap"), ("06_z.ipynb", "")]


def test_the_anchor_rule():
    cell = nbformat.v4.new_markdown_cell("### Erratum 004-1\ntext\n## 2. `THx` *is* wrong")
    nb = nbformat.v4.new_notebook(cells=[cell])
    assert anchors(nb) == {"Erratum-004-1", "2.-THx-is-wrong"}


def test_every_erratum_has_its_section():
    if not ERRATA.exists():
        pytest.skip("the teachers' errata list (../shared/reference/ERRATA.md) is not beside the repository")
    ids = re.findall(r"^\| (\d{3}-n?\d+) \|", ERRATA.read_text(encoding="utf-8"), re.M)
    assert len(ids) >= 30, "the errata list could not be read"
    have = anchors(_notebook(SOURCES))
    missing = [e for e in ids if f"Erratum-{e}" not in have]
    assert not missing, f"errata without a '### Erratum <id>' section in notebook 9: {missing}"


def test_every_erratum_section_has_the_seed_line_the_correction_and_a_link():
    nb = _notebook(SOURCES)
    sections = [c.source for c in nb.cells if c.cell_type == "markdown" and c.source.startswith("### Erratum ")]
    assert len(sections) >= 30
    for text in sections:
        eid = text.splitlines()[0].split()[-1]
        assert re.search(rf"\*\*Seed {eid[:3]}, [^*]+\*\*", text), f"{eid}: where in the seed?"
        assert "**Correct:**" in text or "**Note:**" in text, f"{eid}: no correction"
        assert "**Taught in:**" in text and LINK.search(text), f"{eid}: no link to the section that teaches it"


def test_every_seed_is_named():
    text = _markdown(_notebook(SOURCES))
    seeds = sorted(p.name[:3] for p in SEEDS.glob("*.txt")) if SEEDS.exists() else ["000", "001", "002", "003", "004"]
    for seed in seeds:
        assert f"| {seed} |" in text and f"## Seed {seed}:" in text, f"seed {seed} is not named in notebook 9"


def _all_notebooks():
    return sorted(p.stem for p in NOTEBOOKS.glob("[0-9][0-9]_*.ipynb"))


@pytest.mark.parametrize("name", _all_notebooks())
def test_links_between_notebooks_land_on_a_heading(name):
    """A link 'NN_name.ipynb#Anchor' opens a notebook of the course at a heading it has."""
    nb = _notebook(name)
    broken = []
    for target, fragment in links(_markdown(nb)):
        path = NOTEBOOKS / target
        if not path.exists():
            broken.append(f"{target} (no such notebook)")
        elif fragment and fragment not in anchors(nbformat.read(path, as_version=4)):
            broken.append(f"{target}#{fragment}")
    assert not broken, f"{name}: links that land nowhere: {broken}"


@pytest.mark.parametrize("name", ["05_dh_convention", "06_dh_examples", "07_ssrms", SOURCES])
def test_no_notebook_points_to_files_a_clone_lacks(name):
    nb = _notebook(name)
    text = "\n".join(c.source for c in nb.cells)
    for missing in ("shared/seeds", "VERIFIED_MATH", "ERRATA.md", "seeds/00", "REPORT.md"):
        assert missing not in text, f"{name} refers to {missing}, which a clone of the course does not have"


@pytest.mark.parametrize("name", ["05_dh_convention", "06_dh_examples", "07_ssrms", SOURCES])
def test_objectives_first_recap_last(name):
    nb = _notebook(name)
    first, last = nb.cells[0].source, nb.cells[-1].source
    assert "**After this notebook you can**" in first
    points = re.findall(r"^[-*] ", first.split("**After this notebook you can**", 1)[1].split("\n\n", 2)[1], re.M)
    assert 3 <= len(points) <= 5, f"{name}: {len(points)} objectives"
    assert last.startswith("## Recap") and "**Next:**" in last
    assert nb.metadata.get("language_info", {}).get("name") == "python"
