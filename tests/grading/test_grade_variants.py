"""dhlab-grade with personal variants, end to end: release a class, hand in, grade.

``dhlab-assign release`` writes a notebook per student of a small roster; each is solved
the way a student would (the answer cells filled in with a valid DH assignment of that
student's robot); then one student hands in honestly, one hands in a classmate's notebook,
one changes the variant in the notebook's metadata (to the published PUMA, whose table
is in every book), and one strips the record. ``dhlab-grade --secret-file --release``
must give the honest ones full marks, say what happened to the others, and grade those
against the roster's variant (``--fallback roster``) or not at all (``--fallback none``).

The solved notebooks are the package's own answers (``dhlab.assignment.solution``) in the released
notebooks' answer cells (tests/support/solved_notebooks.py), with the reference frames or others.
"""
import copy
import csv
import json
import sys
from pathlib import Path

import numpy as np
import pytest

from dhlab.assignment import variants as V
from dhlab.assignment.notebook_cells import SEAM_CELL_ID, seam_source
from dhlab.grading.book import grade_variants as GV
from dhlab.grading.release import notebooks as R
from dhlab.grading.run.staging import stage
from support.solved_notebooks import released_robot, solved, write

ROOT = Path(__file__).resolve().parents[2]
SECRET = b"grade-variants-test-secret-0123456789"


# --- the class ------------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def released(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("class")
    roster = tmp / "roster.csv"
    roster.write_text("id,name\nana,Ana\nbruno,Bruno\ncarla,Carla\ndora,Dora\n", encoding="utf-8")
    secret = tmp / "secret.key"
    secret.write_bytes(SECRET + b"\n")
    assert R.main(["release", str(roster), "-o", str(tmp / "release"), "--secret-file", str(secret),
                   "--family", "all"]) == 0
    notebooks = {sid: json.loads((tmp / "release" / f"{sid}.ipynb").read_text(encoding="utf-8"))
                 for sid in ("ana", "bruno", "carla", "dora")}
    return tmp, secret, notebooks


@pytest.fixture(scope="module")
def handed_in(released):
    """ana honest (another valid DH assignment than the reference's), bruno hands in carla's
    solved notebook, carla puts the published PUMA in her metadata and robot cell and solves
    that, dora strips the record and solves her own robot."""
    from dhlab.assignment.model import random_frames_from_axes
    tmp, _, nbs = released
    folder = tmp / "submissions"
    ana = released_robot(nbs["ana"])
    write(folder / "ana.ipynb", solved(nbs["ana"], ana, random_frames_from_axes(ana, np.random.default_rng(1))))
    write(folder / "bruno.ipynb", solved(nbs["carla"], released_robot(nbs["carla"])))
    published = V.variant("puma560", "from the textbook")
    forged = copy.deepcopy(nbs["carla"])
    forged["metadata"]["dhlab"]["variant"] = published.to_dict()
    seam = next(c for c in forged["cells"] if c.get("id") == SEAM_CELL_ID)
    seam["source"] = seam_source({"variant": published.to_dict(), "student_id": "carla"})
    write(folder / "carla.ipynb", solved(forged, V.robot_of_variant(published)))
    stripped = copy.deepcopy(nbs["dora"])
    del stripped["metadata"]["dhlab"]
    write(folder / "submitted" / "dora" / "ps8" / "08_puma_assignment.ipynb",
          solved(stripped, released_robot(nbs["dora"])))
    return folder


def _grade(folder, out, *extra, package):
    from support.grader import run_grader
    return run_grader(["puma", str(folder), "-o", str(out), "-j", "2", *extra], package)


def _rows(path) -> dict:
    with open(path, newline="", encoding="utf-8") as f:
        reader = csv.DictReader(f)
        return reader.fieldnames, {row["submission"]: row for row in reader}


def test_the_class_is_graded_against_each_students_robot(released, handed_in, package):
    tmp, secret, nbs = released
    out = tmp / "gradebook.csv"
    proc = _grade(handed_in, out, "--secret-file", str(secret), "--release", str(tmp / "release"), package=package)
    assert proc.returncode == 0, proc.stderr
    columns, rows = _rows(out)
    assert columns[-5:] == GV.COLUMNS and columns[:-5] == R_COLUMNS()
    fp = {sid: V.fingerprint(V.Variant.from_dict(nb["metadata"]["dhlab"]["variant"]))[:12] for sid, nb in nbs.items()}

    ana = rows["ana"]                                # honest: full marks, her own robot
    assert (ana["score"], ana["status"], ana["variant_status"], ana["variant_source"]) == ("10", "ok", "ok", "notebook")
    assert ana["variant_id"] == fp["ana"] and ana["signed_for"] == "ana" and ana["variant_family"]
    feedback = (tmp / "gradebook_feedback" / ana["feedback"]).read_text(encoding="utf-8")
    assert f"Robot graded against: your {released_robot(nbs['ana']).name} ({fp['ana']})" in feedback

    bruno = rows["bruno"]                            # carla's notebook handed in by bruno: named, graded as bruno's
    assert (bruno["variant_status"], bruno["signed_for"], bruno["variant_source"]) == (
        "other_student", "carla", "roster")
    assert "signed for 'carla', not for 'bruno'" in bruno["status"] and bruno["variant_id"] == fp["bruno"]
    assert float(bruno["score"]) < 7

    carla = rows["carla"]                            # the textbook PUMA in her metadata: tampered, graded as hers
    assert (carla["variant_status"], carla["variant_source"], carla["variant_id"]) == (
        "tampered", "roster", fp["carla"])
    assert "graded against the roster's variant for 'carla'" in carla["status"] and float(carla["score"]) < 7

    dora = rows["submitted/dora/ps8/08_puma_assignment"]      # nbgrader's layout; no record: her own robot
    assert (dora["variant_status"], dora["variant_source"], dora["variant_id"], dora["score"]) == \
        ("missing", "roster", fp["dora"], "10")
    assert dora["status"].startswith("variant missing: no signed variant")

    # --fallback none: only the honest one is graded, the others get no marks and say why
    strict = tmp / "strict.csv"
    proc = _grade(handed_in, strict, "--secret-file", str(secret), "--release", str(tmp / "release"),
                  "--fallback", "none", package=package)
    assert proc.returncode == 0, proc.stderr
    _, rows = _rows(strict)
    assert rows["ana"]["score"] == "10"
    for name in ("bruno", "carla", "submitted/dora/ps8/08_puma_assignment"):
        assert rows[name]["score"] == "0" and rows[name]["variant_source"] == "none"
        assert "not graded (--fallback none)" in rows[name]["status"]


def R_COLUMNS():
    from dhlab.grading.book.gradebook import COLUMNS
    return COLUMNS


# --- fast: the rules, in the grader's process ---------------------------------------------------------

@pytest.fixture
def class_setup(released):
    tmp, secret, _ = released
    return GV.setup(secret, tmp / "release")


def test_who_handed_it_in(class_setup, released):
    vs = class_setup
    assert GV.identify(vs, "ana.ipynb")[0] == "ana"
    assert GV.identify(vs, "late/ana.ipynb")[0] == "ana"
    assert GV.identify(vs, "submitted/bruno/ps8/08_puma_assignment.ipynb")[0] == "bruno"
    assert GV.identify(vs, "submitted/bruno/ps8/carla.ipynb")[0] == "bruno"       # nbgrader: the folder wins
    assert GV.identify(vs, "submitted/nobody/ps8/carla.ipynb")[0] is None
    who, how = GV.identify(vs, "ana_final.ipynb")
    assert who is None and "'ana_final' matches no student" in how
    alone = GV.setup(released[1])                                              # no roster: folder, else stem
    assert GV.identify(alone, "submitted/x/ps8/nb.ipynb")[0] == "x" and GV.identify(alone, "y.ipynb")[0] == "y"


def test_the_staged_copy_runs_the_verified_robot(class_setup, released, tmp_path):
    """A student who edits the robot cell to a classmate's robot gets theirs back in the copy
    that runs; a file the grader cannot attribute is not run at all."""
    _, _, nbs = released
    hacked = copy.deepcopy(nbs["ana"])
    cell = next(c for c in hacked["cells"] if c.get("id") == SEAM_CELL_ID)
    cell["source"] = seam_source(nbs["bruno"]["metadata"]["dhlab"])
    write(tmp_path / "in" / "ana.ipynb", hacked)
    write(tmp_path / "in" / "who.ipynb", nbs["ana"])
    resolve = lambda nb, file: GV.resolve(class_setup, nb, file)
    staged = stage(tmp_path / "in" / "ana.ipynb", tmp_path / "in", tmp_path, 0, resolve)
    code = "".join(c["source"] for c in json.loads(staged.copy.read_text())["cells"])
    ana_variant = json.dumps(nbs["ana"]["metadata"]["dhlab"]["variant"], sort_keys=True)
    assert ana_variant in code and json.dumps(nbs["bruno"]["metadata"]["dhlab"]["variant"], sort_keys=True) not in code
    assert staged.variant.status == "ok" and staged.variant.robot.n == released_robot(nbs["ana"]).n
    unknown = stage(tmp_path / "in" / "who.ipynb", tmp_path / "in", tmp_path, 1, resolve)
    assert unknown.copy is None and unknown.variant.status == "unknown_student"
    assert "its record names 'ana'" in GV.status_note(unknown.variant)
    broken = tmp_path / "in" / "bruno.ipynb"
    broken.write_text("{not json", encoding="utf-8")
    staged = stage(broken, tmp_path / "in", tmp_path, 2, resolve)
    assert staged.copy is None and "not valid JSON" in staged.error and staged.variant.status == "missing"


def test_clear_errors_at_the_boundary(released, tmp_path):
    from dhlab import DHLabError
    tmp, secret, _ = released
    release = tmp / "release"
    other = tmp_path / "other.key"
    other.write_bytes(b"another teacher's secret, long enough")
    with pytest.raises(DHLabError, match="none of the 4 variants .* verifies with the secret"):
        GV.setup(other, release)
    with pytest.raises(DHLabError, match="cannot read the secret file"):
        GV.setup(tmp_path / "nope.key", release)
    with pytest.raises(DHLabError, match="has no _teacher/variants.json"):
        GV.setup(secret, tmp_path)
    with pytest.raises(DHLabError, match="is not a folder"):
        GV.setup(secret, tmp_path / "nowhere")
    with pytest.raises(DHLabError, match="--fallback roster needs --release"):
        GV.setup(secret, None, "roster")
    changed = tmp_path / "changed"
    (changed / "_teacher").mkdir(parents=True)
    records = json.loads((release / "_teacher" / "variants.json").read_text(encoding="utf-8"))
    records["ana"]["variant"]["senses"][0] *= -1
    (changed / "_teacher" / "variants.json").write_text(json.dumps(records), encoding="utf-8")
    with pytest.raises(DHLabError, match="1 of the 4 variants .* do not verify .*'ana'"):
        GV.setup(secret, changed)


def test_the_command_line_says_what_is_wrong(released, tmp_path):
    import subprocess
    tmp, secret, nbs = released
    write(tmp_path / "subs" / "ana.ipynb", nbs["ana"])

    def grade(*argv):
        return subprocess.run([sys.executable, "-m", "dhlab.grading.cli", "puma", str(tmp_path / "subs"),
                               "-o", str(tmp_path / "gb.csv"), *argv], capture_output=True, text=True, cwd=ROOT)
    proc = grade("--release", str(tmp / "release"))
    assert proc.returncode == 2 and "give --secret-file too" in proc.stderr
    proc = grade("--secret-file", str(tmp_path / "missing.key"), "--release", str(tmp / "release"))
    assert proc.returncode == 2 and "dhlab-grade: error: cannot read the secret file" in proc.stderr
    assert "Traceback" not in proc.stderr
    proc = grade("--secret-file", str(secret), "--release", str(tmp_path))
    assert proc.returncode == 2 and "has no _teacher/variants.json" in proc.stderr and "Traceback" not in proc.stderr


def test_the_gradebook_with_variant_columns_resumes_only_in_its_own_mode(tmp_path):
    """The variant columns come last, so a reader of the old columns reads the same; --resume
    keeps rows only from a gradebook of the same columns (else every row is graded again)."""
    from dhlab.grading.book.gradebook import COLUMNS, VARIANT_COLUMNS, read_csv, write_csv
    row = {c: "1" for c in VARIANT_COLUMNS} | {"submission": "ana", "variant_status": "ok"}
    write_csv(tmp_path / "v.csv", [row], VARIANT_COLUMNS)
    write_csv(tmp_path / "p.csv", [row])
    assert read_csv(tmp_path / "v.csv", VARIANT_COLUMNS)[0]["variant_status"] == "ok"
    assert read_csv(tmp_path / "v.csv") == [] and read_csv(tmp_path / "p.csv", VARIANT_COLUMNS) == []
    assert list(read_csv(tmp_path / "p.csv")[0]) == COLUMNS
    assert VARIANT_COLUMNS[:len(COLUMNS)] == COLUMNS and VARIANT_COLUMNS[len(COLUMNS):] == GV.COLUMNS
