"""The "Your robot" section of the assignment notebook, for one student's variant.

**The seam.** :func:`use_variant` makes a student's variant the robot of the notebook's
assignment (the released notebook calls it in a locked cell); :func:`current_robot` is
that robot, or the PUMA 560 of the seed when none was set: every check, table and
figure of :mod:`dhlab.assignment.notebook` asks it.

**The release.** :func:`release_notebook` turns the generated student notebook (the template) into one
student's: the robot's section becomes "Your robot" (its figure, axes table and points
table), a locked cell (:func:`seam_source`) makes the student's variant the robot of the
assignment, the answer stubs name this robot's links and transformations, and the signed
record goes into ``metadata["dhlab"]``. The template is changing with the course, so
every step finds its cell by its nbgrader ``grade_id`` and says so (``notes``) when a
cell is not there, instead of failing. :func:`prepare_submission` is the grader's side:
it rewrites the locked cell from a verified variant before a submission runs.
"""
from __future__ import annotations

import base64
import copy
import html
import io
import json
import re

from ..i18n import N_, _
from . import variants as V
from .family import shown_name, spec
from .model import AssignmentRobot
from .reference import reference
from .solution import ANSWER_MARKER, is_answer_marker

__all__ = ["SEAM_CELL_ID", "use_variant", "active_robot", "current_robot", "clear_variant", "seam_source",
           "robot_intro", "release_notebook", "prepare_submission", "apply_rules", "formula_rules"]

SEAM_CELL_ID = "dhlab-your-robot"


# --- the seam: the notebook's robot ------------------------------------------------------------------

_ACTIVE = {"robot": None, "variant": None, "student_id": None}


def use_variant(data, student_id: str | None = None) -> AssignmentRobot:
    """Make the variant ``data`` (a dict, as released) the robot of this notebook's assignment;
    returns its :class:`~dhlab.assignment.model.AssignmentRobot`. The released notebook calls
    it in its "Your robot" cell; :func:`active_robot` then gives it to the checks."""
    v = data if isinstance(data, V.Variant) else V.Variant.from_dict(data)
    robot = V.robot_of_variant(v)
    _ACTIVE.update(robot=robot, variant=v, student_id=student_id)
    return robot


def active_robot():
    """The robot set by :func:`use_variant`, or None (then the assignment is the PUMA 560)."""
    return _ACTIVE["robot"]


def current_robot():
    """The robot of this notebook's assignment: the student's own robot when the notebook's
    "Your robot" cell set one (:func:`use_variant`), else the PUMA 560
    (:func:`dhlab.assignment.reference.reference`)."""
    return active_robot() or reference()


def clear_variant() -> None:
    """Back to the PUMA 560: no student's robot is the assignment's any more."""
    _ACTIVE.update(robot=None, variant=None, student_id=None)


# --- the notebook, for one student -------------------------------------------------------------------


def _grade_id(cell) -> str | None:
    return cell.get("metadata", {}).get("nbgrader", {}).get("grade_id")


def _find(cells, grade_id) -> int | None:
    return next((i for i, c in enumerate(cells) if _grade_id(c) == grade_id), None)


def _lines(text: str) -> list:
    """A cell source as the list of lines nbformat writes."""
    parts = text.split("\n")
    return [p + "\n" for p in parts[:-1]] + ([parts[-1]] if parts[-1] else [])


def _markdown(cell_id: str, text: str) -> dict:
    return {"cell_type": "markdown", "id": cell_id, "metadata": {}, "source": _lines(text)}


def _code(cell_id: str, text: str, grade_id: str, outputs=()) -> dict:
    meta = {"deletable": False, "editable": False,
            "nbgrader": {"grade": False, "grade_id": grade_id, "locked": True, "schema_version": 3, "solution": False}}
    return {"cell_type": "code", "execution_count": None, "id": cell_id, "metadata": meta,
            "outputs": list(outputs), "source": _lines(text)}


def _source(cell) -> str:
    src = cell.get("source", "")
    return "".join(src) if isinstance(src, list) else src


def _set_source(cell, text: str) -> None:
    cell["source"] = _lines(text)
    if cell.get("cell_type") == "code":
        cell["outputs"], cell["execution_count"] = [], None


def seam_source(record: dict) -> str:
    """The locked cell that makes the student's variant the assignment's robot."""
    n = len(record["variant"]["senses"])
    names = ", ".join(f"q{i}" for i in range(1, n + 1))
    variant_text = json.dumps(record["variant"], sort_keys=True)
    return (_("# Your robot: drawn for you and signed by your teacher. Do not edit this cell.") + "\n"
            "from dhlab.assignment import use_variant\n"
            f"my_robot = use_variant({variant_text},\n"
            f"                       student_id={json.dumps(record['student_id'])})\n"
            f"{names} = joint_variables({n})     " + _("# the joint variables q_i of your robot"))


def robot_intro(robot, record) -> str:
    """The markdown of the "Your robot" section: whose notebook it is, which robot, what is fixed."""
    s = spec(record["variant"]["family"])
    n, kinds = robot.n, robot.kinds
    joints = ", ".join(_("joint {i} prismatic").format(i=i) for i, k in enumerate(kinds, 1)
                       if k == "P") or _("all revolute")
    mount = _("hangs from a ceiling plate") if robot.mount["mount"] == "ceiling" else _("stands on a floor plate")
    six = ("" if n == 6 else "\n\n" + _(
        "**Your robot has {n} joints**: `x_cases` has {words} words, the transformations are "
        "T1…T{n}, frame {n} is the end effector's.").format(n=n, words=n - 1))
    who = html.escape(record["student_id"])
    return (_("## Your robot\n\nThis notebook is for **{who}**. Your robot is {robot}: "
              "{family} whose lengths, home pose, positive senses and mounting were changed for you, "
              "so its DH table is yours to work out — it is in no book. It has {n} joints ({joints}) and {mount}."
              ).format(who=who, robot=_a(f"**{shown_name(robot.name)}**"), family=_a(s.name), n=n, joints=joints,
                       mount=mount) + "\n\n" +
            _("The figure shows it in its **home pose** ($q_i = 0$ for every joint). Each joint axis is dashed; its "
              "black arrow is the axis's **positive direction**: a revolute joint turns by the right-hand rule about "
              "it (purple curled arrow), a prismatic joint slides along it (purple arrow). The tables give the "
              "axes and the links' points in numbers (metres, world frame).") + "\n\n" +
            _("What the exercise fixes:") + "\n\n" +
            _("* **Frame 0** is the world frame drawn ($x_0$ red, $y_0$ green, $z_0$ blue): its origin lies on "
              "joint 1's axis and $z_0$ along it. Link 0, the base, is given in it.") + "\n" +
            _("* **The joint variables** $q_i$ are measured from the home pose, positive as the arrows show.") + "\n" +
            _("* **Frame {n}**, the end effector's, has its origin at the end point in the axes table, and "
              "$z_{n}$ along joint {n}'s axis.").format(n=n) + six)


def _a(name: str) -> str:
    """A robot's name with its article ('an Adept Cobra 600', 'a KUKA KR 5'; in Spanish 'un …')."""
    vowel = name.lstrip("*")[:1].upper() in "AEIOU"
    return (_("an {name}") if vowel else _("a {name}")).format(name=name)


_WORDS = {1: "one", 2: "two", 3: "three", 4: "four", 5: "five", 6: "six", 7: "seven", 8: "eight"}
# the same numbers in the student's language, for the answer cells' instructions
_NUMBER_WORDS = {1: N_("one"), 2: N_("two"), 3: N_("three"), 4: N_("four"), 5: N_("five"), 6: N_("six"),
                 7: N_("seven"), 8: N_("eight")}
PART1_STUB = N_('# Part 1: write your answers below, as Python.\n'
                '#   n_links, n_joints   whole numbers\n'
                '#   joint_types         one letter per joint: "R" (revolute) or "P" (prismatic); "RPR" would be a\n'
                '#                       robot whose first and last joints turn and whose middle joint slides\n'
                '#   x_cases             a list of {words} words, for x1 … x{last}: "intersect", "parallel" or "skew"')


def _number_word(n: int) -> str:
    return _(_NUMBER_WORDS[n]) if n in _NUMBER_WORDS else str(n)


def answer_marker() -> str:
    """The line where an answer cell asks for the answer, in the current language (the
    grader and the solved notebook know it in every language: :data:`~.solution.ANSWER_MARKERS`)."""
    return _(ANSWER_MARKER)


def _own_robot_text(text: str, robot, name: str) -> str:
    """The template's text about the PUMA 560 (six revolute joints, T1…T6, q1…q6), said of the
    student's robot: its name, its number of joints, its transformations and variables. Each rule
    changes only the words it finds (the template changes with the course)."""
    n = robot.n
    word = _WORDS.get(n, str(n))
    kinds = ", ".join(f"{robot.kinds.count(k)} {w}" for k, w in (("R", "revolute"), ("P", "prismatic"))
                      if robot.kinds.count(k))
    rules = [
        (r"a real six-joint arm", f"a real {word}-joint arm"),
        (r"configuration of the PUMA\s+robot\*\*", f"configuration of a robot**, here your own {name}"),
        (r"The PUMA 560 has \d+ revolute joints and \d+ links",
         f"Your {name} has {n} joints ({kinds}) and {n + 1} links"),
        (r"\bfive words\b", f"{_WORDS.get(n - 1, str(n - 1))} words"),
        (r"\$z_6\$ along \$z_5\$, \$x_6\$", f"$z_{n}$ along $z_{{{n - 1}}}$, $x_{n}$"),
        (r"^q1, q2, q3, q4, q5, q6 = joint_variables\(6\)",
         ", ".join(f"q{i}" for i in range(1, n + 1)) + f" = joint_variables({n})"),
        (r"\bthe PUMA's\b", "your robot's"),
        (r"\bthe PUMA( 560)?\b", "your robot"),
        (r"\bThe PUMA( 560)?\b", f"Your {name}"),
        (r"\bPUMA 560\b", name),
    ]
    return apply_rules(text, rules + formula_rules(n))


def formula_rules(n: int) -> list:
    """The rules of :func:`_own_robot_text` that read the same in every language: the joint
    count in formulas and the names of the transformations T1…Tn."""
    return [
        (r"(\$i = 1\s*…\s*)6(\$)", rf"\g<1>{n}\2"),
        (r"(\$i = 1\s*…\s*)5(\$)", rf"\g<1>{n - 1}\2"),
        (r"T1 @ T2 @ T3 @ T4 @ T5 @ T6", " @ ".join(f"T{i}" for i in range(1, n + 1))),
        (r"T1 … T6|T1…T6", f"T1…T{n}"),
        (r"`T1` … `T6`", f"`T1` … `T{n}`"),
    ]


def apply_rules(text: str, rules) -> str:
    """``text`` with each (pattern, replacement) rule applied in turn (multi-line patterns)."""
    for pattern, replacement in rules:
        text = re.sub(pattern, replacement, text, flags=re.M)
    return text


def _spec_name(record) -> str:
    return spec(record["variant"]["family"]).name


def _comments_only(source: str) -> tuple:
    """(comment lines, the answer marker line or None) when a stub is only comments, else None."""
    lines = [ln for ln in source.split("\n") if ln.strip()]
    if not lines or not all(ln.lstrip().startswith("#") for ln in lines):
        return None
    marker = lines[-1] if lines[-1].strip().upper().startswith("# YOUR") or is_answer_marker(lines[-1]) else None
    return (lines[:-1] if marker else lines), marker


def _with_marker(text: str, marker) -> str:
    return text + ("\n" + marker if marker else "")


def _part1_stub(robot, source: str) -> str | None:
    n = robot.n
    comments = _comments_only(source)
    if comments is not None and comments[0] and comments[0][0].startswith("# Part 1: write your answers"):
        text = _(PART1_STUB).format(words=_number_word(n - 1), last=n - 1)     # the course's, in the student's language
        return _with_marker(text, answer_marker() if comments[1] else None)
    new, count = re.subn(r"a list of \w+ words, for x1 … x\d+",
                         f"a list of {_WORDS.get(n - 1, n - 1)} words, for x1 … x{n - 1}", source)
    return new if count or n == 6 else None


def _part2_stub(robot, source: str) -> str | None:
    lines = source.split("\n")
    start = next((i for i, ln in enumerate(lines) if ln.startswith("link_points = {")), None)
    end = next((i for i in range(start, len(lines)) if lines[i].strip() == "}"), None) if start is not None else None
    if start is not None and end is not None:              # the stub is a dict to fill in
        body = []
        for k, link in enumerate(robot.points):
            names = ", ".join(name for name, _point in link)
            where = _("in frame 0 (the world frame)") if k == 0 else _("in frame {k}").format(k=k)
            body.append(f"    {k}: ...,   # {names:<18} {where}")
        return "\n".join(lines[:start + 1] + body + lines[end:])
    comments = _comments_only(source)
    if comments is None:
        return None
    links = [_("link {k}: {points}").format(k=k, points=", ".join(name for name, _point in link))
             + (" " + _("(in frame 0, the world frame)") if k == 0 else "")
             for k, link in enumerate(robot.points)]
    rows, row = [], "#  "
    for item in links:
        if len(row) + len(item) > 100:
            rows.append(row)
            row = "#  "
        row += " " + item + "  "
    rows.append(row)
    n = robot.n
    text = (_("# Part 2: write link_points below: for each link k = 0 … {n}, its points in its own frame k\n"
              "# (metres), in the table's order:").format(n=n) + "\n" + "\n".join(r.rstrip() for r in rows) + "\n"
            + _("# as a dict {{0: [(x, y, z), (x, y, z)], 1: [...], ...}} (or a list of {count} lists).").format(
                count=n + 1))
    return _with_marker(text, answer_marker() if comments[1] else None)


def _part3_stub(robot, source: str) -> str | None:
    n = robot.n
    lines = source.split("\n")
    rows = [i for i, ln in enumerate(lines) if re.fullmatch(r"T\d+ = \.\.\.\s*", ln)]
    if rows:                                               # the stub is T1 = ... lines
        new = [f"T{i} = ..." for i in range(1, n + 1)]
        return "\n".join(lines[:rows[0]] + new + lines[rows[-1] + 1:])
    comments = _comments_only(source)
    if comments is None:
        return None
    prismatic = [i for i, k in enumerate(robot.kinds, 1) if k == "P"]
    variable = (_("θ_i with its joint variable for a revolute joint") +
                (_(", d_i for a prismatic one (joint {joints})").format(joints=", ".join(map(str, prismatic)))
                 if prismatic else "") + ": q3, q3 - 90, -q3 + 180, ...")
    text = (_("# Part 3: write T1 … T{n} below, each T_i = Tz(θ_i, d_i) @ Tx(α_i, a_i) (degrees and metres,\n"
              "# {variable}), then").format(n=n, variable=variable) + "\n"
            f"# chain = {' @ '.join(f'T{i}' for i in range(1, n + 1))}")
    return _with_marker(text, answer_marker() if comments[1] else None)


def _outputs(obj, figure: bool) -> list:
    """The cell outputs that show ``obj`` (a table, or a figure as a PNG), as a kernel would."""
    if figure:
        png = obj.png() if hasattr(obj, "png") else _png(obj)
        data = {"image/png": base64.b64encode(png).decode("ascii"), "text/plain": ["<Figure>"]}
        return [{"data": data, "metadata": {}, "output_type": "display_data"}]
    data = {"text/html": _lines(obj._repr_html_()), "text/plain": _lines(repr(obj))}
    return [{"data": data, "metadata": {}, "output_type": "display_data"}]


def _png(fig) -> bytes:
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", metadata={"Software": None})
    return buffer.getvalue()


def release_notebook(template: dict, record: dict, figures: bool = True) -> tuple:
    """The student's notebook (a dict, nbformat 4) from the template and the signed record.
    Returns (notebook, notes): notes name the template cells that could not be adapted."""
    robot = V.robot_of_variant(V.Variant.from_dict(record["variant"]))     # the teacher's process keeps no robot
    nb = copy.deepcopy(template)
    cells, notes = nb["cells"], []
    setup = _find(cells, "setup")
    if setup is None:
        setup = next((i for i, c in enumerate(cells) if c.get("cell_type") == "code"), -1)
        notes.append(_("no 'setup' cell: the robot cell goes after the first code cell"))
    seam = _code(SEAM_CELL_ID, seam_source(record), "your_robot")
    replaced = {}
    for gid, text, obj, is_fig in (("robot_figure", "my_robot.figure()", robot.figure if figures else None, True),
                                   ("axes_table", "my_robot.axes_table()", robot.axes_table, False),
                                   ("points_table", "my_robot.points_table()", robot.points_table, False)):
        i = _find(cells, gid)
        outputs = _outputs(obj(), is_fig) if obj is not None else []
        if i is None:
            notes.append(_("no {cell!r} cell in the template: added to 'Your robot'").format(cell=gid))
            replaced[gid] = _code(f"dhlab-{gid}", text, gid, outputs)
            continue
        _set_source(cells[i], text)
        cells[i]["outputs"] = outputs
    figure = _find(cells, "robot_figure")
    if figure is not None and figure > setup + 1 and cells[figure - 1].get("cell_type") == "markdown" \
            and _source(cells[figure - 1]).startswith("## The robot"):
        _set_source(cells[figure - 1], robot_intro(robot, record))     # the robot's section becomes "Your robot"
        where, extra = figure, [seam]
    else:
        where, extra = setup + 1, [_markdown("dhlab-your-robot-intro", robot_intro(robot, record)), seam]
    extra += list(replaced.values())
    title = _source(cells[0]) if cells and cells[0].get("cell_type") == "markdown" else ""
    if title.startswith("# "):
        first, _sep, rest = title.partition("\n")
        _set_source(cells[0], f"# {first[2:].split('·')[0].strip()} · The DH assignment: your own "
                              f"{_spec_name(record)}\n{rest}")
    else:
        notes.append(_("no title cell: the notebook's title was left as in the template"))
    for gid, fix in (("part1_answers", _part1_stub), ("part2_answers", _part2_stub),
                     ("part3_answers", _part3_stub)):
        i = _find(cells, gid)
        new = fix(robot, _source(cells[i])) if i is not None else None
        if new is None:
            notes.append(_("the {cell!r} cell was left as in the template").format(cell=gid))
        else:
            _set_source(cells[i], new)
    name = _spec_name(record)
    for cell in cells:                            # the template's text, said of the student's robot
        if cell.get("cell_type") == "markdown" or _grade_id(cell) == "setup":
            _set_source(cell, _own_robot_text(_source(cell), robot, name))
    cells[where:where] = extra
    nb.setdefault("metadata", {})[V.METADATA_KEY] = record
    return nb, notes


def prepare_submission(nb: dict, variant, student_id: str) -> dict:
    """A copy of ``nb`` whose "Your robot" cell is rewritten from ``variant`` (verified by the
    grader), so whatever the student did to that cell, the kernel builds the right robot."""
    nb = copy.deepcopy(nb)
    cells = nb.setdefault("cells", [])
    seam = _code(SEAM_CELL_ID, seam_source({"variant": variant.to_dict(), "student_id": student_id}), "your_robot")
    found = [i for i, c in enumerate(cells) if c.get("id") == SEAM_CELL_ID or _grade_id(c) == "your_robot"]
    for i in reversed(found[1:]):
        del cells[i]
    if found:
        cells[found[0]] = seam
    else:
        setup = _find(cells, "setup")
        if setup is None:
            setup = next((i for i, c in enumerate(cells) if c.get("cell_type") == "code"), -1)
        cells.insert(setup + 1, seam)
    return nb
