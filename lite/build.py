"""Build the browser edition of the course: a static JupyterLite site in build/lite/.

    make lite                 (or: build/lite-venv/bin/python lite/build.py)

Every piece is pinned and checked, and nothing in the finished site points outside it:

* JupyterLite and its Pyodide kernel (lite/requirements.txt) come from PyPI into the build-only
  venv build/lite-venv; the site is the output of ``jupyter lite build``.
* The Pyodide 0.27.7 core (``pyodide.js``, ``pyodide.asm.wasm``, ``python_stdlib.zip``, and
  ``pyodide-lock.json`` with the sha256 of every package of the release) comes from npm
  (``npm pack pyodide@0.27.7``), checked against the npm integrity pinned below.
* The release's compiled wheels (numpy, matplotlib, ...) come from ``../shared/pyodide-0.27.7``
  (or ``$DHLAB_PYODIDE_WHEELS``), or else from the release's CDN when it is reachable; each is
  checked against the sha256 that npm's ``pyodide-lock.json`` records for it.
* The pure wheels sympy, mpmath, comm, ipywidgets, ipympl and anywidget come from PyPI (lite/site-wheels.txt,
  hash-pinned); dhlab's own wheel is built from this checkout.
* The JupyterLab extensions installed in the build venv are built in: ipywidgets', ipympl's, anywidget's and
  jupyterlab-slideshow's (the lecture decks, offline), and the Spanish language pack
  (lite/requirements.txt); the site also carries notebooks/es/ (the Spanish edition) in es/, the
  lecture plans of docs/lecturers/ in lecture_plans/, and the docs site (make docs) in docs/.

The site's ``pyodide-lock.json`` lists only what it ships, with ``imports`` and ``depends`` for
the added wheels, so that a cell's ``import dhlab`` loads numpy, sympy, matplotlib, ipywidgets and
ipympl with no ``%pip`` cell; ``disablePyPIFallback`` keeps the kernel off PyPI.
"""
from __future__ import annotations

import base64
import hashlib
import json
import os
import shutil
import subprocess
import sys
import tarfile
import urllib.request
import zipfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
LITE = ROOT / "lite"
BUILD = Path(os.environ.get("DHLAB_LITE_BUILD", ROOT / "build"))   # another folder: a build of one's own
CACHE = BUILD / "lite-cache"
STAGE = BUILD / "lite-stage"          # the "lite dir" that jupyter lite build reads
OUTPUT = BUILD / "lite"

PYODIDE_VERSION = "0.27.7"
PYODIDE_NPM_INTEGRITY = ("sha512-RUSVJlhQdfWfgO9hVHCiXoG+nVZQRS5D9FzgpLJ/VcgGBLSAKoPL8kTiOikxbHQm1kRISeW"
                         "UBdulEgO26qpSRA==")
PYODIDE_CORE = ["pyodide.js", "pyodide.mjs", "pyodide.asm.js", "pyodide.asm.wasm", "python_stdlib.zip"]
PYODIDE_CDN = f"https://cdn.jsdelivr.net/pyodide/v{PYODIDE_VERSION}/full/"
SHARED_WHEELS = Path(os.environ.get("DHLAB_PYODIDE_WHEELS", ROOT.parent / "shared" / f"pyodide-{PYODIDE_VERSION}"))

# What the kernel itself loads at start (jupyterlite-pyodide-kernel 0.6.1's initKernel list, plus
# micropip and piplite), and the course's package: everything the site ships is their closure.
KERNEL_PACKAGES = ["micropip", "piplite", "ssl", "sqlite3", "ipykernel", "comm", "pyodide_kernel", "jedi",
                   "ipython"]
ROOTS = KERNEL_PACKAGES + ["dhlab"]
# The kernel extension's own wheels (it installs them with piplite unless the lock has them).
KERNEL_WHEELS = ["piplite", "pyodide_kernel", "ipykernel"]
# `depends` of the wheels added to the lock: their Requires-Dist that exist in Pyodide
# (widgetsnbextension and jupyterlab_widgets are the browser's half: JupyterLab ships them).
DEPENDS = {
    "sympy": ["mpmath"],
    "mpmath": [],
    "comm": ["traitlets"],
    "ipywidgets": ["comm", "ipython", "traitlets"],
    "ipympl": ["ipython", "ipywidgets", "matplotlib", "numpy", "pillow", "traitlets"],
    "anywidget": ["ipywidgets", "psygnal", "typing-extensions"],
    "psygnal": [],
    "typing-extensions": [],
    "dhlab": ["numpy", "sympy", "matplotlib", "ipywidgets", "ipympl", "anywidget"],
    "piplite": ["micropip"],
    "pyodide-kernel": [],
    "ipykernel": [],
    "matplotlib-fontlist": ["matplotlib"],
}
# Dependencies of the release's packages that the course never imports: not shipped, not fetched.
# matplotlib needs fontTools only to embed fonts in PDF/PS files and pytz not at all (3.8 uses
# zoneinfo); the course draws PNGs. Saving a figure as PDF in the browser edition therefore fails
# with "No module named 'fontTools'".
NOT_SHIPPED = {"matplotlib": ["fonttools", "pytz"]}
# (jedi, 1.6 MB, stays: the kernel turns IPython's jedi completion on, and without jedi Tab
# completes nothing. No setting skips it at start either: the kernel installs its own list
# (ssl, sqlite3, ipykernel, comm, pyodide_kernel, jedi, ipython) whatever loadPyodideOptions
# says, and IPython 8.23 imports jedi with its completer (0.3-0.6 s of the kernel's 2.2 s
# `import pyodide_kernel`, timed under Node.js). ssl and sqlite3 stay too: the kernel loads
# them, and IPython's history imports sqlite3.)
START_HERE = "01_start_here.ipynb"


class BuildError(SystemExit):
    """A missing or wrong piece: the message says which, and how to get it."""

    def __init__(self, message: str):
        super().__init__(f"\nmake lite: {message}\n")


def shown(path: Path) -> Path:
    """``path`` relative to the checkout when it is inside it (a build of one's own may not be)."""
    return path.relative_to(ROOT) if path.is_relative_to(ROOT) else path


def canonical(name: str) -> str:
    """Pyodide's package key: lower case, runs of -_. as one '-'."""
    import re

    return re.sub(r"[-_.]+", "-", name).lower()


def sha256(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def run(*command, cwd=ROOT):
    print("  $", " ".join(str(c) for c in command), flush=True)
    try:
        subprocess.run([str(c) for c in command], cwd=cwd, check=True)
    except FileNotFoundError:
        raise BuildError(f"{command[0]} not found: it is needed to build the site") from None
    except subprocess.CalledProcessError as error:
        raise BuildError(f"this step failed (exit {error.returncode}): {' '.join(map(str, command))}") from None


# --- the pieces ------------------------------------------------------------------------------

def pyodide_core() -> Path:
    """The npm package pyodide@0.27.7, unpacked; returns its folder."""
    CACHE.mkdir(parents=True, exist_ok=True)
    tgz = CACHE / f"pyodide-{PYODIDE_VERSION}.tgz"
    if not tgz.exists():
        if not shutil.which("npm"):
            raise BuildError(f"npm is needed to fetch the Pyodide core (npm pack pyodide@{PYODIDE_VERSION}):"
                             " apt-get install npm, or put pyodide-{PYODIDE_VERSION}.tgz in {CACHE}")
        run("npm", "pack", f"pyodide@{PYODIDE_VERSION}", "--silent", cwd=CACHE)
    integrity = "sha512-" + base64.b64encode(hashlib.sha512(tgz.read_bytes()).digest()).decode()
    if integrity != PYODIDE_NPM_INTEGRITY:
        raise BuildError(f"{tgz} is not npm's pyodide@{PYODIDE_VERSION} (integrity {integrity}): delete it")
    unpacked = CACHE / f"pyodide-{PYODIDE_VERSION}"
    if not (unpacked / "pyodide-lock.json").exists():
        shutil.rmtree(unpacked, ignore_errors=True)
        with tarfile.open(tgz) as archive:
            archive.extractall(unpacked, **({"filter": "data"} if hasattr(tarfile, "data_filter") else {}))
    return unpacked / "package"


def release_wheel(entry: dict) -> Path:
    """One file of the Pyodide release, checked against the sha256 in npm's pyodide-lock.json."""
    name, expected = entry["file_name"], entry["sha256"]
    local = SHARED_WHEELS / name
    if local.exists():
        if sha256(local) != expected:
            raise BuildError(f"{local} does not match the sha256 in pyodide@{PYODIDE_VERSION}'s "
                             f"pyodide-lock.json ({expected}): replace it with the release's file")
        return local
    cached = CACHE / "release" / name
    if not (cached.exists() and sha256(cached) == expected):
        if _cdn_unreachable:
            return None
        cached.parent.mkdir(parents=True, exist_ok=True)
        try:
            with urllib.request.urlopen(PYODIDE_CDN + name, timeout=20) as response:
                cached.write_bytes(response.read())
        except OSError:
            _cdn_unreachable.append(name)          # one try: no CDN, no point asking again
            return None
        if sha256(cached) != expected:
            cached.unlink()
            raise BuildError(f"{PYODIDE_CDN + name} does not match the sha256 in pyodide-lock.json")
    return cached


_cdn_unreachable: list = []


def pypi_wheels() -> list[Path]:
    """The hash-pinned pure wheels of lite/site-wheels.txt, from PyPI (pip checks the hashes)."""
    folder = CACHE / "pypi"
    run(sys.executable, "-m", "pip", "download", "--quiet", "--no-deps", "--only-binary=:all:",
        "--require-hashes", "-r", LITE / "site-wheels.txt", "-d", folder)
    wanted = [line.split("==") for line in (LITE / "site-wheels.txt").read_text().splitlines()
              if line.strip() and not line.startswith("#")]
    found = []
    for name, rest in wanted:
        version = rest.split()[0]
        matches = list(folder.glob(f"{name.replace('-', '_')}-{version}-*.whl"))
        if not matches:
            raise BuildError(f"the wheel {name}=={version} is missing from {folder}")
        found.append(matches[0])
    return found


def dhlab_wheel() -> Path:
    """dhlab's wheel, built from this checkout (no file of the course holds the assignment's
    solutions: dhlab-assign solutions computes them for a teacher)."""
    folder = CACHE / "dist"
    shutil.rmtree(folder, ignore_errors=True)
    run(sys.executable, "-m", "pip", "wheel", "--quiet", "--no-deps", "-w", folder, ROOT)
    return next(folder.glob("dhlab-*.whl"))


def kernel_wheels() -> list[Path]:
    """The Pyodide kernel extension's own wheels (piplite, pyodide_kernel, ipykernel's shim)."""
    pypi = Path(sys.prefix) / "share/jupyter/labextensions/@jupyterlite/pyodide-kernel-extension/static/pypi"
    wheels = [next(iter(sorted(pypi.glob(f"{name}-*.whl"))), None) for name in KERNEL_WHEELS]
    if None in wheels:
        raise BuildError(f"{pypi} lacks the kernel's wheels: pip install -r lite/requirements.txt")
    return wheels


def lock_entry(wheel: Path) -> dict:
    """A pyodide-lock.json entry for a pure wheel: its top-level imports and its depends."""
    name, version = wheel.name.split("-")[:2]
    with zipfile.ZipFile(wheel) as archive:
        tops = {path.split("/")[0].removesuffix(".py") for path in archive.namelist()
                if (path.endswith("/__init__.py") and path.count("/") == 1)
                or ("/" not in path and path.endswith(".py"))}
    key = canonical(name)
    if key not in DEPENDS:
        raise BuildError(f"lite/build.py has no `depends` for {name}: add it to DEPENDS")
    return {"name": key, "version": version, "file_name": wheel.name, "install_dir": "site",
            "sha256": sha256(wheel), "package_type": "package", "imports": sorted(tops),
            "depends": DEPENDS[key], "unvendored_tests": False, "shared_library": False}


def closure(packages: dict, roots: list[str]) -> list[str]:
    """The roots and everything they depend on, by the lock's `depends`."""
    seen, todo = [], [canonical(r) for r in roots]
    while todo:
        key = todo.pop()
        if key in seen:
            continue
        if key not in packages:
            raise BuildError(f"no package {key!r} in the site's pyodide-lock.json")
        seen.append(key)
        todo += [canonical(d) for d in packages[key]["depends"]]
    return sorted(seen)


def assemble_pyodide(target: Path):
    """Pyodide's core, the packages the course needs, and a pyodide-lock.json listing just those."""
    core = pyodide_core()
    lock = json.loads((core / "pyodide-lock.json").read_text())
    target.mkdir(parents=True)
    for name in PYODIDE_CORE:
        shutil.copy2(core / name, target / name)
    added = {}
    for wheel in [*pypi_wheels(), dhlab_wheel(), *kernel_wheels()]:
        entry = lock_entry(wheel)
        added[entry["name"]] = entry
        shutil.copy2(wheel, target / wheel.name)
    for key, dropped in NOT_SHIPPED.items():
        lock["packages"][key]["depends"] = [d for d in lock["packages"][key]["depends"] if d not in dropped]
    packages = {**lock["packages"], **added}
    ship = closure(packages, ROOTS)
    missing = []
    for key in ship:
        if key in added:
            continue
        source = release_wheel(packages[key])
        if source is None:
            missing.append(packages[key]["file_name"])
        else:
            shutil.copy2(source, target / source.name)
    if missing:
        raise BuildError(
            f"these files of the Pyodide {PYODIDE_VERSION} release are missing from {SHARED_WHEELS} and "
            f"{PYODIDE_CDN} was not reachable:\n    " + "\n    ".join(missing) +
            f"\n  Put them in {SHARED_WHEELS} (or set DHLAB_PYODIDE_WHEELS to a folder that has them): they are in"
            f"\n  https://github.com/pyodide/pyodide/releases/download/{PYODIDE_VERSION}/"
            f"pyodide-{PYODIDE_VERSION}.tar.bz2")
    lock["packages"] = {key: packages[key] for key in ship}
    (target / "pyodide-lock.json").write_text(json.dumps(lock, indent=1, sort_keys=True))
    # Bytecode, made once here by this Pyodide, and no test suites, type stubs or unused fonts
    # (lite/precompile.py says why and how). The rewritten wheels get their new sha256 in the lock:
    # Pyodide checks it on every load. (The release's wheels were checked above, as they came.)
    for path in target.glob("*.whl"):
        path.chmod(0o644)                       # the release's files were copied read-only
    run("node", LITE / "precompile.mjs", target)
    for entry in lock["packages"].values():
        entry["sha256"] = sha256(target / entry["file_name"])
    (target / "pyodide-lock.json").write_text(json.dumps(lock, indent=1, sort_keys=True))
    # matplotlib's font list, built once here rather than in every kernel. The release's matplotlib
    # wheel ships a stale one (made by matplotlib 3.9, so 3.8 rebuilds it): ours depends on
    # matplotlib, so that Pyodide installs it after matplotlib, over that file.
    fontlist = matplotlib_fontlist_wheel(target)
    lock["packages"]["matplotlib-fontlist"] = {**lock_entry(fontlist), "imports": []}
    lock["packages"]["dhlab"]["depends"].append("matplotlib-fontlist")
    (target / "pyodide-lock.json").write_text(json.dumps(lock, indent=1, sort_keys=True))
    print(f"  Pyodide {PYODIDE_VERSION}: {len(lock['packages'])} packages: {', '.join(sorted(lock['packages']))}")


def matplotlib_fontlist_wheel(pyodide: Path) -> Path:
    """A wheel holding matplotlib/fontlist.json, as Pyodide's matplotlib writes it on its first
    import (computed here by that matplotlib, in Pyodide under Node.js: lite/fontlist.mjs)."""
    if not shutil.which("node"):
        raise BuildError("node (Node.js) is needed to run Pyodide at build time: apt-get install nodejs")
    json_path = CACHE / "fontlist.json"
    run("node", LITE / "fontlist.mjs", pyodide, json_path)
    version = [e for e in json.loads((pyodide / "pyodide-lock.json").read_text())["packages"].values()
               if e["name"] == "matplotlib"][0]["version"]
    name = f"matplotlib_fontlist-{version}"
    wheel = pyodide / f"{name}-py3-none-any.whl"
    metadata = f"Metadata-Version: 2.1\nName: matplotlib-fontlist\nVersion: {version}\n"
    wheel_info = "Wheel-Version: 1.0\nGenerator: dhlab lite/build.py\nRoot-Is-Purelib: true\nTag: py3-none-any\n"
    files = {"matplotlib/fontlist.json": json_path.read_bytes(),
             f"{name}.dist-info/METADATA": metadata.encode(),
             f"{name}.dist-info/WHEEL": wheel_info.encode()}
    return write_wheel(wheel, name, files)


def write_wheel(path: Path, name: str, files: dict) -> Path:
    """A wheel of ``files`` ({path: bytes}) with its RECORD; the same bytes on every build."""
    def digest(data: bytes) -> str:
        """A sha256 as RECORD writes it: urlsafe base64 without the padding (the wheel format)."""
        return base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()

    record = "".join(f"{p},sha256={digest(data)},{len(data)}\n"
                     for p, data in files.items()) + f"{name}.dist-info/RECORD,,\n"
    files = {**files, f"{name}.dist-info/RECORD": record.encode()}
    with zipfile.ZipFile(path, "w") as archive:
        for p, data in files.items():
            info = zipfile.ZipInfo(p, date_time=(2026, 1, 1, 0, 0, 0))
            archive.writestr(info, data, compress_type=zipfile.ZIP_DEFLATED)
    return path


def stage_site():
    """The lite dir: our settings, the notebooks, and the self-hosted Pyodide."""
    shutil.rmtree(STAGE, ignore_errors=True)
    STAGE.mkdir(parents=True)
    for name in ["jupyter_lite_config.json", "jupyter-lite.json", "overrides.json"]:
        shutil.copy2(LITE / name, STAGE / name)
    notebooks = sorted((ROOT / "notebooks").glob("*.ipynb"))    # the answers stay in the package, not on the site
    if not any(nb.name == START_HERE for nb in notebooks):
        raise BuildError(f"notebooks/{START_HERE} is missing: the site opens on it")
    (STAGE / "files").mkdir()
    for notebook in notebooks:
        shutil.copy2(notebook, STAGE / "files" / notebook.name)
    # the Spanish edition (notebooks/es/, made by the edition tool), in its folder as in notebooks/
    for path in sorted((ROOT / "notebooks" / "es").glob("*.ipynb")):
        (STAGE / "files" / "es").mkdir(exist_ok=True)
        shutil.copy2(path, STAGE / "files" / "es" / path.name)
    stage_lecture_plans(STAGE / "files")
    assemble_pyodide(STAGE / "static" / "pyodide")


# The lecture plans live in docs/lecturers/ and link the notebooks as ../../notebooks/<name>, and
# notebook 1 links them as ../docs/lecturers/<page> (../../ from notebooks/es/). The site keeps the
# notebooks at the top of its files, the Spanish ones in es/ and the plans in lecture_plans/, so
# those links are rewritten for that layout (the site has no folder above its files).
PLAN_LINKS = [("](../../notebooks/", "](../")]
NOTEBOOK_LINKS = {"": [("](../docs/lecturers/", "](lecture_plans/")],
                  "es": [("](../../docs/lecturers/", "](../lecture_plans/")]}


def copy_with_links(source: Path, target: Path, rewrites: list[tuple[str, str]]):
    """``source`` copied to ``target`` with each (old, new) link prefix replaced."""
    text = source.read_text(encoding="utf-8")
    for old, new in rewrites:
        text = text.replace(old, new)
    target.parent.mkdir(parents=True, exist_ok=True)
    target.write_text(text, encoding="utf-8")
    shutil.copystat(source, target)


def stage_lecture_plans(files: Path):
    """The lecture plans in ``files``/lecture_plans/ (with the picture they show, in images/), and the
    staged notebooks' links to them pointed there."""
    for plan in sorted((ROOT / "docs" / "lecturers").glob("*.md")):
        copy_with_links(plan, files / "lecture_plans" / plan.name, PLAN_LINKS)
    for image in sorted((ROOT / "notebooks" / "images").glob("*.png")):
        (files / "images").mkdir(exist_ok=True)
        shutil.copy2(image, files / "images" / image.name)
    for folder, rewrites in NOTEBOOK_LINKS.items():
        for notebook in sorted((files / folder).glob("*.ipynb")):
            copy_with_links(notebook, notebook, rewrites)


DOCS_HTML = ROOT / "docs" / "_build" / "html"      # what `make docs` builds


def add_docs(site: Path = OUTPUT, built: Path = DOCS_HTML) -> bool:
    """The docs site, when `make docs` has built it, in ``site``/docs/ (served beside the course)."""
    if not (built / "index.html").exists():
        print(f"{shown(built)} is not built: the site goes without its docs (make docs, then make lite)")
        return False
    shutil.rmtree(site / "docs", ignore_errors=True)
    shutil.copytree(built, site / "docs", ignore=shutil.ignore_patterns(".buildinfo", ".doctrees"))
    print(f"the docs are in {shown(site / 'docs')}")
    return True


def configure_site():
    """Our settings (lite/jupyter-lite.json) over those jupyter lite build wrote: its addons
    rewrite the kernel's settings, so they are merged here, plugin by plugin."""
    path = OUTPUT / "jupyter-lite.json"
    site = json.loads(path.read_text())
    ours = json.loads((LITE / "jupyter-lite.json").read_text())["jupyter-config-data"]
    config = site["jupyter-config-data"]
    for key, value in ours.items():
        if key == "litePluginSettings":
            for plugin, settings in value.items():
                config.setdefault(key, {}).setdefault(plugin, {}).update(settings)
        else:
            config[key] = value
    path.write_text(json.dumps(site, indent=2, sort_keys=True))


def open_on_start_here():
    """The site's front page opens the "Start here" notebook in JupyterLab.

    The page keeps its ``jupyter-config-data`` script: every app reads it from its parents.
    """
    page = OUTPUT / "index.html"
    target = f"lab/index.html?path={START_HERE}"
    html = page.read_text()
    if "<script type=\"module\">" not in html:
        raise BuildError(f"{page} is not the JupyterLite front page this build knows how to patch")
    html = html.replace("<script type=\"module\">",
                        f"<script>location.replace({target!r} + location.hash)</script>\n"
                        "    <script type=\"module\">", 1)
    page.write_text(html)


def main():
    if sys.argv[1:] == ["--docs-only"]:        # the built docs into an existing site, nothing else
        sys.exit(0 if add_docs() else 1)
    lite_app = Path(sys.prefix) / "bin" / "jupyter-lite"
    if not lite_app.exists():
        raise BuildError(f"{lite_app} not found: run this with the build venv's python "
                         "(make lite creates it from lite/requirements.txt)")
    print("staging the site in", shown(STAGE))
    stage_site()
    shutil.rmtree(OUTPUT, ignore_errors=True)
    run(lite_app, "build", "--lite-dir", STAGE, "--output-dir", OUTPUT, cwd=STAGE)
    configure_site()
    open_on_start_here()
    add_docs()
    (OUTPUT / ".nojekyll").touch()         # GitHub Pages: serve the folder as it is
    size = sum(p.stat().st_size for p in OUTPUT.rglob("*") if p.is_file())
    print(f"built {shown(OUTPUT)}: {size / 1e6:.0f} MB; serve it with `make lite-serve`")


if __name__ == "__main__":
    main()
