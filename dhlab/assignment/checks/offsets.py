"""Which offset d_k to name when x_i crosses z_{i−1} at the wrong height.

Along a run of parallel axes (the UR5's joints 2-3-4, the Cobra's vertical joints) the offsets
d_k add up: d_k moves frame k, and every frame after it, along z_{k−1}, which is the direction
of z_{i−1} too. A slip in any of them shows only at the end of the run, where x_i must cross
z_{i−1} at one height, and changing any one of them fixes it. So the message names:

* the one the student changed, when it can be told: every other offset of the run is the
  reference's (up to its sign: z may point either way) and this one is off by the miss;
* otherwise all of them, honestly ("d2, d3 or d4: along parallel axes these offsets add up"),
  never only one that may be right.
"""
from __future__ import annotations

import math

from ...i18n import _
from ..reference import TOL_DEG, TOL_POS

__all__ = ["parallel_run", "slipped", "advice"]


def _parallel(ref, j: int, k: int) -> bool:
    """Whether z_j and z_k (the axes of joints j+1 and k+1) are parallel."""
    return abs(float(ref.axes[j].direction @ ref.axes[k].direction)) > math.cos(math.radians(TOL_DEG))


def parallel_run(ref, i: int) -> list:
    """The offsets that move x_i along z_{i−1}: [i, i−1, …] while z_{k−1} ∥ z_k ∥ … ∥ z_{i−1}."""
    run, k = [i], i - 1
    while k >= 1 and _parallel(ref, k - 1, k):
        run.append(k)
        k -= 1
    return run


def _d(row) -> float | None:
    const = getattr(getattr(row, "d", None), "const", None)
    return None if const is None else float(const)


def slipped(ref, rows, run: list, miss: float) -> int | None:
    """The k of the run whose d_k alone differs from the reference's by |miss|, the others being the
    reference's (up to sign); None when that cannot be told."""
    table = getattr(ref, "rows", None)
    if not rows or table is None or len(rows) < max(run):
        return None
    found = []
    for k in run:
        mine, theirs = _d(rows[k - 1]), abs(float(table[k - 1][3]))
        if mine is None:
            return None
        off = abs(abs(mine) - theirs)
        if off <= TOL_POS:
            continue
        if abs(off - abs(miss)) > TOL_POS:
            return None                       # an offset changed by another amount: frames of the student's own
        found.append(k)
    return found[0] if len(found) == 1 else None


def advice(ref, i: int, row, rows, miss: float) -> str:
    """What to check when frame i is |miss| metres off along z_{i−1} (see the module)."""
    run = parallel_run(ref, i)
    if len(run) == 1:
        return _("check d{i} (yours: {d})").format(i=i, d=row.d.text())
    k = slipped(ref, rows, run, miss)
    if k is not None:
        yours = rows[k - 1].d.text()
        return _("check d{k} (yours: {yours}): along the parallel axes z{first}…z{last} the offsets {names} add up, "
                 "and d{k} is the one that differs from the robot's table").format(
            k=k, yours=yours, first=min(run) - 1, last=i - 1, names=_names(run))
    if rows and len(rows) >= i:
        yours = ", ".join(f"d{k} = {rows[k - 1].d.text()}" for k in sorted(run) if _d(rows[k - 1]) is not None)
    else:
        yours = f"d{i} = {row.d.text()}"
    return _("check {names} (yours: {yours}): along the parallel axes z{first}…z{last} these offsets add up, so a "
             "slip in any one of them moves x{i} by that much").format(
        names=_names(run), yours=yours, first=min(run) - 1, last=i - 1, i=i)


def _names(run: list) -> str:
    names = [f"d{k}" for k in sorted(run)]
    return names[0] if len(names) == 1 else _("{some} or {last}").format(some=", ".join(names[:-1]), last=names[-1])
