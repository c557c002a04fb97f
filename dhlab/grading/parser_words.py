"""argparse's own words, in the teacher's catalog: ``dhlab-grade --help --language es`` is Spanish throughout.

argparse writes a few words of its own in every help and error message ("usage:", "positional
arguments", "options", "the following arguments are required: …"). It looks them up with gettext's
default domain, which this course does not use; :func:`dhlab.i18n.argparse_speaking` (which the
teacher's commands run under) sends them to the course's catalogs instead. This module only marks
them, so that ``python -m tools.i18n_catalog extract`` puts them in the teacher's domain
(``dhlab_grading``) and a translator sees them: each is argparse's exact English text (Python 3.11).
"""
from __future__ import annotations

from ..i18n import N_

__all__ = ["ARGPARSE_WORDS"]

ARGPARSE_WORDS = (
    N_("usage: "),
    N_("positional arguments"),
    N_("options"),
    N_("show this help message and exit"),
    N_("%(prog)s: error: %(message)s\n"),
    N_("the following arguments are required: %s"),
    N_("unrecognized arguments: %s"),
    N_("argument %(argument_name)s: %(message)s"),
    N_("invalid choice: %(value)r (choose from %(choices)s)"),
    N_("invalid %(type)s value: %(value)r"),
    N_("expected one argument"),
    N_("expected at most one argument"),
    N_("expected at least one argument"),
    N_("ambiguous option: %(option)s could match %(matches)s"),
    N_("not allowed with argument %s"),
    N_("one of the arguments %s is required"),
)
