"""The assignment in Spanish on the grading side: a class that mixes languages, released and graded in one run.

``dhlab-assign release`` writes each student's notebook in the roster's language (column ``idioma`` or
``language``, else ``--language``, else ``DHLAB_LANGUAGE``); ``dhlab-grade`` grades the mixed batch in one
run and writes each feedback file in its student's language, the gradebook's statuses in the teacher's.
The fast tests check the pieces in this process; one batch (six students, three of each language: right,
wrong and blank answers) checks the whole chain.
"""
import copy
import csv
import json
import re
import threading

import pytest

from dhlab.assignment import variants as V
from dhlab.assignment.answers import parse_answers
from dhlab.assignment.checks import check_all
from dhlab.errors import DHLabError
from dhlab.grading.book.gradebook import status_text
from dhlab.grading.book.progress import summary as _summary
from dhlab.grading.release import notebooks as R
from dhlab.grading.release.comments import comments, with_comments
from dhlab.grading.release.language import notebook_language, own_robot_text_es, raw_notebook_language
from dhlab.i18n import _, speaking
from support.solved_notebooks import released_robot, solved, write

SECRET = b"grading-spanish-test-secret-0123456789"
SPANISH_WORDS = ("Parte 1 (el bosquejo)", "puntos", "Estado:", "Entrega:")
ENGLISH_WORDS = ("Part 1 (the sketch)", "/10 points", "Status:", "Submission:", "not answered", "you wrote")


def _release(tmp, roster_text, *extra, family="puma560"):
    tmp.mkdir(parents=True, exist_ok=True)
    roster = tmp / "roster.csv"
    roster.write_text(roster_text, encoding="utf-8")
    secret = tmp / "secret.key"
    secret.write_bytes(SECRET + b"\n")
    out = tmp / "release"
    code = R.main(["release", str(roster), "-o", str(out), "--secret-file", str(secret), "--family", family, *extra])
    return code, out, secret


def _nb(out, sid):
    return json.loads((out / f"{sid}.ipynb").read_text(encoding="utf-8"))


def _markdown(nb):
    return "\n".join("".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "markdown")


def _code(nb):
    return ["".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "code"]


def _no_comments(source):
    return with_comments(source, {text: "" for text in comments(source)})


# --- the release ----------------------------------------------------------------------------------------

def test_the_roster_column_overrides_the_option_and_each_notebook_says_its_language(tmp_path):
    code, out, _ = _release(tmp_path, "id,idioma\nana,es\nbruno,\ncarla,en\ndora,Español\n", "--language", "es")
    assert code == 0
    languages = {sid: notebook_language(_nb(out, sid)) for sid in ("ana", "bruno", "carla", "dora")}
    assert languages == {"ana": "es", "bruno": "es", "carla": "en", "dora": "es"}
    for sid, language in languages.items():
        nb = _nb(out, sid)
        assert nb["metadata"]["dhlab"]["language"] == language
        assert f'dhlab.set_language("{language}")' in _code(nb)[0]
        text = _markdown(nb)
        if language == "es":
            assert "## Su robot" in text and "Parte 1 · El bosquejo" in text and "## Your robot" not in text
            assert "The robot" not in text and "Part 1 ·" not in text
        else:
            assert "## Your robot" in text and "Parte 1" not in text
    manifest = (out / "_teacher" / "manifest.csv").read_text(encoding="utf-8-sig").splitlines()
    assert manifest[0].endswith(",language") and manifest[1].endswith(",es") and manifest[3].endswith(",en")
    teacher = json.loads((out / "_teacher" / "variants.json").read_text(encoding="utf-8"))
    assert "language" not in teacher["ana"]                      # the teacher's signed record is unchanged


def test_the_same_student_gets_the_same_robot_and_code_in_either_language(tmp_path):
    _, english, _ = _release(tmp_path / "en", "id\nana\nbruno\n", "--language", "en", family="all")
    _, spanish, _ = _release(tmp_path / "es", "id\nana\nbruno\n", "--language", "es", family="all")
    for sid in ("ana", "bruno"):
        en, es = _nb(english, sid), _nb(spanish, sid)
        assert en["metadata"]["dhlab"]["variant"] == es["metadata"]["dhlab"]["variant"]
        assert [c.get("id") for c in en["cells"]] == [c.get("id") for c in es["cells"]]
        # the same code once the comments are cut (they are translated), the set-up cell's language aside
        assert [_no_comments(c) for c in _code(es)] == [
            _no_comments(c.replace('dhlab.set_language("en")', 'dhlab.set_language("es")')) for c in _code(en)]
        assert _code(es) != _code(en) and "# ESCRIBA SU CÓDIGO AQUÍ" in "\n".join(_code(es))
        assert _markdown(en) != _markdown(es)


def test_what_the_variant_changes_in_the_english_text_it_changes_in_the_spanish(tmp_path):
    """A four-joint robot (the SCARA): its joints, words, transformations and name, in both texts."""
    _, out, _ = _release(tmp_path, "id,language\nana,es\nbruno,en\n", family="cobra600")
    es, en = _markdown(_nb(out, "ana")), _markdown(_nb(out, "bruno"))
    robot = released_robot(_nb(out, "ana"))
    assert robot.n == 4
    intro = es.split("## Su robot")[1].split("## Parte 1")[0]          # the course's catalog writes it
    assert "**Your robot has 4 joints**" in en and "Your robot" not in es and "4" in intro
    assert "three words" in en and "tres palabras" in es and "cinco palabras" not in es
    assert "chain = T1 @ T2 @ T3 @ T4`" in en and "chain = T1 @ T2 @ T3 @ T4`" in es
    assert "PUMA 560" not in intro and "seis" not in intro
    assert re.search(r"# 8 · La tarea DH: su propio Adept Cobra 600", es)
    assert "Su Adept Cobra 600" in es and "4 articulaciones (3 rotacionales, 1 prismáticas)" in es


def test_own_robot_text_es_changes_only_what_it_finds():
    robot = V.robot_of_variant(V.variant("kr5", "x"))
    assert own_robot_text_es("Una frase sin robot.", robot, "KUKA KR5") == "Una frase sin robot."
    assert own_robot_text_es("sobre el PUMA (gris)", robot, "KUKA KR5") == "sobre su robot (gris)"


@pytest.mark.parametrize("argv, words", [
    (["--language", "xx"], ["--language", "'xx'", "en (English)", "es (Español)"]),
    ([], ["roster roster.csv, row 2", "'klingon'"]),
])
def test_a_bad_language_is_a_clear_error(tmp_path, capsys, argv, words):
    code, out, _ = _release(tmp_path, "id,language\nana,klingon\n", *argv)
    assert code == 2 and not (out / "ana.ipynb").exists()
    err = capsys.readouterr().err
    assert err.startswith("dhlab-assign: error:") and all(w in err for w in words), err
    assert "Traceback" not in err


def test_dhlab_language_is_the_default_and_must_be_a_language(tmp_path, monkeypatch, capsys):
    monkeypatch.setenv("DHLAB_LANGUAGE", "es")
    code, out, _ = _release(tmp_path, "id\nana\n")
    assert code == 0 and notebook_language(_nb(out, "ana")) == "es"
    assert "cuadernos en" in capsys.readouterr().out           # the command speaks the teacher's language too
    monkeypatch.setenv("DHLAB_LANGUAGE", "fr")
    code, _, _ = _release(tmp_path / "again", "id\nana\n")
    assert code == 2 and "DHLAB_LANGUAGE" in capsys.readouterr().err


def test_the_language_of_a_submission():
    nb = {"metadata": {"dhlab": {"language": "es"}}, "cells": []}
    assert notebook_language(nb) == "es"
    nb = {"metadata": {}, "cells": [{"cell_type": "code", "source": 'import dhlab\ndhlab.set_language( "es" )'}]}
    assert notebook_language(nb) == "es"                       # no record: its set_language call
    assert notebook_language({"metadata": {}, "cells": []}) is None
    assert notebook_language({"metadata": {"dhlab": {"language": "fr"}}, "cells": "nonsense"}) is None
    assert notebook_language([1, 2]) is None
    hostile = {"metadata": {"dhlab": "x"}, "cells": [5, {"cell_type": "code", "source": 7},
                                                     {"cell_type": "code", "source": [1, None]},
                                                     {"cell_type": "code", "source": ['dhlab.set_language("es")']}]}
    assert notebook_language(hostile) == "es"
    assert raw_notebook_language(b"\xff\xfe not json") is None and raw_notebook_language(b"[" * 100000) is None


# --- the grader's messages, in the grader's process -------------------------------------------------------

def _answers():
    return parse_answers({"n_links": 6, "n_joints": 6, "joint_types": "RRRRRR",
                          "x_cases": ["intersect", "parallel", "skew", "intersect", "intersect"]})


def test_the_feedback_in_spanish_scores_as_in_english():
    english = check_all(_answers())
    with speaking("es"):
        spanish = check_all(_answers())
        text = spanish.text()
    assert spanish.score == english.score and [p.score for p in spanish.parts] == [p.score for p in english.parts]
    assert "Parte 1 (el bosquejo)" in text and "usted escribió 6" in text and "sin responder" in text
    assert not any(w in text for w in ("Part 1", "you wrote", "not answered", "points"))
    assert "Part 1 (the sketch)" in english.text()


def test_spanish_words_are_accepted_where_words_are_asked():
    words = {"n_links": 7, "n_joints": 6, "joint_types": ["rotacional"] * 6,
             "x_cases": ["se intersecan", "paralelos", "se cruzan", "se cortan", "caso 1"]}
    with speaking("es"):
        report = check_all(parse_answers(words))
        text = report.text()
    assert report.parts[0].full_marks, text
    with speaking("es"):
        not_a_case = ["oblicuos", "paralelos", "se cruzan", "se cortan", "caso 1"]
        bad = check_all(parse_answers({**words, "x_cases": not_a_case}))
    assert "no es un caso" in bad.parts[0].text() and "se intersecan" in bad.parts[0].text()


def test_each_thread_speaks_its_own_language():
    seen = {}

    def write(language):
        with speaking(language):
            for _k in range(200):
                seen.setdefault(language, set()).add(_("not answered"))

    threads = [threading.Thread(target=write, args=(lang,)) for lang in ("en", "es", "en", "es")]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert seen == {"en": {"not answered"}, "es": {"sin responder"}}
    assert _("not answered") == "not answered"                 # outside: the course's language


def test_statuses_and_summary_in_the_teachers_language():
    run = {"errors": [[4, "NameError", "name 'T9' is not defined"]], "timeouts": [6]}
    with speaking("es"):
        status = status_text(run, report_answered=False)
        blank = status_text({}, report_answered=False)
        rows = [{"submission": "a", "score": "3", "max_score": 10, "status": status},
                {"submission": "b", "score": "0", "max_score": 10, "status": blank},
                {"submission": "c", "score": "10", "max_score": 10, "status": "ok"}]
        summary = _summary(rows, 12.0, 2)
    assert status.startswith("error en celda 4 (NameError") and "tiempo agotado" in status and "sin responder" in status
    assert blank == "sin responder"
    assert "Se calificaron 3 entregas" in summary and "errores 1" in summary and "sin responder 1" in summary
    assert "ok 1" in summary and "tiempo agotado 1" in summary


def test_gradescope_results_in_the_students_language():
    from dhlab.grading.export.gradescope import results
    with speaking("es"):
        report = check_all(_answers())
        feedback = "\n".join([_("Submission: {submission}").format(submission="ana"),
                              _("File: {file}").format(file="ana.ipynb"), "", report.text()])
        parts = {p.key: p.text() for p in report.parts}
    row = {"score": f"{report.score:g}", "status": "sin responder", "_feedback_text": feedback, "_part_text": parts,
           "_language": "es", "part1_sketch": "1", "part2_links": "0", "part3_transforms": "0"}
    out = results(row)
    assert [t["name"] for t in out["tests"]] == ["Parte 1: el bosquejo", "Parte 2: cada eslabón en su propio sistema",
                                                 "Parte 3: las transformaciones y su cadena"]
    assert "Entrega:" not in out["output"] and "Tarea del" not in out["output"]


# --- one class, both languages, one run ---------------------------------------------------------------------

def _wrong(nb):
    """One slip: one link too few (part 1), the rest right."""
    nb = copy.deepcopy(nb)
    for cell in nb["cells"]:
        if cell.get("metadata", {}).get("nbgrader", {}).get("grade_id") == "part1_answers":
            cell["source"] = re.sub(r"n_links = (\d+)", lambda m: f"n_links = {int(m[1]) - 1}", "".join(cell["source"]))
    return nb


def _spanish_words(nb):
    """The part-1 answer written with Spanish words (tipos y casos)."""
    nb = copy.deepcopy(nb)
    words = {"intersect": "se intersecan", "parallel": "paralelos", "skew": "se cruzan"}
    for cell in nb["cells"]:
        if cell.get("metadata", {}).get("nbgrader", {}).get("grade_id") == "part1_answers":
            text = "".join(cell["source"])
            for en, es in words.items():
                text = text.replace(f"'{en}'", f"'{es}'").replace(f'"{en}"', f'"{es}"')
            cell["source"] = re.sub(r"joint_types = [\'\"]R{6}[\'\"]", "joint_types = ['rotacional'] * 6", text)
    return nb


@pytest.fixture(scope="module")
def graded(tmp_path_factory, package):
    from support.grader import run_grader
    tmp = tmp_path_factory.mktemp("mixed")
    roster = "id,idioma\n" + "".join(f"{sid},{lang}\n" for sid, lang in (
        ("en_right", "en"), ("en_wrong", "en"), ("en_blank", "en"),
        ("es_right", "es"), ("es_wrong", "es"), ("es_blank", "es"), ("es_words", "es")))
    code, out, secret = _release(tmp, roster)
    assert code == 0
    folder = tmp / "submissions"
    for sid in ("en_right", "en_wrong", "en_blank", "es_right", "es_wrong", "es_blank", "es_words"):
        nb = _nb(out, sid)
        robot = released_robot(nb)
        handed = {"right": solved(nb, robot), "wrong": _wrong(solved(nb, robot)), "blank": nb,
                  "words": _spanish_words(solved(nb, robot))}[sid.split("_")[1]]
        write(folder / f"{sid}.ipynb", handed)
    gradebook = tmp / "gradebook.csv"
    proc = run_grader(["puma", str(folder), "-o", str(gradebook), "-j", "2", "--secret-file", str(secret),
                   "--release", str(out), "--language", "es"], package, timeout=1800)
    assert proc.returncode == 0, proc.stderr
    with open(gradebook, newline="", encoding="utf-8") as f:
        rows = {row["submission"]: row for row in csv.DictReader(f)}
    feedback = {sid: (tmp / "gradebook_feedback" / row["feedback"]).read_text(encoding="utf-8")
                for sid, row in rows.items()}
    return rows, feedback, proc


def test_a_mixed_class_is_graded_in_one_run_each_in_its_language(graded):
    rows, feedback, proc = graded
    assert len(rows) == 7
    for sid, text in feedback.items():
        spanish = sid.startswith("es_")
        assert all((w in text) == spanish for w in SPANISH_WORDS), (sid, text)
        assert all((w in text) != spanish for w in ENGLISH_WORDS if w not in ("not answered", "you wrote")), (sid, text)
        # the robot graded against, by its name: 'PUMA 560 · variante 3fa2c1' in Spanish
        assert (" · variante " if spanish else " · variant ") in text and (" · variant " in text) != spanish, sid
    assert "Se calificaron 7 entregas" in proc.stderr and "Libro de calificaciones:" in proc.stderr


def test_the_scores_do_not_depend_on_the_language(graded):
    rows, feedback, _ = graded
    for kind in ("right", "wrong", "blank"):
        en, es = rows[f"en_{kind}"], rows[f"es_{kind}"]
        assert [en[c] for c in ("score", "part1_sketch", "part2_links", "part3_transforms")] == \
               [es[c] for c in ("score", "part1_sketch", "part2_links", "part3_transforms")], kind
    assert rows["en_right"]["score"] == "10" and float(rows["en_wrong"]["score"]) < 10
    assert rows["en_blank"]["score"] == "0"
    assert rows["es_words"]["score"] == "10", feedback["es_words"]       # Spanish words where words are asked
    # ... and quoted back as the student wrote them, never as the English canonical word
    assert "x1: se intersecan" in feedback["es_words"] and "x2: paralelos" in feedback["es_words"]
    assert not any(f"x{i}: {w}" in feedback["es_words"] for i in range(1, 6)
                   for w in ("intersect", "parallel", "skew", "se cortan")), feedback["es_words"]
    assert "usted escribió" in feedback["es_wrong"] and "you wrote" in feedback["en_wrong"]


def test_the_statuses_are_in_the_teachers_language(graded):
    rows, feedback, _ = graded
    assert rows["en_blank"]["status"] == rows["es_blank"]["status"] and "sin responder" in rows["es_blank"]["status"]
    assert rows["en_right"]["status"] == rows["es_right"]["status"] == "ok"
    assert "Status: not answered" in feedback["en_blank"] and "Estado: sin responder" in feedback["es_blank"]


# --- the command lines and the DH placement report ------------------------------------------------------

def test_dhlab_grade_refuses_a_language_it_does_not_speak(tmp_path, capsys):
    from dhlab.grading import cli
    assert cli.main(["puma", str(tmp_path), "--language", "xx"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("dhlab-grade: error: --language = 'xx'") and "es (Español)" in err


def test_the_help_of_both_commands_speaks_the_teachers_language(capsys):
    from dhlab.grading import cli
    with pytest.raises(SystemExit) as exit_:
        cli.main(["puma", "--help", "--language", "es"])
    assert exit_.value.code == 0
    out = capsys.readouterr().out
    assert "carpeta de cuadernos entregados" in out and "el idioma del profesor" in out
    # argparse's own words too, and the description
    assert out.startswith("uso: dhlab-grade") and "argumentos posicionales:" in out and "opciones:" in out
    assert "muestra esta ayuda" in out and "Califica una carpeta" in out
    assert not any(w in out for w in ("usage:", "positional arguments", "options:", "show this help", "Grade a"))
    with pytest.raises(SystemExit) as exit_:
        cli.main(["puma", "--language", "es"])
    assert exit_.value.code == 2
    assert "dhlab-grade: error: se requieren los siguientes argumentos: submissions" in capsys.readouterr().err
    with pytest.raises(SystemExit):
        R.main(["release", "--help", "--language", "es"])
    assert "el idioma de los cuadernos" in capsys.readouterr().out
    with pytest.raises(SystemExit):
        cli.main(["puma", "--help"])
    assert "folder of submitted notebooks" in capsys.readouterr().out


def test_the_dh_placement_report_in_spanish():
    import dhlab
    from dhlab.dh_frames import dh_assignment, joint_axes
    axes, tool = joint_axes(dhlab.robots.ssrms())
    previous = dhlab.set_language("es")
    try:
        text = str(dh_assignment(axes, tool))
        with pytest.raises(DHLabError, match="falta tool"):
            dh_assignment(axes, None)
    finally:
        dhlab.set_language(previous)
    assert "sistema 1: caso 1 — z0 y z1 se intersecan" in text and "regla 9" in text and "fila 1:" in text
    assert "frame 1" not in text and "rule" not in text
    assert "frame 1: case 1" in str(dh_assignment(axes, tool))


def test_dhlab_grade_export_speaks_the_teachers_language_too(tmp_path, capsys):
    from dhlab.grading import cli
    from dhlab.i18n import split_language
    assert split_language(["canvas", "--language", "es", "g.csv"]) == ("es", ["canvas", "g.csv"])
    assert split_language(["--language=en", "moodle"]) == ("en", ["moodle"])
    with pytest.raises(SystemExit):
        cli.main(["export", "canvas", "--help", "--language", "es"])
    assert "la lista del grupo (CSV con encabezado)" in capsys.readouterr().out
    empty = tmp_path / "gradebook.csv"
    empty.write_text("submission,score\n", encoding="utf-8")
    roster = tmp_path / "roster.csv"
    roster.write_text("id\nana\n", encoding="utf-8")
    code = cli.main(["export", "moodle", str(empty), "--roster", str(roster), "-o", str(tmp_path / "m.csv"),
                     "--language", "es"])
    assert code == 2 and "no es un libro de calificaciones escrito por dhlab-grade" in capsys.readouterr().err
    assert cli.main(["export", "moodle", str(empty), "--language", "xx"]) == 2
    assert "'xx'" in capsys.readouterr().err


def test_the_grader_knows_the_spanish_release_cells(tmp_path):
    """A Spanish notebook's locked cells (their comments are Spanish), its "Your robot" cell and its answer
    cells are known to the grader as the English ones are: an error there is named the same way."""
    from dhlab.grading.book.gradebook import Cells
    _, out, _ = _release(tmp_path, "id\nana\n", "--language", "es", family="cobra600")
    code = [(k, "".join(c["source"])) for k, c in enumerate(_nb(out, "ana")["cells"]) if c["cell_type"] == "code"]
    cells = Cells(code)
    by_first = {source.split("\n", 1)[0]: number for number, source in code}
    seam = next(n for first, n in by_first.items() if first.startswith("# Su robot: sorteado para usted"))
    assert cells.of_assignment(seam)
    check = next(n for first, n in by_first.items() if first.startswith("# Comprobación de la parte 1"))
    assert cells.of_assignment(check)
    answer = next(n for first, n in by_first.items() if first.startswith("# Parte 2: escriba link_points"))
    assert cells.answer_parts(answer) == ["part2"] and not cells.of_assignment(answer)
