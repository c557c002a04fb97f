"""The assignment's own checks in Spanish: what the student's kernel says after
``dhlab.set_language("es")`` — the boundary errors of Tz/Tx/q_i, the tables, the figures'
words, the teach panel's notes, the note of part 3 — and Spanish words accepted where a word
is asked. The feedback lines of each part come from dhlab.assignment.checks
(tests/assignment/test_assignment_checks.py); here: that check_part gives the same scores in either
language, and its own words are Spanish.
"""
import re
from pathlib import Path

import nbformat
import pytest

from dhlab import deg2rad
from dhlab.assignment import notebook as A
from dhlab.assignment.model import build
from dhlab.assignment.pictures import axes_figure
from dhlab.assignment.tables import axes_table, points_table
from dhlab.errors import DHLabError
from dhlab.i18n import set_language

ROOT = Path(__file__).resolve().parents[2]
SUBMISSIONS = ROOT / "tests/data/submissions"
# words a Spanish sentence of the assignment never holds (whole words, lower case)
ENGLISH = re.compile(r"\b(the|is|are|of|and|in|be|must|got|give|number|your|you|not|with|joint|link|frame|home|"
                     r"write|first|only|cannot)\b")


@pytest.fixture
def spanish():
    previous = set_language("es")
    yield
    set_language(previous)


def english_words(text: str) -> list:
    """The English words left in ``text`` (names in code, like Tz(...) or check_part3, do not count)."""
    text = re.sub(r"`[^`]*`|\w+\([^)]*\)|\$[^$]*\$", " ", text)
    return ENGLISH.findall(text.lower())


def answers_of(name: str) -> dict:
    """The namespace a student's filled-in notebook builds: its setup and answer cells, run."""
    nb = nbformat.read(SUBMISSIONS / name, 4)
    ns = {}
    for cell in nb.cells:
        if cell.metadata.get("nbgrader", {}).get("grade_id") in ("setup", "part1_answers", "part2_answers",
                                                                   "part3_answers"):
            exec(cell.source, ns)
    return ns


# --- the boundary: Tz, Tx, q_i and the parts, in Spanish ------------------------------------------------------
q1, q2 = A.joint_variables(2)
MISTAKES = {
    "two joint variables": (lambda: A.Tz(q1, q2), "dos variables articulares"),
    "Tx first": (lambda: A.Tx(90, 0) @ A.Tz(q1, 0), "primero Tz"),
    "a joint variable in Tx": (lambda: A.Tx(q1, 0), "la variable articular va en Tz"),
    "text that is no term": (lambda: A.Tz("q2 + x", 0), "un número o ±q_i \\+ una constante"),
    "too large": (lambda: A.Tz(1e9, 0), "demasiado grande"),
    "an angle for d": (lambda: A.Tz(0, deg2rad(3)), "es una longitud, pero dio un ángulo"),
    "two joint variables added": (lambda: q1 + q2, "no se pueden sumar"),
    "a factor": (lambda: q1 * 2, "no se puede multiplicar"),
    "part 4": (lambda: A.check_part(4, {}), "las partes 1, 2 y 3"),
    "no namespace": (lambda: A.check_part(1, 7), "pase las variables del cuaderno"),
    "a chain of numbers": (lambda: A.DHChain([1, 2]), "una cadena es una lista de transformaciones"),
}


@pytest.mark.parametrize("what", sorted(MISTAKES))
def test_a_mistake_at_the_boundary_is_explained_in_spanish(what, spanish):
    make, spanish_words = MISTAKES[what]
    with pytest.raises(DHLabError, match=spanish_words) as info:
        make()
    assert not english_words(str(info.value)), str(info.value)


@pytest.mark.parametrize("what", sorted(MISTAKES))
def test_the_same_mistake_is_explained_in_english_by_default(what):
    make, spanish_words = MISTAKES[what]
    with pytest.raises(DHLabError) as info:
        make()
    assert not re.search(spanish_words, str(info.value)) and english_words(str(info.value))


# --- what the student reads: tables, figures, notes -------------------------------------------------------------
def test_the_pumas_tables_in_spanish(spanish):
    axes, points = repr(A.axes_table()), repr(A.points_table())
    assert axes.splitlines()[0].startswith("Ejes de las articulaciones en la posición inicial")
    assert "dirección positiva" in axes and "articulación 6" in axes
    assert "3 (antebrazo)" in points and "mundo (x, y, z)" in points
    for table in (axes, points, A.axes_table()._repr_html_()):
        assert not english_words(re.sub(r"<[^>]+>", " ", table)), table


@pytest.mark.parametrize("key", ["stanford", "cobra600"])
def test_a_family_robots_tables_and_figure_in_spanish(key, spanish):
    robot = build(key)
    axes, points = repr(axes_table(robot)), repr(points_table(robot))
    assert "prismática" in axes and "efector final" in axes
    assert "(prismático)" in points
    fig = axes_figure(robot)
    texts = [fig._suptitle.get_text()] + [ax.get_title() for ax in fig.axes] + \
            [t.get_text() for legend in fig.legends for t in legend.texts]
    assert "eslabón 0: base" in texts and "posición inicial (q = 0), sistema del mundo 0" in texts
    for text in [axes, points] + texts:
        assert not english_words(text.replace(robot.name, "")), text


def test_the_pumas_figure_in_spanish(spanish):
    fig = A.puma_figure()
    texts = [fig._suptitle.get_text()] + [ax.get_title() for ax in fig.axes] + \
            [t.get_text() for legend in fig.legends for t in legend.texts]
    assert "eslabón 2: brazo" in texts
    for text in texts:
        assert not english_words(text.replace("PUMA 560", "")), text


def test_the_notes_before_part_3_is_answered_in_spanish(spanish):
    for note in (A.my_robot_figure({}), A.teach({})):
        assert isinstance(note, A.Note) and note.text.startswith("responda primero la parte 3")
        assert not english_words(note.text), note.text


# --- the checks: the same scores in either language, Spanish words accepted ----------------------------------
def test_the_scores_do_not_depend_on_the_language():
    ns = answers_of("mistake_part3.ipynb")
    english = [A.check_part(p, ns).score for p in (1, 2, 3)]
    set_language("es")
    try:
        assert [A.check_part(p, ns).score for p in (1, 2, 3)] == english
    finally:
        set_language("en")
    assert english[2] < 5                       # the mistakes were mistakes


SPANISH_PART1 = {"n_links": 7, "n_joints": 6, "joint_types": ["rotacional"] * 6,
                 "x_cases": ["se cortan", "paralelos", "se cruzan", "se cortan", "se cortan"]}


@pytest.mark.parametrize("language", ["es", "en"])
def test_part_1_answered_with_spanish_words_gets_full_marks(language):
    previous = set_language(language)
    try:
        assert A.check_part1(SPANISH_PART1).full_marks
        wrong = dict(SPANISH_PART1, x_cases=["paralelos"] * 5)
        assert not A.check_part1(wrong).full_marks
    finally:
        set_language(previous)


def test_the_note_of_part_3_in_spanish(spanish):
    """Every T_i right, the links of part 2 drawn in other valid frames: part 3 says so, in Spanish."""
    feedback = A.check_part3(answers_of("mixed_valid_frames.ipynb"))
    assert feedback.score == 5
    assert feedback.note.startswith("(la parte 2 de nuevo, en los sistemas de referencia que construyen estas")
    assert not english_words(feedback.note.split(":")[0]), feedback.note


def test_the_note_of_part_3_in_english():
    feedback = A.check_part3(answers_of("mixed_valid_frames.ipynb"))
    assert feedback.note.startswith("(part 2 again, in the frames these T1…T6 build:")


@pytest.mark.parametrize("key", ["cobra600", "ur5"])
def test_the_your_robot_section_in_spanish(key, spanish):
    """The "Your robot" section a released notebook opens with, in the notebook's language."""
    from dhlab.assignment import variants as V
    from dhlab.assignment.notebook_cells import robot_intro
    variant = V.variant(key, 5)
    robot = V.robot_of_variant(variant)
    text = robot_intro(robot, {"variant": variant.to_dict(), "student_id": "ana"})
    assert text.startswith("## Su robot\n\nEste cuaderno es para **ana**. Su robot es un **")
    assert f"Tiene {robot.n} articulaciones" in text and "posición inicial" in text
    assert ("todas rotacionales" in text) == ("P" not in robot.kinds)
    assert "· variante " in text and "variant " not in text
    assert not english_words(text)
