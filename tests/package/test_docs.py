"""The README and the docs site (docs/, MyST Markdown built by Sphinx).

The README stays a five-minute read (at most 15 KB) that sends each audience to its folder of docs/;
every link of the README and of the docs that points at a file of the repository lands; the site
builds with warnings as errors, so every internal link and cross-reference resolves (``make docs``
does the same); and the browser edition's build carries the lecture plans and the built docs with
links that still land in its own layout.
"""
from __future__ import annotations

import importlib.util
import json
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs"
README = ROOT / "README.md"
PAGES = sorted(p for p in DOCS.rglob("*.md") if "_build" not in p.parts)
AUDIENCES = ["students", "lecturers", "grading", "translators", "developers", "api"]
# the public modules the API reference must document (one page each, or a section of one)
API_MODULES = ["dhlab", "dhlab.transforms", "dhlab.chain", "dhlab.dh", "dhlab.mdh", "dhlab.symbolic", "dhlab.table",
               "dhlab.robots", "dhlab.ik", "dhlab.lines", "dhlab.dh_frames", "dhlab.views", "dhlab.course",
               "dhlab.assignment", "dhlab.grading"]
# a Markdown link or image: [text](target) / ![alt](target); the target ends at a space or ')'
LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")


def links(path: Path) -> list[str]:
    """The link targets of a Markdown file, outside code blocks and code spans."""
    text = re.sub(r"```.*?```", "", path.read_text(encoding="utf-8"), flags=re.S)
    text = re.sub(r"`[^`\n]*`", "", text)
    return LINK.findall(text)


def local(target: str) -> str | None:
    """The file part of a link to a repository file, or None (a web address, an anchor alone)."""
    if re.match(r"^[a-z][a-z0-9+.-]*:", target) or target.startswith("#"):
        return None
    return target.split("#", 1)[0]


def test_the_readme_is_a_five_minute_read():
    text = README.read_text(encoding="utf-8")
    assert README.stat().st_size <= 15_000, f"README.md is {README.stat().st_size} bytes: move the detail into docs/"
    assert "make lab     # sets everything up, then opens the course in JupyterLab" in text
    assert "make test    # sets everything up, then runs the whole test suite" in text
    assert "(notebooks/images/teach_ssrms.png)" in text
    assert "## En español" in text and "cuadernos" in text
    for audience in AUDIENCES:
        assert f"(docs/{audience}/index.md)" in text, f"the README does not send readers to docs/{audience}/"


def test_every_audience_has_its_folder():
    for audience in AUDIENCES:
        assert (DOCS / audience / "index.md").exists(), audience
    api = "\n".join(p.read_text(encoding="utf-8") for p in (DOCS / "api").glob("*.md"))
    for module in API_MODULES:
        assert f".. automodule:: {module}\n" in api, f"the API reference does not document {module}"


@pytest.mark.parametrize("page", [README, *PAGES], ids=lambda p: str(p.relative_to(ROOT)))
def test_links_to_repository_files_land(page):
    broken = [t for t in links(page) if local(t) and not (page.parent / local(t)).resolve().exists()]
    assert not broken, f"{page.relative_to(ROOT)} links files that do not exist: {broken}"


# what the tools write where a page says to look (not in the repository until they have run)
OUTPUTS = ("benchmarks/results/", "tests/browser/results/", "build/", "docs/_build/")


@pytest.mark.parametrize("page", [README, *PAGES], ids=lambda p: str(p.relative_to(ROOT)))
def test_repository_paths_named_in_code_exist(page):
    """A page that names `dhlab/views/live/rig.py` or `tests/maths/test_mdh.py` in code names a file that is there
    (a module or a test moved since the page was written fails here)."""
    text = re.sub(r"```.*?```", "", page.read_text(encoding="utf-8"), flags=re.S)
    paths = {word.strip("(),;:.") for span in re.findall(r"`([^`\n]+)`", text) for word in span.split()}
    named = {p for p in paths if re.fullmatch(r"(dhlab|tools|tests|benchmarks|lite|notebooks|docs)/[\w./-]*", p)}
    missing = sorted(p for p in named if not p.startswith(OUTPUTS) and not (ROOT / p).exists())
    assert not missing, f"{page.relative_to(ROOT)} names files that do not exist: {missing}"


def test_lecture_plans_link_only_what_the_browser_edition_carries():
    """The browser edition copies the plans beside the notebooks, not the rest of docs/: a plan links
    another plan, a notebook, a picture of notebooks/images/ or a web address."""
    for plan in sorted((DOCS / "lecturers").glob("*.md")):
        for target in filter(None, map(local, links(plan))):
            landed = (plan.parent / target).resolve()
            assert landed.parent in {DOCS / "lecturers", ROOT / "notebooks", ROOT / "notebooks" / "images"}, \
                f"{plan.name} links {target}: the browser edition's copy of the plans cannot follow it"


def lite_build():
    """lite/build.py as a module (it imports only the standard library at the top)."""
    spec = importlib.util.spec_from_file_location("lite_build", ROOT / "lite" / "build.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_browser_edition_stages_the_plans_with_links_that_land(tmp_path):
    build = lite_build()
    files = tmp_path / "files"
    (files / "es").mkdir(parents=True)
    cell = {"cell_type": "markdown", "metadata": {}, "source": ["see the [plans](../docs/lecturers/index.md)"]}
    (files / "01_start_here.ipynb").write_text(json.dumps({"cells": [cell]}))
    cell["source"] = ["vea el [índice](../../docs/lecturers/index.md)"]
    (files / "es" / "01_start_here.ipynb").write_text(json.dumps({"cells": [cell]}))
    for notebook in (ROOT / "notebooks").glob("0*.ipynb"):    # what the plans link, as the site has them
        (files / notebook.name).touch()
    build.stage_lecture_plans(files)
    staged = sorted((files / "lecture_plans").glob("*.md"))
    assert [p.name for p in staged] == sorted(p.name for p in (DOCS / "lecturers").glob("*.md"))
    for plan in staged:
        for target in filter(None, map(local, links(plan))):
            assert (plan.parent / target).resolve().exists(), f"{plan.name} in the site links {target}"
    for notebook in [files / "01_start_here.ipynb", files / "es" / "01_start_here.ipynb"]:
        target = local(links_in_notebook(notebook)[0])
        assert (notebook.parent / target).resolve() == files / "lecture_plans" / "index.md"


def links_in_notebook(path: Path) -> list[str]:
    cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    return LINK.findall("\n".join("".join(c["source"]) for c in cells))


def test_the_browser_edition_carries_the_built_docs(tmp_path):
    build = lite_build()
    site, built = tmp_path / "lite", tmp_path / "html"
    site.mkdir()
    assert not build.add_docs(site, built)                 # not built: the site goes without
    (built / ".doctrees").mkdir(parents=True)
    (built / "index.html").write_text("<html>dhlab</html>")
    (built / ".buildinfo").write_text("x")
    assert build.add_docs(site, built)
    assert (site / "docs" / "index.html").read_text() == "<html>dhlab</html>"
    assert not (site / "docs" / ".doctrees").exists() and not (site / "docs" / ".buildinfo").exists()


def test_the_docs_build_without_a_warning(tmp_path):
    """What `make docs` runs: warnings are errors, every internal link and cross-reference resolves."""
    pytest.importorskip("sphinx", reason="the docs extra is not installed (pip install -e '.[docs]')")
    pytest.importorskip("myst_parser", reason="the docs extra is not installed (pip install -e '.[docs]')")
    result = subprocess.run([sys.executable, "-m", "sphinx", "-b", "html", "-E", "-W", "--keep-going", "-n", "-q",
                             str(DOCS), str(tmp_path / "html")], capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, f"the docs do not build cleanly:\n{result.stderr[-6000:]}"
    assert (tmp_path / "html" / "lecturers" / "05_dh_convention.html").exists()
    assert (tmp_path / "html" / "api" / "dh.html").exists()
