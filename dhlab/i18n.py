"""The language every message is written in: English or Spanish, chosen explicitly.

The course never guesses the language from the machine's locale: a notebook
says ``dhlab.set_language("es")`` in its first cell, and the grader and the
release read the ``DHLAB_LANGUAGE`` environment variable (or their
``--language`` option). Messages are looked up in gettext catalogs
(``dhlab/locale/<lang>/LC_MESSAGES/<domain>.mo``, compiled from the ``.po`` files
beside them, and kept up to date by ``python -m dhlab.i18n_catalog``); a message
without a translation is shown in English.

>>> from dhlab.i18n import set_language, _
>>> previous = set_language("es")
>>> _("{name} is not right yet.").format(name="q")
'q todavía no está bien.'
>>> set_language(previous)
'es'
"""
from __future__ import annotations

import gettext
import os
from pathlib import Path

__all__ = ["LANGUAGES", "set_language", "get_language", "language_from_env", "_", "N_"]

LANGUAGES = {"en": "English", "es": "Español"}
ENV_VAR = "DHLAB_LANGUAGE"
LOCALE_DIR = Path(__file__).parent / "locale"

_current = "en"
_catalogs: dict[str, gettext.NullTranslations] = {}


def _catalog(language: str) -> gettext.NullTranslations:
    if language not in _catalogs:
        # the lessons' domain first, then the grader's (see dhlab.i18n_catalog.DOMAINS)
        catalog = gettext.translation("dhlab", LOCALE_DIR, languages=[language], fallback=True)
        catalog.add_fallback(gettext.translation("dhlab_grading", LOCALE_DIR, languages=[language], fallback=True))
        _catalogs[language] = catalog
    return _catalogs[language]


def _checked(language) -> str:
    if not isinstance(language, str) or language.strip().lower() not in LANGUAGES:
        from .validation import DHLabError     # (validation will import this module)
        choices = ", ".join(f"{code!r} ({name})" for code, name in LANGUAGES.items())
        raise DHLabError(_("language = {language!r} is not one of the course's languages: choose {choices}.").format(
            language=language, choices=choices))
    return language.strip().lower()


def set_language(language: str) -> str:
    """Make ``language`` ('en' or 'es') the language of every message; return the previous one."""
    global _current
    previous, _current = _current, _checked(language)
    return previous


def get_language() -> str:
    """The language messages are written in now ('en' unless :func:`set_language` changed it)."""
    return _current


def language_from_env(default: str = "en") -> str:
    """The language named by the ``DHLAB_LANGUAGE`` environment variable, else ``default``."""
    value = os.environ.get(ENV_VAR, "").strip()
    return _checked(value) if value else _checked(default)


def _(message: str) -> str:
    """``message`` (an English text, possibly with ``{placeholders}``) in the current language."""
    if _current == "en" or not message:      # (gettext maps "" to the catalog's header)
        return message
    return _catalog(_current).gettext(message)


def N_(message: str) -> str:
    """Mark ``message`` for translation where it is defined; translate it with :func:`_` where it is shown."""
    return message
