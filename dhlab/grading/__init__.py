"""Grading the PUMA assignment: fair checks, answers as plain data, a sandboxed runner.

* :mod:`dhlab.grading.puma` / :mod:`dhlab.grading.frames` — the reference robot and the valid DH frames;
* :mod:`dhlab.grading.answers` — what a submission's answers are, as plain data;
* :mod:`dhlab.grading.checks` — the fair checks and their feedback;
* :mod:`dhlab.grading.part2` — each link in the frame the student's own transformations give it;
  :mod:`dhlab.grading.part3` — each transformation judged against the frame the student meant
  (one slip, one item); :mod:`dhlab.grading.chain_motion` — the whole chain, moving;
* :mod:`dhlab.grading.staging` — every submission copied, code only, before any runs;
* :mod:`dhlab.grading.runner` / :mod:`dhlab.grading.sandbox` — running one notebook
  in a fresh kernel with time, memory, output and process limits, as an unprivileged
  user in its own mount namespace when the grader is root (:mod:`dhlab.grading.notebook_code`
  reads the notebook's code first, with limits, and lists what it does to dhlab);
* :mod:`dhlab.grading.isolation` — the kernels' users, ending every process a submission
  started, and the check that the installed dhlab is unchanged;
* :mod:`dhlab.grading.gradebook` — the CSV (rewritten after every submission) and feedback files;
* :mod:`dhlab.grading.variants` / :mod:`dhlab.grading.release` — a personal robot for every student,
  signed with the teacher's secret (``dhlab-assign release``), and
  :mod:`dhlab.grading.grade_variants` — each submission graded against its student's own robot;
* :mod:`dhlab.grading.language` — the grader's two languages (the teacher's for the gradebook and the
  command line, each student's for the feedback: ``--language``, ``DHLAB_LANGUAGE``) and
  :mod:`dhlab.grading.release_language` — each released notebook in its student's language (a roster
  column ``language``/``idioma``), the Spanish text from the Spanish edition's catalog of notebook 8;
* :mod:`dhlab.grading.generate` — the student notebook from the teacher's source notebook (with the
  solutions: not in the package, but ``tools/teacher/08_puma_assignment.ipynb`` of the course's repository,
  or ``--source``); the student notebook is package data (``dhlab/grading/template/``, dhlab-assign's start);
* :mod:`dhlab.grading.selfcheck` — one kernel started as the submissions' will be, before any runs;
  :mod:`dhlab.grading.cleanup` — ``dhlab-grade --clean``, what a killed grader left;
* where teachers already grade (``dhlab-grade export``, :mod:`dhlab.grading.export`):
  :mod:`dhlab.grading.gradescope` (the autograder zip and its run; :mod:`dhlab.grading.wheel` makes
  its wheel; :mod:`dhlab.grading.gradescope_local` runs it here as Gradescope does) and
  :mod:`dhlab.grading.lms` (CSV files Canvas and Moodle import).

The command line is :mod:`dhlab.grading.cli` (``dhlab-grade puma SUBMISSIONS_DIR -o gradebook.csv
[--secret-file KEY --release DIR]``); :mod:`dhlab.grading.launch` starts its runner processes,
:mod:`dhlab.grading.rows` makes one submission's gradebook row and :mod:`dhlab.grading.progress`
shows the run's progress and summary.
"""
