"""dhlab.course.predict: predict-then-check never shows the answer before an attempt, and says right/wrong
from the geometry (not from a key typed here)."""
import pytest

import dhlab
import dhlab.course.exercises
from dhlab.course.lessons.dh_first_robot import DRAWN_Q, FIRST_ROBOT_ROWS, first_robot
from dhlab.course.predict import (
    Prediction,
    case_prediction,
    check_row_prediction,
    entry_prediction,
    point_prediction,
    reveal,
    row_prediction,
    step_prediction,
)
from dhlab.errors import DHLabError
from dhlab.mdh import to_modified


@pytest.fixture(scope="module")
def scara():
    return first_robot()


def test_placeholder_prompts_and_never_shows_the_answer(scara):
    p = row_prediction(scara, 2, DRAWN_Q)
    fb = p.check(...)
    assert fb.status == "unanswered" and "worked answer:" not in str(fb) and "l3" not in str(fb)
    assert not p.done
    assert p.check(..., show_me=True).tip.startswith("worked answer") and p.done


@pytest.mark.parametrize("i", [1, 2, 3, 4])
def test_the_tables_own_rows_are_right_and_reveal_the_answer(scara, i):
    fb = check_row_prediction(scara, i, FIRST_ROBOT_ROWS[i - 1], q=DRAWN_Q)
    assert fb.ok, str(fb)
    assert "worked answer" in fb.tip


def test_a_wrong_row_is_wrong_with_the_parameter_named_and_no_answer(scara):
    p = row_prediction(scara, 2, DRAWN_Q)
    fb = p.check(("q2", 0, "l3", 0))                        # the twist forgotten
    assert fb.status == "wrong" and "α" in str(fb) and "worked answer:" not in str(fb)
    assert not p.done
    fb = p.check(("q2", 0, "l3", 0), show_me=True)          # explicit "show me" after the try
    assert fb.status == "wrong" and "worked answer" in fb.tip and p.done


def test_joint_variable_in_the_wrong_column_or_unknown_name(scara):
    assert "belongs in d" in str(check_row_prediction(scara, 3, ("d3", 0, 0, 0), q=DRAWN_Q))
    assert "not a name" in str(check_row_prediction(scara, 2, ("q2", 0, "l9", 180), q=DRAWN_Q))
    assert check_row_prediction(scara, 1, "q1", q=DRAWN_Q).status == "wrong"


SLIDE_RPPR = [("q1", "l1", 0, 0), (90, "d2", 0, 90), (0, "d3", 0, 0), ("q4", "l4", 0, 0)]     # seed 002's slide
ARM_4AXIS = [("q1", 0.5, 0.2, -90), ("q2 - 90", 0, 0.5, 0), ("q3", 0, 0, -90), ("q4", 0.5, 0, 0)]


@pytest.mark.parametrize("robot, rows, q", [
    (dhlab.robots.seed002_4dof(), SLIDE_RPPR, [0.4, 0.3, 0.7, -1.2]),
    (dhlab.course.exercises.four_axis_arm(), ARM_4AXIS, [0.3, -0.5, 1.1, 2.0]),
])
def test_typed_rows_right_at_any_pose_and_a_changed_entry_wrong(robot, rows, q):
    """Rows typed as on the slides (offsets, names) pass against the frames drawn at q (joint angles read
    in degrees inside the row); changing any one entry of any row is caught."""
    for i, row in enumerate(rows, start=1):
        p = row_prediction(robot, i, q)
        assert p.check(row).ok, (i, str(p.check(row)))
        for k in range(4):
            changed = list(row)
            changed[k] = f"({changed[k]}) + 0.25" if k in (1, 2) else f"({changed[k]}) + 30"
            assert p.check(tuple(changed)).status == "wrong", (i, k)


def test_case_prediction_reads_english_and_spanish():
    z0 = ((0, 0, 0), (0, 0, 1))
    skew = case_prediction(z0, ((1, 0, 0), (0, 1, 0)), i=1)
    assert skew.check("se cruzan").ok and skew.check(3).ok
    assert skew.check("parallel").status == "wrong" and "worked" not in str(skew.check("parallel"))
    assert case_prediction(z0, ((1, 0, 0), (0, 0, -1))).check("parallel").ok     # opposite senses: parallel


def test_step_prediction_follows_the_four_motions(scara):
    p = step_prediction(scara, 1, 3)
    A1 = scara.A(1, 0.0)
    assert p.check(A1[:3, 3]).ok                                 # θ1 = 0, α1 = 0: after step 3 it is O1
    fb = p.check((0, 0, A1[2, 3]))                             # where step 2 leaves it
    assert fb.status == "wrong" and "step 2" in str(fb)
    with pytest.raises(DHLabError):
        step_prediction(scara, 1, 5)


def test_entry_prediction_is_symbolic():
    rppr = dhlab.robots.seed002_4dof()
    truth = rppr.link_matrices_sym()[1][0, 2]
    p = entry_prediction(rppr, 2, 0, 2)
    assert p.check(truth).ok and p.check(str(truth)).ok
    assert p.check(truth + 1).status == "wrong"
    assert p.check("not an expression ((").status == "wrong"


def test_point_prediction_and_reveal():
    p = point_prediction("a point", (1, 2, 3), "because")
    shown = []
    assert reveal(p, lambda: shown.append(1)).status == "unanswered" and not shown
    assert p.check((1, 2, 3.5)).status == "wrong" and "z" in str(p.check((1, 2, 3.5)))
    assert p.check([1, 2, 3]).ok
    reveal([p], lambda: shown.append(1))
    assert shown == [1]


def test_bad_input_is_a_clear_error(scara):
    for call in (lambda: row_prediction(scara, 0), lambda: row_prediction("robot", 1),
                 lambda: row_prediction(to_modified(scara), 1), lambda: row_prediction(scara, 1, q=[1, 2]),
                 lambda: Prediction("q", 1, 2), lambda: reveal([], print), lambda: reveal("p", print),
                 lambda: case_prediction("a", "b"),
                 lambda: case_prediction(((0, 0, 0), (0, 0, 0)), ((1, 0, 0), (0, 1, 0))),
                 lambda: point_prediction("p", (1, 2), "why"),
                 lambda: Prediction("q", print, print).check(1, show_me=1)):
        with pytest.raises(DHLabError):
            call()
