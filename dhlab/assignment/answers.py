"""What a submission's answers are, as plain data, and how they are read.

The answer cells of the assignment notebook assign well-known names
(:data:`~dhlab.assignment.encode.ANSWER_NAMES`): ``T1`` … ``Tn`` for a robot of n joints
(the PUMA 560 has six; a student's variant, :mod:`dhlab.assignment.variants`, may have four).
The readers that depend on n take it as a parameter (:func:`parse_answers`), so a message
names the right ``Tn``. After a submission has run, the grader's runner asks the student's
kernel to write the values of those names as JSON (:mod:`dhlab.assignment.encode`, whose
source is sent into the kernel), and :func:`parse_answers` reads that JSON back in the
grader's own process into an :class:`Answers` record. The notebook's own immediate feedback
goes through the same functions (:func:`answers_from_namespace`), so the notebook and the
grader see the same data.

Nothing here runs student code or evaluates text: a JSON value is either read
as the expected kind of data or reported as unreadable.

>>> raw = {"n_links": 7, "n_joints": 6, "joint_types": "RRRRRR", "x_cases": "..."}
>>> a = parse_answers(raw)
>>> a.n_links, a.joint_types, a.x_cases is NOT_ANSWERED, a.chain is NOT_ANSWERED
(7, ['R', 'R', 'R', 'R', 'R', 'R'], True, True)
"""
from __future__ import annotations

import json
import math
import re
from dataclasses import dataclass, field

from ..course.checks.case_words import read_case_words
from ..i18n import _, case_word
from ..validation import decimal_comma_note
from .encode import ANSWER_NAMES, MAX_JOINTS, MAX_JSON_BYTES, encode_json, to_plain

__all__ = ["ANSWER_NAMES", "N_JOINTS", "MAX_JOINTS", "MAX_NUMBER", "NOT_ANSWERED", "Unreadable", "Case",
           "written_case", "Answers", "Row",
           "Term", "parse_answers", "parse_json", "answers_from_namespace", "MAX_JSON_BYTES"]

N_JOINTS = 6              # the PUMA 560's: the default when the robot is not said
MAX_NUMBER = 1e6          # metres or degrees: anything bigger is a slip, and would overflow the checks


class _NotAnswered:
    """The marker of an answer left as ``...`` or missing."""

    def __repr__(self):
        return "NOT_ANSWERED"

    def __bool__(self):
        return False


NOT_ANSWERED = _NotAnswered()


class Case(str):
    """One entry of x_cases as read: equal to its case ('intersect', 'parallel', 'skew', 'coincident'),
    and remembering the words the student wrote (:attr:`written`), which the feedback quotes back.

    >>> case = Case("intersect", "se intersecan")
    >>> case == "intersect", case.written
    (True, 'se intersecan')
    """
    written: str

    def __new__(cls, case: str, written: str):
        obj = super().__new__(cls, case)
        obj.written = written
        return obj


def written_case(case) -> str:
    """What the student wrote for ``case`` (a :class:`Case`), else the case itself."""
    return getattr(case, "written", case)


@dataclass(frozen=True)
class Unreadable:
    """An answer that is there but is not the expected kind of data (``why`` says so)."""
    why: str

    def __bool__(self):
        return False


@dataclass(frozen=True)
class Term:
    """A length or an angle: ``const`` plus ``sign``·q_``joint`` (joint None: a constant).

    Angles are in degrees, lengths in metres, as the student typed them.
    """
    const: float
    joint: int | None = None
    sign: int = 1

    def text(self, unit: str = "") -> str:
        """'q3 - 90°', '-q2', '0.15005' — as a student would write it."""
        c = f"{_g(self.const)}{unit}"
        if self.joint is None:
            return c
        var = ("-" if self.sign < 0 else "") + f"q{self.joint}"
        if self.const == 0:
            return var
        return f"{var} {'-' if self.const < 0 else '+'} {_g(abs(self.const))}{unit}"


def _g(x: float) -> str:
    return f"{x:.6g}"


@dataclass(frozen=True)
class Row:
    """One transformation ``T_i = Tz[θ_i, d_i] · Tx[α_i, a_i]`` (degrees, metres)."""
    theta: Term
    d: Term
    alpha: float
    a: float

    def text(self) -> str:
        return (f"Tz[{self.theta.text('°')}, {self.d.text()}]·"
                f"Tx[{_g(self.alpha)}°, {_g(self.a)}]")

    @property
    def joint(self):
        """(joint number, sign, where): the joint variable and whether it is in θ or d."""
        if self.theta.joint is not None:
            return self.theta.joint, self.theta.sign, "theta"
        if self.d.joint is not None:
            return self.d.joint, self.d.sign, "d"
        return None, 1, None


@dataclass
class Answers:
    """A submission's answers; each is a value, ``NOT_ANSWERED`` or an :class:`Unreadable`."""
    n_links: object = NOT_ANSWERED
    n_joints: object = NOT_ANSWERED
    joint_types: object = NOT_ANSWERED         # list of 'R'/'P'
    x_cases: object = NOT_ANSWERED             # list of 'intersect'/'parallel'/'skew', None or Unreadable per entry
    link_points: object = NOT_ANSWERED         # list over links 0…n: list of (x, y, z) or a marker
    T: list = field(default_factory=lambda: [NOT_ANSWERED] * N_JOINTS)   # Row per T_i or a marker
    chain: object = NOT_ANSWERED               # list of Row

    def items(self) -> list:
        """(name, value) of every answer, T1…Tn by name."""
        out = [(name, getattr(self, name)) for name in ("n_links", "n_joints", "joint_types", "x_cases",
                                                         "link_points")]
        out += [(f"T{i}", value) for i, value in enumerate(self.T, start=1)]
        return out + [("chain", self.chain)]

    def answered(self) -> bool:
        values = [self.n_links, self.n_joints, self.joint_types, self.x_cases, self.link_points,
                  *self.T, self.chain]
        return any(v is not NOT_ANSWERED for v in values)


def answers_from_namespace(namespace, n: int = N_JOINTS) -> Answers:
    """The answers in a namespace (the notebook's globals), read exactly as the grader reads
    them: :func:`to_plain`, then :func:`encode_json`, then :func:`parse_json` (for a robot
    of ``n`` joints)."""
    raw = {}
    for name in ANSWER_NAMES:
        if name in namespace:
            try:
                raw[name] = to_plain(namespace[name])
            except BaseException as e:          # the same as the runner's writer
                raw[name] = {"__type__": "unreadable", "repr": (type(e).__name__ + ": " + str(e))[:200]}
    return parse_json(encode_json(raw), n)


# --- JSON -> Answers ----------------------------------------------------

def parse_json(text: str, n: int = N_JOINTS) -> Answers:
    """:func:`parse_answers` of a JSON text, refusing texts that are too big or not JSON."""
    if len(text) > MAX_JSON_BYTES:
        raise ValueError(_("the answers are {size} bytes of JSON, more than {limit}").format(
            size=len(text), limit=MAX_JSON_BYTES))
    try:
        raw = json.loads(text)
    except (ValueError, RecursionError) as e:
        raise ValueError(_("the answers are not valid JSON ({error})").format(error=str(e)[:80])) from None
    if not isinstance(raw, dict):
        raise ValueError(_("the answers are not a JSON object"))
    return parse_answers(raw, n)


def parse_answers(raw: dict, n: int = N_JOINTS) -> Answers:
    """Read each answer from plain data, for a robot of ``n`` joints (T1 … Tn, and any
    T_i beyond that the notebook defines); what cannot be read becomes :class:`Unreadable`."""
    if isinstance(n, bool) or not isinstance(n, int) or not 1 <= n <= MAX_JOINTS:
        raise ValueError(f"a robot of the assignment has 1 to {MAX_JOINTS} joints, not {n!r}")
    out = Answers()
    readers = {"n_links": _count, "n_joints": _count, "joint_types": _joint_types,
               "x_cases": lambda v: _x_cases(v, n), "link_points": lambda v: _link_points(v, n),
               "chain": lambda v: _chain(v, n)}
    for name, reader in readers.items():
        setattr(out, name, _read(raw, name, reader))
    given = [i for i in range(1, MAX_JOINTS + 1) if raw.get(f"T{i}") is not None]
    out.T = [_read(raw, f"T{i}", _row) for i in range(1, max([n, *given]) + 1)]
    return out


def _read(raw, name, reader):
    if name not in raw or raw[name] is None:
        return NOT_ANSWERED
    value = raw[name]
    if _is_ellipsis_only(value):
        return NOT_ANSWERED
    try:
        return reader(value)
    except _Bad as e:
        return Unreadable(str(e))
    except (TypeError, ValueError, KeyError, IndexError, AttributeError, OverflowError, RecursionError):
        return Unreadable(_("cannot read {value}").format(value=_show(value)))


class _Bad(Exception):
    pass


def _is_ellipsis_only(value) -> bool:
    """True for ``...`` and for lists/dicts of nothing but ``...`` (a template left as is)."""
    if value is None:
        return True
    if isinstance(value, str):
        return value.strip() in ("", "...", "…")
    if isinstance(value, list):
        return all(_is_ellipsis_only(v) for v in value)
    items = _dict_items(value)
    if items is not None:
        return all(_is_ellipsis_only(v) for _key, v in items)
    return False


def _dict_items(value):
    """The (key, value) pairs of a dict as :func:`to_plain` wrote it, or None if not a dict."""
    if not isinstance(value, dict) or "__type__" in value or "__dhlab__" in value:
        return None
    if "__dict__" in value:
        pairs = value["__dict__"]
        if not isinstance(pairs, list) or not all(isinstance(p, list) and len(p) == 2 for p in pairs):
            raise _Bad("unreadable dict")
        return [tuple(p) for p in pairs]
    return list(value.items())


def _show(value) -> str:
    if isinstance(value, dict) and value.get("__type__") == "too big":
        return f"too much data ({value.get('repr', '')})"
    if isinstance(value, dict) and "__type__" in value:
        text = re.sub(r" at 0x[0-9a-fA-F]+", "", str(value.get("repr", "")))
        return f"a {value['__type__']} ({text})"[:120]
    if isinstance(value, dict) and "__dhlab__" in value:
        return f"a dhlab {value['__dhlab__']}"
    text = json.dumps(value)
    return text if len(text) <= 80 else text[:77] + "..."


def _with_note(message: str, note: str) -> str:
    """``message`` and, when there is one, the decimal-comma ``note`` after it."""
    return f"{message}. {note}" if note else message


def _number(value, what: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise _Bad(_with_note(_("{what} must be a number, got {value}").format(what=what, value=_show(value)),
                              decimal_comma_note(value)))
    number = float(value)
    if not math.isfinite(number):
        raise _Bad(_("{what} must be a finite number, got {value}").format(what=what, value=value))
    if abs(number) > MAX_NUMBER:
        raise _Bad(_("{what} is {number}: no length (metres) or angle (degrees) of this robot is that big").format(
            what=what, number=f"{number:g}"))
    return number


def _count(value) -> int:
    if isinstance(value, str) and re.fullmatch(r"\s*\d+\s*", value):
        value = int(value)
    number = _number(value, _("a count"))
    if number != int(number) or number < 0:
        raise _Bad(_("must be a whole number, got {value}").format(value=_show(value)))
    return int(number)


_TYPE_WORDS = {"r": "R", "revolute": "R", "rotational": "R", "rotary": "R", "rotacional": "R",
               "rotación": "R", "rotacion": "R", "revoluta": "R",
               "p": "P", "prismatic": "P", "prismática": "P", "prismatica": "P", "linear": "P"}


def _joint_types(value) -> list:
    if isinstance(value, str):
        words = [w for w in re.split(r"[\s,;/·\-]+", value.strip()) if w]
        if len(words) == 1 and all(ch in "RrPp" for ch in words[0]):
            return [ch.upper() for ch in words[0]]
        value = words
    if not isinstance(value, list):
        raise _Bad(_("give one letter per joint, e.g. 'RRP', got {value}").format(value=_show(value)))
    out = []
    for item in value:
        if not isinstance(item, str) or item.strip().lower() not in _TYPE_WORDS:
            raise _Bad(_("{value} is not a joint type: use 'R' (revolute) or 'P' (prismatic)").format(
                value=_show(item)))
        out.append(_TYPE_WORDS[item.strip().lower()])
    return out


def _case(item):
    """One entry of x_cases: a case, None (not answered) or, when it cannot be read, an
    :class:`Unreadable` saying what was written: that entry's slip only, the others are scored.

    Words are read as the lesson's exercise reads them (:mod:`dhlab.course.checks.case_words`): English or
    Spanish, small slips of spelling accepted ('paralel', 'intersects'); a word that is no case gets
    a "did you mean"."""
    if _is_ellipsis_only(item):
        return None
    if isinstance(item, (int, float)) and not isinstance(item, bool):
        item = str(int(item)) if float(item).is_integer() else str(item)
    if not isinstance(item, str):
        return Unreadable(_("{value} is not a case: use 'intersect', 'parallel' or 'skew'").format(
            value=_show(item)))
    reading = read_case_words(item)
    if reading.case is not None:
        return Case(reading.case, item.strip())
    return Unreadable(_case_problem(item, reading))


def _case_problem(item: str, reading) -> str:
    """Why a word is not read as a case, with the accepted words (in the student's language)."""
    shown = repr(item.strip()[:40])
    if len(reading.named) > 1:
        return _("{value} names several cases ({cases}): write the one case that holds").format(
            value=shown, cases=", ".join(case_word(kind) for kind in reading.named))
    if reading.negated:
        return _("{value} says what does not hold: write the case that does, 'intersect', 'parallel' or "
                 "'skew'").format(value=shown)
    why = _("{value} is not a case: use 'intersect', 'parallel' or 'skew'").format(value=shown)
    if reading.suggestion:
        why += "; " + _("did you mean {word!r}?").format(word=reading.suggestion)
    return why


def _x_cases(value, n: int) -> list:
    items = _dict_items(value)
    if items is not None:                                       # {1: "intersect", ...}
        pairs = {}
        for k, v in items:
            digits = re.sub(r"\D", "", k) if isinstance(k, str) else k
            if digits == "" or isinstance(digits, bool) or not isinstance(digits, (int, str)):
                raise _Bad(_("the keys of x_cases must be the numbers i = 1…{last}, got {value}").format(
                    last=n - 1, value=_show(k)))
            pairs[_count(int(digits))] = v
        value = [pairs.get(i) for i in range(1, max(pairs) + 1)] if pairs else []
    if isinstance(value, str):
        value = [w for w in re.split(r"\s*[,;]\s*", value.strip()) if w]
    if not isinstance(value, list):
        raise _Bad(_("give a list with one case per i, got {value}").format(value=_show(value)))
    return [_case(item) for item in value]


def _point(value, where: str) -> tuple:
    if isinstance(value, list) and len(value) in (3, 4) and all(isinstance(v, list) and len(v) == 1 for v in value):
        value = [v[0] for v in value]                  # a column (3x1 array or sympy Matrix)
    if isinstance(value, list) and len(value) == 4 and value[3] in (1, 1.0):
        raise _Bad(_("{where} has 4 numbers; a point has 3: drop the trailing 1 of the homogeneous form").format(
            where=where))
    if not isinstance(value, list) or len(value) != 3:
        message = _("{where} must be a point (x, y, z), got {value}").format(where=where, value=_show(value))
        raise _Bad(_with_note(message,
                              decimal_comma_note(value, 3) if isinstance(value, (list, tuple)) else ""))
    return tuple(_number(v, where) for v in value)


def _link_points(value, n: int) -> list:
    """Links 0…n, each a list of points, from a list or a {link: points} dict (as many links
    as the answer names: a missing link is for the checks to say)."""
    items = _dict_items(value)
    if items is not None:
        pairs = {}
        for k, v in items:
            if isinstance(k, str) and re.fullmatch(r"\D*\d+\s*", k):      # 3, "3", "link3"
                k = int(re.sub(r"\D", "", k))
            if isinstance(k, bool) or not isinstance(k, int) or not 0 <= k <= 50:
                raise _Bad(_("the keys must be link numbers 0…{n}, got {value}").format(n=n, value=_show(k)))
            pairs[k] = v
        value = [pairs.get(k) for k in range(max(pairs) + 1)] if pairs else []
    if not isinstance(value, list):
        raise _Bad(_("give the points of links 0…{n}, got {value}").format(n=n, value=_show(value)))
    out = []
    for k, pts in enumerate(value):
        if _is_ellipsis_only(pts):
            out.append(NOT_ANSWERED)
            continue
        try:
            if not isinstance(pts, list):
                raise _Bad(_("link {k} must be a list of points (x, y, z), got {value}").format(k=k, value=_show(pts)))
            out.append([_point(p, _("link {k}, point {j}").format(k=k, j=j + 1)) for j, p in enumerate(pts)])
        except _Bad as e:
            out.append(Unreadable(str(e)))
    return out


def _dhlab(value, *names):
    """The class name of a dhlab object's plain data, if it is one of ``names``."""
    return isinstance(value, dict) and value.get("__dhlab__") in names


def _term(value, what: str) -> Term:
    if _dhlab(value, "JointTerm"):
        joint, sign = value.get("joint"), value.get("sign", 1)
        if isinstance(joint, bool) or not isinstance(joint, int) or not 1 <= joint <= 50:
            raise _Bad(_("{what}: joint variable q{joint} does not exist").format(what=what, joint=joint))
        if sign not in (1, -1):
            raise _Bad(_("{what}: the joint variable must appear as +q or -q").format(what=what))
        return Term(_number(value.get("const", 0), what), joint, int(sign))
    return Term(_number(value, what))


def _row(value) -> Row:
    if _dhlab(value, "ZFactor", "XFactor"):
        raise _Bad(_("it is a single factor: write T_i = Tz(θ, d) @ Tx(α, a)"))
    if not _dhlab(value, "DHTransform") or not _dhlab(value.get("z"), "ZFactor") \
            or not _dhlab(value.get("x"), "XFactor"):
        raise _Bad(_("write it as Tz(θ, d) @ Tx(α, a), got {value}").format(value=_show(value)))
    z, x = value["z"], value["x"]
    theta, d = _term(z.get("theta"), "θ"), _term(z.get("d"), "d")
    alpha, a = _term(x.get("alpha"), "α"), _term(x.get("a"), "a")
    if alpha.joint is not None or a.joint is not None:
        raise _Bad(_("α and a are constants: the joint variable goes in θ (or in d for a prismatic joint)"))
    return Row(theta, d, alpha.const, a.const)


def _chain(value, n: int) -> list:
    if _dhlab(value, "DHTransform"):
        return [_row(value)]
    if not _dhlab(value, "DHChain") or not isinstance(value.get("transforms"), list):
        raise _Bad(_("write it as {chain}, got {value}").format(chain=" @ ".join(f"T{i}" for i in range(1, n + 1)),
                                                             value=_show(value)))
    if not value["transforms"]:
        raise _Bad(_("the chain has no transformations"))
    return [_row(v) for v in value["transforms"]]
