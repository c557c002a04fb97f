"""The course's own content: the exercises checked in the notebooks and the assignment.

The feedback machinery, shared by every exercise:

- :mod:`~dhlab.course.feedback` — :class:`Feedback` and :class:`Exercise` (a check never raises)
- :mod:`~dhlab.course.answers` — reading a student's answer into numbers or a matrix, or a clear refusal
- :mod:`~dhlab.course.matrix_checks`, :mod:`~dhlab.course.value_checks`,
  :mod:`~dhlab.course.word_checks` — checking a matrix, numbers and vectors, words

The exercises:

- :mod:`~dhlab.course.exercises` — notebooks 1-4
- :mod:`~dhlab.course.exercises_dh` — notebooks 5-7 (``exercises_dh_frames``, ``_rules``, ``_links``,
  ``_ssrms``, ``_common``)

The assignment:

- :mod:`~dhlab.course.assignment` — what the PUMA assignment notebook imports
- :mod:`~dhlab.course.family` — the family of assignment robots (PUMA 560 and six other arms), with
  ``family_model`` (what the student is given), ``family_views`` (pictures, tables) and
  ``family_notebook`` (a student's own robot in the notebook)
"""
