"""The PUMA homework (notebook 8) as one domain: what the student is given, writes and is told.

Seed 000 ends with an exercise: the DH configuration of the PUMA 560 (or of a student's
own robot), in three scored parts — the sketch, each link in its own frame, the
transformations ``T_i = Tz[θ_i, d_i]·Tx[α_i, a_i]``. The notebook and the grader use
this package alike: one reading of the answers, one set of checks.

**What notebook 8 imports** — from here (``from dhlab.assignment import Tz, Tx, …``) or,
in notebooks released before this package existed, from ``dhlab.course.assignment``:

- :mod:`~dhlab.assignment.notebook` — ``Tz``, ``Tx``, ``joint_variables``, ``puma_figure``,
  ``axes_table``, ``points_table``, ``check_part1`` … ``check_part3`` (each a
  :class:`~dhlab.assignment.notebook.PartReport`), ``my_robot_figure``, ``teach``
- :mod:`~dhlab.assignment.inputs` — what ``Tz``, ``Tx`` and ``q_i`` accept (exactly what the grader reads)
- :mod:`~dhlab.assignment.student_robot` — the student's robot built from their answers:
  a :class:`dhlab.Robot`, its figure, a teach panel
- :mod:`~dhlab.assignment.pictures` — the figures (the robot to work on, the student's robot assembled)
- :mod:`~dhlab.assignment.tables` — the axes and points tables, and their one number format

**The robots** — the PUMA 560 of the seed, or a personal robot for every student:

- :mod:`~dhlab.assignment.reference` — the PUMA 560 checked against, with the grader's tolerances
- :mod:`~dhlab.assignment.family` — the family of assignment robots, as published (PUMA 560, Stanford
  arm, Cobra 600, KR5, IRB 140, UR5, LR Mate 200iC)
- :mod:`~dhlab.assignment.model` — an assignment robot: drawn axes, link points, one reference solution
- :mod:`~dhlab.assignment.variants` — a personal variant of a family robot, signed for one student
- :mod:`~dhlab.assignment.notebook_cells` — the seam (``use_variant``: the student's robot becomes the
  notebook's) and the "Your robot" section written into each student's notebook
- :mod:`~dhlab.assignment.solution` — the teacher's solved notebook, computed from the robot (never stored)

**The fair checks** — one code path for the notebook and the grader:

- :mod:`~dhlab.assignment.encode` — the answers as plain JSON, in the student's kernel (imports nothing of dhlab)
- :mod:`~dhlab.assignment.answers` — reading them back (``Answers``, ``Row``), or a clear refusal
- :mod:`~dhlab.assignment.valid_frames` — every valid DH frame of a link (DH frames are not unique)
- :mod:`~dhlab.assignment.checks` — ``check_all`` and the parts' checks: ``analysis`` (shared),
  ``transforms`` (part 3), ``links`` (part 2), ``offsets``, ``chain_motion``

Layers: this package imports the course, the views and the maths below it, never
:mod:`dhlab.grading` (the batch machinery that stages, runs and scores submissions with
it). Its names are loaded on first use: ``import dhlab.assignment.checks`` (the grader)
does not load the notebook's figures.

>>> from dhlab.assignment import Tz, Tx, joint_variables
>>> q1, q2 = joint_variables(2)
>>> Tz(q2 + 90, 0) @ Tx(0, 0.4318)
Tz[q2 + 90, 0]·Tx[0°, 0.4318]
"""
from __future__ import annotations

import importlib

# What notebook 8 imports: the names of :mod:`dhlab.assignment.notebook`, resolved on first use.
__all__ = ["joint_variables", "Tz", "Tx", "JointTerm", "ZFactor", "XFactor", "DHTransform", "DHChain",
           "check_part1", "check_part2", "check_part3", "check_part", "PartReport",
           "axes_table", "points_table", "puma_figure", "robot_of", "teach", "my_robot_figure", "Note",
           "current_robot", "use_variant"]


def __getattr__(name: str):
    if name in __all__:
        value = getattr(importlib.import_module(".notebook", __name__), name)
        globals()[name] = value                  # found once: later lookups do not come here
        return value
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | set(__all__))
