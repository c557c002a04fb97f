"""Grading the PUMA assignment: fair checks, answers as plain data, a sandboxed runner.

* :mod:`dhlab.grading.puma` — the reference robot and the valid DH frames;
* :mod:`dhlab.grading.answers` — what a submission's answers are, as plain data;
* :mod:`dhlab.grading.checks` — the fair checks and their feedback;
* :mod:`dhlab.grading.runner` / :mod:`dhlab.grading.sandbox` — running one notebook
  in a fresh kernel with time, memory and output limits;
* :mod:`dhlab.grading.gradebook` — the CSV and feedback files;
* :mod:`dhlab.grading.generate` — the student notebook from the source notebook.

The command line is :mod:`dhlab.grading.cli` (``dhlab-grade puma SUBMISSIONS_DIR -o gradebook.csv``).
"""
