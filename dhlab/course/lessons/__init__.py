"""What each notebook needs besides its lesson: its print helpers, its figures, the seeds' programs.

Kept out of the notebooks' cells so that a cell shows the idea, not the plotting; one module per notebook
and kind (``lesson_*`` prints and checks, ``figures_*`` draws):

- notebook 2: :mod:`~dhlab.course.lessons.lesson_homogeneous`, :mod:`~dhlab.course.lessons.figures_homogeneous`
- notebook 3: :mod:`~dhlab.course.lessons.lesson_two_dof`
- notebook 4: :mod:`~dhlab.course.lessons.lesson_pr_mechanism`
- notebook 5: :mod:`~dhlab.course.lessons.lesson_dh_convention`, :mod:`~dhlab.course.lessons.figures_dh`,
  :mod:`~dhlab.course.lessons.dh_first_robot`
- notebook 6: :mod:`~dhlab.course.lessons.lesson_dh_examples`, :mod:`~dhlab.course.lessons.figures_dh_examples`
- notebook 7: :mod:`~dhlab.course.lessons.lesson_ssrms`, :mod:`~dhlab.course.lessons.figures_ssrms`,
  :mod:`~dhlab.course.lessons.ssrms_steps` (seed 000's method step by step) and
  :mod:`~dhlab.course.lessons.ssrms_program` (seed 000's C++ program in Python)
- shared drawing pieces: :mod:`~dhlab.course.lessons.figures_common`
"""
