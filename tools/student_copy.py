"""The student's own copy of the course, ``my-notebooks/``: where ``make lab`` and ``make lab-es`` open.

    python -m tools.student_copy [COPY]          # default: my-notebooks (at the repository's top)

The course (``notebooks/``) is tracked by git, updated by ``git pull`` and tested by ``make test``.
A student who typed answers into it would meet conflicts on the next ``git pull`` and see
``make test`` fail; and JupyterLab rewrites a notebook it has opened (the kernel's version in its
metadata, on autosave) even before anything is typed. So the student works in a copy, which git
ignores (``.gitignore``):

* **the first run** copies the notebooks, ``es/`` and ``images/`` (not the lecturers' plans, nor
  the tests' ``sanitize.cfg``);
* **every later run adds what is new in the course** (next week's notebook) and **never changes a
  file the student has changed**: a notebook they opened or answered is theirs. A file of the copy
  still exactly as it was copied (the student never saved it) follows the course when the course
  changes it: the course home, a notebook not yet opened. Which file was copied as what is recorded
  in ``COPY/.course-copy.json`` (each file's SHA-256 when copied).

A student who wants the course's new version of a notebook they have changed renames their copy
(``05_dh_convention.ipynb`` → ``05_mine.ipynb``) and runs ``make lab`` again: the course's comes back.

>>> sorted(course_files(ROOT / "notebooks"))[:2]
['01_start_here.ipynb', '02_homogeneous_matrices.ipynb']
"""
from __future__ import annotations

import argparse
import hashlib
import json
import shutil
import sys
from pathlib import Path

__all__ = ["ROOT", "COURSE", "COPY", "RECORD", "LEFT_OUT", "course_files", "update_copy", "main"]

ROOT = Path(__file__).resolve().parents[1]          # the repository: this tool works there
COURSE = ROOT / "notebooks"
COPY = ROOT / "my-notebooks"
RECORD = ".course-copy.json"                        # relative path -> SHA-256 of the file as copied
# what is the course's and not the student's: the lecturers' plans, the tests' nbval settings
LEFT_OUT = {"lecture_plans", "sanitize.cfg"}


def _digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def course_files(course: Path = COURSE) -> dict:
    """relative path (POSIX) -> file, for every file of the course a student gets (hidden files and
    folders such as ``.ipynb_checkpoints`` left out, and :data:`LEFT_OUT`)."""
    found = {}
    for path in sorted(course.rglob("*")):
        parts = path.relative_to(course).parts
        if path.is_file() and parts[0] not in LEFT_OUT and not any(p.startswith(".") for p in parts):
            found["/".join(parts)] = path
    return found


def update_copy(course: Path = COURSE, copy: Path = COPY) -> dict:
    """Make or bring up to date the student's copy ``copy`` of ``course`` (see the module); returns
    what happened: {"added": [...], "updated": [...], "kept": [...]} (kept: files the student
    changed whose course version changed too; they stay the student's)."""
    copy.mkdir(parents=True, exist_ok=True)
    record_path = copy / RECORD
    record = json.loads(record_path.read_text(encoding="utf-8")) if record_path.exists() else {}
    done = {"added": [], "updated": [], "kept": []}
    for name, source in course_files(course).items():
        target = copy / name
        wanted = _digest(source)
        if not target.exists():
            done["added"].append(name)
        elif _digest(target) == wanted:
            record[name] = wanted                     # the same as the course's: nothing to do
            continue
        elif record.get(name) == _digest(target):     # as copied, never saved by the student
            done["updated"].append(name)
        else:                                         # the student's work: never touched
            done["kept"].append(name)
            continue
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(source, target)
        record[name] = wanted
    record_path.write_text(json.dumps(record, indent=1, sort_keys=True) + "\n", encoding="utf-8")
    return done


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("copy", nargs="?", type=Path, default=COPY, help="the student's copy (default my-notebooks)")
    args = parser.parse_args(argv)
    first = not args.copy.exists()
    done = update_copy(COURSE, args.copy)
    if first:
        print(f"Your own copy of the course is {args.copy}/: your answers stay there (git ignores it); "
              "make lab adds the course's new notebooks to it and never changes yours.")
    elif done["added"] or done["updated"]:
        print(f"{args.copy}/: new from the course: {', '.join(done['added'] + done['updated'])}")
    if done["kept"]:
        print(f"{args.copy}/: the course changed {', '.join(done['kept'])}, which you have changed too: yours "
              "is kept (rename yours and run make lab again to get the course's as well)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
