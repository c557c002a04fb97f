"""The numbers the notebooks state are the numbers their code prints, and those match seed_cases.json.

These tests read the stored notebooks (executed by ``python -m tools.execute``; nbval checks that the stored
outputs are what the code prints today). They check that:

* every decimal number written in a notebook's text (outside the exercise statements, whose numbers are
  data) appears, to the digits shown, in that notebook's code outputs — for every notebook of the course;
* the key numbers of the seeds' cases (``seed_cases.json``) appear in the outputs of cells marked
  the cell tag ``nbval-check-output``, so that a change in the maths fails the suite;
* every erratum of seed 004 (and the others met in these notebooks) is stated where it arises;
* cells that show a live panel do not have their (random) widget output compared;
* every notebook opens with what the student will be able to do and ends with a recap and where to go
  next, refers to no file a clone lacks, and carries what the browser edition needs (``language_info``,
  ``import ipympl`` beside ``%matplotlib widget``).
"""
import json
import math
import re
from pathlib import Path

import nbformat
import pytest

from support.nbmarks import checks_output, ignores_output

NOTEBOOKS = Path(__file__).resolve().parents[2] / "notebooks"
NAMES = sorted(p.stem for p in NOTEBOOKS.glob("[0-9][0-9]_*.ipynb"))      # every notebook of the course
EXECUTED = [n for n in NAMES if not n.startswith("08_")]   # 08 is the student's version: generated, not run
BASICS = ["01_start_here", "02_homogeneous_matrices", "03_robot_no_tan_elemental", "04_pr_mechanism_and_spaces"]
NUMBER = re.compile(r"(?<![\w.])-?\d+(?:\.\d+)?")          # not the 1 of q1 or θ1, nor the 2 of {S_2}
DECIMAL = re.compile(r"(?<![\w.{,])[-−]?\d+\.\d+(?![\w])")  # decimals in text; seed quotes use commas (0{,}866)


def load(name):
    return nbformat.read(NOTEBOOKS / f"{name}.ipynb", as_version=4)


def output_text(cell) -> str:
    parts = []
    for out in cell.get("outputs", []):
        if out.output_type == "stream":
            parts.append(out.text)
        elif out.output_type in ("execute_result", "display_data"):
            parts.append(out.data.get("text/plain", ""))
    return "\n".join(parts)


def numbers(text):
    return [float(m) for m in NUMBER.findall(text)]


def checked_numbers(nb):
    """The numbers printed by the cells tagged nbval-check-output, in order."""
    return numbers("\n".join(output_text(c) for c in nb.cells
                             if checks_output(c)))


def contains_sequence(values, expected, tol=1e-6) -> bool:
    expected = [float(v) for v in expected]
    n = len(expected)
    return any(all(abs(values[i + k] - expected[k]) <= tol for k in range(n))
               for i in range(len(values) - n + 1))


@pytest.fixture(scope="module")
def notebooks():
    return {name: load(name) for name in NAMES}


@pytest.fixture(scope="module")
def seed_cases():
    path = Path(__file__).resolve().parents[2] / "dhlab" / "data" / "seed_cases.json"
    return {c["id"]: c for c in json.loads(path.read_text(encoding="utf-8"))["cases"]}


# --- the notebooks are stored executed, without errors ----------------------------------------------
@pytest.mark.parametrize("name", EXECUTED)
def test_stored_executed_without_errors(notebooks, name):
    for cell in notebooks[name].cells:
        if cell.cell_type != "code":
            continue
        assert cell.execution_count is not None, f"{name}: a cell was not executed:\n{cell.source[:80]}"
        assert all(o.output_type != "error" for o in cell.outputs), f"{name}: a cell raised:\n{cell.source[:80]}"


# --- numbers in the text are numbers the code prints -----------------------------------------------
def is_exercise_statement(source) -> bool:
    """A markdown cell that states an exercise (its numbers are data, not results)."""
    return (source.lstrip().startswith("## Exercises") or "**Exercise" in source or "**Predict first" in source
            or re.search(r"\*\*(Part|Task|Question) \d", source) is not None)


def text_numbers(nb):
    """(number as written, digits after the point) in the markdown, exercise statements left out."""
    found = []
    for cell in nb.cells:
        if cell.cell_type != "markdown" or is_exercise_statement(cell.source):
            continue
        # not results: section numbers (§3.2), versions (Python 3.10), code spans
        text = re.sub(r"§\s*[\d.–-]+|Python \d+\.\d+|`[^`]*`", " ", cell.source)
        for match in DECIMAL.findall(text):
            found.append((float(match.replace("−", "-")), len(match.split(".")[1])))
    return found


@pytest.mark.parametrize("name", EXECUTED)
def test_numbers_in_the_text_are_printed_by_the_code(notebooks, name):
    nb = notebooks[name]
    printed = numbers("\n".join(output_text(c) for c in nb.cells if c.cell_type == "code"))
    missing = [(value, digits) for value, digits in text_numbers(nb)
               if not any(abs(p - value) <= 0.5 * 10 ** -digits + 1e-12 for p in printed)]
    assert not missing, f"{name}: the text states numbers that no code output prints: {missing}"


# --- the seeds' cases, printed by checked cells --------------------------------------------------------
SEED004 = ["004_robot1_primer_caso", "004_robot1_segundo_caso", "004_robot2_theta_-45", "004_robot2_bandera",
           "004_robot2_exercise_theta_-90_dmax"]


@pytest.mark.parametrize("case_id", SEED004)
def test_seed_004_cases_in_notebook_3(notebooks, seed_cases, case_id):
    values = checked_numbers(notebooks["03_robot_no_tan_elemental"])
    case = seed_cases[case_id]
    assert contains_sequence(values, case["expected_position"]), f"{case_id}: position not printed"
    pose = [v for row in case["expected_pose"] for v in row]
    assert contains_sequence(values, pose), f"{case_id}: pose ⁰H₂ not printed"


def test_seed_004_segundo_caso_details_in_notebook_3(notebooks):
    values = checked_numbers(notebooks["03_robot_no_tan_elemental"])
    assert contains_sequence(values, [0.606218, 0.35, 0.0])            # joint 2 (VERIFIED_MATH §2.1)
    assert contains_sequence(values, [30.0]) and contains_sequence(values, [0.9598], 1e-4)


@pytest.mark.parametrize("case_id", ["003_PR_ik_2.0_0.25", "003_PR_ik_2.0_-0.4", "003_PR_ik_1.2_0.5"])
def test_seed_003_inverse_kinematics_in_notebook_4(notebooks, seed_cases, case_id):
    values = checked_numbers(notebooks["04_pr_mechanism_and_spaces"])
    case = seed_cases[case_id]
    solutions = case["expected_solutions"]
    for branch in ("AB" if case["expected_solution_count"] == 2 else "A"):
        q = solutions[branch]
        assert contains_sequence(values, [q["q1"], q["q2"]]), f"{case_id}: branch {branch} not printed"
        assert contains_sequence(values, [math.degrees(q["q2"])]), f"{case_id}: q2{branch} in degrees"


def test_seed_003_unreachable_target_in_notebook_4(notebooks, seed_cases):
    x, y = seed_cases["003_PR_ik_unreachable"]["target_position"]
    text = "\n".join(output_text(c) for c in notebooks["04_pr_mechanism_and_spaces"].cells
                     if checks_output(c))
    line = next(line for line in text.splitlines() if f"({x}, {y})" in line)
    assert "no solution" in line and "nan" not in line.lower()


@pytest.mark.parametrize("case_id", ["003_geom1_PRR_0.0_0_0", "003_geom1_PRR_0.3_30_45",
                                     "003_geom2_RRR_0_0_0", "003_geom2_RRR_30_45_-30"])
def test_seed_003_geometric_examples_in_notebook_4(notebooks, seed_cases, case_id):
    values = checked_numbers(notebooks["04_pr_mechanism_and_spaces"])
    assert contains_sequence(values, seed_cases[case_id]["expected_position"])


@pytest.mark.parametrize("angle", [0, 30, 45])
def test_seed_001_listing_in_notebook_2(notebooks, seed_cases, angle):
    values = checked_numbers(notebooks["02_homogeneous_matrices"])
    case = seed_cases[f"001_DefinirTHz_{angle}"]
    assert contains_sequence(values, [angle, round(case["listing_001_det_R"], 6) + 0.0])
    if angle == 30:
        assert contains_sequence(values, [v for row in case["listing_001_output"] for v in row])


# --- errata are stated where they arise ---------------------------------------------------------------------
ERRATA = {
    "02_homogeneous_matrices": ["000-1", "004-16", "000-8"],
    "03_robot_no_tan_elemental": [f"004-{k}" for k in range(1, 16)],
    "04_pr_mechanism_and_spaces": ["003-1", "004-17"],
}


@pytest.mark.parametrize("name", list(ERRATA))
def test_errata_are_stated(notebooks, name):
    text = "\n".join(c.source for c in notebooks[name].cells if c.cell_type == "markdown")
    stated = set(re.findall(r"\b(\d{3}-\d+)\b", text))
    missing = [e for e in ERRATA[name] if e not in stated]
    assert not missing, f"{name}: errata not stated: {missing}"


# --- live panels are not compared -----------------------------------------------------------------------------
@pytest.mark.parametrize("name", NAMES)
def test_panel_cells_ignore_their_widget_output(notebooks, name):
    for cell in notebooks[name].cells:
        if cell.cell_type != "code":
            continue
        shows_widget = any("application/vnd.jupyter.widget-view+json" in o.get("data", {}) or
                           "<dhlab" in o.get("data", {}).get("text/plain", "") for o in cell.outputs)
        if shows_widget:
            assert ignores_output(cell), f"{name}: a panel cell is compared:\n{cell.source[:80]}"


@pytest.mark.parametrize("name", BASICS)
def test_exercises_at_the_end_are_checked_by_dhlab(notebooks, name):
    cells = notebooks[name].cells
    start = next(i for i, c in enumerate(cells) if c.cell_type == "markdown" and "## Exercises" in c.source)
    at_end = [c for c in cells[start:] if c.cell_type == "code" and "exercise(" in c.source]
    assert 2 <= len(at_end) <= 4, f"{name}: {len(at_end)} exercises"
    for cell in [c for c in cells if c.cell_type == "code" and "exercise(" in c.source]:
        assert re.search(r"ex\d+\.check\(", cell.source), cell.source


def test_the_readers_exercise_of_seed_004_is_predicted_before_it_is_solved(notebooks):
    """The student answers first (an exercise), the worked solution follows."""
    cells = notebooks["03_robot_no_tan_elemental"].cells
    ask = next(i for i, c in enumerate(cells) if c.cell_type == "code" and 'exercise("3.5")' in c.source)
    solve = next(i for i, c in enumerate(cells) if c.cell_type == "code" and "exercise_pose" in c.source)
    assert "Predict first" in cells[ask - 1].source and ask < solve
    assert "The worked answer" in "".join(c.source for c in cells[ask + 1:solve])


# --- what every notebook opens and ends with, and what it may refer to ------------------------------------------
def markdown(nb) -> str:
    return "\n".join(c.source for c in nb.cells if c.cell_type == "markdown")


@pytest.mark.parametrize("name", NAMES)
def test_opens_with_objectives_and_ends_with_a_recap(notebooks, name):
    cells = [c for c in notebooks[name].cells if c.cell_type == "markdown"]
    head = "\n".join(c.source for c in cells[:2])
    assert "After this notebook you can" in head, f"{name}: no learning objectives at the top"
    lines = head.split("After this notebook you can", 1)[1].splitlines()[1:]
    bullets, started = 0, False
    for line in lines:
        if line.startswith("* "):
            bullets, started = bullets + 1, True
        elif started and not line.startswith(" "):
            break
    assert 3 <= bullets <= 5, f"{name}: {bullets} objectives (3-5 expected)"
    if name.startswith("09_"):
        return                                    # the last notebook: a reference list, nothing after it
    last = cells[-1].source
    assert re.search(r"^## Recap", last, flags=re.M), f"{name}: the last cell is not a recap"
    assert re.search(r"\*\*Next:\*\*.*\]\(\d\d_[\w]+\.ipynb", last, flags=re.S), f"{name}: no 'Next:' link"


CLONE_LACKS = re.compile(r"shared/|VERIFIED_MATH|ERRATA\.md|\.\./tests/")


@pytest.mark.parametrize("name", NAMES)
def test_refers_to_no_file_a_clone_lacks(notebooks, name):
    for cell in notebooks[name].cells:
        found = CLONE_LACKS.findall(cell.source)
        assert not found, f"{name}: refers to {found} (a clone has no such file):\n{cell.source[:120]}"


@pytest.mark.parametrize("name", NAMES)
def test_links_to_other_notebooks_exist(notebooks, name):
    for cell in notebooks[name].cells:
        if cell.cell_type != "markdown":
            continue
        for target, anchor in re.findall(r"\]\((\d\d_[\w]+\.ipynb)(?:#([\w-]+))?\)", cell.source):
            assert (NOTEBOOKS / target).exists(), f"{name}: links to {target}, which does not exist"
            if anchor:
                other = load(target[:-len(".ipynb")])
                headings = {re.sub(r"\s+", "-", h.strip()) for h in
                            re.findall(r"^#+ (.+)$", markdown(other), flags=re.M)}
                assert anchor in headings, f"{name}: links to {target}#{anchor}, no such heading"


@pytest.mark.parametrize("name", NAMES)
def test_ready_for_the_browser_edition(notebooks, name):
    nb = notebooks[name]
    assert nb.metadata.get("language_info", {}).get("name") == "python", f"{name}: no language_info"
    for cell in nb.cells:
        if cell.cell_type == "code" and "%matplotlib widget" in cell.source:
            assert "import ipympl" in cell.source, f"{name}: %matplotlib widget without import ipympl"


@pytest.mark.parametrize("name", EXECUTED)
def test_stored_figures_are_readable(notebooks, name):
    """Every stored static figure at least 450 px wide."""
    import base64
    import struct
    for cell in notebooks[name].cells:
        for out in cell.get("outputs", []):
            png = out.get("data", {}).get("image/png")
            if png:
                width = struct.unpack(">I", base64.b64decode(png)[16:20])[0]
                assert width >= 450, f"{name}: a figure {width} px wide:\n{cell.source[:80]}"
