"""Notebook 5's first robot: a SCARA, simple enough to predict its DH table row by row.

A SCARA (Selective Compliance Assembly Robot Arm) has two revolute joints about vertical
axes (a planar arm seen from above), a prismatic joint that moves the tool up and down and a
revolute joint that turns the tool. Every pair of consecutive axes is parallel (case 2 of
x_i), so its table is the easiest a real robot has, yet it has each kind of entry: joint
variables in θ and in d, link lengths a, and one twist α = 180° where the axis is turned over
to point down the quill.
"""
from __future__ import annotations

from ...dh import DHRobot
from ...i18n import _
from .figures_dh_examples import frame_pairs_figure

__all__ = ["FIRST_ROBOT_ROWS", "FIRST_ROBOT_LENGTHS", "DRAWN_Q", "first_robot", "first_robot_figure"]

# (θ, d, a, α) as the slides write them: angles in degrees, joint variables by name.
FIRST_ROBOT_ROWS = [("q1", "l1", "l2", 0),      # shoulder: turn about the vertical z0, arm of length l2
                    ("q2", 0, "l3", 180),       # elbow: a second arm l3, z2 turned over to point down
                    (0, "d3", 0, 0),            # quill: slides down along z2
                    ("q4", "l4", 0, 0)]         # tool roll: turns about z3, the tool l4 below the wrist
FIRST_ROBOT_LENGTHS = {"l1": 0.4, "l2": 0.35, "l3": 0.25, "l4": 0.1}     # metres
DRAWN_Q = (0.0, 0.0, 0.15, 0.0)        # the pose drawn: q1 = q2 = q4 = 0, the quill down by d3 = 0.15 m


def first_robot() -> DHRobot:
    """The SCARA of notebook 5's first pass through rules 10–13 (standard DH, lengths in metres)."""
    return DHRobot.from_table(FIRST_ROBOT_ROWS, name=_("SCARA (first robot)"), params=FIRST_ROBOT_LENGTHS)


def first_robot_figure(robot=None):
    """The SCARA's frames {S_0} … {S_4} at :data:`DRAWN_Q`, one pair per picture, titled only
    "{S_(i−1)} → {S_i}" (a title with the row would give the prediction away)."""
    robot = first_robot() if robot is None else robot
    return frame_pairs_figure(robot, DRAWN_Q, titles=[f"{{S{i - 1}}} → {{S{i}}}" for i in range(1, robot.n + 1)])
