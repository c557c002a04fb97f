"""The course's own content: the exercises checked in the notebooks and the PUMA assignment.

- :mod:`~dhlab.course.exercises` — the checks of notebooks 1-4 and the feedback machinery
- :mod:`~dhlab.course.exercises_dh` — the DH exercises of notebooks 5-7
- :mod:`~dhlab.course.assignment` — what the PUMA assignment notebook imports
"""
