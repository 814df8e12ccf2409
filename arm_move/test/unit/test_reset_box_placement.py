"""reset refuses a RealSense box pose inside the table (or another scene object) or below
the floor, with MoveIt's codes and a message naming the pose and the obstacle, before
anything moves; a box resting on the table is accepted. The overlap test is checked
against pybullet's contact computation for the same boxes (the truth)."""
import math
import os
import sys

import numpy as np
import pybullet as pb
import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from arm_fixtures import load, planner  # noqa: E402

from arm_move.collision import Box  # noqa: E402
from arm_move.kinematics import ARM_JOINTS, FINGER_JOINTS  # noqa: E402
from arm_move.mover import Mover, MoverSettings, Outcome  # noqa: E402
from arm_move.msg import MoveItErrorCodes as Codes  # noqa: E402
from arm_move.scene_config import (PICK_OBJECT, REALSENSE_BOX, TABLE, empty_scene,  # noqa: E402
                                   pick_box, table_box)
from arm_move.srv import ResetRequest  # noqa: E402
from sim_bridge.poses import quaternion_from_rpy  # noqa: E402

SCENE = load("scene.yaml")
BOX_SIZE = SCENE[REALSENSE_BOX]["size"]
HALF_HEIGHT = BOX_SIZE[2] / 2
# the held object's contact tolerance (mover.yaml): how far a box may sink into its support
TOLERANCE = load("mover.yaml")["attached_contact_tolerance"]


@pytest.fixture(scope="module")
def mover():
    arm_planner = planner()
    moving = Mover(MoverSettings(), arm_planner, SCENE, [])
    moving.scene.add(table_box(SCENE))
    moving.scene.add(pick_box(SCENE))
    # the arm in Sleep, gripper open, as the joint states would say
    moving._positions.update(zip(ARM_JOINTS, arm_planner.k.named_poses["sleep"]))
    moving._positions.update({name: arm_planner.k.finger_max for name in FINGER_JOINTS})
    return moving


def reset_request(x, y, z, roll=0.0, pitch=0.0, yaw=0.0):
    request = ResetRequest()
    request.box_pose.position.x, request.box_pose.position.y = x, y
    request.box_pose.position.z = z
    o = request.box_pose.orientation
    o.x, o.y, o.z, o.w = quaternion_from_rpy(roll, pitch, yaw)
    return request


def scene():
    objects = empty_scene(SCENE)
    objects.add(table_box(SCENE))
    objects.add(pick_box(SCENE))
    return objects


@pytest.mark.parametrize("z,what", [(0.0, "half sunk in the table"),
                                    (-0.3, "wholly inside the table")])
def test_a_box_inside_the_table_is_goal_in_collision_naming_pose_and_table(mover, z, what):
    with pytest.raises(Outcome) as refused:
        mover._reset(reset_request(0.16, -0.17, z))
    assert refused.value.code == Codes.GOAL_IN_COLLISION, what
    message = refused.value.message
    assert f"position [0.16, -0.17, {z}]" in message and "orientation [0.0, 0.0, 0.0, 1.0]" \
        in message
    assert f"inside the {TABLE}" in message and "nothing moved" in message
    assert REALSENSE_BOX not in mover.scene.boxes  # the planner's scene is unchanged


def test_a_box_below_the_floor_is_invalid_goal_constraints(mover):
    floor = -SCENE["table_height"]
    # beside the table (its x from -0.2 to 0.6), its bottom 1 cm below the floor
    with pytest.raises(Outcome) as refused:
        mover._reset(reset_request(0.9, 0.0, floor + HALF_HEIGHT - 0.01))
    assert refused.value.code == Codes.INVALID_GOAL_CONSTRAINTS
    assert "below the floor" in refused.value.message and "position [0.9, 0.0," \
        in refused.value.message


def test_a_box_on_the_block_names_the_block(mover):
    block = SCENE[PICK_OBJECT]["position"]
    with pytest.raises(Outcome) as refused:
        mover._reset(reset_request(block[0], block[1], HALF_HEIGHT))
    assert refused.value.code == Codes.GOAL_IN_COLLISION
    assert f"inside the {PICK_OBJECT}" in refused.value.message


def test_a_box_resting_on_the_table_or_on_the_floor_is_free():
    objects = scene()
    resting = [Box.upright(REALSENSE_BOX, (0.16, -0.17, HALF_HEIGHT), BOX_SIZE),
               Box.upright(REALSENSE_BOX, (0.16, -0.17, HALF_HEIGHT - TOLERANCE / 2), BOX_SIZE),
               Box.upright(REALSENSE_BOX, (0.9, 0.0, -SCENE["table_height"] + HALF_HEIGHT),
                           BOX_SIZE),
               # on its side, turned, on the table
               Box(REALSENSE_BOX, (0.2, -0.3, BOX_SIZE[1] / 2),
                   quaternion_from_rpy(math.pi / 2, 0, 0.7), BOX_SIZE)]
    for box in resting:
        assert objects.placement_conflict(box, TOLERANCE) is None, box.center


def pybullet_depth(client, a: Box, b: Box) -> float:
    """How deep two boxes interpenetrate by pybullet (positive: overlap), the truth."""
    bodies = []
    for box in (a, b):
        shape = pb.createCollisionShape(pb.GEOM_BOX, halfExtents=(box.size / 2).tolist(),
                                        physicsClientId=client)
        bodies.append(pb.createMultiBody(0, shape, basePosition=box.center.tolist(),
                                         baseOrientation=list(box.orientation),
                                         physicsClientId=client))
    # distances up to a metre apart are reported, so a miss is a positive distance
    points = pb.getClosestPoints(bodies[0], bodies[1], 1.0, physicsClientId=client)
    for body in bodies:
        pb.removeBody(body, physicsClientId=client)
    return -min(point[8] for point in points) if points else -1.0


def test_the_overlap_test_agrees_with_pybullet_on_random_poses():
    client = pb.connect(pb.DIRECT)
    rng = np.random.default_rng(3)
    table = table_box(SCENE)
    agreed, inside = 0, 0
    try:
        for _ in range(300):
            # poses around the table's top edge and corner, at any orientation
            centre = rng.uniform((0.5, 0.35, -0.1), (0.7, 0.6, 0.1))
            box = Box(REALSENSE_BOX, centre, quaternion_from_rpy(*rng.uniform(-math.pi, math.pi, 3)),
                      BOX_SIZE)
            only_table = empty_scene(SCENE)
            only_table.add(table)
            depth = pybullet_depth(client, box, table)
            if abs(depth - TOLERANCE) < 1e-4:  # too close to the tolerance to call
                continue
            assert (only_table.placement_conflict(box, TOLERANCE) == TABLE) == \
                (depth > TOLERANCE), (centre, depth)
            agreed += 1
            inside += depth > TOLERANCE
    finally:
        pb.disconnect(client)
    # nearly all poses judged, and both answers among them
    assert agreed > 250 and 50 < inside < agreed - 50, (agreed, inside)
