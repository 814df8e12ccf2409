"""The planner against the table scene: random reachable targets, an independent dense
check of every path on pybullet, the error codes the mover documents, repeatability."""
import math
import os
import subprocess
import sys

import numpy as np
import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from arm_fixtures import PACKAGE, arm_config, planner, table_scene  # noqa: E402
from independent_check import IndependentChecker  # noqa: E402

from arm_move.msg import MoveItErrorCodes as Codes  # noqa: E402
from arm_move.planner import random_reachable_targets  # noqa: E402

OPEN = 0.037
TARGETS = 200


@pytest.fixture(scope="module")
def urdf(tmp_path_factory):
    path = tmp_path_factory.mktemp("px100") / "px100.urdf"
    xml = subprocess.run(["xacro", os.path.join(PACKAGE, "urdf", "px100.urdf.xacro"),
                          "fixed_to_world:=false", "gazebo:=false"],
                         check=True, capture_output=True, text=True).stdout
    path.write_text(xml)
    return str(path)


@pytest.fixture(scope="module")
def checker(urdf):
    scene = table_scene()
    config = arm_config()
    check = IndependentChecker(urdf, config["name"], planner().model.self_pairs,
                               list(scene.boxes.values()), scene.floor_z)
    yield check
    check.close()


def test_random_reachable_targets_succeed_and_every_path_passes_the_dense_check(checker):
    arm, scene = planner(), table_scene()
    start = np.zeros(4)
    failures, collisions, seconds = [], [], []
    for target in random_reachable_targets(arm, scene, TARGETS, OPEN):
        plan = arm.plan_to_position(start, OPEN, target, scene)
        seconds.append(plan.planning_seconds)
        if not plan.ok:
            failures.append((target.round(3).tolist(), plan.code, plan.message))
            continue
        assert np.allclose(arm.k.gripper_point(plan.path[-1]), target, atol=1e-6)
        hit = checker.first_collision(plan.path, OPEN)
        if hit:
            collisions.append((target.round(3).tolist(), hit[0].round(3).tolist(), hit[1]))
        start = plan.path[-1]  # the next plan starts where this one ended
    print(f"{TARGETS} targets: {len(failures)} failed; planning median "
          f"{1000 * np.median(seconds):.1f} ms, 95th percentile "
          f"{1000 * np.percentile(seconds, 95):.1f} ms")
    assert len(failures) <= TARGETS // 100, failures
    assert collisions == []


def test_the_dense_check_does_catch_a_path_through_the_table(checker):
    # the checker must be able to fail: a straight swing down through the table
    assert checker.first_collision([np.zeros(4), np.array([0.0, 1.5, 0.5, 0.0])], OPEN)


def test_a_target_inside_the_box_is_goal_in_collision():
    scene = table_scene()
    box = scene.boxes["realsense_box"]
    plan = planner().plan_to_position(np.zeros(4), OPEN, box.center, scene)
    assert plan.code == Codes.GOAL_IN_COLLISION, plan.message
    assert "realsense_box" in plan.message


@pytest.mark.parametrize("target", [(0.5, 0.0, 0.1), (0.0, 0.0, 0.6), (-0.3, 0.3, 0.2)])
def test_a_target_out_of_reach_has_no_ik_solution(target):
    plan = planner().plan_to_position(np.zeros(4), OPEN, target, table_scene())
    assert plan.code == Codes.NO_IK_SOLUTION, plan.message


def test_below_the_floor_and_nan_are_invalid_goal_constraints():
    arm, scene = planner(), table_scene()
    below = arm.plan_to_position(np.zeros(4), OPEN, (0.1, 0.0, -1.0), scene)
    assert below.code == Codes.INVALID_GOAL_CONSTRAINTS and "floor" in below.message
    nan = arm.plan_to_position(np.zeros(4), OPEN, (0.1, float("nan"), 0.1), scene)
    assert nan.code == Codes.INVALID_GOAL_CONSTRAINTS and "finite" in nan.message


def test_a_start_in_collision_is_refused():
    plan = planner().plan_to_position(np.array([0.0, 1.6, 0.6, 0.0]), OPEN, (0.15, 0.0, 0.1),
                                      table_scene())
    assert plan.code == Codes.START_STATE_IN_COLLISION, plan.message


def test_the_search_goes_around_an_obstacle_and_is_repeatable(checker):
    # a wall in front of the arm: from the right of it to the left of it, the straight
    # swing of the waist hits it, and the search has to fold the arm or lift it over
    from arm_move.collision import Box
    scene = table_scene()
    scene.add(Box.upright("wall", (0.16, 0.0, 0.1), (0.02, 0.12, 0.2)))
    arm = planner()
    start = np.array([-1.2, 0.0, 0.0, 0.0])
    goal = np.array(arm.k.ik((0.05, 0.16, 0.08), math.pi / 2)[0])
    assert not arm.motion_free(start, goal, OPEN, scene)
    first = arm.plan_to_joints(start, OPEN, goal, scene)
    second = arm.plan_to_joints(start, OPEN, goal, scene)
    assert first.ok, first.message
    assert len(first.path) == len(second.path)
    assert all(np.allclose(a, b) for a, b in zip(first.path, second.path))
    assert len(first.path) > 2  # not the straight line
    assert checker.first_collision(first.path, OPEN) is None


def test_the_trajectory_keeps_to_the_speed_limit_and_ends_at_rest():
    arm = planner()
    plan = arm.plan_to_position(np.array(arm.k.named_poses["sleep"]), OPEN, (0.0, 0.2, 0.1),
                                table_scene())
    assert plan.ok, plan.message
    speeds = np.abs(np.array(plan.velocities))
    assert speeds.max() <= arm.k.max_speed * arm.settings.velocity_scaling + 1e-9
    assert np.all(np.diff(plan.times) > 0)
    assert np.allclose(plan.velocities[-1], 0) and np.allclose(plan.positions[-1], plan.path[-1])
    # positions follow the velocities: finite differences agree with them on average
    positions, times = np.array(plan.positions), np.array(plan.times)
    moved = np.abs(np.diff(positions, axis=0)).max(axis=1) / np.diff(times)
    assert moved.max() <= arm.k.max_speed * arm.settings.velocity_scaling * 1.05
