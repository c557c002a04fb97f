"""Frame triads that read without colour: x, y, z in colour *and* by letter.

The seeds draw **x red, y green, z blue** (seed 000, figure 10), and so does the
course by default. Red and green are the pair that about 8 % of male students
cannot tell apart, so every triad can also carry the letters x, y, z at the tips
of its axes, and a colour-blind-safe palette is one call away::

    dhlab.views.triads.set_palette("colorblind")     # Paul Tol's "bright" red, green, blue
    dhlab.views.triads.set_palette("seed")           # back to the seeds' colours

>>> import numpy as np
>>> x, y, z = triad_segments(np.eye(4)[None], 2.0)
>>> z[:2].tolist()
[[0.0, 0.0, 0.0], [0.0, 0.0, 2.0]]
>>> tips = letter_points(np.eye(4)[None], 2.0)
>>> tips[0].round(2).tolist()                  # the x at 1.2 × the axis' length
[[2.4, 0.0, 0.0]]
"""
from __future__ import annotations

import numpy as np

from ..errors import DHLabError
from ..i18n import _
from ..validation import as_choice, as_length, as_matrix4

__all__ = ["PALETTES", "AXIS_COLORS", "set_palette", "palette", "axis_colors", "triad_segments",
           "letter_points", "LETTERS", "LETTER_MARKERS", "draw_triad", "free_direction"]

# x, y, z. "colorblind": Paul Tol's "bright" scheme (red #EE6677, green #228833, blue #4477AA),
# whose red and green differ in lightness as well as hue, so they stay apart for red-green
# colour blindness (deuteranopia, protanopia).
PALETTES = {
    "seed": ("tab:red", "tab:green", "tab:blue"),
    "colorblind": ("#EE6677", "#228833", "#4477AA"),
}
AXIS_COLORS = PALETTES["seed"]          # the seeds' colours (kept for code that imports the constant)
LETTERS = ("x", "y", "z")
LETTER_MARKERS = (r"$x$", r"$y$", r"$z$")   # drawn as markers: one artist per axis
LETTER_GAP = 0.2                        # a letter sits this fraction of the axis' length past its tip

_current = {"palette": "seed"}


def set_palette(name: str = "seed") -> None:
    """Colours of every triad drawn from now on: ``'seed'`` (red, green, blue, as the
    seeds draw them) or ``'colorblind'`` (a red and a green that differ in lightness too)."""
    _current["palette"] = as_choice(name, tuple(PALETTES), "palette")


def palette() -> str:
    """The name of the palette in use."""
    return _current["palette"]


def axis_colors(name: str | None = None) -> tuple:
    """The x, y, z colours of the palette ``name`` (default: the one in use)."""
    return PALETTES[palette() if name is None else as_choice(name, tuple(PALETTES), "palette")]


def triad_segments(frames: np.ndarray, length: float) -> list:
    """Line data for the triads of ``frames`` (m, 4, 4): one array per axis (x, y, z).

    Each array has shape (3m, 3): for every frame its origin, the tip of the
    axis (origin + length · axis) and a NaN row that breaks the line, so that
    one matplotlib line draws the same axis of every frame.
    """
    origins = frames[:, :3, 3]
    out = []
    for k in range(3):
        points = np.full((len(frames), 3, 3), np.nan)
        points[:, 0] = origins
        points[:, 1] = origins + length * frames[:, :3, k]
        out.append(points.reshape(-1, 3))
    return out


def letter_points(frames: np.ndarray, length: float, gap: float = LETTER_GAP) -> list:
    """Where the letters x, y, z of each frame go: one (m, 3) array per axis, just past the tips."""
    origins = frames[:, :3, 3]
    return [origins + (1 + gap) * length * frames[:, :3, k] for k in range(3)]


def draw_triad(ax, T, length: float, label: str | None = None, letters: bool = True, lw: float = 2.5,
               colors=None, fontsize: float = 12, avoid=(), **style) -> list:
    """Draw one triad (a still picture, not a moving view) at the pose ``T`` in a 2D or 3D axes.

    ``letters`` puts x, y, z past the tips (in a 2D axes only the axes that lie in
    the page); ``label`` (mathtext, e.g. ``r'$\\{S_1\\}$'``) goes beside the origin,
    on the side no axis (nor a direction of ``avoid``) points to, as the axes' view shows it
    (so set the view and limits first);
    ``style`` goes to every line (e.g. ``alpha=0.5``, ``ls='--'``). Returns the artists.
    """
    T = as_matrix4(T, "draw_triad's pose T")
    length = as_length(length, "draw_triad's length")
    if not length > 0:
        raise DHLabError(_("draw_triad's length must be positive (the axes' length in data units), "
                           "got {length:g}.").format(length=length))
    colors = axis_colors() if colors is None else colors
    three_d = getattr(ax, "name", "") == "3d"
    artists = []
    for k, (color, seg, tip) in enumerate(zip(colors, triad_segments(T[None], length),
                                              letter_points(T[None], length))):
        if not three_d and abs(T[2, k]) > 0.7:          # points out of / into the page
            mark = r"$\odot$" if T[2, k] > 0 else r"$\otimes$"
            artists += ax.plot(*T[:2, 3], ls="", marker=mark, ms=14, color=color)
            continue
        points = seg[:2] if three_d else seg[:2, :2]
        artists += ax.plot(*points.T, color=color, lw=lw, **style)
        if letters:
            where = tip[0] if three_d else tip[0, :2]
            artists.append(ax.text(*where, LETTERS[k], color=color, fontsize=fontsize, style="italic",
                                   ha="center", va="center", alpha=style.get("alpha")))
    if label:
        o = T[:3, 3] + 0.5 * length * free_direction(ax, T, avoid)
        artists.append(ax.text(*(o if three_d else o[:2]), label, fontsize=fontsize, ha="center", va="center",
                               alpha=style.get("alpha")))
    return artists


def free_direction(ax, T, avoid=()) -> np.ndarray:
    """A unit 3D direction from the origin of ``T`` that, as the axes ``ax`` show it (set
    its view and limits first), points away from the triad's axes and from the
    directions ``avoid`` (e.g. along the links): where a label reads clear."""
    if getattr(ax, "name", "") == "3d":
        azim, elev = np.radians(ax.azim), np.radians(ax.elev)
        right = np.array([-np.sin(azim), np.cos(azim), 0.0])
        up = np.array([-np.sin(elev) * np.cos(azim), -np.sin(elev) * np.sin(azim), np.cos(elev)])
    else:
        right, up = np.array([1.0, 0, 0]), np.array([0, 1.0, 0])
    busy = [T[:3, k] for k in range(3)] + [np.asarray(v, dtype=float) for v in avoid]
    screen = np.array([[v @ right, v @ up] for v in busy])
    length = np.linalg.norm(screen, axis=1)
    screen = screen[length > 0.2] / length[length > 0.2, None]     # an axis seen end-on is in nobody's way
    angles = np.radians(np.arange(0, 360, 15) + 7.5)
    candidates = np.column_stack([np.cos(angles), np.sin(angles)])
    if not len(screen):
        best = candidates[np.argmax(candidates @ [-0.6, -0.8])]
    else:
        best = candidates[np.argmin((candidates @ screen.T).max(axis=1))]   # farthest from every busy one
    return best[0] * right + best[1] * up
