"""The checking machinery every exercise of the course is built of. A check never raises on a student's answer.

- :mod:`~dhlab.course.checks.feedback` — :class:`Feedback` (what a check returns) and :class:`Exercise`
  (a check and its hints)
- :mod:`~dhlab.course.checks.reading` — a student's answer read into numbers or a matrix, or a clear refusal
- :mod:`~dhlab.course.checks.judge` — the ladder every check climbs: right as typed, right to the decimals
  typed, a known mistake
- :mod:`~dhlab.course.checks.matrix` — :func:`check_matrix` (symbolic or numeric) and :func:`check_function`
- :mod:`~dhlab.course.checks.values` — :func:`check_value` (a number, a vector) and :func:`check_solutions`
  (several solutions in any order)
- :mod:`~dhlab.course.checks.words` — :func:`check_choice` and :func:`check_terms` (words, a glossary)
- :mod:`~dhlab.course.checks.case_words` — the words of the three cases of x_i, in English and Spanish
  (shared with the grader)
- :mod:`~dhlab.course.checks.options` — the teacher's arguments of a check, checked where they enter
"""
