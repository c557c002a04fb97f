"""Part 2 of the assignment: each link's points, in the frame the student's own transformations give it.

Seed 000 models each piece of the robot in its own DH frame, so that the program places
it with ``T_1···T_k`` and never touches the model (figures 10–13). A link drawn in a
valid frame that is not the one the student's ``T_k`` builds lands in the wrong place
when the robot is assembled: that is the mistake part 2 is about. So link k is right when

* its points are the link's shape and a valid DH frame k puts them on the robot (the DH
  rules: a message says what is wrong otherwise — a mirror image, z not along the joint's
  axis, the origin off it, x off the common normal …), **and**
* the student's own transformations place it there: with ``T_1 … T_k`` all right in
  part 3, the frame they build is the one; after a row part 3 charges (``T_j`` wrong,
  flipped or missing, the last such j ≤ k), the frame the student meant cannot be known,
  so the link is right when their rows ``T_{j+1} … T_k`` carry *some* valid frame j onto
  it (for j = k: any valid frame k). A slip in part 3 is charged once, in part 3.

With no transformations written yet, the DH rules alone decide, and a note says that the
links will be checked again in the frames of part 3.
"""
from __future__ import annotations

import math

import numpy as np

from ...i18n import _, case_word
from ..answers import NOT_ANSWERED, Answers, Row, Unreadable
from ..reference import TOL_DEG, TOL_POS, relation
from ..valid_frames import fit_link, frame_family, is_valid_frame
from .analysis import Analysis, Item, fits, matrix, point_text, slips_of

__all__ = ["link_items"]


def link_items(answers: Answers, analysis: Analysis, ref) -> tuple:
    """One :class:`Item` per link 0…n, and the notes (not scored): ``(items, notes)``."""
    value = answers.link_points
    items = []
    for k in range(ref.n + 1):
        label = _("link {k} ({name})").format(k=k, name=_(ref.link_names[k]))     # (the course's catalog names them)
        points = value[k] if isinstance(value, list) and k < len(value) else (
            NOT_ANSWERED if isinstance(value, list) else value)
        if points is NOT_ANSWERED:
            items.append(Item(label, None, _("not answered")))
        elif isinstance(points, Unreadable):                # the whole answer, or this link: say why
            items.append(Item(label, False, points.why))
        else:
            items.append(_check_link(ref, k, label, np.array(points, float), analysis))
    notes = []
    if isinstance(value, list) and len(value) > ref.n + 1:
        notes.append(_("(link_points has {count} links; the robot has {links}: links 0…{n})").format(
            count=len(value), links=ref.n + 1, n=ref.n))
    if any(item.ok for item in items[1:]) and not any(isinstance(row, Row) for row in analysis.rows):
        notes.append(_("(checked by the DH rules alone so far: each link must also be drawn in the frame your "
                       "T1…T{n} of part 3 build; they are checked again when you have written them)").format(n=ref.n))
    return items, notes


def _last_charged(analysis: Analysis, k: int) -> int:
    """The last row T_j, j ≤ k, that part 3 does not accept (0 when T_1 … T_k are all right)."""
    return max([j for j in range(1, k + 1) if not analysis.items[j - 1].ok], default=0)


def _check_link(ref, k: int, label: str, P, analysis: Analysis) -> Item:
    names = [name for name, _point in ref.points[k]]
    W = ref.world_points(k)
    if len(P) != len(W):
        return Item(label, False, _("give the {count} points {names} in this order; you gave {given}").format(
            count=len(W), names=", ".join(names), given=len(P)))
    shape = _shape_problem(names, P, W)
    if shape:
        return Item(label, False, shape)
    _fit, err = fit_link(ref, k, P)
    if err > TOL_POS:
        return Item(label, False, _frame_problem(ref, k, names, P, W))
    if k == 0:
        return Item(label, True, _("in frame 0"))
    j = _last_charged(analysis, k)
    if j == 0:                                    # T_1 … T_k all right: the frame they build
        F = analysis.frames[k]
        if _lands(P, F, W):
            return Item(label, True, _("in your frame {k}, the one your {rows}").format(k=k, rows=_rows_text(k)))
        m = _slid_back(ref, analysis, k, P, W)
        if m:
            rows = _("T{m} is").format(m=m) if m == k + 1 else _("T{first}…T{m} are").format(first=k + 1, m=m)
            return Item(label, True, _("in a valid DH frame {k} that your {rows} written for (T{m} is charged in "
                                       "part 3, not this link)").format(k=k, rows=rows, m=m))
        return Item(label, False, _not_your_frame(k, j, names, P @ F[:3, :3].T + F[:3, 3], W))
    if not any(isinstance(row, Row) for row in analysis.rows):
        return Item(label, True, _("in a valid DH frame {k}").format(k=k))    # no transformations yet (a note says so)
    if _meant(ref, analysis, j, k, P, W):
        return Item(label, True, _("in a valid DH frame {k} that your {rows} from a frame {j} your rows are "
                                   "written for").format(k=k, rows=_rows_text(k, j + 1), j=j) if j < k else
                    _("in a valid DH frame {k} (T{k} is charged in part 3, not this link)").format(k=k))
    F = analysis.frames[k]
    return Item(label, False, _not_your_frame(k, j, names, P @ F[:3, :3].T + F[:3, 3], W))


def _meant(ref, analysis: Analysis, j: int, k: int, P, W) -> bool:
    """After the charged row T_j: whether some valid frame j that the student's next rows (up to the
    next charged one) are written for, carried by T_{j+1} … T_k, puts link k's points P on W."""
    rows = analysis.rows
    if _lands(P, analysis.frames[k], W):          # part 3's own reading of the frames the student meant
        return True
    M = np.eye(4)
    for row in rows[j:k]:                         # T_{j+1} … T_k at the home pose
        M = M @ matrix(row)
    carried = P @ M[:3, :3].T + M[:3, 3]          # the points in frame j
    for V in _drawn_in(ref, j, carried, W):
        if _pinned(ref, analysis, j, k, V):
            return True
    return False


def _pinned(ref, analysis: Analysis, j: int, k: int, V) -> bool:
    """Whether the rows after the charged T_j, up to the next charged one, fit on frame j = V."""
    rows = analysis.rows
    end = next((m for m in range(k + 1, ref.n + 1) if not analysis.items[m - 1].ok), ref.n + 1) - 1
    if j == k == end:                             # no row after T_k is written for frame k: nothing pins it,
        if k < ref.n or not isinstance(rows[k - 1], Row):
            return True
        xs = [(analysis.frames[k - 1] @ matrix(row))[:3, 0] for row in [rows[k - 1], *slips_of(rows[k - 1])]]
        return any(float(V[:3, 0] @ x) > math.cos(math.radians(TOL_DEG)) for x in xs)   # the last x:
        # as the student's T_n gives it (a slip in d, a or α leaves it), or as one slip less does
    F = V
    for m in range(j + 1, end + 1):               # every row up to the next charged one fits the frames
        if not fits(ref, m, F, rows[m - 1]):
            return False
        F = F @ matrix(rows[m - 1])
    return True


def _slid_back(ref, analysis: Analysis, k: int, P, W) -> int:
    """T_1 … T_k right, but a later row T_m charged: whether link k lies in a valid frame k that is the
    student's frame k slid (along parallel axes), or next to a sliding joint also turned, so that frames
    k … m−1 stay valid and T_m fits them. Then one slip in T_k (an offset d_k or a_k, a turn in θ_k)
    explains the chain as well as a wrong T_m, which part 3 charges where it first sees it: the links
    are not charged again. Returns m, or 0."""
    m = next((i for i in range(k + 1, ref.n + 1) if not analysis.items[i - 1].ok), None)
    if m is None or not isinstance(analysis.rows[m - 1], Row):
        return 0
    frames = analysis.frames
    slide = np.eye(4)                             # the translation the link's points ask for, or the motion
    slide[:3, 3] = (W - (P @ frames[k][:3, :3].T + frames[k][:3, 3])).mean(axis=0)      # to the valid frame
    moves = [slide]
    if any(frame_family(ref, i).loose for i in range(k, m)):    # next to a sliding joint x_k may turn too
        moves += [G @ np.linalg.inv(frames[k]) for G in _drawn_in(ref, k, P, W)]
    for move in moves:
        if (_lands(P, move @ frames[k], W) and all(is_valid_frame(ref, i, move @ frames[i]) for i in range(k, m))
                and fits(ref, m, move @ frames[m - 1], analysis.rows[m - 1])):
            return m
    return 0


def _drawn_in(ref, k: int, P, W) -> list:
    """The valid frames k that put P on W: the best fit, and when the points lie on one line (a link
    of two points), also that frame turned half a turn about the line (the points do not tell them apart)."""
    G, err = fit_link(ref, k, P, world=W)
    if err > TOL_POS:
        return []
    out = [G]
    spread = W - W.mean(axis=0)
    _u, sv, Vt = np.linalg.svd(spread)
    if len(W) > 1 and sv[0] > 1e-9 and (len(sv) < 2 or sv[1] < 1e-6):     # on one line, direction u
        u = Vt[0]
        turn = np.eye(4)
        turn[:3, :3] = 2 * np.outer(u, u) - np.eye(3)                      # half a turn about u
        turn[:3, 3] = W.mean(axis=0) - turn[:3, :3] @ W.mean(axis=0)
        if is_valid_frame(ref, k, turn @ G):
            out.append(turn @ G)
    return out


def _lands(P, F, W) -> bool:
    """Whether the points P, given in frame F, land on the world points W."""
    return float(np.linalg.norm(P @ F[:3, :3].T + F[:3, 3] - W, axis=1).max()) <= TOL_POS


def _not_your_frame(k: int, j: int, names, placed, W) -> str:
    """A link in a valid frame k that is not the frame the student's transformations give it."""
    miss = np.linalg.norm(placed - W, axis=1)
    p = int(np.argmax(miss))
    where = _("placed by them, point {point} lands at {at}, {miss} m from the robot's {point} at {robot}").format(
        point=names[p], at=point_text(placed[p]), miss=f"{miss[p]:.4f}", robot=point_text(W[p]))
    if j == 0:
        return _("drawn in a valid DH frame {k}, but not in the one your {rows}, so your assembled robot draws it "
                 "elsewhere: {where}; use the same frames in parts 2 and 3").format(
            k=k, rows=_rows_text(k), where=where)
    return _("drawn in a valid DH frame {k}, but not in the one your transformations give it (with T{j}, charged "
             "in part 3, read as you meant it, {where}); use the same frames in parts 2 and 3").format(
        k=k, j=j, where=where)


def _rows_text(k: int, first: int = 1) -> str:
    """Who builds frame k: 'T1 builds', 'T1…T3 build' (from T_first)."""
    return _("T{k} builds").format(k=k) if k == first else _("T{first}…T{k} build").format(first=first, k=k)


def _shape_problem(names, P, W) -> str:
    """A message if the points cannot be the link at all (distances between them differ)."""
    worst, pair = 0.0, None
    for a in range(len(P)):
        for b in range(a + 1, len(P)):
            diff = abs(np.linalg.norm(P[a] - P[b]) - np.linalg.norm(W[a] - W[b]))
            if diff > worst:
                worst, pair = diff, (a, b)
    if worst <= TOL_POS:
        return ""
    a, b = pair
    return _("these points are not the link's shape: {a}–{b} is {yours} m apart in your answer and {robot} m on "
             "the robot (a coordinate mixed up, or points out of order?)").format(
        a=names[a], b=names[b], yours=f"{np.linalg.norm(P[a] - P[b]):.4f}", robot=f"{np.linalg.norm(W[a] - W[b]):.4f}")


def _frame_problem(ref, k: int, names, P, W) -> str:
    """The link has the right shape but no valid DH frame k puts it there: say why."""
    n = ref.n
    if k == 0:
        return _("link 0 is given in frame 0, the world frame drawn in the figure: its points are the table's")
    G = _rigid_fit(P, W)
    if G is not None and np.linalg.norm(P @ G[:3, :3].T + G[:3, 3] - W, axis=1).max() > TOL_POS:
        return _("your coordinates are a mirror image of the link: is your frame right-handed "
                 "(dextrógiro, y{k} = z{k} × x{k})?").format(k=k)
    if G is not None:
        R, o = G[:3, :3], G[:3, 3]
        axis = ref.axes[k] if k < n else ref.axes[n - 1]
        local = R.T @ axis.direction
        which = int(np.argmax(np.abs(local)))
        joint = k + 1 if k < n else n
        if abs(local[2]) < math.cos(math.radians(TOL_DEG)):
            where = (_("along your local {axis} axis").format(axis="xyz"[which]) if abs(local[which]) > 0.999
                     else _("tilted from your z axis"))
            return _("in its own DH frame the axis of joint {joint} must be the z axis (z{k}: seed 000, figures "
                     "11–12); in your model it lies {where}").format(joint=joint, k=k, where=where)
        if k == n:
            miss = float(np.linalg.norm(o - ref.end_point))
            return _("frame {n}'s origin (the end effector's) is {end}; in your model the origin is {miss} m "
                     "from it").format(n=n, end=ref.end_text, miss=f"{miss:.4f}")
        off = axis.distance_to_point(o)
        if ref.kinds[k] == "R" and off > TOL_POS:
            return _("z{k} runs along the axis of joint {joint}, but your frame's origin is {off} m off that "
                     "axis; the origin of frame {k} lies on it").format(k=k, joint=k + 1, off=f"{off:.4f}")
        rel = relation(ref.axes[k - 1], ref.axes[k])
        if "P" in ref.kinds[k - 1:k + 1]:
            return _("your x{k} must be square to the axes of joints {k} and {next} and cross the line you chose "
                     "for z{previous} (a sliding joint's axis may be drawn on any line parallel to it, but x{k} "
                     "then follows it); in your model it does not").format(k=k, next=k + 1, previous=k - 1)
        return _("your x{k} must lie along the common normal of the axes of joints {k} and {next} ({kind}: x{k} ⟂ "
                 "both, crossing the axis of joint {k}); in your model it does not").format(
            k=k, next=k + 1, kind=case_word(rel.kind))
    C, _err = fit_link(ref, k, P)
    expected = (W - C[:3, 3]) @ C[:3, :3]
    j = int(np.argmax(np.linalg.norm(expected - P, axis=1)))
    return _("no valid DH frame {k} gives these coordinates; in the valid frame {k} nearest to your answer, point "
             "{point} would be at {expected}, yours is {yours}").format(
        k=k, point=names[j], expected=point_text(expected[j]), yours=point_text(P[j]))


def _rigid_fit(P, W):
    """The rigid motion G with G·P ≈ W (Kabsch), or None when P is (nearly) collinear."""
    Pc, Wc = P - P.mean(axis=0), W - W.mean(axis=0)
    if np.linalg.svd(Pc, compute_uv=False)[1] < 1e-6:
        return None
    U, _s, Vt = np.linalg.svd(Pc.T @ Wc)
    D = np.diag([1, 1, np.sign(np.linalg.det(Vt.T @ U.T))])
    R = Vt.T @ D @ U.T
    G = np.eye(4)
    G[:3, :3], G[:3, 3] = R, W.mean(axis=0) - R @ P.mean(axis=0)
    return G
