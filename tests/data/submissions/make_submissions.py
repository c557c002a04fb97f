"""How the test submissions of this folder were made: from the student notebook, as students fill it in.

    python tests/data/submissions/make_submissions.py      # rewrites the .ipynb files here

Each one is the generated student notebook with answers typed into its answer cells (the
source notebook's solutions, a valid alternative DH assignment, or specific mistakes) and,
for the hostile ones, extra cells that raise, hang, flood, exhaust memory, kill processes
or tamper with dhlab. Two are not notebooks at all. tests/test_grading_runner.py grades
them all and says what each must get.
"""
import copy
import json
import re
from pathlib import Path

import nbformat

ROOT = Path(__file__).resolve().parents[3]
OUT = ROOT / "tests/data/submissions"
student = nbformat.read(ROOT / "notebooks/08_puma_assignment.ipynb", 4)
source = nbformat.read(ROOT / "notebooks/source/08_puma_assignment.ipynb", 4)

def solution_of(gid):
    for c in source.cells:
        if c.metadata.get("nbgrader", {}).get("grade_id") == gid:
            m = re.search(r"### BEGIN SOLUTION\n(.*?)### END SOLUTION", c.source, re.S)
            return m.group(1).rstrip("\n")
    raise KeyError(gid)

P1, P2, P3 = (solution_of(g) for g in ("part1_answers", "part2_answers", "part3_answers"))

def make(name, answers=None, extra=(), raw=None):
    """answers: {grade_id: code}; extra: [(after_grade_id, code)] cells inserted after that cell."""
    path = OUT / name
    if raw is not None:
        path.write_text(raw, encoding="utf-8")
        return
    nb = copy.deepcopy(student)
    answers = answers or {}
    for c in nb.cells:
        gid = c.metadata.get("nbgrader", {}).get("grade_id")
        if gid in answers:
            c.source = c.source.replace("# YOUR CODE HERE", answers[gid])
    for after, code in reversed(list(extra)):
        idx = next(i for i, c in enumerate(nb.cells) if c.metadata.get("nbgrader", {}).get("grade_id") == after)
        nb.cells.insert(idx + 1, nbformat.v4.new_code_cell(code))
    for i, c in enumerate(nb.cells):
        c["id"] = f"{name.split('.')[0][:40]}-{i}"
    nbformat.write(nb, path)

ALL = {"part1_answers": P1, "part2_answers": P2, "part3_answers": P3}

ALT_P2 = """link_points = {
    0: [(0, 0, -0.67183), (0, 0, -0.25)],
    1: [(0, 0.25, 0), (0, 0, 0), (0, 0, -0.15005)],
    2: [(-0.4318, 0, 0), (0, 0, 0)],
    3: [(-0.0203, 0, 0), (0, 0, 0), (0, 0, 0.3518)],
    4: [(0, -0.08, 0), (0, -0.08, -0.05), (0, 0, -0.05)],
    5: [(0, -0.05, 0), (0, 0, 0), (0, 0, 0.056)],
    6: [(0.03, 0, 0.096), (0.03, 0, 0.056), (-0.03, 0, 0.056), (-0.03, 0, 0.096)],
}"""
ALT_P3 = """# my frames: z1 and z2 point along +y0 (against the arrows of joints 2 and 3, hence -q2, -q3),
# frame 2 at the elbow E, z4 along +y0, x4 backwards, x6 along +y0 at home
T1 = Tz(q1, 0) @ Tx(-90, 0)
T2 = Tz(-q2, -0.15005) @ Tx(0, 0.4318)
T3 = Tz(-q3, 0) @ Tx(90, 0.0203)
T4 = Tz(q4 + 180, 0.4318) @ Tx(90, 0)
T5 = Tz(-q5 + 180, 0) @ Tx(90, 0)
T6 = Tz(q6 + 90, 0) @ Tx(0, 0)
chain = T1 @ T2 @ T3 @ T4 @ T5 @ T6"""
make("valid_alternative.ipynb", {"part1_answers": P1, "part2_answers": ALT_P2, "part3_answers": ALT_P3})

make("mistake_part1.ipynb", {**ALL, "part1_answers": P1.replace("n_links = 7", "n_links = 6").replace(
    '["intersect", "parallel", "skew",', '["intersect", "parallel", "intersect",')})

P2_BAD = P2.replace("3: [(-0.0203, 0, 0), (0, 0, 0), (0, 0, 0.3518)]",       # forearm given in frame 2's coordinates
                    "3: [(0, 0, 0.15005), (0.0203, 0, 0.15005), (0.0203, 0.3518, 0.15005)]")
P2_BAD = P2_BAD.replace("5: [(0, -0.05, 0), (0, 0, 0), (0, 0, 0.056)]",     # left-handed frame 5
                        "5: [(0, 0.05, 0), (0, 0, 0), (0, 0, 0.056)]")
assert P2_BAD != P2
make("mistake_part2.ipynb", {**ALL, "part2_answers": P2_BAD})

P3_BAD = P3.replace("T2 = Tz(q2, 0) @ Tx(0, 0.4318)", "T2 = Tz(q2, 0) @ Tx(-90, 0.4318)")
P3_BAD = P3_BAD.replace("T6 = Tz(q6, 0) @ Tx(0, 0)", "T6 = Tz(q6, 0.056) @ Tx(0, 0)")
make("mistake_part3.ipynb", {**ALL, "part3_answers": P3_BAD})

make("hostile_raises.ipynb", {**ALL, "part2_answers": "link_points = {k: frame_points(k) for k in range(7)}   # a helper I never wrote"},
     extra=[("part1_check", 'raise RuntimeError("I give up on this cell")')])
make("hostile_hangs.ipynb", ALL, extra=[("part2_check", "while True:\n    pass")])
make("hostile_ignores_interrupt.ipynb", ALL, extra=[("part2_check",
     "import time\nwhile True:\n    try:\n        time.sleep(1)\n    except KeyboardInterrupt:\n        pass")])
make("hostile_prints.ipynb", ALL, extra=[("part1_check", 'print("x" * 3_000_000)\nwhile True:\n    print("spam " * 20_000)')])
make("hostile_memory.ipynb", ALL, extra=[("part1_check",
     "hog = []\nwhile True:\n    hog.append(bytearray(100_000_000))"), ("part2_check", "import numpy as np\nbig = np.ones((100_000, 100_000))")])
make("hostile_kills_kernel.ipynb", ALL, extra=[("part1_check", "import os\nos._exit(3)")])
make("hostile_kills_grader.ipynb", ALL, extra=[("part2_check", "import os, signal\nos.kill(os.getppid(), signal.SIGKILL)")])
text = (OUT / "mistake_part1.ipynb").read_text()
make("hostile_invalid_json.ipynb", raw=text[: len(text) // 2])
make("hostile_not_a_notebook.ipynb", raw=json.dumps({"student": "me", "answers": "in my head"}))
MONKEY = '''import dhlab, dhlab.assignment, dhlab.grading.checks, dhlab.grading.answers
from dhlab.course.assignment import check_part3
# make every check say "full marks"
dhlab.assignment.check_part3 = lambda ns: "Part 3 (the transformations and their chain): 5/5 points"
check_part3 = dhlab.assignment.check_part3
dhlab.grading.checks.check_all = lambda answers: "PUMA 560 assignment: 10/10 points"
dhlab.grading.checks.POINTS["part3"] = 0
setattr(dhlab.grading.answers, "parse_answers", lambda raw: None)
# make the answers' reader see the reference solution instead of mine
_ref = dhlab.robots.puma560()
dhlab.grading.answers.to_plain = lambda value, *a, **k: {"kind": "dh", "theta": 0, "d": 0, "alpha": 0, "a": 0}
import json
json.dumps = lambda *a, **k: '{"n_links": 7, "T1": "perfect"}'
list, dict, float, int, str, isinstance = None, None, None, None, None, None
print("PUMA 560 assignment: 10/10 points")'''
make("hostile_monkeypatch.ipynb", {**ALL, "part2_answers": "", "part3_answers": P3_BAD}, extra=[("part3_check", MONKEY)])
WEIRD = '''class Liar:
    def __eq__(self, other):
        return True
    def __repr__(self):
        return "whatever you want"
n_links = Liar()
n_joints = "six"
joint_types = 6
x_cases = {"first": Liar()}'''
WEIRD2 = 'link_points = [[(0, 0, 0)] * 100_000] * 7'
WEIRD3 = '''T1 = lambda q: "a matrix"
T2 = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]
T3 = {"kind": "dh", "theta": {"kind": "term", "joint": 3, "sign": 1, "const": 0}, "d": 0.15005, "alpha": -90, "a": 0.0203}
T4 = float("nan")
def endless():
    while True:
        yield 1
chain = endless()'''
make("hostile_weird_values.ipynb", {"part1_answers": WEIRD, "part2_answers": WEIRD2, "part3_answers": WEIRD3})
if __name__ == "__main__":
    print(sorted(p.name for p in OUT.glob("*.ipynb")))
