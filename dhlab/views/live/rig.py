"""The robot's drawing as a rig: every moving point fixed in one of the chain's frames, so that
the browser can move the picture itself while a slider moves (the canvas backend).

Why: with the canvas backend a slider step still goes to the kernel and back before the
picture changes (a round trip of 40-60 ms on a busy machine, and nothing at all while the
kernel runs another cell). But every point of a robot's stick figure, triads, joints and
frame labels is carried by one of its frames: a point ``p`` that is fixed in the frame
``N_k(q)`` is ``N_k(q) · local`` for one constant ``local``. The browser knows the sliders'
values at once, so with the chain's kinematics (as a list of steps, like
:mod:`dhlab.kinematics` runs them: ``chain.js``) and each point's ``(k, local)`` it moves the
picture in the same animation frame as the slider. The kernel's own picture still arrives
after it and replaces the browser's.

How the points are found to be fixed, without asking the drawing code: the view is put in a
few random poses and, for every point, the *nodes* of the chain (the running product after
each step of the kinematics program: base, joints, constant parts, tool) are tried, the first
in which the point does not move is its node. A point fixed in none (a joint axis cut by the
axes' box, a drawing that stretches) is left to the kernel: its artist keeps the last pose the
kernel sent. A coincidence over random poses is a measure-zero event; the fit is exact to
rounding (``TOLERANCE`` relative to the robot's size).

>>> import numpy as np, dhlab
>>> robot = dhlab.robots.rrr_example()
>>> steps = program_steps(robot)
>>> N = nodes(robot, robot.qz)
>>> np.allclose(N[-1], robot.fk(robot.qz))       # the last node is the end effector
True
"""
from __future__ import annotations

import numpy as np

from ...kinematics import Program, run
from .scene import Numbers, Unsupported, describe_artist

__all__ = ["program_steps", "nodes", "node_program", "fit", "Rig", "TOLERANCE", "PROBES"]

TOLERANCE = 1e-7          # a point is fixed in a node if it moves less than this x the robot's size
PROBES = 3                # random poses tried besides the current one


def program_steps(robot) -> list:
    """The robot's kinematics program as JSON for the browser (``chain.js``): a list of
    ``["const", [16 numbers, row-major]]`` and ``["rot"|"move", axis, joint, sign, offset]``,
    applied on the right of the running product, which starts as the identity (the base is
    the first constant step)."""
    steps = []
    for step in robot.program.steps:
        if step[0] == "const":
            steps.append(["const", _flat(step[1])])
        elif step[0] in ("rot", "move"):
            _, axis, joint, sign, offset = step
            steps.append([step[0], int(axis), int(joint), int(sign), float(offset)])
        # "frame" marks where a link ends: no motion, no node
    return steps


def _flat(M) -> list:
    return np.asarray(M, dtype=float).ravel().tolist()


def nodes(robot, q) -> np.ndarray:
    """Every node of the chain at ``q``: (K, 4, 4), node 0 the world (identity), then the
    running product after each step of :func:`program_steps` (what ``chain.js`` computes);
    for P poses at once, ``q`` of shape (P, n), (P, K, 4, 4).

    Run by :func:`dhlab.kinematics.run`, the course's one forward-kinematics path: the robot's
    own program, with a frame kept after every step instead of after every link."""
    return run(node_program(robot), np.asarray(q, dtype=float), frames=True)


def node_program(robot) -> Program:
    """The robot's kinematics program with a ``("frame",)`` after each step (its own link ends
    dropped) and the world as its base: run with ``frames=True``, it gives every node."""
    steps = [kept for step in robot.program.steps if step[0] != "frame" for kept in (step, ("frame",))]
    return Program(base=np.eye(4), steps=steps)


def fit(points, node_poses, size: float) -> tuple:
    """For points seen at P poses, (P, V, 3), and the nodes at those poses, (P, K, 4, 4):
    ``(node, local)`` per point: the first node in which the point stays fixed (-1 when none:
    the kernel keeps drawing it; -2 for a missing point, NaN, as a ragged face's padding),
    and its coordinates in that node."""
    points = np.asarray(points, dtype=float)
    P, V = points.shape[:2]
    node = np.full(V, -1, dtype=np.int32)
    local = np.zeros((V, 3))
    missing = ~np.isfinite(points).all(axis=(0, 2))
    node[missing] = -2
    inverse = np.linalg.inv(node_poses)                        # (P, K, 4, 4)
    # every point in every node at every pose: (P, K, V, 3)
    seen = np.einsum("pkij,pvj->pkvi", inverse[..., :3, :3], np.nan_to_num(points)) + inverse[..., None, :3, 3]
    spread = np.abs(seen - seen[:1]).max(axis=(0, 3))           # (K, V): how much it moves in each node
    fixed = spread <= TOLERANCE * max(size, 1e-9)
    for v in np.flatnonzero(~missing):
        k = np.flatnonzero(fixed[:, v])
        if len(k):
            node[v], local[v] = k[0], seen[0, k[0], v]
    return node, local


def _arrays(item, numbers) -> dict:
    """The data-space point arrays of a scene item, by key: (V, 3) each."""
    if item.get("space", -1) < 0:
        return {}
    key = {"line": "points", "polys": "faces", "glyphs": "anchors"}[item["kind"]]
    at, count = item[key][0], item[key][1] * (item[key][2] if key == "faces" else 1)
    return {key: numbers[at:at + 3 * count].reshape(count, 3)}


class Rig:
    """How the artists of ``view`` (a :class:`~dhlab.views.viewbase.RobotView` in a LiveFigure
    with the canvas backend) hang on the chain, and which ``sliders`` set its joints (display
    units: ``scales`` turns a slider's value into the joint's, e.g. degrees to radians).

    :meth:`describe` probes the view (then puts it back exactly where it was) and returns the
    message for the browser; ``rig.q`` is the pose the view shows (sent with every scene)."""

    def __init__(self, view, sliders, scales):
        self.view, self.sliders, self.scales = view, list(sliders), [float(s) for s in scales]

    @property
    def q(self) -> list:
        return np.asarray(self.view.q, dtype=float).tolist()

    def describe(self, moving, seed: int = 0) -> tuple:
        """(content, numbers) of the rig message: the program, the sliders' model ids and scales,
        and for each artist of the view (its index in ``moving``), each point array's nodes
        and local coordinates (offsets into ``numbers``: int32 nodes, float32 locals)."""
        view, robot = self.view, self.view.robot
        q0 = np.array(view.q, dtype=float)
        poses = [q0, *_random_poses(robot, q0, PROBES, seed)]
        mine = [k for k, artist in enumerate(moving) if artist in view.artists]
        seen = {k: [] for k in mine}
        try:
            for q in poses:
                view._set_pose(q)
                view._place(view.frames)
                for k in mine:
                    seen[k].append(_seen(moving[k], view.ax.figure))
        finally:
            view._set_pose(q0)
            view._place(view.frames)
            for artist in moving:                  # labels placed for a probe: place them afresh
                artist.__dict__.pop("_dhlab_placed", None)
        node_poses = nodes(robot, np.array(poses))
        size = max(float(robot.reach()), 1e-6)
        numbers, artists = Numbers(), {}
        for k in mine:
            entries = _fit_artist(seen[k], node_poses, size, numbers)
            if entries:
                artists[str(k)] = entries
        content = {"kind": "rig", "steps": program_steps(robot), "scales": self.scales,
                   "sliders": [slider.model_id for slider in self.sliders], "artists": artists,
                   "nodes": int(node_poses.shape[1])}
        return content, numbers.buffer()


def _seen(artist, figure):
    """The point arrays of one artist as the scene would send them now, or None."""
    try:
        numbers = Numbers()
        axes = figure.axes
        space = axes.index(artist.axes) if artist.axes in axes else -1
        item = describe_artist(artist, space, numbers, figure.dpi / 72.0)
    except Unsupported:
        return None
    return _arrays(item, numbers.buffer().astype(float))


def _fit_artist(views, node_poses, size, numbers) -> list:
    """The rig entries of one artist seen in several poses: [{key, count, nodes, local}]."""
    if any(v is None for v in views) or len({tuple(sorted(v)) for v in views}) != 1:
        return []
    entries = []
    for key in views[0]:
        shapes = {v[key].shape for v in views}
        if len(shapes) != 1:                   # the number of points depends on the pose
            continue
        node, local = fit(np.array([v[key] for v in views]), node_poses, size)
        if (node == -1).all():
            continue
        entries.append({"key": key, "count": int(len(node)),
                        "nodes": numbers.add(node.astype(np.float32)), "local": numbers.add(local)})
    return entries


def _random_poses(robot, q0, count, seed) -> list:
    """``count`` poses spread over the joint limits (a turn at most for a revolute joint)."""
    rng = np.random.default_rng(seed)
    lo, hi = np.array(robot.qlim, dtype=float).T
    lo = np.where(np.isfinite(lo), lo, q0 - np.pi)
    hi = np.where(np.isfinite(hi), hi, q0 + np.pi)
    return [rng.uniform(lo, hi) for _ in range(count)]
