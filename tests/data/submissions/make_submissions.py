"""How the test submissions of this folder were made: from the student notebook, as students fill it in.

    python tests/data/submissions/make_submissions.py      # rewrites the .ipynb files here

Each one is the generated student notebook with answers typed into its answer cells (the
teacher's solutions, computed by dhlab.assignment.solution, a valid alternative DH assignment, or
specific mistakes) and,
for the hostile ones, extra cells that raise, hang, flood, exhaust memory, kill processes
or tamper with dhlab. Two are not notebooks at all. tests/grading/test_grading_runner.py grades
them all and says what each must get.
"""
import copy
import json
from pathlib import Path

import nbformat

from dhlab.assignment.solution import answers

ROOT = Path(__file__).resolve().parents[3]
OUT = ROOT / "tests/data/submissions"
student = nbformat.read(ROOT / "notebooks/08_puma_assignment.ipynb", 4)
# the teacher's solutions of the PUMA 560: computed (no file of the course holds them)
P1, P2, P3 = (answers()[g] for g in ("part1_answers", "part2_answers", "part3_answers"))

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
P2_BAD = P2_BAD.replace("5: [(0, -0.05, 0), (0, 0, 0), (0, 0, 0.056)]",     # x5 turned over: still a valid frame 5
                        "5: [(0, 0.05, 0), (0, 0, 0), (0, 0, 0.056)]")
assert P2_BAD != P2
make("mistake_part2.ipynb", {**ALL, "part2_answers": P2_BAD})

P3_BAD = P3.replace("T2 = Tz(q2, 0) @ Tx(0, 0.4318)", "T2 = Tz(q2, 0) @ Tx(-90, 0.4318)")
P3_BAD = P3_BAD.replace("T6 = Tz(q6, 0) @ Tx(0, 0)", "T6 = Tz(q6, 0.056) @ Tx(0, 0)")
make("mistake_part3.ipynb", {**ALL, "part3_answers": P3_BAD})

make("hostile_raises.ipynb",
     {**ALL, "part2_answers": "link_points = {k: frame_points(k) for k in range(7)}   # a helper I never wrote"},
     extra=[("part1_check", 'raise RuntimeError("I give up on this cell")')])
make("hostile_hangs.ipynb", ALL, extra=[("part2_check", "while True:\n    pass")])
make("hostile_ignores_interrupt.ipynb", ALL, extra=[("part2_check",
     "import time\nwhile True:\n    try:\n        time.sleep(1)\n    except KeyboardInterrupt:\n        pass")])
make("hostile_prints.ipynb", ALL,
     extra=[("part1_check", 'print("x" * 3_000_000)\nwhile True:\n    print("spam " * 20_000)')])
make("hostile_memory.ipynb", ALL, extra=[("part1_check",
     "hog = []\nwhile True:\n    hog.append(bytearray(100_000_000))"),
    ("part2_check", "import numpy as np\nbig = np.ones((100_000, 100_000))")])
make("hostile_kills_kernel.ipynb", ALL, extra=[("part1_check", "import os\nos._exit(3)")])
make("hostile_kills_grader.ipynb", ALL,
     extra=[("part2_check", "import os, signal\nos.kill(os.getppid(), signal.SIGKILL)")])
text = (OUT / "mistake_part1.ipynb").read_text()
make("hostile_invalid_json.ipynb", raw=text[: len(text) // 2])
make("hostile_not_a_notebook.ipynb", raw=json.dumps({"student": "me", "answers": "in my head"}))
MONKEY = '''import dhlab, dhlab.assignment, dhlab.assignment.checks, dhlab.assignment.answers, dhlab.assignment.encode
from dhlab.course.assignment import check_part3
# make every check say "full marks"
dhlab.assignment.check_part3 = lambda ns: "Part 3 (the transformations and their chain): 5/5 points"
check_part3 = dhlab.assignment.check_part3
dhlab.assignment.checks.check_all = lambda answers: "PUMA 560 assignment: 10/10 points"
dhlab.assignment.checks.POINTS["part3"] = 0
setattr(dhlab.assignment.answers, "parse_answers", lambda raw: None)
# make the answers' reader see the reference solution instead of mine
_ref = dhlab.robots.puma560()
dhlab.assignment.encode.to_plain = lambda value, *a, **k: {"kind": "dh", "theta": 0, "d": 0, "alpha": 0, "a": 0}
import json
json.dumps = lambda *a, **k: '{"n_links": 7, "T1": "perfect"}'
list, dict, float, int, str, isinstance = None, None, None, None, None, None
print("PUMA 560 assignment: 10/10 points")'''
make("hostile_monkeypatch.ipynb", {**ALL, "part2_answers": "", "part3_answers": P3_BAD},
     extra=[("part3_check", MONKEY)])
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
chain = endless()'''  # noqa: E501  (a student's cell, as the committed hostile_weird_values.ipynb has it)
make("hostile_weird_values.ipynb", {"part1_answers": WEIRD, "part2_answers": WEIRD2, "part3_answers": WEIRD3})

# --- one slip, one item: a mistake that leaves a valid frame costs only its row -------------
make("slip_alpha1.ipynb",
     {**ALL, "part3_answers": P3.replace("T1 = Tz(q1, 0) @ Tx(90, 0)", "T1 = Tz(q1, 0) @ Tx(-90, 0)")})
make("slip_alpha3.ipynb", {**ALL, "part3_answers": P3.replace("Tx(-90, 0.0203)", "Tx(90, 0.0203)")})
# the alternative assignment (x4 backwards), with the +180° of θ4 forgotten
make("slip_theta4_offset.ipynb", {"part1_answers": P1, "part2_answers": ALT_P2,
                                  "part3_answers": ALT_P3.replace("Tz(q4 + 180, 0.4318)", "Tz(q4, 0.4318)")})
# every T_i right, the links drawn in another valid set of frames: full marks, and a note
make("mixed_valid_frames.ipynb", {"part1_answers": P1, "part2_answers": P2, "part3_answers": ALT_P3})

# --- one checking path: numpy, sympy and deg2rad() values are read as the notebook reads them ---------------
NUMERIC_P1 = """import numpy as np, sympy as sp
n_links = np.int64(7)
n_joints = sp.Integer(6)
joint_types = np.array(list("RRRRRR"))
x_cases = ["intersect", "parallel", "skew", "intersect", "intersect"]"""
NUMERIC_P2 = """import numpy as np
# the world points of the table, and my frames at home from my transformations
world = {"O": (0, 0, -0.67183), "B": (0, 0, -0.25), "S": (0, 0, 0), "A": (0, -0.15005, 0),
         "E": (0.4318, -0.15005, 0), "K": (0.4521, -0.15005, 0), "M": (0.4521, -0.15005, 0.3518),
         "Y": (0.4521, -0.20005, 0.3518), "N": (0.4521, -0.20005, 0.4318), "W": (0.4521, -0.15005, 0.4318),
         "F": (0.4521, -0.15005, 0.4878), "G1": (0.4521, -0.12005, 0.5278), "G2": (0.4521, -0.12005, 0.4878),
         "G3": (0.4521, -0.18005, 0.4878), "G4": (0.4521, -0.18005, 0.5278)}
names = [["O", "B"], ["B", "S", "A"], ["A", "E"], ["E", "K", "M"], ["M", "Y", "N"], ["N", "W", "F"],
         ["G1", "G2", "G3", "G4"]]
mine = ((Tz(q1, 0) @ Tx(90, 0)) @ (Tz(q2, 0) @ Tx(0, 0.4318)) @ (Tz(q3, 0.15005) @ Tx(-90, 0.0203))
        @ (Tz(q4, 0.4318) @ Tx(90, 0)) @ (Tz(q5, 0) @ Tx(-90, 0)) @ (Tz(q6, 0) @ Tx(0, 0)))
frames = mine.frames(np.zeros(6))
link_points = {}
for k, F in enumerate(frames):
    R, o = F[:3, :3], F[:3, 3]
    link_points[k] = [tuple(R.T @ (np.array(world[n]) - o)) for n in names[k]]     # numpy floats"""
NUMERIC_P3 = """import numpy as np, sympy as sp
from dhlab import deg2rad
T1 = Tz(q1, 0) @ Tx(deg2rad(90), 0)
T2 = Tz(q2 + deg2rad(0), 0) @ Tx(0, np.float64(0.4318))
T3 = Tz(q3, 0.15005) @ Tx(np.float32(-90), 0.0203)
T4 = Tz(q4, 0.4318) @ Tx(sp.Integer(90), 0)
T5 = Tz(q5, 0) @ Tx(deg2rad(-90), 0)
T6 = Tz(q6, 0) @ Tx(0, 0)
chain = T1 @ T2 @ T3 @ T4 @ T5 @ T6"""
make("numeric_types.ipynb", {"part1_answers": NUMERIC_P1, "part2_answers": NUMERIC_P2, "part3_answers": NUMERIC_P3})


# --- outputs are not the submission (a notebook with 25 MB of saved outputs is made by the test itself,
# from valid_alternative.ipynb, to keep the repository small); the code itself is limited
make("hostile_huge_code.ipynb", ALL, extra=[("part1_check", "junk = '" + "y" * 1_200_000 + "'")])

# --- odd names: two students whose names differ only where a file system might mangle them ---------------
make("Ana María.ipynb", {**ALL, "part3_answers": P3_BAD})
make("Ana_María.ipynb", ALL)

# --- isolation: hostile notebooks against the package, classmates, the gradebook, the grader -------------
TAMPER = r'''import dhlab.course.assignment as mine, dhlab.assignment.checks as checks, pathlib
for module in (mine, checks):                  # every later kernel (and the grader) imports these
    try:
        with open(module.__file__, "a") as f:
            f.write("\nPOINTS_TAMPERED = True\n")
    except OSError as e:
        print("could not write", module.__file__, e)
pathlib.Path(mine.__file__).with_name("sneaky.py").write_text("x = 1")'''
make("hostile_tampers_package.ipynb", ALL, extra=[("part1_check", TAMPER)])
ESCAPE = r'''import os, subprocess, sys
code = """import glob, os, time
time.sleep(4)
for path in glob.glob('/tmp/**/*.csv', recursive=True) + glob.glob('/tmp/**/*.ipynb', recursive=True):
    try:
        open(path, 'w').write('overwritten by a setsid escapee')
    except OSError:
        pass
"""
subprocess.Popen([sys.executable, "-c", code], start_new_session=True,
                 stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)'''
make("hostile_setsid_escapee.ipynb", ALL, extra=[("part1_check", ESCAPE)])
CLASSMATES = r'''import glob, os, pathlib
found = []
for pid in os.listdir("/proc"):                # the paths of the other submissions, wherever they show
    for part in ("cmdline", "environ"):
        try:
            words = pathlib.Path("/proc", pid, part).read_bytes().decode("utf-8", "replace").split("\0")
            found += [w.split("=", 1)[-1] for w in words if ".ipynb" in w or ".csv" in w]
        except OSError:
            pass
paths = list(found)
for folder in {os.path.dirname(p) for p in found} | {"/tmp"}:
    paths += glob.glob(os.path.join(folder, "**", "*.ipynb"), recursive=True)
    paths += glob.glob(os.path.join(folder, "**", "*.csv"), recursive=True)
touched = 0
for path in set(paths):
    try:
        text = open(path).read()
        open(path, "w").write(text.replace("Tx(0, 0.4318)", "Tx(45, 0.4318)"))   # break a classmate's T2
        touched += 1
    except OSError:
        pass
print("touched", touched)'''
make("hostile_edits_classmates.ipynb", ALL, extra=[("part1_check", CLASSMATES)])
KILLER = r'''import os, signal
for pid in [os.getppid()] + [int(p) for p in os.listdir("/proc") if p.isdigit()]:
    if pid != os.getpid():
        try:
            os.kill(pid, signal.SIGKILL)         # the runner, the grader, anything it may signal
        except OSError:
            pass'''
make("hostile_kills_everything.ipynb", ALL, extra=[("part2_check", KILLER)])
FORK = r'''import os, time
children = 0
try:
    for _ in range(5000):
        if os.fork() == 0:
            time.sleep(60)
            os._exit(0)
        children += 1
except OSError as e:
    print("fork stopped after", children, e)'''
make("hostile_fork_bomb.ipynb", ALL, extra=[("part1_check", FORK)])

if __name__ == "__main__":
    print(sorted(p.name for p in OUT.glob("*.ipynb")))
