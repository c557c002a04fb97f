"""Keeping the message catalogs up to date: ``python -m tools.i18n_catalog {extract,update,compile,check}``.

The English messages live in the code, marked ``_("…")`` (translated where shown) or ``N_("…")``
(a constant, translated later with ``_``). From them:

* ``extract``  writes a template ``dhlab/locale/<domain>.pot`` per domain (every marked message);
* ``update``   merges each template into ``dhlab/locale/<lang>/LC_MESSAGES/<domain>.po``: a new message
  comes in untranslated, a changed one *fuzzy* (its old translation kept as a suggestion), a removed
  one obsolete;
* ``compile``  writes each ``<domain>.mo`` (what :mod:`dhlab.i18n` reads) from its ``.po``;
* ``check``    lists every problem (a message of the code missing from a catalog, an entry untranslated,
  fuzzy or obsolete, placeholders that differ, a ``.mo`` older than its ``.po``) and exits 1 if any.

Two domains, two audiences: ``dhlab`` (the lessons, panels, exercises and the assignment's checks: what a
student reads while working) and ``dhlab_grading`` (the grader's and the release tool's messages:
feedback files, statuses, the teacher's command line: :data:`DOMAINS` says which modules).

A contributor who changes an English message runs ``extract`` and ``update``, translates the entries
the ``.po`` marks (untranslated or ``#, fuzzy``), then ``compile`` and ``check``.

The lessons' notebooks mark their printed words the same way (``print(_("same table:"), ok)``):
the ``dhlab`` domain also holds every ``_("…")`` of the English notebooks' code cells
(:data:`NOTEBOOKS`; the Spanish notebooks share that code), located as ``notebooks/<nb>.ipynb#<cell id>:<line>``.

Babel (a development dependency) does the work; :mod:`dhlab.i18n` itself needs only the standard library.
"""
from __future__ import annotations

import io
import json
import re
import sys
from pathlib import Path

from dhlab.i18n import LANGUAGES, LOCALE_DIR

ROOT = Path(__file__).resolve().parents[1]     # the repository (a maintainer's tool: it works there)
PACKAGE = ROOT / "dhlab"
KEYWORDS = {"_": None, "N_": None}
# domain -> the modules whose messages it holds (a module belongs to the first domain that names it;
# "**/*.py" takes the rest: a message marked anywhere must be in a catalog)
# (the assignment's fair checks, reference robot and variants came from grading/, the DH frames' rules are
# dh_frames/, once assign/: their messages stay in the grader's domain)
DOMAINS = {"dhlab_grading": ["grading/**/*.py", "assign/**/*.py", "dh_frames/**/*.py",
                             "assignment/encode.py", "assignment/answers.py", "assignment/checks/**/*.py",
                             "assignment/reference.py", "assignment/valid_frames.py", "assignment/variants.py"],
           "dhlab": ["**/*.py"]}
DOMAIN = "dhlab"                     # the default domain of the functions below
# the English lesson notebooks whose code cells hold messages of the dhlab domain (not the course home, not
# 08: the assignment's code is the grader's; not notebooks/es/: the same code)
NOTEBOOK_DIR = ROOT / "notebooks"
NOTEBOOKS = "[0-9][0-9]_*.ipynb"
NOT_NOTEBOOKS = {"08_puma_assignment.ipynb"}
TEMPLATE = LOCALE_DIR / f"{DOMAIN}.pot"
_PLACEHOLDER = re.compile(r"\{[^{}]*\}|%(?:\([^)]*\))?[-#0 +]*\d*(?:\.\d+)?[sdifgeEr%]")


def po_path(language: str, domain: str = DOMAIN) -> Path:
    return LOCALE_DIR / language / "LC_MESSAGES" / f"{domain}.po"


def template_path(domain: str = DOMAIN) -> Path:
    return LOCALE_DIR / f"{domain}.pot"


def translated_languages() -> list:
    """The languages that have a catalog: every course language but English, the source."""
    return [lang for lang in LANGUAGES if lang != "en"]


def source_files(domain: str = DOMAIN) -> list:
    """The modules whose messages go to ``domain`` (see :data:`DOMAINS`)."""
    taken, files = set(), {}
    for name, patterns in DOMAINS.items():
        files[name] = sorted({p for pattern in patterns for p in PACKAGE.glob(pattern)} - taken)
        taken |= set(files[name])
    return files[domain]


def extract_messages(domain: str = DOMAIN):
    """The catalog of every message marked in ``domain``'s modules (a Babel ``Catalog``)."""
    from babel.messages.catalog import Catalog
    from babel.messages.extract import extract_from_file

    catalog = Catalog(project="dhlab", domain=domain, charset="utf-8")
    for path in source_files(domain):
        rel = path.relative_to(PACKAGE.parent).as_posix()
        for lineno, message, comments, context in extract_from_file(
                "python", str(path), keywords=KEYWORDS, comment_tags=("TRANSLATORS:",),
                strip_comment_tags=True):
            catalog.add(message, locations=[(rel, lineno)], auto_comments=comments, context=context)
    if domain == DOMAIN:
        for location, lineno, message, comments, context in notebook_messages():
            catalog.add(message, locations=[(location, lineno)], auto_comments=comments, context=context)
    return catalog


def notebook_paths() -> list:
    """The English lesson notebooks whose code cells may hold messages (see :data:`NOTEBOOKS`)."""
    return [p for p in sorted(NOTEBOOK_DIR.glob(NOTEBOOKS)) if p.name not in NOT_NOTEBOOKS]


def cell_python(source: str) -> str:
    """A code cell's source as plain Python: IPython's ``%magic`` and ``!shell`` lines blanked
    (kept as empty lines, so line numbers stay those of the cell)."""
    return "\n".join("" if line.lstrip().startswith(("%", "!")) else line for line in source.split("\n"))


def notebook_messages():
    """``(location, line, message, comments, context)`` for every ``_("…")`` in the notebooks' code cells;
    the location names the notebook and the cell by its id (cells move, ids stay), the line is the cell's:
    ``notebooks/02_homogeneous_matrices.ipynb#nb02-09`` and 5 (a .po file writes ``…#nb02-09:5``; Babel's
    reader drops a location whose part after the last ``:`` is not a line number, hence not ``…ipynb:nb02-09``)."""
    from babel.messages.extract import extract

    for path in notebook_paths():
        rel = path.relative_to(PACKAGE.parent).as_posix()
        for cell in json.loads(path.read_text(encoding="utf-8"))["cells"]:
            if cell["cell_type"] != "code":
                continue
            source = "".join(cell["source"]) if isinstance(cell["source"], list) else cell["source"]
            found = extract("python", io.BytesIO(cell_python(source).encode("utf-8")), keywords=KEYWORDS,
                            comment_tags=("TRANSLATORS:",), strip_comment_tags=True)
            for lineno, message, comments, context in found:
                yield f"{rel}#{cell.get('id', '')}", lineno, message, comments, context


def _read(path: Path):
    from babel.messages.pofile import read_po
    with open(path, "rb") as f:
        return read_po(f, charset="utf-8")


def po_text(catalog, **options) -> str:
    """``catalog`` as the text of a PO file (Babel's ``write_po`` with ``options``), without the
    header's ``Generated-By: Babel x.y`` line: a catalog must not change when only the Babel that
    wrote it did (a fresh install gets the newest)."""
    from babel.messages.pofile import write_po
    buffer = io.BytesIO()
    write_po(buffer, catalog, omit_header=False, **options)
    return re.sub(r'^"Generated-By: [^"\n]*"\n', "", buffer.getvalue().decode("utf-8"), flags=re.M)


def _write_po(catalog, path: Path, **options) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(po_text(catalog, width=100, **options).encode("utf-8"))


def extract() -> None:
    for domain in DOMAINS:
        _write_po(extract_messages(domain), template_path(domain), sort_output=True)


def update() -> None:
    for domain in DOMAINS:
        template = _read(template_path(domain))
        for language in translated_languages():
            path = po_path(language, domain)
            if path.exists():
                catalog = _read(path)
            else:
                from babel.messages.catalog import Catalog
                catalog = Catalog(locale=language, domain=domain, project="dhlab", charset="utf-8")
            catalog.update(template, no_fuzzy_matching=False)
            catalog.fuzzy = False                    # the header is ours, not a guess
            catalog.last_translator = catalog.language_team = "dhlab course"
            _write_po(catalog, path, sort_output=True, include_previous=True)


def compile_catalogs() -> None:
    from babel.messages.mofile import write_mo
    for domain in DOMAINS:
        for language in translated_languages():
            buffer = io.BytesIO()
            write_mo(buffer, _read(po_path(language, domain)), use_fuzzy=False)
            po_path(language, domain).with_suffix(".mo").write_bytes(buffer.getvalue())


def placeholders(text: str) -> list:
    """The ``{name}`` and ``%s`` fields of a message, sorted (``{{``/``}}`` are literal braces)."""
    return sorted(_PLACEHOLDER.findall(text.replace("{{", "").replace("}}", "")))


def problems() -> list:
    """Everything that keeps the catalogs from matching the code, one line each."""
    return [line for domain in DOMAINS for line in _domain_problems(domain)]


def _domain_problems(domain: str) -> list:
    found = []
    wanted = {m.id for m in extract_messages(domain) if m.id}
    for language in translated_languages():
        path = po_path(language, domain)
        if not path.exists():
            found.append(f"{path}: missing")
            continue
        catalog = _read(path)
        have = {m.id for m in catalog if m.id}
        found += [f"{language}: not in the catalog: {m!r}" for m in sorted(wanted - have)]
        found += [f"{language}: obsolete: {m!r}" for m in sorted(catalog.obsolete)]
        for m in catalog:
            if not m.id:
                continue
            if m.fuzzy:
                found.append(f"{language}: fuzzy: {m.id!r}")
            elif not m.string:
                found.append(f"{language}: untranslated: {m.id!r}")
            elif placeholders(m.id) != placeholders(m.string):
                found.append(f"{language}: placeholders differ: {m.id!r} -> {m.string!r}")
            if m.id not in wanted:
                found.append(f"{language}: in the catalog but not in the code: {m.id!r}")
        found += _mo_problems(path.with_suffix(".mo"), catalog)
    return found


def _mo_problems(mo: Path, catalog) -> list:
    import gettext
    if not mo.exists():
        return [f"{mo}: missing: run compile"]
    with open(mo, "rb") as f:
        compiled = gettext.GNUTranslations(f)
    stale = [m.id for m in catalog if m.id and m.string and not m.fuzzy and compiled.gettext(m.id) != m.string]
    return [f"{mo}: does not match its .po ({len(stale)} messages): run compile"] if stale else []


def main(argv=None) -> int:
    commands = {"extract": extract, "update": update, "compile": compile_catalogs}
    args = sys.argv[1:] if argv is None else argv
    if len(args) != 1 or args[0] not in (*commands, "check"):
        print(__doc__.split("\n\n")[0] + "\n\nusage: python -m tools.i18n_catalog {extract,update,compile,check}")
        return 2
    if args[0] != "check":
        commands[args[0]]()
        return 0
    found = problems()
    print("\n".join(found) if found else "the catalogs match the code")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
