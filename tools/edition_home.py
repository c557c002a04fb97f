"""The course home, ``notebooks/index.ipynb``: where ``make lab`` opens (in the student's copy,
``my-notebooks/index.ipynb``: :mod:`tools.student_copy`), and either edition starts.

It is generated (markdown only) from the notebooks themselves: each notebook's title, linked in
English, and in Spanish where its Spanish edition is built, so the home never links to a
notebook that does not exist. ``python -m tools.edition build`` rewrites it and
``check`` fails when the stored home differs from what it would write.
"""
from __future__ import annotations

import re

import nbformat

from .edition_catalog import markdown_cells, translations
from .edition_text import headings

__all__ = ["HOME", "home_notebook"]

HOME = "index"
ASSIGNMENT = "08_puma_assignment"     # in the edition too; dhlab-assign releases it per student

INTRO = """\
# dhlab · Robot kinematics · Cinemática de robots

Homogeneous matrices and the Denavit–Hartenberg convention, from five Spanish lecture documents.
*Matrices homogéneas y la convención de Denavit–Hartenberg, a partir de cinco documentos de clase en español.*

**Your work is yours.** On your machine, `make lab` opens your own copy of the course, the folder `my-notebooks/` of the
repository: your answers stay there, and the next `make lab` only adds the course's new notebooks, never
changing yours (`git pull` brings them into `notebooks/`, the course, which you do not edit).
*Su trabajo es suyo: en su equipo, `make lab` abre su propia copia del curso, la carpeta `my-notebooks/`; sus respuestas
se quedan ahí, y el siguiente `make lab` solo añade los cuadernos nuevos del curso, sin cambiar los suyos.*"""

ENGLISH = """\
## English

Start with notebook 1 and go in order. Each notebook runs from top to bottom (**Run › Run All Cells**);
the checkers answer in English. The Spanish notebooks are the same course, generated from these: the same
code, the prose translated."""

SPANISH = """\
## Español

Empiece por el cuaderno 1 y siga en orden. Cada cuaderno se ejecuta de principio a fin (**Run › Run All
Cells**, o **Ejecutar › Ejecutar todas las celdas** con la interfaz en español); los verificadores responden
en español, porque cada cuaderno en español empieza con `dhlab.set_language("es")`.

**La interfaz de JupyterLab en español** (menús y botones): en el menú **Settings › Language** elija
**Español (España)**; JupyterLab se recarga. Para volver: **Configuración › Idioma › English**. También puede
abrir el curso con la interfaz ya en español: `make lab-es`.

Un cuaderno marcado *en preparación* todavía no tiene traducción completa: puede seguirlo en inglés."""


def _title(source: str) -> str:
    """The text of a markdown cell's first heading, without its number ("5. ", "1 · ")."""
    found = headings(source)
    return re.sub(r"^\d+\s*[.·]\s*", "", found[0][1]) if found else ""


def home_notebook(edition, notebooks, built) -> nbformat.NotebookNode:
    """The home notebook: a row for each of ``notebooks`` (stems); ``built`` is the set of notebooks
    whose Spanish edition exists."""
    rows = ["| | English | Español |", "|---|---|---|"]
    for stem in sorted({*notebooks, ASSIGNMENT}):
        if not edition.english_path(stem).exists():
            continue
        english = edition.english(stem)
        first_id, first = markdown_cells(english)[0]
        row = f"| {stem[:2].lstrip('0')} | [{_title(first)}]({stem}.ipynb) | "
        if stem in built:
            row += f"[{_title(translations(edition.catalog(stem))[first_id])}](es/{stem}.ipynb) |"
        else:
            row += "*en preparación* |"
        rows.append(row)
    cells = [nbformat.v4.new_markdown_cell(text) for text in (INTRO, "\n".join(rows), ENGLISH, SPANISH)]
    for cell, cell_id in zip(cells, ("home-intro", "home-notebooks", "home-en", "home-es")):
        cell.id = cell_id
    nb = nbformat.v4.new_notebook(cells=cells)
    # the kernel's language_info in full, as in the executed notebooks: JupyterLab writes the kernel's
    # into a notebook it opens, and saves it 2 minutes later if it differs (with only its name, the
    # course home was rewritten by merely opening it)
    first = next((edition.english(stem) for stem in sorted(notebooks) if edition.english_path(stem).exists()), None)
    nb.metadata = {"kernelspec": {"name": "python3", "display_name": "Python 3 (dhlab)", "language": "python"},
                   "language_info": dict(first.metadata.get("language_info", {})) if first else {}}
    nb.metadata.language_info.setdefault("name", "python")
    return nb
