"""The conda route (environment.yml) installs what `make setup` installs, so the two never drift apart."""
from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def _make_setup_install() -> str:
    """The pip line of `make setup` that installs the course (its extras and constraints)."""
    lines = [line for line in (ROOT / "Makefile").read_text().splitlines() if '-e ".[' in line]
    assert len(lines) == 1, lines
    return lines[0]


def _environment_lines() -> list[str]:
    return [line.strip() for line in (ROOT / "environment.yml").read_text().splitlines()
            if line.strip().startswith("- ")]


def test_environment_installs_the_make_setup_extras():
    extras = re.search(r'-e "\.\[([a-z,]+)\]"', _make_setup_install()).group(1)
    assert f"- -e .[{extras}]" in _environment_lines()


def test_environment_uses_the_same_constraints():
    assert "-c constraints.txt" in _make_setup_install()
    assert "- -c constraints.txt" in _environment_lines()


def test_conda_itself_installs_only_python_and_pip():
    """A version written here as well as in constraints.txt would drift: conda gives only Python and pip."""
    conda = [line[2:] for line in _environment_lines() if not line.startswith("- -") and line != "- pip:"]
    names = {re.split(r"[<>=]", spec)[0] for spec in conda}
    assert names <= {"python", "pip", "conda-forge"}, conda
