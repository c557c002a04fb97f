"""The text the lesson helpers print in the Spanish notebooks is Spanish: each helper a
Spanish notebook prints from (notebooks 03-07, the same calls as their cells) is run under
``set_language("es")`` and its text searched for frequent English words. An English sentence left
in one of them fails here. (Text a notebook's own code cell prints is the edition's concern.)"""
import re

import pytest

import dhlab
from dhlab.i18n import set_language

# frequent English words; a Spanish sentence of the course holds none of them (names in quotes,
# code and maths are left out before looking)
ENGLISH = re.compile(r"\b(the|is|are|of|and|with|from|at|to|not|its|this|which|joint|link|frame|axes|axis|"
                     r"case|same|branch|solutions?|points?)\b")


def english_lines(text) -> list:
    text = str(text)
    return [line for line in text.splitlines()
            if ENGLISH.search(re.sub(r"'[^']*'|\$[^$]*\$|`[^`]*`", " ", line.lower()))]


def _pr():
    from dhlab.course.lessons import lesson_pr_mechanism as P
    pr = dhlab.robots.pr_mechanism()
    return {"ik_report": P.ik_report(pr, [(2.0, 0.25), (2.0, -0.4), (1.2, 0.5), (2.0, 0.6)]),
            "branches_within_limits": P.branches_within_limits(pr, 1.2, 0.25),
            "workspace_report": P.workspace_report(pr)}


def _dh_examples():
    from dhlab.course.lessons import lesson_dh_examples as E
    rppr, arm6, arm3 = dhlab.robots.seed002_4dof(), dhlab.robots.seed002_6dof(), dhlab.robots.seed003_6dof()
    return {"check_cases": E.check_cases(rppr, "002_4dof"), "check_cases 6": E.check_cases(arm6, "002_6dof"),
            "read_rows_at_zero": E.read_rows_at_zero(arm3)}


def _ssrms():
    from dhlab.course.lessons import lesson_ssrms as S
    from dhlab.course.lessons.ssrms_steps import case_name, x_steps
    ssrms = dhlab.robots.ssrms()
    return {"frames_table": S.frames_table(ssrms.frames(ssrms.qz)),
            "x_steps": "\n".join(str(step) for step in x_steps(ssrms)),
            "case_name": "\n".join(case_name(k) for k in (1, 2, 3))}


def _two_dof_and_rules():
    from dhlab.course.lessons import lesson_dh_convention as C
    from dhlab.course.lessons import lesson_two_dof as T
    z_prev, cases = C.three_cases()
    return {"seed004_comparison": T.seed004_comparison(dhlab.robots.robot_no_tan_elemental_1(),
                                                       dhlab.robots.robot_no_tan_elemental_2()),
            "place_x": "\n".join(str(C.place_x(z_prev, z)) for z in cases.values())}


@pytest.mark.parametrize("helpers", [_pr, _dh_examples, _ssrms, _two_dof_and_rules],
                         ids=["notebook 4", "notebook 6", "notebook 7", "notebooks 3 and 5"])
def test_the_lesson_helpers_print_spanish(helpers):
    previous = set_language("es")
    try:
        texts = helpers()
    finally:
        set_language(previous)
    left = {name: english_lines(text) for name, text in texts.items() if english_lines(text)}
    assert not left, left
    english = helpers()                        # the check can fail: the same helpers in English are caught
    assert any(english_lines(text) for text in english.values())


def test_a_step_of_paso_2_in_spanish():
    from dhlab.course.lessons.ssrms_steps import x_steps
    previous = set_language("es")
    try:
        step = str(x_steps(dhlab.robots.ssrms())[2])
    finally:
        set_language(previous)
    assert step == ("x3: caso 2, paralelos, normal común de (0, 6, -3.5) a B3 = (12, 6, -3.5), longitud 12, "
                    "x3 = (1, 0, 0)")
