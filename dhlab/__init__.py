"""dhlab: homogeneous transforms and the Denavit-Hartenberg convention, interactively.

Angles are radians in the API (``deg2rad(30)`` converts), lengths in the robot's unit.

>>> import dhlab
>>> puma = dhlab.robots.puma560()
>>> puma.fk(puma.qz).round(5)[:3, 3].tolist()
[0.4521, -0.15005, 0.4318]
"""
from . import assign, ik, lines, mdh, robots, symbolic, transforms
from .assign import DHAssignment, dh_assignment, dh_from_axes, joint_axes
from .chain import Link, Move, Robot, Rot
from .dh import DHRobot, PrismaticDH, RevoluteDH
from .mdh import MDHRobot, PrismaticMDH, RevoluteMDH, to_modified, to_standard
from .symbolic import compact, legend
from .table import DHTable
from .transforms import Rx, Ry, Rz, Tr, Tx, Tz, check_rigid, dh_matrix, inv, is_rigid, rpy, trans
from .i18n import get_language, set_language
from .units import deg, deg2rad, rad, rad2deg
from .validation import DHLabError

__all__ = [
    "DHRobot", "RevoluteDH", "PrismaticDH", "Robot", "Link", "Rot", "Move", "DHTable",
    "Rx", "Ry", "Rz", "Tr", "trans", "Tx", "Tz", "dh_matrix", "inv", "is_rigid", "check_rigid", "rpy",
    "deg2rad", "rad2deg", "deg", "rad", "compact", "legend", "DHLabError", "robots", "ik", "symbolic", "transforms",
    "dh_from_axes", "dh_assignment", "joint_axes", "DHAssignment", "assign", "lines",
    "MDHRobot", "RevoluteMDH", "PrismaticMDH", "to_modified", "to_standard", "mdh",
    "set_language", "get_language",
]
__version__ = "0.1.0"

# The interactive views (imported here, after the maths, so that ``dhlab.teach`` is the
# function even once the submodule of the same name has been imported).
from .views import view
from .views.projector import projector
from .views.matrices import show_matrix
from .views.spaces import spaces
from .views.stepthrough import stepthrough, stepthrough_link
from .views.teach import teach
from .views.view import robot_view

__all__ += ["teach", "robot_view", "stepthrough", "stepthrough_link", "spaces", "view", "show_matrix",
            "projector"]

# The package was split into maths (here), views/, course/ and grading/. The old module paths
# (``from dhlab.teach import teach``, ``import dhlab.exercises``, ``python -m dhlab.grade``) still
# work: each names the module at its new place.
import sys as _sys

from .course import assignment, exercises, exercises_dh
from .grading import cli as _grade_cli
from .views import livefigure, panel
from .views import spaces as _spaces_module
from .views import stepthrough as _stepthrough_module
from .views import teach as _teach_module

for _old, _module in {
    "view": view, "livefigure": livefigure, "panel": panel, "spaces": _spaces_module,
    "stepthrough": _stepthrough_module, "teach": _teach_module, "exercises": exercises,
    "exercises_dh": exercises_dh, "assignment": assignment, "grade": _grade_cli,
}.items():
    _sys.modules[f"{__name__}.{_old}"] = _module
del _old, _module, _sys
