"""The Spanish edition of the notebooks: generated from the English ones and one catalog per notebook.

The English notebooks are the only place code is written. Each markdown cell is translated in
``tools/locale/es/notebooks/<stem>.po`` (see :mod:`tools.edition_catalog`), and
``notebooks/es/<stem>.ipynb`` is made from the two: the same cells, ids and metadata, the
markdown replaced by its translation (links adjusted to work from ``notebooks/es/``), the code
identical but for its comments (translated in the same catalog) and one line of the set-up cell,
``dhlab.set_language("en")``, which says "es".
It is then executed, like the English notebooks. Three commands::

    python -m tools.edition extract [notebooks...]   # catalogs in step with the English (naming
                                                     #   a notebook without one starts it)
    python -m tools.edition build   [notebooks...]   # write and execute notebooks/es/
    python -m tools.edition check   [notebooks...]   # fails on anything missing or stale

``build`` makes every notebook whose catalog is complete (and rewrites the course home,
``notebooks/index.ipynb``, which links to the Spanish notebooks that exist); a link between two
notebooks stays in Spanish when its target is built, its anchor translated. ``EDITION_NOTEBOOKS``
lists the notebooks the tests require; ``check`` also fails on any built one that is stale.

The package reads one catalog at run time: ``dhlab-assign --language es`` releases notebook 8 in
Spanish. It does not ship the catalogs (nor Babel, which reads them): ``build`` writes that
notebook's translations as plain JSON into the package, ``dhlab/grading/template/<stem>.es.json``
(:data:`SHIPPED`; cell id -> English and Spanish text of every translated entry), and ``check`` fails
when that file is not what the catalog makes.
"""
from __future__ import annotations

import argparse
import copy
import re
import sys
from dataclasses import dataclass, field
from pathlib import Path

import nbformat

from dhlab.errors import DHLabError

from .edition_catalog import (
    catalog_problems,
    comment_translations,
    extract,
    markdown_cells,
    read_catalog,
    shipped_texts,
    translations,
)
from .edition_home import HOME, home_notebook
from .edition_text import anchor, headings, relink, with_comments

__all__ = ["NOTEBOOKS", "EDITION_NOTEBOOKS", "SHIPPED", "Edition", "EditionError", "main"]

ROOT = Path(__file__).resolve().parents[1]          # the repository: this tool works there
# the notebooks with a Spanish edition (08, the assignment, too: dhlab-assign releases each student's
# personal notebook from it with --language es, see dhlab.grading.release.language)
NOTEBOOKS = ["01_start_here", "02_homogeneous_matrices", "03_robot_no_tan_elemental",
             "04_pr_mechanism_and_spaces", "05_dh_convention", "06_dh_examples", "07_ssrms",
             "08_puma_assignment", "09_sources_and_errata"]
# those whose Spanish edition must be complete and up to date (the tests fail otherwise)
EDITION_NOTEBOOKS = ["01_start_here", "02_homogeneous_matrices", "03_robot_no_tan_elemental",
                     "04_pr_mechanism_and_spaces",
                     "05_dh_convention", "06_dh_examples", "07_ssrms", "08_puma_assignment",
                     "09_sources_and_errata"]
# the notebooks whose translations the package reads at run time (dhlab.grading.release.language)
SHIPPED = ["08_puma_assignment"]

SET_LANGUAGE_EN = 'dhlab.set_language("en")'
SET_LANGUAGE_ES = 'dhlab.set_language("es")'
NOTEBOOK_LINK = re.compile(r"[0-9]{2}_\w+\.ipynb")
TRANSIENT = {"execution", "widgets", "kernelspec", "language_info"}   # tools.execute sets these
URL = re.compile(r"[A-Za-z][A-Za-z0-9+.-]*:")      # http:, https:, mailto:, data: ...


class EditionError(DHLabError):
    """The Spanish edition cannot be built as asked: the message says why and what to run."""


@dataclass
class Edition:
    """Where the English notebooks, the Spanish ones, the catalogs and the translations the package
    ships are (the repository's folders by default; tests use copies)."""
    english_dir: Path = ROOT / "notebooks"
    spanish_dir: Path = ROOT / "notebooks" / "es"
    catalog_dir: Path = ROOT / "tools" / "locale" / "es" / "notebooks"
    shipped_dir: Path = ROOT / "dhlab" / "grading" / "template"
    _cache: dict = field(default_factory=dict, repr=False)

    def english_path(self, stem: str) -> Path:
        return self.english_dir / f"{stem}.ipynb"

    def spanish_path(self, stem: str) -> Path:
        return self.spanish_dir / f"{stem}.ipynb"

    def catalog_path(self, stem: str) -> Path:
        return self.catalog_dir / f"{stem}.po"

    def shipped_path(self, stem: str) -> Path:
        """Where the package reads the notebook's translations (a notebook of :data:`SHIPPED`)."""
        return self.shipped_dir / f"{stem}.es.json"

    def english(self, stem: str):
        if ("en", stem) not in self._cache:
            path = self.english_path(stem)
            if not path.exists():
                raise EditionError(f"notebook {stem!r}: {path} does not exist; name a notebook of "
                                   f"the course ({', '.join(NOTEBOOKS)}).")
            self._cache["en", stem] = nbformat.read(path, as_version=4)
        return self._cache["en", stem]

    def catalog(self, stem: str):
        """The notebook's catalog, or None when it has none yet."""
        if ("po", stem) not in self._cache:
            path = self.catalog_path(stem)
            self._cache["po", stem] = read_catalog(path) if path.exists() else None
        return self._cache["po", stem]

    # --- the three commands ---------------------------------------------------------

    def extract(self, stem: str, prune: bool = False) -> str:
        """Bring the notebook's catalog in step with its English cells; a one-line summary."""
        catalog = extract(self.english(stem), self.catalog_path(stem), prune=prune)
        self._cache.pop(("po", stem), None)
        done = sum(1 for m in catalog if m.id and m.string and not m.fuzzy)
        fuzzy = sum(1 for m in catalog if m.id and m.fuzzy)
        return (f"{self.catalog_path(stem)}: {done} of {sum(1 for m in catalog if m.id)} cells translated, "
                f"{fuzzy} fuzzy, {len(catalog.obsolete)} obsolete")

    def problems(self, stem: str) -> list[str]:
        """Why the catalog cannot make the Spanish notebook ([] when it can)."""
        catalog = self.catalog(stem)
        if catalog is None:
            return [f"no catalog yet ({self.catalog_path(stem)}): run extract, then translate it"]
        return catalog_problems(self.english(stem), catalog) + self._setup_problems(stem)

    def spanish(self, stem: str):
        """The Spanish notebook as build makes it, before execution (outputs as in English)."""
        problems = self.problems(stem)
        if problems:
            raise EditionError(f"{stem}: the Spanish catalog is not ready, so the Spanish notebook is not "
                               "built:\n  " + "\n  ".join(problems))
        nb = copy.deepcopy(self.english(stem))
        spanish = translations(self.catalog(stem))
        notes = comment_translations(self.catalog(stem))
        setup = _setup_cell(nb)
        for cell in nb.cells:
            if cell.cell_type == "markdown" and cell.source.strip():
                cell.source = relink(spanish[cell.id], lambda target: self._target(stem, target))
            elif cell.cell_type == "code" and cell.id in notes:     # the code as in English, its comments in Spanish
                cell.source = with_comments(cell.source, notes[cell.id])
        setup.source = setup.source.replace(SET_LANGUAGE_EN, SET_LANGUAGE_ES)
        return nb

    def build(self, stem: str, execute: bool = True) -> Path:
        """Write ``notebooks/es/<stem>.ipynb`` and (unless ``execute`` is False) execute it in place."""
        nb = self.spanish(stem)
        path = self.spanish_path(stem)
        path.parent.mkdir(parents=True, exist_ok=True)
        nbformat.write(nb, path)
        if stem in SHIPPED:
            self.shipped_path(stem).parent.mkdir(parents=True, exist_ok=True)
            self.shipped_path(stem).write_text(shipped_texts(self.catalog(stem)), encoding="utf-8")
        if execute:
            from .execute import execute_notebook
            execute_notebook(path)
        return path

    def check(self, stem: str) -> list[str]:
        """Everything wrong with the notebook's Spanish edition ([] when it is complete and up to date)."""
        problems = self.problems(stem)
        stored = self.spanish_path(stem)
        if problems:
            return problems
        if not stored.exists():
            return [f"{stored} is missing: run `python -m tools.edition build {stem}`"]
        return self._stored_problems(stem, nbformat.read(stored, as_version=4)) + self._shipped_problems(stem)

    # --- the course home -----------------------------------------------------------

    def home_path(self) -> Path:
        return self.english_dir / f"{HOME}.ipynb"

    def home(self):
        """The course home as build writes it: both editions, Spanish links only to built notebooks."""
        return home_notebook(self, NOTEBOOKS, {stem for stem in NOTEBOOKS if self.spanish_path(stem).exists()})

    def write_home(self) -> Path:
        nbformat.write(self.home(), self.home_path())
        return self.home_path()

    def home_problems(self) -> list[str]:
        stored = nbformat.read(self.home_path(), as_version=4) if self.home_path().exists() else None
        home = self.home()
        if stored is None or [c.source for c in stored.cells] != [c.source for c in home.cells] \
                or stored.metadata != home.metadata:
            return [f"{self.home_path()} is missing or not what build makes (it lists the built Spanish "
                    "notebooks): run `python -m tools.edition build`"]
        return []

    # --- what the checks compare ----------------------------------------------------

    def _setup_problems(self, stem: str) -> list[str]:
        setup = _setup_cell(self.english(stem))
        if setup is None or setup.source.count(SET_LANGUAGE_EN) != 1:
            return [f"the English set-up cell (the first code cell) must contain the line {SET_LANGUAGE_EN} "
                    "once, right after `import dhlab` (the Spanish edition says \"es\" there)"]
        return []

    def _shipped_problems(self, stem: str) -> list[str]:
        """Whether the translations the package ships are what the catalog makes ([] when they are)."""
        path = self.shipped_path(stem)
        if stem not in SHIPPED or (path.exists() and path.read_text(encoding="utf-8") == shipped_texts(
                self.catalog(stem))):
            return []
        return [f"{path} is missing or not what the catalog makes (dhlab-assign --language es reads it): "
                f"run `python -m tools.edition build {stem}`"]

    def _stored_problems(self, stem: str, stored) -> list[str]:
        """How the stored Spanish notebook differs from the English one and from what build makes."""
        english, expected = self.english(stem), self.spanish(stem)
        where = f"notebooks/es/{stem}.ipynb"
        if [c.id for c in stored.cells] != [c.id for c in english.cells]:
            return [f"{where}: its cell ids differ from the English notebook's (rebuild it)"]
        problems = []
        for mine, want, en in zip(stored.cells, expected.cells, english.cells):
            where_cell = f"{where}, cell {mine.id}"
            if mine.cell_type != en.cell_type:
                problems.append(f"{where_cell}: a {mine.cell_type} cell, in English a {en.cell_type} cell")
            elif mine.cell_type == "code" and mine.source != want.source:
                problems.append(f"{where_cell}: its code differs from the English notebook's (or its "
                                "comments from the catalog's translations: rebuild it)")
            elif mine.source != want.source:
                problems.append(f"{where_cell}: its text is not what build makes of the catalog (rebuild it)")
            elif _lasting(mine.metadata) != _lasting(want.metadata) or mine.get("attachments") != want.get(
                    "attachments"):
                problems.append(f"{where_cell}: its metadata differ from the English cell's")
        if _lasting(stored.metadata) != _lasting(expected.metadata):
            problems.append(f"{where}: its notebook metadata differ from the English notebook's (rebuild it)")
        return problems

    def in_edition(self, stem: str) -> bool:
        """Whether the Spanish notebooks link to the Spanish ``stem`` (else to the English one): it is
        built. (Not "its catalog is complete": one English sentence changed in ``stem`` would then
        move the links of every notebook that cites it.)"""
        return self.spanish_path(stem).exists()

    def _target(self, stem: str, target: str) -> str:
        """A link target of notebook ``stem`` as it must read from ``notebooks/es/``."""
        if URL.match(target) or target.startswith("/"):
            return target
        path, hash_, fragment = target.partition("#")
        if not path:                                   # a heading of this notebook
            return "#" + self._spanish_anchor(stem, fragment)
        linked = path[:-len(".ipynb")]
        if NOTEBOOK_LINK.fullmatch(path) and linked in NOTEBOOKS and self.in_edition(linked):
            return path + (hash_ + self._spanish_anchor(linked, fragment) if hash_ else "")
        return "../" + target                          # images, files, notebooks not yet in Spanish

    def _spanish_anchor(self, stem: str, english_anchor: str) -> str:
        """The anchor of the Spanish heading that translates the English heading ``english_anchor``
        (the same heading, by position, in the same cell); unchanged if there is none."""
        if ("anchors", stem) not in self._cache:
            spanish = translations(self.catalog(stem)) if self.catalog(stem) else {}
            table = {}
            for cell_id, english in markdown_cells(self.english(stem)):
                es = headings(spanish.get(cell_id, ""))
                for i, (_, text) in enumerate(headings(english)):
                    if i < len(es):
                        table.setdefault(anchor(text), anchor(es[i][1]))
            self._cache["anchors", stem] = table
        return self._cache["anchors", stem].get(english_anchor, english_anchor)


def _lasting(metadata) -> dict:
    """Metadata without what each execution rewrites (timings, widget state, the kernel's name)."""
    return {key: value for key, value in metadata.items() if key not in TRANSIENT}


def _setup_cell(nb):
    """The first code cell (imports and ``dhlab.set_language``), or None."""
    return next((cell for cell in nb.cells if cell.cell_type == "code"), None)


# --- the command line ---------------------------------------------------------------

def _stems(names) -> list[str]:
    """Notebook stems from arguments such as ``notebooks/05_dh_convention.ipynb``, ``05_dh_convention``, ``05``."""
    if not names:
        return list(NOTEBOOKS)
    stems = []
    for name in names:
        stem = Path(name).stem
        matches = [s for s in NOTEBOOKS if s == stem or s.startswith(stem + "_") or s.split("_")[0] == stem]
        if not matches:
            raise EditionError(f"{name!r} is not a notebook of the Spanish edition: "
                               f"choose from {', '.join(NOTEBOOKS)}.")
        stems += matches
    return stems


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("command", choices=["extract", "build", "check"])
    parser.add_argument("notebooks", nargs="*", help="notebooks (path, stem or number); default: all")
    parser.add_argument("--prune", action="store_true", help="extract: drop obsolete entries")
    parser.add_argument("--no-execute", action="store_true", help="build: do not execute the notebooks")
    parser.add_argument("--if-stale", action="store_true",
                        help="build: only the notebooks whose stored Spanish edition is missing or stale")
    args = parser.parse_args(argv)
    edition = Edition()
    try:
        stems = _stems(args.notebooks)
        if args.command == "extract":
            # by default the catalogs that exist; naming a notebook starts its catalog
            for stem in stems if args.notebooks else [s for s in stems if edition.catalog_path(s).exists()]:
                print(edition.extract(stem, prune=args.prune))
            return 0
        if args.command == "build":
            return _build(edition, stems, explicit=bool(args.notebooks), execute=not args.no_execute,
                          if_stale=args.if_stale)
        return _check(edition, stems)
    except EditionError as error:
        print(error, file=sys.stderr)
        return 1


def _build(edition: Edition, stems, explicit: bool, execute: bool, if_stale: bool = False) -> int:
    """Build the named notebooks (an error if one cannot be), or every one whose catalog is ready;
    ``if_stale``: only those whose stored Spanish notebook is missing or differs."""
    ready = []
    for stem in stems:
        problems = edition.problems(stem)
        if problems and not explicit:
            print(f"{stem}: not built ({len(problems)} problems; `check {stem}` lists them)")
        elif not (if_stale and not edition.check(stem)):
            ready.append(stem)
    failed, created = [], []
    for stem in ready:              # every new file first: the links between them depend on which exist
        if not edition.spanish_path(stem).exists():
            try:
                created.append(edition.build(stem, execute=False))
            except EditionError as error:
                print(error, file=sys.stderr)
                failed.append(stem)
    if created:                     # a notebook built for the first time changes the links to it
        ready += [stem for stem in NOTEBOOKS if stem not in ready and edition.spanish_path(stem).exists()
                  and not edition.problems(stem) and edition.check(stem)]
    for stem in ready:
        if stem not in failed:
            try:
                print(f"building {edition.build(stem, execute=execute)}", flush=True)
            except EditionError as error:
                print(error, file=sys.stderr)
                failed.append(stem)
    print(f"writing {edition.write_home()}")
    return 1 if failed else 0


def _check(edition: Edition, stems) -> int:
    """Report every problem; fail on those of a notebook listed in EDITION_NOTEBOOKS, built, or whose
    catalog is complete (then it must be built); a notebook still being translated is only reported."""
    failed = False
    for stem in stems:
        problems = edition.check(stem)
        # required: listed, built, or ready to be built (its catalog complete)
        required = stem in EDITION_NOTEBOOKS or edition.spanish_path(stem).exists() or not edition.problems(stem)
        if not problems:
            print(f"{stem}: Spanish edition complete and up to date")
            continue
        failed |= required
        label = "FAILS" if required else "not in the edition yet"
        print(f"{stem}: {label} ({len(problems)} problems)")
        for line in problems[:40]:
            print("   ", line)
        if len(problems) > 40:
            print(f"    ... and {len(problems) - 40} more")
    for line in edition.home_problems():
        print(line)
        failed = True
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
