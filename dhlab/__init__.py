"""dhlab: homogeneous transforms and the Denavit-Hartenberg convention, interactively.

Angles are radians in the API (``deg2rad(30)`` converts), lengths in the robot's unit.

>>> import dhlab
>>> puma = dhlab.robots.puma560()
>>> puma.fk(puma.qz).round(5)[:3, 3].tolist()
[0.4521, -0.15005, 0.4318]

``import dhlab`` loads the maths only. The interactive views (``dhlab.teach``, ...), the
symbolic helpers (``dhlab.compact``, ...) and their heavy libraries (matplotlib, ipywidgets,
sympy) are imported the first time a name needs them (:func:`__getattr__`, PEP 562); the
course, the assignment and the grader are never imported by ``import dhlab``.
"""
import importlib
import importlib.util
import sys
import types

from . import ik, lines, mdh, moved, robots, transforms
from .chain import Robot
from .dh import DHRobot, PrismaticDH, RevoluteDH
from .dh_frames import DHAssignment, dh_assignment, dh_from_axes, joint_axes
from .errors import DHLabError
from .i18n import get_language, set_language
from .links import Link, Move, Rot
from .mdh import MDHRobot, PrismaticMDH, RevoluteMDH, to_modified, to_standard
from .table import DHTable
from .transforms import Rx, Ry, Rz, Tr, Tx, Tz, check_rigid, dh_matrix, inv, is_rigid, rpy, trans
from .units import deg, deg2rad, rad, rad2deg  # noqa: F401  (deg, rad: the old names, with a FutureWarning)

# name -> (module, attribute); attribute None: the name is the module itself
_LAZY = {
    "compact": ("dhlab.symbolic", "compact"),
    "legend": ("dhlab.symbolic", "legend"),
    "symbolic": ("dhlab.symbolic", None),
    "assign": ("dhlab.dh_frames", None),
    "dh_frames": ("dhlab.dh_frames", None),
    "views": ("dhlab.views", None),
    "view": ("dhlab.views.view", None),
    "teach": ("dhlab.views.panels.teach", "teach"),
    "robot_view": ("dhlab.views.view", "robot_view"),
    "stepthrough": ("dhlab.views.panels.stepthrough", "stepthrough"),
    "stepthrough_link": ("dhlab.views.panels.stepthrough", "stepthrough_link"),
    "spaces": ("dhlab.views.panels.spaces", "spaces"),
    "show_matrix": ("dhlab.views.matrices", "show_matrix"),
    "projector": ("dhlab.views.projector", "projector"),
}

__all__ = [
    "DHRobot", "RevoluteDH", "PrismaticDH", "Robot", "Link", "Rot", "Move", "DHTable",
    "Rx", "Ry", "Rz", "Tr", "trans", "Tx", "Tz", "dh_matrix", "inv", "is_rigid", "check_rigid", "rpy",
    "deg2rad", "rad2deg", "compact", "legend", "DHLabError", "robots", "ik", "symbolic", "transforms",
    "dh_from_axes", "dh_assignment", "joint_axes", "DHAssignment", "dh_frames", "lines",
    "MDHRobot", "RevoluteMDH", "PrismaticMDH", "to_modified", "to_standard", "mdh",
    "set_language", "get_language",
    "teach", "robot_view", "stepthrough", "stepthrough_link", "spaces", "view", "show_matrix", "projector",
]


def __getattr__(name: str):
    """A lazily imported name (see ``_LAZY``), imported on first use and then kept;
    ``__version__`` is read from the installed package's metadata (pyproject.toml says it)."""
    if name == "__version__":
        # here: only __version__ reads the installed metadata
        from importlib.metadata import PackageNotFoundError, version
        try:
            return version("dhlab")
        except PackageNotFoundError:        # a copy of the sources that was never installed
            return "0+unknown"
    if name not in _LAZY:
        # a subpackage reached as an attribute (``dhlab.course.exercises`` after ``import dhlab``), as
        # before the package was made light
        if name.isidentifier() and not name.startswith("_") and importlib.util.find_spec(f"dhlab.{name}"):
            return importlib.import_module(f"dhlab.{name}")
        raise AttributeError(f"module 'dhlab' has no attribute {name!r}")
    module_name, attribute = _LAZY[name]
    module = importlib.import_module(module_name)
    value = module if attribute is None else getattr(module, attribute)
    globals()[name] = value
    return value


def __dir__():
    return sorted(set(globals()) | set(_LAZY))


class _Package(types.ModuleType):
    """``dhlab`` itself. Importing a submodule makes Python set it as an attribute of its
    package, so ``import dhlab.teach`` (the old path of the module ``dhlab.views.panels.teach``) would
    replace the function ``dhlab.teach`` with a module: the functions of ``_LAZY`` keep their name."""

    def __setattr__(self, name, value):
        if isinstance(value, types.ModuleType) and _LAZY.get(name, (None, None))[1] is not None:
            return
        super().__setattr__(name, value)


sys.modules[__name__].__class__ = _Package
moved.install()
