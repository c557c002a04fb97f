"""The gradebook (a CSV) and one feedback file per submission, written atomically.

A file is written to a temporary name in the same folder and then renamed over the
old one (:func:`os.replace`), so a reader — or a second grading run — never sees a
half-written gradebook, even if the grader is stopped in the middle. The grader
rewrites the gradebook after **every** submission, so a batch that is killed keeps
every finished row, and ``--resume`` (:func:`read_csv`) continues from them.

Each row names the submitted file (``file``), its SHA-256 and its feedback file,
whose name is made safe and unique by a hash of the submission's path
(:func:`feedback_filename`): two students never share a feedback file.

>>> status_text({"errors": [[4, "NameError", "name 'T9' is not defined"]]}, report_answered=True)
"error in cell 4 (NameError: name 'T9' is not defined)"
"""
from __future__ import annotations

import csv
import hashlib
import io
import os
import re
import tempfile
import unicodedata
from pathlib import Path

__all__ = ["COLUMNS", "VARIANT_COLUMNS", "PART_COLUMNS", "write_atomic", "write_csv", "read_csv", "feedback_filename", "status_text",
           "feedback_text"]

PART_COLUMNS = {"part1": "part1_sketch", "part2": "part2_links", "part3": "part3_transforms"}
COLUMNS = ["submission", "score", "max_score", "status", *PART_COLUMNS.values(), "seconds", "feedback",
           "file", "sha256"]
# with personal variants (--secret-file) the gradebook has these too, at the end, so that a
# reader of the first columns reads it as before (see dhlab.grading.grade_variants)
VARIANT_COLUMNS = COLUMNS + ["variant_status", "variant_source", "variant_family", "variant_id", "signed_for"]


def write_atomic(path, text: str) -> None:
    """Write ``text`` to ``path`` so that the file is either the old one or the new one."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "w", encoding="utf-8", newline="") as f:
            f.write(text)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def write_csv(path, rows, columns=COLUMNS) -> None:
    """The gradebook: one row per submission (dicts with the keys of ``columns``:
    :data:`COLUMNS`, or :data:`VARIANT_COLUMNS` when grading variants)."""
    buffer = io.StringIO()
    writer = csv.DictWriter(buffer, fieldnames=columns, extrasaction="ignore", restval="")
    writer.writeheader()
    for row in sorted(rows, key=lambda r: r["submission"]):
        writer.writerow(row)
    write_atomic(path, buffer.getvalue())


def read_csv(path, columns=COLUMNS) -> list:
    """The rows of an existing gradebook (for ``--resume``); [] when there is none or it
    is not a gradebook of these columns (one graded with variants is not resumed without
    them, nor the other way round: every row is graded again)."""
    try:
        with open(path, newline="", encoding="utf-8") as f:
            reader = csv.DictReader(f)
            if reader.fieldnames != list(columns):
                return []
            return [dict(row) for row in reader]
    except (OSError, csv.Error, UnicodeDecodeError):
        return []


def feedback_filename(submission: str) -> str:
    """A safe, unique file name for a submission's feedback: readable letters of its path
    and 8 hex digits of its hash (so 'Ana María' and 'Ana_María' get different files,
    on any file system, case-insensitive ones included).

    >>> feedback_filename("alice/ps1/puma")
    'alice__ps1__puma-a78cf37e.txt'
    """
    text = unicodedata.normalize("NFKD", submission)
    text = "".join(ch for ch in text if not unicodedata.combining(ch))
    name = re.sub(r"[^A-Za-z0-9._-]+", "_", text.replace("/", "__")).strip("._") or "submission"
    digest = hashlib.sha256(submission.encode("utf-8", "surrogateescape")).hexdigest()[:8]
    return f"{name[:120]}-{digest}.txt"


def _cells(numbers) -> str:
    numbers = list(numbers)
    return ("cell " if len(numbers) == 1 else "cells ") + ", ".join(str(n) for n in numbers)


def status_text(run: dict, report_answered: bool, answers_problem: str = "") -> str:
    """One line for the gradebook's status column: 'ok', or every reason, joined by '; '."""
    reasons = []
    if run.get("notebook_error"):
        reasons.append(f"invalid notebook: {run['notebook_error']}")
    if run.get("grader_error"):
        reasons.append(f"grader error: {run['grader_error']}")
    memory = [e for e in run.get("errors", []) if e[1] == "MemoryError"]
    others = [e for e in run.get("errors", []) if e[1] != "MemoryError"]
    if memory:
        reasons.append(f"memory limit reached in {_cells(e[0] for e in memory)} (MemoryError)")
    if others:
        first = others[0]
        detail = f" ({first[1]}: {first[2]})" if first[2] else f" ({first[1]})"
        reasons.append(f"error in {_cells(e[0] for e in others)}" + (detail if len(others) == 1 else
                                                                     f", first{detail}"))
    if run.get("timeouts"):
        reasons.append(f"timeout: {_cells(run['timeouts'])} stopped at the time limit")
    if run.get("output_capped"):
        sizes = ", ".join(f"{b / 1e6:.1f} MB in cell {c}" for c, b in run["output_capped"])
        reasons.append(f"output limit: printed {sizes} (stopped, run again without it)")
    if run.get("kernel_died"):
        reasons.append(f"kernel died in {_cells(run['kernel_died'])} (run again without it)")
    if run.get("stuck"):
        reasons.append(f"{_cells(run['stuck'])} could not be interrupted (run again without it)")
    if run.get("runner_killed"):
        reasons.append(f"the grader's runner was killed in {_cells(run['runner_killed'])} (run again without it)")
    if run.get("out_of_time"):
        reasons.append("time limit for the whole notebook reached")
    if run.get("answers_error"):
        reasons.append(f"answers not read: {run['answers_error']}")
    if answers_problem:
        reasons.append(answers_problem)
    if run.get("tampering"):
        reasons.append(f"modifies dhlab, ignored ({run['tampering'][0]})")
    if not report_answered and not run.get("notebook_error"):
        reasons.append("not answered")
    status = "; ".join(reasons) or "ok"
    if run.get("isolation_note"):
        status += f" ({run['isolation_note']})"
    return status


def feedback_text(submission: str, run: dict, report, status: str, robot_lines=()) -> str:
    """The feedback file of one submission: the score, what happened, every check
    (``robot_lines``: which robot it was graded against, with variants)."""
    lines = [f"Submission: {submission}", f"File: {run.get('file', submission + '.ipynb')}", f"Status: {status}", ""]
    lines += list(robot_lines)
    lines.append(report.text())
    details = []
    for number, ename, evalue in run.get("errors", []):
        details.append(f"cell {number} raised {ename}" + (f": {evalue}" if evalue else ""))
    if run.get("skipped"):
        details.append(f"the notebook was run again without {_cells(run['skipped'])}")
    if run.get("tampering"):
        details += [f"{t} (this has no effect: the grader checks your answers in its own process)"
                    for t in run["tampering"]]
    if details:
        lines += ["How your notebook ran:", *[f"  - {d}" for d in details], ""]
    lines.append("Your answers were read from the variables n_links, n_joints, joint_types, x_cases, "
                 f"link_points, T1…T{report.n} and chain after your notebook ran, and checked by the grader "
                 f"against {'your ' + report.robot if report.robot != 'PUMA 560' else 'the PUMA 560'}.")
    return "\n".join(lines) + "\n"
