"""The Spanish edition speaks to the student as *usted*, the seeds' register ("observe", "recuerde",
"considere"): no catalog of tools/locale/es/notebooks/ may use an unambiguous *tú* form.

Unambiguous means a form that only *tú* has: the pronouns and possessives (tú, tu, tus, ti, te,
contigo), second-person verbs (puedes, tienes, debes, podrás …), imperatives with a pronoun attached
(fíjate, pruébalo …) and, at the start of a sentence, the plain imperatives a lesson uses (Mueve,
Calcula, Escribe, Prueba, Mira …), which inside a sentence are also the third person ("el panel mueve").
Maths, code, HTML tags and link targets are left out of the search: they are not prose.
"""
import re
from pathlib import Path

import pytest

from tools.edition_catalog import read_catalog

CATALOGS = sorted((Path(__file__).resolve().parents[2] / "tools/locale/es/notebooks").glob("*.po"))

# Forms only tú has, anywhere in a sentence.
TU_WORDS = (
    "tú tu tus ti te contigo "
    "puedes tienes debes quieres sabes necesitas obtienes haces eres estás ves "
    "podrás verás tendrás sabrás obtendrás necesitarás encontrarás aprenderás deberás "
    "puedas tengas quieras olvides muevas escribas "
    "haz pon fíjate pruébalo pruébala muévelo muévela escríbelo escríbela ejecútalo ejecútala "
    "compruébalo compruébala ábrelo ábrela léelo léela llámalo llámala dale recuérdalo"
).split()
# Imperatives that are also the third person: tú only when they open a sentence.
TU_IMPERATIVES = (
    "Mueve Calcula Escribe Prueba Mira Observa Ejecuta Arrastra Compara Recuerda Considera Comprueba "
    "Responde Encuentra Usa Lee Elige Completa Predice Piensa Abre Pulsa Presiona Oprime Sustituye "
    "Reemplaza Corrige Dibuja Empieza Cambia Busca Revisa Anota Imagina Intenta"
).split()

_WORD = r"(?<!\w)({})(?!\w)"               # \w covers á, é, ñ … in str patterns
_ANYWHERE = re.compile(_WORD.format("|".join(TU_WORDS)), re.IGNORECASE)
_SENTENCE_START = r"(?:^|(?<=[.:;!?¿¡(])\s*|(?<=\*\*)|(?<=^[*-] )|(?<=^\d\. )|(?<=^> ))"
_OPENING = re.compile(_SENTENCE_START + _WORD.format("|".join(TU_IMPERATIVES)), re.MULTILINE)

_NOT_PROSE = [
    re.compile(r"```.*?```", re.DOTALL),          # code blocks
    re.compile(r"\$\$.*?\$\$", re.DOTALL),        # display maths
    re.compile(r"\$[^$\n]*\$"),                   # inline maths
    re.compile(r"`[^`\n]*`"),                     # code spans
    re.compile(r"<[^>\n]*>"),                     # HTML tags and <link targets>
    re.compile(r"\]\([^)\n]*\)"),                 # link targets
]


def prose(markdown: str) -> str:
    """The words of a markdown cell a student reads as Spanish prose: maths, code and targets blanked."""
    for pattern in _NOT_PROSE:
        markdown = pattern.sub(" ", markdown)
    return markdown


def tu_forms(markdown: str) -> list[str]:
    """The *tú* forms of a Spanish markdown cell, each with a little of its context."""
    text = prose(markdown)
    found = []
    for pattern in (_ANYWHERE, _OPENING):
        for match in pattern.finditer(text):
            start, end = match.span(1)
            found.append(f"{match.group(1)!r} in …{text[max(0, start - 30):end + 30]!r}…")
    return found


def test_the_detector_finds_tu_and_spares_usted():
    assert tu_forms("Mueve el deslizador y observa cómo cambia tu matriz.")
    assert tu_forms("Si puedes, escribe la fila.")
    assert tu_forms("**Prueba** $\\alpha = 0$; luego fíjate en $z$.")
    assert tu_forms("1. Calcula ${}^0T_1$.\n2. Compárala.")
    assert tu_forms("Revisa tus respuestas.")
    assert tu_forms("Al terminar este cuaderno podrás colocar los sistemas.")
    assert not tu_forms("Mueva el deslizador y observe cómo cambia su matriz.")
    assert not tu_forms("Si puede, escriba la fila. Pruebe $\\alpha = 0$; luego fíjese en $z$.")
    assert not tu_forms("El panel mueve el brazo; la celda calcula ${}^0T_1$ y escribe la tabla.")
    assert not tu_forms("Use `tu = te(ti)` y la figura ![figura](tus.png).")   # code, targets: not prose


@pytest.mark.parametrize("path", CATALOGS, ids=lambda p: p.stem)
def test_catalog_speaks_as_usted(path):
    problems = [f"{message.context}: {form}"
                for message in read_catalog(path) if message.id and message.string
                for form in tu_forms(message.string)]
    assert not problems, (f"{path.name} uses tú; the edition's register is usted "
                          "(mueva, calcule, su, puede …):\n" + "\n".join(problems))
