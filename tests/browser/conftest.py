"""The real-browser tier: JupyterLab (and Voilà) driven by Playwright with Debian's Chromium.

Not part of the main test run: these tests are skipped unless asked for,

    bash tests/browser/setup.sh                  # chromium (apt), playwright + voila (pip)
    python -m pytest tests/browser --browser     (or --run-browser, or DHLAB_BROWSER_TESTS=1)

They need ``apt-get install chromium`` (``/usr/bin/chromium``, or set
``DHLAB_CHROMIUM``) and ``pip install playwright`` (its own browser download is
not used); the Voilà test also needs ``pip install voila`` (skipped without it). Each test
starts its own server on 127.0.0.1 with a random token.
"""
from __future__ import annotations

import os
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import pytest

from labdriver import write_lab_settings
from support.browser_tiers import CHROMIUM_ARGS, add_tier_option, skip_unless_asked

HERE = Path(__file__).parent
collect_ignore_glob = ["*.ipynb", "results/*"]   # notebooks are opened by the tests, not run by nbval
RESULTS = HERE / "results"             # screenshots and measurements, kept for a look (and by CI)


def pytest_addoption(parser):
    add_tier_option(parser, "browser", "run the real-browser tests in tests/browser (JupyterLab/Voilà + Chromium)")


def pytest_collection_modifyitems(config, items):
    skip_unless_asked(config, items, HERE, "browser", "DHLAB_BROWSER_TESTS",
                      "browser tier: run `python -m pytest tests/browser --browser`")


@pytest.fixture(scope="session")
def chromium_args():
    return CHROMIUM_ARGS


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Server:
    """A Jupyter server process on 127.0.0.1, stopped (and its kernels with it) at the end."""

    def __init__(self, args, root: Path, ready_path: str, timeout: float = 90):
        self.port = free_port()
        self.token = os.urandom(12).hex()
        self.root = root
        # no news or update pop-ups over the notebook; every cell kept in the DOM
        write_lab_settings(root)
        env = dict(os.environ, JUPYTERLAB_SETTINGS_DIR=str(root / ".settings"),
                   JUPYTERLAB_WORKSPACES_DIR=str(root / ".workspaces"),
                   JUPYTER_RUNTIME_DIR=str(root / ".runtime"))
        self.log = open(root / "server.log", "wb")
        command = [sys.executable, "-m", *args, f"--port={self.port}", "--no-browser"]
        self.process = subprocess.Popen([c.format(port=self.port, token=self.token) for c in command],
                                        cwd=root, env=env, stdout=self.log, stderr=subprocess.STDOUT,
                                        start_new_session=True)
        self.url = f"http://127.0.0.1:{self.port}"
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if self.process.poll() is not None:
                raise RuntimeError(f"server exited: {(root / 'server.log').read_text()[-3000:]}")
            try:
                urllib.request.urlopen(self.url + ready_path.format(token=self.token), timeout=2)
                return
            except OSError:
                time.sleep(0.5)
        self.stop()
        raise RuntimeError(f"server not ready in {timeout} s: {(root / 'server.log').read_text()[-3000:]}")

    def stop(self):
        if self.log.closed:
            return
        if self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(timeout=20)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait(timeout=10)
        self.log.close()


@pytest.fixture
def start_server():
    """``start_server(args, root, ready_path)`` -> a running :class:`Server`, stopped after the test."""
    started = []

    def start(*args, **kwargs):
        started.append(Server(*args, **kwargs))
        return started[-1]
    yield start
    for server in started:
        server.stop()


@pytest.fixture(scope="session")
def results_dir():
    """``tests/browser/results``: what the tier leaves behind (screenshots, latency.json)."""
    RESULTS.mkdir(exist_ok=True)
    return RESULTS


@pytest.fixture(scope="session")
def lab_root(tmp_path_factory):
    """A folder for the session's JupyterLab, where the tests put notebook copies."""
    return tmp_path_factory.mktemp("lab")


@pytest.fixture(scope="session")
def lab_server(lab_root):
    """One JupyterLab for the whole session (starting one takes seconds), on ``lab_root``."""
    from labdriver import lab_command

    server = Server(lab_command(lab_root), lab_root, "/api/status?token={token}")
    yield server
    server.stop()


@pytest.fixture(scope="session")
def lab_page(browser, lab_server):
    """One JupyterLab page, 1400 px wide, for the whole session: each test opens
    its notebook in it, runs it and closes it (loading JupyterLab takes seconds)."""
    from labdriver import open_lab

    page = open_lab(browser, lab_server)
    yield page
    page.close()
