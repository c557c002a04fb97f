"""Serve the built browser edition (build/lite/) on 127.0.0.1 for a look, or for the test tier.

    python lite/serve.py [--port 8000] [--root build/lite] [--quiet]

Any static web server does the same job (GitHub Pages, nginx, ``python -m http.server``); this
one only makes sure ``.wasm`` and ``.mjs`` go out with the types browsers want, on every Python.
"""
from __future__ import annotations

import argparse
import functools
import http.server
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
TYPES = {".wasm": "application/wasm", ".mjs": "text/javascript", ".js": "text/javascript",
         ".json": "application/json", ".whl": "application/zip", ".ipynb": "application/json"}


class Handler(http.server.SimpleHTTPRequestHandler):
    extensions_map = {**http.server.SimpleHTTPRequestHandler.extensions_map, **TYPES}
    quiet = False

    def log_message(self, format, *args):
        if not self.quiet:
            super().log_message(format, *args)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--port", type=int, default=8000)
    parser.add_argument("--root", type=Path, default=ROOT / "build" / "lite")
    parser.add_argument("--quiet", action="store_true", help="do not log each request")
    args = parser.parse_args(argv)
    if not (args.root / "index.html").exists():
        raise SystemExit(f"{args.root} has no site: run `make lite` first")
    Handler.quiet = args.quiet
    handler = functools.partial(Handler, directory=str(args.root))
    with http.server.ThreadingHTTPServer(("127.0.0.1", args.port), handler) as server:
        print(f"the course in the browser: http://127.0.0.1:{server.server_address[1]}/  (Ctrl-C stops)",
              flush=True)
        try:
            server.serve_forever()
        except KeyboardInterrupt:
            pass


if __name__ == "__main__":
    main()
