"""Gradescope's autograder: the zip a teacher uploads, and the program it runs for every submission.

    dhlab-grade export gradescope -o autograder.zip [--timeout 30 --total-timeout 240]
                                  [--secret-file KEY --release RELEASE_DIR]

Gradescope's contract (its documented autograder specification; otter-grader's local Docker
grading uses the same layout):

* the zip's root holds ``setup.sh`` and ``run_autograder``; Gradescope unpacks it into
  ``/autograder/source`` and runs ``setup.sh`` once, to build the image;
* for every submission a fresh container runs ``run_autograder``, with the student's files in
  ``/autograder/submission`` and ``/autograder/submission_metadata.json`` naming the student;
* the result is ``/autograder/results/results.json``: ``score``, ``output`` and ``tests[]``
  (``name``, ``score``, ``max_score``, ``output``, ``visibility``). No results file shows as an
  *autograder failure* to the student and the teacher, never as a zero.

What the zip holds (:func:`export`): a wheel of the installed dhlab (made here, offline, from
the package's own files: :mod:`dhlab.grading.export.wheel`), ``setup.sh`` (installs it, with the kernel
the grader starts), ``run_autograder``, the grading options (``dhlab_autograder.json``), the teacher's
solution (``solution.ipynb``, for the self-check: the wheel, like every installed dhlab, does not hold
it) and, for personal variants, the teacher's secret and ``release/_teacher/`` (the roster's variants).
The zip goes to Gradescope only, never to a student.

What ``run_autograder`` does (:func:`run`): the same steps as ``dhlab-grade puma`` for one
submission — staging, the self-check (:mod:`dhlab.grading.run.selfcheck`), the sandboxed runner,
the checks in the grader's process — then writes ``results.json``: one test per part, with that
part's feedback as its output. With variants the student is the roster id found in
``submission_metadata.json`` (a user's ``sid``, email or the email's name before ``@``); the
secret is read into memory and deleted from the container before any student code runs. A
grader error (or a submitter not in the roster) writes **no** results file: an autograder
failure the teacher can run again, with the reason in the log.

**Never as root.** Gradescope runs the autograder as root. The student's kernel runs as an
unprivileged user (a ``dhlab-grade-N`` user, ``nobody``, or the bare uid 65534: root can always
become it, with or without namespaces); when none can be used, the submission is refused
(:data:`ROOT_KERNEL`, no results file) rather than graded by a kernel that could forge its result.
And before results.json is written, every process still below the grader is killed
(:mod:`dhlab.grading.run.reaper`): a daemon a notebook forked cannot rewrite it afterwards.

``DHLAB_AUTOGRADER_ROOT`` moves ``/autograder`` (the local harness,
:mod:`dhlab.grading.export.gradescope_local`, builds the tree in a temporary folder).
"""
from __future__ import annotations

import argparse
import json
import os
import re
import shutil
import sys
import tempfile
import time
import traceback
import zipfile
from pathlib import Path
from types import SimpleNamespace

from ...assignment import checks
from ...assignment.checks import POINTS, TITLES
from ...errors import DHLabError
from ...i18n import _, current_language, speaking
from ..book import grade_variants as GV
from ..book.gradebook import PART_COLUMNS
from ..book.submission_row import grade_submission
from ..release.generate import find_source
from ..run import selfcheck
from ..run.isolation import setup
from ..run.reaper import become_subreaper, end_descendants
from ..run.staging import find_submissions, stage
from .wheel import build_wheel

__all__ = ["export", "run", "results", "main", "ROOT_ENV", "CONFIG", "VISIBILITIES", "AutograderError", "ROOT_KERNEL"]

ROOT_ENV = "DHLAB_AUTOGRADER_ROOT"
CONFIG = "dhlab_autograder.json"
SECRET = "secret.key"
SOLUTION = "solution.ipynb"          # the teacher's solution, for the self-check; deleted once it has run
TEACHER = Path("release") / "_teacher"
_SCORE_LINE = re.compile(r"(.* assignment|Tarea .*): [0-9.]+/[0-9]+ (points|puntos)")   # English or Spanish
_NOT_ISOLATED = re.compile(r" \(not isolated: [^\n]*\)$", re.M)
VISIBILITIES = ("hidden", "after_due_date", "after_published", "visible")

SETUP_SH = """#!/usr/bin/env bash
# Gradescope runs this once, in /autograder/source, to build the image every submission runs in:
# dhlab from the wheel in this zip, and the kernel the grader starts (their dependencies from PyPI).
set -euo pipefail
cd "$(dirname "$0")"
PYTHON="${{DHLAB_AUTOGRADER_PYTHON:-python3}}"
if ! "$PYTHON" -m pip --version >/dev/null 2>&1; then
    apt-get update && apt-get install -y python3 python3-pip
fi
export PIP_BREAK_SYSTEM_PACKAGES=1      # the container is the autograder's alone
"$PYTHON" -m pip install --no-input --disable-pip-version-check "./{wheel}" "ipykernel>=6.0" "jupyter_client>=7"
"$PYTHON" -c "import dhlab.grading.export.gradescope, ipykernel, jupyter_client; print('dhlab autograder installed')"
"""

RUN_AUTOGRADER = """#!/usr/bin/env bash
# Gradescope runs this for every submission: grade /autograder/submission, write
# /autograder/results/results.json (no results file: an autograder failure, never a zero).
ROOT="${DHLAB_AUTOGRADER_ROOT:-/autograder}"
PYTHON="${DHLAB_AUTOGRADER_PYTHON:-python3}"
cd "$ROOT"
exec "$PYTHON" -m dhlab.grading.export.gradescope run --root "$ROOT"
"""


ROOT_KERNEL = ("refused to run the student's notebook as root ({why}): as root a notebook could leave a process "
               "that rewrites results.json or the grader, so no score is given. Let the container create users "
               "(useradd) or keep its 'nobody' user, and do not export with --isolation none; then rerun.")


class AutograderError(Exception):
    """Not the student's fault: no results file (Gradescope shows an autograder failure)."""


# --- the zip ------------------------------------------------------------------------------------------

def export(out, secret_file=None, release=None, fallback=None, timeout: float = 30, total_timeout: float | None = None,
           memory_mb: float = 2048, output_mb: float = 10, isolation: str = "auto", source=None) -> Path:
    """Write ``autograder.zip`` (see the module). ``secret_file`` (+ ``release``): personal variants;
    ``source``: the teacher's solution (default: the course checkout's,
    :func:`~dhlab.grading.release.generate.find_source`)."""
    solution = find_source(source).read_bytes()
    variants = secret_file is not None
    if release is not None and not variants:
        raise DHLabError("--release grades personal variants: give --secret-file too (the secret the notebooks "
                         "were released with).")
    if variants:
        if release is None:
            raise DHLabError("Gradescope names the student, not the notebook's file: give --release (the folder "
                             "'dhlab-assign release' wrote), so the student's roster id and variant can be found.")
        GV.setup(secret_file, release, fallback)           # the secret and the roster agree, or a clear error
    config = {"assignment": "puma", "timeout": timeout, "total_timeout": total_timeout or 4 * timeout,
              "memory_mb": memory_mb, "output_mb": output_mb, "isolation": isolation, "variants": variants,
              "fallback": fallback or "roster"}
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="dhlab-export-") as tmp:
        wheel = build_wheel(Path(tmp))
        tmp_zip = out.with_name(f".{out.name}.tmp")
        # 0600 from its first byte: the zip holds the variants' secret (a student's kernel on this
        # machine runs as another user, in a private root where this folder does not exist)
        fd = os.open(tmp_zip, os.O_WRONLY | os.O_CREAT | os.O_TRUNC | os.O_NOFOLLOW, 0o600)
        os.fchmod(fd, 0o600)
        with os.fdopen(fd, "wb") as raw, zipfile.ZipFile(raw, "w", zipfile.ZIP_DEFLATED) as z:
            _add(z, "setup.sh", SETUP_SH.format(wheel=wheel.name), executable=True)
            _add(z, "run_autograder", RUN_AUTOGRADER, executable=True)
            _add(z, CONFIG, json.dumps(config, indent=1) + "\n")
            z.write(wheel, wheel.name)
            _add(z, SOLUTION, solution, private=True)
            if variants:
                _add(z, SECRET, Path(secret_file).read_bytes(), private=True)
                for name in ("variants.json", "manifest.csv"):
                    path = Path(release) / "_teacher" / name
                    if path.is_file():
                        _add(z, (TEACHER / name).as_posix(), path.read_bytes(), private=True)
        os.replace(tmp_zip, out)
    return out


def _add(z: zipfile.ZipFile, name: str, data, executable: bool = False, private: bool = False) -> None:
    """Add ``data`` as ``name``; ``private``: unpacked readable by its owner only (0600)."""
    info = zipfile.ZipInfo(name, date_time=(2020, 1, 1, 0, 0, 0))
    info.external_attr = (0o755 if executable else 0o600 if private else 0o644) << 16
    info.compress_type = zipfile.ZIP_DEFLATED
    z.writestr(info, data)


# --- one submission --------------------------------------------------------------------------------------

def _notebook(submission: Path, names=()) -> Path | str:
    """The submitted notebook, or what the student must fix (a str)."""
    found = find_submissions(submission)
    if len(found) == 1:
        return found[0]
    if not found:
        return "No notebook (.ipynb) was found in your submission: upload your assignment notebook."
    named = [p for p in found if p.name in names]
    if len(named) == 1:
        return named[0]
    return (f"Your submission holds {len(found)} notebooks ({', '.join(p.name for p in found[:5])}): "
            "upload only your assignment notebook.")


def _student(metadata: dict, vs) -> str:
    """The roster id of the submitter: a user's sid, email, or the email's name before '@'."""
    users = metadata.get("users") if isinstance(metadata, dict) else None
    users = [u for u in users if isinstance(u, dict)] if isinstance(users, list) else []
    known = {sid.casefold(): sid for sid in vs.records} | {stem.casefold(): sid for stem, sid in vs.files.items()}
    tried = []
    for user in users:
        email = str(user.get("email") or "")
        for candidate in (user.get("sid"), email, email.split("@")[0] if "@" in email else None):
            if candidate:
                tried.append(str(candidate))
                if str(candidate).casefold() in known:
                    return known[str(candidate).casefold()]
    raise AutograderError(f"the submitter ({', '.join(tried) or 'no user in submission_metadata.json'}) matches no "
                          "student of the roster in release/_teacher: export the autograder again from a release "
                          "whose roster ids are the students' Gradescope emails, their names before '@' or their "
                          "SIDs, then rerun this submission.")


def _grade(root: Path, config: dict) -> dict:
    """The results of the submission under ``root`` (raises :class:`AutograderError`)."""
    source, submission = root / "source", root / "submission"
    resolve, names = None, {"08_puma_assignment.ipynb"}
    if config.get("variants"):
        vs = GV.setup(source / SECRET, source / "release", config.get("fallback"))
        (source / SECRET).unlink(missing_ok=True)          # in memory now: no student code can read it
        shutil.rmtree(source / "release", ignore_errors=True)
        try:
            metadata = json.loads((root / "submission_metadata.json").read_text(encoding="utf-8"))
        except (OSError, ValueError) as e:
            raise AutograderError(f"cannot read submission_metadata.json ({e})") from None
        student = _student(metadata, vs)
        names |= {f"{stem}.ipynb" for stem, sid in vs.files.items() if sid == student}
        resolve = lambda nb, file: GV.resolve(vs, nb, f"{student}.ipynb")
    notebook = _notebook(submission, names)
    if isinstance(notebook, str):
        return {"score": 0.0, "output": notebook, "tests": []}
    checks.check_all(checks.Answers())                     # the reference, built before any student code runs
    into = Path(tempfile.mkdtemp(prefix="dhlab-grade-copies-"))
    os.chmod(into, 0o700)
    options = SimpleNamespace(**{k: config[k] for k in ("timeout", "total_timeout", "memory_mb", "output_mb")})
    iso = None
    try:
        staged = stage(notebook, submission, into, 0, resolve)
        if staged.variant is not None and staged.variant.variant is not None:
            checks.check_all(checks.Answers(), ref=staged.variant.robot)
        try:
            iso = setup(1, config.get("isolation", "auto"))
        except OSError as e:
            raise AutograderError(f"cannot isolate the submission: {e}") from None
        print(f"dhlab autograder: {iso.note() or 'the kernel runs as ' + iso.users[0][0]}", flush=True)
        if os.geteuid() == 0 and iso.mode != "user":
            raise AutograderError(ROOT_KERNEL.format(why=iso.why))
        options.source = source / SOLUTION
        try:
            selfcheck.check(iso, options)
        except selfcheck.SelfCheckError as e:
            raise AutograderError(str(e)) from None
        finally:
            options.source.unlink(missing_ok=True)         # the solution, before any student code runs
        row = grade_submission(staged, options, iso)
    finally:
        shutil.rmtree(into, ignore_errors=True)
        if iso is not None:
            iso.close()
            shutil.rmtree(iso.base, ignore_errors=True)
    if row["score"] == "":
        raise AutograderError(row["status"])
    return results(row)


def results(row: dict) -> dict:
    """Gradescope's results.json for one gradebook row of :func:`dhlab.grading.book.submission_row.grade_submission`:
    one test per part (its feedback as output), the rest of the feedback as the top-level output."""
    parts = row.get("_part_text", {})
    header = row["_feedback_text"]
    for text in parts.values():
        header = header.replace(text, "")
    with speaking(row.get("_language") or current_language()):           # the student's language
        heads = ("Submission:", "File:", _("Submission: {submission}").split("{")[0], _("File: {file}").split("{")[0])
        names = {key: _("Part {number}: {title}").format(number=key[-1], title=_(TITLES[key])) for key in PART_COLUMNS}
    header = "\n".join(line for line in header.splitlines()       # the score is Gradescope's own line
                       if not line.startswith(heads) and not _SCORE_LINE.fullmatch(line))
    header = _NOT_ISOLATED.sub("", header)      # the container is the boundary there: the log says it
    while "\n\n\n" in header:
        header = header.replace("\n\n\n", "\n\n")
    tests = [{"name": names[key], "number": key[-1], "score": float(row[column] or 0),
              "max_score": float(POINTS[key]), "output": parts.get(key, ""), "visibility": "visible"}
             for key, column in PART_COLUMNS.items()]
    return {"score": float(row["score"]), "output": header.strip() + "\n", "visibility": "visible",
            "stdout_visibility": "hidden", "tests": tests,
            "extra_data": {"status": row["status"], **{k: row[k] for k in row if k.startswith(("variant_", "signed"))}}}


def run(root=None) -> int:
    """``run_autograder``: grade the submission under ``root`` (default ``$DHLAB_AUTOGRADER_ROOT`` or
    ``/autograder``) and write its results.json; 1 (and no results file) on an autograder failure."""
    root = Path(root or os.environ.get(ROOT_ENV) or "/autograder")
    started = time.monotonic()
    become_subreaper()                      # a daemon the notebook starts stays our descendant
    try:
        config = json.loads((root / "source" / CONFIG).read_text(encoding="utf-8"))
        outcome = _grade(root, config)
        left = end_descendants()            # before results.json: nothing of the student's is left to rewrite it
        if left:
            print(f"dhlab autograder: ended {len(left)} process(es) the submission left running", flush=True)
    except AutograderError as e:
        _quietly(end_descendants)
        print(f"dhlab autograder: not graded (not the student's fault; rerun it once fixed): {e}", flush=True)
        return 1
    except Exception as e:                                 # our failure, never the student's zero
        _quietly(end_descendants)
        traceback.print_exc(file=sys.stdout)
        print(f"dhlab autograder: not graded (grader error {type(e).__name__}: {e}); rerun it once fixed.", flush=True)
        return 1
    outcome["execution_time"] = round(time.monotonic() - started, 1)
    out = root / "results" / "results.json"
    out.parent.mkdir(parents=True, exist_ok=True)
    tmp = out.with_name(".results.json.tmp")
    tmp.write_text(json.dumps(outcome, indent=1, ensure_ascii=False), encoding="utf-8")
    os.replace(tmp, out)
    print(f"dhlab autograder: {outcome['score']:g} points; results in {out}", flush=True)
    return 0


def _quietly(step) -> None:
    """Run a clean-up step on the way out of a failure (no results file is written anyway)."""
    try:
        step()
    except Exception as e:
        print(f"dhlab autograder: clean-up failed too ({e})", flush=True)


def main(argv=None) -> int:
    """``python -m dhlab.grading.export.gradescope run [--root DIR]`` (what run_autograder calls)."""
    parser = argparse.ArgumentParser(prog="python -m dhlab.grading.export.gradescope",
                                     description=run.__doc__.split(":")[0])
    parser.add_argument("command", choices=["run"])
    parser.add_argument("--root", default=None, help=f"the autograder's folder (default ${ROOT_ENV} or /autograder)")
    return run(parser.parse_args(argv).root)


if __name__ == "__main__":
    sys.exit(main())
