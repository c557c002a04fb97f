"""What a student writes in notebook 8's answer cells for a robot of the family, and the ground truth
the grader's fair checks are measured against (how the chain of a student's rows really moves, which
links really land in their frames), independent of the grader; used by the assignment's tests and by
benchmarks/bench_grade_slips.py.

A row is ``(sign, joint, θ0°, d0, a, α°)``: the sign and number of the joint variable, θ's and d's
constant parts, a, and α in degrees, as a student types them into ``Tz(θ, d) @ Tx(α, a)``.
"""
import math

import numpy as np

from dhlab.assignment.model import rows_from_frames
from dhlab.assignment.reference import dh_frames

# the word the notebook asks for in part 1 for each relation of two axes (coincident axes are case 2)
WORDS = {"intersect": "intersect", "parallel": "parallel", "coincident": "parallel", "skew": "skew"}


def rows_in_degrees(robot, frames) -> list:
    """The DH rows that carry ``frames`` into each other: (sign, joint, θ0°, d0, a, α°)."""
    return [(sign, j, round(math.degrees(th), 9), d, a, round(math.degrees(al), 9))
            for sign, j, th, d, a, al in rows_from_frames(robot, frames)]


def namespace_from_rows(robot, rows, frames):
    """What a student writes in the notebook's answer cells: part 1 from the drawn axes
    (coincident axes: "parallel", case 2, as the notebook's three words say), part 2 the
    links in ``frames``, part 3 the rows (degrees) with q_i in θ_i, or in d_i for a sliding joint."""
    from dhlab.assignment import Tx, Tz, joint_variables
    from dhlab.lines import relation
    q = joint_variables(robot.n)
    ns = {"n_links": robot.n + 1, "n_joints": robot.n, "joint_types": robot.kinds,
          "x_cases": [WORDS[relation(robot.axes[i - 1], robot.axes[i], tol=2e-3).kind] for i in range(1, robot.n)],
          "link_points": {k: [tuple(map(float, p)) for p in (robot.world_points(k) - F[:3, 3]) @ F[:3, :3]]
                          for k, F in enumerate(frames)}}
    for i, (sign, j, th, d, a, al) in enumerate(rows, start=1):
        var = q[j] if sign > 0 else -q[j]
        ns[f"T{i}"] = Tz(var + th, d) @ Tx(al, a) if robot.kinds[i - 1] == "R" else Tz(th, var + d) @ Tx(al, a)
    chain = ns["T1"]
    for i in range(2, robot.n + 1):
        chain = chain @ ns[f"T{i}"]
    ns["chain"] = chain
    return ns


def student_namespace(robot, frames):
    """What a student who placed DH frames ``frames`` writes in the notebook's answer cells."""
    return namespace_from_rows(robot, rows_in_degrees(robot, frames), frames)


def report(ns, robot):
    from dhlab.assignment import checks
    from dhlab.assignment.answers import answers_from_namespace
    return checks.check_all(answers_from_namespace(ns, robot.n), ref=robot)


def moves_like(robot, rows, Q) -> bool:
    """The ground truth of part 3, independent of the grader: the chain of ``rows`` moves every
    revolute axis on the robot's line (a sliding one: its direction), each the drawn way, puts
    the end point in place, and its last z along the last axis, at the configurations Q."""
    F = dh_frames([(s, j, math.radians(th), d, a, math.radians(al)) for s, j, th, d, a, al in rows], robot.kinds, Q)
    R = robot.frames(Q)
    points, directions = robot.axes_at(Q)
    for i, (row, kind) in enumerate(zip(rows, robot.kinds)):
        z = row[0] * F[:, i, :3, 2]
        if np.abs(np.sum(z * directions[:, i], axis=1) - 1).max() > 1e-6:
            return False
        off = F[:, i, :3, 3] - points[:, i]
        if kind == "R" and np.abs(off - np.sum(off * z, axis=1)[:, None] * z).max() > 1e-6:
            return False
    last_z = np.abs(np.abs(np.sum(F[:, -1, :3, 2] * R[:, -1, :3, 2], axis=1)) - 1).max() < 1e-6
    return bool(last_z and np.abs(F[:, -1, :3, 3] - R[:, -1, :3, 3]).max() < 1e-6)


def row_mistakes(robot, rows):
    """Typical slips in one T_i: the joint's sense, a turned or flipped x (θ + 90°, θ + 180°), a
    wrong length (d, a, the sign of a), a wrong twist (−α, α + 90°, α in radians)."""
    for i, (s, j, th, d, a, al) in enumerate(rows):
        slides = robot.kinds[i] == "P"
        yield i, "sense", (-s, j, th if slides else -th, -d if slides else d, a, al)
        yield i, "θ + 90°", (s, j, th + 90, d, a, al)
        yield i, "θ + 180°", (s, j, th + 180, d, a, al)
        yield i, "d + 5 cm", (s, j, th, d + 0.05, a, al)
        yield i, "a + 5 cm", (s, j, th, d, a + 0.05, al)
        yield i, "−a", (s, j, th, d, -a, al)
        yield i, "−α", (s, j, th, d, a, -al)
        yield i, "α + 90°", (s, j, th, d, a, al + 90)
        yield i, "α in radians", (s, j, th, d, a, math.radians(al))


def lost(report) -> list:
    return [(part.key, item.label) for part in report.parts for item in part.items if not item.ok]


def links_not_in_their_frames(robot, ns, frames) -> list:
    """The labels of the links drawn (in ``frames``) where the chain of ``ns``'s T_k does not put
    them at home (x_n turned by θ_n + 90°: the gripper): the ground truth of part 2."""
    from dhlab.assignment.answers import answers_from_namespace
    from dhlab.assignment.checks.analysis import matrix
    F, out = np.eye(4), []
    for k, row in enumerate(answers_from_namespace(ns, robot.n).T[:robot.n], start=1):
        F = F @ matrix(row)
        G = frames[k]
        if np.abs((robot.world_points(k) - G[:3, 3]) @ G[:3, :3] @ F[:3, :3].T + F[:3, 3]
                  - robot.world_points(k)).max() > 1e-6:
            out.append(f"link {k} ({robot.link_names[k]})")
    return out
