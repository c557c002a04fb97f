"""Where notebook 8 imported the assignment from until it became its own package.

Released student notebooks do ``from dhlab.course.assignment import (Tz, Tx, …)``: this
name keeps them working. New code imports :mod:`dhlab.assignment`. (The one import from
``course/`` up into ``assignment/``, for the notebooks already in students' hands.)
"""
from dhlab.assignment.notebook import *  # noqa: F401,F403
from dhlab.assignment.notebook import __all__  # noqa: F401
