"""KDL's IK checked against forward kinematics computed apart from KDL (urdf_tools'
transforms of the URDF): full poses on a 6-joint arm, positions only on the 4-joint px100
(as its movers ask), within the joints' bounds; unreachable targets give no solution within
the timeout."""
import math
import os
import time

import numpy as np
import pytest

from moveit_core import robot_model
from moveit_core.robot_model import RobotModelError
from moveit_kinematics.kdl_solver import KdlSolver, SolverSettings
from urdf_tools.kinematics import link_transform

DATA = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))), "moveit_core", "test", "data")
TRIALS = 200


def load(name):
    with open(os.path.join(DATA, f"{name}.urdf"), encoding="utf-8") as urdf, \
            open(os.path.join(DATA, f"{name}.srdf"), encoding="utf-8") as srdf:
        return robot_model.load(urdf.read(), srdf.read())


def random_state(solver, rng):
    return [rng.uniform(max(b.lower, -math.pi), min(b.upper, math.pi)) for b in solver.bounds]


def truth(model, solver, positions):
    """The tip in the chain's base frame, by urdf_tools (not KDL)."""
    return link_transform(model.urdf, solver.base, solver.tip, solver.state(positions))


def test_kdl_forward_kinematics_equals_the_urdfs():
    model = load("six_axis_arm")
    solver = KdlSolver(model, "manipulator")
    rng = np.random.default_rng(1)
    for _ in range(TRIALS):
        positions = random_state(solver, rng)
        np.testing.assert_allclose(solver.forward(positions), truth(model, solver, positions),
                                   atol=1e-12)


def test_full_pose_ik_on_six_joints():
    model = load("six_axis_arm")
    solver = KdlSolver(model, "manipulator", SolverSettings(kinematics_solver_timeout=0.1),
                       seed=7)
    rng = np.random.default_rng(2)
    solved = 0
    for _ in range(TRIALS):
        target = truth(model, solver, random_state(solver, rng))
        solution = solver.inverse(target, [0.0] * 6)
        if solution is None:
            continue
        solved += 1
        reached = truth(model, solver, solution)
        assert np.linalg.norm(reached[:3, 3] - target[:3, 3]) < 1e-4
        assert np.allclose(reached[:3, :3], target[:3, :3], atol=2e-3)
        assert not model.within_bounds(solver.state(solution))
    assert solved >= 0.95 * TRIALS, f"{solved} of {TRIALS} reachable poses solved"


def test_position_only_ik_on_the_px100():
    model = load("px100")
    solver = KdlSolver(model, "interbotix_arm", SolverSettings(
        kinematics_solver="lma_kinematics_plugin/LMAKinematicsPlugin",
        kinematics_solver_timeout=0.05, position_only_ik=True), seed=5)
    assert solver.joints == ["waist", "shoulder", "elbow", "wrist_angle"]
    rng = np.random.default_rng(4)
    solved = 0
    for _ in range(TRIALS):
        target = truth(model, solver, random_state(solver, rng))
        target[:3, :3] = np.eye(3)          # an orientation the arm cannot take: ignored
        solution = solver.inverse(target, [0.0] * 4)
        if solution is None:
            continue
        solved += 1
        reached = truth(model, solver, solution)
        assert np.linalg.norm(reached[:3, 3] - target[:3, 3]) < 1e-4
        assert not model.within_bounds(solver.state(solution))
    assert solved >= 0.95 * TRIALS, f"{solved} of {TRIALS} reachable positions solved"


def test_an_unreachable_target_has_no_solution_within_the_timeout():
    model = load("px100")
    solver = KdlSolver(model, "interbotix_arm", SolverSettings(position_only_ik=True), seed=1)
    far = np.eye(4)
    far[:3, 3] = (1.0, 0.0, 0.2)            # four times the arm's reach
    started = time.monotonic()
    assert solver.inverse(far, [0.0] * 4, timeout=0.02) is None
    assert time.monotonic() - started < 0.5


def test_a_group_that_is_no_chain_is_refused():
    with pytest.raises(RobotModelError, match="group 'interbotix_gripper' is not a chain"):
        KdlSolver(load("px100"), "interbotix_gripper")
