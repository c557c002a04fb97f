"""One misspelt word costs one item (and the lesson reads words as the grader does);
a crafted notebook (huge, a million tiny values, deeply nested, a cell whose source is not text)
is that file's row, with its name and why, and the rest of the class is staged."""
from __future__ import annotations

import json
import shutil
import time

import pytest

from dhlab.assignment.answers import Unreadable, parse_answers
from dhlab.assignment.checks import check_part1
from dhlab.course.checks.case_words import read_case_words
from dhlab.course.exercises.dh_rules import read_case
from dhlab.grading.run import notebook_code as NC
from dhlab.grading.run import staging
from dhlab.i18n import speaking

PUMA_CASES = ["intersect", "parallel", "skew", "intersect", "intersect"]


def _part1(x_cases):
    answers = parse_answers({"n_links": 7, "n_joints": 6, "joint_types": "RRRRRR", "x_cases": x_cases})
    return check_part1(answers)


def _x_items(part):
    return [item for item in part.items if item.label.startswith("x")]


# --- words: one slip, one item ----------------------------------------------------------------

def test_a_word_that_is_no_case_costs_its_item_only():
    part = _part1(["intersect", "parrallel", "skew", "intersect", "intersect"])
    oks = [item.ok for item in _x_items(part)]
    assert oks == [True, False, True, True, True], part.text()
    wrong = _x_items(part)[1]
    assert "'parrallel'" in wrong.message and "did you mean 'parallel'" in wrong.message, wrong.message
    assert part.score == 1.75


def test_small_slips_of_spelling_are_read_as_the_lesson_reads_them():
    for word in ("paralel", "paralell", "Parallel lines", "paralelos", "paralelas"):
        assert _part1(["intersect", word, "skew", "intersect", "intersect"]).full_marks, word
    for word in ("intersects", "intersecting", "se cortan", "se intersecan", "case 1", 1):
        assert _part1([word, "parallel", "skew", "intersect", "intersect"]).full_marks, word
    for word in ("skewed", "se cruzan", "alabeadas", "neither", "ni paralelos ni se intersecan",
                 "neither parallel nor intersecting", "caso 3"):
        assert _part1(["intersect", "parallel", word, "intersect", "intersect"]).full_marks, word


def test_a_list_as_one_string_and_empty_entries():
    assert _part1("intersect, paralel; skew, intersect, intersect").full_marks
    part = _part1(["intersect", "", "...", "intersect", "not parallel"])
    assert [item.ok for item in _x_items(part)] == [True, None, None, True, False]
    assert "says what does not hold" in _x_items(part)[4].message


def test_an_answer_naming_two_cases_is_that_items_slip():
    part = _part1(["intersect", "parallel or skew", "skew", "intersect", "intersect"])
    assert [item.ok for item in _x_items(part)] == [True, False, True, True, True]
    assert "several cases" in _x_items(part)[1].message


def test_the_feedback_is_in_the_students_language():
    with speaking("es"):
        part = _part1(["intersect", "paralelso", "se crusan", "intersect", "intersect"])
    assert [item.ok for item in _x_items(part)] == [True, True, False, True, True]
    message = _x_items(part)[2].message
    assert "'se crusan'" in message and "no es un caso" in message and "se cruzan" in message, message


def test_the_lesson_and_the_grader_read_every_word_alike():
    words = ["paralel", "intersects", "skewed", "parrallel", "se cruzan", "neither", "coincident", "same line",
             "they do not intersect", "parallel or skew", "case 2", "caso 3", "3", "hello", "ni paralelos ni se "
             "intersecan", "Intersecting", "alabeadas", "misma recta", "not skew", "se cortan"]
    for word in words:
        lesson = read_case(word)[0]
        graded = parse_answers({"x_cases": [word]}).x_cases[0]
        assert lesson == (None if isinstance(graded, Unreadable) else graded) == read_case_words(word).case, word


# --- a cell whose source is not text ------------------------------------------------------------------

def _nb(*sources) -> dict:
    return {"nbformat": 4, "nbformat_minor": 5, "metadata": {},
            "cells": [{"cell_type": "markdown", "metadata": {}, "source": "# title"}] +
                     [{"cell_type": "code", "metadata": {}, "source": s, "outputs": []} for s in sources]}


def test_a_list_of_strings_is_the_normal_source():
    assert NC.code_cells_of(_nb(["a = 1\n", "b = 2"], "c = 3")) == [(2, "a = 1\nb = 2"), (3, "c = 3")]


@pytest.mark.parametrize("source, said", [(5, "a number (5)"), ({"code": "x = 1"}, "an object (a dict)"),
                                          (None, "null"), (["x = 1\n", 7], "line 2 of its source is a number (7)")])
def test_a_source_that_is_not_text_is_reported_with_its_cell(source, said):
    with pytest.raises(NC.NotebookError) as error:
        NC.code_cells_of(_nb("n_links = 7", source))
    assert "cell 3 cannot be read" in str(error.value) and said in str(error.value), str(error.value)


# --- staging a class with crafted files ------------------------------------------------------------

def _good(folder):
    path = folder / "good.ipynb"
    path.write_text(json.dumps(_nb("n_links = 7")), encoding="utf-8")
    return path


def _stage_class(folder, bad_path):
    into, staged = staging.stage_all(folder, [bad_path, _good(folder)])
    bad, good = staged
    good_copy = json.loads(good.copy.read_text()) if good.copy else None
    shutil.rmtree(into)                              # the grader removes its copies; so does the test
    assert good.copy is not None and good.error == "", good
    assert good_copy["cells"][1]["source"] == "n_links = 7"
    assert bad.copy is None and bad.file == bad_path.name
    return bad


def test_a_file_over_the_size_limit_is_not_read(tmp_path):
    big = tmp_path / "big.ipynb"
    with open(big, "wb") as f:                       # sparse: no memory, no disk
        f.truncate(NC.MAX_NOTEBOOK_BYTES + 50_000_000)
    bad = _stage_class(tmp_path, big)
    assert "150.0 MB, more than 100 MB" in bad.error and "Clear Outputs" in bad.error, bad.error


def test_a_million_tiny_values_are_refused_before_the_json_is_read(tmp_path):
    crafted = tmp_path / "tiny_values.ipynb"          # 3.3 MB that Python's JSON reader would make ~70 MB
    body = json.dumps(_nb("n_links = 7"))[:-2] + ', "junk": [' + "[]," * 1_100_000 + "[]]}"
    crafted.write_text(body, encoding="utf-8")
    started = time.monotonic()
    bad = _stage_class(tmp_path, crafted)
    assert "JSON values, more than 1000000" in bad.error, bad.error
    assert bad.sha256 and time.monotonic() - started < 5


def test_the_memory_to_read_a_file_counts_how_python_stores_its_text():
    ascii_text = b'"' + b"A" * 10_000 + b'"'
    emoji = '"\U0001F600'.encode() + b"A" * 9_996 + b'"'
    escaped = b'"\\ud83d\\ude00' + b"A" * 9_988 + b'"'
    arrow = '"\u2192'.encode() + b"A" * 9_997 + b'"'
    accent = '"é'.encode() + b"A" * 9_998 + b'"'
    sizes = [NC.memory_to_read(raw) for raw in (ascii_text, accent, arrow, emoji, escaped)]
    assert len({len(raw) for raw in (ascii_text, accent, arrow, emoji, escaped)}) == 1
    assert sizes[0] == sizes[1] < sizes[2] < sizes[3] == sizes[4], sizes
    assert NC.memory_to_read(b"[" + b"[]," * 1000 + b"[]]") > 1000 * 100


def test_a_file_that_would_take_too_much_memory_is_refused(tmp_path, monkeypatch):
    monkeypatch.setattr(NC, "MAX_READ_BYTES", 100_000)
    crafted = tmp_path / "emoji.ipynb"                 # one emoji: Python would keep the text 4 bytes a character
    nb = _nb("n_links = 7")
    nb["cells"][1]["outputs"] = [{"output_type": "stream", "name": "stdout", "text": "\U0001F600" + "A" * 20_000}]
    crafted.write_text(json.dumps(nb, ensure_ascii=False), encoding="utf-8")
    bad = _stage_class(tmp_path, crafted)
    assert "reading the file would take about" in bad.error and "more than 0 MB" in bad.error, bad.error
    plain = tmp_path / "plain.ipynb"                   # the same size in ASCII is read
    nb["cells"][1]["outputs"][0]["text"] = "A" * 20_004
    plain.write_text(json.dumps(nb), encoding="utf-8")
    assert NC.read_code_cells(plain) == [(2, "n_links = 7")]


def test_deeply_nested_json_is_that_files_row(tmp_path):
    crafted = tmp_path / "deep.ipynb"
    crafted.write_text('{"cells": [], "x": ' + "[" * 200_000 + "]" * 200_000 + "}", encoding="utf-8")
    bad = _stage_class(tmp_path, crafted)
    assert "not a notebook" in bad.error, bad.error


def test_a_cell_source_that_is_not_text_is_that_files_row(tmp_path):
    crafted = tmp_path / "number_source.ipynb"
    crafted.write_text(json.dumps(_nb("n_links = 7", 42)), encoding="utf-8")
    bad = _stage_class(tmp_path, crafted)
    assert "cell 3 cannot be read" in bad.error and "a number (42)" in bad.error, bad.error


def test_running_out_of_memory_on_one_file_grades_the_rest(tmp_path, monkeypatch):
    real = staging.read_notebook_json
    crafted = tmp_path / "crafted.ipynb"
    crafted.write_text(json.dumps(_nb("x = 1")), encoding="utf-8")

    def reader(raw, **options):
        if b"x = 1" in raw:
            raise MemoryError
        return real(raw, **options)

    monkeypatch.setattr(staging, "read_notebook_json", reader)
    bad = _stage_class(tmp_path, crafted)
    assert "out of memory" in bad.error and bad.grader_fault, bad


def test_the_runner_refuses_a_source_that_is_not_text(tmp_path):
    from dhlab.grading.run import runner
    path = tmp_path / "n.ipynb"
    path.write_text(json.dumps(_nb(["n_links = 7\n", {"x": 1}])), encoding="utf-8")
    with pytest.raises(runner.NotebookError, match="cell 2 cannot be read"):
        runner.read_code_cells(path)
