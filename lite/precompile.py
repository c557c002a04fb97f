"""Compile the Python files of the site's wheels to bytecode, once, at build time.

Run by lite/precompile.mjs inside Pyodide itself (under Node.js), so that the bytecode is made by
the very Python that runs it in the browser (3.12, same magic number).

Why: the wheels of PyPI and of the Pyodide release hold source only, so every visitor's browser
compiled each module on import, every time (the page's file system starts empty). Under Node.js
``import sympy`` took 6.2 s, IPython 5.1 s, pyplot 3.9 s, against 0.8, 1.7 and 1.4 s from
bytecode; in Chromium the SSRMS notebook's first cell went from 7-11 s to 2 s and the kernel's
start from 17-21 s to 10-14 s. It was the biggest part of the time to a working slider.

How, per wheel:

* the course's own package (``KEEP_SOURCE``) keeps its ``.py`` files and gets
  ``__pycache__/*.cpython-312.pyc`` beside them, as *unchecked-hash* pycs (PEP 552): Python uses
  them without looking at the source's time stamp (which unpacking the wheel changes), and a
  traceback into dhlab still shows its source lines;
* every other wheel gets the modules the course imports (``WORKLOAD``, run here first) as
  ``module.pyc`` in place of ``module.py`` (a "sourceless" module, as ``compileall -b`` writes
  them); the modules it does not import stay source, compiled if ever imported (bytecode is
  bigger than source once zipped: all of sympy would grow 6.3 -> 10.3 MB, its imported part
  grows it much less). A traceback inside sympy or matplotlib then shows file and line without
  the line's text. Bytecode is made without column tables (PYTHONNODEBUGRANGES, set by
  precompile.mjs): about a quarter smaller.

The standard library's zip (``python_stdlib.zip``, from npm, source only too) is treated like a
wheel of the second kind: Pyodide and IPython import some 200 of its modules at every start.

Files no browser needs (``DROP``: test suites, type stubs, fonts for serif and PDF) are left out.
The wheel's RECORD is rewritten to list the files it really holds; entries keep their order and a
fixed time stamp, so the same input gives the same bytes.

Usage (inside Pyodide, the packages loaded): ``precompile(["/host/a.whl", ...])`` rewrites each
wheel (or the standard library's zip) in place and returns ``{file name: (files compiled, bytes
before, bytes after)}``.
"""
from __future__ import annotations

import base64
import hashlib
import importlib.util
import io
import marshal
import os
import re
import sys
import zipfile

KEEP_SOURCE = {"dhlab"}                         # distributions whose .py files stay
# Files no one uses in the browser, left out of the wheels: each package's own test suite (sympy's
# is a third of it), type stubs, and the fonts matplotlib needs only for serif text or for
# PostScript/PDF files (the course's figures use DejaVu Sans and DejaVu Sans Mono; mathtext's
# DejaVu, STIX and Computer Modern fonts stay).
# (jedi's type stubs stay: they are how it completes the standard library's names.)
DROP = re.compile(r"^[^/]+/(.+/)?tests?/|^(?!jedi/).*\.pyi$"
                  r"|^matplotlib/mpl-data/fonts/(afm/|pdfcorefonts/|ttf/DejaVuSerif)")
# What a course session imports: the kernel's stack, the course's package, a teach panel drawn,
# sympy's simplification and printing. The modules this loads are the ones compiled.
WORKLOAD = """
import sys, types
sys.modules.setdefault("resource", types.ModuleType("resource"))   # pyodide_kernel's mock
import IPython, IPython.core.completer, ipywidgets, comm, matplotlib_inline.backend_inline
import asyncio, json, pyodide.http, pyodide.webloop, micropip    # (pyodide_kernel needs a browser)
import matplotlib.pyplot as plt, numpy as np, sympy as sp
import dhlab
from dhlab.views.panels.teach import teach
from dhlab.course.exercises import exercise
import dhlab.data
panel = teach(dhlab.robots.ssrms())
panel.sliders[1].value = 30
robot = dhlab.robots.puma560()
x = sp.Symbol("x")
sp.latex(sp.simplify(sp.sin(x) ** 2 + sp.cos(x) ** 2 + sp.Matrix([[sp.cos(x), 0], [0, 1]]).det()))
sp.trigsimp(sp.expand(robot.fk_sym()[0, 3]))
"""
SITE = f"/lib/python{sys.version_info.major}.{sys.version_info.minor}/site-packages"
STDLIB = f"/lib/python{sys.version_info.major}{sys.version_info.minor}.zip"     # python_stdlib.zip
STAMP = (2026, 1, 1, 0, 0, 0)                   # the time stamp of every file written


def _pyc(source: bytes, path: str, *, hashed: bool) -> bytes:
    """The bytecode file of ``source``; ``path`` is where it is installed (shown in tracebacks)."""
    code = compile(source, path, "exec", dont_inherit=True)
    if hashed:                                  # PEP 552, flags 0b01: hash-based, not checked
        header = importlib.util.MAGIC_NUMBER + (1).to_bytes(4, "little") + importlib.util.source_hash(source)
    else:                                       # sourceless: no source to compare with
        header = importlib.util.MAGIC_NUMBER + bytes(12)
    return header + marshal.dumps(code)


def _record_line(name: str, data: bytes) -> str:
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"{name},sha256={digest},{len(data)}\n"


def imported_files() -> set[str]:
    """The files of the modules :data:`WORKLOAD` imports (and Pyodide imported to start), relative
    to site-packages or, for the standard library, to its zip file."""
    exec(WORKLOAD, {})
    files = set()
    for module in list(sys.modules.values()):
        file = getattr(module, "__file__", None) or ""
        for folder in (SITE, STDLIB):
            if file.startswith(folder + "/") and file.endswith(".py"):
                files.add(file[len(folder) + 1:])
    return files


def precompile_stdlib(path: str, wanted: set[str]) -> tuple[int, int, int]:
    """The standard library's zip (python_stdlib.zip), with the modules in ``wanted`` as bytecode
    (sourceless: zipimport loads ``module.pyc`` when there is no ``module.py``)."""
    before = os.path.getsize(path)
    with zipfile.ZipFile(path) as archive:
        members = [(info.filename, archive.read(info)) for info in archive.infolist()]
    out, compiled = [], 0
    for name, data in members:
        if name in wanted:
            out.append((name + "c", _pyc(data, f"{STDLIB}/{name}", hashed=False)))
            compiled += 1
        else:
            out.append((name, data))
    _write_zip(path, out)
    return compiled, before, os.path.getsize(path)


def _write_zip(path: str, members) -> None:
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w") as archive:
        for name, data in members:
            info = zipfile.ZipInfo(name, date_time=STAMP)
            info.external_attr = (0o755 if name.endswith("/") else 0o644) << 16
            archive.writestr(info, data, compress_type=zipfile.ZIP_DEFLATED, compresslevel=9)
    tmp = path + ".tmp"
    with open(tmp, "wb") as f:
        f.write(buffer.getvalue())
    os.replace(tmp, path)


def precompile_wheel(path: str, wanted: set[str]) -> tuple[int, int, int]:
    before = os.path.getsize(path)
    with zipfile.ZipFile(path) as wheel:
        members = [(info, wheel.read(info)) for info in wheel.infolist() if not info.is_dir()]
    dist = next(info.filename.split("/")[0] for info, _ in members if ".dist-info/" in info.filename)
    keep_source = dist.split("-")[0].lower() in KEEP_SOURCE
    out, compiled = [], 0
    for info, data in members:
        name = info.filename
        if DROP.search(name):
            continue
        if (not name.endswith(".py") or name.startswith(dist) or ".data/" in name.split("/")[0] + "/"
                or not (keep_source or name in wanted)):
            out.append((name, data))
            continue
        try:
            pyc = _pyc(data, f"{SITE}/{name}", hashed=keep_source)
        except (SyntaxError, ValueError):       # e.g. a test fixture that is not Python 3.12
            out.append((name, data))
            continue
        compiled += 1
        folder, _, module = name.rpartition("/")
        if keep_source:
            out.append((name, data))
            tag = sys.implementation.cache_tag
            out.append((f"{folder + '/' if folder else ''}__pycache__/{module[:-3]}.{tag}.pyc", pyc))
        else:
            out.append((name + "c", pyc))
    record = f"{dist}/RECORD"
    out = [(n, d) for n, d in out if n != record]
    out.append((record, "".join(_record_line(n, d) for n, d in out).encode() + f"{record},,\n".encode()))
    _write_zip(path, out)
    return compiled, before, os.path.getsize(path)


def precompile(paths) -> dict:
    """Run the workload (its packages must be loaded), then rewrite each wheel."""
    wanted = imported_files()
    return {os.path.basename(p): precompile_stdlib(p, wanted) if p.endswith("python_stdlib.zip")
            else precompile_wheel(p, wanted) for p in paths}
