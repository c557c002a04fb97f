"""Regression tests for the boundary cases the issue-19 sweep left in chain.py and the assignment's Tz/Tx."""
import numpy as np
import pytest

import dhlab
from dhlab.chain import Link, Robot, Rot
from dhlab.assignment import notebook as A
from dhlab.validation import DHLabError

q1, q2, q3 = A.joint_variables(3)


@pytest.mark.parametrize("make, words", [
    (lambda: Link(np.array(0.5)), r"a Link's motions must be a list of motions"),
    (lambda: Link("abc"), r"a Link's motions must be a list of motions"),
    (lambda: Robot([Link([Rot("z", joint=True)])], joint_symbols=["pi"]), r"name of a constant .*π"),
    (lambda: Robot([Link([Rot("z", joint=True)])], joint_symbols=["oo"]), r"name of a constant .*infinity"),
    (lambda: A.Tz("q1", "q2"), r"two joint variables"),
    (lambda: A.Tz(q1, q2), r"two joint variables"),
    (lambda: np.eye(4) - q1, r"is not a valid number"),
    (lambda: np.ma.masked - q1, r"masked"),
], ids=["link-0d", "link-text", "symbol-pi", "symbol-oo", "tz-two-text", "tz-two-terms",
        "array-minus-q", "masked-minus-q"])
def test_refused_where_the_value_enters(make, words):
    with pytest.raises(DHLabError, match=words):
        make()


def test_valid_uses_are_unchanged():
    chain = (A.Tz(q1, 0.5) @ A.Tx(-90, 0)) @ (A.Tz(q2 - 90, 0) @ A.Tx(0, 0.4)) @ (A.Tz(0, q3) @ A.Tx(0, 0))
    assert len(chain) == 3
    assert Robot([Link([Rot("z", joint=True)])], joint_symbols=["theta1"]).q_symbols[0].name == "theta1"
    assert repr(A.Tz(q1 + 400, 0)) == "Tz[q1 + 400, 0]"      # the grader reads any offset (same rotation)
    # a chain that moves one q_i in two links is a slip the grader scores (one item), not refused here
    assert len((A.Tz(q1, 0) @ A.Tx(0, 1)) @ (A.Tz(q1 + 90, 0) @ A.Tx(0, 1))) == 2
