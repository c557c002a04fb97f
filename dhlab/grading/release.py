"""Release the assignment: one notebook per student, each with the student's own robot.

    dhlab-assign release ROSTER.csv -o release/ [--family puma560|kr5,ur5|all]
                         [--secret-file dhlab-secret.key] [--id-column id] [--template NOTEBOOK] [--figures]
                         [--language en|es]

For every row of the roster (a CSV file with a header; the id column is ``id``,
``student_id``, ``student``, ``username`` or ``login`` — in Spanish ``identificador``,
``id_estudiante``, ``estudiante``, ``usuario``… (:data:`ID_COLUMNS`) — or the one ``--id-column``
names) it draws the student's variant (:func:`dhlab.grading.variants.roster_variants`), signs
it with the teacher's secret, and writes ``release/<id>.ipynb``: the generated student
notebook (:data:`TEMPLATE`, shipped with the package: the course's ``notebooks/08_puma_assignment.ipynb``;
``--template`` names another) with a "Your robot" section — the
robot's figure (drawn when the student runs the cell; stored in the notebook with
``--figures``), its axes table and the points table — and the signed record in the
notebook's metadata (``metadata["dhlab"]``). The same roster and secret always give
byte-identical notebooks. ``release/_teacher/`` keeps the teacher's copy of every
variant (``variants.json``) and which file is whose (``manifest.csv``, UTF-8 with a BOM for
Excel, no cell a formula: :mod:`dhlab.grading.csvsafe`): hand out only the ``.ipynb`` files.

**Releasing again into the same folder adds, never replaces.** The teacher's records there are
kept: a student already released keeps the variant recorded (their notebook is written again
from it), a new student gets a new variant, different from every one in the folder, and both
files then list everyone. A folder released with another secret is refused
(:func:`previous_release`). **Ids** holding control characters (NUL, a line break…), or two ids
that are the same text written two ways (``José`` composed, NFC, and decomposed, NFD), are
refused with the rows named (:func:`checked_id`, :func:`look_alikes`); file names never start
with ``-`` nor are a Windows device name (``CON``, ``nul.txt``…) (:func:`safe_filename`).

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
from pathlib import Path, PurePosixPath

from ..assignment import variants as V
from ..assignment.notebook_cells import SEAM_CELL_ID, prepare_submission, release_notebook, seam_source
from ..validation import DHLabError
from . import generate
from ..i18n import _, language_option
from .release_language import default_language, in_language, in_spanish, mark_language, roster_languages

__all__ = ["read_roster", "checked_id", "look_alikes", "previous_release", "safe_filename", "release_notebook", "release", "main", "TEMPLATE",
           "ID_COLUMNS", "SEAM_CELL_ID", "DEFAULT_SECRET_FILE", "seam_source", "load_teacher_records",
           "submission_variant", "prepare_submission"]

TEMPLATE = generate.TEMPLATE          # the student notebook, package data (no solutions in it)
ID_COLUMNS = ("id", "student_id", "student", "username", "login",
              "identificador", "id_estudiante", "id estudiante", "estudiante", "usuario", "nombre de usuario",
              "id number", "número de id")
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
        sid = checked_id(row[column] if column < len(row) else "", path.name, line, header[column])
        if sid in where:
            raise DHLabError(f"roster {path.name}: the id {sid!r} appears twice (rows {where[sid]} and {line}); "
                             "every student needs a different id.")
        where[sid] = line
        ids.append(sid)
    if not ids:
        raise DHLabError(f"the roster {str(path)!r} has a header but no students.")
    look_alikes(where, path.name)
    return ids


def _unsafe_character(text: str) -> str | None:
    """The first character of ``text`` an id must not hold, as 'U+0000', else None: control
    characters (NUL, tab, line breaks…) and invisible format characters (a right-to-left
    override, a zero-width space), which make two different ids look the same. The joiners
    some scripts need (U+200C, U+200D) are allowed."""
    for ch in text:
        kind = unicodedata.category(ch)
        if kind in ("Cc", "Zl", "Zp") or (kind == "Cf" and ch not in "\u200c\u200d"):
            return f"U+{ord(ch):04X}"
    return None


def checked_id(value: str, roster_name: str, line: int, column: str) -> str:
    """One roster cell as a student id: stripped, not empty, no control character (a clear
    error naming the row otherwise: such an id is a file name and a gradebook cell later)."""
    sid = value.strip()
    if not sid:
        raise DHLabError(f"roster {roster_name}, row {line}: the id column {column!r} is empty.")
    bad = _unsafe_character(sid)
    if bad:
        raise DHLabError(_("roster {name}, row {line}: the id {sid!r} holds the invisible or control character "
                           "{char}; retype the id in the roster without it.").format(
            name=roster_name, line=line, sid=sid, char=bad))
    return sid


def look_alikes(where, roster_name: str) -> None:
    """Refuse two ids that are the same text in two Unicode forms (``José`` typed with one 'é',
    NFC, and with 'e' + an accent, NFD, as a Mac may write it): they look alike everywhere,
    but would be two students. ``where``: id -> its row (or a list of ids)."""
    rows = where if isinstance(where, dict) else {sid: None for sid in where}
    seen = {}
    for sid, line in rows.items():
        key = unicodedata.normalize("NFC", sid)
        if key in seen:
            first, first_line = seen[key]
            at = _(" (rows {first} and {second})").format(first=first_line, second=line) if line else ""
            raise DHLabError(_("roster {name}: the ids {first!r} and {second!r} are the same name written two ways "
                               "(Unicode NFC and NFD){at}: two students to the grader, one to the eye; retype one of them "
                               "in the roster so that both are spelled the same way, or make them different ids.").format(
                name=roster_name, first=first, second=sid, at=at))
        seen[key] = (sid, line)


def _column_key(name: str) -> str:
    """A column's name as compared: stripped, lower case, composed ('Número de ID' → 'número de id')."""
    return unicodedata.normalize("NFC", name.strip().lower())


def _id_column(header, id_column, path) -> int:
    lowered = [_column_key(h) for h in header]
    if id_column is not None:
        if _column_key(id_column) not in lowered:
            raise DHLabError(f"the roster {path.name} has no column {id_column!r}; its columns are {header}.")
        return lowered.index(_column_key(id_column))
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
    if re.fullmatch(r"[A-Za-z0-9_][A-Za-z0-9._-]{0,79}", student_id) and not _reserved(student_id):
        return student_id
    spelled = "".join(_readable(ch) for ch in unicodedata.normalize("NFC", student_id))
    slug = re.sub(r"_+", "_", spelled).strip("._-")[:60] or "student"
    name = f"{slug}-{hashlib.sha256(student_id.encode('utf-8')).hexdigest()[:6]}"
    return f"_{name}" if _reserved(name) else name          # 'nul.txt-1a2b3c' is still NUL to Windows


def _reserved(name: str) -> bool:
    """Whether Windows reserves the file name ``name`` (+ '.ipynb'): a device name, alone or
    before any extension ('CON', 'nul.txt', 'com1.x'). A name starting with '-' (read as an
    option by a shell command) never reaches here: it is not plain, so it is spelled and hashed."""
    return name.split(".")[0].rstrip(" ").upper() in _RESERVED


# --- the notebook ------------------------------------------------------------------------------------

def _load_template(path) -> dict:
    """The student notebook to start from (the package's :data:`TEMPLATE` by default)."""
    path = Path(path)
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


MANIFEST_COLUMNS = ["student_id", "file", "family", "fingerprint", "language"]


def release(roster, out, secret: bytes, families=None, id_column=None, template=TEMPLATE,
            figures: bool = False, language: str | None = None) -> list:
    """Write one notebook per student of ``roster`` into ``out`` (see the module); returns
    the manifest rows of this roster (student id, file, family, fingerprint, language).
    ``language``: the notebooks' language where the roster has no language column (default
    ``DHLAB_LANGUAGE``, else 'en'). An earlier release in ``out`` is added to, never replaced."""
    ids = read_roster(roster, id_column)
    languages = roster_languages(csv_rows(Path(roster)), ids, default_language(language), Path(roster).name)
    out = Path(out)
    earlier, earlier_rows = previous_release(out, secret)
    _check_file_names(ids, earlier_rows)
    tpl = _load_template(template)
    chosen = _variants(ids, secret, families, earlier)
    (out / "_teacher").mkdir(parents=True, exist_ok=True)
    manifest, teacher, notes = [], dict(earlier), set()
    for sid in ids:
        record = earlier.get(sid) or V.sign(chosen[sid], sid, secret)
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
    _write_teacher_records(out, teacher, _merged(earlier_rows, manifest))
    kept = [sid for sid in ids if sid in earlier]
    if earlier:
        notes.add(_("{folder} already held a release of {count} students: it was added to, not replaced; "
                    "{kept} of this roster were released there before and keep their robots, {new} are new.").format(
            folder=out, count=len(earlier), kept=len(kept), new=len(ids) - len(kept)))
    for note in sorted(notes):
        print(_("dhlab-assign: note: {note}").format(note=note), file=sys.stderr)
    return manifest


def previous_release(out: Path, secret: bytes) -> tuple:
    """(id -> signed record, manifest rows) of an earlier release into ``out`` (empty when there
    is none). Refused with a clear error when its records were signed with another secret: two
    secrets in one folder would make half the class unverifiable."""
    records_file = out / "_teacher" / "variants.json"
    if not records_file.exists():
        return {}, []
    records = load_teacher_records(records_file)
    foreign = [sid for sid, record in records.items() if not V.verify(record, sid, secret).ok]
    if foreign:
        raise DHLabError(_("{folder} already holds a release whose variants do not verify with this secret "
                           "({count} of {total}, first {first!r}): release into a new folder, or pass the "
                           "--secret-file that release was made with. One folder never mixes two secrets.").format(
            folder=out, count=len(foreign), total=len(records), first=foreign[0]))
    rows = {row["student_id"]: row for row in _manifest_rows(out / "_teacher" / "manifest.csv")
            if row.get("student_id") in records}
    for sid, record in records.items():                  # a student the manifest lost: rebuilt from the record
        if sid not in rows:
            variant = V.Variant.from_dict(record["variant"])
            rows[sid] = {"student_id": sid, "file": f"{safe_filename(sid)}.ipynb", "family": variant.family,
                         "fingerprint": V.fingerprint(variant), "language": ""}
    return records, list(rows.values())


def _manifest_rows(path) -> list:
    """The rows of a manifest this module wrote (dicts; [] when there is none), cells unescaped."""
    from .csvsafe import restored
    try:
        with open(path, newline="", encoding="utf-8-sig") as f:
            return [{k: restored(v) for k, v in row.items() if k is not None} for row in csv.DictReader(f)]
    except (OSError, csv.Error, UnicodeDecodeError):
        return []


def _check_file_names(ids, earlier_rows) -> None:
    """Two students never share a file, even on a file system that ignores case (Windows, macOS),
    nor a new student the file of one released earlier."""
    names = {PurePosixPath(row["file"]).stem.lower(): row["student_id"] for row in earlier_rows}
    for sid in ids:
        name = safe_filename(sid)
        if names.get(name.lower(), sid) != sid:
            raise DHLabError(f"the ids {names[name.lower()]!r} and {sid!r} would share the file {name}.ipynb.")
        names[name.lower()] = sid


def _variants(ids, secret: bytes, families, earlier: dict) -> dict:
    """id -> Variant: a student released before keeps the recorded variant; a new one gets a
    draw different from every variant in the folder (with no earlier release: exactly
    :func:`dhlab.grading.variants.roster_variants`)."""
    if not earlier:
        return V.roster_variants(ids, secret, families)
    chosen = {sid: V.Variant.from_dict(record["variant"]) for sid, record in earlier.items()}
    seen = {V.fingerprint(v) for v in chosen.values()}
    for sid in ids:
        if sid in chosen:
            continue
        for attempt in range(50):
            v = V.student_variant(sid, secret, families, attempt)
            if V.fingerprint(v) not in seen:
                break
        else:
            raise DHLabError(f"could not draw a variant for {sid!r} different from every classmate's.")
        seen.add(V.fingerprint(v))
        chosen[sid] = v
    return chosen


def _merged(earlier_rows, rows) -> list:
    """The manifest: the earlier rows in their order (updated where released again), then the new."""
    merged = {row["student_id"]: row for row in earlier_rows}
    merged.update((row["student_id"], row) for row in rows)
    return list(merged.values())


def _write_teacher_records(out: Path, teacher: dict, manifest: list) -> None:
    """``_teacher/variants.json`` and ``_teacher/manifest.csv``, each written atomically (a
    stopped release leaves the old file or the new one). The manifest is for Excel: UTF-8 with
    a BOM, every cell text and escaped when it starts like a formula (an id ``=1+2``)."""
    from .csvsafe import csv_text
    from .gradebook import write_atomic
    table = [MANIFEST_COLUMNS] + [[row.get(c, "") for c in MANIFEST_COLUMNS] for row in manifest]
    write_atomic(out / "_teacher" / "variants.json",
                 json.dumps(teacher, sort_keys=True, indent=1, ensure_ascii=False) + "\n")
    write_atomic(out / "_teacher" / "manifest.csv", csv_text(table))


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
