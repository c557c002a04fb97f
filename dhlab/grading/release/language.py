"""The released notebook in the student's language: English or Spanish, one roster, one run.

``dhlab-assign release ROSTER -o DIR --language es`` releases every notebook in Spanish; a roster
column ``language`` (or ``idioma``) with ``en``/``es`` per student overrides the option, so a class
may mix; without either, the ``DHLAB_LANGUAGE`` environment variable, else English.

A Spanish notebook is the English one, released for the student as always
(:func:`dhlab.assignment.notebook_cells.release_notebook`), with its markdown replaced cell by cell
by the Spanish edition's translation (:data:`SPANISH_TEXTS`, keyed by cell id: the translations of
the catalog ``notebooks/es/`` is built from, written into the package by the repository's
``python -m tools.edition build``). What the
variant changes in the English text (the robot's name, its number of joints, T1…Tn, "Your
robot") is changed the same way in the Spanish text (:func:`own_robot_text_es`); the "Your
robot" section itself is written by :func:`~dhlab.assignment.notebook_cells.release_notebook`, run
in the student's language (its sentences are in the course's catalog). The code cells stay the
English ones but for their comments — the template's translated like the markdown
(:func:`spanish_comments`), the answer cells' instructions written by ``release_notebook`` in the
student's language — and the set-up cell's ``dhlab.set_language("es")``; the language is also
recorded in ``metadata["dhlab"]["language"]``, where the grader reads it (:func:`notebook_language`).
"""
from __future__ import annotations

import contextlib
import json
import re
from pathlib import Path

from ...assignment import variants as V
from ...assignment.family import spec
from ...assignment.notebook_cells import apply_rules, formula_rules
from ...i18n import LANGUAGES, _, checked_language, set_language, speaking
from .comments import with_comments

__all__ = ["LANGUAGE_COLUMNS", "roster_languages", "in_language", "spanish_texts",
           "spanish_comments", "in_spanish", "mark_language", "notebook_language", "raw_notebook_language",
           "own_robot_text_es", "SPANISH_TEXTS"]

LANGUAGE_COLUMNS = ("language", "idioma", "lang")
STEM = "08_puma_assignment"
# the Spanish edition's text of the assignment, cell id -> {"en": English source, "es": its translation}
SPANISH_TEXTS = Path(__file__).resolve().parents[1] / "template" / f"{STEM}.es.json"     # dhlab/grading/template/
# release_notebook's "Your robot" cell, when the template has no "## The robot"
INTRO_CELL_ID = "dhlab-your-robot-intro"
SET_LANGUAGE = re.compile(r'dhlab\.set_language\(\s*["\'](\w+)["\']\s*\)')


def roster_languages(rows: list, ids: list, default: str, roster_name: str = "roster") -> dict:
    """student id -> language: the roster's language column where it has a value, else ``default``.
    ``rows``: the roster's rows (header first), ``ids`` the ids in the same order."""
    header = [h.strip().lower() for h in rows[0]]
    column = next((header.index(name) for name in LANGUAGE_COLUMNS if name in header), None)
    languages = {}
    for line, (sid, row) in enumerate(zip(ids, rows[1:]), start=2):
        value = row[column].strip() if column is not None and column < len(row) else ""
        where = _("roster {name}, row {line}, column {column!r}").format(
            name=roster_name, line=line, column=rows[0][column].strip()) if value else ""
        languages[sid] = checked_language(value, where) if value else default
    return languages


@contextlib.contextmanager
def in_language(language: str):
    """Messages in ``language`` inside the block, as before after it."""
    previous = set_language(language)
    try:
        yield
    finally:
        set_language(previous)


# --- the Spanish text -------------------------------------------------------------------------------

def _shipped(part: str) -> dict:
    """One part (``cells`` or ``comments``) of the Spanish edition's texts, {} when unreadable."""
    try:
        found = json.loads(SPANISH_TEXTS.read_text(encoding="utf-8")).get(part, {})
    except (OSError, ValueError, AttributeError):
        return {}
    return found if isinstance(found, dict) else {}


def spanish_comments(template: dict) -> dict:
    """code cell id -> {English comment: its Spanish} for each code cell of ``template`` the
    catalog knows (by id: a teacher's own cell keeps its comments, unless one is word for word
    the course's)."""
    known = _shipped("comments")
    return {cell["id"]: known[cell["id"]] for cell in template.get("cells", [])
            if cell.get("cell_type") == "code" and cell.get("id") in known}


def spanish_texts(template: dict) -> dict:
    """cell id -> the Spanish text of each markdown cell of the English ``template`` that the
    catalog translates (a cell it does not know, or whose English differs, e.g. of a teacher's own
    template, is left out)."""
    known = _shipped("cells")
    found = {}
    for cell in template.get("cells", []):
        entry = known.get(cell.get("id")) if cell.get("cell_type") == "markdown" else None
        if entry is not None and entry["en"] == _source(cell):
            found[cell["id"]] = entry["es"]
    return found


_WORDS_ES = {1: "una", 2: "dos", 3: "tres", 4: "cuatro", 5: "cinco", 6: "seis", 7: "siete", 8: "ocho"}


def _name_es(name: str) -> str:
    with speaking("es"):                 # the catalog's word, whatever the teacher's language
        return V.shown_name(name)


def own_robot_text_es(text: str, robot, name: str) -> str:
    """The Spanish text about the PUMA 560 said of the student's robot (the Spanish twin of
    the English rules :func:`dhlab.assignment.notebook_cells.release_notebook` applies to that text: each rule
    changes only what it finds)."""
    n, name = robot.n, _name_es(name)
    kinds = ", ".join(f"{robot.kinds.count(k)} {w}" for k, w in (("R", "rotacionales"), ("P", "prismáticas"))
                      if robot.kinds.count(k))
    rules = [
        (r"un brazo real de seis articulaciones", f"un brazo real de {_WORDS_ES.get(n, n)} articulaciones"),
        (r"del robot PUMA\*\*", f"de un robot**, aquí su propio {name}"),
        (r"El PUMA 560 tiene \d+ articulaciones rotacionales y \d+ eslabones",
         f"Su {name} tiene {n} articulaciones ({kinds}) y {n + 1} eslabones"),
        (r"\bcinco palabras\b", f"{_WORDS_ES.get(n - 1, n - 1)} palabras"),
        (r"\$z_6\$ a lo largo de \$z_5\$, \$x_6\$", f"$z_{n}$ a lo largo de $z_{{{n - 1}}}$, $x_{n}$"),
        (r"\bdel PUMA( 560)?\b", "de su robot"),
        (r"\bel PUMA( 560)?\b", "su robot"),
        (r"\bEl PUMA( 560)?\b", f"Su {name}"),
        (r"\bPUMA 560\b", name),
    ]
    return apply_rules(text, rules + formula_rules(n))


def in_spanish(released: dict, template: dict, record: dict, notes: set) -> dict:
    """The English released notebook ``released`` (made from ``template`` for ``record``) in
    Spanish: each markdown cell from the catalog, changed as the variant changed the English."""
    robot = V.robot_of_variant(V.Variant.from_dict(record["variant"]))
    name = spec(record["variant"]["family"]).name
    spanish = spanish_texts(template)
    if not spanish:
        notes.add(_("the Spanish catalog of the assignment has no entry for this template: "
                    "the notebooks' text stays in English"))
    english_cells = {c.get("id"): _source(c) for c in template.get("cells", [])}
    comments = spanish_comments(template)
    for k, cell in enumerate(released["cells"]):
        if cell.get("cell_type") == "code" and cell.get("id") in comments:
            cell["source"] = _lines(with_comments(_source(cell), comments[cell["id"]]))
        if cell.get("cell_type") != "markdown":
            continue
        text = english = _source(cell)
        if cell.get("id") == INTRO_CELL_ID or (english_cells.get(cell.get("id"), "").startswith("## The robot")
                                                and text != english_cells[cell["id"]]):
            pass            # "Your robot": written for this student by release_notebook, in the course's catalog
        elif cell.get("id") in spanish:
            text = own_robot_text_es(spanish[cell["id"]], robot, name)
            if k == 0 and text.startswith("# ") and english != english_cells.get(cell["id"]):   # the title
                first, _nl, rest = text.partition("\n")
                text = f"# {first[2:].split('·')[0].strip()} · La tarea DH: su propio {_name_es(name)}\n{rest}"
        elif text.strip():
            notes.add(_("cell {id}: not in the Spanish catalog, left in English").format(id=cell.get("id")))
        cell["source"] = _lines(text)
    return released


def mark_language(nb: dict, language: str) -> dict:
    """Record ``language`` in the notebook's metadata and say it in its set-up cell."""
    setup = next((c for c in nb.get("cells", []) if c.get("cell_type") == "code"), None)
    if setup is not None:
        setup["source"] = _lines(SET_LANGUAGE.sub(f'dhlab.set_language("{language}")', _source(setup), count=1))
    meta = nb.setdefault("metadata", {})
    meta[V.METADATA_KEY] = {**meta.get(V.METADATA_KEY, {}), "language": language}   # a copy: not the teacher's record
    return nb


def notebook_language(nb) -> str | None:
    """The language a submitted notebook was written in: its metadata's, else the one its code
    sets with ``dhlab.set_language``; None when it says neither (or not a course language)."""
    if not isinstance(nb, dict):
        return None
    meta = nb.get("metadata")
    record = meta.get(V.METADATA_KEY) if isinstance(meta, dict) else None
    said = record.get("language") if isinstance(record, dict) else None
    if isinstance(said, str) and said in LANGUAGES:
        return said
    cells = nb.get("cells")
    for cell in cells if isinstance(cells, list) else []:       # a submission may hold anything: read with care
        source = cell.get("source") if isinstance(cell, dict) and cell.get("cell_type") == "code" else None
        if isinstance(source, list):
            source = "".join(line for line in source if isinstance(line, str))
        found = SET_LANGUAGE.search(source) if isinstance(source, str) else None
        if found and found[1] in LANGUAGES:
            return found[1]
    return None


def raw_notebook_language(raw: bytes) -> str | None:
    """:func:`notebook_language` of a notebook file's bytes (None when it is not JSON)."""
    try:
        return notebook_language(json.loads(raw.decode("utf-8")))
    except (UnicodeDecodeError, ValueError, RecursionError):
        return None


def _source(cell) -> str:
    source = cell.get("source", "")
    return "".join(source) if isinstance(source, list) else source


def _lines(text: str) -> list:
    parts = text.split("\n")
    return [p + "\n" for p in parts[:-1]] + ([parts[-1]] if parts[-1] else [])
