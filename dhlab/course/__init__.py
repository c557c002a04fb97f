"""The course's own content: what notebooks 1-7 and 9 import, besides the maths and the views.

Three sub-packages, each importing only the ones above it in this list (and the layers below ``course``):

- :mod:`dhlab.course.checks` — the checking machinery: :class:`~dhlab.course.checks.feedback.Feedback`
  and :class:`~dhlab.course.checks.feedback.Exercise`, reading a student's answer (``reading``), the
  judging ladder (``judge``), and the checks of a matrix (``matrix``), of numbers (``values``) and of
  words (``words``, ``case_words``); ``options`` checks the teacher's arguments
- :mod:`dhlab.course.exercises` — every exercise of the course in one registry: ``exercise("1.1")`` …
  ``exercise("7.3")``, ``available()``; one module per notebook or subject (``basics``, ``homogeneous``,
  ``first_robots``, ``pr_mechanism``, ``dh_rules``, ``dh_tables``, ``dh_links``, ``ssrms``, and
  ``dh_common``, what the DH checks share)
- :mod:`dhlab.course.lessons` — each notebook's helpers and figures (``lesson_*``, ``figures_*``,
  ``dh_first_robot``, ``ssrms_steps``, ``ssrms_program``)

and :mod:`dhlab.course.predict` (notebooks 5 and 6: predict, then check, then reveal).

The course imports neither :mod:`dhlab.assignment` nor :mod:`dhlab.grading`. Three old names still
import (:mod:`dhlab.moved` answers them, no file here): ``dhlab.course.exercises_dh`` (now
:mod:`dhlab.course.exercises`; it warns, and goes in 0.2), and, for good, ``dhlab.course.assignment`` and
``dhlab.course.family_notebook``, which notebooks already released to students import (the PUMA
assignment is its own package, :mod:`dhlab.assignment`).
"""
