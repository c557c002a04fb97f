"""The comments of a notebook's code cell: found, and replaced by their translations.

A notebook in Spanish keeps the English code and reads its comments in Spanish: the course's
Spanish edition (``python -m tools.edition``) and every Spanish release (:mod:`.language`)
translate a code cell's comments, each from its ``#`` to the end of its line, and nothing else.
Python's tokenizer tells a comment from a ``#`` inside a string.

>>> comments('x = "#1"  # the first\\n# and back\\n')
['# the first', '# and back']
>>> with_comments('x = "#1"  # the first', {'# the first': '# el primero'})
'x = "#1"  # el primero'
"""
from __future__ import annotations

import io
import re
import tokenize

__all__ = ["comments", "with_comments"]

# a line that is only a comment: what a cell the tokenizer cannot read (an IPython magic) still has
FULL_LINE_COMMENT = re.compile(r"^[ \t]*(#.*)$")


def _places(source: str) -> list[tuple[int, int, str]]:
    """(line index, column, text) of every comment of ``source``, in order."""
    try:
        return [(token.start[0] - 1, token.start[1], token.string)
                for token in tokenize.generate_tokens(io.StringIO(source).readline)
                if token.type == tokenize.COMMENT]
    except (tokenize.TokenError, SyntaxError):        # IndentationError is a SyntaxError
        return [(i, m.start(1), m.group(1)) for i, line in enumerate(source.split("\n"))
                for m in [FULL_LINE_COMMENT.match(line)] if m]


def comments(source: str) -> list[str]:
    """The comments of a code cell (each from its '#' to the end of its line), in order."""
    return [text for _line, _column, text in _places(source)]


def with_comments(source: str, translated: dict) -> str:
    """The code cell ``source`` with each comment found in ``translated`` replaced by its
    translation (the code, and any comment not found, unchanged)."""
    lines = source.split("\n")
    for line, column, text in _places(source):
        if text in translated:
            lines[line] = lines[line][:column] + translated[text]
    return "\n".join(lines)
