"""The exercises of notebook 1 (start here): a joint vector for the API, the glossary, the colour of z."""
from __future__ import annotations

import math

from ...i18n import N_
from ..checks.feedback import Exercise
from ..checks.values import check_value
from ..checks.words import check_choice, check_terms


def _ex_1_1():
    return Exercise("1.1", N_("a joint vector for the API"), lambda a: check_value(
        a, [math.radians(45), math.radians(-90)], name=N_("your q"), components=("θ0", "θ1"), unit="rad"),
        [N_("The sliders show degrees; robot.fk takes radians: dhlab.deg2rad converts (it also takes a list)."),
         N_("q lists the joints from the base: [θ0, θ1].")])


def _ex_1_2():
    return Exercise("1.2", "glossary", lambda a: check_terms(a, {
        "eslabón": "link", "articulación": "joint", "efector final": ("end effector", "end-effector"),
        "dextrógiro": ("right-handed", "right handed"), "grados de libertad": ("degrees of freedom", "dof"),
    }, name=N_("the glossary")), [N_("The glossary table above has every term.")])


def _ex_1_3():
    return Exercise("1.3", N_("colour of z"), lambda a: check_choice(
        a, "blue", name=N_("the colour of the z axis"), accepted=("azul",),
        explanations={"red": N_("red is the x axis."), "green": N_("green is the y axis."),
                      "rojo": N_("rojo (red) is the x axis."), "verde": N_("verde (green) is the y axis.")}),
        [N_("x, y, z are drawn in the order of the colours of RGB.")])


# The exercises of this notebook, by key: dhlab.course.exercises.exercise(key) makes them.
EXERCISES = {"1.1": _ex_1_1, "1.2": _ex_1_2, "1.3": _ex_1_3}
