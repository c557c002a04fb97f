"""The roster of a release: the students' ids, read from a CSV file, and a file name for each.

:func:`read_roster` reads the ids (the column ``id``, ``student_id``, … :data:`ID_COLUMNS`, or the one
``--id-column`` names), refusing an empty or duplicate id, an id holding a control or invisible character
(:func:`checked_id`) and two ids that are one name written two ways (:func:`look_alikes`);
:func:`safe_filename` is the id as a file name any system accepts. The LMS export
(:mod:`dhlab.grading.export.lms`) reads its roster with the same functions.
"""
from __future__ import annotations

import csv
import hashlib
import io
import re
import unicodedata
from pathlib import Path

from ...errors import DHLabError
from ...i18n import _

__all__ = ["ID_COLUMNS", "RESERVED", "csv_rows", "read_roster", "checked_id", "look_alikes", "id_column_index",
           "safe_filename"]

ID_COLUMNS = ("id", "student_id", "student", "username", "login",
              "identificador", "id_estudiante", "id estudiante", "estudiante", "usuario", "nombre de usuario",
              "id number", "número de id")
RESERVED = {"CON", "PRN", "AUX", "NUL", *(f"COM{i}" for i in range(1, 10)), *(f"LPT{i}" for i in range(1, 10))}


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
    column = id_column_index(header, id_column, path)
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
            raise DHLabError(_("roster {name}: the ids {first!r} and {second!r} are the same name written two "
                               "ways (Unicode NFC and NFD){at}: two students to the grader, one to the eye; retype "
                               "one of them in the roster so that both are spelled the same way, or make them "
                               "different ids.").format(name=roster_name, first=first, second=sid, at=at))
        seen[key] = (sid, line)


def _column_key(name: str) -> str:
    """A column's name as compared: stripped, lower case, composed ('Número de ID' → 'número de id')."""
    return unicodedata.normalize("NFC", name.strip().lower())


def id_column_index(header, id_column, path) -> int:
    """The index of the roster's id column in ``header``: ``id_column`` when given, else the first of
    :data:`ID_COLUMNS` (names compared without case), with a clear error when there is none."""
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
    return name.split(".")[0].rstrip(" ").upper() in RESERVED
