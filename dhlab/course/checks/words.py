"""Checking words: :func:`check_choice` (a choice or a short answer) and :func:`check_terms`
(a glossary: a word for each term). Text is compared without case, accents, hyphens or a
leading article, so "The End-Effector" and "end effector" are the same answer. A choice may be
answered in Spanish too (:func:`in_english`): "Azul" is "blue", "el eje z" is "z axis", "sí" is "yes".

>>> check_choice("Azul", "blue")
✓ correct: your answer is right.
"""
from __future__ import annotations

from ...i18n import _
from . import options as teacher
from .case_words import words  # one normalisation for every word answer (and the grader's x_cases)
from .feedback import Feedback, correct, short_repr, unanswered, wrong
from .reading import is_unanswered

__all__ = ["check_choice", "check_terms", "words", "in_english"]


# The Spanish of the words a choice may ask for, so that either language answers (after words():
# lower case, no accents). Phrases first, then single words; an English answer is left as it is.
SPANISH_PHRASES = {"se cruzan": "skew", "se cortan": "intersect", "se intersecan": "intersect",
                   "misma recta": "same line"}
SPANISH_WORDS = {
    "azul": "blue", "rojo": "red", "roja": "red", "verde": "green", "amarillo": "yellow", "negro": "black",
    "gris": "grey", "gray": "grey", "si": "yes", "verdadero": "true", "cierto": "true", "falso": "false",
    "paralelo": "parallel", "paralela": "parallel", "paralelos": "parallel", "paralelas": "parallel",
    "alabeadas": "skew", "perpendicular": "perpendicular", "perpendiculares": "perpendicular",
    "ambas": "both", "ambos": "both", "ninguna": "none", "ninguno": "none", "rama": "branch",
    "eje": "axis", "ejes": "axes", "rotacional": "revolute", "prismatica": "prismatic", "prismatico": "prismatic",
}


def in_english(text) -> str:
    """``words(text)`` with the Spanish of :data:`SPANISH_WORDS` put in English: 'el eje Z' -> 'z axis',
    'Sí' -> 'yes', 'se cruzan' -> 'skew', 'la rama B' -> 'branch b'."""
    text = f" {words(text)} "
    for spanish, english in SPANISH_PHRASES.items():
        text = text.replace(f" {spanish} ", f" {english} ")
    parts = [SPANISH_WORDS.get(w, w) for w in text.split()]
    if len(parts) == 2 and parts[0] == "axis":          # 'eje x' -> 'x axis'
        parts.reverse()
    return " ".join(parts)


def _norm(value, textual: bool):
    if textual:
        return in_english(value)
    try:
        hash(value)
    except Exception:                     # unhashable (a list, a dict): it equals no choice
        return short_repr(value, 10 ** 6)
    return value


def check_choice(student, correct_answer, *, name: str = "your answer", accepted=(), explanations=None) -> Feedback:
    """A choice or a short word answer: ``correct_answer`` (or one of ``accepted``) passes.

    ``explanations`` maps wrong answers to what is wrong with them.

    >>> check_choice("Red", "green", name="the colour of y", explanations={"red": "red is the x axis."})
    ✗ the colour of y is not right yet.
      • red is the x axis.
    """
    name = teacher.name(name)
    accepted, explanations = teacher.accepted_answers(accepted), teacher.explanations(explanations)
    if is_unanswered(student):
        return unanswered(name)
    textual = isinstance(correct_answer, str)
    if textual and not isinstance(student, str):
        return wrong(name, [_("{name} is a word: write it as text, in quotes (you gave {answer}).").format(
            name=name, answer=_short(student))])
    mine = _norm(student, textual)
    if mine in {_norm(correct_answer, textual), *(_norm(a, textual) for a in accepted)}:
        return correct(name)
    for wrong_answer, why in explanations.items():
        if mine == _norm(wrong_answer, textual):
            return wrong(name, [_(why)])
    return wrong(name, [_("you answered {answer}, which is not right.").format(answer=_short(student))])


def _short(v) -> str:
    return short_repr(v, 40)


def check_terms(student: dict, expected: dict, *, name: str = "your glossary") -> Feedback:
    """Words for terms, e.g. Spanish -> English: ``expected`` maps each term to its
    answer (or a tuple of accepted answers). Says which terms are wrong, missing,
    or given the answer of another term.

    >>> check_terms({"eslabón": "joint", "articulación": "joint"},
    ...             {"eslabón": "link", "articulación": "joint"}, name="the glossary")
    ✗ the glossary is not right yet.
      • eslabón: you wrote 'joint', which is the English for articulación.
    """
    name, expected = teacher.name(name), teacher.glossary(expected)
    if not isinstance(student, dict):
        return unanswered(name) if is_unanswered(student) else wrong(
            name, [_("{name} must be a dict {{term: answer, …}}, as in the cell.").format(name=name)])
    accepted = {term: {words(a) for a in (v if isinstance(v, (tuple, list, set)) else (v,))}
                for term, v in expected.items()}
    given = {words(k): v for k, v in student.items()}
    items, empty = [], 0
    for term, answers in accepted.items():
        value = given.get(words(term))
        if value is None or value is Ellipsis or (isinstance(value, str) and value.strip() in ("", "...")):
            empty += 1
            continue
        if not isinstance(value, str):
            items.append(_("{term}: you wrote {answer}; write the English word(s) as text, in quotes.").format(
                term=term, answer=_short(value)))
            continue
        if words(value) in answers:
            continue
        other = next((t for t, a in accepted.items() if t != term and words(value) in a), None)
        items.append((_("{term}: you wrote {answer!r}, which is the English for {other}.") if other
                      else _("{term}: you wrote {answer!r}, which is not right.")).format(
                          term=term, answer=value, other=other))
    if empty == len(accepted):
        return unanswered(name)
    if empty:
        items.append((_("{k} terms are still empty (...).") if empty > 1 else
                      _("{k} term is still empty (...).")).format(k=empty))
    unknown = sorted(k for k in given if k not in {words(t) for t in accepted})
    if unknown and not items:
        items.append(_("{terms}: not a term of this glossary; keep the terms of the cell.").format(
            terms=", ".join(map(repr, unknown))))
    return correct(name) if not items else wrong(name, items)
