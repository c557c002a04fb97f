"""The browser edition's tier: the built JupyterLite site (build/lite/) in Chromium, via Playwright.

Not part of the main test run: these tests are skipped unless asked for,

    make test-lite                               # builds the site, then runs this tier
    python -m pytest tests/lite --lite -p no:xdist   (or DHLAB_LITE_TESTS=1)

They need the built site (``make lite``), Debian's Chromium (``/usr/bin/chromium`` or
``DHLAB_CHROMIUM``; a test tool's own browser download does not work here) and ``pip install
playwright`` (``bash tests/browser/setup.sh`` installs both). The site is served on 127.0.0.1 by
``lite/serve.py``; Chromium resolves no other host, and any request for one fails the test.
Measurements (times, download size) go to build/lite-measurements.json and the end of the report.
"""
from __future__ import annotations

import json
import os
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import pytest

from support.browser_tiers import CHROMIUM_ARGS, add_tier_option, skip_unless_asked

HERE = Path(__file__).parent
ROOT = HERE.parent.parent
SITE = Path(os.environ.get("DHLAB_LITE_SITE", ROOT / "build" / "lite"))   # another build: DHLAB_LITE_SITE
MEASUREMENTS = ROOT / "build" / "lite-measurements.json"


def pytest_addoption(parser):
    add_tier_option(parser, "lite", "run the browser-edition tests in tests/lite (JupyterLite + Chromium)")


def pytest_collection_modifyitems(config, items):
    skip_unless_asked(config, items, HERE, "lite", "DHLAB_LITE_TESTS", "browser-edition tier: run `make test-lite`")


@pytest.fixture(scope="session")
def chromium_args():
    # nothing but loopback resolves: a request for another host cannot leave the machine
    return CHROMIUM_ARGS + ["--host-resolver-rules=MAP * ~NOTFOUND , EXCLUDE 127.0.0.1"]


_measured: dict = {}


@pytest.fixture(scope="session")
def measurements():
    """A dict the tests fill; written to build/lite-measurements.json at the end."""
    return _measured


def pytest_terminal_summary(terminalreporter):
    if not _measured:
        return
    MEASUREMENTS.parent.mkdir(exist_ok=True)
    _measured["machine: cores, load average over 1/5/15 min at the end"] = \
        f"{os.cpu_count()}, " + "/".join(f"{x:.1f}" for x in os.getloadavg())
    # a run of some tests (-k) updates their entries and keeps the others' from earlier runs
    try:
        everything = json.loads(MEASUREMENTS.read_text())
    except (OSError, ValueError):
        everything = {}
    everything.update(_measured)
    MEASUREMENTS.write_text(json.dumps(everything, indent=2, sort_keys=True))
    terminalreporter.section("browser edition: measurements")
    for key, value in sorted(_measured.items()):
        terminalreporter.write_line(f"{key}: {value}")


@pytest.fixture(scope="session")
def site():
    if not (SITE / "index.html").exists():
        pytest.fail("no site in build/lite: run `make lite` (or `make test-lite`, which builds it)")
    return SITE


@pytest.fixture(scope="session")
def base_url(site):
    """lite/serve.py serving the site on 127.0.0.1 for the whole session."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    process = subprocess.Popen([sys.executable, str(ROOT / "lite" / "serve.py"), "--port", str(port),
                                "--root", str(site), "--quiet"], stdout=subprocess.DEVNULL,
                               start_new_session=True)
    url = f"http://127.0.0.1:{port}"
    deadline = time.monotonic() + 30
    while True:
        try:
            urllib.request.urlopen(url + "/index.html", timeout=2)
            break
        except OSError:
            if process.poll() is not None or time.monotonic() > deadline:
                process.kill()
                pytest.fail("lite/serve.py did not start")
            time.sleep(0.2)
    yield url
    process.terminate()
    process.wait(timeout=10)


class Visit:
    """A cold visit: a fresh browser context (empty cache and storage) that records every request
    and fails on one that is not for the local site."""

    def __init__(self, browser, base_url):
        from litedriver import expose_app

        self.base_url = base_url
        self.context = browser.new_context(viewport={"width": 1400, "height": 1000})
        self.outside, self.urls = [], []
        self.context.on("request", self._record)
        expose_app(self.context, base_url)
        self.page = self.context.new_page()
        # uncaught exceptions and console.error() of the page and of its workers (Pyodide's):
        # the test fails on any (the site turns off what made them: lite/jupyter-lite.json)
        self.console_errors = []
        self.page.on("pageerror", lambda error: self.console_errors.append(
            "uncaught: " + " | ".join((error.stack or str(error)).splitlines()[:3])))
        self.page.on("console", lambda message: message.type == "error" and self.console_errors.append(
            "console.error: " + " | ".join(message.text.splitlines()[:3])))

    def _record(self, request):
        url = request.url
        if url.startswith((self.base_url + "/", "data:", "blob:")):
            self.urls.append(url)
        else:
            self.outside.append(url)

    def downloaded_bytes(self, site: Path) -> int:
        """Bytes of the site's files this visit fetched (each file once, as a browser cache would)."""
        files = {url[len(self.base_url) + 1:].split("?")[0].split("#")[0] for url in self.urls
                 if url.startswith(self.base_url)}
        return sum((site / f).stat().st_size for f in files if f and (site / f).is_file())

    def close(self):
        self.context.close()


@pytest.fixture
def visit(browser, base_url):
    visits = []

    def start():
        visits.append(Visit(browser, base_url))
        return visits[-1]
    yield start
    for v in visits:
        outside = v.outside
        v.close()
        assert not outside, f"requests that would leave the machine: {outside[:10]}"
