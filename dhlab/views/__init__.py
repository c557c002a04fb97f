"""The interactive views: robots drawn in place with matplotlib, moved by ipywidgets sliders.

**Pictures** (a figure a teacher puts on a slide):

- :mod:`~dhlab.views.figures` — figures that are pictures: readable sizes, never clipped, the projector setting
- :mod:`~dhlab.views.projector` — the lecture-hall switch: ``projector()`` makes everything larger together
- :mod:`~dhlab.views.triads` — frame triads that read without colour: x, y, z in colour *and* by letter
- :mod:`~dhlab.views.labels` — frame labels that never pile up
- :mod:`~dhlab.views.layout` — tick labels that do not collide, texts kept inside the figure
- :mod:`~dhlab.views.camera` — camera presets, and a default from which every triad reads right-handed
- :mod:`~dhlab.views.framing` — the robot fills its view, re-framed with hysteresis
- :mod:`~dhlab.views.mechanism` — the mechanism drawn as a textbook draws it (joints, links, base)

**A robot in a view**:

- :mod:`~dhlab.views.viewbase` — what every robot view shares: the robot, its pose, its frames, ``update``
- :mod:`~dhlab.views.view` — a robot as a stick figure with x/y/z frame triads (``robot_view``)
- :mod:`~dhlab.views.view2d` — a planar robot seen from above; :mod:`~dhlab.views.view3d` — a robot in 3D
- :mod:`~dhlab.views.poses` — a robot's pose in a view or a panel, and its units on a slider

**Live figures** (redrawn in place at screen rate), in :mod:`dhlab.views.live`:

- :mod:`~dhlab.views.live.livefigure` — a figure redrawn in place (blitting), inline, ipympl or canvas
- :mod:`~dhlab.views.live.backend` — which of the three backends a live figure uses (``choose_backend``)
- :mod:`~dhlab.views.live.notebook_cell` — the cell a figure belongs to, and the front end that never answered
- :mod:`~dhlab.views.live.ipympl_canvas` — ipympl's faster canvas, when ipympl draws
- :mod:`~dhlab.views.live.canvas` — the canvas backend: the browser paints what moves (``receive`` takes its messages)
- :mod:`~dhlab.views.live.scene` — the moving artists as plain numbers, for the browser to draw
- :mod:`~dhlab.views.live.rig` — the robot as a rig: the browser moves the picture itself while a slider moves
- :mod:`~dhlab.views.live.keys` — keys that reach the slider (arrows, Page Up/Down) without fighting the deck's
- :mod:`~dhlab.views.live.png` — the fast PNG writer of every update

**Panels** (sliders and a view), in :mod:`dhlab.views.panels`:

- :mod:`~dhlab.views.panels.panel` — what the panels share (sliders, layout, error display)
- :mod:`~dhlab.views.panels.teach` — the teach panel: one slider per joint, live pose and matrix
- :mod:`~dhlab.views.panels.stepthrough` — one DH link as Rz, Tz, Tx, Rx applied in turn
- :mod:`~dhlab.views.panels.spaces` — joint space and Cartesian space side by side

**Symbolic matrices**:

- :mod:`~dhlab.views.matrices` — symbolic matrices that fit the notebook column (``show_matrix``)

The floors, lowest first, each importing only the ones below it: the pictures (and the matrices);
``live/``, which draws with them; a robot in a view, which is a live figure; ``panels/``, a view and
its sliders. The old flat paths (``dhlab.views.teach``, ``dhlab.views.livefigure``, ...) still
import the same modules (:mod:`dhlab.moved`).
"""
