"""One gettext catalog per notebook: the Spanish text of each markdown cell and of each comment of
its code cells, keyed by cell id.

``tools/locale/es/notebooks/<stem>.po`` holds one entry per markdown cell of the English
notebook: ``msgctxt`` is the cell id, ``msgid`` the cell's whole English source, ``msgstr``
its Spanish translation. A code cell's comments are entries too, one per comment (``msgctxt``
the code cell's id, ``msgid`` the comment from its ``#`` to the end of its line, an extracted
comment ``#. a comment of a code cell`` above it): the code stays the English code, its comments
are read in Spanish. :func:`extract` keeps the catalog in step with the notebook by
gettext's own rules (Babel's ``Catalog.update``): a new cell gets an empty entry; a cell
whose English changed keeps its old translation marked *fuzzy*, with the previous English
beside it (``#| msgid``) so the translator sees what changed; a removed cell's entry becomes
obsolete (``#~``). :func:`catalog_problems` lists everything that keeps a catalog from
being used: an untranslated, fuzzy or obsolete entry, or a translation that lost or
changed a placeholder or a heading level.
"""
from __future__ import annotations

import io
import json
from pathlib import Path

from babel.messages.catalog import Catalog
from babel.messages.pofile import denormalize, normalize, read_po

from dhlab.errors import DHLabError

from .edition_text import comments, headings, placeholder_difference
from .i18n_catalog import po_text

HEADER_COMMENT = """\
# The Spanish edition of a dhlab notebook: one entry per markdown cell, msgctxt = the cell id,
# msgid = the English source, msgstr = its Spanish translation; code cells are here only by their
# comments (one entry per comment, msgid from its '#' to the end of its line: translate the words,
# keep the '#' and the layout), their code never.
# Update after changing the English: python -m tools.edition extract <notebook>"""

# Babel guesses these from a "%" or "{}" in the text: markdown is not a format string
FORMAT_FLAGS = {"python-format", "python-brace-format"}

COMMENT_NOTE = "a comment of a code cell"

__all__ = ["markdown_cells", "code_comments", "template", "comment_translations", "read_catalog", "write_catalog",
           "extract",
           "translations", "shipped_texts", "catalog_problems"]


def markdown_cells(nb) -> list[tuple[str, str]]:
    """(cell id, source) of every markdown cell with text, in order."""
    cells = [cell for cell in nb.cells if cell.cell_type == "markdown" and cell.source.strip()]
    for cell in cells:
        if not cell.get("id"):
            raise DHLabError(f"a markdown cell has no id (it starts {cell.source[:40]!r}): the catalog keys on "
                             "cell ids; save the notebook with nbformat 4.5 or newer so every cell gets one.")
    return [(cell.id, cell.source) for cell in cells]


def code_comments(nb) -> list[tuple[str, str]]:
    """(cell id, comment) of every comment of the code cells, in order (a comment repeated in one
    cell once)."""
    found = []
    for cell in nb.cells:
        if cell.cell_type == "code":
            for text in dict.fromkeys(comments(cell.source)):
                if not cell.get("id"):
                    raise DHLabError(f"a code cell has no id (it starts {cell.source[:40]!r}): save the "
                                     "notebook with nbformat 4.5 or newer so every cell gets one.")
                found.append((cell.id, text))
    return found


def template(nb) -> Catalog:
    """The catalog of the English notebook ``nb`` with every translation empty."""
    catalog = Catalog(locale="es", project="dhlab", charset="utf-8", fuzzy=False,
                      header_comment=HEADER_COMMENT, language_team="dhlab Spanish edition",
                      last_translator="dhlab course")
    for cell_id, source in markdown_cells(nb):
        message = catalog.add(source, string="", context=cell_id)
        message.flags -= FORMAT_FLAGS
    for cell_id, text in code_comments(nb):
        message = catalog.add(text, string="", context=cell_id, auto_comments=[COMMENT_NOTE])
        message.flags -= FORMAT_FLAGS
    return catalog


def read_catalog(path) -> Catalog:
    """The catalog at ``path``, with the previous English of each fuzzy entry (``#| msgid``)."""
    text = Path(path).read_text(encoding="utf-8")
    previous, kept, block = {}, [], []
    for line in text.splitlines(keepends=True):
        if line.startswith("#|"):                 # Babel's reader would take these for comments
            block.append(line[2:].strip())
            continue
        if line.startswith("msgctxt ") and block:
            previous[denormalize(line[len("msgctxt "):])] = _previous_msgid(block)
        if not line.startswith("#"):
            block = []
        kept.append(line)
    catalog = read_po(io.StringIO("".join(kept)), locale="es")
    for message in catalog:
        message.flags -= FORMAT_FLAGS             # Babel adds them again when it reads
        if message.context in previous:
            message.previous_id = [previous[message.context]]
    return catalog


def _previous_msgid(block: list[str]) -> str:
    lines = [line for line in block if not line.startswith("msgctxt")]
    if not lines or not lines[0].startswith("msgid "):
        return ""
    return denormalize("\n".join([lines[0][len("msgid "):], *lines[1:]]))


def write_catalog(catalog: Catalog, path) -> None:
    """Write ``catalog`` as a PO file: no line wrapping; a fuzzy entry's previous English is kept
    above it in gettext's form (``#| msgid``), which Babel's writer would squeeze onto one line."""
    text = po_text(catalog, width=0, include_previous=False)
    for message in catalog:
        if message.id and message.fuzzy and message.previous_id and message.context:
            head = f"\nmsgctxt {normalize(message.context, width=0)}\n"
            old = normalize(message.previous_id[0], prefix="#| ", width=0)
            text = text.replace(head, f"\n#| msgid {old}{head}", 1)
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    Path(path).write_text(text, encoding="utf-8")


def extract(nb, path, prune: bool = False) -> Catalog:
    """Create or update the catalog at ``path`` from the English notebook ``nb``, and write it.

    ``prune`` drops the obsolete entries (cells no longer in the notebook)."""
    new = template(nb)
    if not Path(path).exists():
        write_catalog(new, path)
        return new
    catalog = read_catalog(path)
    previous = {m.context: m.previous_id for m in catalog if m.id and m.fuzzy and m.previous_id}
    # Babel would guess a changed cell's old entry by textual similarity, across cells; the
    # cell id is the real key, so fuzzy matching goes by cell id instead (just below).
    catalog.update(new, no_fuzzy_matching=True, update_creation_date=False)
    _match_changed_cells(catalog)
    for message in catalog:
        message.flags -= FORMAT_FLAGS
        if message.fuzzy and not message.previous_id:      # still fuzzy since an earlier extract
            message.previous_id = previous.get(message.context, [])
    if prune:
        catalog.obsolete.clear()
    write_catalog(catalog, path)
    return catalog


def _match_changed_cells(catalog: Catalog) -> None:
    """An untranslated entry whose cell id has an obsolete translation: the cell's English
    changed. It gets that translation back, marked fuzzy, with the old English as previous msgid."""
    old_by_cell = {m.context: (key, m) for key, m in catalog.obsolete.items() if m.context and m.string}
    for message in catalog:
        if message.id and not message.string and message.context in old_by_cell:
            key, old = old_by_cell.pop(message.context)
            message.string = old.string
            message.previous_id = [old.id]
            message.flags.add("fuzzy")
            del catalog.obsolete[key]


def translations(catalog: Catalog) -> dict[str, str]:
    """markdown cell id -> its Spanish text, for every translated entry (fuzzy ones too: their text is
    still Spanish); the comments of code cells are :func:`comment_translations`."""
    found = {}
    for message in list(catalog) + list(catalog.obsolete.values()):
        if message.id and message.string and message.context not in found \
                and COMMENT_NOTE not in message.auto_comments:
            found[message.context] = message.string
    return found


def comment_translations(catalog: Catalog) -> dict[str, dict[str, str]]:
    """code cell id -> {English comment: its Spanish} for every translated comment (fuzzy ones too)."""
    found = {}
    for message in list(catalog) + list(catalog.obsolete.values()):
        if message.id and message.string and COMMENT_NOTE in message.auto_comments:
            found.setdefault(message.context, {}).setdefault(message.id, message.string)
    return found


def shipped_texts(catalog: Catalog) -> str:
    """The catalog as the package reads it at run time (no Babel there): JSON, cell id -> its English
    (``en``) and Spanish (``es``) text, for every translated entry that is not fuzzy (a fuzzy one
    translates an English text that changed)."""
    done = [m for m in catalog if m.id and m.string and not m.fuzzy]
    cells = {m.context: {"en": m.id, "es": m.string} for m in done if COMMENT_NOTE not in m.auto_comments}
    notes = {}
    for m in done:
        if COMMENT_NOTE in m.auto_comments:
            notes.setdefault(m.context, {})[m.id] = m.string
    return json.dumps({"about": "Generated by python -m tools.edition build from its catalog: do not edit.",
                       "cells": cells, "comments": notes}, indent=1, ensure_ascii=False) + "\n"


def catalog_problems(nb, catalog: Catalog) -> list[str]:
    """One line per reason the catalog cannot make the Spanish notebook yet ([] when it can)."""
    problems = []
    entries = [(cell_id, english, False) for cell_id, english in markdown_cells(nb)]
    entries += [(cell_id, text, True) for cell_id, text in code_comments(nb)]
    current = set()
    by_cell = {}
    for m in catalog:
        if m.id:
            by_cell.setdefault(m.context, []).append(m)
    for cell_id, english, is_comment in entries:
        message = catalog.get(english, context=cell_id)
        what = f"cell {cell_id}, comment {english!r}" if is_comment else f"cell {cell_id}"
        if message is None:
            if cell_id in by_cell:
                problems.append(f"{what}: its English text changed since the catalog was updated "
                                "(run extract: the old translation becomes fuzzy; revise it)")
                current.update((m.id, cell_id) for m in by_cell[cell_id])
            else:
                problems.append(f"{what}: not in the catalog (run extract, then translate it)")
            continue
        current.add((english, cell_id))
        if not message.string:
            problems.append(f"{what}: untranslated")
        elif message.fuzzy:
            problems.append(f"{what}: fuzzy (the English changed: revise the translation, "
                            "then remove the '#, fuzzy' line and the '#|' lines)")
        elif is_comment:
            if not message.string.startswith("#") or "\n" in message.string:
                problems.append(f"{what}: its translation must be one line that starts with '#'")
        else:
            problems += _translation_problems(cell_id, english, message.string)
    for message in catalog:
        if message.id and (message.id, message.context) not in current:
            problems.append(f"cell {message.context}: the catalog has an entry for a cell the English "
                            "notebook does not have (run extract)")
    problems += [f"cell {m.context}: obsolete entry (the cell left the English notebook; "
                 "run extract --prune)" for m in catalog.obsolete.values()]
    return problems


def _translation_problems(cell_id: str, english: str, spanish: str) -> list[str]:
    problems = []
    difference = placeholder_difference(english, spanish)
    if difference:
        problems.append(f"cell {cell_id}: the placeholders differ (maths, code, links, images and HTML tags "
                        f"stay byte-identical): {difference}")
    levels_en = [level for level, _ in headings(english)]
    levels_es = [level for level, _ in headings(spanish)]
    if levels_en != levels_es:
        problems.append(f"cell {cell_id}: heading levels {levels_en} in English but {levels_es} in Spanish")
    return problems
