"""Release the assignment: one notebook per student, each with the student's own robot.

    dhlab-assign release ROSTER.csv -o release/ [--family puma560|kr5,ur5|all]
                         [--secret-file dhlab-secret.key] [--id-column id] [--template NOTEBOOK] [--figures]
                         [--language en|es]

For every row of the roster (a CSV file with a header; the id column is ``id``,
``student_id``, ``student``, ``username`` or ``login``, or the one ``--id-column`` names)
it draws the student's variant (:func:`dhlab.grading.variants.roster_variants`), signs
it with the teacher's secret, and writes ``release/<id>.ipynb``: the generated student
notebook (``notebooks/08_puma_assignment.ipynb``) with a "Your robot" section — the
robot's figure (drawn when the student runs the cell; stored in the notebook with
``--figures``), its axes table and the points table — and the signed record in the
notebook's metadata (``metadata["dhlab"]``). The same roster and secret always give
byte-identical notebooks. ``release/_teacher/`` keeps the teacher's copy of every
variant (``variants.json``) and which file is whose (``manifest.csv``): hand out only
the ``.ipynb`` files.

**The student's language** (:mod:`dhlab.grading.release_language`): ``--language es`` releases
the notebooks in Spanish; a roster column ``language`` (or ``idioma``) with ``en``/``es`` per
student overrides it, so a class may mix; the default is ``DHLAB_LANGUAGE``, else English. The
language is recorded in ``metadata["dhlab"]["language"]`` and said in the set-up cell
(``dhlab.set_language("es")``); the grader writes each student's feedback in it.

**The seam for the grader.** The released notebook's locked cell ``your_robot`` calls
``use_variant(<the variant>, student_id=…)`` (:func:`dhlab.course.family_notebook.use_variant`),
which makes the variant the robot the assignment's checks use
(:func:`~dhlab.course.family_notebook.active_robot`). ``dhlab-grade`` reads
``metadata["dhlab"]``, verifies it (:func:`~dhlab.grading.variants.verify`) and rewrites
that cell from the verified variant before running a submission.
"""
from __future__ import annotations

import argparse
import csv
import hashlib
import io
import json
import re
import sys
import unicodedata
from pathlib import Path

from ..course.family_notebook import SEAM_CELL_ID, prepare_submission, release_notebook, seam_source
from ..validation import DHLabError
from . import variants as V
from .language import _, language_option
from .release_language import default_language, in_language, in_spanish, mark_language, roster_languages

__all__ = ["read_roster", "safe_filename", "release_notebook", "release", "main", "TEMPLATE",
           "ID_COLUMNS", "SEAM_CELL_ID", "DEFAULT_SECRET_FILE", "seam_source", "load_teacher_records",
           "submission_variant", "prepare_submission"]

_ROOT = Path(__file__).resolve().parents[2]
TEMPLATE = _ROOT / "notebooks" / "08_puma_assignment.ipynb"
ID_COLUMNS = ("id", "student_id", "student", "username", "login")
DEFAULT_SECRET_FILE = Path("dhlab-secret.key")
_RESERVED = {"CON", "PRN", "AUX", "NUL", *(f"COM{i}" for i in range(1, 10)), *(f"LPT{i}" for i in range(1, 10))}


# --- the roster ------------------------------------------------------------------------------------

def csv_rows(path) -> list:
    """The non-empty rows of a roster CSV (comma, semicolon or tab; UTF-8, with or without BOM),
    with clear errors for a missing file or another encoding."""
    try:
        text = path.read_text(encoding="utf-8-sig")
    except OSError as exc:
        raise DHLabError(f"cannot read the roster {str(path)!r}: {exc.strerror}.") from None
    except UnicodeDecodeError:
        raise DHLabError(f"the roster {str(path)!r} is not UTF-8 text: save it as 'CSV UTF-8'.") from None
    try:
        dialect = csv.Sniffer().sniff(text[:4096], delimiters=",;\t")
    except csv.Error:
        dialect = csv.excel
    return [r for r in csv.reader(io.StringIO(text), dialect) if any(cell.strip() for cell in r)]


def read_roster(path, id_column: str | None = None) -> list:
    """The student ids of a roster CSV, in order, with clear errors: no such file, no header,
    no id column, an empty id, a duplicate id."""
    path = Path(path)
    rows = csv_rows(path)
    if not rows:
        raise DHLabError(f"the roster {str(path)!r} is empty: it needs a header row and one row per student.")
    header = [h.strip() for h in rows[0]]
    column = _id_column(header, id_column, path)
    ids, where = [], {}
    for line, row in enumerate(rows[1:], start=2):
        sid = row[column].strip() if column < len(row) else ""
        if not sid:
            raise DHLabError(f"roster {path.name}, row {line}: the id column {header[column]!r} is empty.")
        if sid in where:
            raise DHLabError(f"roster {path.name}: the id {sid!r} appears twice (rows {where[sid]} and {line}); "
                             "every student needs a different id.")
        where[sid] = line
        ids.append(sid)
    if not ids:
        raise DHLabError(f"the roster {str(path)!r} has a header but no students.")
    return ids


def _id_column(header, id_column, path) -> int:
    lowered = [h.lower() for h in header]
    if id_column is not None:
        if id_column.lower() not in lowered:
            raise DHLabError(f"the roster {path.name} has no column {id_column!r}; its columns are {header}.")
        return lowered.index(id_column.lower())
    for name in ID_COLUMNS:
        if name in lowered:
            return lowered.index(name)
    raise DHLabError(f"the roster {path.name} has no id column: its columns are {header}. Name one of them "
                     f"{', '.join(ID_COLUMNS)}, or pass --id-column.")


# letters NFKD does not take apart, and the Cyrillic and Greek alphabets, spelled in ASCII
_SPELLED = {"Ø": "O", "ø": "o", "ß": "ss", "Ł": "L", "ł": "l", "Æ": "AE", "æ": "ae", "Œ": "OE", "œ": "oe",
            "Đ": "D", "đ": "d", "Ð": "D", "ð": "d", "Þ": "Th", "þ": "th", "ı": "i"}
_CYRILLIC = ("а a б b в v г g д d е e ё e ж zh з z и i й y к k л l м m н n о o п p р r с s т t у u ф f х kh "
             "ц ts ч ch ш sh щ shch ъ _ ы y ь _ э e ю yu я ya і i ї yi є ye ґ g")
_GREEK = "α a β v γ g δ d ε e ζ z η i θ th ι i κ k λ l μ m ν n ξ x ο o π p ρ r σ s ς s τ t υ y φ f χ ch ψ ps ω o"
for _pairs in (_CYRILLIC, _GREEK):
    _words = _pairs.split()
    for _letter, _ascii in zip(_words[::2], _words[1::2]):
        _SPELLED[_letter] = "" if _ascii == "_" else _ascii
        _SPELLED[_letter.upper()] = "" if _ascii == "_" else _ascii.capitalize()
_SPELL = str.maketrans(_SPELLED)


def _readable(ch: str) -> str:
    """One character of an id in ASCII, for a file name: letters with accents without them (é → e,
    ñ → n), ß → ss, ł → l, Cyrillic and Greek letters spelled out (Иван → Ivan); anything else '_'."""
    folded = ch.translate(_SPELL)                        # й → y, before NFKD would make it и + ˘
    if folded == ch:
        folded = unicodedata.normalize("NFKD", ch).translate(_SPELL)     # é → e + ´, έ → ε + ´ → e + ´
    kept = "".join(c for c in folded if c.isascii() and (c.isalnum() or c in "._-"))
    return kept if kept or unicodedata.combining(ch) else "_"


def safe_filename(student_id: str) -> str:
    """A file name (without extension) for ``student_id``: the id itself when it is plain
    (letters, digits, '.', '_', '-'), else the id spelled in ASCII (:func:`_readable`: accents
    dropped, Cyrillic and Greek spelled out, other characters '_'; an id with nothing left,
    e.g. Chinese, is 'student') and a short hash of the id, so two different ids never share a file.

    >>> safe_filename("ana.garcia"), safe_filename("Ana María"), safe_filename("Ana_María")
    ('ana.garcia', 'Ana_Maria-8358ed', 'Ana_Maria-0fd2b0')
    >>> safe_filename("Łukasz.Øster"), safe_filename("Иван.Петров"), safe_filename("李雷")
    ('Lukasz.Oster-dead72', 'Ivan.Petrov-519ffb', 'student-3a4732')
    """
    if re.fullmatch(r"[A-Za-z0-9_-][A-Za-z0-9._-]{0,79}", student_id) and student_id.upper() not in _RESERVED:
        return student_id
    spelled = "".join(_readable(ch) for ch in unicodedata.normalize("NFC", student_id))
    slug = re.sub(r"_+", "_", spelled).strip("._")[:60] or "student"
    return f"{slug}-{hashlib.sha256(student_id.encode('utf-8')).hexdigest()[:6]}"


# --- the notebook ------------------------------------------------------------------------------------

def _load_template(path) -> dict:
    """The student notebook to start from; without a course checkout (an installed dhlab), the
    default is generated from the teacher's source notebook shipped with the package."""
    path = Path(path)
    if path == TEMPLATE and not path.exists():
        from . import generate
        try:
            return generate.student_notebook(json.loads(Path(generate.SOURCE).read_text(encoding="utf-8")))
        except (OSError, AttributeError, ValueError):
            pass                                        # fall through to the clear error below
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except OSError as exc:
        raise DHLabError(f"cannot read the template notebook {str(path)!r}: {exc.strerror}. Pass "
                         "--template with the generated student notebook (08_puma_assignment.ipynb).") from None
    except json.JSONDecodeError as exc:
        raise DHLabError(f"the template {str(path)!r} is not a notebook (JSON error: {exc.msg}).") from None


def _dumps(nb: dict) -> str:
    """The notebook as nbformat writes it (1-space indent, sorted keys, final newline)."""
    return json.dumps(nb, sort_keys=True, indent=1, ensure_ascii=False) + "\n"


def release(roster, out, secret: bytes, families=None, id_column=None, template=TEMPLATE,
            figures: bool = False, language: str | None = None) -> list:
    """Write one notebook per student of ``roster`` into ``out`` (see the module); returns
    the manifest rows (student id, file, family, fingerprint, language). ``language``: the
    notebooks' language where the roster has no language column (default ``DHLAB_LANGUAGE``, else 'en')."""
    ids = read_roster(roster, id_column)
    languages = roster_languages(csv_rows(Path(roster)), ids, default_language(language), Path(roster).name)
    names = {}
    for sid in ids:
        name = safe_filename(sid)
        if name.lower() in names:                            # case-insensitive file systems
            raise DHLabError(f"the ids {names[name.lower()]!r} and {sid!r} would share the file {name}.ipynb.")
        names[name.lower()] = sid
    tpl = _load_template(template)
    chosen = V.roster_variants(ids, secret, families)
    out = Path(out)
    (out / "_teacher").mkdir(parents=True, exist_ok=True)
    manifest, teacher, notes = [], {}, set()
    for sid in ids:
        record = V.sign(chosen[sid], sid, secret)
        with in_language(languages[sid]):               # the figure's and tables' words too
            nb, cell_notes = release_notebook(tpl, record, figures)
            if languages[sid] == "es":
                nb = in_spanish(nb, tpl, record, notes)
        mark_language(nb, languages[sid])
        notes.update(cell_notes)
        file = f"{safe_filename(sid)}.ipynb"
        (out / file).write_text(_dumps(nb), encoding="utf-8")
        fp = V.fingerprint(chosen[sid])
        manifest.append({"student_id": sid, "file": file, "family": chosen[sid].family, "fingerprint": fp,
                         "language": languages[sid]})
        teacher[sid] = record
    buffer = io.StringIO()
    writer = csv.DictWriter(buffer, ["student_id", "file", "family", "fingerprint", "language"],
                            lineterminator="\n")
    writer.writeheader()
    writer.writerows(manifest)
    (out / "_teacher" / "manifest.csv").write_text(buffer.getvalue(), encoding="utf-8")
    (out / "_teacher" / "variants.json").write_text(
        json.dumps(teacher, sort_keys=True, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
    for note in sorted(notes):
        print(_("dhlab-assign: note: {note}").format(note=note), file=sys.stderr)
    return manifest


# --- what the grader needs (the integration seam) ---------------------------------------------------

def load_teacher_records(path) -> dict:
    """The teacher's copy of every signed record (``release/_teacher/variants.json``): id -> record."""
    try:
        records = json.loads(Path(path).read_text(encoding="utf-8"))
    except (OSError, json.JSONDecodeError) as exc:
        raise DHLabError(f"cannot read the teacher's variants {str(path)!r}: {exc}.") from None
    if not isinstance(records, dict):
        raise DHLabError(f"{str(path)!r} is not the teacher's variants file (a JSON object id -> record).")
    return records


def submission_variant(nb: dict, student_id: str, secret: bytes, teacher_records=None, roster_ids=()):
    """The variant to grade ``nb`` (a submitted notebook, as a dict) against, for ``student_id``.

    Returns ``(variant, verification, source)``: the notebook's own variant when its signature
    verifies (source ``"notebook"``); otherwise, when ``teacher_records`` (see
    :func:`load_teacher_records`) has the student, the variant released to them (source
    ``"roster"``); else ``(None, verification, None)``. ``verification.status`` is what the
    gradebook records either way (ok / missing / tampered / other_student).
    """
    record = nb.get("metadata", {}).get(V.METADATA_KEY) if isinstance(nb, dict) else None
    roster_ids = list(roster_ids) or list(teacher_records or ())
    check = V.verify(record, student_id, secret, roster_ids)
    if check.ok:
        return check.variant, check, "notebook"
    released = (teacher_records or {}).get(student_id)
    if released is not None and V.verify(released, student_id, secret).ok:
        return V.Variant.from_dict(released["variant"]), check, "roster"
    return None, check, None


def _secret(path) -> bytes:
    if path is not None:
        return V.load_secret(path)
    if DEFAULT_SECRET_FILE.exists():
        return V.load_secret(DEFAULT_SECRET_FILE)
    secret = V.new_secret()
    DEFAULT_SECRET_FILE.touch(mode=0o600)
    DEFAULT_SECRET_FILE.write_bytes(secret + b"\n")
    print(f"dhlab-assign: made a new secret in {DEFAULT_SECRET_FILE.resolve()}: keep it (grading needs it) "
          "and never hand it out.", file=sys.stderr)
    return secret


def main(argv=None) -> int:
    """``dhlab-assign release ROSTER.csv -o OUT`` (see the module). Returns the exit code. The command
    speaks the teacher's language (``--language``, else ``DHLAB_LANGUAGE``), which is also the
    notebooks' language where the roster has no language column."""
    from ..i18n import set_language
    argv = sys.argv[1:] if argv is None else list(argv)
    try:
        previous = set_language(language_option(argv))
    except DHLabError as exc:
        print(f"dhlab-assign: error: {exc}", file=sys.stderr)
        return 2
    try:
        return _main(argv)
    finally:
        set_language(previous)


def _main(argv) -> int:
    parser = argparse.ArgumentParser(prog="dhlab-assign", description=_(
        "Release the DH assignment: one personal robot and notebook per student."))
    sub = parser.add_subparsers(dest="command", required=True)
    rel = sub.add_parser("release", help=_("write one notebook per student of a roster"))
    rel.add_argument("roster", help=_("CSV file with a header and one row per student"))
    rel.add_argument("-o", "--output", required=True, help=_("folder for the notebooks"))
    rel.add_argument("--family", default="puma560",
                     help=_("robot(s) to draw from: a key, a comma-separated list, or 'all' (default puma560)"))
    rel.add_argument("--secret-file", default=None,
                     help=_("the teacher's secret (default {file}, made when missing)").format(file=DEFAULT_SECRET_FILE))
    rel.add_argument("--id-column", default=None,
                     help=_("the roster's id column (default: {names})").format(names=", ".join(ID_COLUMNS)))
    rel.add_argument("--template", default=str(TEMPLATE), help=_("the student notebook to start from"))
    rel.add_argument("--figures", action="store_true",
                     help=_("store the robot's picture in each notebook (about 0.5 s per student more; "
                            "without it the picture is drawn when the student runs the cell)"))
    rel.add_argument("--language", default=None,
                     help=_("the notebooks' language, en or es, where the roster has no 'language' (or 'idioma') "
                            "column; also this command's (default: DHLAB_LANGUAGE, else en)"))
    args = parser.parse_args(argv)
    try:
        secret = _secret(args.secret_file)
        rows = release(args.roster, args.output, secret, args.family, args.id_column, args.template,
                       figures=args.figures, language=args.language)
    except DHLabError as exc:
        print(f"dhlab-assign: error: {exc}", file=sys.stderr)
        return 2
    families = sorted({r["family"] for r in rows})
    counts = ", ".join(f"{language} {sum(1 for r in rows if r['language'] == language)}"
                       for language in sorted({r["language"] for r in rows}))
    print(_("dhlab-assign: {count} notebooks in {folder} ({families}; {languages}); the teacher's record is in "
            "{record}").format(count=len(rows), folder=args.output, families=", ".join(families), languages=counts,
                               record=Path(args.output) / "_teacher"))
    return 0


if __name__ == "__main__":               # pragma: no cover
    sys.exit(main())
