"""Which way a live figure reaches the browser: its *backend*, chosen once when it is made.

:class:`~dhlab.views.live.livefigure.LiveFigure` has three (``backend=``; ``DHLAB_BACKEND=canvas|ipympl|image``
in the environment overrides ``"auto"``):

* ``"ipympl"`` under ``%matplotlib widget``: an interactive canvas widget, sent the changed pixels
  (:mod:`dhlab.views.live.ipympl_canvas`);
* ``"canvas"`` in a Jupyter kernel where anywidget imports: the browser paints the moving artists
  from numbers the kernel sends (:mod:`dhlab.views.live.canvas`);
* ``"image"`` elsewhere (a script, a test, a page without anywidget): a PNG after each update.

>>> choose_backend("image"), "auto" in BACKENDS
('image', True)
"""
from __future__ import annotations

import os
import sys

import matplotlib

from ...errors import DHLabError
from ...i18n import _

__all__ = ["BACKENDS", "choose_backend", "ipympl_active", "in_kernel", "anywidget_imports"]

BACKENDS = ("auto", "canvas", "ipympl", "image")


def ipympl_active() -> bool:
    """True when ``%matplotlib widget`` (ipympl) is the current matplotlib backend."""
    backend = str(matplotlib.rcParams._get_backend_or_none() or "").lower()
    return backend in ("widget", "ipympl") or "ipympl" in backend


def in_kernel() -> bool:
    """True in a Jupyter kernel (ipykernel, or the browser edition's Pyodide kernel), where a
    front end can show widgets; False in a script, a test or a terminal IPython."""
    try:
        from IPython import get_ipython  # lazy: IPython is there only in a kernel or a notebook tool
    except ImportError:
        return False
    shell = get_ipython()
    if shell is None:
        return False
    return getattr(shell, "kernel", None) is not None or sys.platform == "emscripten"


def anywidget_imports() -> bool:
    """True when anywidget, which the canvas backend's widget is made with, can be imported."""
    try:
        import anywidget  # noqa: F401      (imported only to see whether it can be: ~0.2 s)
    except ImportError:
        return False
    return True


def choose_backend(backend: str = "auto") -> str:
    """The backend a LiveFigure uses: ``backend`` itself unless it is ``"auto"``; then the
    environment variable ``DHLAB_BACKEND`` if set, else ipympl under ``%matplotlib widget``,
    else "canvas" in a Jupyter kernel where anywidget imports (JupyterLab, Notebook 7, Voila,
    the browser edition), else "image" (a script, a test: nothing shows a widget there)."""
    if not isinstance(backend, str) or backend not in BACKENDS:
        raise DHLabError(_("backend must be one of {names}, got {backend!r}.").format(
            names=", ".join(map(repr, BACKENDS)), backend=backend))
    if backend != "auto":
        return backend
    forced = os.environ.get("DHLAB_BACKEND", "").strip().lower()
    if forced:
        if forced not in BACKENDS[1:]:
            raise DHLabError(_("the environment variable DHLAB_BACKEND must be 'canvas', 'ipympl' or 'image' "
                               "(or unset), got {value!r}.").format(value=forced))
        return forced
    if ipympl_active():
        return "ipympl"
    if in_kernel() and anywidget_imports():
        return "canvas"
    return "image"
