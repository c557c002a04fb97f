"""The grader's two languages: the teacher's and each student's, in one run.

One batch may hold English and Spanish submissions, graded by several threads at once
(``-j N``), while the gradebook's statuses and the command line speak the teacher's language
(``dhlab-grade --language es``, else ``DHLAB_LANGUAGE``). So the grader's messages are not
translated by the course's one global language (:func:`dhlab.i18n.set_language`) but by this
module's :func:`_`, which follows the language of the **current thread** when :func:`speaking`
set one (a student's feedback is written inside ``with speaking(student_language):``), and the
global language otherwise (in a student's kernel, where ``dhlab.set_language("es")`` rules).

>>> with speaking("es"):
...     _("not answered")
'sin responder'
>>> _("not answered")
'not answered'
"""
from __future__ import annotations

import contextlib
import os
import sys
import threading

from ..i18n import ENV_VAR, LANGUAGES, _catalog, _checked, get_language, set_language
from ..validation import DHLabError

__all__ = ["_", "N_", "speaking", "current_language", "case_word", "checked_language", "default_language",
           "language_option", "split_language", "as_teacher"]

_local = threading.local()


def current_language() -> str:
    """The language of this thread's messages: the one :func:`speaking` set, else the course's."""
    return getattr(_local, "language", None) or get_language()


@contextlib.contextmanager
def speaking(language: str):
    """Every grader message of this thread in ``language`` ('en' or 'es') inside the block."""
    previous = getattr(_local, "language", None)
    _local.language = _checked(language)
    try:
        yield
    finally:
        _local.language = previous


def _(message: str) -> str:
    """``message`` (English, possibly with ``{placeholders}``) in this thread's language."""
    language = current_language()
    if language == "en" or not message:
        return message
    return _catalog(language).gettext(message)


def N_(message: str) -> str:
    """Mark a constant for translation; translate it with :func:`_` where it is shown."""
    return message


# how two consecutive joint axes meet (dhlab.grading.puma.relation(...).kind), as a student reads it
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
    """``value`` as a course language ('en' or 'es'), or a clear error naming ``where``."""
    if isinstance(value, str) and value.strip().lower() in _NAMES:
        return _NAMES[value.strip().lower()]
    choices = ", ".join(f"{code} ({name})" for code, name in LANGUAGES.items())
    from ..validation import DHLabError
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
    command whose parser does not take the option itself."""
    argv, rest, skip = list(argv), [], False
    for k, arg in enumerate(argv):
        if skip:
            skip = False
        elif arg == "--language" and k + 1 < len(argv):
            skip = True
        elif not arg.startswith("--language="):
            rest.append(arg)
    return language_option(argv), rest


def as_teacher(prog: str, argv, run, strip: bool = False) -> int:
    """``run(argv)`` with every message in the teacher's language (:func:`language_option`); with
    ``strip`` the ``--language`` option is taken out of ``argv`` first (:func:`split_language`).
    A bad language is reported as ``prog: error: …``, exit status 2, as argparse does."""
    try:
        if strip:
            language, argv = split_language(argv)
        else:
            language = language_option(argv)
    except DHLabError as exc:
        print(f"{prog}: error: {exc}", file=sys.stderr)
        return 2
    previous = set_language(language)
    try:
        return run(argv)
    finally:
        set_language(previous)
