"""The language every message is written in: English or Spanish, chosen explicitly.

The course never guesses the language from the machine's locale: a notebook
says ``dhlab.set_language("es")`` in its first cell, and the grader and the
release read the ``DHLAB_LANGUAGE`` environment variable (or their
``--language`` option). Messages are looked up in gettext catalogs
(``dhlab/locale/<lang>/LC_MESSAGES/<domain>.mo``, compiled from the ``.po`` files
beside them, and kept up to date by ``python -m tools.i18n_catalog``); a message
without a translation is shown in English.

>>> previous = set_language("es")
>>> _("{name} is not right yet.").format(name="q")
'q todavía no está bien.'
>>> set_language(previous)
'es'

Two languages in one run. The grader writes the gradebook in the teacher's language
while several threads (``-j N``) write each student's feedback in the student's. So
:func:`_` follows the language of the **current thread** when :func:`speaking` set one,
and the global language (:func:`set_language`) otherwise:

>>> with speaking("es"):
...     _("not answered")
'sin responder'
>>> _("not answered")
'not answered'
"""
from __future__ import annotations

import argparse
import contextlib
import gettext
import os
import sys
import threading
from pathlib import Path

from .errors import DHLabError

__all__ = ["LANGUAGES", "ENV_VAR", "LOCALE_DIR", "set_language", "get_language", "language_from_env", "_", "N_",
           "ngettext", "speaking", "current_language", "translations", "CASE_WORDS", "case_word",
           "checked_language", "default_language", "language_option", "split_language", "argparse_speaking",
           "error_line", "as_teacher"]

LANGUAGES = {"en": "English", "es": "Español"}
ENV_VAR = "DHLAB_LANGUAGE"
LOCALE_DIR = Path(__file__).parent / "locale"

_current = "en"                      # the course's language (set_language)
_local = threading.local()           # this thread's language, while speaking(...) holds
_catalogs: dict[str, gettext.NullTranslations] = {}


def translations(language: str) -> gettext.NullTranslations:
    """The gettext catalog of ``language``: the lessons' domain first, then the grader's
    (see ``tools.i18n_catalog.DOMAINS``), loaded once."""
    if language not in _catalogs:
        catalog = gettext.translation("dhlab", LOCALE_DIR, languages=[language], fallback=True)
        catalog.add_fallback(gettext.translation("dhlab_grading", LOCALE_DIR, languages=[language], fallback=True))
        _catalogs[language] = catalog
    return _catalogs[language]


def _language_code(language) -> str:
    """``language`` as one of the codes of :data:`LANGUAGES`, or a clear error."""
    if not isinstance(language, str) or language.strip().lower() not in LANGUAGES:
        choices = ", ".join(f"{code!r} ({name})" for code, name in LANGUAGES.items())
        raise DHLabError(_("language = {language!r} is not one of the course's languages: choose {choices}.").format(
            language=language, choices=choices))
    return language.strip().lower()


# --- the course's language, and this thread's --------------------------------------------------

def set_language(language: str) -> str:
    """Make ``language`` ('en' or 'es') the language of every message; return the previous one."""
    global _current
    previous, _current = _current, _language_code(language)
    return previous


def get_language() -> str:
    """The language messages are written in now ('en' unless :func:`set_language` changed it)."""
    return _current


def language_from_env(default: str = "en") -> str:
    """The language named by the ``DHLAB_LANGUAGE`` environment variable, else ``default``."""
    value = os.environ.get(ENV_VAR, "").strip()
    return _language_code(value) if value else _language_code(default)


def current_language() -> str:
    """The language of this thread's messages: the one :func:`speaking` set, else the course's."""
    return getattr(_local, "language", None) or _current


@contextlib.contextmanager
def speaking(language: str):
    """Every message of this thread in ``language`` ('en' or 'es') inside the block
    (other threads, and the course's language, are left as they are)."""
    previous = getattr(_local, "language", None)
    _local.language = _language_code(language)
    try:
        yield
    finally:
        _local.language = previous


# --- translating -------------------------------------------------------------------------------

def _(message: str) -> str:
    """``message`` (an English text, possibly with ``{placeholders}``) in this thread's language."""
    language = current_language()
    if language == "en" or not message:      # (gettext maps "" to the catalog's header)
        return message
    return translations(language).gettext(message)


def N_(message: str) -> str:
    """Mark ``message`` for translation where it is defined; translate it with :func:`_` where it is shown."""
    return message


def ngettext(singular: str, plural: str, n: int) -> str:
    """``singular`` or ``plural`` as ``n`` asks, in this thread's language.

    >>> ngettext("{n} joint", "{n} joints", 1).format(n=1)
    '1 joint'
    >>> ngettext("{n} joint", "{n} joints", 3).format(n=3)
    '3 joints'
    """
    language = current_language()
    if language == "en":
        return singular if n == 1 else plural
    return translations(language).ngettext(singular, plural, n)


# how two consecutive joint axes meet (dhlab.assignment.reference.relation(...).kind), as a student reads it
CASE_WORDS = {"intersect": N_("intersect"), "parallel": N_("parallel"), "skew": N_("skew"),
              "coincident": N_("coincident")}


def case_word(kind: str) -> str:
    """The word for a case of x_i ('intersect', 'parallel', 'skew', 'coincident') in this thread's language."""
    return _(CASE_WORDS[kind]) if kind in CASE_WORDS else kind


# --- the language a teacher chose (--language, DHLAB_LANGUAGE) -----------------------------------

# what a teacher may write in the roster's language column
_NAMES = {"en": "en", "english": "en", "inglés": "en", "ingles": "en",
          "es": "es", "spanish": "es", "español": "es", "espanol": "es"}


def checked_language(value, where: str = "--language") -> str:
    """``value`` as a course language ('en' or 'es'), or a clear error naming ``where``.

    >>> checked_language("Español")
    'es'
    """
    if isinstance(value, str) and value.strip().lower() in _NAMES:
        return _NAMES[value.strip().lower()]
    choices = ", ".join(f"{code} ({name})" for code, name in LANGUAGES.items())
    raise DHLabError(_("{where} = {value!r} is not one of the course's languages: choose {choices}.").format(
        where=where, value=value, choices=choices))


def default_language(option=None) -> str:
    """The ``--language`` option, else ``DHLAB_LANGUAGE``, else English."""
    if option:
        return checked_language(option)
    value = os.environ.get(ENV_VAR, "").strip()
    return checked_language(value, ENV_VAR) if value else "en"


def language_option(argv) -> str:
    """The teacher's language from a command line (``--language es`` or ``--language=es``), else
    ``DHLAB_LANGUAGE``, else English: read before the parser is built, so that its help is in it."""
    argv = list(argv)
    for k, arg in enumerate(argv):
        if arg == "--language" and k + 1 < len(argv):
            return default_language(argv[k + 1])
        if arg.startswith("--language="):
            return default_language(arg.split("=", 1)[1])
    return default_language(None)


def split_language(argv) -> tuple:
    """(:func:`language_option` of ``argv``, ``argv`` without its ``--language`` option), for a
    command whose parser does not take the option itself.

    >>> split_language(["a.ipynb", "--language", "es", "-j", "2"])
    ('es', ['a.ipynb', '-j', '2'])
    """
    argv, rest, skip = list(argv), [], False
    for k, arg in enumerate(argv):
        if skip:
            skip = False
        elif arg == "--language" and k + 1 < len(argv):
            skip = True
        elif not arg.startswith("--language="):
            rest.append(arg)
    return language_option(argv), rest


def error_line(prog: str, message) -> str:
    """A command's error line as argparse writes it (``prog: error: message``, then a newline),
    in this thread's language."""
    return _("%(prog)s: error: %(message)s\n") % {"prog": prog, "message": message}


@contextlib.contextmanager
def argparse_speaking():
    """argparse's own words ("usage:", "positional arguments", "error: …") in this thread's language
    inside the block. argparse looks each of them up with its module's ``_`` (gettext's default
    domain, which the course does not use): the block points that ``_`` at the course's catalogs,
    where the teacher's domain holds their translations (:mod:`dhlab.grading.parser_words`)."""
    saved = argparse._, argparse.ngettext
    argparse._ = _
    argparse.ngettext = ngettext
    try:
        yield
    finally:
        argparse._, argparse.ngettext = saved


def as_teacher(prog: str, argv, run, strip: bool = False) -> int:
    """``run(argv)`` with every message in the teacher's language (:func:`language_option`); with
    ``strip`` the ``--language`` option is taken out of ``argv`` first (:func:`split_language`).
    argparse's own words included (:func:`argparse_speaking`). A bad language is reported as
    ``prog: error: …``, exit status 2, as argparse does."""
    try:
        if strip:
            language, argv = split_language(argv)
        else:
            language = language_option(argv)
    except DHLabError as exc:
        print(error_line(prog, exc), file=sys.stderr, end="")
        return 2
    previous = set_language(language)
    try:
        with argparse_speaking():
            return run(argv)
    finally:
        set_language(previous)
