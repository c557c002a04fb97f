"""Every verified case of shared/reference/seed_cases.json, against dhlab.

The cases were derived independently (sympy exact + numpy) from the seeds'
formulas; here they are recomputed through dhlab's robots.
"""
from pathlib import Path

import numpy as np
import pytest

import dhlab
from dhlab import ik, robots
from dhlab.transforms import Rz, Tz, dh_matrix, is_rigid, trans
from support.seeddata import DATA, load_cases

CASES = load_cases()
TOL = 1e-9


def robot_for(case):
    """The catalogue robot a case is about, built with the case's own parameters."""
    cid, p = case["id"], dict(case["parameters"])
    if cid.startswith("004_robot1"):
        return robots.robot_no_tan_elemental_1(**p)
    if cid.startswith("004_robot2"):
        return robots.robot_no_tan_elemental_2(l=p["l"], d_max=p.get("d_max", 0.30))
    if cid.startswith("003_geom1"):
        return robots.prr_example(**p)
    if cid.startswith("003_geom2"):
        return robots.rrr_example(**p)
    if cid.startswith("003_6dof"):
        return robots.seed003_6dof(**p)
    if cid.startswith("002_4dof"):
        return robots.seed002_4dof(**p)
    if cid.startswith("002_6dof"):
        return robots.seed002_6dof(**p)
    if cid.startswith("000_SSRMS"):
        return robots.ssrms()
    if cid.startswith("000_exercise_PUMA560"):
        return robots.puma560()
    raise KeyError(cid)


POSE_CASES = [c for c in CASES if "expected_pose" in c and not c["id"].startswith("001_")]


def test_every_case_is_used():
    """No case of the reference file is silently left out."""
    ik_cases = [c for c in CASES if c["id"].startswith("003_PR_ik")]
    thz = [c for c in CASES if c["id"].startswith("001_")]
    assert len(POSE_CASES) + len(ik_cases) + len(thz) == len(CASES) == 42


def test_reference_copy_is_current():
    """dhlab/data/seed_cases.json is the shared reference, byte for byte (when shared/ is beside us)."""
    shared = Path(__file__).resolve().parents[3] / "shared" / "reference" / "seed_cases.json"
    if not shared.exists():
        pytest.skip("shared/ is not beside this checkout")
    assert shared.read_bytes() == (DATA / "seed_cases.json").read_bytes()


@pytest.mark.parametrize("case", POSE_CASES, ids=lambda c: c["id"])
def test_pose(case):
    robot = robot_for(case)
    assert [str(s) for s in robot.q_symbols] == list(case["joint_values"]), "joint names as in the case"
    q = np.array(list(case["joint_values"].values()))
    T = robot.fk(q)
    np.testing.assert_allclose(T, case["expected_pose"], atol=TOL)
    np.testing.assert_allclose(T[:3, 3], case["expected_position"], atol=TOL)
    if "frame_origins" in case:
        np.testing.assert_allclose(robot.frames(q)[:, :3, 3], case["frame_origins"], atol=TOL)
    if "frame_axes_zero" in case:
        F = robot.frames(q)
        for i, axes in enumerate(case["frame_axes_zero"]):
            for k, name in enumerate("xyz"):
                np.testing.assert_allclose(F[i, :3, k], axes[name], atol=TOL, err_msg=f"frame {i} {name}")


@pytest.mark.parametrize("case", [c for c in POSE_CASES if "dh_rows_numeric" in c], ids=lambda c: c["id"])
def test_dh_rows_product(case):
    """The case's numeric DH rows (θ, d, a, α at that configuration), multiplied by dh_matrix."""
    T = np.eye(4)
    for row in case["dh_rows_numeric"]:
        T = T @ dh_matrix(*row)
    expected = case.get("expected_pose_dh_base", case["expected_pose"])
    np.testing.assert_allclose(T, expected, atol=TOL)


@pytest.mark.parametrize("case", [c for c in POSE_CASES if c["id"][:9] in ("003_geom1", "003_geom2")],
                         ids=lambda c: c["id"])
def test_geometric_examples_by_matrices(case):
    """Seed 003's geometric examples by homogeneous matrices reach the same point as the DH tables."""
    p = case["parameters"]
    robot = (robots.prr_example_matrices if case["id"].startswith("003_geom1") else robots.rrr_example_matrices)(**p)
    q = np.array(list(case["joint_values"].values()))
    np.testing.assert_allclose(robot.fk(q)[:3, 3], case["expected_position"], atol=TOL)


@pytest.mark.parametrize("case", [c for c in CASES if c["id"].startswith("003_PR_ik")], ids=lambda c: c["id"])
def test_pr_inverse_kinematics(case):
    robot = robots.pr_mechanism(**case["parameters"])
    x, y = case["target_position"]
    sols = ik.pr_mechanism_ik(robot, x, y)
    assert len(sols) == case["expected_solution_count"], sols.message
    for q, name in zip(sols, "AB"):
        expected = case["expected_solutions"][name]
        np.testing.assert_allclose(q, [expected["q1"], expected["q2"]], atol=TOL)
        np.testing.assert_allclose(robot.fk(q)[:2, 3], [x, y], atol=TOL)
    if not sols:
        assert "no solution" in sols.message and "l2" in sols.message


@pytest.mark.parametrize("case", [c for c in CASES if c["id"].startswith("001_")], ids=lambda c: c["id"])
def test_definir_thz_listing_is_wrong(case):
    """Seed 001's DefinirTHz: the correct THz is Tr(d)·Rz(θ) = Tz(θ, z); the listing's output is not."""
    theta, d = case["joint_values"]["dtheta"], case["parameters"]["d"]
    correct = Tz(theta, d[2])
    np.testing.assert_allclose(correct, case["expected_pose"], atol=TOL)
    np.testing.assert_allclose(trans(*d) @ Rz(theta), correct, atol=TOL)
    listing = np.array(case["listing_001_output"])
    assert not np.allclose(correct, listing, atol=1e-6)
    assert not is_rigid(listing)
    np.testing.assert_allclose(np.linalg.det(listing[:3, :3]), case["listing_001_det_R"], atol=TOL)
    np.testing.assert_allclose(np.linalg.det(listing[:3, :3]), -np.cos(2 * theta), atol=TOL)
    with pytest.raises(dhlab.DHLabError, match="not a proper rigid transform"):
        dhlab.check_rigid(listing, "THz")
