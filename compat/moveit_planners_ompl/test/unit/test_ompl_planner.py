"""The OMPL pipeline on the px100 with a scene: joint and position goals planned around
objects, paths checked densely against the scene and the final gripper position against
the URDF's kinematics (urdf_tools, apart from the planner's); MoveIt's codes for goals in
collision, unreachable targets, goals outside the bounds, a start in collision; trajectories
within the joint limits."""
import os

import numpy as np
import pytest
from geometry_msgs.msg import Pose
from moveit_msgs.msg import (CollisionObject, Constraints, JointConstraint, MotionPlanRequest,
                             MoveItErrorCodes as Codes, PositionConstraint)
from shape_msgs.msg import SolidPrimitive

from moveit_core import robot_model
from moveit_core.planning_scene import PlanningScene
from moveit_kinematics.kdl_solver import KdlSolver, SolverSettings
from moveit_planners_ompl.planner import OmplPlanner
from moveit_planners_ompl.planner_configs import PlannerConfigs
from urdf_tools.kinematics import link_transform

DATA = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))), "moveit_core", "test", "data")
ARM = ["waist", "shoulder", "elbow", "wrist_angle"]
TIP = "px100/ee_gripper_link"
LIMITS = {j: {"has_velocity_limits": True, "max_velocity": 2.35,
              "has_acceleration_limits": True, "max_acceleration": 5.0} for j in ARM}
CONFIGS = {"planner_configs": {"RRTConnectkConfigDefault": {"type": "geometric::RRTConnect",
                                                            "range": 0.0}},
           "interbotix_arm": {"default_planner_config": "RRTConnectkConfigDefault"}}


@pytest.fixture
def setup():
    with open(os.path.join(DATA, "px100.urdf"), encoding="utf-8") as urdf, \
            open(os.path.join(DATA, "px100.srdf"), encoding="utf-8") as srdf:
        model = robot_model.load(urdf.read(), srdf.read(), LIMITS)
    scene = PlanningScene(model)
    solver = KdlSolver(model, "interbotix_arm", SolverSettings(position_only_ik=True,
                                                               kinematics_solver_timeout=0.01))
    planner = OmplPlanner(PlannerConfigs(CONFIGS), lambda group: solver)
    return model, scene, planner


def add_box(scene, name, xyz, size):
    message = CollisionObject(id=name, operation=CollisionObject.ADD)
    message.header.frame_id = "world"
    message.pose.position.x, message.pose.position.y, message.pose.position.z = xyz
    message.pose.orientation.w = 1.0
    message.primitives = [SolidPrimitive(type=SolidPrimitive.BOX, dimensions=list(size))]
    message.primitive_poses = [Pose()]
    scene.apply_collision_object(message)


def joint_request(goal, scaling=1.0):
    request = MotionPlanRequest(group_name="interbotix_arm", allowed_planning_time=5.0,
                                max_velocity_scaling_factor=scaling,
                                max_acceleration_scaling_factor=scaling)
    request.goal_constraints = [Constraints(joint_constraints=[
        JointConstraint(joint_name=j, position=v, tolerance_above=1e-4, tolerance_below=1e-4,
                        weight=1.0) for j, v in zip(ARM, goal)])]
    return request


def position_request(xyz, tolerance=1e-4):
    """As moveit_commander's set_position_target writes it: a sphere around the point."""
    constraint = PositionConstraint(link_name=TIP, weight=1.0)
    constraint.header.frame_id = "world"
    constraint.constraint_region.primitives = [SolidPrimitive(type=SolidPrimitive.SPHERE,
                                                              dimensions=[tolerance])]
    pose = Pose()
    pose.position.x, pose.position.y, pose.position.z = xyz
    pose.orientation.w = 1.0
    constraint.constraint_region.primitive_poses = [pose]
    request = MotionPlanRequest(group_name="interbotix_arm", allowed_planning_time=5.0)
    request.goal_constraints = [Constraints(position_constraints=[constraint])]
    return request


def dense_free(scene, result, step=0.005):
    """Every state of the trajectory's segments, at most ``step`` rad apart, is free."""
    positions = result.timed.positions
    for a, b in zip(positions, positions[1:]):
        count = max(1, int(np.ceil(np.max(np.abs(b - a)) / step)))
        for k in range(count + 1):
            state = dict(zip(result.joints, a + (b - a) * k / count))
            if scene.contacts(state, "interbotix_arm"):
                return False
    return True


def test_a_joint_goal_around_a_wall(setup):
    model, scene, planner = setup
    start, goal = [-1.2, 0.3, 0.3, 0.4], [1.2, 0.3, 0.3, 0.4]
    scene.set_state(dict(zip(ARM, start)))
    # a wall in front of the arm: the straight turn of the waist goes through it
    add_box(scene, "wall", (0.2, 0.0, 0.1), (0.05, 0.1, 0.4))
    result = planner.plan(scene, joint_request(goal))
    assert result.code == Codes.SUCCESS, result.message
    np.testing.assert_allclose(result.timed.positions[0], start, atol=1e-9)
    np.testing.assert_allclose(result.timed.positions[-1], goal, atol=1e-4)
    assert dense_free(scene, result)


def test_a_goal_at_the_start_is_sampled_in_its_tolerance_and_timed_strictly(setup):
    """MoveIt's JointConstraintSampler draws each joint within its tolerance band
    (default_constraint_samplers.cpp l. 184-186): a goal equal to the start is not the start
    to the last bit, so the path's times strictly increase (a trajectory controller refuses
    equal ones: the gripper's 'open' when already open refused in the simulation)."""
    model, scene, planner = setup
    here = [0.2, 0.1, -0.1, 0.3]
    scene.set_state(dict(zip(ARM, here)))
    ends = []
    for _ in range(3):
        result = planner.plan(scene, joint_request(here))
        assert result.code == Codes.SUCCESS, result.message
        assert np.all(np.diff(result.timed.times) > 0), result.timed.times
        ends.append(result.timed.positions[-1])
        np.testing.assert_allclose(ends[-1], here, atol=1e-4)
        assert np.any(ends[-1] != here)


def test_a_position_goal_lands_the_gripper_there(setup):
    model, scene, planner = setup
    target = (0.15, 0.1, 0.12)
    result = planner.plan(scene, position_request(target))
    assert result.code == Codes.SUCCESS, result.message
    final = dict(zip(result.joints, result.timed.positions[-1]))
    reached = link_transform(model.urdf, "world", TIP, final)[:3, 3]
    assert np.linalg.norm(reached - target) <= 1e-4


def test_the_trajectory_keeps_the_joint_limits_scaled(setup):
    model, scene, planner = setup
    result = planner.plan(scene, joint_request([1.5, -0.5, 0.8, -0.6], scaling=0.5))
    assert result.code == Codes.SUCCESS, result.message
    times, q = result.timed.times, result.timed.positions
    speeds = np.abs(np.diff(q, axis=0)) / np.diff(times)[:, None]
    assert speeds.max() <= 2.35 * 0.5 + 1e-6
    np.testing.assert_allclose(result.timed.velocities[[0, -1]], 0.0)


def test_a_start_a_hair_outside_its_bounds_does_not_slow_the_motion():
    """Interbotix's px100 in the simulation (two finger joints, no mimic) reports its
    fingers closed, the right one 2e-7 m beyond its limit. As FixStartStateBounds does, the
    start as given leads the path (fix_start_state_bounds.cpp:145-152, 197), and Noetic's
    IPTP times it in seconds: the earlier timing crawled through that point, off the path's
    direction (52 s; a 73 s gripper motion hung the course grader's step)."""
    with open(os.path.join(DATA, "interbotix_px100_gazebo.urdf"), encoding="utf-8") as urdf, \
            open(os.path.join(DATA, "interbotix_px100.srdf"), encoding="utf-8") as srdf:
        model = robot_model.load(urdf.read(), srdf.read(), {
            f: {"has_velocity_limits": True, "max_velocity": 1.0,
                "has_acceleration_limits": True, "max_acceleration": 0.01}
            for f in ("left_finger", "right_finger")})
    scene = PlanningScene(model)
    scene.set_state(dict(model.default_positions(), left_finger=0.014999999999999996,
                         right_finger=-0.014999808756815974))
    configs = {"planner_configs": CONFIGS["planner_configs"],
               "interbotix_gripper": {"default_planner_config": "RRTConnectkConfigDefault"}}
    planner = OmplPlanner(PlannerConfigs(configs), lambda group: None)
    request = MotionPlanRequest(group_name="interbotix_gripper", allowed_planning_time=5.0)
    request.goal_constraints = [Constraints(joint_constraints=[
        JointConstraint(joint_name=j, position=v, tolerance_above=1e-4, tolerance_below=1e-4,
                        weight=1.0) for j, v in (("left_finger", 0.037), ("right_finger", -0.037))])]
    result = planner.plan(scene, request)
    assert result.code == Codes.SUCCESS, result.message
    np.testing.assert_array_equal(result.timed.positions[0], [0.014999999999999996,
                                                              -0.014999808756815974])
    assert result.timed.positions[1][1] == -0.015
    # IPTP on this path: the time the whole opening takes at 0.01 m/s^2 (2.97 s for the
    # ideal triangle) and IPTP's tolerance, not tens of seconds
    assert 2.0 < result.timed.times[-1] < 5.0, result.timed.times[-1]


@pytest.mark.parametrize("case, code", [
    # MoveIt's OMPL context answers every failed solve PLANNING_FAILED (-1); the message
    # (the log's) says why
    ("inside a box", Codes.PLANNING_FAILED),
    ("beyond reach", Codes.PLANNING_FAILED),
    ("joint outside its bounds", Codes.INVALID_GOAL_CONSTRAINTS),
    ("start in collision", Codes.START_STATE_IN_COLLISION),
    ("no group", Codes.INVALID_GROUP_NAME),
    ("no goal", Codes.INVALID_GOAL_CONSTRAINTS),
])
def test_what_cannot_be_planned_gets_its_code(setup, case, code):
    model, scene, planner = setup
    request = position_request((0.15, 0.1, 0.12))
    if case == "inside a box":
        add_box(scene, "box", (0.15, 0.1, 0.12), (0.06, 0.06, 0.06))
    elif case == "beyond reach":
        request = position_request((0.8, 0.0, 0.1))
    elif case == "joint outside its bounds":
        request = joint_request([0.0, 2.5, 0.0, 0.0])
    elif case == "start in collision":
        add_box(scene, "on_the_arm", (0.2, 0.0, 0.2), (0.3, 0.3, 0.15))
    elif case == "no group":
        request.group_name = "arm"
    else:
        request.goal_constraints = []
    result = planner.plan(scene, request)
    assert result.code == code, result.message
    why = {"inside a box": "every goal state collides", "beyond reach": "no IK solution"}
    assert why.get(case, "") in result.message
