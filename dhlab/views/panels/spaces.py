"""Joint space and Cartesian space side by side (seed 003), for a 2-DOF mechanism.

On the left, the joint vector q = (q1, q2) is a point in **joint space**
(*espacio articular*); on the right, the mechanism and its end effector in
**Cartesian space** (*espacio cartesiano*). Both move together: moving a joint
slider moves the point and the robot.

Given an inverse-kinematics function ``ik(x, y) -> list of q``, the panel also
shows **every** solution for the end effector's position (both branches of the
P-R mechanism: two points on the left, two ghost robots on the right), and
gets target sliders (x, y): moving the target runs the inverse kinematics. An
unreachable target (|y| > l2 for the P-R mechanism) is reported, not a crash.

**The panel moves only what the student moves.** A joint slider never moves
another joint slider; moving the target keeps the robot on its branch
(*rama*) of the inverse kinematics, and never jumps to the other branch unless
the student picks it with the ``branch`` buttons. Where the robot's own branch
cannot reach the target within the joint limits, the robot stays and the
panel says which branch would.

>>> import functools, dhlab
>>> robot = dhlab.robots.pr_mechanism()
>>> panel = spaces(robot, ik=functools.partial(dhlab.ik.pr_mechanism_ik, robot))
>>> panel.set_target(2.0, 0.25)        # both branches: A (q2 = 30°) and B (q2 = 150°)
>>> [s.round(6).tolist() for s in panel.solutions]
[[0.566987, 0.523599], [1.433013, 2.617994]]
>>> panel.branch, panel.q.round(6).tolist()      # the robot went to A, its branch
('A', [0.566987, 0.523599])
>>> panel.set_branch("B"); panel.q.round(6).tolist()
[1.433013, 2.617994]
"""
from __future__ import annotations

import html
import inspect

import ipywidgets as widgets
import numpy as np
from matplotlib.patches import Rectangle
from matplotlib.ticker import MultipleLocator
from matplotlib.transforms import offset_copy

from ...errors import DHLabError
from ...i18n import _
from ...validation import as_choice, as_length, check_joint_values, describe
from ..live.livefigure import LiveFigure
from ..poses import checked_start, default_q, q_to_slider, unit_of
from ..view import robot_view
from ..viewbase import checked_robot
from .panel import Panel, SliderEchoes, follow_sliders, joint_sliders

__all__ = ["spaces", "SpacesPanel", "wrap_into_limits"]

# The figure (two subplots side by side) is 860 px wide at 100 dpi: with ipympl's toolbar beside
# it, the panel fits a JupyterLab column at a 1400 px window (968 px); the controls go under it.
FIGSIZE = (8.6, 3.3)
CONTROLS_WIDTH_PX = 820
MAX_SOLUTIONS = 4              # ghost robots made in advance (the artists never change in number)
SOLUTION_NAMES = "ABCD"
MESSAGE_HEIGHT = "6.4em"           # the report's box: its heading, two solutions and a note
GHOST_COLORS = ("tab:purple", "tab:cyan", "tab:olive", "tab:pink")


def wrap_into_limits(robot, q) -> tuple:
    """``q`` with each revolute angle shifted by whole turns into its joint limits
    where possible (π − asin(…) may come out as 233° for a ±180° joint).
    Returns (q, True if every joint is within its limits)."""
    q = np.array(q, dtype=float)
    ok = True
    for j, link in enumerate(robot.links):
        lo, hi = link.qlim
        if link.is_revolute:
            for turn in (0.0, -2 * np.pi, 2 * np.pi):
                if lo - 1e-9 <= q[j] + turn <= hi + 1e-9:
                    q[j] += turn
                    break
        ok = ok and bool(lo - 1e-9 <= q[j] <= hi + 1e-9)
    return q, ok


def _check_ik_function(ik) -> None:
    """``ik`` must be a function that can be called as ik(x, y)."""
    if not callable(ik):
        raise DHLabError(_("ik must be a function ik(x, y) -> list of joint vectors, got {value}.").format(
            value=describe(ik)))
    try:
        signature = inspect.signature(ik)
    except (TypeError, ValueError):      # some built-in callables have none: they are tried as they are
        return
    try:
        signature.bind(0.0, 0.0)
    except TypeError:
        raise DHLabError(_("ik must be a function ik(x, y) of the target's two coordinates (e.g. functools."
                           "partial(dhlab.ik.pr_mechanism_ik, robot)); this one takes {signature}.").format(
                               signature=signature)) from None


class SpacesPanel(Panel):
    """The widget of :func:`spaces`.

    Attributes: ``sliders`` (the joints, display units), ``target_sliders``
    (x, y; only with ``ik``), ``figure``, ``view`` (the Cartesian view),
    ``solutions`` (the inverse-kinematics solutions shown, radians / length),
    ``message`` (HTML) and ``q``.
    """

    def __init__(self, robot, q=None, *, ik=None, figsize=FIGSIZE, backend="auto"):
        checked_robot(robot)
        if callable(q) and ik is None:
            raise DHLabError(_("spaces(robot, q=None, *, ik=None): the second argument is the start pose q; pass "
                               "the inverse kinematics by name, spaces(robot, ik=...)."))
        if ik is not None:
            _check_ik_function(ik)
        if robot.n != 2:
            raise DHLabError(_("the joint-space view needs a 2-DOF mechanism (one axis per joint); {name!r} has {n} "
                               "joints.").format(name=robot.name, n=robot.n))
        self.robot, self.ik = robot, ik
        self.solutions = []
        q = default_q(robot) if q is None else checked_start(robot, q)
        live = LiveFigure(figsize=figsize, backend=backend)
        planar = bool(getattr(robot, "is_planar", False))
        # a planar workspace is wide and short (the P-R mechanism's: 3.8 by 1.7): it gets the room
        self._grid = live.figure.add_gridspec(1, 2, width_ratios=(1, 2.1) if planar else (1, 1))
        self._build_joint_axes(live)
        self._build_cartesian_axes(live, q)
        rows, self.sliders = joint_sliders(robot, q)
        # under the figure (two subplots side by side need the width): the joints and the
        # target in two columns, the inverse kinematics' report under both
        # the inverse kinematics' report: its line count changes with the target (solutions, a
        # note), so it gets a box of fixed size; the panel never grows or shrinks under the mouse
        self.message = widgets.HTML(layout=widgets.Layout(
            max_width=f"{CONTROLS_WIDTH_PX}px", height=None if ik is None else MESSAGE_HEIGHT, overflow="auto"))
        columns = [widgets.VBox([widgets.HTML(_("<b>Joints</b> (<i>articulaciones</i>)")), *rows],
                                layout=widgets.Layout(margin="0 2em 0 0"))]
        self.target_sliders = []
        self.branch_buttons = None
        if ik is not None:
            self.target_sliders = self._target_sliders()
            self.branch_buttons = widgets.ToggleButtons(
                options=list(SOLUTION_NAMES[:2]), description=_("branch"),
                tooltips=[_("solution A of the inverse kinematics"), _("solution B")],
                style={"description_width": "3em", "button_width": "3em"})
            columns.append(widgets.VBox([
                widgets.HTML(_("<b>Target</b> of the end effector (inverse kinematics)")),
                *self.target_sliders, self.branch_buttons]))
        controls = [widgets.HBox(columns, layout=widgets.Layout(flex_flow="row wrap")), self.message]
        super().__init__(live, controls, below=True)
        # The panel's state is its own (q, target, branch); the sliders show it. A value that
        # comes back from the browser is the student's move only if it is not the browser's
        # rounding of a value the panel set (see SliderEchoes: late echoes made it drift).
        self._q = np.array([float(np.clip(v, *link.qlim)) for v, link in zip(q, robot.links)])
        self.echoes = SliderEchoes()
        for slider in [*self.sliders, *self.target_sliders]:
            self.echoes.expect(slider)
        self._quiet = False
        self.branch = None
        self.target = None
        self.run(self._from_joints)
        follow_sliders(self.view, self.sliders)     # the browser moves the mechanism at once
        for j, slider in enumerate(self.sliders):
            slider.observe(lambda change, j=j: self._slider_moved(self._joint_moved, change, j), names="value")
        for k, slider in enumerate(self.target_sliders):
            slider.observe(lambda change, k=k: self._slider_moved(self._target_moved, change, k), names="value")
        if self.branch_buttons is not None:
            self.branch_buttons.observe(lambda change: self._quiet or self.run(self.set_branch, change["new"]),
                                        names="value")

    # --- figure ------------------------------------------------------------------------
    def _build_joint_axes(self, live):
        ax = live.figure.add_subplot(self._grid[0, 0])
        (lo1, hi1), (lo2, hi2) = [[q_to_slider(link, v) for v in link.qlim] for link in self.robot.links]
        labels = list(getattr(self.robot, "joint_labels", ["q1", "q2"]))
        pad1, pad2 = 0.08 * (hi1 - lo1), 0.08 * (hi2 - lo2)
        ax.set(xlim=(lo1 - pad1, hi1 + pad1), ylim=(lo2 - pad2, hi2 + pad2),
               xlabel=f"{labels[0]} [{unit_of(self.robot, self.robot.links[0])}]",
               ylabel=f"{labels[1]} [{unit_of(self.robot, self.robot.links[1])}]",
               title=_("Joint space (espacio articular)"))
        ax.add_patch(Rectangle((lo1, lo2), hi1 - lo1, hi2 - lo2, fc="0.93", ec="0.5", lw=1,
                               label=_("joint limits")))
        for axis, link, (lo, hi) in ((ax.xaxis, self.robot.links[0], (lo1, hi1)),
                                     (ax.yaxis, self.robot.links[1], (lo2, hi2))):
            if link.is_revolute and hi - lo >= 270:      # angles: ticks every 90° (or 180°)
                axis.set_major_locator(MultipleLocator(90 if hi - lo <= 540 else 180))
        ax.grid(True, alpha=0.3)
        self.solution_marks = [ax.plot([], [], "o", ms=12, mfc="none", mew=2, color=c)[0]
                               for c in GHOST_COLORS]
        beside = offset_copy(ax.transData, fig=live.figure, x=8, y=6, units="points")
        self.solution_names = [ax.text(0, 0, name, color=c, fontsize=10, fontweight="bold",
                                       transform=beside)
                               for name, c in zip(SOLUTION_NAMES, GHOST_COLORS)]
        self.joint_point, = ax.plot([], [], "o", ms=8, color="k")
        live.add_moving(*self.solution_marks, *self.solution_names, self.joint_point)
        self.joint_ax = ax

    def _build_cartesian_axes(self, live, q):
        planar = bool(getattr(self.robot, "is_planar", False))
        ax = live.figure.add_subplot(self._grid[0, 1], projection=None if planar else "3d")
        # the ghosts (one per possible IK solution) first, so the robot is drawn on top
        self.ghosts = [robot_view(self.robot, q, ax=ax, live=live, planar=planar, triads=False,
                                  labels=False, color=c, alpha=0.45, style="stick") for c in GHOST_COLORS]
        self.view = robot_view(self.robot, q, ax=ax, live=live, planar=planar, framing="fixed")
        self.view.setup_axes(ax)
        ax.set_title(_("Cartesian space (espacio cartesiano)"))
        if planar:                     # the workspace, as the end effector positions it can reach
            ax.plot(*self._workspace_points().T, ".", ms=1, color="0.8", zorder=0)
        self.target_mark, = ax.plot([], [], "x", ms=12, mew=3, color="k") if planar else \
            ax.plot([], [], [], "x", ms=12, mew=3, color="k")
        live.add_moving(self.target_mark)
        live.figure.set_layout_engine("constrained")

    def _workspace_points(self, per_joint: int = 60):
        (lo1, hi1), (lo2, hi2) = (link.qlim for link in self.robot.links)
        grid = np.stack(np.meshgrid(np.linspace(lo1, hi1, per_joint),
                                    np.linspace(lo2, hi2, per_joint)), axis=-1).reshape(-1, 2)
        return np.asarray(self.robot.fk(grid), dtype=float)[:, :2, 3]

    def _target_sliders(self):
        lo, hi = self.view.box
        return [widgets.FloatSlider(value=0.0, min=float(lo[k]), max=float(hi[k]),
                                    step=float(hi[k] - lo[k]) / 1000, description=name,
                                    readout_format=".3f", continuous_update=True,
                                    style={"description_width": "3em"},
                                    layout=widgets.Layout(width="330px"))
                for k, name in enumerate(("x", "y"))]

    # --- updates ------------------------------------------------------------------------
    @property
    def q(self) -> np.ndarray:
        """The joint vector shown (radians / length units)."""
        return self._q.copy()

    def _slider_moved(self, action, change, index):
        if self._quiet or self.echoes.setting:
            return
        if self.echoes.classify(change["owner"]) == "student":
            self.run(action, index)

    def _joint_moved(self, j):
        """The student moved joint slider ``j``: that joint, and only that one, moves."""
        link, value = self.robot.links[j], float(self.sliders[j].value)
        self._q[j] = np.radians(value) if link.is_revolute else value
        self._from_joints()

    def _target_moved(self, k):
        """The student moved target slider ``k`` (0: x, 1: y)."""
        target = list(self.target) if self.target is not None else [float(s.value) for s in self.target_sliders]
        target[k] = float(self.target_sliders[k].value)
        self.set_target(*target)

    def _from_joints(self):
        """The joints moved: move the robot, and run the IK on where it went.
        No joint slider moves; the target sliders follow the end effector."""
        q = self.q
        x, y = np.asarray(self.robot.fk(q), dtype=float)[:2, 3]
        if self.ik is not None:
            self._set_target_sliders((x, y))
            self._show_solutions((x, y))
            if self.solutions:                 # the robot's branch: the solution it is at
                near = int(np.argmin([np.linalg.norm(s - q) for s in self.solutions]))
                self._set_branch_quietly(SOLUTION_NAMES[near])
        self._draw(q, (x, y) if self.ik is not None else None)
        self._say(self._ik_text((x, y)) if self.ik is not None else "")

    def set_target(self, x: float, y: float) -> None:
        """Solve the inverse kinematics for (x, y), show every solution, and move
        the robot to the solution of its own branch (never to another branch:
        see :meth:`set_branch`)."""
        if self.ik is None:
            raise DHLabError(_("this panel has no inverse kinematics: pass ik=... to spaces()."))
        x, y = as_length(x, _("target x")), as_length(y, _("target y"))
        self._set_target_sliders((x, y))
        self._show_solutions((x, y))
        q, note = self.q, ""
        k = SOLUTION_NAMES.index(self.branch) if self.branch in SOLUTION_NAMES else 0
        if k < len(self.solutions) and self.solutions_ok[k]:
            q = self._q = np.array(self.solutions[k], dtype=float)
            self._set_quietly(self.sliders, [q_to_slider(link, v) for link, v in zip(self.robot.links, q)])
        elif self.solutions:
            others = [SOLUTION_NAMES[j] for j, ok in enumerate(self.solutions_ok) if ok]
            why = (_("Branch {branch} cannot reach this target within the joint limits: the robot stays where it "
                     "is; branch {others} can (choose it with the branch buttons).") if others else
                   _("Branch {branch} cannot reach this target within the joint limits: the robot stays where it "
                     "is."))
            note = "<br><i>" + why.format(branch=self.branch, others=_(" or ").join(others)) + "</i>"
        self._draw(q, (x, y))
        self._say(self._ik_text((x, y)) + note)

    def set_branch(self, name: str) -> None:
        """Move the robot to solution ``name`` ('A', 'B', …) of the current target:
        the only way the panel changes branch."""
        name = as_choice(name, SOLUTION_NAMES[:max(len(self.solutions), 1)], "branch")
        self._set_branch_quietly(name)
        if self.ik is None or getattr(self, "target", None) is None:
            return
        self.set_target(*self.target)

    def _set_branch_quietly(self, name):
        self.branch = name
        if self.branch_buttons is not None and name in self.branch_buttons.options:
            self._quiet = True
            try:
                self.branch_buttons.value = name
            finally:
                self._quiet = False

    def _set_target_sliders(self, target):
        self._set_quietly(self.target_sliders, target)

    def _show_solutions(self, target):
        """Solve the IK for ``target`` and remember the solutions; return those within the joint limits."""
        solutions, self.ik_message = self._solve(*target)
        wrapped = [wrap_into_limits(self.robot, s) for s in solutions[:MAX_SOLUTIONS]]
        self.solutions = [s for s, ok in wrapped]
        self.solutions_ok = [ok for s, ok in wrapped]
        self.target = target
        return [s for s, ok in wrapped if ok]

    def _solve(self, x, y) -> tuple:
        """The student's ``ik(x, y)``, checked: (the joint vectors as floats, its message)."""
        try:
            solutions = self.ik(x, y)
        except DHLabError:
            raise
        except Exception as exc:        # a bug in the student's ik: say where it happened
            raise DHLabError(_("ik({x:g}, {y:g}) failed: {error}: {message}").format(
                x=x, y=y, error=type(exc).__name__, message=exc)) from exc
        expected = _("ik must return a list of joint vectors, [[q1, q2], ...] ([] when there is none)")
        if not isinstance(solutions, (list, tuple, np.ndarray)) or getattr(solutions, "ndim", 1) == 0:
            raise DHLabError(_("{expected}; ik({x:g}, {y:g}) returned {value}.").format(
                expected=expected, x=x, y=y, value=describe(solutions)))
        message = getattr(solutions, "message", "")
        message = message if isinstance(message, str) else ""
        if len(solutions) == 0:
            return [], message
        try:
            checked = check_joint_values(solutions, self.robot.links, name=_("the solutions"))
        except DHLabError as error:
            raise DHLabError(_("{expected}; ik({x:g}, {y:g}) returned {value}: {error}").format(
                expected=expected, x=x, y=y, value=describe(solutions), error=error)) from None
        if checked.ndim != 2:
            raise DHLabError(_("{expected}; ik({x:g}, {y:g}) returned one joint vector, {value}: put it in a list, "
                               "[{value}].").format(expected=expected, x=x, y=y, value=describe(solutions)))
        return list(checked), message

    def _draw(self, q, target):
        self.view.update(q, draw=False)
        shown = [q_to_slider(link, v) for link, v in zip(self.robot.links, q)]
        self.joint_point.set_data([shown[0]], [shown[1]])
        for k, (ghost, mark, name) in enumerate(zip(self.ghosts, self.solution_marks, self.solution_names)):
            visible = k < len(self.solutions)
            for artist in (*ghost.artists, mark, name):
                artist.set_visible(visible)
            if visible:
                s = self.solutions[k]
                ghost.update(s, draw=False)
                p = [q_to_slider(link, v) for link, v in zip(self.robot.links, s)]
                mark.set_data([p[0]], [p[1]])
                mark.set_markeredgewidth(2 if self.solutions_ok[k] else 1)
                name.set_position((p[0], p[1]))
        if target is None:
            self.target_mark.set_visible(False)
        else:
            self.target_mark.set_visible(True)
            reachable = bool(self.solutions)
            self.target_mark.set_color("k" if reachable else "red")
            if self.view.projection == "3d":
                self.target_mark.set_data_3d([target[0]], [target[1]], [0.0])
            else:
                self.target_mark.set_data([target[0]], [target[1]])
        self.live.refresh()

    def _ik_text(self, target):
        x, y = target
        count = _("{n} solution(s)").format(n=len(self.solutions))
        lines = [_("Target (x, y) = ({x:.3f}, {y:.3f}): {message}").format(
            x=x, y=y, message=html.escape(self.ik_message or count))]
        for name, s, ok in zip(SOLUTION_NAMES, self.solutions, self.solutions_ok):
            shown = ", ".join(
                f"{label} = {q_to_slider(link, v):.3f}{unit_of(self.robot, link) if link.is_revolute else ''}"
                for label, link, v in zip(self.robot.joint_labels, self.robot.links, s))
            lines.append(f"<b>{name}</b>: {shown}" + ("" if ok else _(" <i>(outside the joint limits)</i>")))
        return "<br>".join(lines)

    def _say(self, text):
        self.message.value = text

    def _set_quietly(self, sliders, values):
        for slider, value in zip(sliders, values):
            self.echoes.set(slider, value)

    def __repr__(self):
        return _("<dhlab joint/Cartesian spaces: {name}>").format(name=self.robot.name)


def spaces(robot, q=None, *, ik=None, figsize=FIGSIZE, backend: str = "auto") -> SpacesPanel:
    """Joint space and Cartesian space side by side for a 2-DOF ``robot``.

    ``q``: the starting pose (radians / length units). ``ik(x, y)`` (optional,
    keyword) returns the list of joint vectors that put the end effector at
    (x, y), e.g. ``functools.partial(dhlab.ik.pr_mechanism_ik, robot)``; all of
    them are shown, and target sliders and branch buttons appear.

    >>> import dhlab
    >>> panel = spaces(dhlab.robots.pr_mechanism(), [0.5, dhlab.deg2rad(30)])
    """
    return SpacesPanel(robot, q, ik=ik, figsize=figsize, backend=backend)
