"""Where the 3D camera looks from: presets, and a default from which every triad reads.

A camera is matplotlib's ``(elev, azim)`` pair in degrees: ``elev`` is the
height of the eye above the x-y plane, ``azim`` its turn about z (``azim=-90``
looks along +y, with x to the right).

Presets (seed 000 draws its frames from ``iso``):

=========  =====================================================  =============
``iso``    the most readable oblique view for the frames shown    computed
``front``  looking along +y: x to the right, z up                  (0, -90)
``side``   looking along -x: y to the right, z up                  (0, 0)
``top``    looking down -z: x to the right, y up                   (90, -90)
=========  =====================================================  =============

A triad *reads* from a camera when none of its axes points (nearly) at the
eye and no two of its axes are drawn (nearly) on top of each other: then x, y
and z are three distinct arrows and the eye sees the right-handed frame. From
a badly chosen camera an axis shrinks to a dot, or z₁ is drawn along z₀.
:func:`readable_camera` searches the oblique views for the one where every
triad reads best.

>>> import numpy as np
>>> frames = np.stack([np.eye(4), np.eye(4)])
>>> frames[1, :3, :3] = [[1, 0, 0], [0, 0, -1], [0, 1, 0]]     # turned 90° about x
>>> elev, azim = readable_camera(frames)
>>> bool(triad_readability(frames, elev, azim).min() >= 1)     # both triads read
True
>>> PRESETS["front"]
(0.0, -90.0)
"""
from __future__ import annotations

import numpy as np

from ..errors import DHLabError
from ..i18n import _

__all__ = ["PRESETS", "DEFAULT_CAMERA", "readable_camera", "triad_readability", "set_camera",
           "camera_direction"]

PRESETS = {"front": (0.0, -90.0), "side": (0.0, 0.0), "top": (90.0, -90.0)}
DEFAULT_CAMERA = (30.0, -60.0)       # matplotlib's own default oblique view
MIN_PROJECTED = 0.4                  # an axis drawn shorter than this (of its length) hardly reads
MIN_ANGLE_DEG = 30.0                 # two axes drawn closer than this look like one


def camera_direction(elev, azim) -> np.ndarray:
    """Unit vector(s) from the scene towards the eye for ``(elev, azim)`` in degrees."""
    e, a = np.radians(elev), np.radians(azim)
    return np.stack([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)], axis=-1)


def _screen_basis(view):
    """(right, up) unit vectors of the screen for eye directions ``view`` (..., 3), z up."""
    right = np.cross([0.0, 0.0, 1.0], view)
    norm = np.linalg.norm(right, axis=-1, keepdims=True)
    right = np.where(norm > 1e-9, right / np.maximum(norm, 1e-12), [1.0, 0.0, 0.0])
    up = np.cross(view, right)
    return right, up


def triad_readability(frames, elev, azim) -> np.ndarray:
    """How well each triad of ``frames`` (m, 4, 4) reads from ``(elev, azim)``: 1 or more
    reads (every axis drawn at least :data:`MIN_PROJECTED` of its length and every two
    axes at least :data:`MIN_ANGLE_DEG` apart), below 1 does not. Shape (m,)."""
    R = np.asarray(frames, dtype=float)[:, :3, :3]
    right, up = _screen_basis(camera_direction(elev, azim))
    # screen coordinates of each axis of each frame: (m, 3 axes, 2)
    xy = np.stack([np.einsum("mik,i->mk", R, right), np.einsum("mik,i->mk", R, up)], axis=-1)
    length = np.linalg.norm(xy, axis=-1)
    angles = []
    for i, j in ((0, 1), (1, 2), (0, 2)):
        cos = np.sum(xy[:, i] * xy[:, j], axis=-1) / np.maximum(length[:, i] * length[:, j], 1e-12)
        angles.append(np.degrees(np.arccos(np.clip(cos, -1, 1))))
    return np.minimum(length.min(axis=1) / MIN_PROJECTED, np.min(angles, axis=0) / MIN_ANGLE_DEG)


def readable_camera(frames, prefer=DEFAULT_CAMERA) -> tuple:
    """The oblique camera ``(elev, azim)`` from which the triads of ``frames`` (m, 4, 4)
    read best: most triads reading, then the worst one as clear as possible (a margin
    beyond 1.5 counts no more), then as close to ``prefer`` as possible."""
    frames = np.asarray(frames, dtype=float)
    if frames.ndim != 3 or frames.shape[1:] != (4, 4):
        raise DHLabError(_("readable_camera needs frames of shape (m, 4, 4), got {shape}.").format(shape=frames.shape))
    best, best_key = prefer, None
    for elev in (15.0, 20.0, 25.0, 30.0, 35.0, 40.0):
        for azim in np.arange(-180.0, 180.0, 5.0):
            score = triad_readability(frames, elev, azim)
            distance = abs(elev - prefer[0]) + abs((azim - prefer[1] + 180) % 360 - 180) / 3
            key = (int(np.sum(score >= 1)), round(min(float(score.min()), 1.5), 2), -distance)
            if best_key is None or key > best_key:
                best, best_key = (elev, float(azim)), key
    return best


def set_camera(ax, preset="iso", *, frames=None, elev=None, azim=None) -> tuple:
    """Point the camera of a 3D ``ax``: a preset name ('iso', 'front', 'side', 'top'),
    or ``elev``/``azim`` in degrees. 'iso' with ``frames`` (m, 4, 4) picks
    :func:`readable_camera` for them (without: matplotlib's default oblique view).
    Returns ``(elev, azim)``.

    >>> from dhlab.views.figures import new_figure
    >>> ax = new_figure().add_subplot(projection="3d")
    >>> set_camera(ax, "top")
    (90.0, -90.0)
    """
    if elev is not None or azim is not None:
        view = (float(elev if elev is not None else ax.elev), float(azim if azim is not None else ax.azim))
    elif preset == "iso":
        view = readable_camera(frames) if frames is not None else DEFAULT_CAMERA
    elif preset in PRESETS:
        view = PRESETS[preset]
    else:
        raise DHLabError(_("camera preset must be one of 'iso', {presets}; got {preset!r}.").format(
            presets=", ".join(map(repr, PRESETS)), preset=preset))
    if not hasattr(ax, "view_init"):
        raise DHLabError(_("set_camera needs a 3D axes (projection='3d')."))
    ax.view_init(elev=view[0], azim=view[1])
    return view
