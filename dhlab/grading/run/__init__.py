"""Running submissions: every notebook copied, then run alone in a fresh, limited kernel.

* :mod:`~dhlab.grading.run.staging` — every submission copied, code only, before any runs;
* :mod:`~dhlab.grading.run.notebook_code` — a notebook's code read with limits, and what it does to dhlab;
* :mod:`~dhlab.grading.run.launch` — one runner process per submission
  (:func:`~dhlab.grading.run.launch.run_submission`);
* :mod:`~dhlab.grading.run.runner` — that process: one notebook in a fresh kernel, its answers as plain data
  (started as a script, it reads only its neighbours ``kernel.py``, ``read_answers.py``, ``notebook_code.py``,
  ``sandbox.py``, ``cgroups.py`` and ``dhlab/assignment/encode.py``, never the whole package);
  :mod:`~dhlab.grading.run.kernel` — the student's kernel, driven cell by cell;
  :mod:`~dhlab.grading.run.read_answers` — the answers written as JSON by the kernel, and read back;
* :mod:`~dhlab.grading.run.sandbox` — the kernel's own limits and, as root, its private root;
  :mod:`~dhlab.grading.run.cgroups` — a control group per submission;
* :mod:`~dhlab.grading.run.isolation` — the kernels' users, ending every process a submission started, and
  the check that the installed dhlab is unchanged; :mod:`~dhlab.grading.run.reaper` — no daemon outlives a run;
* :mod:`~dhlab.grading.run.selfcheck` — the teacher's solution run first, as a submission will be;
* :mod:`~dhlab.grading.run.cleanup` — ``dhlab-grade --clean``, what a killed grader left.
"""
