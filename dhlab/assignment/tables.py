"""What the student reads of an assignment robot in numbers: its joint axes and its link points.

:func:`axes_table` gives, for each joint, a point on its axis and the direction of its
drawn arrow at the home pose (positive q_i: right-hand rule, or the sliding sense);
:func:`points_table` the labelled points that draw each link, both in the world frame 0
(metres). :func:`puma_axes_table` and :func:`puma_points_table` are the PUMA 560's own
(notebook 8's stored outputs: its anchors are the seed's letters S, E, K, W). Each is a
:class:`Table`, shown as HTML in Jupyter and as aligned text elsewhere, its vectors
written by :func:`xyz`.

>>> xyz([0.4318, -0.15005, 1e-17])
'(0.4318, -0.15005, 0)'
>>> Table("Two points", ("point", "world (x, y, z)"), [("A", xyz([0, 0, 1])), ("B", xyz([0.5, 0, 1]))])
Two points
point | world (x, y, z)
A     | (0, 0, 1)
B     | (0.5, 0, 1)
"""
from __future__ import annotations

import html

import numpy as np

from ..i18n import _
from .family import shown_name

__all__ = ["Table", "xyz", "axes_table", "points_table", "puma_axes_table", "puma_points_table"]


class Table:
    """A small table shown as HTML in Jupyter and as aligned text elsewhere; ``rows`` are
    tuples of strings (what the student reads)."""

    def __init__(self, title, header, rows):
        self.title, self.header, self.rows = title, tuple(header), [tuple(r) for r in rows]

    def __repr__(self):
        table = [self.header, *self.rows]
        widths = [max(len(str(r[c])) for r in table) for c in range(len(self.header))]
        return "\n".join([self.title] + [" | ".join(str(v).ljust(w) for v, w in zip(r, widths)).rstrip()
                                         for r in table])

    def _repr_html_(self):
        head = "".join(f"<th>{html.escape(str(h))}</th>" for h in self.header)
        body = "".join("<tr>" + "".join(f"<td>{html.escape(str(v))}</td>" for v in r) + "</tr>"
                       for r in self.rows)
        return (f"<div><b>{html.escape(self.title)}</b><table><thead><tr>{head}</tr></thead>"
                f"<tbody>{body}</tbody></table></div>")


def xyz(v) -> str:
    """A point or a direction as the tables write it: to the micrometre, at most six significant
    digits, never "-0" (rounding first, so 1e-17 left over by a rotation reads 0)."""
    return "(" + ", ".join(f"{round(float(x), 6) + 0.0:.6g}" for x in np.asarray(v, float)) + ")"


# --- any robot of the family -----------------------------------------------------------------------

def anchors(robot) -> list:
    """For each joint axis, a named link point on it, the one nearest the axis's own point
    ((None, the axis's point) when no link point lies on the axis)."""
    out = []
    for axis in robot.axes:
        on = [(float(np.linalg.norm(p - axis.point)), name, p) for link in robot.points for name, p in link
              if axis.distance_to_point(p) < 1e-9]
        out.append(min(on, key=lambda t: t[0])[1:] if on else (None, axis.point))
    return out


def axes_table(robot) -> Table:
    """The joint axes at the home pose, in the world frame 0: a point on each axis and the
    direction of its drawn arrow (positive q_i: right-hand rule, or the sliding sense)."""
    rows = []
    for i, (axis, kind, (name, p)) in enumerate(zip(robot.axes, robot.kinds, anchors(robot)), start=1):
        where = f"{name} = {xyz(p)}" if name else xyz(p)
        rows.append((_("joint {i}").format(i=i), _("revolute") if kind == "R" else _("prismatic"), where,
                     xyz(axis.direction)))
    rows.append((_("end effector"), "", f"{robot.end_name} = {xyz(robot.end_point)}", ""))
    return Table(_("{robot}: joint axes at the home pose (world frame 0, metres)").format(robot=shown_name(robot.name)),
                 (_("joint"), _("kind"), _("passes through"), _("positive direction")), rows)


def points_table(robot) -> Table:
    """The points that draw each link, in the world frame at the home pose (metres)."""
    rows = [(f"{k} ({_(robot.link_names[k])})", name, xyz(p))
            for k, link in enumerate(robot.points) for name, p in link]
    return Table(_("{robot}: link points at the home pose (world frame 0, metres): give them, in this "
                   "order, in each link's own DH frame").format(robot=shown_name(robot.name)),
                 (_("link"), _("point"), _("world (x, y, z)")), rows)


# --- the PUMA 560 of the seed ------------------------------------------------------------------------

PUMA_ANCHORS = ("S", "S", "E", "K", "W", "W")      # the seed's letters: a point on each joint axis


def puma_axes_table(ref) -> Table:
    """The PUMA's joint axes at the home pose, in the world frame (frame 0 at the shoulder):
    a point on each and the direction of its drawn arrow (positive q_i turns by the
    right-hand rule). ``ref``: :func:`dhlab.assignment.reference.reference`."""
    points = {name: p for link in ref.points for name, p in link}
    rows = [(_("joint {i}").format(i=i), f"{name} = {xyz(points[name])}", xyz(axis.direction))
            for i, (axis, name) in enumerate(zip(ref.axes, PUMA_ANCHORS), start=1)]
    return Table(_("Joint axes at the home pose (world frame 0 at the shoulder, metres)"),
                 (_("joint"), _("passes through"), _("positive direction")), rows)


def puma_points_table(ref) -> Table:
    """The points that draw each of the PUMA's links, in the world frame at the home pose (metres)."""
    rows = [(f"{k} ({_(ref.link_names[k])})", name, xyz(p))
            for k, link in enumerate(ref.points) for name, p in link]
    return Table(_("Link points at the home pose (world frame 0, metres): give them, in this order, "
                   "in each link's own DH frame"), (_("link"), _("point"), _("world (x, y, z)")), rows)
