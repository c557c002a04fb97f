"""Seed 000's C++ SSRMS program, line for line in Python (the appendix of notebook 7).

``configurarTH`` pushes two matrices per model into ``THList`` (the base's pair first), a key press
rebuilds one joint's Tz factor and writes it into its slot, and ``renderizar`` multiplies the list in
order. ``SeedProgram(printed=True)`` runs the key handler as the seed prints it, which stores ``THx``
instead of ``THz`` (erratum 000-2). :func:`seed001_frames` builds the arm with seed 001's faulty
``DefinirTHz`` instead (errata 001-1, 001-2).

>>> program = SeedProgram()
>>> program.press(97)                       # numpad 1: θ1 += 5°
>>> program.theta[1]
5.0
>>> SeedProgram(printed=True).pressed(97).renderizar()[:3, 3].round(6).tolist()
[24.0, 0.0, -13.0]
"""
from __future__ import annotations

import numpy as np

from ...errors import DHLabError
from ...i18n import _
from ...transforms import Rx, Rz, trans
from ...validation import as_number
from ..exercises.homogeneous import seed001_DefinirTHz  # seed 001's listing, transcribed in notebook 2

__all__ = ["CONFIGURAR_TH", "KEYS", "OFFSETS", "SeedProgram", "seed001_frames"]

# configurarTH, one line per link b1 … b6 and the gripper: (d, α in degrees, a)
CONFIGURAR_TH = [(2.5, -90, 0), (6, -90, 0), (6, 0, 12), (1, 0, 12), (6, -90, 0), (6, -90, 0), (0, 0, 0)]
# WindowProc: key code -> (joint, sense of the change); 97, 100, 103 are VK_NUMPAD1, 4, 7
KEYS = {97: (1, +1), 100: (2, +1), 103: (3, +1), ord("R"): (4, +1), ord("F"): (5, +1), ord("V"): (6, +1),
        ord("G"): (7, -1)}
OFFSETS = {k + 1: d for k, (d, _alpha, _a) in enumerate(CONFIGURAR_TH)}      # d_k of each joint's Tz factor


class SeedProgram:
    """Seed 000's C++ SSRMS: THList, configurarTH, the key handler and renderizar (angles in degrees)."""

    def __init__(self, printed: bool = False):
        self.printed = bool(printed)
        self.theta = {k: 0.0 for k in range(1, 8)}
        self.THList = []
        self.configurarTH()

    def AplicarTHz(self, theta_deg, d):
        """THz = Tr(d)·R_z(θ): the seed's DefinirTHz (erratum note 000-8)."""
        self.THz = trans(*d) @ Rz(np.radians(theta_deg))

    def AplicarTHx(self, alpha_deg, d):
        """THx = Tr(d)·R_x(α): the seed's DefinirTHx."""
        self.THx = trans(*d) @ Rx(np.radians(alpha_deg))

    def configurarTH(self):
        """Push the 16 matrices, two per model, the base's pair (the identity) first."""
        for d, alpha, a in [(0, 0, 0)] + CONFIGURAR_TH:
            self.AplicarTHz(0, (0, 0, d))
            self.THList.append(self.THz)
            self.AplicarTHx(alpha, (a, 0, 0))
            self.THList.append(self.THx)

    def press(self, code, dtheta=5.0):
        """One key press: θ_k ± dtheta, rebuild joint k's Tz, write it into THList[2k]."""
        joint, sense, dtheta = _read_key(code, dtheta)
        self.theta[joint] += sense * dtheta
        self.AplicarTHz(self.theta[joint], (0, 0, OFFSETS[joint]))
        self.THList[2 * joint] = self.THx if self.printed else self.THz   # the seed prints THx: erratum 000-2

    def pressed(self, *codes):
        """Press the keys ``codes`` in order; returns the program (to chain calls)."""
        for code in codes:
            self.press(code)
        return self

    def renderizar(self) -> np.ndarray:
        """TH = TH · THList[2m] · THList[2m+1] for each model m: the gripper's pose in the base."""
        TH = np.eye(4)
        for m in range(8):
            TH = TH @ self.THList[2 * m] @ self.THList[2 * m + 1]
        return TH


def seed001_frames(theta_deg) -> np.ndarray:
    """Every frame (8, 4, 4) of the SSRMS chain built with seed 001's ``DefinirTHz`` for each Tz factor
    (the THx of seed 000 is right); ``theta_deg``: the 7 joint angles in degrees."""
    theta_deg = np.asarray(theta_deg, dtype=float) if _is_numbers(theta_deg) else None
    if theta_deg is None or theta_deg.shape != (len(CONFIGURAR_TH),):
        raise DHLabError(_("theta_deg: expected {n} joint angles in degrees, e.g. [0] * 7.").format(
            n=len(CONFIGURAR_TH)))
    frames = [np.eye(4)]
    for (d, alpha, a), t in zip(CONFIGURAR_TH, theta_deg):
        A = seed001_DefinirTHz(np.radians(t), (0, 0, d)) @ trans(a, 0, 0) @ Rx(np.radians(alpha))
        frames.append(frames[-1] @ A)
    return np.array(frames)


def _is_numbers(values) -> bool:
    try:
        return np.asarray(values, dtype=float).dtype.kind == "f"
    except (TypeError, ValueError):
        return False


def _read_key(code, dtheta):
    """The joint and sense of key ``code``, and ``dtheta`` as a number; a clear error otherwise."""
    if isinstance(code, bool) or not isinstance(code, (int, np.integer)) or int(code) not in KEYS:
        raise DHLabError(_("key code {code!r} is not one of the seed's keys {keys}: 97, 100, 103 are "
                           "numpad 1, 4, 7; the letters are ord('R'), ord('F'), ord('V'), ord('G').").format(
                               code=code, keys=sorted(KEYS)))
    return (*KEYS[int(code)], as_number(dtheta, "dtheta"))
