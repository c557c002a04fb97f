"""Grading personal variants: whose submission it is, which robot to grade it against.

``dhlab-grade puma SUBMISSIONS --secret-file KEY [--release DIR] [--fallback roster|none]``
grades each submission against the student's own robot (:mod:`dhlab.assignment.variants`).
Everything here runs in the grader's process while the submissions are staged, before
any student code runs:

1. **Who handed it in.** With ``--release`` (the folder ``dhlab-assign release`` wrote):
   the first of these that is a roster id, or the file name the release gave a roster id
   (``_teacher/manifest.csv``): the folder after ``submitted/`` in nbgrader's layout
   (``submitted/ana/ps8/08_puma_assignment.ipynb`` → ``ana``: the folder is the student, so
   ana's folder holding ``bob.ipynb`` is ana's), then the submission file's stem
   (``ana.ipynb`` → ``ana``). None of them: the status ``unknown_student`` and no marks
   (rename the file ``<id>.ipynb``). Without ``--release``: the folder after ``submitted/``
   when there is one, else the file's stem.
2. **Which variant.** The notebook's signed record (``metadata["dhlab"]``) is verified
   for that student with the teacher's secret (:func:`dhlab.assignment.variants.verify`):
   ``ok``, ``missing``, ``tampered`` or ``other_student`` (a classmate's notebook: the
   record names whose). Only an ``ok`` record is graded as it is. Otherwise, with
   ``--fallback roster`` (the default with ``--release``) the submission is graded
   against the variant released to that student (``_teacher/variants.json``), and the
   status says so; with ``--fallback none`` (the only choice without ``--release``) it
   gets no marks, and the status says why.
3. **The robot cell.** The staged copy's locked "Your robot" cell is rewritten from the
   variant chosen (:func:`dhlab.assignment.notebook_cells.prepare_submission`), so whatever
   the student did to it, the kernel builds that robot; the grader scores the answers
   against the same robot (``check_all(answers, ref=robot)``).

The gradebook gets five more columns (:data:`COLUMNS`): ``variant_status``,
``variant_source`` (notebook / roster / none), ``variant_family``, ``variant_id``
(the first 12 hex digits of :func:`~dhlab.assignment.variants.fingerprint`, as in the
release's manifest) and ``signed_for`` (whose signature the notebook carries).
"""
from __future__ import annotations

import unicodedata
from dataclasses import dataclass, field
from pathlib import Path, PurePosixPath

from ...assignment import variants as V
from ...assignment.notebook_cells import prepare_submission
from ...errors import DHLabError
from ...i18n import N_, _
from ..release.folder import load_teacher_records, manifest_file, manifest_rows, records_file
from ..release.roster import safe_filename

__all__ = ["COLUMNS", "VariantSetup", "VariantInfo", "setup", "identify", "resolve", "columns", "status_note",
           "feedback_lines", "FALLBACKS", "release_files"]

COLUMNS = ["variant_status", "variant_source", "variant_family", "variant_id", "signed_for"]
FALLBACKS = ("roster", "none")
ID_DIGITS = 12


@dataclass
class VariantSetup:
    """What the grader knows about the class: the secret and, with ``--release``, the roster."""
    secret: bytes
    records: dict = field(default_factory=dict)      # student id -> the record released to them
    files: dict = field(default_factory=dict)        # release file stem -> student id
    fallback: str = "none"
    release: Path | None = None

    @property
    def roster_ids(self) -> list:
        return list(self.records)


@dataclass
class VariantInfo:
    """The variant one submission is graded against, and how it was chosen."""
    student: str | None
    status: str                     # ok / missing / tampered / other_student / unknown_student
    source: str                     # notebook / roster / none
    message: str
    variant: object = None          # the Variant graded against (None: not graded)
    signed_for: str = ""

    @property
    def robot(self):
        return V.robot_of_variant(self.variant) if self.variant is not None else None


# --- the class: secret, release folder --------------------------------------------------------------

def setup(secret_file, release=None, fallback=None) -> VariantSetup:
    """Read the secret and the release folder, with clear errors (a :class:`DHLabError`)."""
    secret = V.load_secret(secret_file)
    fallback = fallback or ("roster" if release is not None else "none")
    if fallback not in FALLBACKS:
        raise DHLabError(_("--fallback {value!r}: choose one of {choices}.").format(
            value=fallback, choices=", ".join(FALLBACKS)))
    if release is None:
        if fallback == "roster":
            raise DHLabError(_("--fallback roster needs --release: the folder dhlab-assign release wrote "
                               "(its _teacher/variants.json holds every student's variant)."))
        return VariantSetup(secret, fallback=fallback)
    release = Path(release)
    teacher_file = records_file(release)
    if not release.is_dir():
        raise DHLabError(_("--release {folder!r} is not a folder: pass the folder that "
                           "'dhlab-assign release ROSTER.csv -o FOLDER' wrote.").format(folder=str(release)))
    if not teacher_file.is_file():
        raise DHLabError(_("--release {folder!r} has no _teacher/variants.json: pass the folder that "
                           "'dhlab-assign release ROSTER.csv -o FOLDER' wrote (not the students' copies).").format(
            folder=str(release)))
    records = load_teacher_records(teacher_file)
    bad = [sid for sid, record in records.items() if not V.verify(record, sid, secret).ok]
    if records and len(bad) == len(records):
        raise DHLabError(_("none of the {count} variants in {file} verifies with the secret in {secret!r}: is "
                           "it the secret the notebooks were released with?").format(
            count=len(records), file=teacher_file, secret=str(secret_file)))
    if bad:
        raise DHLabError(_("{bad} of the {count} variants in {file} do not verify with the secret (first: "
                           "{first}): the teacher's file was changed; release the class again, or restore the "
                           "file from a backup.").format(bad=len(bad), count=len(records), file=teacher_file,
                                                         first=", ".join(map(repr, bad[:5]))))
    if not records:
        raise DHLabError(_("{file} lists no students: release the roster again.").format(file=teacher_file))
    return VariantSetup(secret, records, release_files(release, records), fallback, release)


def release_files(release: Path, records: dict) -> dict:
    """Release file stem -> student id, from the manifest (ids with unusual characters get
    another file name, see :func:`dhlab.grading.release.roster.safe_filename`)."""
    files = {safe_filename(sid): sid for sid in records}
    for row in manifest_rows(manifest_file(release)):     # none: the names derived from the ids are enough
        sid, file = row.get("student_id"), row.get("file")
        if sid in records and file:
            files[unicodedata.normalize("NFC", PurePosixPath(file).stem)] = sid
    return files


# --- one submission ------------------------------------------------------------------------------------

def _nbgrader_student(parts) -> str | None:
    """The folder after ``submitted/`` (nbgrader's submitted/<student>/<assignment>/<file>)."""
    for i, part in enumerate(parts[:-1]):
        if part == "submitted" and i + 1 < len(parts) - 1:
            return parts[i + 1]
    return None


def identify(vs: VariantSetup, rel_path) -> tuple:
    """(student id or None, a sentence saying how), for a submission at ``rel_path`` (its
    path under the submissions folder). See the module for the rule."""
    parts = PurePosixPath(str(rel_path).replace("\\", "/")).parts
    stem = PurePosixPath(parts[-1]).stem
    folder = _nbgrader_student(parts)
    if not vs.records:
        return ((folder, _("the folder submitted/{folder}/").format(folder=folder)) if folder
                else (stem, _("the file name")))
    if folder:                                  # nbgrader's layout: the folder is the student, whatever the file
        student = _roster_id(vs, folder)
        return (student, _("the folder submitted/{folder}/").format(folder=folder)) if student else (
            None, _("the folder {folder!r} matches no student of the roster").format(folder=folder))
    student = _roster_id(vs, stem)
    if student:
        return student, _("the file name")
    return None, _("the file name {stem!r} matches no student of the roster").format(stem=stem)


def _roster_id(vs: VariantSetup, name: str) -> str | None:
    """The roster id ``name`` is (an id, or the file name the release gave one), else None.
    Compared composed (NFC): a Mac writes 'é' as 'e' + a combining accent (NFD) in file names,
    and a roster typed on one may hold its ids so."""
    composed = unicodedata.normalize("NFC", name)
    for candidate in dict.fromkeys((name, composed)):
        if candidate in vs.records:
            return candidate
        if candidate in vs.files:
            return vs.files[candidate]
    return next((sid for sid in vs.records if unicodedata.normalize("NFC", sid) == composed), None)


def resolve(vs: VariantSetup, nb, rel_path) -> tuple:
    """(the notebook to run or None, :class:`VariantInfo`) for the submitted notebook ``nb``
    (a dict) at ``rel_path``. None: the submission is not run (no variant to grade it against)."""
    student, how = identify(vs, rel_path)
    record = nb.get("metadata", {}).get(V.METADATA_KEY) if isinstance(nb, dict) else None
    claimed = record.get("student_id") if isinstance(record, dict) else None
    if student is None:
        names = " " + _("(its record names {claimed!r})").format(claimed=claimed) if isinstance(claimed, str) else ""
        return None, VariantInfo(None, "unknown_student", "none", _(
            "cannot tell whose submission this is: {how}{names}; name the file <student id>.ipynb as in the release "
            "(or nbgrader's submitted/<id>/…)").format(how=how, names=names))
    check = V.verify(record, student, vs.secret, vs.roster_ids)
    signed_for = check.signed_for or ""
    if check.ok:
        signed = _("signed for {student!r} ({how})").format(student=student, how=how)
        info = VariantInfo(student, "ok", "notebook", signed, check.variant, signed_for)
    elif vs.fallback == "roster" and student in vs.records:
        variant = V.Variant.from_dict(vs.records[student]["variant"])
        info = VariantInfo(student, check.status, "roster", _("{why}; graded against the roster's variant for "
                                                              "{student!r}").format(why=check.message, student=student),
                           variant, signed_for)
    else:
        return None, VariantInfo(student, check.status, "none", _("{why}; not graded (--fallback none)").format(
            why=check.message), None, signed_for)
    if not isinstance(nb, dict) or not isinstance(nb.get("cells"), list):
        return nb, info                                    # not a notebook: the runner says so
    return prepare_submission(nb, info.variant, student), info


# --- what the gradebook and the feedback say --------------------------------------------------------

def columns(info: VariantInfo | None) -> dict:
    """The gradebook's variant columns of one row."""
    if info is None:
        return {c: "" for c in COLUMNS}
    v = info.variant
    return {"variant_status": info.status, "variant_source": info.source,
            "variant_family": v.family if v is not None else "",
            "variant_id": V.fingerprint(v)[:ID_DIGITS] if v is not None else "", "signed_for": info.signed_for}


# the status column's note on a variant that did not verify ('variant missing: …';
# dhlab.grading.book.progress counts them)
VARIANT_NOTES = {"unknown_student": N_("student not identified: {message}"),
                 "missing": N_("variant missing: {message}"), "tampered": N_("variant tampered: {message}"),
                 "other_student": N_("variant other_student: {message}")}


def status_note(info: VariantInfo | None) -> str:
    """The variant's part of the status column ('' when the notebook's own variant verified)."""
    if info is None or info.status == "ok":
        return ""
    note = _(VARIANT_NOTES.get(info.status, N_("variant {status}: {message}")))
    return note.format(status=info.status, message=info.message)


def feedback_lines(info: VariantInfo | None) -> list:
    """The feedback file's lines about the robot graded against."""
    if info is None:
        return []
    if info.variant is None:
        return [_("Robot: none — {note}").format(note=status_note(info)), ""]
    robot = info.robot
    where = {"notebook": _("the variant signed for you in your notebook"),
             "roster": _("the variant your teacher released to you")}[info.source]
    lines = [_("Robot graded against: your {robot} ({id}), {where}.").format(
        robot=V.shown_name(robot.name), id=V.fingerprint(info.variant)[:ID_DIGITS], where=where)]
    if info.status != "ok":
        lines.append(_("Variant check: {status} — {message}.").format(status=info.status, message=info.message))
    return lines + [""]
