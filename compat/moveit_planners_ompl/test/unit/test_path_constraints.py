"""Path constraints in the OMPL pipeline, on the six-axis Setup-Assistant fixture arm
(test/fixtures/moveit_ws): MoveIt's tutorial case (an OrientationConstraint on the end
effector, 0.1 rad on each axis, 10 s of planning time, from a start that keeps it to a pose
goal that keeps it), joint and position constraints on the path, a start that breaks them
(FixStartStatePathConstraints: a prefix to them, or START_STATE_VIOLATES_PATH_CONSTRAINTS),
and a goal that breaks them. Every waypoint of a returned trajectory is checked by the
URDF's own forward kinematics (urdf_tools) and tf's intrinsic XYZ Euler angles, apart from
the planner's code."""
import math
import os
import time

import numpy as np
import pytest
import yaml
from geometry_msgs.msg import Pose, Quaternion
from moveit_msgs.msg import (CollisionObject, Constraints, JointConstraint, MotionPlanRequest,
                             MoveItErrorCodes as Codes, OrientationConstraint,
                             PositionConstraint)
from shape_msgs.msg import SolidPrimitive
from tf.transformations import euler_from_matrix, quaternion_from_matrix

from moveit_core import robot_model
from moveit_core.planning_scene import PlanningScene
from moveit_kinematics.kdl_solver import KdlSolver, SolverSettings
from moveit_planners_ompl.planner import OmplPlanner
from moveit_planners_ompl.planner_configs import PlannerConfigs
from urdf_tools.kinematics import link_transform

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))))
FIXTURE = os.path.join(ROOT, "test", "fixtures", "moveit_ws", "src")
CONFIG = os.path.join(FIXTURE, "six_axis_arm_moveit_config", "config")
GROUP = "manipulator"
TIP = "tool0"
BASE = "base_link"
# move_group_interface_tutorial.cpp (moveit_tutorials noetic-devel): the orientation
# constraint's tolerances and the planning time it allows
TUTORIAL_TOLERANCE = 0.1
TUTORIAL_PLANNING_TIME = 10.0
GOAL_TOLERANCE = 1e-4          # m, rad: the pose goal's region and orientation tolerance
LIMIT_SECONDS = 30.0           # no test here may take longer
# a pose goal the fixture arm reaches from 'ready' only by turning its wrist along the way
# (the straight joint-space line breaks the orientation constraint: checked below)
GOAL_SHIFT = (-0.2, -0.4, 0.1)
BOX_WIDTH = 0.04               # m: a position constraint's box across the tool's way


@pytest.fixture(autouse=True)
def time_limit():
    """Each test within LIMIT_SECONDS (planning is bounded by allowed_planning_time)."""
    began = time.monotonic()
    yield
    assert time.monotonic() - began < LIMIT_SECONDS


@pytest.fixture(scope="module")
def arm():
    with open(os.path.join(FIXTURE, "six_axis_arm_description", "urdf", "six_axis_arm.urdf"),
              encoding="utf-8") as urdf, \
            open(os.path.join(CONFIG, "six_axis_arm.srdf"), encoding="utf-8") as srdf, \
            open(os.path.join(CONFIG, "joint_limits.yaml"), encoding="utf-8") as limits, \
            open(os.path.join(CONFIG, "ompl_planning.yaml"), encoding="utf-8") as ompl, \
            open(os.path.join(CONFIG, "kinematics.yaml"), encoding="utf-8") as kinematics:
        model = robot_model.load(urdf.read(), srdf.read(), yaml.safe_load(limits)["joint_limits"])
        configs = PlannerConfigs(yaml.safe_load(ompl))
        settings = SolverSettings.from_parameters(yaml.safe_load(kinematics)[GROUP])
    solver = KdlSolver(model, GROUP, settings)
    start = dict(model.default_positions(), **model.named_state(GROUP, "ready"))
    return model, configs, solver, start


def planner_of(arm):
    model, configs, solver, _ = arm
    return OmplPlanner(configs, lambda group: solver), PlanningScene(model)


def fk(model, positions):
    return link_transform(model.urdf, BASE, TIP, positions)


def euler_error(target: np.ndarray, link: np.ndarray) -> np.ndarray:
    """|intrinsic XYZ Euler angles| of the link's rotation relative to the target (tf's
    'rxyz' convention: R = Rx Ry Rz), as MoveIt's OrientationConstraint reads it."""
    relative = np.eye(4)
    relative[:3, :3] = target[:3, :3].T @ link[:3, :3]
    return np.abs(np.array(euler_from_matrix(relative, "rxyz")))


def orientation_constraint(rotation: np.ndarray, tolerance: float) -> OrientationConstraint:
    matrix = np.eye(4)
    matrix[:3, :3] = rotation
    constraint = OrientationConstraint(link_name=TIP, weight=1.0,
                                       orientation=Quaternion(*quaternion_from_matrix(matrix)),
                                       absolute_x_axis_tolerance=tolerance,
                                       absolute_y_axis_tolerance=tolerance,
                                       absolute_z_axis_tolerance=tolerance)
    constraint.header.frame_id = BASE
    return constraint


def box_constraint(center, size) -> PositionConstraint:
    constraint = PositionConstraint(link_name=TIP, weight=1.0)
    constraint.header.frame_id = BASE
    constraint.constraint_region.primitives = [SolidPrimitive(type=SolidPrimitive.BOX,
                                                              dimensions=list(size))]
    pose = Pose()
    pose.position.x, pose.position.y, pose.position.z = center
    pose.orientation.w = 1.0
    constraint.constraint_region.primitive_poses = [pose]
    return constraint


def add_box(scene, name, xyz, size):
    message = CollisionObject(id=name, operation=CollisionObject.ADD)
    message.header.frame_id = BASE
    message.pose.position.x, message.pose.position.y, message.pose.position.z = xyz
    message.pose.orientation.w = 1.0
    message.primitives = [SolidPrimitive(type=SolidPrimitive.BOX, dimensions=list(size))]
    message.primitive_poses = [Pose()]
    scene.apply_collision_object(message)


def pose_goal(target: np.ndarray) -> Constraints:
    """As MoveGroupInterface::setPoseTarget writes it: a small sphere and an orientation."""
    position = PositionConstraint(link_name=TIP, weight=1.0)
    position.header.frame_id = BASE
    position.constraint_region.primitives = [SolidPrimitive(type=SolidPrimitive.SPHERE,
                                                            dimensions=[GOAL_TOLERANCE])]
    pose = Pose()
    pose.position.x, pose.position.y, pose.position.z = target[:3, 3]
    pose.orientation.w = 1.0
    position.constraint_region.primitive_poses = [pose]
    return Constraints(position_constraints=[position],
                       orientation_constraints=[orientation_constraint(target[:3, :3],
                                                                       GOAL_TOLERANCE)])


def request(start, goal: Constraints, path: Constraints,
            seconds=TUTORIAL_PLANNING_TIME) -> MotionPlanRequest:
    message = MotionPlanRequest(group_name=GROUP, allowed_planning_time=seconds,
                                max_velocity_scaling_factor=1.0,
                                max_acceleration_scaling_factor=1.0)
    message.start_state.joint_state.name = list(start)
    message.start_state.joint_state.position = list(start.values())
    message.goal_constraints = [goal]
    message.path_constraints = path
    return message


def waypoints(start, result):
    return [dict(start, **dict(zip(result.joints, p))) for p in result.timed.positions]


def tutorial_case(arm):
    model, _, _, start = arm
    begin = fk(model, start)
    target = begin.copy()
    target[:3, 3] += GOAL_SHIFT
    path = Constraints(orientation_constraints=[orientation_constraint(begin[:3, :3],
                                                                       TUTORIAL_TOLERANCE)])
    return begin, target, path


def test_the_tutorials_orientation_constraint_holds_at_every_waypoint(arm):
    model, _, solver, start = arm
    begin, target, path = tutorial_case(arm)
    planner, scene = planner_of(arm)
    # the straight joint-space line to the goal leaves the constraint: a plan that ignored
    # it would break it (the goal IK solution nearest the start)
    goal_joints = solver.state(solver.inverse(target, [start[j] for j in solver.joints]))
    line = [dict(start, **{j: start[j] + (goal_joints[j] - start[j]) * s for j in goal_joints})
            for s in np.linspace(0.0, 1.0, 50)]
    assert max(euler_error(begin, fk(model, q)).max() for q in line) > TUTORIAL_TOLERANCE
    began = time.monotonic()
    result = planner.plan(scene, request(start, pose_goal(target), path))
    assert result.code == Codes.SUCCESS, result.message
    assert time.monotonic() - began < TUTORIAL_PLANNING_TIME
    states = waypoints(start, result)
    worst = max(euler_error(begin, fk(model, q)).max() for q in states)
    assert worst < TUTORIAL_TOLERANCE, f"a waypoint turned {worst:.4f} rad"
    assert np.linalg.norm(fk(model, states[-1])[:3, 3] - target[:3, 3]) <= GOAL_TOLERANCE
    assert np.allclose([states[0][j] for j in result.joints],
                       [start[j] for j in result.joints])


def test_a_rotation_vector_constraint_holds_too(arm):
    model, _, _, start = arm
    begin, target, path = tutorial_case(arm)
    path.orientation_constraints[0].parameterization = OrientationConstraint.ROTATION_VECTOR
    planner, scene = planner_of(arm)
    result = planner.plan(scene, request(start, pose_goal(target), path))
    assert result.code == Codes.SUCCESS, result.message
    for q in waypoints(start, result):
        relative = begin[:3, :3].T @ fk(model, q)[:3, :3]
        angle = math.acos(max(-1.0, min(1.0, (np.trace(relative) - 1) / 2)))
        # each component of axis * angle is at most the angle; the tolerance bounds each
        axis = np.array([relative[2, 1] - relative[1, 2], relative[0, 2] - relative[2, 0],
                         relative[1, 0] - relative[0, 1]])
        vector = axis / np.linalg.norm(axis) * angle if angle > 1e-9 else np.zeros(3)
        assert np.all(np.abs(vector) < TUTORIAL_TOLERANCE)


def test_joint_path_constraints_hold_at_every_waypoint(arm):
    """A box on the straight line makes the planner search: its detour keeps the held
    joints in their bands."""
    model, _, _, start = arm
    planner, scene = planner_of(arm)
    held = {"wrist_3_joint": 0.05, "shoulder_pan_joint": 0.3}
    path = Constraints(joint_constraints=[
        JointConstraint(joint_name=j, position=start[j], tolerance_above=t, tolerance_below=t,
                        weight=1.0) for j, t in held.items()])
    goal = dict(start, shoulder_pan_joint=start["shoulder_pan_joint"] + 0.25,
                shoulder_lift_joint=-0.6, elbow_joint=1.6, wrist_1_joint=-1.0)
    middle = {j: (start[j] + goal[j]) / 2 for j in goal}
    add_box(scene, "block", fk(model, middle)[:3, 3], (0.1, 0.1, 0.1))
    assert scene.contacts(middle, GROUP)
    goal_set = Constraints(joint_constraints=[
        JointConstraint(joint_name=j, position=goal[j], tolerance_above=GOAL_TOLERANCE,
                        tolerance_below=GOAL_TOLERANCE, weight=1.0)
        for j in model.group(GROUP).variables])
    result = planner.plan(scene, request(start, goal_set, path))
    assert result.code == Codes.SUCCESS, result.message
    for q in waypoints(start, result):
        for joint, tolerance in held.items():
            assert abs(q[joint] - start[joint]) <= tolerance + 1e-12


def test_a_position_path_constraint_keeps_the_tool_in_its_box(arm):
    """A box along the Cartesian segment from the start to the goal, narrower than the
    straight joint-space line's bulge."""
    model, _, solver, start = arm
    begin, target, _ = tutorial_case(arm)
    planner, scene = planner_of(arm)
    along = target[:3, 3] - begin[:3, 3]
    frame = np.eye(4)
    frame[:3, 0] = along / np.linalg.norm(along)
    frame[:3, 1] = np.cross([0.0, 0.0, 1.0], frame[:3, 0])
    frame[:3, 1] /= np.linalg.norm(frame[:3, 1])
    frame[:3, 2] = np.cross(frame[:3, 0], frame[:3, 1])
    frame[:3, 3] = (begin[:3, 3] + target[:3, 3]) / 2
    size = np.array([np.linalg.norm(along) + 0.02, BOX_WIDTH, BOX_WIDTH])
    constraint = box_constraint(frame[:3, 3], size)
    constraint.constraint_region.primitive_poses[0].orientation = Quaternion(
        *quaternion_from_matrix(frame))
    path = Constraints(position_constraints=[constraint])

    def inside(q):
        local = np.linalg.inv(frame) @ fk(model, q)[:, 3]
        return bool(np.all(np.abs(local[:3]) <= size / 2 + 1e-12))

    goal_joints = solver.state(solver.inverse(target, [start[j] for j in solver.joints]))
    line = [dict(start, **{j: start[j] + (goal_joints[j] - start[j]) * s for j in goal_joints})
            for s in np.linspace(0.0, 1.0, 50)]
    assert not all(inside(q) for q in line)
    result = planner.plan(scene, request(start, pose_goal(target), path))
    assert result.code == Codes.SUCCESS, result.message
    assert all(inside(q) for q in waypoints(start, result))


def test_a_start_off_the_constraints_is_first_moved_onto_them(arm):
    """FixStartStatePathConstraints: the plan begins at the start as given, reaches the
    constraints near it (turning the wrist back, the tool still far from the goal) and keeps
    them from there to the goal. (The straight line from that start turns the tool into
    the tolerance only 9 cm before the goal.)"""
    model, _, _, start = arm
    begin, target, path = tutorial_case(arm)
    planner, scene = planner_of(arm)
    off = dict(start, wrist_3_joint=start["wrist_3_joint"] + 0.5)
    assert euler_error(begin, fk(model, off)).max() > TUTORIAL_TOLERANCE
    result = planner.plan(scene, request(off, pose_goal(target), path))
    assert result.code == Codes.SUCCESS, result.message
    errors = [euler_error(begin, fk(model, q)).max() for q in waypoints(off, result)]
    assert errors[0] > TUTORIAL_TOLERANCE
    first_inside = next(i for i, e in enumerate(errors) if e < TUTORIAL_TOLERANCE)
    assert max(errors[first_inside:]) < TUTORIAL_TOLERANCE
    reached = fk(model, waypoints(off, result)[first_inside])[:3, 3]
    assert np.linalg.norm(reached - target[:3, 3]) > np.linalg.norm(GOAL_SHIFT) / 2


def test_a_start_that_cannot_reach_the_constraints_is_refused(arm):
    _, _, _, start = arm
    _, target, _ = tutorial_case(arm)
    planner, scene = planner_of(arm)
    # a box 5 m away: the start is outside and no state of the arm is inside
    path = Constraints(position_constraints=[box_constraint((5.0, 0.0, 0.0), (0.1, 0.1, 0.1))])
    result = planner.plan(scene, request(start, pose_goal(target), path, seconds=1.0))
    assert result.code == Codes.START_STATE_VIOLATES_PATH_CONSTRAINTS, result.message


def test_a_goal_that_breaks_the_constraints_is_not_planned(arm):
    model, _, _, start = arm
    begin, _, path = tutorial_case(arm)
    planner, scene = planner_of(arm)
    goal = dict(start, wrist_3_joint=start["wrist_3_joint"] + 1.0)
    assert euler_error(begin, fk(model, goal)).max() > TUTORIAL_TOLERANCE
    goal_set = Constraints(joint_constraints=[
        JointConstraint(joint_name=j, position=goal[j], tolerance_above=GOAL_TOLERANCE,
                        tolerance_below=GOAL_TOLERANCE, weight=1.0)
        for j in model.group(GROUP).variables])
    result = planner.plan(scene, request(start, goal_set, path, seconds=2.0))
    assert result.code == Codes.PLANNING_FAILED
    assert "path constraints" in result.message
