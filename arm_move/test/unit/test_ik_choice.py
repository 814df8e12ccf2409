"""Which IK solution the planner goes to: for targets in front of the arm the waist faces
the target and no plan passes behind the base; between two nearby waypoints the gripper
moves about as far as they are apart. Gripper positions along the trajectories come from
the URDF's own forward kinematics (urdf_tools), not the planner's."""
import math
import os
import sys

import numpy as np
import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from arm_fixtures import PACKAGE, arm_config, planner, table_scene  # noqa: E402

from arm_move.kinematics import ARM_JOINTS  # noqa: E402
from arm_move.planner import random_reachable_targets  # noqa: E402
from urdf_tools.kinematics import link_transform  # noqa: E402
from urdf_tools.model import parse_urdf  # noqa: E402
from urdf_tools.xacro_loader import expand  # noqa: E402

OPEN = 0.037
XACRO = os.path.join(PACKAGE, "urdf", "px100.urdf.xacro")
# the pair of waypoints, 8.1 cm apart either side of the arm's x axis
WAYPOINTS = (np.array([0.262, 0.042, 0.213]), np.array([0.262, -0.039, 0.213]))


@pytest.fixture(scope="module")
def px100():
    return parse_urdf(expand(XACRO), XACRO)


def gripper_points(model, positions):
    """The gripper point at each trajectory point, by the URDF's forward kinematics."""
    return np.array([link_transform(model, "px100/base_link", "px100/ee_gripper_link",
                                    dict(zip(ARM_JOINTS, q)))[:3, 3] for q in positions])


def bearing_error(waist, target):
    bearing = math.atan2(target[1], target[0])
    return abs(math.atan2(math.sin(waist - bearing), math.cos(waist - bearing)))


def front_targets(arm, scene, count):
    return [t for t in random_reachable_targets(arm, scene, 4 * count, OPEN, seed=5)
            if t[0] > 0][:count]


def test_the_waist_faces_targets_in_front_and_plans_stay_in_front_of_the_base(px100):
    arm, scene = planner(), table_scene()
    behind_base = -arm_config()["links"]["base"]["size"][0] / 2  # the base's back face
    start, errors, rearmost = np.zeros(4), [], []
    for target in front_targets(arm, scene, 60):
        plan = arm.plan_to_position(start, OPEN, target, scene)
        assert plan.ok, (target.round(3).tolist(), plan.message)
        assert "faces the target" in plan.message  # the choice is reported
        errors.append(bearing_error(plan.path[-1][0], target))
        points = gripper_points(px100, plan.positions)
        np.testing.assert_allclose(points[-1], target, atol=1e-6)
        rearmost.append(points[:, 0].min())
        start = plan.path[-1]
    print(f"waist off the target's bearing: median {math.degrees(np.median(errors)):.1f} deg, "
          f"largest {math.degrees(max(errors)):.1f} deg; rearmost gripper x "
          f"{min(rearmost):.3f} m")
    assert max(errors) < math.pi / 2
    assert min(rearmost) > behind_base


def test_cycling_two_nearby_waypoints_moves_the_gripper_about_as_far_as_they_are_apart(px100):
    arm, scene = planner(), table_scene()
    apart = float(np.linalg.norm(WAYPOINTS[1] - WAYPOINTS[0]))
    start, per_cycle = np.zeros(4), []
    for _ in range(3):
        travelled = 0.0
        for target in WAYPOINTS:
            plan = arm.plan_to_position(start, OPEN, target, scene)
            assert plan.ok, plan.message
            points = gripper_points(px100, plan.positions)
            travelled += float(np.sum(np.linalg.norm(np.diff(points, axis=0), axis=1)))
            assert points[:, 0].min() > 0.0  # never behind the base
            start = plan.path[-1]
        per_cycle.append(travelled)
    print(f"waypoints {apart:.3f} m apart: the gripper travels "
          f"{', '.join(f'{d:.3f}' for d in per_cycle)} m per cycle")
    # the first cycle starts from Home; the later ones only go back and forth
    assert max(per_cycle[1:]) < 0.3


def test_the_nearest_solution_wins_among_equally_preferred_ones():
    # elbow up and elbow down both reach this target at the first pitch that reaches it
    # at all: the plan ends at the one with less weighted joint travel from where the arm is
    arm, scene = planner(), table_scene()
    target = np.array([0.2, 0.0, 0.15])
    solutions = next(found for found in (
        [np.array(q) for q in arm.k.ik(target, pitch) if arm.faces(np.array([q[0]]), target)[0]]
        for pitch in arm.pitches()) if found)
    assert len(solutions) == 2
    for near in solutions:
        start = near + np.array([0.0, 0.05, -0.05, 0.05])  # close to one of them
        plan = arm.plan_to_position(start, OPEN, target, scene)
        assert plan.ok, plan.message
        np.testing.assert_allclose(plan.path[-1], near, atol=1e-9)


def test_a_target_behind_the_arm_still_turns_the_waist_towards_it():
    arm, scene = planner(), table_scene()
    target = np.array([-0.15, 0.1, 0.12])
    plan = arm.plan_to_position(np.zeros(4), OPEN, target, scene)
    assert plan.ok, plan.message
    assert bearing_error(plan.path[-1][0], target) < math.pi / 2
