"""The interactive views: robots drawn in place with matplotlib, moved by ipywidgets sliders.

- :mod:`~dhlab.views.livefigure` — a figure redrawn in place (blitting), inline or ipympl
- :mod:`~dhlab.views.view` — a robot as a stick figure with x/y/z frame triads
- :mod:`~dhlab.views.panel` — what the panels share (sliders, layout, error display)
- :mod:`~dhlab.views.teach` — the teach panel: one slider per joint, live pose and matrix
- :mod:`~dhlab.views.stepthrough` — one DH link as Rz, Tz, Tx, Rx applied in turn
- :mod:`~dhlab.views.spaces` — joint space and Cartesian space side by side
"""
