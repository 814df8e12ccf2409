"""The planning scene knows what the arm can hit: the block (standing, and held by the
gripper once grasped) and the arm itself (every pair of link groups that is not adjacent
and does not touch in a named pose). Truth is the independent pybullet check on the URDF's
own shapes (independent_check.py) and the URDF's forward kinematics (urdf_tools)."""
import math
import os
import subprocess
import sys

import numpy as np
import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from arm_fixtures import PACKAGE, arm_config, planner, table_scene  # noqa: E402
from independent_check import IndependentChecker  # noqa: E402

from arm_move.collision import CHAIN, boxes_overlap, fingers_around  # noqa: E402
from arm_move.kinematics import ARM_JOINTS  # noqa: E402
from arm_move.msg import MoveItErrorCodes as Codes  # noqa: E402
from arm_move.scene_config import PICK_OBJECT  # noqa: E402
from urdf_tools.kinematics import link_transform  # noqa: E402
from urdf_tools.model import parse_urdf  # noqa: E402
from urdf_tools.xacro_loader import expand  # noqa: E402

OPEN, CLOSED = 0.037, 0.015
XACRO = os.path.join(PACKAGE, "urdf", "px100.urdf.xacro")
# found by sampling the joint space: the forearm against the turning shoulder
FOREARM_IN_SHOULDER = np.array([0.6, 0.26, 1.57, 1.7])


@pytest.fixture(scope="module")
def checker(tmp_path_factory):
    path = tmp_path_factory.mktemp("px100") / "px100.urdf"
    path.write_text(subprocess.run(["xacro", XACRO, "fixed_to_world:=false", "gazebo:=false"],
                                   check=True, capture_output=True, text=True).stdout)
    scene = table_scene()
    check = IndependentChecker(str(path), arm_config()["name"], planner().model.self_pairs,
                               list(scene.boxes.values()), scene.floor_z)
    yield check
    check.close()


def test_self_collision_pairs_are_every_non_adjacent_pair_free_in_the_named_poses():
    arm = planner()
    model, poses = arm.model, [np.array(q) for q in arm.k.named_poses.values()]
    adjacent = {frozenset(p) for p in zip(CHAIN, CHAIN[1:])}
    checked = {frozenset(p) for p in model.self_pairs}
    assert not checked & adjacent
    assert {frozenset(("base", "forearm")), frozenset(("base", "hand"))} <= checked
    centres = model.centres(np.array(poses), OPEN)
    waists = np.array(poses)[:, 0]
    for i, a in enumerate(CHAIN):
        for b in CHAIN[i + 2:]:
            if {a, b} <= {"base", "shoulder"}:
                continue  # they stand still together
            touches = model._pair_hits((a, b), centres, waists, -model.padding).any()
            # checked exactly when it does not touch where the arm rests by design
            assert (frozenset((a, b)) in checked) == (not touches), (a, b)
    print("self-collision pairs:", ", ".join(f"{a}-{b}" for a, b in model.self_pairs))


def test_a_goal_where_the_arm_hits_itself_is_goal_in_collision(checker):
    arm, scene = planner(), table_scene()
    # the truth: the URDF's shapes touch there
    assert checker.touches(FOREARM_IN_SHOULDER, OPEN) == "self: shoulder-forearm"
    plan = arm.plan_to_joints(np.zeros(4), OPEN, FOREARM_IN_SHOULDER, scene)
    assert plan.code == Codes.GOAL_IN_COLLISION, plan.message
    assert "itself (shoulder and forearm)" in plan.message


def test_a_target_only_reachable_by_folding_into_the_base_is_refused(checker):
    arm, scene = planner(), table_scene()
    target = np.array([0.0, 0.05, 0.06])  # just beside the shoulder, low
    plan = arm.plan_to_position(np.zeros(4), OPEN, target, scene)
    assert plan.code == Codes.GOAL_IN_COLLISION, plan.message
    assert "itself" in plan.message
    # the truth: the URDF's shapes do fold into each other there (the planner's verdict
    # is conservative: padding and goal margin)
    solutions = list(arm.k.ik_candidates(target, arm.pitches()))
    assert any((checker.touches(q, OPEN) or "").startswith("self") for q in solutions)


def test_a_path_across_the_block_goes_around_it(checker):
    arm, scene = planner(), table_scene()
    block = scene.boxes[PICK_OBJECT]
    bearing, radius = math.atan2(block.center[1], block.center[0]), 0.175
    side = 0.5  # rad either side of the block, low enough to sweep through it
    start_target, target = (np.array([radius * math.cos(bearing + s * side),
                                       radius * math.sin(bearing + s * side), 0.05])
                            for s in (1, -1))
    start = arm.plan_to_position(np.zeros(4), OPEN, start_target, scene).path[-1]
    plan = arm.plan_to_position(start, OPEN, target, scene)
    assert plan.ok, plan.message
    goal = plan.path[-1]
    without = table_scene()
    without.remove(PICK_OBJECT)
    assert not arm.motion_free(start, goal, OPEN, scene)  # the straight way hits the block
    assert arm.motion_free(start, goal, OPEN, without)    # ... and nothing else
    assert checker.first_collision([start, goal], OPEN)[1] == PICK_OBJECT
    clearance = checker.clearance(plan.path, OPEN, PICK_OBJECT)
    print(f"around the block: {len(plan.path)} vertices, least clearance {clearance:.4f} m")
    assert clearance > 0.0
    assert checker.first_collision(plan.path, OPEN) is None


def grasp(arm, scene):
    """The arm around the block (straight down, open), then the block attached."""
    block = scene.boxes[PICK_OBJECT]
    target = block.center + np.array([0.0, 0.0, 0.022])  # as config/waypoints.yaml grasps
    assert fingers_around(block, target, arm.k.finger_max, arm.model.finger_length)
    scene.touch_allowed = PICK_OBJECT  # as the mover does for a grasp's approach
    plan = arm.plan_to_position(np.zeros(4), OPEN, target, scene)
    assert plan.ok, plan.message
    q = plan.path[-1]
    scene.remove(PICK_OBJECT)
    scene.attached = arm.model.attach(PICK_OBJECT, block, q)
    return q, block


def test_a_held_block_moves_with_the_hand_and_is_checked():
    arm, scene = planner(), table_scene()
    q, block = grasp(arm, scene)
    # resting on the table is not a collision: it can be lifted off
    assert arm.model.collision(q, CLOSED, scene, -arm.model.padding) is None
    lifted = arm.plan_to_position(q, CLOSED, arm.k.gripper_point(q) + (0, 0, 0.06), scene)
    assert lifted.ok, lifted.message
    # it follows the URDF's gripper frame: the same pose relative to it everywhere
    model = parse_urdf(expand(XACRO), XACRO)

    def relative(q_):
        hand = link_transform(model, "px100/base_link", "px100/ee_gripper_link",
                              dict(zip(ARM_JOINTS, q_)))
        centre, rotation = arm.model.attached_pose(scene.attached, q_)
        return np.linalg.inv(hand)[:3, :3] @ (centre - hand[:3, 3]), hand[:3, :3].T @ rotation
    np.testing.assert_allclose(arm.model.attached_pose(scene.attached, q)[0], block.center,
                               atol=1e-9)
    for other in (lifted.path[-1], np.array([0.5, 0.2, -0.3, 1.0])):
        for a, b in zip(relative(q), relative(other)):
            np.testing.assert_allclose(a, b, atol=1e-9)
    # a goal that would press it into the table is refused, naming it
    low = arm.plan_to_position(lifted.path[-1], CLOSED, arm.k.gripper_point(q) - (0, 0, 0.01),
                               scene)
    assert low.code == Codes.GOAL_IN_COLLISION, low.message
    assert "pick_object (held) and table" in low.message
    # over the RealSense box where only the gripper would clear it: either refused, naming
    # the held block, or planned with the gripper pitched so that the block clears it
    box = scene.boxes["realsense_box"]
    over = box.center + np.array([0.0, 0.0, box.size[2] / 2 + 0.035])
    into = arm.plan_to_position(lifted.path[-1], CLOSED, over, scene)
    if into.ok:
        centre, rotation = arm.model.attached_pose(scene.attached, into.path[-1])
        assert not boxes_overlap(centre[None], rotation, scene.attached.size / 2,
                                 box.center[None], box.rotation, box.size / 2)[0]
    else:
        assert "pick_object (held) and realsense_box" in into.message
