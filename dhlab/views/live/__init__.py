"""Live figures: a figure redrawn in place at screen rate, and the browser's side of it.

- :mod:`~dhlab.views.live.livefigure` — a figure redrawn in place (blitting), inline, ipympl or canvas
- :mod:`~dhlab.views.live.backend` — which of the three backends a live figure uses (``choose_backend``)
- :mod:`~dhlab.views.live.notebook_cell` — the cell a figure belongs to, and the front end that never answered
- :mod:`~dhlab.views.live.ipympl_canvas` — ipympl's faster canvas, when ipympl draws
- :mod:`~dhlab.views.live.canvas` — the canvas backend: the browser paints what moves (``receive`` takes its
  messages); ``canvas.js`` the ES module that paints, ``dirty.js`` the rectangle a step of a drag repaints
- :mod:`~dhlab.views.live.scene` — the moving artists as plain numbers, for the browser to draw
- :mod:`~dhlab.views.live.rig` — the robot as a rig: the browser moves the picture itself while a slider
  moves (``rig.js`` its JavaScript twin)
- :mod:`~dhlab.views.live.keys` — keys that reach the slider (arrows, Page Up/Down) without fighting the
  deck's (``keys.js``)
- :mod:`~dhlab.views.live.png` — the fast PNG writer of every update

They import the pictures of :mod:`dhlab.views` (figures, labels), never a panel. Their old paths
(``dhlab.views.livefigure``, ...) still import the same modules (see :mod:`dhlab.moved`).
"""
