"""Shared fixtures (the verified seed cases, one grading batch at a time); nbval's kernels on
private Unix sockets.

Why the sockets: see tests/support/kernelsockets.py (the flaky "Kernel didn't respond in 60 seconds").
"""
import fcntl
import os
import shutil
import tempfile

import pytest
from hypothesis import settings

from support.kernelsockets import PrivateSocketKernelManager
from support.seeddata import load_cases

# the browser tiers' Chromium (tests/browser, tests/lite: each asks for it with its own chromium_args)
pytest_plugins = ["support.browser_tiers"]


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


@pytest.fixture(scope="module")
def one_batch_at_a_time():
    """Hold a lock while a module grades a class, so the other pytest worker's batch waits.

    Two graders at once are safe (each locks its own kernel users: dhlab.grading.run.isolation.claim;
    tests/grading/test_grading_isolation.py proves it), but a test that asserts "no kernel of the grader
    is left running" cannot tell its own batch's kernels from the other worker's."""
    with open(os.path.join(tempfile.gettempdir(), "dhlab-tests-one-batch.lock"), "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        yield


@pytest.fixture(scope="module")
def package(one_batch_at_a_time):
    """dhlab copied into a folder every user can read, for a module's grader runs (PYTHONPATH):
    a submission that tampers with "the installed dhlab" touches only the copy, and no one editing
    this working tree disturbs the grader's check that its package is unchanged."""
    from support.grader import package_copy
    folder = package_copy()
    yield folder
    shutil.rmtree(folder, ignore_errors=True)
