"""A planar robot seen from above (+z towards you)."""
from __future__ import annotations

import numpy as np
from matplotlib.collections import PolyCollection

from . import framing
from .labels import FrameLabels
from .triads import LETTER_MARKERS, letter_points, triad_segments
from .viewbase import EE_COLOR, LETTER_SIZE, RobotView

__all__ = ["RobotView2D", "Solids2D"]


class RobotView2D(RobotView):
    """The robot seen from above (+z towards you), for robots that stay in the xy plane.

    An axis that points out of the page is drawn as ⊙, into the page as ⊗,
    in its colour (so z is a blue ⊙ for the usual planar robot).
    """

    def _figsize(self):
        # a wide workspace (e.g. the P-R mechanism) gets a wide, short figure
        width, height = (self.box[1] - self.box[0])[:2]
        return (6, float(np.clip(6 * height / max(width, 1e-9) + 0.8, 3.4, 6)))

    def setup_axes(self, ax):
        ax.set(xlabel=self._axis_label("x"), ylabel=self._axis_label("y"))
        ax.set_autoscale_on(False)
        if self.title:
            ax.set_title(self.title)
        ax.grid(True, alpha=0.3)
        self.limits = self._frame_limits(ax)

    MARGINS_PX = (72, 56, 18, 34)     # left, bottom, right, top: tick labels, axis labels, title

    def _fit(self, figure):
        width, height = figure.bbox.width, figure.bbox.height
        left, bottom, right, top = (m * figure.dpi / 100 for m in self.MARGINS_PX)
        self.ax.set_position([left / width, bottom / height, 1 - (left + right) / width,
                              1 - (bottom + top) / height])

    def _frame_limits(self, ax):
        if self.framing == "fixed":
            lo, hi = self.box[0][:2], self.box[1][:2]
        else:
            lo, hi = framing.frame_box(self.framed_points()[:, :2], pad=1.0 * self.triad_length)
        center, half = (lo + hi) / 2, (hi - lo) / 2 / self.zoom
        if self.framing == "follow":      # equal scaling: widen the shorter side to the axes' shape
            shape = (ax.get_position().height * ax.figure.bbox.height
                     / (ax.get_position().width * ax.figure.bbox.width))
            half = np.maximum(half, half[::-1] * np.array([1 / shape, shape]))
        ax.set(xlim=(center[0] - half[0], center[0] + half[0]), ylim=(center[1] - half[1], center[1] + half[1]))
        ax.set_aspect("equal", adjustable="box")
        return center - half, center + half

    def _make_artists(self, color, alpha):
        ax = self.ax
        self.joint_axes_line = None               # joint axes point out of the page: the ⊙ marks
        self.joint_solids = self.gripper_line = None
        if self.mechanism is None:
            self.link_line, = ax.plot([], [], "-o", color=color, lw=3, ms=5, alpha=alpha)
        else:
            self.link_line, = ax.plot([], [], "-", color=color, lw=4, alpha=alpha,
                                      solid_capstyle="round", solid_joinstyle="round")
            self.joint_solids = Solids2D([], linewidths=0.8, zorder=2.2)
            self.joint_solids.opacity = alpha
            ax.add_collection(self.joint_solids, autolim=False)
            self.gripper_line, = ax.plot([], [], "-", color=EE_COLOR, lw=3.5, alpha=alpha, zorder=2.4,
                                         solid_capstyle="round")
        self.axis_lines, self.out_marks, self.in_marks, self.letter_marks = [], [], [], []
        if self.show_triads:
            for c, letter in zip(self.colors, LETTER_MARKERS):
                self.axis_lines.append(ax.plot([], [], "-", color=c, lw=2.5, alpha=alpha, zorder=3)[0])
                self.out_marks.append(ax.plot([], [], ls="", marker=r"$\odot$", ms=13, color=c, zorder=3)[0])
                self.in_marks.append(ax.plot([], [], ls="", marker=r"$\otimes$", ms=13, color=c, zorder=3)[0])
                self.letter_marks.append(ax.plot([], [], ls="", marker=letter, ms=LETTER_SIZE, mew=0, color=c,
                                                 alpha=alpha, zorder=3.1, visible=self._labels_on)[0])
        self.ee_marker, = ax.plot([], [], "*", color=EE_COLOR, mec="k", ms=15 if self.mechanism is None else 12,
                                  alpha=alpha, zorder=3.2)
        self.labels = FrameLabels(ax, self.frame_labels, alpha=alpha) if self._labels_on else None
        return [a for a in (self.link_line, self.joint_solids, self.gripper_line, *self.axis_lines,
                            *self.out_marks, *self.in_marks, *self.letter_marks, self.ee_marker, self.labels) if a]

    def _place(self, frames):
        origins = frames[:, :2, 3]
        if self.shape is None:
            self.link_line.set_data(*origins.T)
        else:
            self.link_line.set_data(*self.shape.path[:, :2].T)
            self.joint_solids.set_faces(self.shape.faces, self.shape.colors)
            self.gripper_line.set_data(*self.shape.gripper[:, :2].T)
        segments = triad_segments(frames, self.triad_length)
        tips = letter_points(frames, self.triad_length)
        for k, line in enumerate(self.axis_lines):
            in_page = np.abs(frames[:, 2, k]) <= 0.7             # an axis along the page's normal is ⊙ / ⊗
            line.set_data(*segments[k][:, :2].T)
            out_of_page = frames[:, 2, k]                 # z component of axis k
            self.out_marks[k].set_data(*origins[out_of_page > 0.7].T)
            self.in_marks[k].set_data(*origins[out_of_page < -0.7].T)
            self.letter_marks[k].set_data(*tips[k][in_page, :2].T)
        self.ee_marker.set_data(*origins[-1:].T)
        if self.labels:
            self.labels.set_points(origins, tol=1e-3 * self.triad_length, avoid=self._strokes(frames)[:, :2])


class Solids2D(PolyCollection):
    """The joints' solids seen from above (+z towards you), the nearest painted last."""

    opacity = 1.0

    def set_faces(self, faces, colors) -> None:
        order = np.argsort(faces[..., 2].mean(axis=1), kind="stable")
        colors = colors[order].copy()
        colors[:, 3] *= self.opacity
        self.set_verts(faces[order, :, :2])
        self.set_facecolor(colors)
        self.set_edgecolor(np.column_stack([0.25 * colors[:, :3], 0.8 * colors[:, 3:]]))
