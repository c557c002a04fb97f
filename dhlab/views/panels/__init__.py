"""Panels: sliders and a view, for a notebook cell.

- :mod:`~dhlab.views.panels.panel` — what the panels share (sliders, layout, error display)
- :mod:`~dhlab.views.panels.teach` — the teach panel: one slider per joint, live pose and matrix
- :mod:`~dhlab.views.panels.stepthrough` — one DH link as Rz, Tz, Tx, Rx applied in turn
- :mod:`~dhlab.views.panels.spaces` — joint space and Cartesian space side by side

The top floor of :mod:`dhlab.views`: they import the robot views and :mod:`dhlab.views.live`.
Their old paths (``from dhlab.views.teach import teach``, ``dhlab.teach``) still import the same
modules (see :mod:`dhlab.moved`).
"""
