"""Shared fixtures (the verified seed cases); nbval's kernels on private Unix sockets.

Why the sockets: see tests/kernelsockets.py (the flaky "Kernel didn't respond in 60 seconds").
"""
import os

import pytest
from hypothesis import settings

from kernelsockets import PrivateSocketKernelManager
from seeddata import load_cases


def _private_sockets_for_nbval():
    try:
        import nbval.kernel
    except ImportError:          # nbval is only needed for the notebooks
        return
    nbval.kernel.KernelManager = PrivateSocketKernelManager


_private_sockets_for_nbval()

# Property-based tests draw the same examples on every run ("ci", the default), so the suite
# cannot pass today and fail tomorrow on luck; HYPOTHESIS_PROFILE=explore draws new ones each
# run to hunt for bugs (a failure prints the example and how to reproduce it).
settings.register_profile("ci", derandomize=True, database=None, deadline=None, print_blob=True)
settings.register_profile("explore", deadline=None, print_blob=True)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))


@pytest.fixture(scope="session")
def cases():
    return {c["id"]: c for c in load_cases()}
