"""Drawing pieces shared by the notebooks' own figures (notebooks 2, 5 and 7).

* :func:`triad` draws a frame as three arrows, **x red, y green, z blue** (seed 000, figure 10),
  with the letters x, y, z at the tips, so that the axes can be told apart without colour;
* :func:`label` writes a text with a white halo, readable over lines and grid;
* :func:`fit_box` sets equal-scale 3D limits around some points (nothing drawn outside the box).

Every figure is a :func:`~dhlab.views.figures.new_figure`: at least 100 dpi and 450 px wide, no text
under 12 px, never clipped when shown.
"""
from __future__ import annotations

import numpy as np
from matplotlib import patheffects

from ...views.triads import AXIS_COLORS, axis_colors

__all__ = ["AXIS_COLORS", "LETTERS", "triad", "label", "fit_box", "HALO"]

LETTERS = ("x", "y", "z")
FONTSIZE = 13                                  # points: 18 px at 100 dpi, readable when projected
HALO = [patheffects.withStroke(linewidth=3.5, foreground="white")]   # text stays readable over lines


def _is_3d(ax) -> bool:
    return ax.name == "3d"


def label(ax, point, text, *, color="black", fontsize=FONTSIZE, **style):
    """``text`` at ``point`` (2 or 3 coordinates), with a white halo. Returns the Text."""
    point = np.asarray(point, dtype=float)
    style = {"ha": "center", "va": "center", "path_effects": HALO, **style}
    if _is_3d(ax):
        return ax.text(*point[:3], text, color=color, fontsize=fontsize, **style)
    return ax.text(*point[:2], text, color=color, fontsize=fontsize, **style)


def triad(ax, T, length, *, sub: str = "", letters=True, names=None, shifts=None, lw: float = 2.5, ls: str = "-",
          alpha: float = 1.0, tip: float = 1.22, gid: str | None = None) -> list:
    """Draw frame ``T`` (4x4) as three axes of ``length``, x red, y green, z blue, with the
    letters at the tips (``sub``: their subscript, e.g. ``"0"`` gives x₀ y₀ z₀; ``names``: three
    texts of your own instead, e.g. ``("$x'$", "$y'$", "$z'$")``; ``shifts``: three offsets, in data
    units, that move a letter off a line it would sit on).

    On a 2D axes the frame is seen from above: x and y are drawn, z (towards you) is a blue ⊙ at
    the origin. ``gid`` names the lines ``f"{gid}:x"`` … so a test can find what was drawn.
    Returns the artists."""
    T = np.asarray(T, dtype=float)
    origin = T[:3, 3]
    artists = []
    for k, (letter, color) in enumerate(zip(LETTERS, axis_colors())):
        end = origin + length * T[:3, k]
        name = names[k] if names else f"${letter}_{{{sub}}}$" if sub else f"${letter}$"
        if _is_3d(ax):
            line, = ax.plot(*np.array([origin, end]).T, color=color, lw=lw, ls=ls, alpha=alpha,
                            solid_capstyle="round")
        elif k < 2:
            line, = ax.plot(*np.array([origin, end])[:, :2].T, color=color, lw=lw, ls=ls, alpha=alpha,
                            solid_capstyle="round")
        else:                                   # seen from above, z points at the reader
            line, = ax.plot(*origin[:2], ls="", marker="o", ms=9, mfc="white", mec=color, mew=1.8,
                            alpha=alpha)
            artists += [line, ax.plot(*origin[:2], ls="", marker=".", ms=5, color=color, alpha=alpha)[0]]
            line.set_gid(f"{gid}:{letter}" if gid else None)
            continue
        line.set_gid(f"{gid}:{letter}" if gid else None)
        artists.append(line)
        if letters:
            at = origin + tip * length * T[:3, k]
            if shifts is not None:
                at = at + np.resize(np.asarray(shifts[k], dtype=float), 3) * (np.arange(3) < len(shifts[k]))
            artists.append(label(ax, at, name, color=color, alpha=alpha))
    return artists


def fit_box(ax, points, pad: float) -> None:
    """Equal-scale 3D limits around ``points`` (n, 3) plus ``pad``, the box shaped like them."""
    P = np.asarray(points, dtype=float).reshape(-1, 3)
    lo, hi = P.min(axis=0) - pad, P.max(axis=0) + pad
    ax.set(xlim=(lo[0], hi[0]), ylim=(lo[1], hi[1]), zlim=(lo[2], hi[2]))
    ax.set_box_aspect(hi - lo)
