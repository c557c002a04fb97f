"""A robot's pose in a view or a panel: one checked joint vector, and its units on a slider.

Units (one rule everywhere): a revolute joint's slider is in **degrees**, a prismatic joint's
slider in the robot's **length unit**; the maths gets radians. :func:`slider_to_q` and
:func:`q_to_slider` are the only two places that convert.

>>> import dhlab
>>> robot = dhlab.robots.pr_mechanism()
>>> checked_start(robot, [0.25, dhlab.deg2rad(30)]).round(6).tolist()
[0.25, 0.523599]
>>> [round(q_to_slider(link, v), 6) for link, v in zip(robot.links, [0.25, dhlab.deg2rad(30)])]
[0.25, 30.0]
"""
from __future__ import annotations

import numpy as np

from ..errors import DHLabError
from ..i18n import _
from ..validation import check_joint_values

__all__ = ["one_pose", "default_q", "checked_start", "unit_of", "q_to_slider", "slider_to_q"]


def one_pose(robot, q, name: str = "q") -> np.ndarray:
    """One joint vector for ``robot`` as floats (radians / length units): ``None``
    gives :func:`default_q`; a batch, text, NaN… are refused with a DHLabError."""
    if q is None:
        return default_q(robot)
    return check_joint_values(q, robot.links, name=name, single=True)


def default_q(robot) -> np.ndarray:
    """The zero pose, moved inside the joint limits where zero is outside them."""
    lo, hi = np.array([link.qlim for link in robot.links], dtype=float).T
    return np.clip(np.zeros(robot.n), lo, hi)


def checked_start(robot, q) -> np.ndarray:
    """``q`` as a float array, refused with a clear message if it has the wrong
    length or lies outside the joint limits (a slider could not show it)."""
    q = one_pose(robot, q)              # one pose: no batch, text, NaN, degrees as radians
    for j, (link, value) in enumerate(zip(robot.links, q)):
        lo, hi = link.qlim
        if not lo - 1e-12 <= value <= hi + 1e-12:
            shown = [f"{q_to_slider(link, v):g}{unit_of(robot, link)}" for v in (value, lo, hi)]
            raise DHLabError(_("q[{j}] = {value} is outside joint {joint}'s limits [{lo}, {hi}]; start inside "
                               "them (revolute values in radians: use dhlab.deg2rad(...) for degrees).").format(
                j=j, value=shown[0], joint=j + 1, lo=shown[1], hi=shown[2]))
    return q


def unit_of(robot, link) -> str:
    """The display unit of a joint: '°' for revolute, the robot's length unit for prismatic."""
    if link.is_revolute:
        return "°"
    return getattr(robot, "unit", "") or _("length")


def q_to_slider(link, value: float) -> float:
    """Joint value (radians or length) -> slider value (degrees or length)."""
    return float(np.degrees(value)) if link.is_revolute else float(value)


def slider_to_q(robot, sliders) -> np.ndarray:
    """The joint vector (radians / length units) that the sliders show."""
    return np.array([np.radians(s.value) if link.is_revolute else s.value
                     for link, s in zip(robot.links, sliders)], dtype=float)
