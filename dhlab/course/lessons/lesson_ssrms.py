"""What notebook 7 (the SSRMS) needs only to print and compare, kept out of its lesson cells.

The lesson cells compute (the 14 factors, the DH table, the frames at zero, the axes at 201
configurations); these helpers only turn the results into short, readable text:

* :func:`fmt`: a vector as ``(x, y, z)``, rounded, without ``-0``;
* :func:`factors_latex`: seed 000's product of 14 factors, on two lines (one is wider than the page);
* :func:`frames_table`: the frames B_0 … B_n, one line each (origin, x, y, z);
* :func:`same_axes`: do the frames' axes match a list of ``{"x": …, "y": …, "z": …}``?
* :func:`seed_words`: seed 000's claim for one link ("the point 12i+0j+6k, axes unturned");
* :func:`axis_relations`: how z_(i−1) and z_i lie at every configuration (:func:`dhlab.lines.relation`).

>>> fmt([12.0, -0.0, -3.5])
'(12, 0, -3.5)'
>>> seed_words(-90, (0, 0, 2.5))
"the seed's point 0i+0j+2.5k, turned -90° about x"
"""
from __future__ import annotations

import numpy as np
import sympy as sp

from ...errors import DHLabError
from ...i18n import _
from ...lines import relation
from . import printing

__all__ = ["fmt", "factors_latex", "frames_table", "same_axes", "seed_words", "axis_relations"]


def fmt(v, digits: int = 3) -> str:
    """The vector ``v`` as ``(x, y, z)``, rounded to ``digits`` decimals, trailing zeros and -0 dropped
    (see :func:`dhlab.course.lessons.printing.fmt`)."""
    return printing.fmt(v, digits, trim=True)


def factors_latex(config, per_line: int = 4) -> str:
    """Seed 000's product T = T_z[θ1, d1] T_x[α1°, a1] · … as LaTeX, ``per_line`` links a line.

    ``config``: one ``(d, α in degrees, a)`` per link (``CONFIGURAR_TH``); link k turns by θ_k."""
    rows = list(config)
    if not rows or any(len(row) != 3 for row in rows):
        raise DHLabError(_("config: expected one (d, alpha_deg, a) per link, got {config!r}; "
                           "pass dhlab.course.lessons.ssrms_program.CONFIGURAR_TH.").format(config=config))
    pairs = [rf"T_z[\theta_{k + 1}, {sp.latex(sp.nsimplify(d))}]\,T_x[{alpha}^\circ, {a}]"
             for k, (d, alpha, a) in enumerate(rows)]
    lines = [r"\cdot ".join(pairs[i:i + per_line]) for i in range(0, len(pairs), per_line)]
    return r"\begin{aligned} T = {} & " + r"\\ & \cdot ".join(lines) + r"\end{aligned}"


def frames_table(frames) -> str:
    """The frames (n, 4, 4) as a text table: one line per frame, its origin and its x, y, z axes."""
    frames = _frames(frames)
    lines = [_("frame | origin         | x          | y          | z")]
    for i, F in enumerate(frames):
        lines.append(f"  {i}   | {fmt(F[:3, 3]):14s} | {fmt(F[:3, 0]):10s} | {fmt(F[:3, 1]):10s} | {fmt(F[:3, 2])}")
    return "\n".join(lines)


def same_axes(frames, axes, atol: float = 1e-9) -> bool:
    """True when every frame's columns x, y, z equal ``axes[i]["x"]``, ``["y"]``, ``["z"]``."""
    frames = _frames(frames)
    if len(axes) != len(frames):
        return False
    return all(np.allclose(F[:3, k], expected[name], atol=atol)
               for F, expected in zip(frames, axes) for k, name in enumerate("xyz"))


def seed_words(angle, point) -> str:
    """Seed 000's claim for one link, as it words it: the point ``ai+bj+ck`` and the turn about x."""
    i, j, k = point
    turn = _(", turned {angle:g}° about x").format(angle=angle) if angle else _(", axes unturned")
    return _("the seed's point {i:g}i+{j:g}j+{k:g}k{turn}").format(i=i, j=j, k=k, turn=turn)


def axis_relations(frames, i: int) -> list:
    """How z_(i−1) and z_i lie at each configuration: one :class:`dhlab.lines.LineRelation` per
    configuration, for ``frames`` of shape (m, n+1, 4, 4) (``robot.frames(Q)``)."""
    frames = np.asarray(frames, dtype=float)
    if frames.ndim != 4 or frames.shape[-2:] != (4, 4):
        raise DHLabError(_("frames: expected shape (configurations, frames, 4, 4), got {shape}; "
                           "pass robot.frames(Q) for a 2D array Q of configurations.").format(shape=frames.shape))
    if not 1 <= i < frames.shape[1]:
        raise DHLabError(_("i = {i!r}: expected 1 … {last} (z_(i-1) and z_i must both exist).").format(
            i=i, last=frames.shape[1] - 1))
    return [relation((F[i - 1, :3, 3], F[i - 1, :3, 2]), (F[i, :3, 3], F[i, :3, 2])) for F in frames]


def _frames(frames) -> np.ndarray:
    frames = np.asarray(frames, dtype=float)
    if frames.ndim != 3 or frames.shape[1:] != (4, 4):
        raise DHLabError(_("frames: expected shape (n, 4, 4), got {shape}; pass robot.frames(q) for one q.").format(
            shape=frames.shape))
    return frames
