"""A robot in a 3D axes: orthographic, equal scaling, framed around its configuration."""
from __future__ import annotations

import numpy as np
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

from . import framing
from .camera import set_camera
from .labels import FrameLabels3D
from .layout import keep_texts_inside, space_ticks
from .triads import LETTER_MARKERS, letter_points, triad_segments
from .viewbase import EE_COLOR, JOINT_AXIS_COLOR, LETTER_SIZE, RobotView

__all__ = ["RobotView3D", "Solids3D"]


class RobotView3D(RobotView):
    """The robot in a 3D axes (orthographic: parallel axes stay parallel), equal
    scaling, framed around its configuration."""

    projection = "3d"
    _camera_set = None
    MARGINS = (0.10, 0.06, 0.10, 0.10)      # left, bottom, right, top: room for the tick labels

    def setup_axes(self, ax):
        ax.set_proj_type("ortho")
        ax.set(xlabel=self._axis_label("x"), ylabel=self._axis_label("y"),
               zlabel=self._axis_label("z"))
        for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
            axis.labelpad = 8                        # clear of the tick labels
        if self.title:
            ax.set_title(self.title, pad=2)         # its own axes' title, never a neighbour's
        self.limits = self._frame_limits(ax)

    def _fit(self, figure):
        left, bottom, right, top = self.MARGINS
        self.ax.set_position([left, bottom, 1 - left - right, 1 - bottom - top])
        keep_texts_inside(self.ax)

    def _frame_limits(self, ax):
        if self.framing == "fixed":
            lo, hi = self.box
        else:
            lo, hi = framing.frame_box(self.framed_points(), pad=0.6 * self.triad_length)
        ax.set(xlim=(lo[0], hi[0]), ylim=(lo[1], hi[1]), zlim=(lo[2], hi[2]))
        if self._camera_set != self.camera:       # the camera moves only when asked to
            set_camera(ax, self.camera, frames=self.frames)
            self._camera_set = self.camera
        framing.fit_zoom(ax, self.zoom)
        if self.framing == "follow":
            lo, hi = framing.zoom_in_on(ax, self.framed_points(), lo, hi, zoom=self.zoom,
                                         target=framing.TARGET * self.zoom)
        space_ticks(ax)
        return lo, hi

    def _make_artists(self, color, alpha):
        ax = self.ax
        ax.computed_zorder = False          # solids under the triads, as they are painted live
        self.joint_axes_line, = ax.plot([], [], [], "--", color=JOINT_AXIS_COLOR, lw=1, alpha=alpha,
                                        visible=self._joint_axes_on)
        self.joint_solids = self.gripper_line = None
        if self.mechanism is None:
            self.link_line, = ax.plot([], [], [], "-o", color=color, lw=3, ms=4, alpha=alpha)
        else:
            self.link_line, = ax.plot([], [], [], "-", color=color, lw=4, alpha=alpha,
                                      solid_capstyle="round", solid_joinstyle="round")
            self.joint_solids = Solids3D(np.zeros((0, 4, 3)), linewidths=0.5, zorder=2.2)
            self.joint_solids.opacity = alpha
            # already 3D: add_collection (add_collection3d has no autolim before matplotlib 3.10)
            ax.add_collection(self.joint_solids, autolim=False)
            self.gripper_line, = ax.plot([], [], [], "-", color=EE_COLOR, lw=3.5, alpha=alpha, zorder=2.4,
                                         solid_capstyle="round")
        self.axis_lines = [ax.plot([], [], [], "-", color=c, lw=2.5, alpha=alpha, zorder=3)[0]
                           for c in self.colors] if self.show_triads else []
        self.letter_marks = [ax.plot([], [], [], ls="", marker=m, ms=LETTER_SIZE, mew=0, color=c, alpha=alpha,
                                     zorder=3.1, visible=self._labels_on)[0]
                             for c, m in zip(self.colors, LETTER_MARKERS)] if self.show_triads else []
        self.ee_marker, = ax.plot([], [], [], "*", color=EE_COLOR, mec="k", ms=15 if self.mechanism is None else 12,
                                  alpha=alpha, zorder=3.2)
        self.labels = FrameLabels3D(ax, self.frame_labels, alpha=alpha, gap=6.0) if self._labels_on else None
        return [a for a in (self.joint_axes_line, self.link_line, self.joint_solids, self.gripper_line,
                            *self.axis_lines, *self.letter_marks, self.ee_marker, self.labels) if a]

    def _place(self, frames):
        origins = frames[:, :3, 3]
        if self.shape is None:
            self.link_line.set_data_3d(*origins.T)
        else:
            self.link_line.set_data_3d(*self.shape.path.T)
            self.joint_solids.set_faces(self.shape.faces, self.shape.colors)
            self.gripper_line.set_data_3d(*self.shape.gripper.T)
        for line, points in zip(self.axis_lines, triad_segments(frames, self.triad_length)):
            line.set_data_3d(*points.T)
        for mark, points in zip(self.letter_marks, letter_points(frames, self.triad_length)):
            mark.set_data_3d(*points.T)
        self.ee_marker.set_data_3d(*origins[-1:].T)
        if self.labels:
            self.labels.set_points(origins, tol=1e-3 * self.triad_length, avoid=self._strokes(frames))
        if self._joint_axes_on:
            lo, hi = (np.array(lim) for lim in zip(self.ax.get_xlim(), self.ax.get_ylim(), self.ax.get_zlim()))
            self.joint_axes_line.set_data_3d(*self._joint_axis_points(lo, hi).T)


class Solids3D(Poly3DCollection):
    """The joints' solids: faces set at every pose, projected when drawn on their own
    (blitting draws an artist without the 3D axes' projection pass)."""

    opacity = 1.0

    def set_faces(self, faces, colors) -> None:
        colors = colors.copy()
        colors[:, 3] *= self.opacity
        self.set_verts(faces)
        self.set_facecolor(colors)
        self.set_edgecolor(np.column_stack([0.25 * colors[:, :3], 0.6 * colors[:, 3:]]))

    def draw(self, renderer):
        self.do_3d_projection()
        super().draw(renderer)
