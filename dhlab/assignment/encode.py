"""What crosses from the student's kernel to the grader: the answers' names and values as JSON.

After a submission has run, the grader's runner (:mod:`dhlab.grading.run.runner`) asks the
student's kernel to write the values of the answer names (:data:`ANSWER_NAMES`) as JSON
text, with :func:`to_plain` and :func:`encode_json`. It sends **the source text** of these
two functions into the kernel, so nothing the notebook did to ``dhlab`` (or to ``json``)
changes how its answers are written. That is why this module imports nothing, not even
from ``dhlab``: the runner also loads it as a plain file, without the package.

The grader reads the JSON back in its own process (:mod:`dhlab.assignment.answers`).

>>> encode_json(to_plain({"n_links": 7, "x_cases": ..., "T1": (1, 2.5)}))
'{"n_links":7,"x_cases":null,"T1":[1,2.5]}'
"""
from __future__ import annotations

__all__ = ["MAX_JOINTS", "ANSWER_NAMES", "MAX_JSON_BYTES", "to_plain", "encode_json"]

MAX_JOINTS = 12           # T1 … T12 are read; no robot of the course has more joints
ANSWER_NAMES = ("n_links", "n_joints", "joint_types", "x_cases", "link_points",
                *(f"T{i}" for i in range(1, MAX_JOINTS + 1)), "chain")
MAX_JSON_BYTES = 1_000_000


def to_plain(value, _depth=0, _budget=None):
    """A JSON-able copy of ``value``: numbers, strings, lists, dicts; ``...`` -> None.

    Self-contained on purpose (the runner sends its source into the kernel).
    Objects of ``dhlab`` (``Tz(...) @ Tx(...)``, ``q3 + 90``) become
    ``{"__dhlab__": class name, field: value, ...}``; anything else unknown becomes
    ``{"__type__": name, "repr": ...}``. Sizes are capped, so a huge or cyclic value
    cannot stall the grader.
    """
    if _budget is None:
        _budget = [5000]
    _budget[0] -= 1
    if _budget[0] < 0 or _depth > 8:
        return {"__type__": "too big", "repr": "(more than 5000 values or 8 levels deep)"}
    if value is None or value is Ellipsis:
        return None
    if isinstance(value, bool):
        return bool(value)
    # subclasses (numpy.float64, dhlab.deg2rad() values, str subclasses) become the plain type, so
    # that every numeric type a student may use is read the same way
    if isinstance(value, int):
        value = int(value)
        return value if abs(value) < 10 ** 15 else float(value)
    if isinstance(value, float):
        value = float(value)
        return value if value == value and abs(value) != float("inf") else {"__type__": "float", "repr": repr(value)}
    if isinstance(value, str):
        return str(value)[:300]
    kind = type(value)
    module = getattr(kind, "__module__", "") or ""
    if getattr(value, "is_Integer", False) is True and module.startswith("sympy"):
        return to_plain(int(value), _depth + 1, _budget)
    if module.startswith(("numpy", "sympy")) and hasattr(value, "tolist"):
        if getattr(value, "size", 1) > 2000:
            return {"__type__": "too big", "repr": "an array of %s values" % getattr(value, "size", "?")}
        return to_plain(value.tolist(), _depth + 1, _budget)
    if module.startswith("dhlab."):
        # dhlab's answer objects (Tz(...) @ Tx(...), chains, q_i + 90): their fields, read
        # directly; no method of the object is called, so patching dhlab changes nothing
        try:
            fields = dict(object.__getattribute__(value, "__dict__"))
        except Exception:
            fields = {}
        out = {"__dhlab__": kind.__name__[:40]}
        for key, item in list(fields.items())[:20]:
            if isinstance(key, str) and not key.startswith("_"):
                out[key[:40]] = to_plain(item, _depth + 1, _budget)
        return out
    if isinstance(value, (list, tuple)):
        if len(value) > 500:
            return {"__type__": "too big", "repr": "a list of %d items" % len(value)}
        return [to_plain(v, _depth + 1, _budget) for v in value]
    if isinstance(value, dict):
        if len(value) > 500:
            return {"__type__": "too big", "repr": "a dict of %d items" % len(value)}
        items = list(value.items())
        if all(isinstance(k, str) for k, _value in items) and not {"__dict__", "__type__", "__dhlab__"} & set(value):
            return {k[:100]: to_plain(v, _depth + 1, _budget) for k, v in items}
        return {"__dict__": [[to_plain(k, _depth + 1, _budget), to_plain(v, _depth + 1, _budget)]
                             for k, v in items]}
    if hasattr(value, "__float__") and not isinstance(value, (bytes, bytearray)):
        try:
            number = float(value)
            if number == number and abs(number) != float("inf"):
                return number
        except Exception:
            pass
    try:
        text = repr(value)[:120]
    except Exception:
        text = "?"
    return {"__type__": kind.__name__[:60], "repr": text}


def encode_json(value) -> str:
    """The JSON text of plain data, written by hand (self-contained, like :func:`to_plain`:
    the runner sends both into the student's kernel, where ``json`` may have been replaced).
    Anything that is not plain data becomes ``null``.

    >>> encode_json({"a": [1, 2.5, "x", None, True]})
    '{"a":[1,2.5,"x",null,true]}'
    """
    if value is None:
        return "null"
    if value is True or value is False:
        return "true" if value else "false"
    if type(value) is int:
        return str(value)
    if type(value) is float:
        return repr(value) if value == value and abs(value) != float("inf") else "null"
    if type(value) is str:
        out = []
        for ch in value:
            code = ord(ch)
            if 32 <= code < 127 and ch not in '"\\':
                out.append(ch)
            elif code < 0x10000:
                out.append("\\u%04x" % code)
            else:
                code -= 0x10000
                out.append("\\u%04x\\u%04x" % (0xD800 + (code >> 10), 0xDC00 + (code & 0x3FF)))
        return '"' + "".join(out) + '"'
    if type(value) is list:
        return "[" + ",".join(encode_json(v) for v in value) + "]"
    if type(value) is dict:
        return "{" + ",".join(encode_json(str(k)) + ":" + encode_json(v) for k, v in value.items()) + "}"
    return "null"
