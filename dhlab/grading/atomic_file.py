"""A file written whole or not at all: what the grader and the release write (gradebooks, feedback,
rosters) is either the old file or the new one, never half of it, even if the machine stops midway.

>>> import tempfile, pathlib
>>> path = pathlib.Path(tempfile.mkdtemp()) / "grades.csv"
>>> write_atomic(path, "id,score\\n")
>>> path.read_text()
'id,score\\n'
"""
from __future__ import annotations

import os
import tempfile
from pathlib import Path

__all__ = ["write_atomic"]

def write_atomic(path, text: str) -> None:
    """Write ``text`` to ``path`` so that the file is either the old one or the new one."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "w", encoding="utf-8", newline="") as f:
            f.write(text)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
