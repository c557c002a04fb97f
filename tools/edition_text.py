"""What a translation of a markdown cell must keep: its placeholders, its headings, its links.

The Spanish edition translates the prose of each markdown cell and nothing else. The parts a
translator must copy byte for byte are the **placeholders**: every ``$…$``/``$$…$$`` formula,
every ``code span`` (and fenced block), every link target and image path, every HTML tag.
:func:`placeholders` lists them, so that the English and the Spanish cell can be compared as
multisets. Headings keep their level (:func:`headings`); their anchors (:func:`anchor`) are the
ids JupyterLab gives them, which links between notebooks point to. :func:`relink` rewrites the
link targets of a cell (the edition lives one folder down, in ``notebooks/es/``).

>>> sorted(placeholders("Rotate by $\\\\theta$ with `Rz` ([see](05_x.ipynb#Rules)).<br>"))
['$\\\\theta$', '05_x.ipynb#Rules', '<br>', '`Rz`']
>>> anchor("2. `THx` *is* wrong")
'2.-THx-is-wrong'

The comments of a code cell are translated too (the code itself never is): :func:`comments`
finds them, :func:`with_comments` puts their translations in their place (both from the package,
:mod:`dhlab.grading.release.comments`, whose Spanish releases translate them the same way).
"""
from __future__ import annotations

import re
from collections import Counter

from dhlab.grading.release.comments import comments, with_comments

__all__ = ["placeholders", "placeholder_difference", "headings", "anchor", "relink", "comments",
           "with_comments"]

# In the order they are taken out of the text: code first (a `$` in code is not maths),
# then maths, then link targets (a `<target>` is not an HTML tag), then HTML tags.
FENCE = re.compile(r"^(```|~~~)[^\n]*\n.*?^\1[ \t]*$", re.S | re.M)
CODE_SPAN = re.compile(r"(`+)(?!`).+?(?<!`)\1(?!`)", re.S)
DISPLAY_MATH = re.compile(r"\$\$.+?\$\$", re.S)
INLINE_MATH = re.compile(r"(?<![\\$])\$(?!\$)(?:\\.|[^$\\])+?\$", re.S)
# the target of a link or an image: ](target) or ](<target>), an optional "title" after it
LINK_TARGET = re.compile(r"\]\((<[^<>\n]*>|[^()\s<>]*(?:\([^()\s]*\)[^()\s<>]*)*)((?:\s+\"[^\"\n]*\")?\s*)\)")
IMG_SRC = re.compile(r"(<img\b[^>]*?\bsrc=)([\"'])([^\"']*)\2", re.I)
HTML_TAG = re.compile(r"</?[A-Za-z][A-Za-z0-9-]*(?:\s[^<>]*)?/?>")
HEADING = re.compile(r"^(#{1,6})[ \t]+(.+?)[ \t#]*$", re.M)


def _masked(text: str, patterns) -> tuple[str, list[str]]:
    """``text`` with every match of ``patterns`` (in turn) blanked out, and the matches."""
    found = []
    for pattern in patterns:
        found += [m.group(0) for m in pattern.finditer(text)]
        text = pattern.sub(lambda m: " " * len(m.group(0)), text)
    return text, found


def placeholders(markdown: str) -> Counter:
    """The multiset of parts a translation must keep unchanged: code, maths, link targets, HTML tags."""
    rest, found = _masked(markdown, [FENCE, CODE_SPAN, DISPLAY_MATH, INLINE_MATH])
    found += [m.group(1) for m in LINK_TARGET.finditer(rest)]
    rest = LINK_TARGET.sub(lambda m: " " * len(m.group(0)), rest)
    found += HTML_TAG.findall(rest)
    return Counter(found)


def placeholder_difference(english: str, spanish: str) -> str:
    """'' when both texts keep the same placeholders; else what is missing and what was added."""
    en, es = placeholders(english), placeholders(spanish)
    missing, added = sorted((en - es).elements()), sorted((es - en).elements())
    parts = ([f"missing in Spanish {missing}"] if missing else []) + ([f"only in Spanish {added}"] if added else [])
    return "; ".join(parts)


def headings(markdown: str) -> list[tuple[int, str]]:
    """(level, text) of every heading of a markdown cell, in order (not those inside code blocks)."""
    rest, _ = _masked(markdown, [FENCE])
    return [(len(m.group(1)), markdown[m.start(2):m.end(2)]) for m in HEADING.finditer(rest)]


def anchor(heading_text: str) -> str:
    """The id JupyterLab gives a heading: its text without code and emphasis marks, spaces as '-'."""
    return re.sub(r"[`*]", "", heading_text.strip()).replace(" ", "-")


def relink(markdown: str, new_target) -> str:
    """``markdown`` with every link target and image path ``t`` replaced by ``new_target(t)``
    (code spans, fenced blocks and maths are left alone)."""
    mask, _ = _masked(markdown, [FENCE, CODE_SPAN, DISPLAY_MATH, INLINE_MATH])
    edits = []                                   # (start, end, replacement) in the original text
    for m in LINK_TARGET.finditer(mask):
        target = m.group(1)
        bracketed = target.startswith("<")
        new = new_target(target[1:-1] if bracketed else target)
        if bracketed or re.search(r"[\s()<>]", new):
            new = f"<{new}>"
        edits.append((m.start(1), m.end(1), new))
    for m in IMG_SRC.finditer(mask):
        edits.append((m.start(3), m.end(3), new_target(markdown[m.start(3):m.end(3)])))
    for start, end, new in sorted(edits, reverse=True):
        markdown = markdown[:start] + new + markdown[end:]
    return markdown

