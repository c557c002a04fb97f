"""The family of assignment robots: the PUMA 560 and six other well-known arms.

Every robot of the family is given by its **published standard-DH table** (metres,
degrees), its joint limits, how high its frame 0 sits above the plate it is
mounted on, and the pose it is pictured in. Published numbers are facts: each
:class:`Spec` cites where its table comes from. :func:`dhlab.assignment.model.build`
turns a spec (or a variant of it, :mod:`dhlab.assignment.variants`) into the
:class:`~dhlab.assignment.model.AssignmentRobot` that the assignment and the
grader work with: the joint axes the student is given, the link points of part 2,
and one reference solution. :func:`shown_name` is how every page writes a robot's name.

=================  ======  =====================================================
key                joints  source of the DH table
=================  ======  =====================================================
``puma560``        RRRRRR  Corke, ``mdl_puma560`` (frame 0 at the shoulder)
``stanford``       RRPRRR  Scheinman, Stanford AIM-177 fig. 2.3, via Corke's RTB
``cobra600``       RRPR    Adept Cobra 600 SCARA, Corke's RTB ``Cobra600``
``kr5``            RRRRRR  KUKA KR5 (G. Sinha, IIT Kanpur), Corke's RTB ``KR5``
``irb140``         RRRRRR  ABB IRB 140 data sheet, Corke's RTB ``IRB140``
``ur5``            RRRRRR  Universal Robots' published UR5 parameters, RTB ``UR5``
``lrmate200ic``    RRRRRR  Fanuc LR Mate 200iC, ARTE ``parameters.m`` (UMH)
=================  ======  =====================================================

>>> sorted(FAMILY) == sorted(["puma560", "stanford", "cobra600", "kr5", "irb140", "ur5", "lrmate200ic"])
True
>>> spec("cobra600").kinds
'RRPR'
>>> spec("ur5").rows[1]                    # (kind, θ°, d, a, α°) as published
('R', 0, 0.0, -0.425, 0)
"""
from __future__ import annotations

from dataclasses import dataclass

from ..errors import DHLabError
from ..i18n import N_, _

__all__ = ["Spec", "FAMILY", "DEFAULT", "spec", "family_names", "shown_name", "VARIANT_TAG"]

DEFAULT = "puma560"


@dataclass(frozen=True)
class Spec:
    """One robot of the family, as published.

    ``rows``: per joint ``(kind, θ°, d, a, α°)`` of the standard DH table (metres,
    degrees); for a revolute joint θ is the constant offset added to q, for a
    prismatic one d is (q is the extension itself, as in the Robotics Toolbox).
    ``qlim``: per joint (low, high), degrees or metres. ``home``: the pictured pose
    (the published q, degrees or metres; where the published zero pose dips below the
    plate, this course's choice, said in ``source``). ``floor``: the distance from the mounting
    plate up to frame 0's origin, along joint 1's axis. ``link_names``: links 0…n. ``mounts``:
    how a variant may hang it (a SCARA's tool always points away from its plate's side, so
    hung from a ceiling it would point at it: floor only).
    """
    key: str
    name: str
    source: str
    rows: tuple
    qlim: tuple
    home: tuple
    floor: float
    link_names: tuple
    mounts: tuple = (N_("floor"), N_("ceiling"))

    @property
    def n(self) -> int:
        return len(self.rows)

    @property
    def kinds(self) -> str:
        return "".join(row[0] for row in self.rows)


# Link k is the body that turns with joint k and carries frame k: with the forearm's length in d4,
# link 4 is the forearm (it rolls with joint 4) and link 3 the elbow.
_SIX = (N_("base"), N_("trunk"), N_("upper arm"), N_("elbow"),
        N_("forearm"), N_("wrist"), N_("flange and gripper"))

FAMILY = {s.key: s for s in [
    Spec("puma560", "PUMA 560",
         "P. Corke, Robotics Toolbox, mdl_puma560 (standard DH, metres), with frame 0 at the "
         "shoulder; the pedestal's height 0.67183 m is the toolbox's Puma560 d1. Limits: dhlab.robots.",
         (("R", 0, 0.0, 0.0, 90), ("R", 0, 0.0, 0.4318, 0), ("R", 0, 0.15005, 0.0203, -90),
          ("R", 0, 0.4318, 0.0, 90), ("R", 0, 0.0, 0.0, -90), ("R", 0, 0.0, 0.0, 0)),
         ((-160, 160), (-45, 225), (-225, 45), (-110, 170), (-100, 100), (-266, 266)),
         (0, 0, 0, 0, 0, 0), 0.67183,
         (N_("base (pedestal)"), N_("trunk"), N_("upper arm"), N_("elbow"),
          N_("forearm"), N_("wrist"), N_("gripper"))),
    Spec("stanford", "Stanford arm",
         "V. Scheinman, 'Design of a computer controlled manipulator', Stanford AIM-177 (1969), fig. 2.3, "
         "as in P. Corke's Robotics Toolbox for Python, models/DH/Stanford.py (limits from there too; "
         "the boom slides 12 to 50 inches). The pictured pose (boom level, out 0.5 m) is this course's choice.",
         (("R", 0, 0.412, 0.0, -90), ("R", 0, 0.154, 0.0, 90), ("P", -90, 0.0, 0.0203, 0),
          ("R", 0, 0.0, 0.0, -90), ("R", 0, 0.0, 0.0, 90), ("R", 0, 0.0, 0.0, 0)),
         ((-170, 170), (-170, 170), (0.3048, 1.27), (-170, 170), (-90, 90), (-170, 170)),
         (0, 90, 0.5, 0, 0, 0), 0.0,
         (N_("base"), N_("column"), N_("shoulder"), N_("boom (prismatic)"),
          N_("wrist roll"), N_("wrist"), N_("flange and gripper"))),
    Spec("cobra600", "Adept Cobra 600 (SCARA)",
         "Adept Cobra 600, standard DH as in P. Corke's Robotics Toolbox for Python, models/DH/Cobra600.py "
         "(limits of joints 1-3 from there; joint 4's ±180° is this course's choice, the file gives none). "
         "The pictured pose (quill down 0.1 m) is this course's choice.",
         (("R", 0, 0.387, 0.325, 0), ("R", 0, 0.0, 0.275, 180), ("P", 0, 0.0, 0.0, 0), ("R", 0, 0.0, 0.0, 0)),
         ((-50, 50), (-88, 88), (0.0, 0.21), (-180, 180)),
         (0, 0, 0.1, 0), 0.0,
         (N_("base"), N_("inner link"), N_("outer link"), N_("quill (prismatic)"), N_("tool")), (N_("floor"),)),
    Spec("kr5", "KUKA KR5",
         "KUKA KR5 arc, standard DH by G. Sinha (IIT Kanpur) in P. Corke's Robotics Toolbox for Python, "
         "models/DH/KR5.py (metres; limits from there). Pictured with q3 = -90° (the forearm level; at the "
         "toolbox's zero pose it points into the floor): this course's choice.",
         (("R", 0, 0.4, 0.18, 90), ("R", 0, 0.135, 0.6, 180), ("R", 0, 0.135, 0.12, -90),
          ("R", 0, 0.62, 0.0, 90), ("R", 0, 0.0, 0.0, -90), ("R", 0, 0.0, 0.0, 0)),
         ((-155, 155), (-180, 65), (-110, 170), (-165, 165), (-140, 140), (-180, 180)),
         (0, 0, -90, 0, 0, 0), 0.0, _SIX),
    Spec("irb140", "ABB IRB 140",
         "ABB, 'IRB 140 data sheet'; standard DH as in P. Corke's Robotics Toolbox for Python, "
         "models/DH/IRB140.py (from ARTE's parameters.m; limits from there, joint 6 cut to ±360°). "
         "Pictured with q2 = -90° (upper arm up, forearm level): this course's choice.",
         (("R", 0, 0.352, 0.070, -90), ("R", 0, 0.0, 0.360, 0), ("R", 0, 0.0, 0.0, -90),
          ("R", 0, 0.380, 0.0, 90), ("R", 0, 0.0, 0.0, -90), ("R", 0, 0.065, 0.0, 0)),
         ((-180, 180), (-100, 100), (-220, 60), (-200, 200), (-120, 120), (-360, 360)),
         (0, -90, 0, 0, 0, 0), 0.0, _SIX),
    Spec("ur5", "Universal Robots UR5",
         "Universal Robots, 'Parameters for calculations of kinematics and dynamics' (UR5), as in "
         "P. Corke's Robotics Toolbox for Python, models/DH/UR5.py; every joint turns ±360° (UR data sheet). "
         "Pictured upright, q2 = q4 = -90°: this course's choice.",
         (("R", 0, 0.089459, 0.0, 90), ("R", 0, 0.0, -0.425, 0), ("R", 0, 0.0, -0.39225, 0),
          ("R", 0, 0.10915, 0.0, 90), ("R", 0, 0.09465, 0.0, -90), ("R", 0, 0.0823, 0.0, 0)),
         ((-360, 360),) * 6,
         (0, -90, 0, -90, 0, 0), 0.0,
         (N_("base"), N_("shoulder"), N_("upper arm"), N_("forearm"),
          N_("wrist 1"), N_("wrist 2"), N_("wrist 3 and gripper"))),
    Spec("lrmate200ic", "Fanuc LR Mate 200iC",
         "FANUC LR Mate 200iC, standard DH from ARTE (A Robotics Toolbox for Education, Univ. Miguel "
         "Hernández), robots/FANUC/LR_MATE_200iC/parameters.m (metres; limits from there).",
         (("R", 0, 0.33, 0.075, -90), ("R", -90, 0.0, 0.300, 0), ("R", 0, 0.0, 0.075, -90),
          ("R", 0, 0.320, 0.0, 90), ("R", 0, 0.0, 0.0, -90), ("R", 0, 0.08, 0.0, 0)),
         ((-155, 155), (-180, 120), (-150, 150), (-350, 350), (-130, 110), (-360, 360)),
         (0, 0, 0, 0, 0, 0), 0.0, _SIX),
]}


def family_names() -> list:
    """The keys of the family, the default (the PUMA 560, the seed's exercise) first."""
    return [DEFAULT] + sorted(k for k in FAMILY if k != DEFAULT)


def spec(key: str) -> Spec:
    """The published robot ``key`` (see :data:`FAMILY`); a clear error for an unknown key."""
    if key not in FAMILY:
        raise DHLabError(_("no robot {key} in the assignment family: choose one of {names}.").format(
            key=repr(key), names=", ".join(family_names())))
    return FAMILY[key]


VARIANT_TAG = " · variant "     # between the family's name and the fingerprint of a variant's robot


def shown_name(name: str) -> str:
    """A robot's name as its reader's language writes it: a variant's name
    (:func:`dhlab.assignment.variants.robot_of_variant`) stays English inside, since robots are
    cached and shared by threads grading in different languages; only its tag is translated.

    >>> shown_name("UR5 · variant 49540b")
    'UR5 · variant 49540b'
    """
    return name.replace(VARIANT_TAG, _(" · variant "))
