"""Shared fixtures: the verified seed cases."""
import pytest

from seeddata import load_cases


@pytest.fixture(scope="session")
def cases():
    return {c["id"]: c for c in load_cases()}
