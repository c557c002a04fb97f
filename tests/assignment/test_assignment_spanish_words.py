"""The assignment in the student's words and habits: Spanish answers quoted back, decimal commas named.

A student who answers *se intersecan* reads back *se intersecan* (in the check and in the feedback file,
which is the same text), never the English canonical word. A student used to decimal commas — a point
``(0,4, 0,35, 0)`` or a text ``"0,4"`` — reads that Python wants a decimal point, in either language,
wherever an answer's numbers are read. And the Spanish release's answer cells are Spanish: their
instructions and their code stub.
"""
import json
import re

import pytest

from dhlab.assignment import Tx, Tz
from dhlab.assignment.answers import parse_answers
from dhlab.assignment.checks import check_all
from dhlab.assignment.solution import ANSWER_MARKERS, solved_notebook
from dhlab.errors import DHLabError
from dhlab.i18n import speaking
from dhlab.validation import as_number, as_sequence, as_vector, decimal_comma_note

PART1 = {"n_links": 7, "n_joints": 6, "joint_types": "RRRRRR"}


def _part1(cases, language):
    with speaking(language):
        return check_all(parse_answers({**PART1, "x_cases": cases})).parts[0].text()


def test_a_right_case_is_quoted_back_in_the_students_words():
    text = _part1(["se intersecan", "paralelos", "se cruzan", "se cortan", "caso 1"], "es")
    assert "x1: se intersecan" in text and "x2: paralelos" in text and "x3: se cruzan" in text
    assert "x4: se cortan" in text                       # accepted, and quoted as written
    english = _part1(["intersect", "parallel", "skew", "intersect", 1], "en")
    assert "x1: intersect" in english and "x5: intersect" in english      # a number: the case's own word


def test_a_wrong_case_is_quoted_back_in_the_students_words():
    text = _part1(["paralelos", "se intersecan", "se cruzan", "se cortan", "caso 1"], "es")
    assert "usted escribió 'paralelos'" in text and "usted escribió 'se intersecan'" in text
    assert "'parallel'" not in text and "'intersect'" not in text


def test_a_word_that_is_no_case_is_answered_with_the_spanish_words_first():
    text = _part1(["oblicuos", "paralelos", "se cruzan", "se cortan", "caso 1"], "es")
    assert "use 'se intersecan', 'paralelos' o 'se cruzan'" in text


@pytest.mark.parametrize("language, words", [("en", "decimal points?"), ("es", "puntos? decimal")])
def test_decimal_commas_in_a_point_are_named(language, words):
    with speaking(language):
        part2 = check_all(parse_answers({"link_points": {0: [(0, 4, 0, 35, 0), (0, 0, 0)],
                                                         1: [("0,4", 0, 0)]}})).parts[1].text()
    assert len(re.findall(words, part2)) == 2, part2


@pytest.mark.parametrize("language, words", [("en", "decimal points?"), ("es", "puntos? decimal")])
def test_decimal_commas_in_tz_and_tx_are_named_not_a_typeerror(language, words):
    with speaking(language):
        for make in (lambda: Tz(0, 4, 0, 35), lambda: Tx(90, 0, 5), lambda: Tz("0,4", 0)):
            with pytest.raises(DHLabError, match=words):
                make()


@pytest.mark.parametrize("language, words", [("en", "decimal points?"), ("es", "puntos? decimal")])
def test_decimal_commas_are_named_by_the_common_readers(language, words):
    """The checkers of the lessons read numbers through dhlab.validation: they say it too."""
    with speaking(language):
        for read in (lambda: as_number("0,4", "d"), lambda: as_sequence(("q1", 0, 4, 0, 35, 0), "row", "a row", 4),
                     lambda: as_vector((0, 4, 0, 35, 0), "p", 3)):
            with pytest.raises(DHLabError, match=words):
                read()


def test_only_what_looks_like_decimal_commas_is_named():
    assert decimal_comma_note("0,4") and decimal_comma_note("-1,25") and decimal_comma_note([1, 2, 0, 5], 3)
    assert not decimal_comma_note("0.4") and not decimal_comma_note("1,2,3") and not decimal_comma_note("abc")
    assert not decimal_comma_note([0.4, 0.35, 0.1, 2.5], 3) and not decimal_comma_note((1, 2), 3)
    for odd in (None, object(), {"a": 1}, [[1, 2], [3]], float("nan"), "𝟘,𝟜", b"0,4", 10 ** 400):
        assert isinstance(decimal_comma_note(odd, 3), str)        # odd inputs: no note, no traceback


# --- the Spanish release: its answer cells ----------------------------------------------------------------

def _release(tmp_path, family, language="es"):
    from dhlab.grading.release import notebooks as R
    (tmp_path / "roster.csv").write_text("id\nana\n", encoding="utf-8")
    (tmp_path / "key").write_bytes(b"spanish-words-test-secret-0123456789\n")
    assert R.main(["release", str(tmp_path / "roster.csv"), "-o", str(tmp_path / "out"), "--secret-file",
                   str(tmp_path / "key"), "--family", family, "--language", language]) == 0
    return json.loads((tmp_path / "out" / "ana.ipynb").read_text(encoding="utf-8"))


@pytest.mark.parametrize("family", ["puma560", "cobra600"])
def test_a_spanish_release_has_no_english_comment_line(tmp_path, family):
    from edition.test_edition_comments import english_words  # the same word list as the edition's check

    from dhlab.grading.release.comments import comments
    nb = _release(tmp_path, family)
    code = ["".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "code"]
    english = [c for source in code for c in comments(source) if english_words(c)]
    assert english == [], english
    assert sum(source.count(ANSWER_MARKERS["es"]) for source in code) == 3
    assert not any(ANSWER_MARKERS["en"] in source for source in code)


def test_the_english_release_keeps_its_english_stub(tmp_path):
    nb = _release(tmp_path, "cobra600", "en")
    code = "\n".join("".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "code")
    assert code.count(ANSWER_MARKERS["en"]) == 3 and "# Part 1: write your answers" in code
    assert "a list of three words, for x1 … x3" in code


def test_the_solution_goes_where_the_spanish_stub_is(tmp_path):
    nb = _release(tmp_path, "puma560")
    solved = solved_notebook(nb)
    cells = {c["metadata"]["nbgrader"]["grade_id"]: "".join(c["source"]) for c in solved["cells"]
             if c.get("metadata", {}).get("nbgrader", {}).get("grade_id", "").endswith("_answers")}
    for source in cells.values():
        assert ANSWER_MARKERS["es"] not in source and source.count("### BEGIN SOLUTION") == 1
        assert source.index("### BEGIN SOLUTION") > source.index("# Parte")   # in place of the stub
