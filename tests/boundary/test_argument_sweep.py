"""Which values get in: every public entry point of the maths, the robot catalogue, modified DH, the
exercise checks (the student's answer *and* the teacher's arguments) and the assignment's inputs,
called with hostile values one argument at a time (the others good), a fixed list.

Each call must end in a result or a :class:`dhlab.DHLabError`: no other exception, no numpy or sympy
warning, no hang (20 s). A student's answer to an exercise must always come back as feedback (never an
exception, never "correct" for junk). ``MUST_REFUSE`` lists the nonsense this sweep found accepted (a
negative link length, a deg2rad() value as a length, a set as an ordered pair, a masked value read as 0,
a robot without DH frames in a DH check …): each must now be a DHLabError.

Unlike test_public_api_sweep.py (which checks each result's value too), this sweep is about
*which values get in*: it adds the teacher's arguments of the checks, modified DH, the catalogue's
lengths, and values that sweep does not try (Decimal('sNaN'), np.longdouble, bytearray, generators,
sympy booleans and relations, str subclasses, 0-d object arrays).
"""
from __future__ import annotations

import datetime
import inspect
import signal
import warnings
from decimal import Decimal
from fractions import Fraction

import matplotlib
import numpy as np
import pytest
import sympy as sp

matplotlib.use("Agg")

import dhlab
from dhlab import DHLabError, DHRobot, MDHRobot, RevoluteDH, RevoluteMDH, robots, symbolic, transforms
from dhlab.assignment import inputs as AI
from dhlab.assignment import notebook as AS
from dhlab.course import exercises as E
from dhlab.course import exercises_dh as D
from dhlab.mdh import PrismaticMDH, mdh_matrix, to_modified, to_modified_rows, to_standard, to_standard_rows

X = sp.Symbol("x")


def _gen():
    return (i for i in range(3))


HOSTILE = [
    ("nan", float("nan")), ("inf", float("inf")), ("-inf", -float("inf")), ("1e308", 1e308), ("-1e308", -1e308),
    ("-0.0", -0.0), ("1j", 1j), ("True", True), ("None", None), ("'abc'", "abc"), ("''", ""), ("'90'", "90"),
    ("long text", "q" * 5000), ("b'x'", b"x"), ("bytearray", bytearray(b"1")), ("[]", []), ("[1, 2]", [1, 2]),
    ("ragged", [[1], [2, 3]]), ("[[[1]]]", [[[1]]]), ("0-d array", np.array(0.5)), ("0-d nan", np.array(np.nan)),
    ("object array", np.array([1, None], dtype=object)), ("0-d object None", np.array(None, dtype=object)),
    ("symbol", X), ("zoo", sp.zoo), ("oo", sp.oo), ("sp.nan", sp.nan), ("I", sp.I), ("exp(I)", sp.exp(sp.I)),
    ("Decimal", Decimal("0.5")), ("Decimal sNaN", Decimal("sNaN")), ("Decimal inf", Decimal("Infinity")),
    ("Fraction", Fraction(1, 3)), ("{}", {}), ("{1: 2}", {1: 2}), ("set", {1, 2}), ("generator", "GENERATOR"),
    ("-5", -5), ("90", 90), ("10**400", 10**400), ("np.longdouble 1e400", np.longdouble("1e400")),
    ("uint64 max", np.uint64(2**64 - 1)), ("deg2rad(30)", dhlab.deg2rad(30)), ("masked", np.ma.masked),
    ("date", datetime.date(2020, 1, 1)), ("object()", object()), ("Ellipsis", ...), ("sp.true", sp.true),
    ("Eq(x, 1)", sp.Eq(X, 1)), ("np.eye(4)", np.eye(4)), ("4x4 of NaN objects", np.full((4, 4), np.nan, dtype=object)),
    ("str subclass", type("Text", (str,), {})("q1")), ("np.str_", np.str_("1")), ("range", range(3)),
]


def hostile():
    """Fresh hostile values (a generator is used up by one call)."""
    return [(label, _gen() if label == "generator" else value) for label, value in HOSTILE]


class _Timeout(Exception):
    pass


def _alarm(*_):
    raise _Timeout()


def outcome(fn) -> str:
    """'result' or 'refused' (a DHLabError); anything else is a failure, described."""
    previous = signal.signal(signal.SIGALRM, _alarm)
    signal.alarm(20)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            fn()
        return "result"
    except DHLabError:
        return "refused"
    except _Timeout:
        return "HANG (over 20 s)"
    except Exception as exc:                       # the failure this sweep exists to find
        return f"RAW {type(exc).__name__}: {str(exc)[:120]}"
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, previous)


# ------------------------------------------------------------------------------------------------
# The entry points: (name, good arguments, function)
# ------------------------------------------------------------------------------------------------
def _arm():
    return D.four_axis_arm()


Q1, Q2 = sp.symbols("q1 q2")
TH = sp.Symbol("theta")
ROT2 = sp.Matrix([[sp.cos(TH), -sp.sin(TH)], [sp.sin(TH), sp.cos(TH)]])


def maths_entries():
    pr = robots.pr_mechanism()
    return [
        ("mdh_matrix", {"theta": 0.3, "d": 1, "a": 1, "alpha": 0.2}, mdh_matrix),
        ("dh_matrix", {"theta": 0.3, "d": 1, "a": 1, "alpha": 0.2}, dhlab.dh_matrix),
        ("Tz", {"theta": 0.3, "z": 1}, dhlab.Tz),
        ("Tx", {"alpha": 0.3, "x": 1}, dhlab.Tx),
        ("inv", {"T": np.eye(4)}, dhlab.inv),
        ("rpy", {"T": np.eye(4)}, dhlab.rpy),
        ("position", {"T": np.eye(4)}, transforms.position),
        ("deg", {"x": 1}, dhlab.deg2rad),
        ("rad", {"x": 1}, dhlab.rad2deg),
        ("compact", {"M": dhlab.Rz(Q1) * dhlab.Rz(Q2), "q": (Q1, Q2)}, lambda M, q: dhlab.compact(M, q)),
        ("legend", {"M": dhlab.Rz(Q1) * dhlab.Rz(Q2), "q": (Q1, Q2)}, lambda M, q: dhlab.legend(M, q)),
        ("exact", {"x": 0.5}, symbolic.exact_angle),
        ("pr_mechanism_ik", {"r": pr, "x": 1.2, "y": 0.3, "tol": 1e-12}, dhlab.ik.pr_mechanism_ik),
        ("RevoluteDH", {"d": 0, "a": 1, "alpha": 0, "offset": 0, "qlim": None, "name": ""}, RevoluteDH),
        ("RevoluteMDH", {"d": 0, "a": 1, "alpha": 0, "offset": 0, "qlim": None, "name": ""}, RevoluteMDH),
        ("PrismaticMDH", {"theta": 0, "a": 1, "alpha": 0, "offset": 0, "qlim": None, "name": ""}, PrismaticMDH),
        ("DHRobot", {"links": [RevoluteDH(a=1)], "name": "r", "base": None, "tool": None, "params": None,
                     "joint_symbols": None, "unit": ""}, DHRobot),
        ("MDHRobot", {"links": [RevoluteMDH(a=1)], "name": "r", "base": None, "tool": None, "params": None,
                      "joint_symbols": None, "unit": ""}, MDHRobot),
        ("DHRobot.from_table", {"rows": [("q1", 0, 1, 0)], "name": "t", "params": None, "angles": "deg",
                                "qlim": None}, DHRobot.from_table),
        ("MDHRobot.from_table", {"rows": [("q1", 0, 1, 0)], "name": "t", "params": None, "angles": "deg",
                                 "qlim": None}, MDHRobot.from_table),
        ("from_table θ", {"v": "q1"}, lambda v: DHRobot.from_table([(v, 0, 1, 0)])),
        ("from_table d", {"v": 0}, lambda v: DHRobot.from_table([("q1", v, 1, 0)])),
        ("from_table a", {"v": 1}, lambda v: DHRobot.from_table([("q1", 0, v, 0)])),
        ("from_table α", {"v": 0}, lambda v: DHRobot.from_table([("q1", 0, 1, v)])),
        ("from_table params", {"v": 1}, lambda v: DHRobot.from_table([("q1", "l1", 1, 0)], params={"l1": v})),
        ("from_table qlim", {"v": (-90, 90)}, lambda v: DHRobot.from_table([("q1", 0, 1, 0)], qlim=[v])),
        ("to_modified_rows", {"rows": [("q1", 0, 1, 0)]}, to_modified_rows),
        ("to_standard_rows", {"rows": [("q1", 0, 1, 0)]}, to_standard_rows),
        ("to_modified", {"robot": robots.puma560()}, to_modified),
        ("to_standard", {"robot": to_modified(robots.puma560())}, to_standard),
    ]


def catalogue_entries():
    out = []
    for name, factory in robots.catalogue().items():
        good = {k: p.default for k, p in inspect.signature(factory).parameters.items()}
        if good:
            out.append((f"robots.{name}", good, factory))
    modified = to_modified(robots.seed002_4dof())
    out += [("MDHRobot.fk", {"q": modified.qz}, modified.fk), ("MDHRobot.A", {"i": 2, "q": 0.1}, modified.A),
            ("MDHRobot.table", {"robot": modified}, dhlab.DHTable)]
    return out


def check_entries():
    """The teacher's arguments of the checks (the student's answer is a slot too)."""
    return [
        ("check_matrix", {"student": ROT2, "expected": ROT2, "name": "R", "symbols": (), "tol": 1e-3,
                          "mistakes": (), "index_style": "python"},
         lambda student, expected, **kw: E.check_matrix(student, expected, **kw)),
        ("check_value", {"student": [1.0, 2], "expected": [1.0, 2], "name": "p", "components": ("x", "y"),
                         "unit": ("m", "m"), "tol": 1e-3, "mistakes": ()},
         lambda student, expected, **kw: E.check_value(student, expected, **kw)),
        ("check_solutions", {"student": [[1.0, 2]], "expected": [[1.0, 2]], "components": None, "unit": "",
                             "tol": 1e-3, "mistakes": ()},
         lambda student, expected, **kw: E.check_solutions(student, expected, **kw)),
        ("check_choice", {"student": "a", "correct": "a", "accepted": (), "explanations": None, "name": "w"},
         lambda student, correct, **kw: E.check_choice(student, correct, **kw)),
        ("check_terms", {"student": {"a": "b"}, "expected": {"a": "b"}, "name": "g"},
         lambda student, expected, **kw: E.check_terms(student, expected, **kw)),
        ("check_function", {"fn": lambda t: np.eye(4), "reference": lambda t: np.eye(4), "cases": [(0.1,)]},
         lambda fn, reference, cases: E.check_function(fn, reference, cases)),
        ("seed001_DefinirTHz", {"dtheta": 0.1, "d": (1, 2, 3)}, E.seed001_DefinirTHz),
        ("exercise", {"key": "1.1"}, E.exercise),
        ("exercises_dh.exercise", {"key": "5.1"}, D.exercise),
        ("check_x_cases", {"answer": {1: "skew"}, "robot": None}, D.check_x_cases),
        ("check_dh_row", {"answer": (1, 2, 3, 4), "frames": None}, D.check_dh_row),
        ("check_table", {"rows": [("q1", 0, 1, 0)], "exercise": "arm", "params": None, "different": False},
         D.check_table),
        ("compare_robots", {"student": _arm(), "reference": _arm(), "samples": 5, "seed": 0}, D.compare_robots),
        ("check_link_matrix", {"M": np.eye(4), "i": 2, "robot": None}, D.check_link_matrix),
        ("check_wrist_centre", {"p": (1, 2, 3), "q_deg": D.WRIST_Q_DEG, "robot": None}, D.check_wrist_centre),
        ("thlist_slot", {"joint": 1, "robot": None}, D.thlist_slot),
        ("check_thlist_slots", {"slots": {1: 2}, "robot": None}, D.check_thlist_slots),
        ("parallel_pairs", {"robot": None, "samples": 5, "seed": 0}, D.parallel_pairs),
        ("check_parallel_pairs", {"pairs": {(3, 4)}, "robot": None}, D.check_parallel_pairs),
        ("printed_key_position", {"joints": (2, 5), "robot": None}, D.printed_key_position),
        ("check_key_jump", {"position": (1, 2, 3), "joints": (2, 5), "robot": None}, D.check_key_jump),
        ("axis_relation", {"p1": (0, 0, 0), "u1": (0, 0, 1), "p2": (1, 0, 0), "u2": (0, 1, 0), "tol": 1e-9},
         D.axis_relation),
        ("show_axes", {"axes": [((0, 0, 0), (0, 0, 1), "R")], "tool": None, "ax": None, "length": 0.3,
                       "title": ""}, D.show_axes),
    ]


def assignment_entries():
    q = AS.joint_variables(3)
    chain = AS.Tz(q[0], 0.5) @ AS.Tx(90, 0.2) @ (AS.Tz(q[1], 0) @ AS.Tx(0, 1))
    return [
        ("AI.degrees", {"v": 90, "what": "θ"}, lambda v, what: AI.degrees(v, what)),
        ("AI.length", {"v": 1, "what": "d"}, lambda v, what: AI.length(v, what)),
        ("AI.joint_number", {"v": 1}, lambda v: AI.joint_number(v)),
        ("AI.sign", {"v": 1}, lambda v: AI.sign(v)),
        ("AI.unit_factor", {"v": 1}, lambda v: AI.unit_factor(v)),
        ("AI.joint_count", {"v": 3}, lambda v: AI.joint_count(v)),
        ("AI.part_number", {"v": 1}, lambda v: AI.part_number(v)),
        ("AI.term_parts", {"v": "q2 + 90", "what": "θ"}, lambda v, what: AI.term_parts(v, what)),
        ("AI.joint_value", {"q": 0.1, "where": "theta"}, AI.joint_value),
        ("Tz", {"theta": 90, "d": 0.5}, AS.Tz),
        ("Tx", {"alpha": 90, "a": 0.5}, AS.Tx),
        ("Tz[q, d]", {"d": 0.5}, lambda d: AS.Tz(q[0], d)),
        ("q1 + c", {"c": 90}, lambda c: q[0] + c),
        ("q1 - c", {"c": 90}, lambda c: c - q[0]),
        ("chain.matrix", {"q": [0.1, 0.2]}, chain.matrix),
        ("chain.frames", {"q": [0.1, 0.2]}, chain.frames),
        ("check_part", {"part": 1, "namespace": {}}, AS.check_part),
    ]


GROUPS = {"maths": maths_entries, "catalogue": catalogue_entries, "checks": check_entries,
          "assignment": assignment_entries}

# Failures of this sweep whose fix belongs to another module, each with the file and the fix:
# (entry, slot, labels — None for every label —, where, the fix)
KNOWN_RULES = [
    ("q1 - c", "c", ("masked", "sp.true"), "dhlab/assignment/notebook.py",
     "JointTerm: `__array_ufunc__ = None`, so numpy defers to JointTerm.__rsub__ (sympy's BooleanAtom "
     "raises in its own __sub__: nothing to do on our side)."),
]


def _known(entry, slot, label) -> bool:
    return any(entry == e and slot == s and (labels is None or label in labels) for e, s, labels, _, _ in KNOWN_RULES)


def _by_keyword(fn, good: dict) -> bool:
    """Whether ``fn`` takes the good arguments by their names (else they are passed in order)."""
    try:
        inspect.signature(fn).bind(**good)
        return True
    except (TypeError, ValueError):
        return False


def sweep(group: str) -> list:
    bad = []
    for entry, good, fn in GROUPS[group]():
        keywords = _by_keyword(fn, good)
        assert keywords or len(inspect.signature(fn).parameters) >= len(good), f"the sweep's call of {entry}"
        for slot in good:
            for label, value in hostile():
                args = dict(good, **{slot: value})
                result = outcome(lambda: fn(**args) if keywords else fn(*args.values()))
                if result not in ("result", "refused") and not _known(entry, slot, label):
                    bad.append(f"{entry}({slot}={label}): {result}")
    return bad


@pytest.mark.parametrize("group", sorted(GROUPS))
def test_hostile_values_get_a_result_or_a_clear_error(group):
    bad = sweep(group)
    assert not bad, f"{len(bad)} call(s) failed:\n" + "\n".join(bad)


@pytest.mark.parametrize("module", [E], ids=["notebooks 1-7"])      # one registry (D forwards to it)
def test_every_exercise_answers_junk_with_feedback(module):
    bad = []
    for key in module.available():
        for label, value in hostile():
            try:
                with warnings.catch_warnings():
                    warnings.simplefilter("error")
                    feedback = module.exercise(key).check(value)
            except Exception as exc:               # a check never raises on a student's answer
                bad.append(f"{key}({label}): {type(exc).__name__}: {str(exc)[:100]}")
                continue
            if feedback.status == "correct" and label not in ("Ellipsis", "None"):
                bad.append(f"{key}({label}): junk judged correct")
    assert not bad, "\n".join(bad)


# ------------------------------------------------------------------------------------------------
# The nonsense this sweep found accepted: each is now refused with a DHLabError naming the value
# ------------------------------------------------------------------------------------------------
MUST_REFUSE = [
    # the catalogue: a link length is not negative (the table writes '-l2' where it needs the sign)
    ("robots.prr_example(l1=-5)", lambda: robots.prr_example(l1=-5), "l1"),
    ("robots.pr_mechanism(l2=-0.5)", lambda: robots.pr_mechanism(l2=-0.5), "l2"),
    ("robots.seed002_6dof(l2=-2)", lambda: robots.seed002_6dof(l2=-2), "l2"),
    ("robots.robot_no_tan_elemental_1(l1=-1)", lambda: robots.robot_no_tan_elemental_1(l1=-1), "l1"),
    ("robots.rrr_example_matrices(l3=-1)", lambda: robots.rrr_example_matrices(l3=-1), "l3"),
    # from_table: a deg2rad() angle as a length; a set (no order) or a 0-d array as the pair of limits
    ("from_table d = deg2rad(30)", lambda: DHRobot.from_table([("q1", dhlab.deg2rad(30), 1, 0)]), "length"),
    ("from_table a = deg2rad(30)", lambda: DHRobot.from_table([("q1", 0, dhlab.deg2rad(30), 0)]), "length"),
    ("from_table qlim = [{-90, 90}]", lambda: DHRobot.from_table([("q1", 0, 1, 0)], qlim=[{-90, 90}]), "set"),
    ("from_table qlim = 0-d array", lambda: DHRobot.from_table([("q1", 0, 1, 0)], qlim=np.array(5.0)), "qlim"),
    ("from_table rows = a set", lambda: DHRobot.from_table({("q1", 0, 1, 0), ("q2", 0, 1, 0)}), "set"),
    # modified DH: rows with no joint variable, or NaN, are no table
    ("to_modified_rows(np.eye(4))", lambda: to_modified_rows(np.eye(4)), "joint variable"),
    ("to_standard_rows(NaN)", lambda: to_standard_rows([("q1", float("nan"), 0, 0)]), "row 1"),
    # units: more than 100 turns is no angle
    ("deg2rad(1e308)", lambda: dhlab.deg2rad(1e308), "turns"),
    ("rad2deg(np.uint64 max)", lambda: dhlab.rad2deg(np.uint64(2**64 - 1)), "turns"),
    # symbolic display: a complex, masked or empty M
    ("compact(1j)", lambda: dhlab.compact(1j, ["q1"]), "complex"),
    ("compact(I*q1)", lambda: dhlab.compact(sp.Matrix([[sp.I * Q1]]), ["q1"]), "real"),
    ("compact(masked)", lambda: dhlab.compact(np.ma.masked, ["q1"]), "M"),
    ("legend([])", lambda: dhlab.legend([], ["q1"]), "empty"),
    # the DH checks: a robot without DH frames, a wrist that is not spherical, no key pressed
    ("check_x_cases(robot by motions)", lambda: D.check_x_cases({1: "skew"}, robots.rrr_example_matrices()), "DH"),
    ("parallel_pairs(robot by motions)", lambda: D.parallel_pairs(robots.prr_example_matrices()), "DH"),
    ("check_x_cases(MDH robot)", lambda: D.check_x_cases({1: "skew"}, to_modified(_arm())), "to_standard"),
    ("check_wrist_centre(SSRMS)", lambda: D.check_wrist_centre((1, 2, 3), robot=robots.ssrms()), "6-DOF"),
    ("check_wrist_centre(no spherical wrist)",
     lambda: D.check_wrist_centre((1, 2, 3), robot=DHRobot([RevoluteDH(a=0.3, d=0.1, alpha=0.4)] * 6)),
     "spherical wrist"),
    ("check_key_jump(joints=[])", lambda: D.check_key_jump((24, 0, -10.5), joints=[]), "empty"),
    # the teacher's arguments of the checks
    ("check_value(expected=masked)", lambda: E.check_value(0, np.ma.masked), "expected"),
    ("check_value(expected=bytearray)", lambda: E.check_value(49, bytearray(b"1")), "expected"),
    ("check_value(components=3 for 2)", lambda: E.check_value([1, 2], [1, 2], components="xyz"), "components"),
    ("check_value(tol='1e-3')", lambda: E.check_value(1, 1, tol="1e-3"), "tol"),
    ("check_matrix(tol=None)", lambda: E.check_matrix(ROT2, ROT2, tol=None), "tol"),
    ("check_matrix(expected=NaN)", lambda: E.check_matrix([[1]], [[float("nan")]]), "expected"),
    ("check_solutions(expected=[1, 2])", lambda: E.check_solutions([[1, 2]], [1, 2]), "expected"),
    ("check_choice(explanations=list)", lambda: E.check_choice("a", "b", explanations=["a"]), "explanations"),
    ("check_terms(expected={})", lambda: E.check_terms({"a": "b"}, {}), "expected"),
    ("check_function(cases=5)", lambda: E.check_function(abs, abs, 5), "cases"),
    ("seed001_DefinirTHz(d=nan)", lambda: E.seed001_DefinirTHz(0.1, (float("nan"), 0, 0)), "d"),
    ("axis_relation(tol='abc')", lambda: D.axis_relation((0, 0, 0), (0, 0, 1), (1, 0, 0), (0, 1, 0), tol="abc"), "tol"),
    ("show_axes(direction 0)", lambda: D.show_axes([((0, 0, 0), (0, 0, 0), "R")]), "direction"),
    ("joint_value(where=5)", lambda: AI.joint_value(0.1, 5), "where"),
]


@pytest.mark.parametrize("label, call, word", MUST_REFUSE, ids=[m[0] for m in MUST_REFUSE])
def test_nonsense_is_refused(label, call, word):
    with pytest.raises(DHLabError) as error:
        call()
    assert word.lower() in str(error.value).lower()


def test_the_good_values_next_to_them_still_work():
    assert robots.prr_example(l1=0).n == 3 and robots.pr_mechanism(l2=0.5).n == 2
    assert dhlab.deg2rad(720) == pytest.approx(4 * np.pi) and dhlab.rad2deg(-4 * np.pi) == pytest.approx(-720)
    assert DHRobot.from_table([("q1", 0, 1, 0)], qlim=[(-90, 90)]).qlim[0, 1] == pytest.approx(np.pi / 2)
    assert D.check_wrist_centre((1, 2, 3), robot=robots.puma560()).status == "wrong"
    assert E.check_value([1, 2], [1, 2], components="xy").status == "correct"
    assert E.check_choice("Azul", "blue", accepted="azul").status == "correct"
    assert E.check_choice("a", "blue", accepted="azul").status == "wrong"      # not the letters of 'azul'
    assert E.check_solutions([], []).status == "correct"
    assert E.check_solutions([[1, 2]], []).status == "wrong"
    assert str(dhlab.compact(90, ["q1"])) == "90"
    assert D.printed_key_position({2, 5}).shape == (3,)
