"""Releasing the assignment: ``dhlab-assign release``, one notebook per student, each with its own robot.

* :mod:`~dhlab.grading.release.notebooks` — the release: a variant drawn and signed for every student
  (its :func:`~dhlab.grading.release.notebooks.main` is ``dhlab-assign``; ``python -m dhlab.grading.release``);
* :mod:`~dhlab.grading.release.roster` — the roster's student ids, and a safe file name for each;
* :mod:`~dhlab.grading.release.folder` — a release folder's signed records and manifest, read back;
* :mod:`~dhlab.grading.release.language` — each released notebook in its student's language;
* :mod:`~dhlab.grading.release.comments` — a code cell's comments, found and translated (the code stays);
* :mod:`~dhlab.grading.release.generate` — the student notebook (package data, ``dhlab/grading/template/``)
  kept the course's, and made again from a solved notebook (``python -m dhlab.grading.release.generate``);
* :mod:`~dhlab.grading.release.solutions` — ``dhlab-assign solutions``: the teacher's solved notebook,
  computed (no file holds it), for the PUMA 560 or one student's own robot.
"""
from __future__ import annotations

__all__ = ["main"]


def main(argv=None) -> int:
    """``dhlab-assign`` (:func:`dhlab.grading.release.notebooks.main`; imported only when it runs)."""
    from .notebooks import main as release_main
    return release_main(argv)
