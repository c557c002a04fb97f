"""Run an ``autograder.zip`` the way Gradescope does, on this machine (no Docker, no network).

    dhlab-grade export try-gradescope autograder.zip NOTEBOOK [--email ana@uni.edu] [--keep DIR]

Like ``otter run``, it builds an ``/autograder`` tree in a temporary folder and points the
autograder at it (``DHLAB_AUTOGRADER_ROOT``):

1. :class:`Harness` runs the zip's ``setup.sh`` once, as Gradescope does when the teacher
   uploads it, into a fresh virtual environment of its own. Offline, that environment reaches
   the libraries of the Python running this (a ``.pth`` file) and pip may not use the network
   (``PIP_NO_INDEX``), so dhlab itself comes from the zip's wheel and nothing else is fetched;
2. :meth:`Harness.run` is one submission, in a fresh tree (Gradescope's fresh container):
   the zip unpacked into ``source/``, the student's files in ``submission/``,
   ``submission_metadata.json``, an empty ``results/``; then ``run_autograder``, and the
   ``results.json`` it wrote (None: an autograder failure);
3. :func:`problems` checks a results.json against Gradescope's documented schema.
"""
from __future__ import annotations

import json
import os
import shutil
import site
import subprocess
import sys
import tempfile
import zipfile
from dataclasses import dataclass
from pathlib import Path

from .gradescope import ROOT_ENV, VISIBILITIES

__all__ = ["Harness", "Outcome", "problems", "metadata", "TOP_KEYS", "TEST_KEYS"]

TOP_KEYS = {"score", "execution_time", "output", "output_format", "test_output_format", "test_name_format",
            "visibility", "stdout_visibility", "extra_data", "tests", "leaderboard"}
TEST_KEYS = {"score", "max_score", "status", "name", "name_format", "number", "output", "output_format",
             "tags", "visibility", "extra_data"}


def metadata(email: str = "student@example.edu", name: str = "A Student", sid: str = "") -> dict:
    """A ``submission_metadata.json`` as Gradescope writes it (the fields the autograder reads)."""
    return {"id": 1, "created_at": "2026-01-01T00:00:00.000000-08:00", "submission_method": "upload",
            "assignment": {"id": 1, "title": "PUMA assignment", "total_points": "10.0"},
            "users": [{"email": email, "id": 1, "name": name, "sid": sid}], "previous_submissions": []}


@dataclass
class Outcome:
    """One run of ``run_autograder``: its results.json (None when it wrote none) and its log."""
    results: dict | None
    returncode: int
    log: str


class Harness:
    """An autograder zip, set up once (``setup.sh``) in ``folder``, ready to run submissions."""

    def __init__(self, zip_path, folder, timeout: float = 600):
        self.zip, self.folder = Path(zip_path), Path(folder)
        self.python = self._environment()
        source = self.folder / "setup"
        self._unpack(source)
        proc = subprocess.run(["bash", str(source / "setup.sh")], cwd=source, env=self._env(PIP_NO_INDEX="1"),
                              capture_output=True, text=True, timeout=timeout)
        if proc.returncode != 0:
            raise RuntimeError(f"setup.sh failed (exit {proc.returncode}): {(proc.stdout + proc.stderr)[-2000:]}")

    def _environment(self) -> Path:
        """A virtual environment whose own site-packages come first, reaching this Python's libraries."""
        venv = self.folder / "venv"
        subprocess.run([sys.executable, "-m", "venv", "--without-pip", str(venv)], check=True)
        python = venv / "bin" / "python"
        own = subprocess.run([str(python), "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
                             capture_output=True, text=True, check=True).stdout.strip()
        Path(own, "dhlab-harness-libraries.pth").write_text("\n".join(site.getsitepackages()) + "\n")
        return python

    def _env(self, **extra) -> dict:
        env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME", ROOT_ENV)}
        env.update(DHLAB_AUTOGRADER_PYTHON=str(self.python), PATH=f"{self.python.parent}:{env.get('PATH', '')}",
                   **extra)
        return env

    def _unpack(self, source: Path) -> None:
        source.mkdir(parents=True)
        with zipfile.ZipFile(self.zip) as z:
            z.extractall(source)
            for info in z.infolist():                    # zipfile drops the executable bits
                mode = info.external_attr >> 16
                if mode:
                    os.chmod(source / info.filename, mode & 0o777)

    def run(self, files, meta: dict | None = None, timeout: float = 900, env=None) -> Outcome:
        """One submission (``files``: paths copied into ``submission/``) in a fresh tree."""
        root = Path(tempfile.mkdtemp(prefix="autograder-", dir=self.folder))
        try:
            self._unpack(root / "source")
            (root / "submission").mkdir()
            (root / "results").mkdir()
            for path in files:
                shutil.copy(path, root / "submission" / Path(path).name)
            (root / "submission_metadata.json").write_text(json.dumps(meta or metadata()), encoding="utf-8")
            shutil.copy(root / "source" / "run_autograder", root / "run_autograder")
            proc = subprocess.run([str(root / "run_autograder")], cwd=root, capture_output=True, text=True,
                                  timeout=timeout, env=self._env(**{ROOT_ENV: str(root)}, **(env or {})))
            out = root / "results" / "results.json"
            results = json.loads(out.read_text(encoding="utf-8")) if out.exists() else None
            return Outcome(results, proc.returncode, proc.stdout + proc.stderr)
        finally:
            shutil.rmtree(root, ignore_errors=True)


def _number(x) -> bool:
    return isinstance(x, (int, float)) and not isinstance(x, bool)


def problems(results) -> list:
    """What in ``results`` does not follow Gradescope's results.json schema ([] when all does)."""
    if not isinstance(results, dict):
        return ["results.json is not a JSON object"]
    out = [f"unknown key {k!r}" for k in results if k not in TOP_KEYS]
    if "score" in results and not _number(results["score"]):
        out.append("score is not a number")
    if "score" not in results and "tests" not in results:
        out.append("neither score nor tests")
    for key in ("output", "stdout_visibility", "visibility"):
        if key in results and not isinstance(results[key], str):
            out.append(f"{key} is not a string")
    for key in ("visibility", "stdout_visibility"):
        if key in results and results[key] not in VISIBILITIES:
            out.append(f"{key} {results[key]!r} is not one of {VISIBILITIES}")
    tests = results.get("tests", [])
    if not isinstance(tests, list):
        return out + ["tests is not a list"]
    for k, test in enumerate(tests):
        if not isinstance(test, dict):
            out.append(f"tests[{k}] is not an object")
            continue
        out += [f"tests[{k}]: unknown key {key!r}" for key in test if key not in TEST_KEYS]
        for key in ("score", "max_score"):
            if key in test and not _number(test[key]):
                out.append(f"tests[{k}].{key} is not a number")
        if _number(test.get("score")) and _number(test.get("max_score")) and test["score"] > test["max_score"]:
            out.append(f"tests[{k}] scores more than its max_score")
        for key in ("name", "output"):
            if key in test and not isinstance(test[key], str):
                out.append(f"tests[{k}].{key} is not a string")
        if "visibility" in test and test["visibility"] not in VISIBILITIES:
            out.append(f"tests[{k}].visibility {test['visibility']!r} is not one of {VISIBILITIES}")
    return out
