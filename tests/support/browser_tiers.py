"""What the two browser tiers share (tests/browser: JupyterLab and Voilà; tests/lite: the JupyterLite
site): the switch that runs a tier only when asked for, and Debian's Chromium driven by Playwright.

A tier's ``conftest.py`` calls :func:`add_tier_option` and :func:`skip_unless_asked` from its hooks and
defines the fixture ``chromium_args`` (the command line its Chromium starts with); the fixtures
``chromium_path`` and ``browser`` come from here (tests/conftest.py loads this module as a plugin).
"""
from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest

CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync", "--no-first-run"]


def add_tier_option(parser, name: str, help: str) -> None:
    """``--name`` (or ``--run-name``) runs the tier; without it its tests are skipped."""
    parser.addoption(f"--{name}", f"--run-{name}", dest=f"run_{name}", action="store_true", default=False,
                     help=help)


def asked_for(config, name: str, env: str) -> bool:
    """Whether the tier was asked for, on the command line or by the environment variable ``env``."""
    try:
        asked = config.getoption(f"run_{name}")
    except ValueError:                      # option not registered (conftest loaded late)
        asked = False
    return bool(asked or os.environ.get(env))


def skip_unless_asked(config, items, folder: Path, name: str, env: str, reason: str) -> None:
    """Mark the tests under ``folder`` skipped (``reason`` says how to run them) unless asked for."""
    if asked_for(config, name, env):
        return
    skip = pytest.mark.skip(reason=reason)
    for item in items:
        if folder in Path(str(item.fspath)).resolve().parents:
            item.add_marker(skip)


@pytest.fixture(scope="session")
def chromium_path():
    """Debian's Chromium (``apt-get install chromium``) or ``DHLAB_CHROMIUM``: Playwright's own browser
    download is not used."""
    path = os.environ.get("DHLAB_CHROMIUM") or shutil.which("chromium") or "/usr/bin/chromium"
    if not Path(path).exists():
        pytest.fail("the browser tiers need Chromium: apt-get install -y chromium (or set DHLAB_CHROMIUM)")
    return path


@pytest.fixture(scope="session")
def browser(chromium_path, chromium_args):
    """One headless Chromium for the session, started with the tier's ``chromium_args``."""
    playwright = pytest.importorskip("playwright.sync_api", reason="pip install playwright")
    with playwright.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=chromium_path, args=chromium_args, headless=True)
        yield browser
        browser.close()
