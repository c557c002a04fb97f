"""Old module paths that moved, still importable: ``import dhlab.teach``, ``python -m dhlab.grade``.

The package was split into maths (``dhlab/``), ``views/``, ``course/``, ``assignment/`` and
``grading/``. Notebooks and scripts written before still say ``from dhlab.teach import teach`` or
``import dhlab.exercises``; a finder on ``sys.meta_path`` (installed by ``dhlab/__init__``) answers
each old name with the module at its new place — the very same module object, imported only when
the old name is, so that ``import dhlab`` stays light.

Five old paths stay for good, silently (:data:`KEPT`): notebooks already handed to students import
them (the assignment's locked cells; a student's own copy of a lesson). Every other old path warns
(a ``DeprecationWarning`` naming the new place, pointed at the line that imports it) and goes in
version 0.2 (docs/developers/changelog.md).

>>> import dhlab.livefigure, dhlab.views.livefigure, dhlab.views.live.livefigure
>>> dhlab.livefigure is dhlab.views.livefigure is dhlab.views.live.livefigure
True
"""
from __future__ import annotations

import importlib
import importlib.abc
import importlib.machinery
import sys
import warnings

__all__ = ["MOVED", "KEPT", "REMOVED_IN", "new_name", "MovedFinder", "install"]

# old name -> new name; an old package's submodules follow it (dhlab.assign.frames -> dhlab.dh_frames.frames)
MOVED = {
    "dhlab.view": "dhlab.views.view",
    "dhlab.livefigure": "dhlab.views.live.livefigure",
    "dhlab.panel": "dhlab.views.panels.panel",
    "dhlab.spaces": "dhlab.views.panels.spaces",
    "dhlab.stepthrough": "dhlab.views.panels.stepthrough",
    "dhlab.teach": "dhlab.views.panels.teach",
    # views/ was one flat folder until its roles became sub-packages: the live figure's machinery in
    # views/live/, the slider panels in views/panels/ (the released notebooks say
    # `from dhlab.views.teach import teach`)
    **{f"dhlab.views.{name}": f"dhlab.views.live.{name}" for name in (
        "livefigure", "backend", "notebook_cell", "ipympl_canvas", "canvas", "scene", "rig", "keys", "png")},
    **{f"dhlab.views.{name}": f"dhlab.views.panels.{name}" for name in ("panel", "teach", "stepthrough", "spaces")},
    "dhlab.exercises": "dhlab.course.exercises",
    "dhlab.exercises_dh": "dhlab.course.exercises",
    "dhlab.course.exercises_dh": "dhlab.course.exercises",      # notebooks 5-7's exercises joined the one registry
    # notebook 8 until the assignment became its own package: every notebook already released to students
    # imports these (a locked cell: `from dhlab.course.family_notebook import use_variant`)
    "dhlab.course.assignment": "dhlab.assignment.notebook",
    "dhlab.course.family_notebook": "dhlab.assignment.notebook_cells",
    "dhlab.grade": "dhlab.grading.cli",
    "dhlab.assign": "dhlab.dh_frames",
    # the grader's languages joined the course's one ``_``
    "dhlab.grading.language": "dhlab.i18n",
    # ``python -m dhlab.grading.generate --check``: the release's tools are in grading/release/
    "dhlab.grading.generate": "dhlab.grading.release.generate",
}

# never warn, never removed: the notebooks already released to students import the first two (locked
# cells); the course's own lesson notebooks imported the panels from the other three until 0.1.0, and a
# student's copy of them (make lab's my-notebooks/, never overwritten once edited) still does
KEPT = ("dhlab.course.assignment", "dhlab.course.family_notebook",
        "dhlab.views.teach", "dhlab.views.stepthrough", "dhlab.views.spaces")
REMOVED_IN = "0.2"


def new_name(fullname: str) -> str | None:
    """Where the module once called ``fullname`` lives now, or None if it did not move.

    >>> new_name("dhlab.grade"), new_name("dhlab.assign.frames"), new_name("dhlab.chain")
    ('dhlab.grading.cli', 'dhlab.dh_frames.frames', None)
    """
    for old, new in MOVED.items():
        if fullname == old or fullname.startswith(old + "."):
            return new + fullname[len(old):]
    return None


class MovedFinder(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    """Finds an old name and loads it as the module at its new place."""

    def find_spec(self, fullname, path=None, target=None):
        new = new_name(fullname)
        if new is None:
            return None
        return importlib.machinery.ModuleSpec(fullname, self, origin=new)

    def create_module(self, spec):
        if not _kept(spec.name):
            warnings.warn(f"{spec.name} moved to {spec.origin}: import it from there (the old path goes in "
                          f"dhlab {REMOVED_IN})", DeprecationWarning, stacklevel=_importer_level())
        module = importlib.import_module(spec.origin)
        spec.loader_state = module.__spec__
        return module

    def exec_module(self, module):
        # The import system wrote the old name's spec onto the module: give it its own back,
        # so that it is still the module at its new place (reload, pickling, inspect).
        module.__spec__ = module.__spec__.loader_state

    def get_code(self, fullname):
        """For ``python -m dhlab.grade``: code that runs the new module as ``__main__`` (run
        under its own name, so that its relative imports find its own package)."""
        new = new_name(fullname)
        source = f"import runpy\nrunpy.run_module({new!r}, run_name='__main__', alter_sys=True)\n"
        return compile(source, f"<{fullname}, moved to {new}>", "exec")


def _kept(fullname: str) -> bool:
    return any(fullname == old or fullname.startswith(old + ".") for old in KEPT)


def _importer_level() -> int:
    """The ``stacklevel`` of the line that imports the old name: the first frame, counted from
    ``warnings.warn``'s caller, outside this file and the import system (so that a warning shows
    where a notebook cell or a script says the old name, as Python shows one for its own code)."""
    frame, level = sys._getframe(1), 1
    while frame is not None and _in_import_system(frame):
        frame = frame.f_back
        # warnings.warn does not count the import system's own frames (importlib._bootstrap): nor do we
        level += frame is not None and not _is_bootstrap(frame)
    return level


def _is_bootstrap(frame) -> bool:
    filename = frame.f_code.co_filename
    return "importlib" in filename and "_bootstrap" in filename


def _in_import_system(frame) -> bool:
    module = frame.f_globals.get("__name__", "")
    return module == __name__ or module == "importlib" or _is_bootstrap(frame)


def install() -> None:
    """Put the finder first on ``sys.meta_path`` (once): an old package's folder left behind
    (``dhlab/assign/__pycache__``) must not be found as an empty namespace package instead."""
    if not any(isinstance(finder, MovedFinder) for finder in sys.meta_path):
        sys.meta_path.insert(0, MovedFinder())
