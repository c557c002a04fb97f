"""Variants: deterministic, sensible, exact as JSON, solvable, told apart, and signed."""
import json
import math

import numpy as np
import pytest

from dhlab import DHLabError
from dhlab.assignment import variants as V
from dhlab.assignment.family import FAMILY, family_names
from dhlab.assignment.model import build, physical_frames, random_frames_from_axes, rows_from_frames
from dhlab.assignment.reference import dh_frames
from dhlab.dh_frames import dh_from_axes
from support import written_answers as W
from support.robot_motion import assert_same_motion, random_q

SECRET = b"the teacher's secret: 32 random bytes would be better"
SEEDS = range(6)
CASES = [(key, seed) for key in family_names() for seed in SEEDS]


@pytest.fixture(autouse=True)
def _the_puma_again():
    """A test that runs a notebook's "Your robot" cell (use_variant) leaves the PUMA in place after it."""
    from dhlab.assignment.notebook_cells import clear_variant
    yield
    clear_variant()


def test_same_seed_same_variant_and_exact_json():
    for key in family_names():
        v = V.variant(key, "s")
        assert V.variant(key, "s") == v
        text = json.dumps(v.to_dict())
        again = V.Variant.from_dict(json.loads(text))
        assert again == v and V.canonical_json(again.to_dict()) == V.canonical_json(v.to_dict())
        assert V.fingerprint(again) == V.fingerprint(v)


def test_the_draw_is_pinned():
    """A variant must be the same on every machine and next year (grading re-draws from the
    roster): the draw is SHA-256 based, and this pins one of them."""
    assert V.variant("puma560", 0).to_dict() == {
        "v": 1, "family": "puma560", "table": V.table_digest("puma560"),
        "lengths": {"a2": 0.495, "a3": 0.02, "d3": 0.14, "d4": 0.415, "floor": 0.76},
        "home": [0, 0, -90, 90, 0, 0], "senses": [1, 1, 1, 1, -1, 1],
        "base": {"mount": "floor", "plate": -0.76, "yaw": 180}}


@pytest.mark.parametrize("key,seed", CASES)
def test_variant_is_sensible_and_not_the_published_robot(key, seed):
    v = V.variant(key, seed)
    robot = V.robot_of_variant(v)
    s = FAMILY[key]
    lengths = dict(v.lengths)
    published = {f"d{j}": d for j, (_, _, d, _, _) in enumerate(s.rows, 1)} | \
                {f"a{j}": a for j, (_, _, _, a, _) in enumerate(s.rows, 1)}
    assert any(lengths[k] != published[k] for k in lengths if k in published)
    for name, value in lengths.items():
        if name != "stroke":
            assert abs(value) >= 0.01 and abs(round(value * 1000) - value * 1000) < 1e-6     # whole millimetres
            if name in published:
                assert 0.7 < value / published[name] < 1.35                                 # the same arm, resized
    z = np.vstack([robot.world_points(k) for k in range(1, robot.n + 1)])[:, 2]
    plate = robot.mount["plate"]
    assert robot.mount["mount"] in s.mounts                 # a SCARA never hangs: its tool would point up
    assert (z > plate).all() if robot.mount["mount"] == "floor" else (z < plate).all()
    for (lo, hi) in robot.qlim:                            # the home pose is inside the joint limits
        assert lo <= 1e-12 and hi >= -1e-12


@pytest.mark.parametrize("key,seed", CASES)
def test_reference_and_every_valid_answer_move_like_the_variant(key, seed):
    """The reference solution, dh_from_axes on the drawn axes, and random valid DH frames
    all give the variant's axes and end point at random configurations."""
    robot = V.robot_of_variant(V.variant(key, seed))
    rng = np.random.default_rng(seed)
    Q = random_q(robot, rng, 8)
    truth = physical_frames(robot, Q)
    assert_same_motion(robot, truth, robot.frames(Q), robot.kinds)
    rebuilt = dh_from_axes([(a.point, a.direction, k) for a, k in zip(robot.axes, robot.kinds)], robot.end_point)
    assert_same_motion(robot, truth, np.array([rebuilt.frames(q) for q in Q]), robot.kinds)
    for _ in range(8):
        rows = rows_from_frames(robot, random_frames_from_axes(robot, rng))
        assert_same_motion(robot, truth, dh_frames(rows, robot.kinds, Q), robot.kinds)


def _moves_apart(a, b, Q) -> float:
    """How far apart two robots' end points and drawn axes get at the same q (metres, or the
    sine of the angle between axis directions)."""
    Fa, Fb = a.frames(Q), b.frames(Q)
    Pa, Da = a.axes_at(Q)
    Pb, Db = b.axes_at(Q)
    ends = np.linalg.norm(Fa[:, -1, :3, 3] - Fb[:, -1, :3, 3], axis=1).max()
    dirs = np.linalg.norm(Da - Db, axis=2).max()
    return float(max(ends, dirs))


@pytest.mark.parametrize("key", family_names())
def test_another_variant_does_not_pass_for_yours(key):
    """Two different variants move differently (far beyond the grader's 2 mm / 0.5°): a
    solution of one, graded against the other, fails."""
    robots = [V.robot_of_variant(V.variant(key, s)) for s in SEEDS]
    Q = np.vstack([np.zeros(robots[0].n), np.random.default_rng(9).uniform(-1, 1, (20, robots[0].n)) * 0.3])
    for i in range(len(robots)):
        assert _moves_apart(robots[i], robots[i], Q) < 1e-12
        for j in range(i):
            assert _moves_apart(robots[i], robots[j], Q) > 5e-3


def test_roster_variants_are_all_different_and_depend_on_the_secret():
    ids = [f"s{i:03d}" for i in range(40)]
    chosen = V.roster_variants(ids, SECRET, "all")
    assert len({V.fingerprint(v) for v in chosen.values()}) == 40
    assert len({v.family for v in chosen.values()}) == len(FAMILY)
    assert V.roster_variants(ids, SECRET, "all") == chosen
    other = V.roster_variants(ids, SECRET + b"!", "all")
    assert sum(other[i] == chosen[i] for i in ids) == 0
    assert {v.family for v in V.roster_variants(ids[:5], SECRET).values()} == {"puma560"}   # the default
    assert {v.family for v in V.roster_variants(ids[:9], SECRET, "kr5, ur5").values()} <= {"kr5", "ur5"}


@pytest.mark.parametrize("bad,match", [
    ("not a dict", "is a dict"),
    ({"extra": 1}, "exactly the keys"),
    ({"family": "r2d2"}, "not one of"),
    ({"senses": [1, 1, 1, 1, 1, 0]}, "each 1 or -1"),
    ({"senses": [True, 1, 1, 1, 1, 1]}, "each 1 or -1"),
    ({"home": [0, 0, 0]}, "must list 6"),
    ({"lengths": {"d1": 0.4}}, "must name"),
    ({"base": {"mount": "wall", "plate": 0, "yaw": 0}}, "variant base"),
    ({"v": 2}, "format 2"),
    ({"table": "0123456789ab"}, "another version of the KUKA KR5's table"),
    ({"family": "cobra600", "table": V.table_digest("cobra600"),
      "lengths": {"a1": 0.3, "a2": 0.3, "d1": 0.4, "stroke": 1.0}, "home": [0, 0, 0.1, 0],
      "senses": [1, 1, 1, 1], "base": {"mount": "ceiling", "plate": 2, "yaw": 0}}, "floor only"),
])
def test_from_dict_rejects_bad_variants(bad, match):
    data = V.variant("kr5", 1).to_dict()
    if isinstance(bad, dict):
        data.update(bad)
    else:
        data = bad
    with pytest.raises(DHLabError, match=match):
        V.Variant.from_dict(data)


def test_lengths_must_be_numbers():
    data = V.variant("kr5", 1).to_dict()
    data["lengths"]["d1"] = float("nan")
    with pytest.raises(DHLabError, match="d1"):
        V.Variant.from_dict(data)


# --- signatures ------------------------------------------------------------------------------------

def test_signature_statuses():
    ana, bruno = V.student_variant("ana", SECRET), V.student_variant("bruno", SECRET)
    rec_ana, rec_bruno = V.sign_record(ana, "ana", SECRET), V.sign_record(bruno, "bruno", SECRET)
    ok = V.verify(rec_ana, "ana", SECRET)
    assert ok.status == "ok" and ok.variant == ana and ok.ok
    # a classmate's notebook handed in: named by its record, or found in the roster
    assert V.verify(rec_bruno, "ana", SECRET).status == "other_student"
    renamed = dict(rec_bruno, student_id="ana")
    found = V.verify(renamed, "ana", SECRET, roster_ids=["ana", "bruno", "carla"])
    assert (found.status, found.signed_for) == ("other_student", "bruno")
    assert V.verify(renamed, "ana", SECRET).status == "tampered"          # without the roster: not genuine for ana
    # anything changed
    changed = json.loads(json.dumps(rec_ana))
    changed["variant"]["lengths"]["d4"] = round(changed["variant"]["lengths"]["d4"] + 0.001, 4)
    assert V.verify(changed, "ana", SECRET).status == "tampered"
    flipped = json.loads(json.dumps(rec_ana))
    flipped["variant"]["senses"][0] *= -1
    assert V.verify(flipped, "ana", SECRET).status == "tampered"
    forged = dict(rec_ana, signature="0" * 64)
    assert V.verify(forged, "ana", SECRET).status == "tampered"
    published = {"variant": V.variant("puma560", "web").to_dict(), "signature": "ab" * 32}
    assert V.verify(published, "ana", SECRET).status == "tampered"
    assert V.verify(rec_ana, "ana", SECRET + b"x").status == "tampered"   # another teacher's secret
    # nothing there
    for record in (None, {}, {"variant": rec_ana["variant"]}, {"signature": rec_ana["signature"]}, "text"):
        assert V.verify(record, "ana", SECRET).status == "missing"
    assert V.verify({"variant": "x", "signature": 5}, "ana", SECRET).status == "tampered"


def _as_javascript_saves_it(value):
    """JupyterLab keeps metadata as JavaScript numbers: 0.0 comes back as 0, 1.5 as 1.5."""
    if isinstance(value, float) and value.is_integer():
        return int(value)
    if isinstance(value, dict):
        return {k: _as_javascript_saves_it(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_as_javascript_saves_it(v) for v in value]
    return value


def test_a_notebook_saved_by_jupyterlab_still_verifies():
    for key in family_names():
        v = V.variant(key, 7)
        raw = {"variant": v.to_dict()}
        raw["variant"]["base"]["plate"] = float(raw["variant"]["base"]["plate"])      # as Python might write it
        raw["variant"]["home"] = [float(h) for h in raw["variant"]["home"]]
        record = V.sign_record(V.Variant.from_dict(raw["variant"]), "ana", SECRET)
        record["variant"] = raw["variant"]
        saved = json.loads(json.dumps(_as_javascript_saves_it(record)))
        assert V.verify(saved, "ana", SECRET).status == "ok"
        assert V.verify(saved, "ana", SECRET).variant == v


def test_signature_is_over_canonical_json():
    """Key order and spacing of the stored JSON do not matter; values do."""
    rec = V.sign_record(V.variant("ur5", 3), "ana", SECRET)
    shuffled = json.loads(json.dumps(rec, sort_keys=False, indent=4))
    shuffled["variant"] = dict(reversed(list(shuffled["variant"].items())))
    assert V.verify(shuffled, "ana", SECRET).status == "ok"


def test_secrets():
    with pytest.raises(DHLabError, match="at least 16 bytes"):
        V.sign_record(V.variant("kr5", 1), "ana", b"short")
    with pytest.raises(DHLabError, match="non-empty"):
        V.sign_record(V.variant("kr5", 1), "", SECRET)
    assert len(V.new_secret()) == 64 and V.new_secret() != V.new_secret()


def test_load_secret(tmp_path):
    path = tmp_path / "key"
    path.write_bytes(b"  0123456789abcdef0123  \n")
    assert V.load_secret(path) == b"0123456789abcdef0123"
    path.write_bytes(b"short\n")
    with pytest.raises(DHLabError, match="at least 16"):
        V.load_secret(path)
    with pytest.raises(DHLabError, match="cannot read"):
        V.load_secret(tmp_path / "nope")


def test_use_variant_is_the_seam():
    from dhlab.assignment import reference as puma
    from dhlab.assignment.notebook_cells import active_robot, clear_variant, current_robot, use_variant
    v = V.variant("cobra600", 2)
    try:
        robot = use_variant(v.to_dict(), student_id="ana")
        assert active_robot() is robot and robot.n == 4 and V.fingerprint(robot) == V.fingerprint(v)
        assert current_robot() is robot
        assert math.isclose(float(np.linalg.norm(robot.axes[2].direction)), 1.0)
    finally:
        clear_variant()
    assert active_robot() is None and current_robot() is puma.reference()


@pytest.mark.parametrize("key", family_names())
def test_the_graders_valid_frames_accept_the_reference_and_random_answers(key):
    """Integration seam: an AssignmentRobot works where the grader takes the PUMA reference
    (dhlab.assignment.reference's valid-frame families and link fit)."""
    from dhlab.assignment import valid_frames as puma
    if not all(hasattr(puma, f) for f in ("is_valid_frame", "fit_link")):
        pytest.skip("the grader's valid-frame functions changed")
    rng = np.random.default_rng(11)
    for seed in range(3):
        robot = V.robot_of_variant(V.variant(key, seed))
        for k in range(robot.n + 1):
            assert puma.is_valid_frame(robot, k, robot.home_frames[k])
            assert puma.fit_link(robot, k, robot.local_points(k))[1] < 1e-6
        for _ in range(4):                   # a prismatic axis's line moved too: its frames' families allow it
            frames = random_frames_from_axes(robot, rng, slide=0.3)
            assert all(puma.is_valid_frame(robot, k, F) for k, F in enumerate(frames))
            for k, F in enumerate(frames):
                local = (robot.world_points(k) - F[:3, 3]) @ F[:3, :3]
                assert puma.fit_link(robot, k, local)[1] < 1e-6


# --- with the grader's fair checks (the integration seam: the checks take ref=robot) ----------------

def _grade(ns, robot):
    return W.report(ns, robot).score


@pytest.mark.parametrize("key", family_names())
def test_graded_against_its_own_variant_every_valid_answer_scores_full_marks(key):
    """The reference solution and random valid DH assignments (z_i either way, x_i either way,
    origins slid along parallel axes, x_i turned about coincident ones, a sliding joint's axis
    drawn on another line parallel to it, x_n turned) of published robots and of variants."""
    rng = np.random.default_rng(21)
    for seed in (None, 0, 1):
        robot = build(key) if seed is None else V.robot_of_variant(V.variant(key, seed))
        report = W.report(W.student_namespace(robot, robot.home_frames), robot)
        assert report.score == 10, report.text()
        assert f"move like the {robot.name}" in report.text()
        for _ in range(4):
            report = W.report(W.student_namespace(robot, random_frames_from_axes(robot, rng, slide=0.3)), robot)
            assert report.score == 10, report.text()


@pytest.mark.parametrize("key", family_names())
def test_a_classmates_solution_does_not_pass(key):
    """Full marks for a classmate's robot (same family, another variant) are far from full marks
    for yours: part 2's links and part 3's transformations do not fit."""
    for mine, theirs in (("mine", "theirs"), ("x", "y")):
        mine, theirs = (V.robot_of_variant(V.variant(key, s)) for s in (mine, theirs))
        assert _grade(W.student_namespace(theirs, theirs.home_frames), theirs) == 10
        report = W.report(W.student_namespace(theirs, theirs.home_frames), mine)
        assert report.score < 7 and report.part("part3").score < 5 and report.part("part2").score < 3


def test_coincident_axes_are_case_2():
    """The SCARA's quill slides along the line its tool turns about: "parallel" (case 2, the
    notebook's word) or "coincident" are right for x3, "intersect" is not; and since a sliding
    joint's axis may be drawn on any parallel line, "coincident" is right for joints 2 and 3 too."""
    robot = V.robot_of_variant(V.variant("cobra600", 1))
    ns = W.student_namespace(robot, robot.home_frames)
    assert ns["x_cases"] == ["parallel", "parallel", "parallel"]
    for words, lost in ((["parallel", "coincident", "coincident"], []), (["parallel", "parallel", "intersect"], ["x3"]),
                        (["coincident", "parallel", "parallel"], ["x1"])):
        part1 = W.report(dict(ns, x_cases=words), robot).part("part1")
        assert [item.label for item in part1.items if not item.ok] == lost


# --- mistakes: each one costs exactly its item ----------------------------------------------------

def _other_mistakes(robot, ns):
    """Slips in parts 1 and 2 and in the chain: (part, what, the changed namespace)."""
    from dhlab.assignment import valid_frames as puma
    wrong_word = {"intersect": "skew", "skew": "intersect", "parallel": "intersect"}
    yield "part1", "n_links", dict(ns, n_links=robot.n)
    yield "part1", "n_joints", dict(ns, n_joints=robot.n + 1)
    k = robot.kinds.find("P") if "P" in robot.kinds else 1
    swapped = "PR"[robot.kinds[k] == "P"]          # joint k's kind turned into the other one
    yield "part1", "joint_types", dict(ns, joint_types=robot.kinds[:k] + swapped + robot.kinds[k + 1:])
    for i in range(1, robot.n):
        cases = list(ns["x_cases"])
        if "P" in robot.kinds[i - 1:i + 1] and cases[i - 1] in ("intersect", "skew"):
            cases[i - 1] = "parallel"    # next to a sliding joint both of those are right; their directions are not
        else:
            cases[i - 1] = wrong_word[cases[i - 1]]
        yield "part1", f"x{i}", dict(ns, x_cases=cases)
    for k in range(robot.n + 1):
        points = dict(ns["link_points"])
        moved = [list(p) for p in points[k]]
        moved[-1][k % 3] += 0.05
        points[k] = [tuple(p) for p in moved]
        yield "part2", f"link {k}: a point 5 cm off", dict(ns, link_points=points)
        if k and not puma.frame_family(robot, k).loose and not puma.is_valid_frame(robot, k, np.eye(4)):
            # (next to a sliding joint, and on a SCARA, the world frame may be a valid frame k)
            world = {**ns["link_points"], k: [tuple(map(float, p)) for p in robot.world_points(k)]}
            yield "part2", f"link {k} in world coordinates", dict(ns, link_points=world)
    swapped = ns["T2"] @ ns["T1"]
    for i in range(3, robot.n + 1):
        swapped = swapped @ ns[f"T{i}"]
    yield "part3", "chain out of order", dict(ns, chain=swapped)


@pytest.mark.parametrize("key", family_names())
def test_each_mistake_costs_exactly_its_item(key):
    """Every single slip, in a variant's reference solution and in a random valid one: when it
    changes what the answer says (the chain moves unlike the robot, a fact of part 1 or a
    link's points), exactly one item is lost, and the score drops by that item's share of its
    part; a change that leaves a valid chain (e.g. θ + 90° on the last frame, whose x is free)
    costs only the link that is no longer drawn in its frame (part 2), if any. Ground truth from
    the robot's motion and the links' points, not from the grader."""
    rng = np.random.default_rng(31)
    counted = 0
    for seed in (2, 3):                                   # the reference solution of one, a random one of the other
        robot = V.robot_of_variant(V.variant(key, seed))
        Q = np.vstack([np.zeros(robot.n)] + [[rng.uniform(max(lo, -3.0), min(hi, 3.0)) for lo, hi in robot.qlim]
                                             for _ in range(6)])
        for frames in [robot.home_frames if seed == 2 else random_frames_from_axes(robot, rng, slide=0.3)]:
            rows = W.rows_in_degrees(robot, frames)
            ns = W.namespace_from_rows(robot, rows, frames)
            cases = [(part, what, changed) for part, what, changed in _other_mistakes(robot, ns)]
            for i, what, row in W.row_mistakes(robot, rows):
                if row != rows[i]:
                    changed = rows[:i] + [row] + rows[i + 1:]
                    cases.append(("part3" if not W.moves_like(robot, changed, Q) else None, f"T{i + 1}: {what}",
                                  W.namespace_from_rows(robot, changed, frames)))
            for part, what, changed in cases:
                report = W.report(changed, robot)
                lost = W.lost(report)
                if part is None:                          # still a valid chain, but its frames may have moved:
                    moved = W.links_not_in_their_frames(robot, changed, frames)
                    assert [k for _, k in lost] == moved and len(moved) <= 1, (key, seed, what, report.text())
                    continue
                counted += 1
                assert len(lost) == 1 and lost[0][0] == part, (key, seed, what, report.text())
                share = report.part(part).points / len(report.part(part).items)
                assert report.score == pytest.approx(10 - share, abs=0.011), (what, report.text())
    assert counted > 60                                   # the mistakes were mistakes


@pytest.mark.parametrize("key", ["kr5", "ur5"])
def test_the_notebooks_own_checks_tables_and_figures_use_the_students_robot(key):
    """After the "Your robot" cell (use_variant), the notebook's check_part, tables, figures and
    teach panel are about that robot: its n, its axes, its name."""
    from dhlab.assignment import notebook as A
    from dhlab.assignment.notebook_cells import use_variant
    v = V.variant(key, 5)
    robot = use_variant(v.to_dict(), student_id="ana")
    ns = W.student_namespace(robot, robot.home_frames)
    assert [A.check_part(p, ns).score for p in (1, 2, 3)] == [2, 3, 5]
    assert f"move like the {robot.name}" in A.check_part3(ns).text()
    assert repr(A.axes_table()) == repr(robot.axes_table()) and "G4" in repr(A.points_table())
    wrong = dict(ns, T2=ns["T3"])
    wrong["chain"] = wrong["T1"] @ wrong["T2"] @ ns["T3"] @ ns["T4"] @ ns["T5"] @ ns["T6"]
    assert A.check_part3(wrong).score < 5
    assert A.robot_of(ns).name == f"your {robot.name}"
    np.testing.assert_allclose(A.robot_of(ns).fk(np.zeros(robot.n))[:3, 3], robot.end_point, atol=1e-9)
    figure = A.my_robot_figure(ns)
    assert not isinstance(figure, A.Note) and robot.name in figure.legends[0].texts[0].get_text()
    assert isinstance(A.my_robot_figure({}), A.Note) and "T1" in A.my_robot_figure({}).text
    panel = A.teach(ns)
    assert len(panel.sliders) == robot.n
    assert A.puma_figure().axes                           # the robot's own picture
