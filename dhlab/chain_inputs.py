"""What a robot is given, checked: its links, the names of its joint variables, its parameters.

:class:`~dhlab.chain.Robot` (and :class:`~dhlab.dh.DHRobot`, :class:`~dhlab.mdh.MDHRobot`) turn
each argument into one plain, checked value here, or stop with a :class:`~dhlab.validation.DHLabError`
that says what was expected.

>>> joint_names(None, 2), joint_label("theta1"), numeric_params({"l1": 0.7})
(('q1', 'q2'), 'θ1', {'l1': 0.7})
"""
from __future__ import annotations

import numpy as np

from .errors import DHLabError
from .i18n import _
from .lazy_sympy import has_symbols, is_matrix, is_symbol
from .links import Link
from .validation import Angle, as_number, describe

__all__ = ["link_list", "joint_names", "one_value", "numeric_params", "joint_label", "SYMPY_CONSTANTS"]

SYMPY_CONSTANTS = {"pi": "π", "E": "Euler's number e", "I": "the imaginary unit", "oo": "infinity",
                   "zoo": "complex infinity", "nan": "not a number"}


def link_list(links, expected=None, what: str = "a Link (or RevoluteDH / PrismaticDH)") -> list:
    """The robot's links as a list of ``expected`` (default :class:`Link`), or a clear error."""
    if isinstance(links, (str, bytes, dict, Link)) or not hasattr(links, "__iter__"):
        raise DHLabError(_("a robot takes a list of links, e.g. [RevoluteDH(a=1), RevoluteDH(a=0.5)]; "
                           "got {got}.").format(got=describe(links)))
    try:
        links = list(links)
    except TypeError:            # iterable in name only, e.g. a 0-d numpy array
        raise DHLabError(_("a robot takes a list of links, e.g. [RevoluteDH(a=1), RevoluteDH(a=0.5)]; "
                           "got {got}.").format(got=describe(links))) from None
    if not links:
        raise DHLabError(_("a robot needs at least one link."))
    for i, link in enumerate(links, start=1):
        if not isinstance(link, expected or Link):
            raise DHLabError(_("link {i} must be {what}, got {got}.").format(i=i, what=what, got=describe(link)))
    return links


def joint_names(names, n: int) -> tuple:
    """The names of the joint variables (text or sympy symbols): default q1 … qn; names must be distinct."""
    if names is None:
        names = [f"q{i + 1}" for i in range(n)]
    if isinstance(names, (str, bytes, dict)) or not hasattr(names, "__iter__"):
        raise DHLabError(_("joint_symbols must be a list of {n} names, e.g. {example}; got {got}.").format(
            n=n, example=[f"q{i + 1}" for i in range(n)], got=describe(names)))
    try:
        names = list(names)
    except TypeError:            # iterable in name only, e.g. a 0-d numpy array
        raise DHLabError(_("joint_symbols must be a list of {n} names; got {got}.").format(
            n=n, got=describe(names))) from None
    if len(names) != n:
        raise DHLabError(_("joint_symbols must name {n} joints, got {count}: {got}.").format(
            n=n, count=len(names), got=describe(names)))
    text = []
    for k, s in enumerate(names):
        if is_symbol(s):
            s = s.name
        if not isinstance(s, str) or not s.isidentifier():
            raise DHLabError(_("joint_symbols[{k}] must be a name such as 'q{k1}' or 'theta{k1}', got {got}.").format(
                k=k, k1=k + 1, got=describe(s)))
        if s in SYMPY_CONSTANTS:        # it would print, and be read back, as the constant
            raise DHLabError(_("joint_symbols[{k}] = {name!r} is the name of a constant in the printed maths "
                               "({constant}); name the joint e.g. 'q{k1}' or 'theta{k1}'.").format(
                                   k=k, name=s, constant=SYMPY_CONSTANTS[s], k1=k + 1))
        text.append(s)
    repeated = sorted({s for s in text if text.count(s) > 1})
    if repeated:
        raise DHLabError(_("joint_symbols name {name!r} twice: every joint needs its own variable, "
                           "or two joints would merge into one in fk_sym().").format(name=repeated[0]))
    return tuple(text)


def one_value(q, i: int):
    """The value of joint i: as given, or the element of a one-element list or array (checked later)."""
    if isinstance(q, np.ma.MaskedArray) and q.size == 1:          # keep a missing value missing
        return np.ma.masked if np.ma.is_masked(q) else q.data.ravel()[0]
    if isinstance(q, np.ndarray) and q.ndim == 0 or not (isinstance(q, (list, tuple, np.ndarray)) or is_matrix(q)):
        return q
    try:
        arr = None if is_matrix(q) else np.asarray(q, dtype=object).ravel()
    except (ValueError, TypeError):          # ragged beyond what an object array holds
        arr = None
    if arr is None or arr.size != 1:
        raise DHLabError(_("q must be one number, the value of joint {i}, got {got}.").format(i=i, got=describe(q)))
    return arr[0]


def numeric_params(params) -> dict:
    """Robot parameters as {name: float}, refusing anything that is not a finite number."""
    if params is None:
        return {}
    if not isinstance(params, dict):
        raise DHLabError(_("params must be a dict of numbers, e.g. {{'l1': 0.7}}; got {got}.").format(
            got=describe(params)))
    out = {}
    for key, value in params.items():
        name = key.name if is_symbol(key) else key
        if not isinstance(name, str) or not name.isidentifier():
            raise DHLabError(_("params keys must be names such as 'l1', got {got}.").format(got=describe(key)))
        if has_symbols(value) or isinstance(value, str):
            raise DHLabError(_("parameter {name} = {value!r} must be a finite number (a length or an angle in "
                               "radians).").format(name=name, value=value))
        number = as_number(value, _("parameter {name}").format(name=name))
        out[name] = value if isinstance(value, Angle) else number   # deg2rad() values stay marked as angles
    return out


def joint_label(symbol) -> str:
    """'theta1' -> 'θ1', 'q2' -> 'q2'."""
    name = str(symbol)
    for greek, char in (("theta", "θ"), ("alpha", "α"), ("phi", "φ")):
        if name.startswith(greek):
            return char + name[len(greek):].lstrip("_")
    return name
