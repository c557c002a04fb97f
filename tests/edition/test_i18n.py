"""The Spanish messages: the catalog matches the code, the language is chosen explicitly, and the
checks, errors and panels speak it."""
import ast
import gettext
import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

import dhlab
from dhlab.errors import DHLabError
from dhlab.i18n import _, get_language, language_from_env, set_language
from tools import i18n_catalog

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture
def spanish():
    previous = set_language("es")
    yield
    set_language(previous)


# --- the catalog matches the code ----------------------------------------------------------------------
@pytest.fixture(scope="module")
def catalog():
    return i18n_catalog._read(i18n_catalog.po_path("es"))


@pytest.fixture(scope="module")
def code_messages():
    return {m.id for m in i18n_catalog.extract_messages() if m.id}


def test_every_message_of_the_code_is_in_the_catalog(catalog, code_messages):
    missing = sorted(code_messages - {m.id for m in catalog if m.id})
    assert not missing, f"{len(missing)} messages not in the Spanish catalog (python -m tools.i18n_catalog " \
                        f"extract; ... update; translate): {missing[:5]}"


def test_no_entry_is_untranslated_fuzzy_or_obsolete(catalog, code_messages):
    assert not catalog.obsolete, f"obsolete entries: {list(catalog.obsolete)[:5]}"
    bad = [m.id for m in catalog if m.id and (m.fuzzy or not m.string)]
    assert not bad, f"{len(bad)} untranslated or fuzzy entries: {bad[:5]}"
    stray = sorted({m.id for m in catalog if m.id} - code_messages)
    assert not stray, f"entries no code uses: {stray[:5]}"


def test_placeholders_are_the_same_in_english_and_spanish(catalog):
    differ = [(m.id, m.string) for m in catalog
              if m.id and m.string and i18n_catalog.placeholders(m.id) != i18n_catalog.placeholders(m.string)]
    assert not differ, differ[:5]


def test_placeholder_check_can_fail():
    assert i18n_catalog.placeholders("{name} is {value!r}") != i18n_catalog.placeholders("{nombre} es {value!r}")
    assert i18n_catalog.placeholders("a dict {{term: answer}} for {name}") == ["{name}"]
    assert i18n_catalog.placeholders("%s of %d") == ["%d", "%s"]


def test_the_compiled_catalog_matches_its_source(catalog):
    with open(i18n_catalog.po_path("es").with_suffix(".mo"), "rb") as f:
        compiled = gettext.GNUTranslations(f)
    stale = [m.id for m in catalog if m.id and m.string and compiled.gettext(m.id) != m.string]
    assert not stale, f".mo is stale (python -m tools.i18n_catalog compile): {stale[:3]}"


def test_the_template_lists_the_messages_of_the_code(code_messages):
    template = i18n_catalog._read(i18n_catalog.TEMPLATE)
    assert {m.id for m in template if m.id} == code_messages, "run python -m tools.i18n_catalog extract"


def test_the_check_command_reports_a_missing_translation(tmp_path, monkeypatch):
    """The check fails on an English message the catalog does not have (as after an edit)."""
    real = i18n_catalog.extract_messages

    def with_a_new_message(domain=i18n_catalog.DOMAIN):
        catalog = real(domain)
        catalog.add("a sentence nobody translated yet", locations=[("dhlab/x.py", 1)])
        return catalog
    monkeypatch.setattr(i18n_catalog, "extract_messages", with_a_new_message)
    found = i18n_catalog.problems()
    assert any("a sentence nobody translated yet" in p for p in found)
    assert i18n_catalog.main(["check"]) == 1


def test_every_module_belongs_to_exactly_one_domain():
    """The grader's modules go to its own catalog, every other module to the lessons' one."""
    files = {d: set(i18n_catalog.source_files(d)) for d in i18n_catalog.DOMAINS}
    assert not files["dhlab"] & files["dhlab_grading"]
    every = set((ROOT / "dhlab").rglob("*.py"))
    assert files["dhlab"] | files["dhlab_grading"] == every
    assert ROOT / "dhlab" / "grading" / "cli.py" in files["dhlab_grading"]
    assert ROOT / "dhlab" / "dh_frames" / "report.py" in files["dhlab_grading"]


def test_a_grader_message_is_found_through_the_lessons_catalog():
    """``_`` looks in the lessons' catalog, then the grader's: one function for both."""
    import gettext

    from dhlab import i18n
    es = i18n.translations("es")
    assert isinstance(es, gettext.GNUTranslations)
    assert (i18n_catalog.po_path("es", "dhlab_grading").with_suffix(".mo")).exists()


def test_underscore_is_never_rebound_where_it_translates():
    """A module that imports ``_`` must not use ``_`` as a throw-away name: it would hide the function."""
    offenders = []
    for path in sorted((ROOT / "dhlab").rglob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        imports = any(isinstance(n, ast.ImportFrom) and any(a.name == "_" for a in n.names)
                      for n in ast.walk(tree))
        if not imports:
            continue
        offenders += [f"{path.relative_to(ROOT)}:{n.lineno}" for n in ast.walk(tree)
                      if isinstance(n, ast.Name) and n.id == "_" and isinstance(n.ctx, ast.Store)]
    assert not offenders, offenders


# --- the language is chosen explicitly -----------------------------------------------------------------
def test_set_language_switches_and_returns_the_previous(spanish):
    assert get_language() == "es"
    assert set_language("en") == "es"
    assert _("correct: {name} is right.") == "correct: {name} is right."
    set_language("ES ")
    assert _("correct: {name} is right.") != "correct: {name} is right."


def test_an_unknown_language_is_refused():
    with pytest.raises(DHLabError, match="not one of the course's languages"):
        set_language("fr")
    assert get_language() == "en"


def test_the_environment_variable_names_the_language(monkeypatch):
    monkeypatch.setenv("DHLAB_LANGUAGE", "es")
    assert language_from_env() == "es"
    monkeypatch.delenv("DHLAB_LANGUAGE")
    assert language_from_env() == "en"


@pytest.mark.parametrize("variable", ["LANG", "LANGUAGE", "LC_ALL", "LC_MESSAGES"])
def test_the_machine_locale_does_not_choose_the_language(variable):
    code = ("import dhlab\nfrom dhlab.course.exercises import check_value\n"
            "print(dhlab.get_language()); print(check_value(2, 1, name='q'))")
    env = {**os.environ, variable: "es_ES.UTF-8"}
    env.pop("DHLAB_LANGUAGE", None)
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True).stdout
    assert out.splitlines()[0] == "en"
    assert "q is not right yet." in out


# --- real messages in Spanish ----------------------------------------------------------------------------
def test_feedback_of_a_check_in_spanish(spanish):
    from dhlab.course.exercises import check_matrix, check_value, exercise
    assert str(check_value(2, 1, name="q")).startswith("✗ q todavía no está bien.")
    fb = exercise("1.1").check([45, -90])
    text = str(fb)
    assert text.startswith("✗ Ejercicio 1.1:")
    assert "grados" in text and "radianes" in text and "deg2rad(45)" in text
    assert "¿Se atoró?" in text
    import sympy as sp
    th = sp.Symbol("theta")
    R = sp.Matrix([[sp.cos(th), -sp.sin(th)], [sp.sin(th), sp.cos(th)]])
    assert "transpuesta" in str(check_matrix(R.T, R, name="R"))


def test_feedback_in_english_is_unchanged():
    from dhlab.course.exercises import exercise
    text = str(exercise("1.1").check([45, -90]))
    assert text.startswith("✗ Exercise 1.1: your q is not right yet.")


def test_boundary_error_in_spanish(spanish):
    with pytest.raises(DHLabError, match="más de una vuelta completa") as info:
        dhlab.validation.as_angle(30, "theta")
    assert "dhlab.deg2rad(30)" in str(info.value)


def test_a_message_shown_after_the_switch_is_in_the_new_language():
    """Messages are translated when shown, not when the module is imported."""
    from dhlab.course.checks.feedback import NOT_ANSWERED, unanswered
    assert NOT_ANSWERED in str(unanswered("q"))
    previous = set_language("es")
    try:
        assert "todavía sin responder" in str(unanswered("q")) and NOT_ANSWERED not in str(unanswered("q"))
    finally:
        set_language(previous)


# --- answers in Spanish where a word is asked --------------------------------------------------------------
@pytest.mark.parametrize("answer", ["azul", "Azul", "AZUL ", "el azul", "blue"])
def test_colour_in_spanish_or_english(answer):
    from dhlab.course.exercises import exercise
    assert exercise("1.3").check(answer).ok


def test_a_wrong_spanish_colour_is_explained(spanish):
    from dhlab.course.exercises import exercise
    fb = exercise("1.3").check("rojo")
    assert not fb.ok and "eje x" in str(fb)


@pytest.mark.parametrize("answer, right", [
    ("Sí", "yes"), ("si", "yes"), ("el eje Z", "z axis"), ("Eje z", "z axis"), ("paralelas", "parallel"),
    ("Paralelos", "parallel"), ("se cruzan", "skew"), ("Se cortan", "intersect"), ("verde", "green"),
    ("¿Azul?", "blue"), ("la rama B", "branch B"), ("falso", "false"), ("ambas", "both")])
def test_a_word_may_be_answered_in_spanish(answer, right):
    from dhlab.course.exercises import check_choice
    assert check_choice(answer, right).ok


@pytest.mark.parametrize("answer, right", [("no", "yes"), ("rojo", "blue"), ("se cortan", "skew"),
                                           ("paralelas", "intersect"), ("eje y", "z axis")])
def test_a_wrong_spanish_word_is_still_wrong(answer, right):
    from dhlab.course.exercises import check_choice
    assert not check_choice(answer, right).ok


def test_a_glossary_still_asks_for_the_english_word():
    """check_terms translates Spanish terms: the Spanish word itself is not the answer."""
    from dhlab.course.exercises import exercise
    fb = exercise("1.2").check({"eslabón": "eslabón", "articulación": "joint", "efector final": "end effector",
                                "dextrógiro": "right-handed", "grados de libertad": "dof"})
    assert not fb.ok and "eslabón" in str(fb)


@pytest.mark.parametrize("said, ok", [("se cruzan", True), ("Se cruzan.", True), ("alabeadas", True),
                                      ("caso 3", True), ("paralelas", False), ("no se cortan", False)])
def test_the_case_of_x1_in_spanish(said, ok):
    """x1 of the exercise arm: z0 and z1 are skew (exercise 5.1)."""
    from dhlab.course.exercises import exercise
    fb = exercise("5.1").check({1: said, 2: "parallel", 3: "intersect"})
    assert fb.ok is ok


def test_the_case_feedback_in_spanish(spanish):
    from dhlab.course.exercises import exercise
    text = str(exercise("5.1").check({1: "paralelos", 2: "paralelos", 3: "se cortan"}))
    assert "Ejercicio 5.1: los casos de x1 … x3 todavía no están bien." in text
    assert "dijo que z0 y z1 son paralelos" in text


def test_a_table_feedback_in_spanish(spanish):
    from dhlab.course.exercises import check_table
    text = str(check_table([("q1", 0.5, 0.2, -90), ("q2 - 90", 0, 0.5, -90), ("q3", 0, 0, -90), ("q4", 0.5, 0, 0)]))
    assert text.startswith("✗ su tabla todavía no está bien: corrija esto primero")
    assert "articulación 3: su α2 es -90°" in text and "son paralelos" in text


def test_a_panel_readout_in_spanish(spanish):
    import numpy as np

    from dhlab.views.panels.stepthrough import motion_text
    from dhlab.views.panels.teach import pose_text
    assert motion_text(1.5, 0.0, 2.0, 0.0, 0.0, "m") == \
        "<b>Paso 2 de 4: Tz(d)</b>, d = 2 m: trasladar d a lo largo de z<sub>i−1</sub>. Hecho: 50 %."
    assert pose_text(np.eye(4), "m").startswith("<b>Efector final</b> (<i>end effector</i>)<br>posición [m]")


# --- the predictions of notebooks 5 and 6, the lesson helpers and the maths' boundary ----------------------
def test_a_prediction_in_spanish(spanish):
    from dhlab.course.predict import case_prediction
    p = case_prediction(((0, 0, 0), (0, 0, 1)), ((1, 0, 0), (0, 0, 1)), 1)      # two parallel lines, 1 apart
    prompt = str(p.check(...))
    assert "primero prediga: el caso de x1" in prompt and "respuesta resuelta" in prompt
    wrong = str(p.check("se cortan"))
    assert wrong.startswith("✗ su caso de x1 todavía no está bien.") and "normal común" not in wrong
    right = str(p.check("paralelos"))
    assert "z0 y z1 son paralelos: caso 2, x1 sobre cualquier normal común (de longitud 1)." in right


def test_a_row_prediction_names_the_row_in_spanish(spanish):
    import dhlab
    from dhlab.course.predict import row_prediction
    robot = dhlab.DHRobot.from_table([("q1", 0, 1, 0), ("q2", 0, 0.5, 0)], name="2R")
    text = str(row_prediction(robot, 2).check(("q1", 0, 0.5, 0)))
    assert text.startswith("✗ su fila 2") and "la articulación 2 es rotacional: su variable q2 va en θ" in text


def test_a_chain_and_a_dh_boundary_error_in_spanish(spanish):
    import dhlab
    with pytest.raises(DHLabError, match="un robot necesita al menos un eslabón"):
        dhlab.Robot([])
    with pytest.raises(DHLabError, match="la fila 2 debe tener 4 entradas"):
        dhlab.DHRobot.from_table([("q1", 0, 1, 0), ("q2", 0, 1)])
    with pytest.raises(DHLabError, match="es más de una vuelta completa") as info:
        dhlab.DHRobot.from_table([("q1", 0, 1, 720)])
    assert "fila 1, α" in str(info.value)


def test_the_maths_errors_stay_english_by_default():
    import dhlab
    with pytest.raises(DHLabError, match="a robot needs at least one link."):
        dhlab.Robot([])


def test_the_ik_and_the_table_in_spanish(spanish):
    import dhlab
    robot = dhlab.robots.pr_mechanism()
    assert dhlab.ik.pr_mechanism_ik(robot, 0.0, 0.0).message.startswith("dos soluciones: rama A")
    assert dhlab.ik.pr_mechanism_ik(robot, 0.0, 99.0).message.startswith("sin solución")
    assert repr(dhlab.robots.puma560().table()).startswith("tabla DH de 'PUMA 560'")
    assert "articulación" in str(dhlab.robots.puma560().table()).splitlines()[0]


def test_a_lesson_helper_in_spanish(spanish):
    from dhlab.course.lessons.lesson_dh_convention import place_x, three_cases
    z_prev, cases = three_cases()
    assert str(place_x(z_prev, cases["case 3"])).startswith("se cruzan  normal común de (0, 0, 0.5) a")
    with pytest.raises(DHLabError, match="son la misma recta"):
        place_x(z_prev, z_prev)


@pytest.mark.parametrize("name", ["two steps", "three cases", "DH parameters", "exercise 5.1", "common normals",
                                  "exercise 5.2", "SSRMS links", "Rot_x(-90)", "seed 001's arm"])
def test_every_spanish_figure_text_is_inside_the_figure(name, spanish):
    """The Spanish words are longer: the figures of the course still hold every one of them."""
    figures = course_figures_tests()
    assert name in figures.FIGURES, f"{name} is no longer a figure of tests/course/test_course_figures.py"
    figures.test_every_text_is_inside_the_figure_and_readable(name)


def course_figures_tests():
    """tests/course/test_course_figures.py, loaded from its file (the folders of tests/ are not packages):
    its figures and its check that every text lies inside its figure, run here in Spanish."""
    import importlib.util

    path = Path(__file__).resolve().parents[1] / "course" / "test_course_figures.py"
    spec = importlib.util.spec_from_file_location("course_figures_tests", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_a_figure_title_in_spanish(spanish):
    from dhlab.course.lessons import figures_dh
    fig = figures_dh.dh_parameters_figure()
    assert fig.axes[0].get_title() == "los cuatro parámetros DH del eslabón $i$"


# --- one register: usted, as the seeds address the student ------------------------------------------------------
# forms that only *tú* uses: pronouns, 2nd-person verbs, and imperatives that open a sentence
# ("Revisa …"; in the middle of one, "revisa" may be "he/it checks", which usted also says)
TU_WORDS = ["tú", "tu", "tus", "ti", "contigo", "tuyo", "tuya", "te", "puedes", "tienes", "debes", "quieres", "estás",
            "necesitas", "obtienes", "sabes", "verás", "podrás", "tendrás", "diste", "escribiste", "usaste",
            "respondiste", "obtuviste", "hiciste", "pusiste", "elegiste", "dijiste", "omitiste", "elige", "escoge",
            "pon", "haz", "fíjate", "asegúrate", "pregúntate", "sustituye", "conviertas", "sustituyas", "olvides",
            "escríbela", "conviértelo", "llénalo", "ejecútala", "dala", "dalo", "gíralo", "ponlo", "multiplícalas"]
TU_OPENING = ["Revisa", "Calcula", "Escribe", "Observa", "Mira", "Mueve", "Usa", "Compara", "Prueba a", "Sustituye",
              "Verifica", "Da", "Pasa", "Llama", "Lee", "Dibuja", "Elige", "Vuelve", "Responde", "Recuerda", "Sigue"]
_TU = re.compile(r"(?<![\w{])(" + "|".join(TU_WORDS) + r")(?![\w}])", re.IGNORECASE)
_TU_OPENING = re.compile(r"(?:^|[.:;!?¿(]\s+|<b>)(" + "|".join(TU_OPENING) + r")\b")


def tu_forms(text: str) -> list:
    """The *tú* forms in a Spanish message (code spans and placeholders left out)."""
    text = re.sub(r"`[^`]*`|\{[^{}]*\}|'[^']*'", " ", text)
    return _TU.findall(text) + _TU_OPENING.findall(text)


def test_the_catalog_addresses_the_student_as_usted(catalog):
    found = {m.id: tu_forms(m.string) for m in catalog if m.id and m.string and tu_forms(m.string)}
    assert not found, f"{len(found)} messages say tú, not usted: {list(found.items())[:5]}"


@pytest.mark.parametrize("text", ["Revisa tu respuesta.", "¿Te atoraste? Llama .hint().", "no conviertas dos veces",
                                  "tienes {mine}, que no es correcto.", "Escríbela con símbolos. Sustituye ... por "
                                  "tu predicción"])
def test_the_register_check_finds_tu(text):
    assert tu_forms(text)


@pytest.mark.parametrize("text", ["Revise su respuesta.", "la prueba de la regla 7", "el eslabón gira 90°",
                                  "a x le toca l2·cos q2", "{tu} es un nombre de variable", "q1 se mide desde x0"])
def test_the_register_check_leaves_usted_alone(text):
    assert not tu_forms(text)


# --- the words the notebooks' code cells print (the Spanish edition shares that code) ---------------------
_WORD = re.compile(r"(?<![\w{])[a-z][a-z']+\b")          # a lowercase word of 2+ letters, outside {fields}
_MATHS = {"det", "cos", "sin", "tan", "fk", "eq", "rad", "deg", "dtheta", "theta", "dx", "dy", "px", "dpi", "mm"}


def _literal(node) -> str:
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return node.value
    if isinstance(node, ast.JoinedStr):
        return " ".join(v.value for v in node.values if isinstance(v, ast.Constant))
    return ""


def printed_english(source: str) -> list:
    """The string literals of ``print(...)`` calls in a code cell that hold at least two English words and are
    not marked ``_("…")`` (in the Spanish edition they would print English)."""
    found = []
    for call in ast.walk(ast.parse(i18n_catalog.cell_python(source))):
        if not (isinstance(call, ast.Call) and isinstance(call.func, ast.Name) and call.func.id == "print"):
            continue
        todo = list(call.args)
        while todo:
            node = todo.pop()
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "_":
                continue                                   # marked: translated where shown
            words = [w for w in _WORD.findall(_literal(node)) if w not in _MATHS]
            if len(words) >= 2:
                found.append(_literal(node))
            todo += [v.value for v in node.values if isinstance(v, ast.FormattedValue)] \
                if isinstance(node, ast.JoinedStr) else list(ast.iter_child_nodes(node))
    return found


def _lesson_code_cells():
    for path in i18n_catalog.notebook_paths():
        for cell in json.loads(path.read_text(encoding="utf-8"))["cells"]:
            if cell["cell_type"] == "code":
                yield path.name, cell.get("id"), "".join(cell["source"])


def test_the_lesson_notebooks_print_no_unmarked_english():
    found = {(name, cell_id): english for name, cell_id, source in _lesson_code_cells()
             if (english := printed_english(source))}
    assert not found, (f"{len(found)} code cells print English the Spanish edition cannot translate: write "
                       f"print(_(\"same table:\"), ok) or _(\"x{{i}}: case {{case}}\").format(...), then "
                       f"python -m tools.i18n_catalog extract/update and translate: {list(found.items())[:3]}")


@pytest.mark.parametrize("source, english", [
    ('print("same table as the seed\'s:", ok)', True),
    ('print(f"pen at {fmt(p)}, joint 2 at {fmt(j)}")', True),
    ('print("\\n".join(f"{name}: the same" for name in names))', True),
    ('print(_("same table as the seed\'s:"), ok)', False),
    ('print(_("pen at {pen}").format(pen=fmt(p)))', False),
    ('print("T =", T, "det R =", det)', False),
    ('%matplotlib inline\nprint(f"cos(θ) = {c:.3f}")', False)])
def test_the_printed_english_check(source, english):
    assert bool(printed_english(source)) is english


def test_a_notebook_message_is_in_the_catalog_with_its_cell(catalog):
    where = {m.id: m.locations for m in i18n_catalog.extract_messages()}
    assert ("notebooks/07_ssrms.ipynb#n07-18", 4) in where["same table as the seed's:"]
    spanish = {m.id: m.string for m in catalog}
    assert spanish["same table as the seed's:"] == "misma tabla que la de la semilla:"


def test_underscore_is_not_rebound_in_the_lesson_notebooks():
    """``_`` is the translation function there: ``x, _ = ...`` or ``for _ in ...`` would break every later cell."""
    rebound = [(name, cell_id) for name, cell_id, source in _lesson_code_cells()
               for node in ast.walk(ast.parse(i18n_catalog.cell_python(source)))
               if isinstance(node, ast.Name) and node.id == "_" and isinstance(node.ctx, ast.Store)]
    assert not rebound, f"cells that rebind _ (name the value instead): {rebound}"


def test_speaking_sets_the_language_of_this_thread_only():
    """One ``_`` for the course and the grader: ``speaking(lang)`` holds for its thread, the course's
    language (set_language) everywhere else."""
    import threading

    from dhlab.i18n import current_language, speaking

    seen = {}

    def other_thread():
        seen["other"] = (current_language(), _("not answered"))

    with speaking("es"):
        assert (current_language(), _("not answered")) == ("es", "sin responder")
        worker = threading.Thread(target=other_thread)
        worker.start()
        worker.join()
    assert seen["other"] == ("en", "not answered")
    assert current_language() == get_language() == "en"
    with pytest.raises(DHLabError, match="not one of the course's languages"):
        with speaking("fr"):
            pass


def test_the_grader_language_helpers_live_in_i18n():
    from dhlab.i18n import case_word, checked_language, ngettext, speaking, split_language

    assert checked_language("Spanish") == "es" and split_language(["x", "--language=es"]) == ("es", ["x"])
    with speaking("es"):
        assert case_word("parallel") != "parallel"
    assert ngettext("{n} joint", "{n} joints", 2) == "{n} joints"
