"""Release the assignment: one notebook per student, each with the student's own robot.

    dhlab-assign release ROSTER.csv -o release/ [--family puma560|kr5,ur5|all]
                         [--secret-file dhlab-secret.key] [--id-column id] [--template NOTEBOOK] [--figures]
                         [--language en|es]
    dhlab-assign solutions OUT.ipynb [--student ID --release release/]     # the teacher's solved notebook

The second command writes the solutions, computed, for the PUMA 560 or one student's own robot
(:mod:`dhlab.grading.release.solutions`): no file of the course holds them.

For every row of the roster (a CSV file with a header; the id column is ``id``,
``student_id``, ``student``, ``username`` or ``login`` — in Spanish ``identificador``,
``id_estudiante``, ``estudiante``, ``usuario``… (:data:`ID_COLUMNS`) — or the one ``--id-column``
names) it draws the student's variant (:func:`dhlab.assignment.variants.roster_variants`), signs
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

**The student's language** (:mod:`dhlab.grading.release.language`): ``--language es`` releases
the notebooks in Spanish; a roster column ``language`` (or ``idioma``) with ``en``/``es`` per
student overrides it, so a class may mix; the default is ``DHLAB_LANGUAGE``, else English. The
language is recorded in ``metadata["dhlab"]["language"]`` and said in the set-up cell
(``dhlab.set_language("es")``); the grader writes each student's feedback in it.

**The seam for the grader.** The released notebook's locked cell ``your_robot`` calls
``use_variant(<the variant>, student_id=…)`` (:func:`dhlab.assignment.notebook_cells.use_variant`),
which makes the variant the robot the assignment's checks use
(:func:`~dhlab.assignment.notebook_cells.active_robot`). ``dhlab-grade`` reads
``metadata["dhlab"]``, verifies it (:func:`~dhlab.assignment.variants.verify`) and rewrites
that cell from the verified variant before running a submission.
"""
from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path, PurePosixPath

from ...assignment import variants as V
from ...assignment.notebook_cells import release_notebook
from ...errors import DHLabError
from ...i18n import _, argparse_speaking, default_language, error_line, language_option, set_language
from ..atomic_file import write_atomic
from ..csvsafe import csv_text
from ..options import DEFAULT_SECRET_FILE, shared
from . import folder, generate, solutions
from .folder import load_teacher_records, manifest_rows
from .language import in_language, in_spanish, mark_language, roster_languages
from .roster import ID_COLUMNS, csv_rows, read_roster, safe_filename

# (the roster's, the notebook's and the folder's own names live in roster.py, notebook_cells.py, folder.py)
__all__ = ["previous_release", "release", "main", "TEMPLATE", "submission_variant"]

TEMPLATE = generate.TEMPLATE          # the student notebook, package data (no solutions in it)


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
        record = earlier.get(sid) or V.sign_record(chosen[sid], sid, secret)
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
    records_file = folder.records_file(out)
    if not records_file.exists():
        return {}, []
    records = load_teacher_records(records_file)
    foreign = [sid for sid, record in records.items() if not V.verify(record, sid, secret).ok]
    if foreign:
        raise DHLabError(_("{folder} already holds a release whose variants do not verify with this secret "
                           "({count} of {total}, first {first!r}): release into a new folder, or pass the "
                           "--secret-file that release was made with. One folder never mixes two secrets.").format(
            folder=out, count=len(foreign), total=len(records), first=foreign[0]))
    rows = {row["student_id"]: row for row in manifest_rows(folder.manifest_file(out))
            if row.get("student_id") in records}
    for sid, record in records.items():                  # a student the manifest lost: rebuilt from the record
        if sid not in rows:
            variant = V.Variant.from_dict(record["variant"])
            rows[sid] = {"student_id": sid, "file": f"{safe_filename(sid)}.ipynb", "family": variant.family,
                         "fingerprint": V.fingerprint(variant), "language": ""}
    return records, list(rows.values())


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
    :func:`dhlab.assignment.variants.roster_variants`)."""
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
    table = [MANIFEST_COLUMNS] + [[row.get(c, "") for c in MANIFEST_COLUMNS] for row in manifest]
    write_atomic(out / "_teacher" / "variants.json",
                 json.dumps(teacher, sort_keys=True, indent=1, ensure_ascii=False) + "\n")
    write_atomic(out / "_teacher" / "manifest.csv", csv_text(table))


# --- what the grader needs (the integration seam) ---------------------------------------------------

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
    print(_("dhlab-assign: made a new secret in {file}: keep it (grading needs it) and never hand it "
            "out.").format(file=DEFAULT_SECRET_FILE.resolve()), file=sys.stderr)
    return secret


def main(argv=None) -> int:
    """``dhlab-assign release ROSTER.csv -o OUT`` (see the module). Returns the exit code. The command
    speaks the teacher's language (``--language``, else ``DHLAB_LANGUAGE``), which is also the
    notebooks' language where the roster has no language column."""
    argv = sys.argv[1:] if argv is None else list(argv)
    try:
        previous = set_language(language_option(argv))
    except DHLabError as exc:
        print(error_line("dhlab-assign", exc), file=sys.stderr, end="")
        return 2
    try:
        with argparse_speaking():              # argparse's own words too ("usage:", "error:")
            return _main(argv)
    finally:
        set_language(previous)


def _main(argv) -> int:
    parser = argparse.ArgumentParser(prog="dhlab-assign", description=_(
        "Release the DH assignment: one personal robot and notebook per student."))
    sub = parser.add_subparsers(dest="command", required=True)
    options = shared(secret=_("the teacher's secret (default {file}, made when missing)").format(
                         file=DEFAULT_SECRET_FILE),
                     language=_("the notebooks' language, en or es, where the roster has no 'language' (or 'idioma') "
                                "column; also this command's (default: DHLAB_LANGUAGE, else en)"))
    rel = sub.add_parser("release", help=_("write one notebook per student of a roster"), parents=[options])
    rel.add_argument("roster", help=_("CSV file with a header and one row per student"))
    rel.add_argument("-o", "--output", required=True, help=_("folder for the notebooks"))
    rel.add_argument("--family", default="puma560",
                     help=_("robot(s) to draw from: a key, a comma-separated list, or 'all' (default puma560)"))
    rel.add_argument("--id-column", default=None,
                     help=_("the roster's id column (default: {names})").format(names=", ".join(ID_COLUMNS)))
    rel.add_argument("--template", default=str(TEMPLATE), help=_("the student notebook to start from"))
    rel.add_argument("--figures", action="store_true",
                     help=_("store the robot's picture in each notebook (about 0.5 s per student more; "
                            "without it the picture is drawn when the student runs the cell)"))
    solutions.add_parser(sub)
    args = parser.parse_args(argv)
    if args.command == "solutions":
        return _solutions(args)
    try:
        secret = _secret(args.secret_file)
        rows = release(args.roster, args.output, secret, args.family, args.id_column, args.template,
                       figures=args.figures, language=args.language)
    except DHLabError as exc:
        print(error_line("dhlab-assign", exc), file=sys.stderr, end="")
        return 2
    families = sorted({r["family"] for r in rows})
    counts = ", ".join(f"{language} {sum(1 for r in rows if r['language'] == language)}"
                       for language in sorted({r["language"] for r in rows}))
    print(_("dhlab-assign: {count} notebooks in {folder} ({families}; {languages}); the teacher's record is in "
            "{record}").format(count=len(rows), folder=args.output, families=", ".join(families), languages=counts,
                               record=Path(args.output) / "_teacher"))
    return 0


def _solutions(args) -> int:
    """``dhlab-assign solutions OUT.ipynb …`` (:mod:`dhlab.grading.release.solutions`)."""
    try:
        out = solutions.run(args, TEMPLATE)
    except DHLabError as exc:
        print(error_line("dhlab-assign", exc), file=sys.stderr, end="")
        return 2
    print(_("dhlab-assign: the solutions are in {file}: never hand them to students.").format(file=out))
    return 0


if __name__ == "__main__":               # pragma: no cover
    sys.exit(main())
