"""The Spanish edition: complete and up to date for every notebook of EDITION_NOTEBOOKS, and each
check able to fail (a changed English sentence, a fuzzy or untranslated or obsolete entry, a lost
placeholder, a changed code cell, a stale stored notebook), shown on modified copies in tmp_path.

nbval re-executes notebooks/es/*.ipynb like the English notebooks (pyproject's testpaths).
"""
import copy
import fnmatch
import shutil
import sys
from pathlib import Path

import nbformat
import pytest

from tools import edition as ed
from tools.edition import EDITION_NOTEBOOKS, NOTEBOOKS, Edition, EditionError
from tools.edition_catalog import code_comments, markdown_cells, read_catalog, write_catalog
from tools.edition_text import anchor, comments, headings, placeholder_difference, placeholders, relink, with_comments

ROOT = Path(__file__).resolve().parents[2]
REPO = Edition()
SAMPLE = "09_sources_and_errata"         # the notebook the tests copy and break


# --- the edition in the repository -----------------------------------------------------

@pytest.mark.parametrize("stem", EDITION_NOTEBOOKS)
def test_edition_notebook_complete_and_up_to_date(stem):
    problems = REPO.check(stem)
    assert not problems, f"the Spanish edition of {stem}:\n" + "\n".join(problems)


def test_every_stored_spanish_notebook_is_up_to_date():
    """A Spanish notebook in notebooks/es/ belongs to the edition and matches what build makes,
    whether or not EDITION_NOTEBOOKS lists it yet."""
    stored = sorted(p.stem for p in REPO.spanish_dir.glob("*.ipynb"))
    assert set(EDITION_NOTEBOOKS) <= set(stored)
    for stem in stored:
        assert stem in NOTEBOOKS, f"notebooks/es/{stem}.ipynb has no English notebook in the edition"
        assert not REPO.check(stem), f"notebooks/es/{stem}.ipynb is stale: {REPO.check(stem)[:5]}"


def spanish_links(path):
    """(cell id, target) of every relative link or image of a stored notebook."""
    nb = nbformat.read(path, as_version=4)
    found = []
    for cell in nb.cells:
        if cell.cell_type == "markdown":
            relink(cell.source, lambda target: found.append((cell.id, target)) or target)
    return [(i, t) for i, t in found if not ed.URL.match(t)]


@pytest.mark.parametrize("path", sorted(REPO.spanish_dir.glob("*.ipynb")), ids=lambda p: p.stem)
def test_every_link_of_a_spanish_notebook_lands(path):
    """From notebooks/es/: the file exists, and a notebook's anchor is one of its headings' ids."""
    broken = []
    for cell_id, target in spanish_links(path):
        file, _, fragment = target.partition("#")
        landing = (path.parent / file).resolve() if file else path
        if not landing.exists():
            broken.append(f"cell {cell_id}: {target} (no such file)")
        elif fragment and landing.suffix == ".ipynb":
            ids = {anchor(text) for c in nbformat.read(landing, as_version=4).cells
                   if c.cell_type == "markdown" for _, text in headings(c.source)}
            if fragment not in ids:
                broken.append(f"cell {cell_id}: {target} (no such heading)")
    assert not broken, f"{path.name}:\n  " + "\n  ".join(broken)


def test_the_course_home_lists_both_editions():
    assert REPO.home_problems() == [], REPO.home_problems()
    home = nbformat.read(REPO.home_path(), as_version=4)
    assert all(c.cell_type == "markdown" for c in home.cells)
    text = "\n".join(c.source for c in home.cells)
    assert "(01_start_here.ipynb)" in text and "Settings › Language" in text
    for stem in NOTEBOOKS:
        assert (f"(es/{stem}.ipynb)" in text) == REPO.spanish_path(stem).exists(), stem


def test_the_edition_lists_name_real_notebooks():
    assert set(EDITION_NOTEBOOKS) <= set(NOTEBOOKS)
    for stem in NOTEBOOKS:
        assert REPO.english_path(stem).exists(), stem


def test_nbval_collects_the_spanish_notebooks():
    tomllib = pytest.importorskip("tomllib") if sys.version_info >= (3, 11) else pytest.importorskip("tomli")
    options = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["pytest"]["ini_options"]
    assert "notebooks" in options["testpaths"]
    assert not any(fnmatch.fnmatch("es", pattern) for pattern in options.get("norecursedirs", []))
    assert "--nbval" in options["addopts"]


# --- a copy of one notebook's edition, to break ----------------------------------------

@pytest.fixture
def edition(tmp_path):
    """The sample notebook and its catalog copied into tmp_path, its Spanish notebook built there
    (not executed: the checks compare sources and metadata)."""
    if REPO.problems(SAMPLE):
        pytest.skip(f"{SAMPLE}'s catalog is not complete")
    copy_ = Edition(english_dir=tmp_path / "en", spanish_dir=tmp_path / "en" / "es", catalog_dir=tmp_path / "po",
                    shipped_dir=tmp_path / "shipped")
    for source, target in ((REPO.english_path(SAMPLE), copy_.english_path(SAMPLE)),
                           (REPO.catalog_path(SAMPLE), copy_.catalog_path(SAMPLE))):
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(source, target)
    copy_.build(SAMPLE, execute=False)
    return fresh(copy_)


def fresh(edition):
    """The same folders, nothing cached (after a file changed)."""
    return Edition(edition.english_dir, edition.spanish_dir, edition.catalog_dir, edition.shipped_dir)


def edit_english(edition, cell_id, change):
    path = edition.english_path(SAMPLE)
    nb = nbformat.read(path, as_version=4)
    cell = next(c for c in nb.cells if c.id == cell_id)
    change(nb, cell)
    nbformat.write(nb, path)
    return fresh(edition)


def edit_catalog(edition, cell_id, change):
    catalog = read_catalog(edition.catalog_path(SAMPLE))
    change(next(m for m in catalog if m.context == cell_id))
    write_catalog(catalog, edition.catalog_path(SAMPLE))
    return fresh(edition)


def first_markdown_with(edition, text):
    return next(i for i, s in markdown_cells(edition.english(SAMPLE)) if text in s)


def test_the_copy_passes(edition):
    assert edition.check(SAMPLE) == []


def test_a_changed_english_sentence_fails_naming_the_cell_until_the_translation_is_revised(edition):
    cell_id = first_markdown_with(edition, "**Correct:**")
    edition = edit_english(edition, cell_id,
                           lambda nb, c: setattr(c, "source", c.source.replace("**Correct:**", "**Right:**")))
    problems = edition.check(SAMPLE)
    assert any(cell_id in p and "English text changed" in p for p in problems), problems
    with pytest.raises(EditionError, match=cell_id):
        edition.build(SAMPLE, execute=False)

    edition.extract(SAMPLE)                        # gettext's rule: the old translation is kept, fuzzy
    edition = fresh(edition)
    message = next(m for m in edition.catalog(SAMPLE) if m.context == cell_id)
    assert message.fuzzy and "**Correct:**" in message.previous_id[0] and "**Right:**" in message.id
    assert "#| msgid" in edition.catalog_path(SAMPLE).read_text()     # gettext's form, for the translator
    assert message.string, "the old translation must be kept for the translator to revise"
    problems = edition.check(SAMPLE)
    assert any(cell_id in p and "fuzzy" in p for p in problems), problems
    with pytest.raises(EditionError, match="fuzzy"):
        edition.build(SAMPLE, execute=False)

    def revise(m):
        m.string = m.string.replace("Lo correcto", "Correcto")
        m.flags.discard("fuzzy")
        m.previous_id = []
    edition = edit_catalog(edition, cell_id, revise)
    problems = edition.check(SAMPLE)                # the catalog is right, the stored notebook is not
    assert problems and all("rebuild" in p for p in problems) and any(cell_id in p for p in problems), problems
    edition.build(SAMPLE, execute=False)
    assert fresh(edition).check(SAMPLE) == []
    spanish = nbformat.read(edition.spanish_path(SAMPLE), as_version=4)
    assert "**Correcto:**" in next(c for c in spanish.cells if c.id == cell_id).source


def test_an_untranslated_entry_fails(edition):
    cell_id = first_markdown_with(edition, "## The shelf")
    problems = edit_catalog(edition, cell_id, lambda m: setattr(m, "string", "")).check(SAMPLE)
    assert f"cell {cell_id}: untranslated" in problems


def test_a_new_english_cell_is_extracted_untranslated(edition):
    def add(nb, cell):
        new = nbformat.v4.new_markdown_cell("A new paragraph.")
        new.id = "t-new"
        nb.cells.insert(nb.cells.index(cell) + 1, new)
    edition = edit_english(edition, first_markdown_with(edition, "## The shelf"), add)
    assert any("t-new" in p and "not in the catalog" in p for p in edition.check(SAMPLE))
    edition.extract(SAMPLE)
    assert "cell t-new: untranslated" in fresh(edition).check(SAMPLE)


def test_a_removed_english_cell_becomes_obsolete_then_pruned(edition):
    cell_id = first_markdown_with(edition, "## The shelf")
    edition = edit_english(edition, cell_id, lambda nb, c: nb.cells.remove(c))
    assert any(cell_id in p and "does not have" in p for p in edition.check(SAMPLE))
    edition.extract(SAMPLE)
    edition = fresh(edition)
    assert any(cell_id in p and "obsolete" in p for p in edition.check(SAMPLE))
    edition.extract(SAMPLE, prune=True)
    assert not any(cell_id in p for p in fresh(edition).check(SAMPLE))


def test_extract_leaves_a_complete_catalog_byte_identical(edition):
    before = edition.catalog_path(SAMPLE).read_bytes()
    edition.extract(SAMPLE)
    assert edition.catalog_path(SAMPLE).read_bytes() == before


@pytest.mark.parametrize("change", [
    lambda s: s.replace("`", "'", 2),                              # a code span lost
    lambda s: s.replace("03_robot_no_tan_elemental.ipynb", "03_robot.ipynb", 1),   # a link target changed
    lambda s: s.replace("${}^0H_1$", "$^0H_1$", 1),               # maths retyped
    lambda s: s + " <br>",                                         # an HTML tag added
])
def test_a_wrong_placeholder_fails_naming_the_cell(edition, change):
    cell_id = first_markdown_with(edition, "${}^0H_1$")
    problems = edit_catalog(edition, cell_id, lambda m: setattr(m, "string", change(m.string))).check(SAMPLE)
    assert any(p.startswith(f"cell {cell_id}: the placeholders differ") for p in problems), problems


def test_a_changed_heading_level_fails(edition):
    cell_id = first_markdown_with(edition, "## The shelf")
    problems = edit_catalog(edition, cell_id, lambda m: setattr(m, "string", "#" + m.string)).check(SAMPLE)
    assert any(cell_id in p and "heading levels" in p for p in problems), problems


def _edit_spanish(edition, change):
    path = edition.spanish_path(SAMPLE)
    nb = nbformat.read(path, as_version=4)
    change(nb)
    nbformat.write(nb, path)
    return fresh(edition)


def test_a_changed_spanish_code_cell_fails(edition):
    def change(nb):
        cell = [c for c in nb.cells if c.cell_type == "code"][-1]
        cell.source += "\nprint('hola')"
    problems = _edit_spanish(edition, change).check(SAMPLE)
    assert any("its code differs from the English" in p for p in problems), problems


def test_a_changed_english_code_cell_makes_the_stored_spanish_stale(edition):
    cell_id = next(c.id for c in edition.english(SAMPLE).cells if c.cell_type == "code")
    edition = edit_english(edition, cell_id, lambda nb, c: setattr(c, "source", c.source + "\n1 + 1"))
    problems = edition.check(SAMPLE)
    assert any(cell_id in p and "code differs" in p for p in problems), problems


def test_changed_spanish_cell_ids_fail(edition):
    problems = _edit_spanish(edition, lambda nb: setattr(nb.cells[0], "id", "x1")).check(SAMPLE)
    assert any("cell ids differ" in p for p in problems), problems


def test_changed_spanish_metadata_fail(edition):
    edited = _edit_spanish(edition, lambda nb: nb.cells[1].metadata.update(slideshow={"slide_type": "skip"}))
    problems = edited.check(SAMPLE)
    assert any(nb_cell_id(edition, 1) in p and "metadata differ" in p for p in problems), problems


def test_a_hand_edited_spanish_text_fails(edition):
    edited = _edit_spanish(edition, lambda nb: setattr(nb.cells[0], "source", nb.cells[0].source + " ¡Hola!"))
    problems = edited.check(SAMPLE)
    assert any(nb_cell_id(edition, 0) in p and "not what build makes of the catalog" in p for p in problems), problems


def nb_cell_id(edition, index):
    return edition.english(SAMPLE).cells[index].id


def test_the_setup_cell_must_set_the_language(edition):
    cell_id = next(c.id for c in edition.english(SAMPLE).cells if c.cell_type == "code")
    edition = edit_english(edition, cell_id, lambda nb, c: setattr(
        c, "source", c.source.replace(ed.SET_LANGUAGE_EN + "\n", "")))
    assert any("set_language" in p for p in edition.check(SAMPLE))


# --- what build makes --------------------------------------------------------------------

def test_build_keeps_cells_ids_metadata_and_code(edition):
    english, spanish = edition.english(SAMPLE), edition.spanish(SAMPLE)
    assert [c.id for c in spanish.cells] == [c.id for c in english.cells]
    assert spanish.metadata == english.metadata
    code_changed = 0
    for en, es in zip(english.cells, spanish.cells):
        assert (es.cell_type, es.metadata) == (en.cell_type, en.metadata)
        if en.cell_type == "code":
            code_changed += es.source != en.source
            assert es.source == en.source.replace(ed.SET_LANGUAGE_EN, ed.SET_LANGUAGE_ES)
        elif en.source.strip():
            assert es.source != en.source, f"cell {en.id} is not translated"
    assert code_changed == 1, "exactly the set-up cell differs (its set_language line)"


def test_the_stored_spanish_notebook_is_executed():
    if not REPO.spanish_path(SAMPLE).exists():
        pytest.skip("no Spanish notebook yet")
    nb = nbformat.read(REPO.spanish_path(SAMPLE), as_version=4)
    code = [c for c in nb.cells if c.cell_type == "code"]
    assert all(c.execution_count for c in code) and all(c.outputs for c in code)
    assert not [o for c in code for o in c.outputs if o.output_type == "error"]


def test_build_relinks_images_links_and_anchors(tmp_path):
    """From notebooks/es/: images one folder up; a notebook with a Spanish edition stays in
    Spanish (its anchor translated); one without goes to the English notebook; URLs unchanged."""
    edition = Edition(english_dir=tmp_path, spanish_dir=tmp_path / "es", catalog_dir=tmp_path / "po",
                      shipped_dir=tmp_path / "shipped")
    setup = nbformat.v4.new_code_cell('import dhlab\ndhlab.set_language("en")')
    a = nbformat.v4.new_notebook(cells=[
        nbformat.v4.new_markdown_cell("## Start\n![a robot](images/r.png) <img src=\"images/s.png\"> "
                                      "[next](09_sources_and_errata.ipynb#The-end) [here](#Start) "
                                      "[old](05_dh_convention.ipynb#Recap) [web](https://example.org/x.png) "
                                      "`images/code.png`"), setup])
    b = nbformat.v4.new_notebook(cells=[nbformat.v4.new_markdown_cell("# Title\n## The end"), copy.deepcopy(setup)])
    for nb, stem, translation in ((a, "01_start_here", None), (b, "09_sources_and_errata", "# Título\n## El final")):
        for i, cell in enumerate(nb.cells):
            cell.id = f"{stem[:2]}-{i}"
        nbformat.write(nb, edition.english_path(stem))
        edition.extract(stem)
        catalog = read_catalog(edition.catalog_path(stem))
        for message in catalog:
            if message.id:
                message.string = translation or message.id.replace("## Start", "## Inicio")
        write_catalog(catalog, edition.catalog_path(stem))
    edition = fresh(edition)
    edition.build("09_sources_and_errata", execute=False)       # built: the others link to it in Spanish
    text = edition.spanish("01_start_here").cells[0].source
    assert "](../images/r.png)" in text and 'src="../images/s.png"' in text
    assert "](09_sources_and_errata.ipynb#El-final)" in text           # in the edition, anchor in Spanish
    assert "](#Inicio)" in text                                         # this notebook's own heading
    assert "](../05_dh_convention.ipynb#Recap)" in text                  # no Spanish edition yet
    assert "](https://example.org/x.png)" in text and "`images/code.png`" in text
    assert edition.spanish("01_start_here").cells[1].source.endswith('dhlab.set_language("es")')


# --- the pieces: placeholders, headings, catalogs ----------------------------------------

@pytest.mark.parametrize("english, spanish", [
    ("the angle $\\theta$", "el ángulo $\\alpha$"),
    ("$$A = B$$", "$$A=B$$"),
    ("call `fk(q)`", "llame a fk(q)"),
    ("[see](05_x.ipynb#Rules)", "[vea](05_x.ipynb#Reglas)"),
    ("![robot](images/a.png)", "![robot](images/b.png)"),
    ("<details><summary>Answer</summary>x</details>", "<details>Respuesta x</details>"),
    ("a `$x$` code span", "un $x$ sin código"),
])
def test_placeholder_differences_are_found(english, spanish):
    assert placeholder_difference(english, spanish)
    assert placeholder_difference(english, english) == ""


def test_placeholders_ignore_prose_and_count_repeats():
    assert placeholder_difference("Two `x` and `x`.", "Dos `x` y `x`.") == ""
    assert "missing" in placeholder_difference("Two `x` and `x`.", "Dos `x`.")
    assert placeholders("A [link](<07_s.ipynb#Part-(a)>) here") == {"<07_s.ipynb#Part-(a)>": 1}


def test_headings_and_anchors():
    assert headings("# A\ntext\n```\n# not a heading\n```\n### B `c`") == [(1, "A"), (3, "B `c`")]
    assert anchor("Erratum 000-1: −90° about x") == "Erratum-000-1:-−90°-about-x"
    assert relink("[a](x.ipynb) `[b](y.ipynb)`", lambda t: "../" + t) == "[a](../x.ipynb) `[b](y.ipynb)`"


@pytest.mark.parametrize("stem", NOTEBOOKS)
def test_every_english_notebook_round_trips_through_a_catalog(stem, tmp_path):
    """extract writes each markdown cell's source and each code comment exactly: read back, every one is
    found by (cell id, text)."""
    edition = Edition(english_dir=REPO.english_dir, spanish_dir=tmp_path / "es", catalog_dir=tmp_path,
                      shipped_dir=tmp_path / "shipped")
    edition.extract(stem)
    catalog = read_catalog(edition.catalog_path(stem))
    cells = markdown_cells(edition.english(stem)) + code_comments(edition.english(stem))
    assert len([m for m in catalog if m.id]) == len(cells)
    for cell_id, source in cells:
        assert catalog.get(source, context=cell_id) is not None, cell_id


def test_the_command_line(capsys):
    assert ed.main(["check", "no_such_notebook"]) == 1
    assert "not a notebook of the Spanish edition" in capsys.readouterr().err
    if EDITION_NOTEBOOKS:
        assert ed.main(["check", *EDITION_NOTEBOOKS]) == 0


def test_a_markdown_cell_without_an_id_is_refused_clearly():
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_markdown_cell("Some text.")])
    del nb.cells[0]["id"]
    with pytest.raises(ed.DHLabError, match="no id"):
        markdown_cells(nb)


def test_build_if_stale_rebuilds_only_what_changed_and_writes_the_home(edition, capsys):
    assert ed._build(edition, [SAMPLE], explicit=False, execute=False, if_stale=True) == 0
    assert "building" not in capsys.readouterr().out          # up to date: nothing rebuilt
    assert edition.home_problems() == [] and f"(es/{SAMPLE}.ipynb)" in edition.home_path().read_text()
    edition = edit_catalog(edition, first_markdown_with(edition, "## The shelf"),
                           lambda m: setattr(m, "string", m.string.replace("El estante", "La estantería")))
    assert ed._build(edition, [SAMPLE], explicit=False, execute=False, if_stale=True) == 0
    assert f"building {edition.spanish_path(SAMPLE)}" in capsys.readouterr().out
    assert fresh(edition).check(SAMPLE) == []


# --- the assignment (notebook 8): in the edition, and the source of every Spanish release ------------------

ASSIGNMENT = "08_puma_assignment"


def without_comments(source: str) -> str:
    """A code cell's text with every comment cut (from its '#' to the end of its line)."""
    return with_comments(source, {text: "" for text in comments(source)})


def test_the_assignment_is_in_the_edition_and_its_code_is_the_english_code():
    assert ASSIGNMENT in EDITION_NOTEBOOKS
    english, spanish = REPO.english(ASSIGNMENT), REPO.spanish(ASSIGNMENT)
    code_en = [c.source for c in english.cells if c.cell_type == "code"]
    code_es = [c.source for c in spanish.cells if c.cell_type == "code"]
    assert ed.SET_LANGUAGE_ES in code_es[0] and ed.SET_LANGUAGE_EN in code_en[0]
    # the same code, line for line, once the comments are taken out; the comments are Spanish
    assert [without_comments(s) for s in code_es] == [without_comments(s.replace(ed.SET_LANGUAGE_EN,
                                                                                 ed.SET_LANGUAGE_ES)) for s in code_en]
    assert "# ESCRIBA SU CÓDIGO AQUÍ" in "\n".join(code_es) and "# YOUR CODE HERE" not in "\n".join(code_es)
    assert [c.metadata.get("nbgrader") for c in spanish.cells] == [c.metadata.get("nbgrader") for c in english.cells]


def test_the_home_lists_the_spanish_assignment_beside_the_english_one():
    home = REPO.home().cells[1].source
    assert f"({ASSIGNMENT}.ipynb)" in home
    assert (f"(es/{ASSIGNMENT}.ipynb)" in home) == REPO.spanish_path(ASSIGNMENT).exists()


def test_a_spanish_release_uses_the_editions_text(tmp_path):
    """Every markdown cell the variant leaves alone reads as in notebooks/es/08 (one translation, one catalog)."""
    import json

    from dhlab.grading.release import notebooks as R
    roster = tmp_path / "roster.csv"
    roster.write_text("id\nana\n", encoding="utf-8")
    (tmp_path / "key").write_bytes(b"edition-test-secret-0123456789\n")
    assert R.main(["release", str(roster), "-o", str(tmp_path / "out"), "--secret-file", str(tmp_path / "key"),
                   "--language", "es"]) == 0
    released = json.loads((tmp_path / "out" / "ana.ipynb").read_text(encoding="utf-8"))
    edition = {c.id: c.source for c in REPO.spanish(ASSIGNMENT).cells}
    same = [c for c in released["cells"]
            if c["cell_type"] == "markdown" and "".join(c["source"]) == edition.get(c["id"])]
    texts = ["".join(c["source"]) for c in same]
    assert any(t.startswith("## Parte 2") for t in texts) and any(t.startswith("## Parte 3") for t in texts), \
        "the cells the variant does not change are the edition's"


def test_the_package_reads_the_assignment_s_translations_where_build_writes_them():
    """dhlab-assign --language es reads notebook 8's Spanish text from the package (no catalog, no Babel
    there): the file build writes from the catalog, which check compares."""
    from dhlab.grading.release.language import SPANISH_TEXTS, spanish_texts
    assert ed.SHIPPED == [ASSIGNMENT] and REPO.shipped_path(ASSIGNMENT) == SPANISH_TEXTS
    template = REPO.english(ASSIGNMENT)
    found = spanish_texts(template)
    spanish = {c.id: c.source for c in REPO.spanish(ASSIGNMENT).cells if c.cell_type == "markdown"}
    assert found and all(spanish[cell_id].startswith(text[:20]) or "](" in text for cell_id, text in found.items())
    changed = nbformat.from_dict(copy.deepcopy(template))
    first = next(c for c in changed.cells if c.id in found)
    first.source += " (changed)"                         # a teacher's own text: not translated
    assert first.id not in spanish_texts(changed)


def test_a_stale_shipped_translation_fails_the_check(tmp_path):
    edition = Edition(english_dir=REPO.english_dir, spanish_dir=REPO.spanish_dir, catalog_dir=REPO.catalog_dir,
                      shipped_dir=tmp_path)
    assert any("tools.edition build" in p for p in edition.check(ASSIGNMENT))        # missing
    edition.shipped_path(ASSIGNMENT).write_text(REPO.shipped_path(ASSIGNMENT).read_text(encoding="utf-8"),
                                                encoding="utf-8")
    assert edition.check(ASSIGNMENT) == []
    edition.shipped_path(ASSIGNMENT).write_text("{}", encoding="utf-8")
    assert any("not what the catalog makes" in p for p in edition.check(ASSIGNMENT))


def test_opening_the_home_leaves_it_as_it_is():
    """JupyterLab writes the kernel's language_info into a notebook it opens and autosaves it when it
    differs: the home carries it in full, as the executed notebooks do (with only its name, merely
    opening the home modified the tracked notebooks/index.ipynb)."""
    stored = nbformat.read(REPO.home_path(), as_version=4)
    executed = REPO.english(NOTEBOOKS[0]).metadata.language_info
    assert stored.metadata.language_info == executed and "version" in executed
    assert REPO.home_problems() == []
