"""``dhlab-assign solutions``: the teacher's solved notebook, computed when asked, never stored.

    dhlab-assign solutions OUT.ipynb [--language es]                       # the PUMA 560
    dhlab-assign solutions OUT.ipynb --student ID --release DIR            # one student's own robot,
    dhlab-assign solutions OUT.ipynb --student ID --roster ROSTER.csv      # ... as released (see below)
                         [--secret-file dhlab-secret.key] [--family F] [--id-column C]

The answers are written from the robot's reference solution
(:func:`dhlab.assignment.solution.solved_notebook`) into the notebook the student has: the course's
student notebook for the PUMA 560, or the student's released notebook, made again from their signed
variant. The variant is the one the release folder recorded for the student (``--release``: its
``_teacher/variants.json``, verified with the secret), else the one ``dhlab-assign release`` draws
for them from the roster and the secret (``--roster``, ``--family`` as released: a first release of
that roster). The notebook is in the student's language (the release's manifest, the roster's
``language`` column, else ``--language``). Any valid DH assignment earns full marks: this is one of them.
"""
from __future__ import annotations

import copy
import json
from pathlib import Path

from ...assignment import variants as V
from ...assignment.notebook_cells import release_notebook
from ...assignment.solution import solved_notebook
from ...errors import DHLabError
from ...i18n import _, default_language
from ..options import DEFAULT_SECRET_FILE, shared
from . import folder
from .comments import with_comments
from .language import (
    in_language,
    in_spanish,
    mark_language,
    roster_languages,
    spanish_comments,
    spanish_texts,
)
from .roster import csv_rows, read_roster

__all__ = ["add_parser", "run", "puma_solutions", "student_solutions"]

def _lines(text: str) -> list:
    return text.splitlines(keepends=True)


def puma_solutions(template: dict, language: str = "en") -> dict:
    """The solved notebook of the PUMA 560: the course's student notebook ``template`` with the answers,
    its text and its code's comments in ``language``."""
    nb = copy.deepcopy(template)
    if language == "es":
        spanish, comments = spanish_texts(template), spanish_comments(template)
        for cell in nb["cells"]:
            if cell.get("id") in spanish:
                cell["source"] = _lines(spanish[cell["id"]])
            elif cell.get("id") in comments:      # before the answers go in: the marker is found in Spanish
                cell["source"] = _lines(with_comments("".join(cell["source"]), comments[cell["id"]]))
    return mark_language(solved_notebook(nb), language)


def student_solutions(template: dict, record: dict, language: str = "en") -> dict:
    """The solved notebook of one student: their released notebook (``record``: the signed variant)
    with the answers for their robot, in ``language``."""
    robot = V.robot_of_variant(V.Variant.from_dict(record["variant"]))
    with in_language(language):
        nb, _notes = release_notebook(template, record, figures=False)
        if language == "es":
            nb = in_spanish(nb, template, record, set())
    return solved_notebook(mark_language(nb, language), robot)


def _released_record(release: Path, student: str, secret: bytes) -> tuple:
    """(the signed record, the language) the release in ``release`` recorded for ``student``,
    verified with ``secret``."""
    teacher_file = folder.records_file(release)
    if not teacher_file.is_file():
        raise DHLabError(_("{folder} has no _teacher/variants.json: name the folder dhlab-assign release "
                           "wrote.").format(folder=release))
    record = folder.load_teacher_records(teacher_file).get(student)
    if record is None:
        raise DHLabError(_("{student!r} is not in the release {folder}.").format(student=student, folder=release))
    if not V.verify(record, student, secret).ok:
        raise DHLabError(_("the variant recorded for {student!r} does not verify with this secret: pass the "
                           "--secret-file the notebooks were released with.").format(student=student))
    rows = [row for row in folder.manifest_rows(folder.manifest_file(release)) if row.get("student_id") == student]
    return record, (rows[0].get("language") or None) if rows else None


def _drawn_record(roster: Path, student: str, secret: bytes, families, id_column, language) -> tuple:
    """(the signed record, the language) ``dhlab-assign release`` gives ``student`` of ``roster``."""
    ids = read_roster(roster, id_column)
    if student not in ids:
        raise DHLabError(_("{student!r} is not in the roster {roster}.").format(student=student, roster=roster))
    variant = V.roster_variants(ids, secret, families)[student]
    languages = roster_languages(csv_rows(roster), ids, default_language(language), roster.name)
    return V.sign_record(variant, student, secret), languages[student]


def add_parser(sub) -> None:
    """The ``solutions`` command of ``dhlab-assign`` (``sub``: its subparsers)."""
    options = shared(secret=_("the teacher's secret the notebooks were released with (default {file})").format(
                         file=DEFAULT_SECRET_FILE),
                     language=_("the notebook's language, en or es, where the release or roster does not say "
                                "(default: DHLAB_LANGUAGE, else en)"))
    sol = sub.add_parser("solutions", help=_("write the solved notebook: the PUMA 560's, or one student's"),
                         parents=[options])
    sol.add_argument("output", type=Path, help=_("the notebook to write (never hand it to students)"))
    sol.add_argument("--student", default=None, help=_("the student whose own robot to solve"))
    sol.add_argument("--release", type=Path, default=None,
                     help=_("the folder 'dhlab-assign release' wrote (its _teacher/ holds the roster's variants)"))
    sol.add_argument("--roster", type=Path, default=None,
                     help=_("the roster the notebooks were released from, to draw the student's robot again"))
    sol.add_argument("--family", default="puma560", help=_("with --roster: the --family it was released with"))
    sol.add_argument("--id-column", default=None, help=_("with --roster: the roster's id column"))
    sol.add_argument("--template", type=Path, default=None, help=_("the student notebook to start from"))


def run(args, template_path: Path) -> Path:
    """Write the solved notebook ``args`` ask for (see the module); returns its path."""
    template = json.loads(Path(args.template or template_path).read_text(encoding="utf-8"))
    if args.student is None:
        if args.release or args.roster:
            raise DHLabError(_("--release and --roster need --student: whose robot to solve."))
        nb = puma_solutions(template, default_language(args.language))
    else:
        if args.release is None and args.roster is None:
            raise DHLabError(_("--student needs --release (the folder the notebooks were released into) "
                               "or --roster (the roster they were released from)."))
        secret = V.load_secret(args.secret_file or DEFAULT_SECRET_FILE)
        if args.release is not None:
            record, language = _released_record(args.release, args.student, secret)
        else:
            record, language = _drawn_record(args.roster, args.student, secret, args.family, args.id_column,
                                             args.language)
        nb = student_solutions(template, record, language or default_language(args.language))
    args.output.parent.mkdir(parents=True, exist_ok=True)
    args.output.write_text(json.dumps(nb, sort_keys=True, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
    return args.output
