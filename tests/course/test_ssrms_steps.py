"""Notebook 7's SSRMS step by step (dhlab.course.lessons.ssrms_steps, the Paso figures) and the seed's C++
program (dhlab.course.lessons.ssrms_program), measured on the arm and on what the figures draw; and the notebook's
order: Paso 0 → 3 before the table, the student's prediction before the figure that answers it, the C++
keyboard material in an appendix at the end."""
import json
import re
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest

from dhlab import robots
from dhlab.course.exercises import four_axis_arm
from dhlab.course.exercises.ssrms import printed_key_position
from dhlab.course.lessons import figures_ssrms
from dhlab.course.lessons.ssrms_program import KEYS, SeedProgram
from dhlab.course.lessons.ssrms_steps import frames_b, x_steps, z_axes
from dhlab.errors import DHLabError
from support.drawn_text import drawn, text_box, visible_texts

NOTEBOOK = Path(__file__).resolve().parents[2] / "notebooks" / "07_ssrms.ipynb"
SSRMS = robots.ssrms()


def _on_line(point, line, tol=1e-9):
    return line.distance_to_point(point) < tol


# --- Paso 1 … 3 -------------------------------------------------------------------------------------------
def test_each_z_lies_on_the_next_joints_axis():
    frames = SSRMS.frames(SSRMS.qz)
    lines = z_axes(SSRMS)
    assert len(lines) == SSRMS.n
    for i, line in enumerate(lines):
        # joint i+1 turns frame i+1 about z_i: its origin moves on a circle about this line, the line stays
        q = np.zeros(SSRMS.n)
        q[i] = 0.7
        moved = SSRMS.frames(q)
        assert _on_line(moved[i][:3, 3], line) and np.allclose(moved[i][:3, 2], line.direction)
        assert _on_line(frames[i][:3, 3], line)


@pytest.mark.parametrize("robot", [SSRMS, four_axis_arm()], ids=["ssrms", "four-axis arm"])
def test_x_steps_follow_the_three_cases(robot):
    lines = z_axes(robot)
    for step in x_steps(robot):
        before, after = lines[step.i - 1], lines[step.i]
        assert _on_line(step.foot, before, 1e-7) and _on_line(step.origin, after, 1e-7)
        normal = step.origin - step.foot
        assert abs(normal @ before.direction) < 1e-7 and abs(normal @ after.direction) < 1e-7
        assert step.length == pytest.approx(abs(float(robot.links[step.i - 1].a)), abs=1e-7)
        parallel = np.linalg.norm(np.cross(before.direction, after.direction)) < 1e-9
        assert step.case == (2 if parallel else 1 if step.length < 1e-9 else 3)
        if step.case == 1:
            assert np.allclose(step.x, np.cross(after.direction, before.direction))   # the seed's sign
        else:
            assert np.allclose(step.x, normal / step.length)                          # from z_(i-1) to z_i


def test_ssrms_cases_are_the_seeds_and_the_other_arm_has_a_skew_pair():
    assert [s.case for s in x_steps(SSRMS)] == [1, 1, 2, 2, 1, 1]          # seed 000, Paso 2, figure 8
    assert 3 in [s.case for s in x_steps(four_axis_arm())]


def test_paso_3_completes_right_handed_frames_that_are_the_tables():
    B = frames_b(SSRMS)
    assert np.allclose(B, SSRMS.frames(SSRMS.qz))
    for F in B:
        assert np.allclose(F[:3, 1], np.cross(F[:3, 2], F[:3, 0]))
        assert np.linalg.det(F[:3, :3]) == pytest.approx(1.0)


def test_steps_refuse_what_is_not_a_robot():
    for bad in ("ssrms", 7, [1, 2]):
        with pytest.raises(DHLabError):
            x_steps(bad)


# --- the seed's C++ program -------------------------------------------------------------------------------
def test_key_presses_are_the_sliders():
    rng = np.random.default_rng(3)
    for _ in range(20):
        program = SeedProgram()
        codes = rng.choice(sorted(KEYS), size=12)
        program.pressed(*codes)
        q = np.radians([program.theta[k] for k in range(1, 8)])
        assert np.allclose(program.renderizar(), SSRMS.fk(q))
        for k in range(1, 8):                                     # each key moves its own joint, 5° a press
            joint_presses = sum(1 for c in codes if KEYS[int(c)][0] == k)
            assert abs(program.theta[k]) == pytest.approx(5.0 * joint_presses)


@pytest.mark.parametrize("joints", [(1,), (2,), (2, 5), (1, 3, 6), (7,)])
def test_printed_handler_matches_the_exercise_helper(joints):
    code_of = {joint: code for code, (joint, _) in KEYS.items()}
    program = SeedProgram(printed=True).pressed(*(code_of[j] for j in joints))
    assert np.allclose(program.renderizar()[:3, 3], printed_key_position(joints))


@pytest.mark.parametrize("code, dtheta", [(1, 5), ("a", 5), ([97], 5), (True, 5), (97, float("nan")), (97, "5")])
def test_bad_keys_are_refused_clearly(code, dtheta):
    with pytest.raises(DHLabError):
        SeedProgram().press(code, dtheta)


# --- the figures ------------------------------------------------------------------------------------------
PASO = {"paso 1": figures_ssrms.paso1_figure, "paso 2": figures_ssrms.paso2_figure,
        "paso 3": figures_ssrms.paso3_figure}


@pytest.mark.parametrize("name", list(PASO))
def test_paso_figures_are_readable_and_whole(name):
    fig = PASO[name](SSRMS)
    renderer = drawn(fig)
    assert fig.bbox.width >= 450 and fig.dpi >= 100
    for text in visible_texts(fig):
        box = text_box(text, renderer)
        assert box.x0 >= 0 and box.y0 >= 0 and box.x1 <= fig.bbox.width and box.y1 <= fig.bbox.height, \
            f"{name}: {text.get_text()!r} is cut at the figure's edge"
        assert text.get_fontsize() * fig.dpi / 72 >= 12 - 1e-9, f"{name}: {text.get_text()!r} is too small"


def _words(fig):
    return {t.get_text() for t in visible_texts(fig)}


def test_paso1_names_every_joint_and_its_z():
    words = _words(figures_ssrms.paso1_figure(SSRMS))
    assert {f"$A_{k}$" for k in range(1, 8)} | {f"$z_{i}$" for i in range(7)} <= words


def test_paso2_draws_the_common_normal_of_each_parallel_pair_and_names_each_case():
    fig = figures_ssrms.paso2_figure(SSRMS)
    words = _words(fig)
    ax = fig.axes[0]
    purple = [np.column_stack(line.get_data_3d()) for line in ax.lines if line.get_color() == "tab:purple"]
    for step in x_steps(SSRMS):
        assert f"$x_{step.i}$: case {step.case}" in words
        if step.case != 1:
            assert any(np.allclose(seg, [step.foot, step.origin]) for seg in purple), step.i
    assert len(purple) == sum(s.case != 1 for s in x_steps(SSRMS))


def test_paso3_names_every_origin_and_draws_y_as_z_cross_x():
    fig = figures_ssrms.paso3_figure(SSRMS)
    words = _words(fig)
    assert {f"$B_{{{i}}}$" for i in range(6)} | {"$B_{6,7}$"} <= words
    thick = [np.column_stack(line.get_data_3d()) for line in fig.axes[0].lines if line.get_linewidth() == 4.5]
    for F in frames_b(SSRMS):
        y = np.cross(F[:3, 2], F[:3, 0])
        assert any(np.allclose(seg[0], F[:3, 3]) and np.allclose(seg[1] - seg[0], 3.0 * y) for seg in thick)


# --- the notebook -------------------------------------------------------------------------------------------
def _cells():
    if not NOTEBOOK.exists():
        pytest.skip("notebook 7 not present")
    return [(c["cell_type"], "".join(c["source"])) for c in json.loads(NOTEBOOK.read_text())["cells"]]


def _first(cells, predicate):
    return next(i for i, (kind, text) in enumerate(cells) if predicate(kind, text))


def test_notebook_teaches_paso_0_to_3_before_the_table_and_asks_before_answering():
    cells = _cells()
    paso = [_first(cells, lambda k, t, p=p: k == "markdown" and f"**Paso {p}" in t) for p in range(4)]
    table = _first(cells, lambda k, t: t.startswith("## 1. From the 14 factors"))
    assert paso == sorted(paso) and paso[-1] < table
    for figure in ("paso1_figure(", "paso2_figure(", "paso3_figure("):
        assert paso[0] < _first(cells, lambda k, t, f=figure: k == "code" and t.startswith(f)) < table
    predict = _first(cells, lambda k, t: k == "code" and "check_x_cases(" in t)
    figure = _first(cells, lambda k, t: k == "code" and t.startswith("paso2_figure("))
    printed = _first(cells, lambda k, t: k == "code" and "for step in x_steps(" in t)
    assert predict < figure and predict < printed
    assert cells[predict + 1][1].startswith("**Check your prediction.**")


def test_notebook_keeps_the_cpp_material_in_an_appendix_at_the_end():
    cells = _cells()
    appendix = _first(cells, lambda k, t: t.startswith("## 6. The seed's keyboard control"))
    exercises = _first(cells, lambda k, t: t.startswith("## Exercises"))
    assert exercises < appendix and cells[-1][1].startswith("## Recap")
    cpp = ("THList", "AplicarTHz", "SeedProgram(", "Micalse", "DefinirTHz")
    # section 1 transcribes configurarTH's table (its heading and the notes cells under it, up to section 2)
    section_1 = _first(cells, lambda k, t: t.startswith("## 1. From the 14 factors"))
    section_2 = _first(cells, lambda k, t: t.startswith("## 2. "))
    before = [i for i, (k, t) in enumerate(cells[:appendix]) if any(w in t for w in cpp)
              and not section_1 <= i < section_2 and "import" not in t]
    assert not before, f"C++ material before the appendix: cells {before}"
    assert not any(k == "code" and "class SeedProgram" in t for k, t in cells), "helper code in a lesson cell"


def test_notebook_says_what_the_label_slips_do_and_keeps_one_notation():
    text = "\n".join(t for k, t in _cells() if k == "markdown")
    slips = next(p for p in text.split("\n\n") if "000-5" in p and "compil" in p)
    compiling = slips.split("000-5")[0]
    assert "000-3" in compiling and "000-4" in compiling
    assert re.search(r"not (?:affected|of the code)", slips), slips
    other_names = r"\\mathrm\{(?:Rot|Tras)\}|Rot_[xz]|T_z\("
    assert not re.search(other_names, text), "one name for a rotation, one for a translation"
