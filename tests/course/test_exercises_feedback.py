"""Feedback that never misleads: rounding is never blamed, each typical wrong form of an answer
gets its own message, no message gives the answer away, and no answer makes a check raise."""
import doctest
import importlib
import math

import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from dhlab import deg2rad
from dhlab.course.exercises import available, check_matrix, check_solutions, check_value, exercise
from dhlab.transforms import Rz, trans

T22 = Rz(math.radians(30)) @ trans(2, 0, 0)             # the answer of exercise 2.2


def feedback_of(key, answer):
    fb = exercise(key).check(answer)
    assert fb.status in ("correct", "wrong", "unanswered"), (key, answer)
    return str(fb)


# --- rounding is never blamed ----------------------------------------------------------------------------------
def test_2_2_rounded_to_two_decimals_is_accepted_with_a_note():
    fb = exercise("2.2").check(np.round(T22, 2))
    assert fb.ok, str(fb)
    assert "right to the 2 decimals you typed" in str(fb) and "not a rotation" not in str(fb)
    assert exercise("2.2").check(np.round(T22, 2).tolist()).ok          # as typed, in lists
    assert exercise("2.2").check(sp.Matrix(np.round(T22, 2))).ok        # as a sympy Matrix of Floats


def test_3_decimals_needs_no_note_and_1_decimal_asks_for_more_without_blame():
    assert exercise("2.2").check(np.round(T22, 3)).items == []
    fb = exercise("2.2").check(np.round(T22, 1))
    assert fb.status == "wrong" and "give 3 decimals" in str(fb)
    assert "not a rotation" not in str(fb) and "not right" not in " ".join(fb.items)


def test_a_transposed_rotation_rounded_is_told_only_that():
    wrong = T22.copy()
    wrong[:3, :3] = wrong[:3, :3].T
    for decimals in (2, 3):
        fb = exercise("2.2").check(np.round(wrong, decimals))
        assert "transpose of the right one" in str(fb), (decimals, str(fb))
        assert "not a rotation" not in str(fb), (decimals, str(fb))


def test_not_a_rotation_beyond_rounding_is_still_said():
    wrong = np.round(T22, 2)
    wrong[0, 0] = 0.5                                       # a real mistake, not rounding
    assert "not a rotation" in feedback_of("2.2", wrong)


def test_vectors_rounded_pass_and_a_cut_off_digit_is_named_gently():
    right = [-0.35 * 0 + 0.3 * math.cos(math.radians(75)) - 0.7 * math.sin(math.radians(30)),
             0.3 * math.sin(math.radians(75)) + 0.7 * math.cos(math.radians(30)), 0]
    assert exercise("3.3").check(np.round(right, 2)).ok
    assert exercise("4.2").check([[round(0.4, 2), 0.64], [1.2, 2.5]]).ok
    fb = check_value(0.86, math.sqrt(3) / 2)
    assert "check the last digit" in str(fb) and "0.866" not in str(fb)


# --- the specific messages of each exercise ---------------------------------------------------------------------------
def test_2_4_answered_as_rz_times_translation():
    fb = feedback_of("2.4", lambda dtheta, d: Rz(dtheta) @ trans(*d))
    assert "Rz(θ)·Tr(d)" in fb and "turned too" in fb


def test_3_3_with_link_1_along_x():
    t0, t1 = math.radians(30), math.radians(45)
    answer = [0.7 * math.cos(t0) + 0.3 * math.cos(t0 + t1), 0.7 * math.sin(t0) + 0.3 * math.sin(t0 + t1), 0]
    assert "link 1 along x0" in feedback_of("3.3", answer)


def test_4_1_with_sin_30_for_y():
    answer = [0.5 + 1 + 0.5 * math.cos(math.radians(60)), 0.5 * math.sin(math.radians(30))]
    assert "sin 30°" in feedback_of("4.1", answer)


def test_4_3_explains_every_kind_of_count_without_giving_it():
    fb = feedback_of("4.3", [2, 1, 1])
    assert "|y| = l2" in fb and "branches meet" in fb            # (1.5, −0.5)
    assert "|y| = 0.7 > l2" in fb                                 # (1.5, 0.7)
    assert "|y| = 0.1 < l2" in fb                                 # (2.5, 0.1)
    for count in ("it is 1", "it is 0", "it is 2", "one solution", "no solution", "two solutions"):
        assert count not in fb


@pytest.mark.parametrize("key, answer, message", [
    ("3.3", [0.2, 0.7, 0, 1], "your answer has 4 numbers; a position has 3: drop the trailing 1"),
    ("4.4", sp.Matrix([1, 2, 3, 1]), "drop the trailing 1 of the homogeneous form"),
    ("4.1", [1.75, 0.43, 0], "the mechanism is planar: give (x, y), without z"),
    ("4.1", [1.75, 0.43, 0, 1], "drop the trailing 1"),
    ("3.3", np.eye(4), "a whole pose: the position is its last column"),
])
def test_homogeneous_and_planar_forms(key, answer, message):
    assert message in feedback_of(key, answer)


@pytest.mark.parametrize("colour", ["azul", "Azul", "blue", "the Blue"])
def test_1_3_accepts_spanish(colour):
    assert exercise("1.3").check(colour).ok
    assert "y axis" in feedback_of("1.3", "verde")


def test_reader_exercise_predict_then_check():
    assert exercise("3.5").check([1.0, 0.0, 0.0]).ok
    assert "counter-clockwise" in feedback_of("3.5", [-1.0, 0.0, 0.0])
    assert "d = 0" in feedback_of("3.5", [0.7, 0.0, 0.0])
    assert exercise("3.5").check(...).status == "unanswered"


def test_no_feedback_gives_the_answer_away():
    """A wrong answer's feedback never prints the right numbers of a numeric exercise."""
    answers = {"3.3": ([0.1, 0.2, 0.3], ["0.428", "0.895"]), "3.4": ([0.1, 0.1], ["0.785", "0.148"]),
               "4.1": ([1.0, 0.2], ["1.75", "0.433"]), "4.4": ([1.0, 1.0, 1.0], ["2.5", "1.6", "3.0"]),
               "4.2": ([[0.1, 0.2]], ["0.4", "0.643", "1.2", "2.498"]), "3.5": ([0.5, 0.5, 0.5], ["1.0"])}
    for key, (answer, secrets) in answers.items():
        fb = feedback_of(key, answer)
        assert not any(s in fb for s in secrets), (key, fb)


# --- hostile answers: feedback, never an exception ------------------------------------------------------------------
class Weird:
    def __float__(self):
        raise RuntimeError("no")


f = sp.Function("f")
x = sp.Symbol("theta")
HOSTILE = [np.nan, np.inf, -np.inf, 1j, [np.arcsin(2.0), 0], [np.nan, 0, 0], [np.inf, 1, 2], [1j, 0, 0],
           [sp.zoo, 0, 0], [sp.nan, 1, 2], [sp.oo, 1], [None, 1, 2], [True, 1, 2], [False, 0], True,
           10 ** 400, [10 ** 400, 1, 2], -(10 ** 30), "abc", "", "1.5", {"a": 1}, {1, 2}, [[1, 2], [3]],
           [[[1]]], [], (), np.array([]), np.zeros((2, 3, 4)), object(), Weird(), [Weird(), 1, 2],
           sp.Matrix([[f(x), 0], [0, 1]]), sp.Integral(x, x), [sp.Integral(x, x), 0, 0], sp.Derivative(f(x), x),
           np.array([[np.nan] * 4] * 4), np.eye(4) / 0.0 if False else np.full((4, 4), np.inf),
           sp.eye(4) / sp.cos(sp.pi / 2), sp.Matrix([[sp.zoo] * 4] * 4), sp.Matrix(4, 4, [x] * 16),
           np.array(["a"] * 16).reshape(4, 4), [[None] * 4] * 4, [[True] * 4] * 4, lambda *a: 1 / 0,
           lambda *a: "text", lambda *a: None, lambda *a: np.full((4, 4), np.nan), print, sp.S.ComplexInfinity,
           sp.Symbol("q") ** 10 ** 5, [deg2rad(30), "30°"], np.datetime64("2024-01-01"), slice(1, 2), Ellipsis]


@pytest.mark.filterwarnings("ignore")
@pytest.mark.parametrize("key", available())
def test_hostile_answers_get_feedback(key):
    for answer in HOSTILE:
        fb = exercise(key).check(answer)
        assert fb.status in ("wrong", "unanswered"), (key, answer, str(fb))
        assert "could not be compared" not in str(fb) or callable(answer) or key in ("2.4",), (key, answer, str(fb))


def test_known_hostile_answers_get_feedback():
    assert "not a finite number" in str(exercise("1.1").check([np.arcsin(2.0), 0]))
    assert "infinite or undefined" in str(exercise("2.2").check(sp.Matrix(T22) / sp.cos(sp.pi / 2)))
    assert "a function sympy does not know" in str(exercise("2.1").check(sp.Matrix(4, 4, [f(x)] * 16)))
    assert "unevaluated Integral" in str(exercise("2.1").check(sp.Matrix(4, 4, [sp.Integral(x, x)] * 16)))
    assert "None is not a number" in str(exercise("3.3").check([None, 1, 2]))
    assert "True is not a number" in str(exercise("3.3").check([True, 1, 2]))
    assert "far too large" in str(exercise("3.3").check([10 ** 400, 1, 2]))


# --- property: random answers in, feedback out ------------------------------------------------------------------
numbers = st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.integers(), st.complex_numbers(),
                    st.booleans(), st.none(), st.text(max_size=5),
                    st.sampled_from([sp.zoo, sp.nan, sp.oo, sp.pi, sp.Symbol("theta"), sp.Symbol("l1"),
                                     sp.Symbol("θ0"), sp.cos(sp.Symbol("theta0")), sp.Integral(x, x), f(x)]))
vectors = st.lists(numbers, max_size=5)
matrices = st.integers(1, 5).flatmap(lambda n: st.lists(st.lists(numbers, min_size=n, max_size=n),
                                                        min_size=1, max_size=5))
answers = st.one_of(numbers, vectors, matrices, st.lists(vectors, max_size=3),
                    st.dictionaries(st.text(max_size=12), numbers, max_size=5),
                    matrices.map(lambda m: np.array(m, dtype=object)))


@pytest.mark.filterwarnings("ignore")
@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(key=st.sampled_from(available()), answer=answers)
def test_random_answers_get_feedback_never_an_exception(key, answer):
    fb = exercise(key).check(answer)
    assert fb.status in ("correct", "wrong", "unanswered")
    assert str(fb) and fb._repr_html_()


@pytest.mark.filterwarnings("ignore")
@settings(max_examples=100, deadline=None)
@given(answer=answers)
def test_the_generic_checks_never_raise(answer):
    for fb in (check_matrix(answer, Rz(x)), check_matrix(answer, np.eye(3)),
               check_value(answer, [1.0, 2.0], unit=("rad", "m")), check_value(answer, 0.5),
               check_solutions(answer, [[0.4, 0.64], [1.2, 2.5]], unit=("", "rad"))):
        assert fb.status in ("correct", "wrong", "unanswered")


# --- the worked examples in the docstrings of the checks' modules ----------------------------------------------------
@pytest.mark.parametrize("name", ["checks.feedback", "checks.reading", "checks.matrix", "checks.values", "checks.words",
                                  "exercises"])
def test_docstring_examples_of_the_checks(name):
    module = importlib.import_module(f"dhlab.course.{name}")
    result = doctest.testmod(module, optionflags=doctest.NORMALIZE_WHITESPACE | doctest.ELLIPSIS)
    assert result.attempted > 0 and result.failed == 0, f"{result.failed} docstring example(s) failed in {name}"
