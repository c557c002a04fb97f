"""What a release folder keeps for the teacher, read back: ``_teacher/variants.json`` (every
student's signed record) and ``_teacher/manifest.csv`` (which file is whose, and in which language).
``dhlab-assign release`` reads them to add to a release, ``dhlab-assign solutions`` to solve one
student's robot, and the grader (:mod:`dhlab.grading.book.grade_variants`) to grade against them.
"""
from __future__ import annotations

import csv
import json
from pathlib import Path

from ...errors import DHLabError
from ..csvsafe import restored

__all__ = ["records_file", "manifest_file", "load_teacher_records", "manifest_rows"]


def records_file(release) -> Path:
    return Path(release) / "_teacher" / "variants.json"


def manifest_file(release) -> Path:
    return Path(release) / "_teacher" / "manifest.csv"


def load_teacher_records(path) -> dict:
    """The teacher's copy of every signed record (``release/_teacher/variants.json``): id -> record."""
    try:
        records = json.loads(Path(path).read_text(encoding="utf-8"))
    except (OSError, json.JSONDecodeError) as exc:
        raise DHLabError(f"cannot read the teacher's variants {str(path)!r}: {exc}.") from None
    if not isinstance(records, dict):
        raise DHLabError(f"{str(path)!r} is not the teacher's variants file (a JSON object id -> record).")
    return records


def manifest_rows(path) -> list:
    """The rows of a manifest ``dhlab-assign release`` wrote (dicts; [] when there is none, with or
    without a BOM), its cells unescaped (:mod:`dhlab.grading.csvsafe`)."""
    try:
        with open(path, newline="", encoding="utf-8-sig") as f:
            return [{k: restored(v) for k, v in row.items() if k is not None} for row in csv.DictReader(f)]
    except (OSError, csv.Error, UnicodeDecodeError):
        return []
