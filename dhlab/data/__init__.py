"""The course's data, shipped with the package so that notebooks find it wherever they run
(a clone, a wheel, the browser edition):

- ``seed_cases.json`` — the 42 verified numeric cases of the seeds (a byte-identical copy of
  the course's reference ``seed_cases.json``)
- ``seed002_printed_A.json`` — the A matrices printed on seed 002's slides, verbatim as LaTeX

>>> from dhlab.data import load
>>> len(load("seed_cases")["cases"])
42
"""
from __future__ import annotations

import json
from importlib import resources

from ..errors import DHLabError

NAMES = ("seed_cases", "seed002_printed_A")


def load(name: str) -> dict:
    """The data file ``name`` (one of :data:`NAMES`) as parsed JSON."""
    if name not in NAMES:
        raise DHLabError(f"no course data named {name!r}: the data files are {', '.join(NAMES)}")
    return json.loads(resources.files(__name__).joinpath(f"{name}.json").read_text(encoding="utf-8"))
