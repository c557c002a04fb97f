"""Where teachers already grade: ``dhlab-grade export gradescope|try-gradescope|canvas|moodle``.

* :mod:`~dhlab.grading.export.command` — the ``export`` command;
* :mod:`~dhlab.grading.export.gradescope` — the Gradescope autograder zip and its run
  (:mod:`~dhlab.grading.export.wheel` makes its wheel; :mod:`~dhlab.grading.export.gradescope_local`
  runs it here as Gradescope does);
* :mod:`~dhlab.grading.export.lms` — the CSV files Canvas and Moodle import.
"""
