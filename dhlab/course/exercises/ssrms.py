"""Exercises of notebook 7: the SSRMS's C++ keyboard control (7.1, 7.3) and its parallel axes (7.2)."""
from __future__ import annotations

import numpy as np

from ... import robots
from ...dh import DHRobot
from ...errors import DHLabError
from ...i18n import N_, _
from ...transforms import trans
from ...validation import as_index, describe
from ..checks.feedback import Exercise, Feedback, short_repr, unanswered
from ..checks.reading import is_unanswered
from ..checks.values import check_value
from .dh_common import as_robot, as_samples, number_text, right_answer, vector_text, whole_number, wrong_answer

__all__ = ["thlist_slot", "check_thlist_slots", "parallel_pairs", "check_parallel_pairs",
           "printed_key_position", "check_key_jump"]


# --- notebook 7: the SSRMS's C++ keyboard control, and its parallel axes ------------------------------
SSRMS_JOINTS = 7         # seed 000's arm: the keys '1' … '7'


def thlist_slot(joint: int, robot=None) -> int:
    """Index in seed 000's ``THList`` of joint ``joint``'s Tz[θ, d] factor (the base has slots 0, 1).
    ``joint`` is 1 … n (the SSRMS, or ``robot``, has n joints)."""
    n = SSRMS_JOINTS if robot is None else as_robot(robot).n
    return 2 * as_index(joint, "joint", 1, n)


def check_thlist_slots(slots, robot=None) -> Feedback:
    """Check ``{joint: THList index}``: the slot a key must overwrite to move each SSRMS joint."""
    robot = robots.ssrms() if robot is None else as_robot(robot)
    name = _("your THList slots")
    if is_unanswered(slots):
        return unanswered(name)
    if not isinstance(slots, dict):
        return wrong_answer(name, [_("give a dict {{joint: index}} for joints 1 … {n}, not a {type}.").format(
            n=robot.n, type=type(slots).__name__)])
    items = []
    for joint in range(1, robot.n + 1):
        if joint not in slots:
            items.append(_("joint {joint}: missing.").format(joint=joint))
            continue
        given = whole_number(slots[joint])
        if given is None:
            items.append(_("joint {joint}: {value} is not an index (a whole number such as 5).").format(
                joint=joint, value=short_repr(slots[joint], 30)))
            continue
        right = thlist_slot(joint, robot)
        if given == right:
            continue
        if given == right + 1:
            why = _("THList[{given}] is link {joint}'s Tx[α, a] factor, which never changes: the key must rebuild "
                    "the factor that holds θ{joint}").format(given=given, joint=joint)
        elif given == right - 2:
            owner = _("the base") if joint == 1 else _("joint {k}").format(k=joint - 1)
            why = _("THList[{given}] is the Tz factor of {owner}: count the base's pair too (the base is a model of "
                    "its own, with its Tz and Tx)").format(given=given, owner=owner)
        else:
            why = _("the list holds two factors per link, Tz then Tx, and the base's pair comes first")
        items.append(_("joint {joint}: not THList[{given}]: {why}.").format(joint=joint, given=given, why=why))
    return wrong_answer(name, items) if items else right_answer(
        name, [_("Joint k's key overwrites THList[2k], its Tz[θ_k, d_k] factor.")])


def parallel_pairs(robot=None, samples: int = 200, seed: int = 0) -> set:
    """Pairs (j, k), j < k, of joints whose axes are parallel at zero and at every one of
    ``samples`` random configurations within the joint limits.

    >>> sorted(parallel_pairs())                 # the SSRMS
    [(3, 4), (3, 5), (4, 5)]
    """
    robot = robots.ssrms() if robot is None else as_robot(robot)
    samples, seed = as_samples(samples, seed)
    rng = np.random.default_rng(seed)
    lo, hi = robot.qlim.T
    Q = np.vstack([np.zeros(robot.n), lo + (hi - lo) * rng.random((samples, robot.n))])
    Z = np.asarray(robot.frames(Q), dtype=float)[:, :-1, :3, 2]      # (N, n, 3): axis of joint k = z_(k-1)
    return {(j + 1, k + 1) for j in range(robot.n) for k in range(j + 1, robot.n)
            if np.all(np.linalg.norm(np.cross(Z[:, j], Z[:, k]), axis=1) < 1e-9)}


def _counterexample(robot, j: int, k: int):
    """One joint at 30° (degrees, others 0) where the axes of joints j and k are not parallel."""
    for m in range(robot.n):
        q = np.zeros(robot.n)
        q[m] = 30.0
        F = np.asarray(robot.frames(np.radians(q)), dtype=float)
        if np.linalg.norm(np.cross(F[j - 1, :3, 2], F[k - 1, :3, 2])) > 1e-6:
            return q
    return None


def _read_pairs(pairs):
    """A set or list of pairs of whole numbers as a set of sorted tuples; None if it is not one."""
    if isinstance(pairs, (str, dict)) or not isinstance(pairs, (set, frozenset, list, tuple)):
        return None
    given = set()
    for pair in pairs:
        if isinstance(pair, (str, dict)) or not isinstance(pair, (set, frozenset, list, tuple)):
            return None
        numbers = [whole_number(v) for v in pair]
        if None in numbers:
            return None
        given.add(tuple(sorted(numbers)))
    return given


def check_parallel_pairs(pairs, robot=None) -> Feedback:
    """Check the set of joint pairs (j, k) whose axes stay parallel at every configuration
    (default robot: the SSRMS)."""
    robot = robots.ssrms() if robot is None else as_robot(robot)
    name = _("your set of parallel pairs")
    if is_unanswered(pairs):
        return unanswered(name)
    given = _read_pairs(pairs)
    if given is None:
        return wrong_answer(name, [_("give a set of pairs of joint numbers, e.g. {(1, 2), (2, 5)}.")])
    if any(len(p) != 2 or p[0] == p[1] or not all(1 <= v <= robot.n for v in p) for p in given):
        return wrong_answer(name, [_("each pair must be two different joint numbers from 1 to {n}.").format(n=robot.n)])
    right = parallel_pairs(robot)
    F0 = np.asarray(robot.frames(robot.qz), dtype=float)
    items = []
    for j, k in sorted(given - right):
        at_zero = np.linalg.norm(np.cross(F0[j - 1, :3, 2], F0[k - 1, :3, 2])) < 1e-9
        q = _counterexample(robot, j, k)
        shown = "" if q is None else _(": at θ = {q}° they are not").format(q=vector_text(q, 0))
        what = _("parallel at θ = 0, but not at every configuration") if at_zero else _("their axes are not parallel")
        items.append(_("joints {j} and {k}: {what}").format(j=j, k=k, what=what) + shown + ".")
    missed = len(right - given)
    if missed:          # how many, not which: finding them is the exercise
        items.append((_("{k} pairs of joints whose axes stay parallel at every configuration are missing from your "
                        "set (being parallel is transitive).") if missed > 1 else
                      _("{k} pair of joints whose axes stay parallel at every configuration is missing from your "
                        "set (being parallel is transitive).")).format(k=missed))
    return wrong_answer(name, items) if items else right_answer(
        name, [_("Exactly these pairs stay parallel: {pairs}.").format(
            pairs=", ".join(f"({j}, {k})" for j, k in sorted(right)))])


def printed_key_position(joints, robot=None) -> np.ndarray:
    """Where the SSRMS's end effector would be, all joints at 0, after one press of the key of
    each joint in ``joints`` (one joint number or several) with the seed's printed handler
    (``THList[2k] = THx``, erratum 000-2).

    At that moment THx holds the last Tx that ``configurarTH`` built, the gripper's
    Tx[0, 0] = identity: joint k's factor Tz[θ_k, d_k] becomes the identity.

    >>> printed_key_position(1).round(6).tolist()
    [24.0, 0.0, -13.0]
    """
    robot = robots.ssrms() if robot is None else as_robot(robot, kind=DHRobot)
    pressed = _pressed(joints, robot.n)
    T = np.eye(4)
    for k in range(1, robot.n + 1):
        A = np.asarray(robot.A(k, 0.0), dtype=float)
        if k in pressed:
            A = np.linalg.solve(trans(0, 0, float(robot.links[k - 1].d)), A)   # only Tx[α_k, a_k] is left
        T = T @ A
    return T[:3, 3].round(12) + 0.0


def _pressed(joints, n: int) -> tuple:
    """The joints whose keys are pressed, in order, each once: one joint number (1 … n) or several."""
    if isinstance(joints, np.ndarray):
        if joints.ndim > 1:
            raise DHLabError(_("joints must be one joint number or a list of them, got {value}.").format(
                value=describe(joints)))
        joints = joints.tolist()            # a number (0-d) or a list of numbers
    if isinstance(joints, (list, tuple, set, frozenset, range)):
        if not len(joints):
            raise DHLabError(_("joints is empty: name the joint whose key is pressed (1 … {n}), or several, e.g. "
                               "(2, 5).").format(n=n))
        return tuple(dict.fromkeys(as_index(j, _("each joint of joints"), 1, n) for j in joints))
    return (as_index(joints, "joints", 1, n),)


def check_key_jump(position, joints=(2, 5), robot=None) -> Feedback:
    """Check where the end effector ends up when the keys of ``joints`` are pressed once each
    with the printed (wrong) handler of seed 000, all joints at 0."""
    robot = robots.ssrms() if robot is None else as_robot(robot, kind=DHRobot)
    joints = _pressed(joints, robot.n)
    correct = np.asarray(robot.fk(robot.qz), dtype=float)[:3, 3]
    mistakes = [(correct, _("that is where the correct code (THz) puts it. With the printed THx, slot "
                            "THList[2k] receives the identity: the last Tx that configurarTH built is the "
                            "gripper's Tx[0, 0]."))]
    if len(joints) > 1:
        for k in joints:
            mistakes.append((printed_key_position(k, robot), _(
                "that is the jump of joint {k}'s key alone: each pressed key overwrites its own slot, and the slots "
                "stay overwritten.").format(k=k)))
    feedback = check_value(position, printed_key_position(joints, robot), name=_("your position"),
                           components=("x", "y", "z"), mistakes=mistakes)
    if feedback.ok:
        lost = ", ".join(f"d{k} = {number_text(float(robot.links[k - 1].d))}" for k in joints)
        feedback.items.append(_("The factors Tz[θk, dk] of joints {joints} became the identity: those joints are "
                                "frozen and their offsets ({lost}) are lost.").format(
                                    joints=", ".join(map(str, joints)), lost=lost))
    return feedback


# --- the exercises of this module, by key: dhlab.course.exercises.exercise(key) makes them -------------
EXERCISES = {
    "7.1": lambda: Exercise("7.1", N_("the THList slot of each joint"), check_thlist_slots, [
        N_("configurarTH pushes two matrices per link (THz, then THx), starting with the base's pair."),
        N_("Key '1' (code 97) writes THList[2] for joint 1.")]),
    "7.2": lambda: Exercise("7.2", N_("which joint axes stay parallel"), check_parallel_pairs, [
        N_("Not only consecutive joints: if z2 ∥ z3 and z3 ∥ z4, then z2 ∥ z4."),
        N_("A pair that is parallel at θ = 0 must stay parallel when any joint turns.")]),
    "7.3": lambda: Exercise("7.3", N_("where the printed key handler sends the arm"), check_key_jump, [
        N_("As printed, the key of joint k sets THList[2k] = THx, and THx is the identity at that moment."),
        N_("Both slots stay overwritten: multiply the 14 factors with Tz[θ2, 6] and Tz[θ5, 6] replaced by "
           "the identity, all joints at 0.")]),
}
