"""Grading a class: the batch machinery that stages, runs and scores submissions of the PUMA assignment.

What a submission must answer, and the fair checks that score it, are the assignment's
(:mod:`dhlab.assignment`: :mod:`~dhlab.assignment.answers`, :mod:`~dhlab.assignment.checks`,
:mod:`~dhlab.assignment.reference`, :mod:`~dhlab.assignment.variants`); the languages are :mod:`dhlab.i18n`'s.
This package runs them on a whole class, in four sub-packages:

* :mod:`dhlab.grading.run` — running the submissions: every one copied first
  (:mod:`~dhlab.grading.run.staging`), then run in a fresh kernel with time, memory, output and process
  limits, as an unprivileged user in its own mount namespace when the grader is root
  (:mod:`~dhlab.grading.run.launch`, :mod:`~dhlab.grading.run.runner`, :mod:`~dhlab.grading.run.sandbox`,
  :mod:`~dhlab.grading.run.cgroups`, :mod:`~dhlab.grading.run.isolation`, :mod:`~dhlab.grading.run.reaper`,
  :mod:`~dhlab.grading.run.notebook_code`); the grader checks itself first
  (:mod:`~dhlab.grading.run.selfcheck`) and ``dhlab-grade --clean`` removes what a killed one left
  (:mod:`~dhlab.grading.run.cleanup`);
* :mod:`dhlab.grading.book` — the gradebook: one submission's row (:mod:`~dhlab.grading.book.submission_row`),
  the CSV and feedback files (:mod:`~dhlab.grading.book.gradebook`, :mod:`~dhlab.grading.csvsafe`),
  each submission against its student's own robot (:mod:`~dhlab.grading.book.grade_variants`), the progress
  and the summary (:mod:`~dhlab.grading.book.progress`);
* what the gradebook and the release both write: CSV cells a spreadsheet never runs as formulas
  (:mod:`~dhlab.grading.csvsafe`), files written whole or not at all (:mod:`~dhlab.grading.atomic_file`);
* :mod:`dhlab.grading.release` — ``dhlab-assign release``: a personal robot for every student, signed with
  the teacher's secret (:mod:`~dhlab.grading.release.notebooks`, :mod:`~dhlab.grading.release.roster`), in the
  student's language (:mod:`~dhlab.grading.release.language`), from the student notebook, package data
  (``dhlab/grading/template/``, with its Spanish text; :mod:`~dhlab.grading.release.generate` keeps it the
  course's). The teacher's solutions are in no file: ``dhlab-assign solutions`` computes them, for the PUMA
  560 or one student's robot (:mod:`~dhlab.grading.release.solutions`, from
  :mod:`dhlab.assignment.solution`), and so does the grader's self-check (or it reads ``--source``);
* :mod:`dhlab.grading.options` — the options the teacher's commands share (``--language``,
  ``--secret-file``, ``--source``), defined once;
* :mod:`dhlab.grading.export` — where teachers already grade (``dhlab-grade export``): the Gradescope
  autograder (:mod:`~dhlab.grading.export.gradescope`) and the CSV files Canvas and Moodle import
  (:mod:`~dhlab.grading.export.lms`).

The command line is :mod:`dhlab.grading.cli` (``dhlab-grade puma SUBMISSIONS_DIR -o gradebook.csv
[--secret-file KEY --release DIR]``, also ``python -m dhlab.grading.cli``); one run's state, shared by its
workers, is :mod:`dhlab.grading.batch`. Within the package the sub-packages
import one another only through their public names; ``run`` reads nothing of ``book`` or ``export``.
"""
