"""Sphinx configuration of the dhlab docs (MyST Markdown pages, API reference from the docstrings).

    make docs            # docs/_build/html, warnings are errors, every internal link checked
    make docs-linkcheck  # also the external links (needs the network)

The build needs no network: the theme is Sphinx's built-in alabaster and no page loads anything
from a CDN (MathJax is off: the pages write formulas as text, as the README did).
"""
from __future__ import annotations

import sys
from pathlib import Path

DOCS = Path(__file__).resolve().parent
sys.path.insert(0, str(DOCS.parent))        # dhlab from this checkout, also without an editable install

import dhlab  # noqa: E402  (after the path: the version and the API reference come from it)

project = "dhlab"
author = "the dhlab authors"
copyright = "dhlab authors, MIT licence"
version = release = dhlab.__version__

extensions = ["myst_parser", "sphinx.ext.autodoc"]
source_suffix = {".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build"]

# MyST: heading anchors for `page.md#section` links; `$...$` stays text as written (no MathJax
# from a CDN). A link to a repository file outside docs/ (a notebook, a module) must exist.
myst_enable_extensions = ["colon_fence", "deflist"]
myst_heading_anchors = 3

# the API reference (docs/api/, one automodule per public module): each module's own public members,
# in the order the source gives them; signatures as written, without type hints repeated
autodoc_member_order = "bysource"
autodoc_default_options = {"members": True}
autodoc_typehints = "none"

html_theme = "alabaster"
html_title = f"dhlab {release}"
html_theme_options = {"description": "robot kinematics, interactively", "fixed_sidebar": False}
html_static_path: list[str] = []


# A docstring may name a module or object that the API reference does not document (an internal
# module such as dhlab.grading.run.sandbox, a private helper): that is not a broken reference as long as
# the name exists in the code, so it is shown as code, without a link. A name that exists nowhere (a
# module moved or renamed since the docstring was written) stays a warning, so the build fails on it.
def _exists(target: str, module: str | None, cls: str | None) -> bool:
    import importlib

    candidates = [target]
    if module:
        candidates += [f"{module}.{cls}.{target}" if cls else "", f"{module}.{target}"]
    for name in filter(None, candidates):
        parts = name.split(".")
        for cut in range(len(parts), 0, -1):
            try:
                obj = importlib.import_module(".".join(parts[:cut]))
            except ImportError:
                continue
            try:
                for attr in parts[cut:]:
                    obj = getattr(obj, attr)
            except AttributeError:
                break
            return True
    # a bare name (``Feedback``) documented where it is used, defined in a sibling module
    return "." not in target and any(hasattr(m, target) for n, m in list(sys.modules.items())
                                     if n.startswith("dhlab") and m is not None)


def _undocumented_but_real(app, env, node, contnode):
    if node.get("refdomain") == "py" and _exists(node["reftarget"], node.get("py:module"), node.get("py:class")):
        return contnode
    return None


# The docstrings are written to be read as plain text too (help(), an editor), so two things are
# spelled for reStructuredText here, not in the code: a block set off by indentation after a
# paragraph (a formula, a command's usage) is shown as it is ("::"), and |c| in prose is an absolute value, not a
# substitution (escaped outside ``code``, doctests, tables and those blocks).
def _plain_text_docstrings(app, what, name, obj, options, lines):
    import re

    literal_indent = None                     # inside a literal block: the indentation that opened it
    for i, line in enumerate(lines):
        indent = len(line) - len(line.lstrip())
        if literal_indent is not None and (not line.strip() or indent > literal_indent):
            continue
        literal_indent = None
        following = next((n for n in lines[i + 1:i + 3] if n.strip()), "")
        opens = (line.strip() and not line.lstrip().startswith(("..", ":", ">>>", "...", "*", "-"))
                 and i + 1 < len(lines) and not lines[i + 1].strip()
                 and len(following) - len(following.lstrip()) > indent
                 and not following.lstrip().startswith((">>>", "..", ":", "*", "-")))
        table_row = line.strip().startswith(("+-", "+=")) or (line.strip()[:1] == line.strip()[-1:] == "|")
        if "|" in line and not table_row and not line.lstrip().startswith((">>>", "...")):
            line = "".join(p if p.startswith("``") else p.replace("|", r"\|") for p in re.split(r"(``.*?``)", line))
        if opens or line.rstrip().endswith("::"):
            literal_indent = indent
            if opens and not line.rstrip().endswith("::"):
                line = line.rstrip() + (":" if line.rstrip().endswith(":") else " ::")   # " ::" shows nothing
        lines[i] = line


def setup(app):
    app.connect("missing-reference", _undocumented_but_real)
    app.connect("autodoc-process-docstring", _plain_text_docstrings)

# make docs-linkcheck: external links, when the network allows (not in CI: it reaches only PyPI)
linkcheck_timeout = 15
linkcheck_retries = 1
