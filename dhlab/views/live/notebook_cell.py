"""The notebook cell that made a live figure: what its previous run made, and whether its page runs canvas.js.

Two things a live figure learns from the cell that is running (:func:`current_cell`):

* re-running a cell closes the panels its previous run made (:func:`forget_previous_run`), so that
  their widgets (and the figures they hold) do not pile up in the kernel;
* a notebook page that cannot run the canvas backend's ``canvas.js`` gets PNG frames instead
  (:func:`watch_front_end`).

Outside a notebook (scripts, tests) there is no cell, and neither does anything.

>>> current_cell() is None
True
"""
from __future__ import annotations

import asyncio
import weakref

__all__ = ["current_cell", "forget_previous_run", "watch_front_end", "FRONT_END_S"]

# --- a page that cannot run canvas.js -----------------------------------------------------
FRONT_END_S = 4           # a notebook page that has not run canvas.js this long: PNG frames instead
_WATCH_S = 1.0            # how often the kernel looks (between cells: it runs on the kernel's event loop)


def watch_front_end(live) -> None:
    """Fall back to PNG frames if the notebook page that ran this cell cannot run canvas.js.

    A page with anywidget's front end runs ``initialize`` of canvas.js, which says "loaded", as
    soon as it creates the widget (before showing it). A cell run from a notebook page (JupyterLab,
    Notebook 7, the browser edition: its request names the cell) whose widget has not said so
    after :data:`FRONT_END_S` gets ``live.fall_back_to_image()``. The kernel looks only between
    cells, every :data:`_WATCH_S`, so a message queued behind a long cell is read first. Run by
    nbval, a grader, Voila (no cell named) or outside a kernel's event loop: nothing is watched."""
    try:
        loop = asyncio.get_running_loop()
    except RuntimeError:
        return
    if current_cell() is None:
        return
    widget = live.canvas_widget

    def check(looks: int) -> None:
        if live.canvas_widget is not widget or widget.loaded:
            return
        if looks * _WATCH_S >= FRONT_END_S:
            live.fall_back_to_image()
        else:
            loop.call_later(_WATCH_S, check, looks + 1)

    loop.call_later(_WATCH_S, check, 1)


# --- re-running a cell -------------------------------------------------------------
# Each panel remembers the notebook cell that made it. When that cell runs
# again, the panels of its previous run are closed, so their widgets (and the
# figures they hold) do not pile up in the kernel.
_made_by_cell: dict = {}


def current_cell():
    """(cell id, execution count) of the running notebook cell, or None outside a notebook."""
    try:
        from IPython import get_ipython  # lazy: there is no IPython in a plain script

        shell = get_ipython()
        kernel = getattr(shell, "kernel", None)
        if kernel is None:
            return None
        parent = kernel.get_parent() if hasattr(kernel, "get_parent") else kernel._parent_header
        cell_id = (parent or {}).get("metadata", {}).get("cellId")
        return (cell_id, shell.execution_count) if cell_id else None
    except Exception:                 # no IPython, or an unusual kernel: nothing to forget
        return None


def forget_previous_run(panel) -> None:
    """Close what the current cell made the last time it ran, and remember ``panel``.

    Outside a notebook (scripts, tests) this does nothing.
    """
    cell = current_cell()
    if cell is None:
        return
    cell_id, count = cell
    kept = []
    for made_count, ref in _made_by_cell.get(cell_id, []):
        old = ref()
        if old is None:
            continue
        if made_count != count:
            old.close()
        else:
            kept.append((made_count, ref))
    kept.append((count, weakref.ref(panel)))
    _made_by_cell[cell_id] = kept
