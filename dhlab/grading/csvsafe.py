"""CSV cells a spreadsheet shows as text and never runs ("CSV injection"), and back.

Excel, LibreOffice and Google Sheets run a cell that starts with ``=``, ``+``, ``-`` or ``@``
(and, after a tab or a carriage return, what follows) as a formula: a submission file named
``=HYPERLINK(…).ipynb`` would put a live formula into the teacher's gradebook. As OWASP
recommends ("CSV Injection"), every *text* cell that starts with one of :data:`TRIGGERS` gets a
single quote in front (``'=1+2``), which a spreadsheet shows as text.

The escape is reversible, so the grader reads its own files back unchanged (``--resume`` must
find the submission ``=1+2`` again): a text cell that already starts with a quote gets a second
one (``'abc`` → ``''abc``), and :func:`restored` drops exactly one leading quote from any cell.

*Numbers stay numbers*: in a column the writer declares numeric (a score, the seconds…), a
plain decimal number such as ``-0.5`` or ``1e-3`` is written as it is — a spreadsheet reads it
as a number, never as a formula. Anything else in a numeric column is escaped like text.

>>> [neutralised(v) for v in ("=1+2", "-2+3", "'quoted", "José", "")]
["'=1+2", "'-2+3", "''quoted", 'José', '']
>>> neutralised("-0.5", numeric=True), neutralised("-0.5"), neutralised("=A1", numeric=True)
('-0.5', "'-0.5", "'=A1")
>>> all(restored(neutralised(v)) == v for v in ("=1+2", "'x", "''y", "@cmd", "\\tx", "ok"))
True
"""
from __future__ import annotations

import csv
import io
import re

__all__ = ["TRIGGERS", "QUOTE", "BOM", "GRADEBOOK_BOM", "neutralised", "restored", "is_number", "csv_text"]

# OWASP's list (= + - @ tab CR), a line feed, and the full-width forms some spreadsheets also accept
TRIGGERS = ("=", "+", "-", "@", "\t", "\r", "\n", "\uff1d", "\uff0b", "\uff0d", "\uff20")
QUOTE = "'"
BOM = "\ufeff"          # UTF-8 with BOM: Excel then reads 'José', not 'JosÃ©'
# The gradebook is the grader's own working file first (--resume, the exports, scripts that read
# it with csv.DictReader(open(..., encoding="utf-8")), where a BOM would rename the first column
# '\ufeffsubmission'): it is written without one; the files made for Excel and an LMS (Canvas,
# Moodle, the release's manifest) have one. Every reader here accepts both.
GRADEBOOK_BOM = False
_NUMBER = re.compile(r"-?(\d+(\.\d*)?|\.\d+)([eE][-+]?\d+)?")


def is_number(text: str) -> bool:
    """Whether ``text`` is a plain decimal number ('10', '-0.5', '8.57', '1e-3')."""
    return bool(_NUMBER.fullmatch(text))


def neutralised(value, numeric: bool = False) -> str:
    """``value`` as a cell no spreadsheet runs (see the module); ``numeric``: the column holds
    numbers, so a plain number is kept as it is."""
    text = "" if value is None else str(value)
    if numeric and is_number(text):
        return text
    if text.startswith(TRIGGERS) or text.startswith(QUOTE):
        return QUOTE + text
    return text


def restored(text) -> str:
    """The value :func:`neutralised` was given: one leading quote dropped (None reads as '')."""
    if text is None:
        return ""
    return text[1:] if text.startswith(QUOTE) else text


def csv_text(rows, numeric_columns=(), bom: bool = True) -> str:
    """The CSV text of ``rows`` (lists of cells; the first is the header, written as text),
    every cell neutralised; ``numeric_columns``: the indexes of the numeric columns. It starts
    with a BOM (``bom``) for Excel; lines end in CRLF, as RFC 4180 says."""
    numeric = set(numeric_columns)
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\r\n")
    for number, row in enumerate(rows):
        writer.writerow([neutralised(cell, number > 0 and k in numeric) for k, cell in enumerate(row)])
    return (BOM if bom else "") + buffer.getvalue()
