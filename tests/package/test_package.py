"""The public names of the package stay what they say, whatever was imported before; ``import dhlab``
stays light; the old module paths still import; the modules import only down the chain of layers."""
import ast
import functools
import importlib
import subprocess
import sys
from pathlib import Path

import dhlab


def test_panel_functions_are_not_shadowed_by_their_modules():
    import pytest

    for module in ("dhlab.teach", "dhlab.spaces", "dhlab.stepthrough", "dhlab.view"):
        sys.modules.pop(module, None)          # (the old name only: the module at its new place stays)
        with pytest.warns(DeprecationWarning, match="moved to"):    # old paths: they warn
            importlib.import_module(module)
    assert callable(dhlab.teach) and callable(dhlab.spaces)
    assert callable(dhlab.stepthrough) and callable(dhlab.stepthrough_link) and callable(dhlab.robot_view)


def test_everything_in_all_exists():
    missing = [name for name in dhlab.__all__ if not hasattr(dhlab, name)]
    assert not missing


def test_unit_helpers_say_their_direction_and_old_names_still_work_with_a_message():
    import math

    import pytest

    assert math.isclose(dhlab.deg2rad(180), math.pi) and math.isclose(dhlab.rad2deg(math.pi), 180.0)
    assert repr(-dhlab.deg2rad(30)) == "deg2rad(-30)"
    with pytest.warns(FutureWarning, match=r"dhlab.deg\(\) is renamed dhlab.deg2rad\(\)"):
        assert dhlab.deg(90) == dhlab.deg2rad(90)
    with pytest.warns(FutureWarning, match=r"dhlab.rad\(\) is renamed dhlab.rad2deg\(\)"):
        assert dhlab.rad(math.pi / 2) == dhlab.rad2deg(math.pi / 2)


# --- a light ``import dhlab``, the old module paths, the layers -----------------------------------
PACKAGE = Path(dhlab.__file__).parent

# what ``import dhlab`` must not load: the course, the assignment, the grader, and the heavy libraries
# that only the symbolic side and the views need (each is imported on first use)
NOT_AT_IMPORT = ("dhlab.course", "dhlab.assignment", "dhlab.grading", "dhlab.views", "sympy",
                 "mpl_toolkits.mplot3d", "matplotlib.pyplot", "ipywidgets")

# the old module paths (notebooks and scripts written before the split) and where they live now
OLD_PATHS = {"dhlab.teach": "dhlab.views.panels.teach", "dhlab.view": "dhlab.views.view",
             "dhlab.livefigure": "dhlab.views.live.livefigure", "dhlab.panel": "dhlab.views.panels.panel",
             "dhlab.spaces": "dhlab.views.panels.spaces", "dhlab.stepthrough": "dhlab.views.panels.stepthrough",
             **{f"dhlab.views.{name}": f"dhlab.views.live.{name}" for name in (
                 "livefigure", "backend", "notebook_cell", "ipympl_canvas", "canvas", "scene", "rig", "keys", "png")},
             **{f"dhlab.views.{name}": f"dhlab.views.panels.{name}"
                for name in ("panel", "teach", "stepthrough", "spaces")},
             "dhlab.exercises": "dhlab.course.exercises", "dhlab.exercises_dh": "dhlab.course.exercises",
             "dhlab.course.exercises_dh": "dhlab.course.exercises",
             "dhlab.course.assignment": "dhlab.assignment.notebook",
             "dhlab.course.family_notebook": "dhlab.assignment.notebook_cells",
             "dhlab.grading.generate": "dhlab.grading.release.generate",
             "dhlab.grade": "dhlab.grading.cli", "dhlab.assign": "dhlab.dh_frames",
             "dhlab.assign.frames": "dhlab.dh_frames.frames", "dhlab.grading.language": "dhlab.i18n"}


def run_python(code: str, *args) -> subprocess.CompletedProcess:
    """``code`` in a fresh interpreter (nothing imported by the tests before)."""
    return subprocess.run([sys.executable, "-c", code, *args], capture_output=True, text=True, timeout=300)


def test_import_dhlab_loads_the_maths_only():
    out = run_python("import sys, dhlab; print(' '.join(m for m in sys.modules if m in sys.argv[1:] or "
                     "any(m.startswith(p + '.') for p in sys.argv[1:])))", *NOT_AT_IMPORT)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == [], f"import dhlab loaded {out.stdout.split()}"


def test_lazy_names_resolve_on_first_use_and_stay_in_dir_and_star():
    out = run_python(
        "import sys, dhlab\n"
        "assert 'sympy' not in sys.modules\n"
        "assert callable(dhlab.compact) and 'sympy' in sys.modules\n"
        "assert callable(dhlab.teach) and dhlab.symbolic.__name__ == 'dhlab.symbolic'\n"
        "assert set(dhlab.__all__) <= set(dir(dhlab)), set(dhlab.__all__) - set(dir(dhlab))\n"
        "names = {}\n"
        "exec('from dhlab import *', names)\n"
        "assert set(dhlab.__all__) <= set(names)\n"
        "assert 'deg' not in dhlab.__all__ and callable(dhlab.deg)      # deprecated: importable, not starred\n"
        "assert dhlab.__version__ and dhlab.DHLabError.__module__ == 'dhlab.validation'\n")
    assert out.returncode == 0, out.stderr


def test_every_old_module_path_imports_as_the_module_at_its_new_place():
    out = run_python(
        "import importlib, sys, dhlab\n"
        f"old_paths = {OLD_PATHS!r}\n"
        "for old, new in old_paths.items():\n"
        "    assert importlib.import_module(old) is importlib.import_module(new), old\n"
        "    assert sys.modules[new].__spec__.name == new, old     # still the module at its new place\n"
        "import dhlab.teach, dhlab.spaces, dhlab.stepthrough\n"
        "from dhlab.teach import TeachPanel\n"
        "assert callable(dhlab.teach) and not isinstance(dhlab.teach, type(sys))\n"
        "assert callable(dhlab.spaces) and callable(dhlab.stepthrough)\n"
        "assert isinstance(dhlab.view, type(sys)) and dhlab.view.robot_view is dhlab.robot_view\n"
        "from dhlab.assign import dh_from_axes\n"
        "from dhlab.course.assignment import Tz\n")
    assert out.returncode == 0, out.stderr


def test_old_paths_warn_where_they_are_imported_except_the_released_notebooks():
    """A developer's old path warns at the line that imports it; a released notebook's never warns."""
    out = run_python(
        "import warnings\n"
        "warnings.simplefilter('always')\n"
        "with warnings.catch_warnings(record=True) as seen:\n"
        "    from dhlab.views.livefigure import LiveFigure\n"
        "    import dhlab.assign.frames\n"
        "    from dhlab.course.assignment import Tz\n"
        "    from dhlab.course.family_notebook import use_variant\n"
        "    from dhlab.views.teach import teach\n"
        "for w in seen:\n"
        "    print(w.category.__name__, w.filename, w.lineno, str(w.message).split(':')[0])\n")
    assert out.returncode == 0, out.stderr
    assert out.stdout.splitlines() == [
        "DeprecationWarning <string> 4 dhlab.views.livefigure moved to dhlab.views.live.livefigure",
        "DeprecationWarning <string> 5 dhlab.assign moved to dhlab.dh_frames",
        "DeprecationWarning <string> 5 dhlab.assign.frames moved to dhlab.dh_frames.frames"]


def test_the_course_itself_never_imports_an_old_path():
    """Every module of the package, imported with DeprecationWarning as an error, imports."""
    out = run_python(
        "import importlib, pkgutil, warnings, dhlab\n"
        "warnings.simplefilter('error', DeprecationWarning)\n"
        "for m in pkgutil.walk_packages(dhlab.__path__, 'dhlab.'):\n"
        "    importlib.import_module(m.name)\n")
    assert out.returncode == 0, out.stderr[-2000:]


def test_python_m_dhlab_grade_still_runs_the_grader():
    out = subprocess.run([sys.executable, "-m", "dhlab.grade", "--help"], capture_output=True, text=True,
                         timeout=300)
    assert out.returncode == 0, out.stderr
    assert out.stdout.startswith("usage: dhlab-grade")


# The layers, bottom to top: a module imports only from its own layer and the layers below.
LAYERS = ["ground", "maths", "views", "course", "assignment", "grading"]
GROUND = ("dhlab.errors", "dhlab.i18n", "dhlab.units", "dhlab.validation", "dhlab.lazy_sympy", "dhlab.moved")


def layer_of(module: str) -> str | None:
    """The layer of a dhlab module (None: the package itself, which names everything lazily)."""
    if module == "dhlab":
        return None
    if ".".join(module.split(".")[:2]) in GROUND:
        return "ground"
    second = module.split(".")[1]
    return second if second in ("views", "course", "assignment", "grading") else "maths"


def module_name(path: Path) -> str:
    parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _type_checking_only(node, parents) -> bool:
    """True inside ``if TYPE_CHECKING:`` (imports for annotations only, never run)."""
    return any(isinstance(p, ast.If) and "TYPE_CHECKING" in ast.unparse(p.test) for p in parents)


def imports_of(path: Path, modules: set) -> list:
    """(line, imported dhlab module) for every import in ``path``, at module level or in a function."""
    name = module_name(path)
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    tree = ast.parse(path.read_text(encoding="utf-8"))
    parents = {}
    for node in ast.walk(tree):
        for child in ast.iter_child_nodes(node):
            parents[child] = node
    found = []
    for node in ast.walk(tree):
        if not isinstance(node, (ast.Import, ast.ImportFrom)):
            continue
        chain, p = [], node
        while p in parents:
            p = parents[p]
            chain.append(p)
        if _type_checking_only(node, chain):
            continue
        if isinstance(node, ast.Import):
            targets = [alias.name for alias in node.names]
        else:
            base = node.module or ""
            if node.level:
                anchor = package.split(".")[:len(package.split(".")) - node.level + 1]
                base = ".".join(anchor + ([node.module] if node.module else []))
            # ``from pkg import sub``: the submodule when there is one, else the package
            targets = [f"{base}.{alias.name}" if f"{base}.{alias.name}" in modules else base for alias in node.names]
        for target in targets:
            while target and target not in modules and "." in target:
                target = target.rpartition(".")[0]          # ``import dhlab.views.panels.teach as t`` and the like
            if target in modules and target != name:
                found.append((node.lineno, target))
    return found


@functools.cache
def import_graph() -> dict:
    """{module: [(file, line, imported module), ...]} over every module of the package."""
    paths = sorted(PACKAGE.rglob("*.py"))
    modules = {module_name(p) for p in paths}
    return {module_name(p): [(p.relative_to(PACKAGE.parent), line, target) for line, target in imports_of(p, modules)]
            for p in paths}


def circles(graph: dict) -> list:
    """The strongly connected components of more than one module (Tarjan), each a sorted list."""
    index, low, stack, on_stack, found, counter = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on_stack.add(v)
        for _file, _line, w in graph[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    sys.setrecursionlimit(max(sys.getrecursionlimit(), 10_000))
    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def test_import_graph_has_no_circle():
    graph = import_graph()
    found = circles(graph)
    report = []
    for component in found:
        members = set(component)
        edges = [f"{file}:{line} -> {target}"
                 for m in component for file, line, target in graph[m] if target in members]
        report.append(" <-> ".join(component) + "\n    " + "\n    ".join(edges))
    assert not found, "import circles:\n" + "\n".join(report)


@functools.cache
def is_forwarder(path: Path) -> bool:
    """A module kept at an old path for one release: nothing but a docstring, imports and ``__all__``
    (it re-exports its new home, which may be a layer above). Today there is none: :mod:`dhlab.moved` answers
    the old names without a file at the old place."""
    body = ast.parse(path.read_text(encoding="utf-8")).body
    return bool(body) and all(
        isinstance(node, (ast.Import, ast.ImportFrom)) or
        isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant) or
        isinstance(node, ast.Assign) and [ast.unparse(t) for t in node.targets] == ["__all__"] for node in body)


def test_imports_only_run_down_the_layers():
    graph = import_graph()
    upward = [f"{file}:{line}: {layer_of(module)} imports {layer_of(target)} ({target})"
              for module, edges in graph.items() for file, line, target in edges
              if layer_of(module) and layer_of(target) and not is_forwarder(PACKAGE.parent / file)
              and LAYERS.index(layer_of(target)) > LAYERS.index(layer_of(module))]
    assert not upward, f"{len(upward)} imports run up the chain {' -> '.join(LAYERS)}:\n" + "\n".join(upward)


def test_the_package_imports_only_the_maths_at_module_level():
    tree = ast.parse((PACKAGE / "__init__.py").read_text(encoding="utf-8"))
    imported = [node.module for node in tree.body if isinstance(node, ast.ImportFrom) and node.level]
    assert all(layer_of(f"dhlab.{m}") in ("ground", "maths") for m in imported if m), imported
