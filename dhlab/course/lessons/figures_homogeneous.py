"""The figures of notebook 2 (homogeneous matrices), drawn by the notebook's own code.

* :func:`two_steps` and :func:`two_step_figure`: "turn 90° about z, then move 1 along x", read in
  the moving frame (the move follows the turned x) and in the fixed frame (the move follows x₀);
* :func:`frame_panel`: three sliders θ, a, α and the same three motions about the moving axes
  (solid triad) and about the fixed axes (dashed triad), with both matrices live.
"""
from __future__ import annotations

import numpy as np
from matplotlib.lines import Line2D

from ...i18n import N_, _
from ...transforms import Rx, Rz, trans
from ...units import deg2rad
from ...views.figures import new_figure
from .figures_common import AXIS_COLORS, LETTERS, label, triad

__all__ = ["two_steps", "two_step_figure", "frame_panel"]


def two_steps(reading: str, angle_deg: float = 90.0, distance: float = 1.0) -> dict:
    """The frames of "turn ``angle_deg`` about z, then move ``distance`` along x":
    ``{"start", "step 1", "step 2"}`` (4x4 each). ``reading`` is ``"moving"`` (the move follows the
    frame's own, turned x: post-multiply) or ``"fixed"`` (the move follows x₀: pre-multiply).
    Either way step 1 is the turn alone, in place."""
    turn, move = Rz(deg2rad(angle_deg)), trans(distance, 0, 0)
    final = {"moving": lambda: turn @ move, "fixed": lambda: move @ turn}
    if reading not in final:
        raise ValueError(f"reading must be 'moving' or 'fixed', got {reading!r}")
    return {"start": np.eye(4), "step 1": turn, "step 2": final[reading]()}


# Where the words go in each panel (data units), placed by eye so that no text sits on a line:
# in each reading some axis of one frame runs on along an axis of another.
_LAYOUT = {
    "moving": dict(title=N_(r"moving frame: $R_z(90°)\cdot\mathrm{Tr}(1,0,0)$"),
                   move=N_("2: move 1\nalong the\nnew $x'$"), move_side=(0.3, 0), move_text_at=(0.4, 0.62),
                   turn_text_at=(0.3, -0.15), S0_at=(-0.3, -0.24), S1_at=(0.25, 1.22),
                   start_shifts=((0.07, 0), (-0.13, -0.08), (0, 0))),
    "fixed": dict(title=N_(r"fixed frame: $\mathrm{Tr}(1,0,0)\cdot R_z(90°)$"),
                  move=N_("2: move 1 along $x_0$"), move_side=(0, -0.22), move_text_at=(0.5, -0.42),
                  turn_text_at=(0.25, 0.2), S0_at=(-0.3, -0.24), S1_at=(1.3, -0.22),
                  start_shifts=((-0.06, -0.12), (-0.13, -0.08), (0, 0))),
}


def _turn_arc(ax, text_at, radius=0.2):
    """Step 1 as a curved arrow about z, from x₀ round to the turned x (90°)."""
    t = np.radians(np.linspace(8, 80, 30))
    ax.plot(radius * np.cos(t), radius * np.sin(t), color="0.35", lw=1.5)
    ax.annotate("", xy=(radius * np.cos(np.radians(86)), radius * np.sin(np.radians(86))),
                xytext=(radius * np.cos(t[-2]), radius * np.sin(t[-2])),
                arrowprops=dict(arrowstyle="-|>", color="0.35", lw=1.5, mutation_scale=14))
    label(ax, text_at, _("1: turn 90°"), color="0.2", ha="left")


def _move_arrow(ax, start, end, side, text, text_at):
    """Step 2 as a straight arrow beside the path of the origin (moved by ``side``, so that it does
    not hide an axis drawn along the same line)."""
    side = np.asarray(side, dtype=float)
    ax.annotate("", xy=end[:2] + side, xytext=start[:2] + side,
                arrowprops=dict(arrowstyle="-|>", color="0.35", lw=2, ls="--", mutation_scale=16,
                                shrinkA=0, shrinkB=0))
    label(ax, text_at, text, color="0.2", ha="left" if side[0] > 0 else "center")


def two_step_figure():
    """Two panels seen from above: the moving-frame reading (left) and the fixed-frame reading
    (right) of "turn 90° about z, then move 1 along x". Faint: {S₀}; dashed: the frame after step 1
    (the turn, in place); solid: {S₁} after step 2 (the move). The lines are named
    ``"<reading>:<frame>:<axis>"`` (e.g. ``"moving:step 1:x"``). Returns the figure."""
    fig = new_figure((10, 5.6))
    axes = fig.subplots(1, 2, sharey=True)
    for ax, (reading, where) in zip(axes, _LAYOUT.items()):
        frames = two_steps(reading)
        title, move = where["title"], where["move"]             # marked N_ above: translated here
        triad(ax, frames["start"], 0.4, sub="0", lw=1.8, alpha=0.5, shifts=where["start_shifts"],
              gid=f"{reading}:start")
        triad(ax, frames["step 1"], 0.72, names=("$x'$", "$y'$", "$z'$"), lw=2.2, ls=(0, (4, 2)),
              shifts=((-0.13, -0.1), (0, 0), (0, 0)), gid=f"{reading}:step 1")
        triad(ax, frames["step 2"], 0.45, sub="1", lw=3.2, shifts=((0, 0), (0, 0.1), (0, 0)),
              gid=f"{reading}:step 2")
        _turn_arc(ax, where["turn_text_at"])
        _move_arrow(ax, frames["step 1"][:3, 3], frames["step 2"][:3, 3], where["move_side"], _(move),
                    where["move_text_at"])
        label(ax, where["S0_at"], r"$\{S_0\}$", color="0.3")
        label(ax, where["S1_at"], r"$\{S_1\}$")
        ax.set(xlim=(-1.1, 1.75), ylim=(-0.75, 1.75), aspect="equal", xlabel="$x_0$")
        ax.set_title(_(title), fontsize=13)
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("$y_0$")
    fig.suptitle(_("turn 90° about z, then move 1 along x: two readings"), fontsize=14)
    handles = [Line2D([], [], color="0.3", lw=1.8, alpha=0.5, label=_(r"$\{S_0\}$, the start")),
               Line2D([], [], color="0.3", lw=2.2, ls=(0, (4, 2)), label=_("after step 1 (the turn)")),
               Line2D([], [], color="0.3", lw=3.2, label=_(r"$\{S_1\}$, after step 2 (the move)")),
               Line2D([], [], ls="", marker="o", ms=9, mfc="white", mec=AXIS_COLORS[2], mew=1.8,
                      label=_("$z$, towards you"))]
    fig.legend(handles=handles, loc="outside lower center", ncols=4, fontsize=12, frameon=False)
    return fig


def frame_panel(theta_deg=30.0, a=1.0, alpha_deg=45.0):
    """Sliders θ, a, α: the same three motions about the moving axes (solid triad,
    Rz(θ)·Tr(a,0,0)·Rx(α), the DH way) and about the fixed axes (dashed triad,
    Rx(α)·Tr(a,0,0)·Rz(θ)), both matrices live. Returns the panel (``.sliders``: θ, a, α)."""
    import ipywidgets as widgets  # lazy: the notebook's own libraries, on first display

    from ...views.live.livefigure import LiveFigure  # lazy: the live views load ipywidgets and mplot3d
    from ...views.panels.panel import Panel  # lazy: the live views load ipywidgets and mplot3d
    from ...views.panels.teach import matrix_html  # lazy: the live views load ipywidgets and mplot3d

    live = LiveFigure(figsize=(6.0, 6.4))
    ax = live.figure.add_subplot(projection="3d")
    live.figure.subplots_adjust(left=0.0, right=0.92, bottom=0.15, top=1.0)
    ax.set(xlim=(-1.5, 1.5), ylim=(-1.5, 1.5), zlim=(-1.5, 1.5), xlabel="$x_0$", ylabel="$y_0$", zlabel="$z_0$")
    ax.set_box_aspect((1, 1, 1), zoom=0.95)
    triad(ax, np.eye(4), 0.6, sub="0", lw=1.5, alpha=0.5)                        # {S0}, still
    solid = [ax.plot([], [], [], color=c, lw=3)[0] for c in AXIS_COLORS]
    dashed = [ax.plot([], [], [], color=c, lw=2, ls="--")[0] for c in AXIS_COLORS]
    letters = [label(ax, (0, 0, 0), f"${k}$", color=c) for k, c in zip(LETTERS, AXIS_COLORS)]
    dashed_letters = [label(ax, (0, 0, 0), f"${k}$", color=c, alpha=0.8) for k, c in zip(LETTERS, AXIS_COLORS)]
    live.add_moving(*solid, *dashed, *letters, *dashed_letters)
    moving_name = _(r"about the moving axes: $R_z(\theta)\,\mathrm{Tr}(a,0,0)\,R_x(\alpha)$")
    fixed_name = _(r"about the fixed axes: $R_x(\alpha)\,\mathrm{Tr}(a,0,0)\,R_z(\theta)$")
    handles = [Line2D([], [], color="0.3", lw=3, label=moving_name),
               Line2D([], [], color="0.3", lw=2, ls="--", label=fixed_name),
               Line2D([], [], color="0.3", lw=1.5, alpha=0.5, label=_(r"$\{S_0\}$, the fixed frame"))]
    live.figure.legend(handles=handles, loc="lower center", fontsize=11, frameon=False)
    sliders = [widgets.FloatSlider(value=theta_deg, min=-180, max=180, step=1, description="θ [°]"),
               widgets.FloatSlider(value=a, min=0, max=1.2, step=0.01, description="a"),
               widgets.FloatSlider(value=alpha_deg, min=-180, max=180, step=1, description="α [°]")]
    moving_html, fixed_html = widgets.HTML(), widgets.HTML()
    panel = Panel(live, [*sliders, moving_html, fixed_html])

    def redraw():
        th, a_, al = deg2rad(sliders[0].value), sliders[1].value, deg2rad(sliders[2].value)
        T_moving = Rz(th) @ trans(a_, 0, 0) @ Rx(al)
        T_fixed = Rx(al) @ trans(a_, 0, 0) @ Rz(th)
        for lines, T in ((solid, T_moving), (dashed, T_fixed)):
            for k, line in enumerate(lines):
                line.set_data_3d(*np.array([T[:3, 3], T[:3, 3] + 0.8 * T[:3, k]]).T)
        for texts, T in ((letters, T_moving), (dashed_letters, T_fixed)):       # x, y, z at the tips
            for k, text in enumerate(texts):
                text.set_position_3d(T[:3, 3] + 0.98 * T[:3, k])
        live.refresh()
        moving_html.value = matrix_html(
            T_moving, _("moving axes (solid): R<sub>z</sub>(θ)·Tr(a,0,0)·R<sub>x</sub>(α)"))
        fixed_html.value = matrix_html(
            T_fixed, _("fixed axes (dashed): R<sub>x</sub>(α)·Tr(a,0,0)·R<sub>z</sub>(θ)"))

    panel.observe_values(sliders, redraw)
    redraw()
    panel.sliders = sliders
    return panel
