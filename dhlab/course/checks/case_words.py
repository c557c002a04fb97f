"""The case of an x_i, read from words: one reading for the lesson and the grader.

Step 2 of the DH procedure asks how the axes z_(i-1) and z_i meet: they *intersect* (case 1),
are *parallel* (case 2) or *skew* (case 3). Students answer in words, English or Spanish, and
sometimes misspell them. The lesson's exercise (:func:`dhlab.course.exercises.dh_rules.check_x_cases`)
and the grader (:mod:`dhlab.assignment.answers`) both read an answer with :func:`read_case_words`, so
the two never disagree on what a word means.

A word is read by its stem, so small slips and other forms pass ('paralel', 'paralelos',
'intersects', 'skewed'); an answer that names no case, several cases, or says what does *not*
hold ('they do not intersect') is not read, and :func:`closest_word` offers a "did you mean".

Standard library only: the grader's ``answers.py`` uses this module.

>>> read_case_words("Paralel").case, read_case_words("se cruzan").case, read_case_words("neither").case
('parallel', 'skew', 'skew')
>>> r = read_case_words("interesct"); r.case, r.suggestion
(None, 'intersect')
"""
from __future__ import annotations

import difflib
import re
import unicodedata
from dataclasses import dataclass

__all__ = ["CaseReading", "read_case_words", "closest_word", "words", "CASE_NUMBERS", "ACCEPTED_WORDS"]

CASE_NUMBERS = {1: "intersect", 2: "parallel", 3: "skew"}

# whole answers (after words()) that name a case although no stem below is in them, or that name
# it by what it is not (the assignment's own words for case 3: 'ni paralelos ni se intersecan')
_WHOLE = {"1": "intersect", "2": "parallel", "3": "skew", "case 1": "intersect", "caso 1": "intersect",
          "case 2": "parallel", "caso 2": "parallel", "case 3": "skew", "caso 3": "skew",
          "neither": "skew", "ni paralelos ni se intersecan": "skew",
          "coincide": "coincident"}

# a word holding one of these stems names that case (English and Spanish, accents dropped)
_STEMS = (("intersec", "intersect"), ("corta", "intersect"), ("parallel", "parallel"), ("parale", "parallel"),
          ("skew", "skew"), ("cruza", "skew"), ("alabead", "skew"), ("coinciden", "coincident"),
          ("same line", "coincident"), ("misma recta", "coincident"))

_NEGATION = re.compile(r"\b(not|no|never|neither|nor|cannot|can t|don t|doesn t|isn t|aren t|dont|doesnt|isnt|"
                       r"arent|nunca|ni|tampoco)\b")
_NEITHER_NOR = re.compile(r"^(neither|ni)\b.*\b(nor|ni)\b")     # 'neither parallel nor intersecting': case 3

# the words a "did you mean" may offer: what the assignment asks for, in both languages
ACCEPTED_WORDS = ("intersect", "parallel", "skew", "se intersecan", "paralelos", "se cruzan")
_ARTICLES = ("the", "a", "an", "el", "la", "los", "las", "un", "una", "unos", "unas")


@dataclass(frozen=True)
class CaseReading:
    """What an answer says: ``case`` ('intersect', 'parallel', 'skew', 'coincident') or None,
    with why not: the cases it ``named`` (more than one), ``negated`` (it says what does not
    hold), else it named none, and ``suggestion`` is the closest accepted word ('' if none is close)."""
    case: str | None
    named: tuple = ()
    negated: bool = False
    suggestion: str = ""


def words(text) -> str:
    """'End-Effector ' -> 'end effector': lower case, accents dropped ('eslabón' -> 'eslabon'),
    punctuation as spaces, no leading article."""
    text = unicodedata.normalize("NFKD", str(text))
    text = "".join(ch for ch in text if not unicodedata.combining(ch)).casefold()
    for sep in ("-", "_", "/", ".", ",", "!", "?", "¡", "¿", "'", '"'):
        text = text.replace(sep, " ")
    parts = text.split()
    if parts and parts[0] in _ARTICLES:
        parts = parts[1:]
    return " ".join(parts)


def _named(text: str) -> set:
    """Every case a text names by a stem, or as 'case 2' / 'caso 2'."""
    named = {kind for stem, kind in _STEMS if stem in text}
    named |= {CASE_NUMBERS[int(n)] for n in re.findall(r"\b(?:case|caso)\s*([123])\b", text)}
    if named == {"parallel", "coincident"}:          # "parallel: the same line" is one case
        named = {"coincident"}
    return named


def read_case_words(text: str) -> CaseReading:
    """The one case a text names (see the module doc); numbers are read as 'case n'."""
    text = words(text)
    if text in _WHOLE:
        return CaseReading(_WHOLE[text])
    named = _named(text)
    if named == {"parallel", "intersect"} and _NEITHER_NOR.match(text):
        return CaseReading("skew")
    if len(named) > 1:
        return CaseReading(None, tuple(sorted(named)))
    if _NEGATION.search(text):
        return CaseReading(None, tuple(named), negated=True)
    if not named:
        return CaseReading(None, suggestion=closest_word(text))
    return CaseReading(named.pop())


def closest_word(text: str) -> str:
    """The accepted word closest to a misspelt one ('interesct' -> 'intersect'), '' if none is close."""
    close = difflib.get_close_matches(words(text), ACCEPTED_WORDS, n=1, cutoff=0.6)
    return close[0] if close else ""
