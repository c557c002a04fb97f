"""Notebook 7's print helpers (dhlab.course.lessons.lesson_ssrms) and seed 001's arm (ssrms_program.seed001_frames),
measured against the arm, the line maths and the verified cases; and notebook 7 as a deck: its set-up
hidden, its helper code out of its lesson cells, its C++ appendix off the lecture's screens."""
import json
import re
from pathlib import Path

import numpy as np
import pytest

from dhlab import robots
from dhlab.course.lessons.lesson_ssrms import axis_relations, factors_latex, fmt, frames_table, same_axes, seed_words
from dhlab.course.lessons.ssrms_program import CONFIGURAR_TH, seed001_frames
from dhlab.data import load as load_data
from dhlab.errors import DHLabError
from dhlab.lines import relation
from dhlab.transforms import Rx, trans

SSRMS = robots.ssrms()
CASES = {c["id"]: c for c in load_data("seed_cases")["cases"]}
NOTEBOOK = Path(__file__).resolve().parents[2] / "notebooks" / "07_ssrms.ipynb"


def test_fmt_rounds_and_drops_negative_zero():
    assert fmt([1e-12, -1e-12, 2.5]) == "(0, 0, 2.5)"
    assert fmt([-3.14159, 12.0, -0.0004], 2) == "(-3.14, 12, 0)"
    assert fmt(np.array([[1.0], [2.0], [3.0]])) == "(1, 2, 3)"


def test_factors_latex_has_every_factor_once_on_two_lines():
    text = factors_latex(CONFIGURAR_TH)
    for k, (_d, alpha, a) in enumerate(CONFIGURAR_TH, start=1):
        assert rf"T_z[\theta_{k}," in text and rf"T_x[{alpha}^\circ, {a}]" in text
    assert text.count(r"T_z[") == 7 and text.count(r"T_x[") == 7 and text.count(r"\\") == 1
    assert factors_latex(CONFIGURAR_TH, per_line=7).count(r"\\") == 0
    with pytest.raises(DHLabError, match="one \\(d, alpha_deg, a\\) per link"):
        factors_latex([(1, 2)])


def test_frames_table_is_the_frames_at_zero_and_same_axes_reads_the_verified_case():
    case = CASES["000_SSRMS_0_0_0_0_0_0_0"]
    F0 = SSRMS.frames(SSRMS.qz)
    lines = frames_table(F0).splitlines()
    assert len(lines) == 1 + len(F0)
    for line, origin in zip(lines[1:], case["frame_origins"]):
        assert fmt(origin) in line
    assert same_axes(F0, case["frame_axes_zero"])
    turned = F0.copy()
    turned[3] = turned[3] @ Rx(np.pi / 2)
    assert not same_axes(turned, case["frame_axes_zero"])
    assert not same_axes(F0[:-1], case["frame_axes_zero"])
    with pytest.raises(DHLabError, match="shape"):
        frames_table(F0[0])


def test_seed_words_say_the_matrix_the_link_is_checked_against():
    for link, (angle, point) in {1: (-90, (0, 0, 2.5)), 3: (0, (12, 0, 6))}.items():
        words = seed_words(angle, point)
        assert f"{point[0]:g}i+{point[1]:g}j+{point[2]:g}k" in words
        assert ("turned -90° about x" in words) == bool(angle) and ("unturned" in words) != bool(angle)
        assert np.allclose(SSRMS.A(link, 0.0), trans(*point) @ Rx(np.radians(angle)))


def test_axis_relations_agree_with_the_line_maths_at_random_configurations():
    Q = np.random.default_rng(5).uniform(-np.pi, np.pi, size=(20, 7))
    F = SSRMS.frames(Q)
    kinds = {i: {r.kind for r in axis_relations(F, i)} for i in range(1, 8)}
    assert kinds == {1: {"intersect"}, 2: {"intersect"}, 3: {"parallel"}, 4: {"parallel"}, 5: {"intersect"},
                     6: {"intersect"}, 7: {"coincident"}}
    assert np.allclose([r.distance for r in axis_relations(F, 3)], 12)
    one = axis_relations(F, 4)[7]
    direct = relation((F[7, 3, :3, 3], F[7, 3, :3, 2]), (F[7, 4, :3, 3], F[7, 4, :3, 2]))
    assert one.kind == direct.kind and np.isclose(one.distance, direct.distance)
    with pytest.raises(DHLabError, match="i = 0"):
        axis_relations(F, 0)
    with pytest.raises(DHLabError, match="configurations, frames"):
        axis_relations(F[0], 1)


def test_seed001_frames_fold_the_arm_as_verified():
    wrong = seed001_frames([0] * 7)[-1]
    assert np.allclose(wrong[:3, 3], (0, 0, 10.5)) and np.isclose(np.linalg.det(wrong[:3, :3]), -1)
    at45 = seed001_frames([45] * 7)[-1]
    assert np.allclose(at45[:3, 3], (-0.5, 0.5, 12.692), atol=5e-4) and np.isclose(np.linalg.det(at45[:3, :3]), 0)
    assert seed001_frames([10] * 7).shape == (8, 4, 4)
    for bad in ([0] * 6, "seven", [[0] * 7]):
        with pytest.raises(DHLabError, match="7 joint angles"):
            seed001_frames(bad)


# --- notebook 7 as a deck -----------------------------------------------------------------------------------
def _cells():
    if not NOTEBOOK.exists():
        pytest.skip("notebook 7 not present")
    return json.loads(NOTEBOOK.read_text(encoding="utf-8"))["cells"]


def _kind(cell):
    return cell["metadata"].get("slideshow", {}).get("slide_type")       # None: continues the screen


def test_setup_is_hidden_sets_the_language_and_defines_no_helper():
    cells = _cells()
    setup = next(c for c in cells if c["cell_type"] == "code")
    source = "".join(setup["source"])
    assert _kind(setup) == "skip" and setup["metadata"]["jupyter"]["source_hidden"]
    lines = source.splitlines()
    assert lines[lines.index("import dhlab") + 1] == 'dhlab.set_language("en")'
    shown = "\n".join("".join(c["source"]) for c in cells if c["cell_type"] == "code" and _kind(c) != "skip")
    # the one function on screen is the lesson itself: the seed's product of the 14 factors
    assert re.findall(r"^\s*(?:def|class) (\w+)", shown, re.M) == ["fourteen_factors"], "helper code on a slide"


def test_appendix_is_one_screen_and_the_panel_has_its_own():
    cells = _cells()
    start = next(i for i, c in enumerate(cells) if "".join(c["source"]).startswith("## 6. The seed's keyboard"))
    assert _kind(cells[start]) == "slide"
    assert all(_kind(c) in ("skip", "notes") for c in cells[start + 1:-1])
    assert "".join(cells[-1]["source"]).startswith("## Recap") and _kind(cells[-1]) == "slide"
    panel = next(i for i, c in enumerate(cells) if "teach(ssrms)" in "".join(c["source"]) and _kind(c) != "skip")
    head = max(i for i in range(panel) if _kind(cells[i]) in ("slide", "subslide"))
    on_screen = [c for c in cells[head:panel] if _kind(c) not in ("skip", "notes")]
    assert len(on_screen) == 1 and "".join(on_screen[0]["source"]).startswith("## 4. Seven sliders")
