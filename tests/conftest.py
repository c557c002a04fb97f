"""Shared fixtures (the verified seed cases); nbval's kernels on private Unix sockets.

Why the sockets: see tests/kernelsockets.py (the flaky "Kernel didn't respond in 60 seconds").
"""
import pytest

from kernelsockets import PrivateSocketKernelManager
from seeddata import load_cases


def _private_sockets_for_nbval():
    try:
        import nbval.kernel
    except ImportError:          # nbval is only needed for the notebooks
        return
    nbval.kernel.KernelManager = PrivateSocketKernelManager


_private_sockets_for_nbval()


@pytest.fixture(scope="session")
def cases():
    return {c["id"]: c for c in load_cases()}
