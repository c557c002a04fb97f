"""Shared fixtures: the verified seed cases (a copy of shared/reference/seed_cases.json)."""
import json
from pathlib import Path

import pytest

DATA = Path(__file__).parent / "data"


def load_cases():
    return json.loads((DATA / "seed_cases.json").read_text(encoding="utf-8"))["cases"]


@pytest.fixture(scope="session")
def cases():
    return {c["id"]: c for c in load_cases()}
