"""The browser edition's first working slider, side by side: two built sites, cold visits alternated.

    python benchmarks/bench_lite_first_slider.py OLD_SITE NEW_SITE [--visits 6] [--json FILE]

For each visit, in a fresh browser context (empty cache and storage, as a student's first visit):
open the SSRMS notebook, run its code cells from the top until its first slider shows, move that
slider and wait for the figure to change. It prints, per site, the median and range of
"open -> kernel ready", of the cells and the move after it, and of "open -> first slider move
redrawn" (the tier's own measure,
tests/lite/test_lite_notebooks.py), and the ratio new/old of the medians. Old and new alternate,
so that the machine's load falls on both alike; the load average is printed beside.

Needs what tests/lite needs: Debian's Chromium and playwright (bash tests/browser/setup.sh), and
two built sites: without them (as ``make bench`` runs it) it says so and stops, successfully. To
build the old one, unpack its commit elsewhere (``git archive COMMIT | tar -x -C /tmp/old``) and run
``build/lite-venv/bin/python /tmp/old/lite/build.py`` with ``DHLAB_PYODIDE_WHEELS`` set to the shared
Pyodide wheels; the site is then ``/tmp/old/build/lite``.
"""
from __future__ import annotations

import argparse
import json
import os
import socket
import statistics
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path[:0] = [str(ROOT / "tests" / "lite"), str(ROOT / "tests")]

from test_lite_notebooks import SSRMS, first_panel, move_slider, run_until_slider  # noqa: E402

import litedriver as driver  # noqa: E402  (tests/lite: the tier's driver)
from support.browser_tiers import CHROMIUM_ARGS  # noqa: E402


def serve(site: Path) -> tuple[subprocess.Popen, str]:
    """lite/serve.py on a free loopback port: (the process, its URL)."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    process = subprocess.Popen([sys.executable, str(ROOT / "lite" / "serve.py"), "--port", str(port),
                                "--root", str(site), "--quiet"], stdout=subprocess.DEVNULL)
    url = f"http://127.0.0.1:{port}"
    for _ in range(150):
        try:
            urllib.request.urlopen(url + "/index.html", timeout=2)
            return process, url
        except OSError:
            time.sleep(0.2)
    process.kill()
    raise SystemExit(f"lite/serve.py did not start for {site}")


def cold_visit(browser, url: str) -> tuple[float, float]:
    """One cold visit: seconds from opening to the kernel ready, and to the first slider move redrawn."""
    context = browser.new_context(viewport={"width": 1400, "height": 1000})
    try:
        driver.expose_app(context, url)
        page = context.new_page()
        start = time.monotonic()
        driver.open_notebook(page, url, SSRMS)
        ready = time.monotonic() - start
        code = [i for i, c in enumerate(driver.cells(page)) if c["type"] == "code" and c["source"].strip()]
        if run_until_slider(page, code) is None:
            raise SystemExit(f"{url}: no slider in {SSRMS}")
        move_slider(page, first_panel(page), fraction=0.5)
        return ready, time.monotonic() - start
    finally:
        context.close()


def summary(values) -> str:
    return f"{statistics.median(values):.1f} s ({min(values):.1f}-{max(values):.1f})"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("old", type=Path, nargs="?", help="the built site to compare against (a build/lite folder)")
    parser.add_argument("new", type=Path, nargs="?", help="the built site measured")
    parser.add_argument("--visits", type=int, default=6, help="cold visits of each site (default 6)")
    parser.add_argument("--json", type=Path, help="also write the visits' times to this file")
    args = parser.parse_args()
    if not (args.old and args.new and (args.old / "index.html").exists() and (args.new / "index.html").exists()):
        print("needs two built sites (OLD_SITE NEW_SITE, each a folder with index.html): nothing measured")
        return
    from playwright.sync_api import sync_playwright

    chromium = os.environ.get("DHLAB_CHROMIUM", "/usr/bin/chromium")
    servers = {name: serve(site) for name, site in (("old", args.old), ("new", args.new))}
    results = {"old": [], "new": []}
    try:
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path=chromium, headless=True, args=CHROMIUM_ARGS + [
                "--host-resolver-rules=MAP * ~NOTFOUND , EXCLUDE 127.0.0.1"])
            for visit in range(args.visits):
                for name in (("old", "new") if visit % 2 == 0 else ("new", "old")):
                    ready, working = cold_visit(browser, servers[name][1])
                    results[name].append((ready, working))
                    load = "/".join(f"{x:.1f}" for x in os.getloadavg())
                    print(f"visit {visit + 1} {name}: kernel ready {ready:.1f} s, first slider move redrawn "
                          f"{working:.1f} s (load {load})", flush=True)
            browser.close()
    finally:
        for process, _url in servers.values():
            process.terminate()
    for name in ("old", "new"):
        ready, working = zip(*results[name])
        cells = [w - r for r, w in results[name]]       # the notebook's cells up to the moved slider
        print(f"{name}: kernel ready {summary(ready)}, then the cells and the move {summary(cells)}, "
              f"first slider move redrawn {summary(working)}")
    medians = {name: statistics.median(w for _r, w in results[name]) for name in results}
    print(f"first slider, new/old: {medians['new'] / medians['old']:.2f}")
    if args.json:
        args.json.write_text(json.dumps({name: [{"kernel ready [s]": round(r, 2), "first slider move redrawn [s]":
                                                 round(w, 2)} for r, w in results[name]] for name in results},
                                        indent=2))


if __name__ == "__main__":
    main()
