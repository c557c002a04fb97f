"""The options the teacher's commands share (``dhlab-grade``, ``dhlab-grade export``, ``dhlab-assign``):
each defined once, here, as an argparse parent parser (``ArgumentParser(parents=[…])``).

``--language`` (the teacher's language: the command's messages; read before the parser is built,
:func:`dhlab.i18n.language_option`, so that the help is in it), ``--secret-file`` (the teacher's
secret the notebooks are released with, :data:`DEFAULT_SECRET_FILE` by default) and ``--source``
(a teacher's own solution notebook; without it the solution is computed,
:func:`dhlab.grading.release.generate.solution_notebook`). What an option means to one command (the
release makes a missing secret; the grader grades against the PUMA 560 without one) is said in that
command's help text, given here by the command.

>>> args = shared(secret=True, source=True).parse_args(["--source", "mine.ipynb"])
>>> args.source.name, args.secret_file, args.language
('mine.ipynb', None, None)
"""
from __future__ import annotations

import argparse
from pathlib import Path

from ..i18n import _

__all__ = ["DEFAULT_SECRET_FILE", "shared"]

DEFAULT_SECRET_FILE = Path("dhlab-secret.key")       # where dhlab-assign release keeps the secret it made


def shared(*, secret: bool | str = False, source: bool = False, language: bool | str = True) -> argparse.ArgumentParser:
    """A parent parser with the shared options: ``--language`` (unless ``language`` is False),
    ``--secret-file`` when ``secret``, ``--source`` when ``source``. A text given for ``secret`` or
    ``language`` is that command's help of the option (messages are translated when the parser is built)."""
    parser = argparse.ArgumentParser(add_help=False)
    if language:
        parser.add_argument("--language", default=None, help=language if isinstance(language, str) else _(
            "the teacher's language, en or es: this command's messages (default: DHLAB_LANGUAGE, else en)"))
    if secret:
        parser.add_argument("--secret-file", type=Path, default=None, help=secret if isinstance(secret, str) else _(
            "personal variants: the teacher's secret the notebooks were released with"))
    if source:
        parser.add_argument("--source", type=Path, default=None,
                            help=_("the teacher's own solution notebook, graded first as a self-check (default: "
                                   "the solution dhlab computes for the PUMA 560)"))
    return parser
