"""The gradebook: one row per submission, the CSV file, the feedback files and the run's summary.

* :mod:`~dhlab.grading.book.submission_row` — one submission run and scored: its gradebook row
  (:func:`~dhlab.grading.book.submission_row.grade_submission`);
* :mod:`~dhlab.grading.book.gradebook` — the CSV (rewritten after every submission) and the feedback files,
  in cells a spreadsheet never runs as formulas (:mod:`~dhlab.grading.csvsafe`, shared with the release);
* :mod:`~dhlab.grading.book.grade_variants` — each submission graded against its student's own robot;
* :mod:`~dhlab.grading.book.progress` — the progress line while grading and the summary at its end.
"""
