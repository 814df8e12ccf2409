"""move_group's context from the parameter server's values: what it cannot start without
is named; the kinematics capability answers without a master."""
import os

import pytest
from moveit_msgs.msg import MoveItErrorCodes
from moveit_msgs.srv import GetPositionFKRequest, GetPositionIKRequest

from moveit_ros_move_group import kinematics_service
from moveit_ros_move_group.context import ContextError, from_parameters

DATA = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))), "moveit_core", "test", "data")


def parameters(**values):
    def get_param(name):
        return values[name]
    return get_param


def px100(**overrides):
    with open(os.path.join(DATA, "px100.urdf"), encoding="utf-8") as urdf, \
            open(os.path.join(DATA, "px100.srdf"), encoding="utf-8") as srdf:
        values = {"robot_description": urdf.read(), "robot_description_semantic": srdf.read(),
                  "robot_description_kinematics": {"interbotix_arm": {
                      "kinematics_solver": "kdl_kinematics_plugin/KDLKinematicsPlugin",
                      "position_only_ik": True}}}
    values.update(overrides)
    return {k: v for k, v in values.items() if v is not None}


@pytest.mark.parametrize("missing, said", [
    ("robot_description", "no robot_description: load the robot's URDF"),
    ("robot_description_semantic", "no robot_description_semantic: load the config"),
])
def test_a_missing_description_is_named(missing, said):
    with pytest.raises(ContextError, match=said):
        from_parameters(parameters(**px100(**{missing: None})))


def test_a_broken_srdf_is_named():
    with pytest.raises(ContextError, match="robot model cannot be built: .*not an SRDF"):
        from_parameters(parameters(**px100(robot_description_semantic="<robot")))


def test_fk_and_ik_answer_from_the_current_state():
    context = from_parameters(parameters(**px100()))
    fk = GetPositionFKRequest(fk_link_names=["px100/ee_gripper_link"])
    pose = kinematics_service.compute_fk(context, fk).pose_stamped[0]
    assert pose.header.frame_id == "world"
    # every joint at 0 but the fingers (their bounds' middle): the gripper straight ahead
    assert (pose.pose.position.x, pose.pose.position.z) == pytest.approx((0.2486, 0.1931),
                                                                         abs=0.02)
    ik = GetPositionIKRequest()
    ik.ik_request.group_name = "interbotix_arm"
    ik.ik_request.pose_stamped.pose.position.x = 0.2
    ik.ik_request.pose_stamped.pose.position.z = 0.1
    ik.ik_request.pose_stamped.pose.orientation.w = 1.0
    answer = kinematics_service.compute_ik(context, ik)
    assert answer.error_code.val == MoveItErrorCodes.SUCCESS
    ik.ik_request.pose_stamped.pose.orientation.w = 0.0      # a zero quaternion
    assert kinematics_service.compute_ik(context, ik).error_code.val == \
        MoveItErrorCodes.INVALID_GOAL_CONSTRAINTS


def test_collision_aware_ik_refuses_a_target_inside_an_object():
    """avoid_collisions as MoveIt's: a target inside a box has IK solutions, none of them
    free: NO_IK_SOLUTION; without the flag the colliding solution is the answer; a free
    target is solved either way."""
    from geometry_msgs.msg import Pose
    from moveit_msgs.msg import CollisionObject
    from shape_msgs.msg import SolidPrimitive
    from moveit_core.planning_scene import PlanningScene
    from moveit_ros_move_group.scene_monitor import SceneMonitor

    context = from_parameters(parameters(**px100()))
    monitor = SceneMonitor(PlanningScene(context.model), context.state)
    box = CollisionObject(id="crate", operation=CollisionObject.ADD)
    box.header.frame_id = "world"
    box.primitives = [SolidPrimitive(type=SolidPrimitive.BOX, dimensions=[0.06, 0.06, 0.06])]
    box.primitive_poses = [Pose()]
    box.primitive_poses[0].position.x, box.primitive_poses[0].position.z = 0.2, 0.1
    box.primitive_poses[0].orientation.w = 1.0
    monitor.scene.apply_collision_object(box)

    def ik_to(x, z, avoid):
        request = GetPositionIKRequest()
        request.ik_request.group_name = "interbotix_arm"
        request.ik_request.avoid_collisions = avoid
        request.ik_request.pose_stamped.pose.position.x = x
        request.ik_request.pose_stamped.pose.position.z = z
        request.ik_request.pose_stamped.pose.orientation.w = 1.0
        return kinematics_service.compute_ik(context, request, monitor).error_code.val

    assert ik_to(0.2, 0.1, avoid=True) == MoveItErrorCodes.NO_IK_SOLUTION
    assert ik_to(0.2, 0.1, avoid=False) == MoveItErrorCodes.SUCCESS
    assert ik_to(0.15, 0.25, avoid=True) == MoveItErrorCodes.SUCCESS
