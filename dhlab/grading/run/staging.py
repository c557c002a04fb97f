"""Every submission is copied, without its outputs, before any of them runs.

The grader reads each submitted file once, at the start of a batch, and keeps a
private copy (a folder only the grader's user can enter) holding only the code of
its code cells, numbered as in Jupyter. So:

* what a notebook printed or drew is not the submission: a correct notebook with
  50 MB of saved outputs is graded like any other (the *code* is limited, with
  :data:`dhlab.grading.run.notebook_code.MAX_CODE_BYTES`);
* the memory one file may take is bounded: it is measured before its JSON is read
  (:func:`dhlab.grading.run.notebook_code.check_notebook_bytes`: at most 100 MB and a million
  JSON values), read once, and a file the grader still cannot read is that file's row (its
  name and why), never the end of the batch;
* a submission that edits a classmate's file, or its own, while the batch runs
  changes nothing: the copies were made before anything ran;
* the gradebook records each file's SHA-256, so ``--resume`` regrades a file that
  changed since its row was written;
* with personal variants (``--secret-file``, :mod:`dhlab.grading.book.grade_variants`) the
  notebook's signed record is verified here, in the grader's process, and the copy's
  "Your robot" cell is rewritten from the variant it will be graded against;
* the notebook's language is read here too (``metadata["dhlab"]["language"]``, else its
  ``dhlab.set_language`` call: :func:`dhlab.grading.release.language.notebook_language`): the
  student's feedback is written in it.
"""
from __future__ import annotations

import hashlib
import json
import os
import tempfile
from dataclasses import dataclass
from pathlib import Path

from ...i18n import _
from ..release.language import notebook_language
from .notebook_code import NotebookError, check_notebook_bytes, code_cells_of, read_notebook_bytes, read_notebook_json

__all__ = ["Staged", "stage", "stage_all", "find_submissions"]


@dataclass
class Staged:
    """One submission, as the grader keeps it."""
    submission: str          # its path under the submissions folder, without .ipynb ('alice/ps8/puma')
    file: str                # the same, with the file's own name ('alice/ps8/puma.ipynb')
    sha256: str              # of the file as handed in
    copy: Path | None        # the code-only copy, None when the file cannot be run (or is not run)
    error: str = ""          # why it cannot be run
    variant: object = None   # with variants: the VariantInfo it is graded by (dhlab.grading.book.grade_variants)
    language: str = ""       # the student's language ('en'/'es'; '' when the notebook does not say)
    # True when ``error`` is the grader's failure (out of memory, disk full), not the file's
    grader_fault: bool = False


def find_submissions(folder: Path) -> list:
    """Every notebook under ``folder``, skipping checkpoints, hidden folders and links."""
    out = []
    for path in sorted(Path(folder).rglob("*.ipynb")):
        parts = path.relative_to(folder).parts
        if any(p.startswith(".") for p in parts) or path.is_symlink() or not path.is_file():
            continue
        out.append(path)
    return out


def stage(path: Path, folder: Path, into: Path, index: int, resolve=None) -> Staged:
    """Read ``path`` once; write its code-only copy into ``into``. ``resolve(notebook,
    submission file)`` (variants): (the notebook to run, its VariantInfo); a VariantInfo
    without a variant means the submission is not run.

    Whatever the file holds, the answer is a :class:`Staged` naming it: a file too big to read
    safely, or one the grader runs out of memory on, is that file's row, and the class is graded."""
    rel = path.relative_to(folder)
    submission, file = rel.with_suffix("").as_posix(), rel.as_posix()
    try:
        return _stage(path, submission, file, into, index, resolve)
    except (MemoryError, RecursionError) as e:
        kind = _("out of memory") if isinstance(e, MemoryError) else _("nested too deeply")
        return Staged(submission, file, "", None, _("the grader could not read this file ({why}); clear its outputs "
                                                    "and try again, or grade it on a machine with more memory").format(
            why=kind), grader_fault=isinstance(e, MemoryError))


def _stage(path: Path, submission: str, file: str, into: Path, index: int, resolve) -> Staged:
    try:
        raw = read_notebook_bytes(path)
    except OSError as e:
        return Staged(submission, file, "", None, _("cannot read the file ({error})").format(error=e.strerror or e))
    except NotebookError as e:
        return Staged(submission, file, "", None, str(e))
    digest = hashlib.sha256(raw).hexdigest()
    try:
        check_notebook_bytes(raw)           # before any JSON is read: the memory one file may take is bounded
    except NotebookError as e:
        return Staged(submission, file, digest, None, str(e))
    try:
        nb, problem = read_notebook_json(raw, checked=True), ""
    except NotebookError as e:
        nb, problem = None, str(e)
    del raw                                 # the notebook is read once: its bytes are not needed any more
    language = notebook_language(nb) or ""
    info = None
    if resolve is not None:
        prepared, info = resolve(nb, file)
        if info.variant is None:
            return Staged(submission, file, digest, None, variant=info, language=language)
        nb = prepared
    try:
        if problem:
            raise NotebookError(problem)
        cells = code_cells_of(nb)
    except NotebookError as e:
        return Staged(submission, file, digest, None, str(e), info, language)
    del nb
    try:
        copy = _write_copy(cells, into / f"{index:05d}.ipynb")
    except OSError as e:
        return Staged(submission, file, digest, None, _("the grader could not write its copy of this file ({error})")
                      .format(error=e.strerror or e), info, language, grader_fault=True)
    return Staged(submission, file, digest, copy, variant=info, language=language)


def _write_copy(cells: list, copy: Path) -> Path:
    """The code-only copy: the code cells at their own numbers, empty markdown cells between."""
    numbered = dict(cells)
    last = max(numbered, default=0)
    nb = {"nbformat": 4, "nbformat_minor": 5, "metadata": {},
          "cells": [{"cell_type": "code", "metadata": {}, "source": numbered[k], "outputs": [],
                     "execution_count": None} if k in numbered else
                    {"cell_type": "markdown", "metadata": {}, "source": ""} for k in range(1, last + 1)]}
    copy.write_text(json.dumps(nb), encoding="utf-8")
    return copy


def stage_all(folder: Path, paths, resolve=None) -> tuple:
    """(the private folder, [Staged]) for every path, all copied before anything runs."""
    into = Path(tempfile.mkdtemp(prefix="dhlab-grade-copies-"))
    os.chmod(into, 0o700)
    return into, [stage(p, Path(folder), into, k, resolve) for k, p in enumerate(paths)]
