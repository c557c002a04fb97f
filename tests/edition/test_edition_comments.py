"""The comments of the code cells in the Spanish edition: translated through the catalogs, checked.

Every comment of an English code cell is an entry of its notebook's catalog (msgctxt the cell id);
``build`` puts its translation in place of the English one and leaves the code alone; ``check`` fails on
a comment that changed in English (its entry is no longer the comment) and on a stored Spanish notebook
whose comments are not the catalog's. The stored Spanish notebooks have no English comment line left.
"""
import re
import shutil

import nbformat
import pytest

from tools.edition import EDITION_NOTEBOOKS, SET_LANGUAGE_EN, SET_LANGUAGE_ES, Edition
from tools.edition_catalog import COMMENT_NOTE, read_catalog, write_catalog
from tools.edition_text import comments

REPO = Edition()
# words that only an English sentence has (code, identifiers and the course's names aside)
ENGLISH = re.compile(r"\b(the|your|write|below|run|this|cell|after|answering|points|each|link|frame|with|"
                     r"then|and|of|here|drawn|by|as|printed|seen|from|joints?|whole|numbers|one|per|list|"
                     r"words|metres|degrees|turn|slides|code|check|part|scored|build|own|same|move|along|"
                     r"back|at|in|is|are|for|to|or|not)\b", re.I)
# what a comment may hold that is not prose: code after "e.g."-like words, identifiers, formulas
CODE_BITS = re.compile(r"\"[^\"]*\"|'[^']*'|`[^`]*`|\b\w+\(|\b\w+\.\w+[\w./]*|\b[A-Za-z]\w*_\w*\b|"
                       r"\b[a-zA-Z]\d*\b|\{[^}]*\}|\[[^\]]*\]")


def english_words(comment: str) -> list[str]:
    """The English prose words of a comment (quoted text, code and identifiers ignored).

    >>> english_words("# the product, as multiplied"), english_words("# el producto (x, y, z)")
    (['the', 'as'], [])
    """
    return ENGLISH.findall(CODE_BITS.sub(" ", comment))


@pytest.mark.parametrize("stem", EDITION_NOTEBOOKS)
def test_no_english_comment_line_in_the_spanish_code_cells(stem):
    stored = nbformat.read(REPO.spanish_path(stem), as_version=4)
    english = [(cell.id, c) for cell in stored.cells if cell.cell_type == "code"
               for c in comments(cell.source) if english_words(c)]
    assert english == [], english


def test_the_english_notebooks_do_have_english_comments():
    """The word check can fail: it finds the English comments of the English notebooks."""
    nb = REPO.english("08_puma_assignment")
    found = [c for cell in nb.cells if cell.cell_type == "code" for c in comments(cell.source) if english_words(c)]
    assert "# YOUR CODE HERE" in found and len(found) >= 10


@pytest.fixture
def copy_edition(tmp_path):
    stem = "09_sources_and_errata"
    for sub in ("en", "es", "po", "shipped"):
        (tmp_path / sub).mkdir()
    shutil.copy(REPO.english_path(stem), tmp_path / "en")
    shutil.copy(REPO.spanish_path(stem), tmp_path / "es")
    shutil.copy(REPO.catalog_path(stem), tmp_path / "po")
    return stem, Edition(english_dir=tmp_path / "en", spanish_dir=tmp_path / "es", catalog_dir=tmp_path / "po",
                         shipped_dir=tmp_path / "shipped")


def test_a_comment_is_translated_and_the_code_stays(copy_edition):
    stem, edition = copy_edition
    assert edition.problems(stem) == []
    catalog = read_catalog(edition.catalog_path(stem))
    entry = next(m for m in catalog if m.id == "# (d, α°, a)")
    entry.string = "# (d, α en grados, a)"
    write_catalog(catalog, edition.catalog_path(stem))
    edition = Edition(edition.english_dir, edition.spanish_dir, edition.catalog_dir, edition.shipped_dir)
    english = [c.source for c in edition.english(stem).cells if c.cell_type == "code"]
    spanish = [c.source for c in edition.spanish(stem).cells if c.cell_type == "code"]
    changed = [(en, es) for en, es in zip(english, spanish) if en != es]
    # the set-up cell's language, and the one comment: nothing else differs
    expected = [en.replace(SET_LANGUAGE_EN, SET_LANGUAGE_ES).replace("# (d, α°, a)", "# (d, α en grados, a)")
                for en, _es in changed]
    assert changed and [es for _en, es in changed] == expected
    assert any("# (d, α en grados, a)" in es for _en, es in changed)


def test_a_changed_english_comment_makes_the_edition_stale(copy_edition):
    stem, edition = copy_edition
    nb = nbformat.read(edition.english_path(stem), as_version=4)
    cell = next(c for c in nb.cells if c.cell_type == "code" and "# (d, α°, a)" in c.source)
    cell.source = cell.source.replace("# (d, α°, a)", "# (d, α in degrees, a)")
    nbformat.write(nb, edition.english_path(stem))
    problems = Edition(edition.english_dir, edition.spanish_dir, edition.catalog_dir, edition.shipped_dir).check(stem)
    assert any("comment '# (d, α in degrees, a)'" in p and "changed" in p for p in problems), problems


def test_an_untranslated_or_broken_comment_is_a_problem(copy_edition):
    stem, edition = copy_edition
    catalog = read_catalog(edition.catalog_path(stem))
    entry = next(m for m in catalog if m.id and COMMENT_NOTE in m.auto_comments)
    entry.string = "(d, α°, a) sin almohadilla"
    write_catalog(catalog, edition.catalog_path(stem))
    problems = Edition(edition.english_dir, edition.spanish_dir, edition.catalog_dir, edition.shipped_dir).check(stem)
    assert any("must be one line that starts with '#'" in p for p in problems), problems
