"""Assignment variants: a personal robot for every student, and the signature that binds it.

A **variant** is a robot of the family (:mod:`dhlab.assignment.family`) with changes drawn
deterministically from a seed: its DH lengths scaled and rounded to sensible values,
its pictured home pose and the drawn positive sense of some joints changed, and its
base placed differently (on the floor or hanging from the ceiling, the world frame
turned about joint 1 and at another height). Every variant is a physically sensible
arm — at home every link is on the robot's side of its mounting plate — whose DH
table cannot be looked up: working it out from the drawn axes is the exercise.

A variant is a small JSON-able dict (:meth:`Variant.to_dict`, :meth:`Variant.from_dict`,
exact both ways). The teacher's secret signs it for one student (:func:`sign_record`, HMAC-SHA256
over a canonical JSON of the variant and the student id) and :func:`verify` says whether
a notebook's record is that student's: ``ok``, ``missing``, ``tampered`` or
``other_student``.

>>> v = variant("kr5", "seed 1")
>>> v == variant("kr5", "seed 1"), v == variant("kr5", "seed 2")
(True, False)
>>> Variant.from_dict(v.to_dict()) == v
True
>>> record = sign_record(v, "ana", b"a teacher's secret, 16+ bytes")
>>> verify(record, "ana", b"a teacher's secret, 16+ bytes").status
'ok'
>>> verify(record, "bruno", b"a teacher's secret, 16+ bytes").status
'other_student'
"""
from __future__ import annotations

import functools
import hashlib
import hmac
import json
import math
import secrets as _secrets
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..errors import DHLabError
from ..i18n import _
from .family import FAMILY, VARIANT_TAG, family_names, shown_name
from .family import spec as family_spec
from .model import AssignmentRobot, build

__all__ = ["Variant", "variant", "table_digest", "student_variant", "roster_variants", "robot_of_variant", "shown_name",
           "fingerprint",
           "canonical_json", "sign_record", "verify", "Verification", "STATUSES", "SCHEME", "METADATA_KEY",
           "load_secret", "new_secret", "MIN_SECRET_BYTES"]

FORMAT = 1
SCHEME = "HMAC-SHA256/dhlab-variant-v1"
METADATA_KEY = "dhlab"                     # notebook.metadata[METADATA_KEY] holds the signed record
STATUSES = ("ok", "missing", "tampered", "other_student")
MIN_SECRET_BYTES = 16

SCALES = (0.8, 0.85, 0.9, 0.95, 1.05, 1.1, 1.15, 1.2)      # the whole arm, never 1
TURNS = (0, 0, 90, -90)                                   # a joint's change of home pose, degrees
YAWS = (0, 90, 180, 270)                                  # the world x0 turned about joint 1
TABLES = (0.0, 0.25, 0.5)                                 # a floor robot on a pedestal this high
CEILINGS = (1.6, 1.8, 2.0)                                # a hanging robot's plate above the world floor
CLEARANCE = 0.02                                          # metres between the plate and any link at home


# --- a deterministic draw, the same on every machine and version ---------------------------------

class _Draw:
    """Numbers drawn from SHA-256 of a seed and a counter (not numpy's generators, whose
    streams may change between versions: a variant must be the same next year)."""

    def __init__(self, seed: str):
        self.seed, self.count = seed.encode("utf-8"), 0

    def uniform(self) -> float:
        self.count += 1
        digest = hashlib.sha256(self.seed + b"|" + str(self.count).encode()).digest()
        return int.from_bytes(digest[:7], "big") / 2 ** 56

    def choice(self, options):
        return options[min(int(self.uniform() * len(options)), len(options) - 1)]


def _round_length(value: float) -> float:
    """To 5 mm from 10 cm up, to 1 mm below; never below 1 cm (a zero stays zero)."""
    if value == 0:
        return 0.0
    step = 0.005 if abs(value) >= 0.1 else 0.001
    out = round(round(value / step) * step, 4)
    return math.copysign(max(abs(out), 0.01), value)


# --- the variant ---------------------------------------------------------------------------------

@dataclass(frozen=True)
class Variant:
    """A robot of the family, changed (see the module). ``lengths``: every non-zero published DH
    length by name (``d1``, ``a2`` …, ``floor``: plate to frame 0) and ``stroke`` (the prismatic
    range's factor); ``home``: the pictured pose as published joint values (degrees, metres);
    ``senses``: +1/−1 per joint; ``base``: ``mount``, ``plate`` (metres), ``yaw`` (degrees)."""
    family: str
    lengths: tuple            # sorted (name, metres) pairs
    home: tuple
    senses: tuple
    base: tuple               # sorted (key, value) pairs

    def to_dict(self) -> dict:
        return _normal({"v": FORMAT, "family": self.family, "table": table_digest(self.family),
                        "lengths": dict(self.lengths), "home": list(self.home), "senses": list(self.senses),
                        "base": dict(self.base)})

    @classmethod
    def from_dict(cls, data) -> Variant:
        """The variant a dict describes, checked: every problem is a clear DHLabError."""
        return _read_variant(data)

    def robot(self) -> AssignmentRobot:
        return robot_of_variant(self)

    @property
    def name(self) -> str:
        """The robot's name with a short tag of its geometry, e.g. 'KUKA KR5 · variant 3fa2c1'."""
        return robot_of_variant(self).name


def table_digest(family: str) -> str:
    """A short hash of everything about robot ``family`` that a variant does not store (its
    published angles, kinds, limits, pictured pose): a variant made with one table is never
    read with another (after a correction to the family, re-release)."""
    s = family_spec(family)
    data = [s.key, [list(r) for r in s.rows], [list(q) for q in s.qlim], list(s.home), s.floor, list(s.mounts)]
    return hashlib.sha256(canonical_json(data).encode()).hexdigest()[:12]


def canonical_json(data) -> str:
    """The one text of a JSON-able value: sorted keys, no spaces, ASCII, and whole numbers
    without a decimal point (what is signed). JupyterLab saves a notebook's metadata through
    JavaScript, which writes 0.0 as 0: both must sign alike.

    >>> canonical_json({"b": [1.0, -0.0, 0.25], "a": "x"})
    '{"a":"x","b":[1,0,0.25]}'
    """
    return json.dumps(_normal(data), sort_keys=True, separators=(",", ":"), ensure_ascii=True, allow_nan=False)


def _normal(value):
    """Whole-number floats as ints (recursively), so JSON from Python and from JavaScript agree."""
    if isinstance(value, float) and value.is_integer():
        return int(value)
    if isinstance(value, dict):
        return {k: _normal(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_normal(v) for v in value]
    return value


def variant(family: str, seed) -> Variant:
    """The variant of robot ``family`` drawn from ``seed`` (any text or number): the same seed
    always gives the same variant. It differs from the published robot in at least one length."""
    s = family_spec(family)
    draw = _Draw(f"{family}|{seed}")
    for _attempt in range(200):
        v = _draw_once(s, draw)
        if _sensible(v):
            return v
    raise DHLabError(f"could not draw a sensible variant of {family!r} from seed {seed!r} (200 tries).")


def _draw_once(s, draw: _Draw) -> Variant:
    scale = draw.choice(SCALES)
    lengths = {}
    for j, (_kind, _theta, d, a, _alpha) in enumerate(s.rows, start=1):
        for name, value in ((f"d{j}", d), (f"a{j}", a)):
            if value:
                lengths[name] = _round_length(value * scale * (0.9 + 0.2 * draw.uniform()))
    if s.floor:
        lengths["floor"] = _round_length(s.floor * scale * (0.9 + 0.2 * draw.uniform()))
    if "P" in s.kinds:
        lengths["stroke"] = round(scale, 2)
    home = []
    for j, kind in enumerate(s.kinds):
        lo, hi = s.qlim[j]
        if kind == "P":
            lo, hi = lo * scale, hi * scale
            home.append(round(round((lo + draw.choice((0.25, 0.5, 0.75)) * (hi - lo)) / 0.005) * 0.005, 4))
            continue
        turn = 0 if j == 0 else draw.choice(TURNS)
        value = s.home[j] + turn
        home.append(value if lo <= value <= hi else s.home[j])
    senses = [-1 if draw.uniform() < 0.35 else 1 for _kind in s.kinds]
    mount = "ceiling" if draw.uniform() < 0.25 and "ceiling" in s.mounts else "floor"
    shoulder = -(lengths.get("floor", 0.0) + lengths.get("d1", 0.0))
    if mount == "floor":
        plate = draw.choice(TABLES + (round(shoulder, 4),))
    else:
        plate = draw.choice(CEILINGS + (round(-shoulder, 4), 0.0))
    base = {"mount": mount, "plate": float(plate) + 0.0, "yaw": draw.choice(YAWS)}
    return Variant(s.key, tuple(sorted(lengths.items())), tuple(home), tuple(senses), tuple(sorted(base.items())))


def _sensible(v: Variant) -> bool:
    """At home, every link on the robot's side of its plate; not the published robot."""
    s = family_spec(v.family)
    published = {f"{n}{j}": val for j, (_kind, _theta, d, a, _alpha) in enumerate(s.rows, 1)
                 for n, val in (("d", d), ("a", a))}
    published["floor"] = s.floor
    if all(published.get(k) == val for k, val in v.lengths if k != "stroke"):
        return False
    robot = robot_of_variant(v)
    z = np.vstack([robot.world_points(k) for k in range(1, robot.n + 1)])[:, 2]
    plate = robot.mount["plate"]
    if robot.mount["mount"] == "floor":
        return bool(z.min() >= plate + CLEARANCE)
    above_floor = z.min() >= CLEARANCE if plate in CEILINGS else True     # the room's floor at z = 0
    return bool(z.max() <= plate - CLEARANCE and above_floor)


@functools.lru_cache(maxsize=512)
def robot_of_variant(v: Variant) -> AssignmentRobot:
    """The assignment robot of variant ``v`` (its axes, points, reference solution), named
    with a short tag of its geometry. Cached: treat it as read-only."""
    robot = build(v.family, lengths=dict(v.lengths), home=list(v.home), senses=list(v.senses), base=dict(v.base))
    robot.name = f"{family_spec(v.family).name}{VARIANT_TAG}{fingerprint(robot)[:6]}"
    return robot


def fingerprint(v) -> str:
    """A hash of what the student is given and graded on — the drawn axes (lines with their
    senses), the joint kinds and the end point at home, rounded to 0.1 mm: two variants with
    different fingerprints are different assignments (a swapped one does not pass)."""
    robot = v if isinstance(v, AssignmentRobot) else robot_of_variant(v)
    parts = [robot.kinds]
    for axis in robot.axes:
        foot = axis.nearest_point(np.zeros(3))
        parts.append([_r(x) for x in (*foot, *axis.direction)])
    parts.append([_r(x) for x in robot.end_point])
    return hashlib.sha256(canonical_json(parts).encode()).hexdigest()


def _r(x: float) -> float:
    return round(float(x), 4) + 0.0


# --- reading a variant back: strict, with clear errors -------------------------------------------

def _read_variant(data) -> Variant:
    if not isinstance(data, dict):
        raise DHLabError(f"a variant is a dict (from Variant.to_dict()), got {type(data).__name__}.")
    expected = {"v", "family", "table", "lengths", "home", "senses", "base"}
    if set(data) != expected:
        raise DHLabError(f"a variant has exactly the keys {sorted(expected)}, got {sorted(data)}.")
    if data["v"] != FORMAT:
        raise DHLabError(f"variant format {data['v']!r} is not known (this dhlab reads format {FORMAT}).")
    family = data["family"]
    if family not in FAMILY:
        raise DHLabError(f"variant family {family!r} is not one of {', '.join(family_names())}.")
    s = FAMILY[family]
    if data["table"] != table_digest(family):
        raise DHLabError(f"this variant was made from another version of the {s.name}'s table (digest "
                         f"{data['table']!r}, this dhlab has {table_digest(family)!r}): grade it with the dhlab "
                         "version that released it, or release again.")
    lengths = data["lengths"]
    allowed = {f"{n}{j}" for j, (_kind, _theta, d, a, _alpha) in enumerate(s.rows, 1)
               for n, val in (("d", d), ("a", a)) if val}
    allowed |= {"floor"} if s.floor else set()
    allowed |= {"stroke"} if "P" in s.kinds else set()
    if not isinstance(lengths, dict) or set(lengths) != allowed:
        raise DHLabError(f"variant lengths of {family!r} must name {sorted(allowed)}, got {_keys(lengths)}.")
    for name, value in lengths.items():
        if not _finite(value) or abs(value) > 10 or (name in ("floor", "stroke") and value <= 0):
            raise DHLabError(f"variant length {name} = {value!r} is not a sensible length in metres.")
    home, senses = data["home"], data["senses"]
    if not isinstance(home, list) or len(home) != s.n or not all(_finite(h) for h in home):
        raise DHLabError(f"variant home must list {s.n} joint values (degrees or metres), got {home!r}.")
    if not isinstance(senses, list) or len(senses) != s.n or any(x not in (1, -1) or isinstance(x, bool)
                                                                 for x in senses):
        raise DHLabError(f"variant senses must list {s.n} values, each 1 or -1, got {senses!r}.")
    base = data["base"]
    if not isinstance(base, dict) or set(base) != {"mount", "plate", "yaw"} \
            or base["mount"] not in ("floor", "ceiling") or not _finite(base["plate"]) \
            or base["yaw"] not in YAWS or isinstance(base["yaw"], bool):
        raise DHLabError("variant base must be {'mount': 'floor' or 'ceiling', 'plate': metres, "
                         f"'yaw': one of {YAWS}}}, got {base!r}.")
    if base["mount"] not in s.mounts:
        raise DHLabError(f"the {s.name} is mounted on the {' or '.join(s.mounts)} only, not the {base['mount']}.")
    return Variant(family, tuple(sorted(lengths.items())), tuple(home), tuple(senses), tuple(sorted(base.items())))


def _finite(x) -> bool:
    return isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x)


def _keys(x):
    return sorted(x) if isinstance(x, dict) else repr(x)


# --- one variant per student ----------------------------------------------------------------------

def _read_families(families) -> list:
    if families is None:
        return ["puma560"]
    if isinstance(families, str):
        families = [f.strip() for f in families.split(",") if f.strip()]
    families = list(families)
    if families == ["all"]:
        return family_names()
    for f in families:
        family_spec(f)                                   # a clear error for an unknown name
    if not families:
        raise DHLabError("give at least one robot family (e.g. 'puma560', 'kr5,ur5' or 'all').")
    return families


def student_variant(student_id: str, secret: bytes, families=None, attempt: int = 0) -> Variant:
    """The variant of ``student_id``: its seed is an HMAC of the id with the teacher's secret,
    so nobody without the secret can tell which variant a student gets. ``families``: a list
    of family keys, a comma-separated text, or "all" (default: the PUMA 560)."""
    families = _read_families(families)
    seed = hmac.new(_secret_bytes(secret), f"dhlab-variant-seed|{student_id}|{attempt}".encode(),
                    hashlib.sha256).hexdigest()
    family = families[int(seed[:8], 16) % len(families)]
    return variant(family, seed)


def roster_variants(student_ids, secret: bytes, families=None) -> dict:
    """One variant per student id, in roster order, every one a different assignment (a draw
    that repeats an earlier student's robot is drawn again). Deterministic: the same roster
    and secret always give the same variants."""
    seen, out = set(), {}
    for sid in student_ids:
        for attempt in range(50):
            v = student_variant(sid, secret, families, attempt)
            key = fingerprint(v)
            if key not in seen:
                break
        else:
            raise DHLabError(f"could not draw a variant for {sid!r} different from every classmate's.")
        seen.add(key)
        out[sid] = v
    return out


# --- signing --------------------------------------------------------------------------------------

def _secret_bytes(secret) -> bytes:
    if isinstance(secret, str):
        secret = secret.encode("utf-8")
    if not isinstance(secret, (bytes, bytearray)) or len(secret) < MIN_SECRET_BYTES:
        raise DHLabError(f"the teacher's secret must be at least {MIN_SECRET_BYTES} bytes "
                         "(make one with dhlab.assignment.variants.new_secret()).")
    return bytes(secret)


def _mac(variant_dict: dict, student_id: str, secret: bytes) -> str:
    message = canonical_json({"scheme": SCHEME, "student_id": student_id, "variant": variant_dict})
    return hmac.new(_secret_bytes(secret), message.encode("ascii"), hashlib.sha256).hexdigest()


def sign_record(v: Variant, student_id: str, secret: bytes) -> dict:
    """The record kept in the student's notebook metadata: the variant, the student id and
    the HMAC-SHA256 signature of both with the teacher's secret."""
    if not isinstance(student_id, str) or not student_id:
        raise DHLabError(f"the student id must be non-empty text, got {student_id!r}.")
    data = v.to_dict()
    return {"scheme": SCHEME, "student_id": student_id, "variant": data,
            "signature": _mac(data, student_id, secret)}


@dataclass(frozen=True)
class Verification:
    """What :func:`verify` found: ``status`` (one of :data:`STATUSES`), a sentence for the
    gradebook, the variant when it can be trusted, and whose it is."""
    status: str
    message: str
    variant: Variant | None = None
    signed_for: str | None = None

    @property
    def ok(self) -> bool:
        return self.status == "ok"


def verify(record, student_id: str, secret: bytes, roster_ids=()) -> Verification:
    """Is ``record`` (a notebook's metadata record, see :func:`sign_record`) the variant signed for
    ``student_id``?

    * ``ok``: signed for this student with this secret;
    * ``missing``: no record, or no variant or signature in it;
    * ``other_student``: a genuine record, signed for someone else (the id it names, or a
      roster id in ``roster_ids``) — a classmate's notebook handed in;
    * ``tampered``: the signature fits no student: the variant, the id or the signature
      was changed, or it was signed with another secret.
    """
    if not isinstance(record, dict) or not record.get("variant") or not record.get("signature"):
        return Verification("missing", _("no signed variant in the notebook's metadata"))
    data, signature = record["variant"], record["signature"]
    if not isinstance(signature, str) or not isinstance(data, dict):
        return Verification("tampered", _("the variant record is malformed"))
    try:
        mine = _mac(data, student_id, secret)
    except (TypeError, ValueError):
        return Verification("tampered", _("the variant cannot be read as JSON"))
    if hmac.compare_digest(mine, signature):
        try:
            return Verification("ok", _("signed variant"), Variant.from_dict(data), student_id)
        except DHLabError as exc:                         # signed by us, unreadable here: a newer format
            return Verification("tampered", _("signed, but not readable by this dhlab: {error}").format(error=exc))
    claimed = record.get("student_id")
    others = ([claimed] if isinstance(claimed, str) and claimed != student_id else []) + \
        [r for r in roster_ids if r != student_id and r != claimed]
    for other in others:
        if hmac.compare_digest(_mac(data, other, secret), signature):
            why = _("this is the variant signed for {other!r}, not for {student!r}").format(
                other=other, student=student_id)
            return Verification("other_student", why, None, other)
    return Verification("tampered", _("the signature does not match: the variant or the id was changed, "
                                      "or it was signed with another secret"))


def new_secret() -> bytes:
    """A fresh random secret (32 bytes, as hex text) for :func:`sign_record`."""
    return _secrets.token_hex(32).encode("ascii")


def load_secret(path) -> bytes:
    """The teacher's secret from a file (surrounding whitespace ignored), with clear errors."""
    path = Path(path)
    try:
        secret = path.read_bytes().strip()
    except OSError as exc:
        raise DHLabError(_("cannot read the secret file {path!r}: {why}.").format(
            path=str(path), why=exc.strerror)) from None
    if len(secret) < MIN_SECRET_BYTES:
        raise DHLabError(_("the secret file {path!r} holds {count} bytes: at least {needed} are needed (a long "
                           "random text).").format(path=str(path), count=len(secret), needed=MIN_SECRET_BYTES))
    return secret
