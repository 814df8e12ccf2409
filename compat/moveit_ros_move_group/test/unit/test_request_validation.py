"""move_group under hostile input, without a master: requests holding NaN or infinity, a
trajectory outside the joint limits, a scene diff that cannot be applied, a goal preempted
before its plan is executed. Each gets MoveIt's code and a message naming the field (the
point, the joint, the limit and the value), nothing is executed, and nothing raises.
Issue 38; the rostest on the px100's fake MoveIt is interbotix_xsarm_moveit's
hostile_requests.test."""
import math
import os

import genpy
import pytest
from geometry_msgs.msg import Pose
from moveit_msgs.msg import (CollisionObject, Constraints, ExecuteTrajectoryGoal,
                             JointConstraint, MotionPlanRequest, MoveGroupGoal,
                             MoveItErrorCodes as Codes, OrientationConstraint,
                             PositionConstraint, RobotTrajectory)
from moveit_msgs.srv import GetMotionPlanRequest
from sensor_msgs.msg import JointState
from shape_msgs.msg import SolidPrimitive
from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint

from moveit_core.planning_scene import PlanningScene
from moveit_planners_ompl.planner import AdapterSettings, OmplPlanner
from moveit_planners_ompl.planner_configs import PlannerConfigs
from moveit_ros_move_group.context import from_parameters
from moveit_ros_move_group.planning_service import Planning
from moveit_ros_move_group.scene_monitor import SceneMonitor

DATA = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))), "moveit_core", "test", "data")
ARM = ["waist", "shoulder", "elbow", "wrist_angle"]
TIP = "px100/ee_gripper_link"
NAN, INF = float("nan"), float("inf")
CONFIGS = {"planner_configs": {"RRTConnectkConfigDefault": {"type": "geometric::RRTConnect",
                                                            "range": 0.0}},
           "interbotix_arm": {"default_planner_config": "RRTConnectkConfigDefault"}}
START_MARGIN = 0.1       # start_state_max_bounds_error


class RecordingExecutor:
    """The trajectory execution manager's place: records what it is asked to execute."""

    def __init__(self):
        self.executed = []

    def execute(self, trajectory, preempted=None):
        self.executed.append(trajectory)
        return Codes.SUCCESS, "executed"

    def stop(self):
        pass


@pytest.fixture(scope="module")
def context():
    with open(os.path.join(DATA, "px100.urdf"), encoding="utf-8") as urdf, \
            open(os.path.join(DATA, "px100.srdf"), encoding="utf-8") as srdf:
        values = {"robot_description": urdf.read(), "robot_description_semantic": srdf.read(),
                  "robot_description_kinematics": {"interbotix_arm": {
                      "kinematics_solver": "kdl_kinematics_plugin/KDLKinematicsPlugin",
                      "kinematics_solver_timeout": 0.01, "position_only_ik": True}}}
    return from_parameters(values.__getitem__)


@pytest.fixture
def planning(context):
    monitor = SceneMonitor(PlanningScene(context.model), context.state)
    planner = OmplPlanner(PlannerConfigs(CONFIGS), context.solver,
                          AdapterSettings(start_state_max_bounds_error=START_MARGIN))
    return Planning(context, monitor, planner, RecordingExecutor())


def pose_goal(x=0.2, y=0.0, z=0.1, plan_only=False):
    goal = MoveGroupGoal()
    goal.request.group_name = "interbotix_arm"
    goal.request.allowed_planning_time = 2.0
    constraint = PositionConstraint(link_name=TIP, weight=1.0)
    constraint.header.frame_id = "world"
    constraint.constraint_region.primitives = [
        SolidPrimitive(type=SolidPrimitive.SPHERE, dimensions=[0.01])]
    region = Pose()
    region.position.x, region.position.y, region.position.z = x, y, z
    region.orientation.w = 1.0
    constraint.constraint_region.primitive_poses = [region]
    goal.request.goal_constraints = [Constraints(position_constraints=[constraint])]
    goal.planning_options.plan_only = plan_only
    return goal


def joint_goal(positions, plan_only=True):
    goal = MoveGroupGoal()
    goal.request.group_name = "interbotix_arm"
    goal.request.allowed_planning_time = 2.0
    goal.request.goal_constraints = [Constraints(joint_constraints=[
        JointConstraint(joint_name=j, position=p, tolerance_above=1e-4, tolerance_below=1e-4,
                        weight=1.0) for j, p in zip(ARM, positions)])]
    goal.planning_options.plan_only = plan_only
    return goal


def trajectory(*points, joints=ARM, seconds=1.0):
    message = JointTrajectory(joint_names=list(joints))
    for index, positions in enumerate(points):
        message.points.append(JointTrajectoryPoint(
            positions=list(positions), time_from_start=genpy.Duration.from_sec(seconds * index)))
    return ExecuteTrajectoryGoal(trajectory=RobotTrajectory(joint_trajectory=message))


REGION = ("request.goal_constraints[0].position_constraints[0].constraint_region"
          ".primitive_poses[0]")


# --- the move_group action and plan_kinematic_path: non-finite goals -------------------

@pytest.mark.parametrize("plan_only", [True, False])
def test_a_nan_region_pose_is_an_invalid_goal_naming_the_field(planning, plan_only):
    """Issue 38: the action aborted with code 0 and a SceneError traceback."""
    result, text = planning.move(pose_goal(x=NAN, plan_only=plan_only))
    assert result.error_code.val == Codes.INVALID_GOAL_CONSTRAINTS
    assert f"{REGION}.position.x is nan" in text
    assert result.planned_trajectory.joint_trajectory.points == []
    assert planning.executor.executed == []


def _break(goal, where):
    """``goal`` with one float of its goal constraints made NaN or infinite."""
    constraints = goal.request.goal_constraints[0]
    if where == "orientation":
        orientation = OrientationConstraint(link_name=TIP, weight=1.0,
                                            absolute_x_axis_tolerance=0.1,
                                            absolute_y_axis_tolerance=0.1,
                                            absolute_z_axis_tolerance=INF)
        orientation.header.frame_id = "world"
        orientation.orientation.w = 1.0
        constraints.orientation_constraints = [orientation]
        return ("request.goal_constraints[0].orientation_constraints[0]"
                ".absolute_z_axis_tolerance is inf")
    position = constraints.position_constraints[0]
    if where == "offset":
        position.target_point_offset.y = -INF
        return "request.goal_constraints[0].position_constraints[0].target_point_offset.y is -inf"
    if where == "quaternion":
        position.constraint_region.primitive_poses[0].orientation.w = NAN
        return f"{REGION}.orientation.w is nan"
    position.constraint_region.primitives[0].dimensions = [NAN]
    return ("request.goal_constraints[0].position_constraints[0].constraint_region"
            ".primitives[0].dimensions[0] is nan")


@pytest.mark.parametrize("where", ["orientation", "offset", "quaternion", "dimensions"])
def test_every_non_finite_goal_value_is_named(planning, where):
    goal = pose_goal(plan_only=True)
    said = _break(goal, where)
    result, text = planning.move(goal)
    assert result.error_code.val == Codes.INVALID_GOAL_CONSTRAINTS
    assert said in text


@pytest.mark.parametrize("field", ["position", "tolerance_above", "tolerance_below"])
def test_a_non_finite_joint_goal_names_the_joint(planning, field):
    goal = joint_goal([0.3, 0.0, 0.0, 0.0])
    setattr(goal.request.goal_constraints[0].joint_constraints[2], field, NAN)
    result, text = planning.move(goal)
    assert result.error_code.val == Codes.INVALID_GOAL_CONSTRAINTS
    assert f"request.goal_constraints[0].joint_constraints[2].{field} is nan" in text
    assert "elbow" in text


def test_plan_kinematic_path_answers_the_same(planning):
    request = GetMotionPlanRequest(motion_plan_request=pose_goal(y=INF).request)
    response = planning.plan_service(request).motion_plan_response
    assert response.error_code.val == Codes.INVALID_GOAL_CONSTRAINTS
    assert response.trajectory.joint_trajectory.points == []


def test_a_non_finite_start_state_is_an_invalid_robot_state_naming_the_joint(planning):
    goal = joint_goal([0.3, 0.0, 0.0, 0.0])
    goal.request.start_state.joint_state = JointState(name=["waist", "elbow"],
                                                      position=[0.0, NAN])
    result, text = planning.move(goal)
    assert result.error_code.val == Codes.INVALID_ROBOT_STATE
    assert "start_state.joint_state.position[1] (joint 'elbow') is nan" in text
    # efforts and velocities are not planned with (a driver may publish NaN there)
    goal.request.start_state.joint_state = JointState(name=["waist", "elbow"],
                                                      position=[0.0, 0.1], effort=[NAN, NAN])
    result, text = planning.move(goal)
    assert result.error_code.val == Codes.SUCCESS, text


def test_a_scene_diff_that_cannot_be_applied_is_refused_naming_the_object(planning):
    """planning_options.planning_scene_diff with a NaN object pose raised SceneError out of
    the capability (a traceback, code 0); now MoveIt's code for a pipeline that failed
    (FAILURE, as move_action_capability.cpp answers an exception) and the object named."""
    goal = joint_goal([0.3, 0.0, 0.0, 0.0])
    crate = CollisionObject(id="crate", operation=CollisionObject.ADD)
    crate.header.frame_id = "world"
    crate.pose.position.x, crate.pose.orientation.w = NAN, 1.0
    crate.primitives = [SolidPrimitive(type=SolidPrimitive.BOX, dimensions=[0.1, 0.1, 0.1])]
    crate.primitive_poses = [Pose()]
    crate.primitive_poses[0].orientation.w = 1.0
    goal.planning_options.planning_scene_diff.is_diff = True
    goal.planning_options.planning_scene_diff.world.collision_objects = [crate]
    result, text = planning.move(goal)
    assert result.error_code.val == Codes.FAILURE
    assert "planning_scene_diff" in text and "crate" in text


def test_a_good_goal_after_the_bad_ones_is_planned_and_executed(planning):
    for bad in (pose_goal(x=NAN), pose_goal(z=INF, plan_only=True)):
        planning.move(bad)
    result, _ = planning.move(joint_goal([0.3, 0.1, 0.0, 0.0], plan_only=False))
    assert result.error_code.val == Codes.SUCCESS
    assert len(planning.executor.executed) == 1


def test_a_goal_preempted_while_it_was_planned_is_not_executed(planning):
    """As MoveIt's PlanExecution (plan_execution.cpp): a preempt heard while planning ends
    the goal PREEMPTED before anything is executed."""
    result, _ = planning.move(joint_goal([0.3, 0.1, 0.0, 0.0], plan_only=False),
                              preempted=lambda: True)
    assert result.error_code.val == Codes.PREEMPTED
    assert planning.executor.executed == []


def test_a_preempt_heard_before_the_execution_began_is_not_lost():
    """The preempt callback's stop may come between the goal's last look and the start
    of its execution, which clears the stop flag: the execution manager asks the goal once
    more when it holds the manager, and executes nothing."""
    from moveit_ros_move_group.execution import ExecutionSettings, TrajectoryExecutionManager

    class NoController:
        controllers = {}

        def start(self, *_):
            raise AssertionError("a preempted goal reached the controllers")
    manager = TrajectoryExecutionManager(NoController(), ExecutionSettings(), None)
    manager.stop()
    code, text = manager.execute(trajectory([0.0] * 4, [0.1] * 4).trajectory.joint_trajectory,
                                 preempted=lambda: True)
    assert code == Codes.PREEMPTED and "nothing was executed" in text


# --- execute_trajectory: non-finite and out-of-limit trajectories ----------------------

def here(planning):
    positions = planning.context.state.positions()
    return [positions[j] for j in ARM]


def test_a_trajectory_holding_nan_is_refused_naming_the_point_and_joint(planning):
    """Issue 38: it was executed and the fake controllers published waist = NaN."""
    start = here(planning)
    code, text = planning.execute_trajectory(trajectory(start, [NAN] + start[1:]))
    assert code == Codes.INVALID_MOTION_PLAN
    assert "trajectory.joint_trajectory.points[1].positions[0] (joint 'waist') is nan" in text
    assert planning.executor.executed == []


@pytest.mark.parametrize("field", ["velocities", "accelerations", "effort"])
def test_non_finite_velocities_accelerations_and_efforts_are_refused(planning, field):
    start = here(planning)
    goal = trajectory(start, [start[0] + 0.1] + start[1:])
    setattr(goal.trajectory.joint_trajectory.points[1], field, [0.0, 0.0, INF, 0.0])
    code, text = planning.execute_trajectory(goal)
    assert code == Codes.INVALID_MOTION_PLAN
    assert f"points[1].{field}[2] (joint 'elbow') is inf" in text
    assert planning.executor.executed == []


def test_a_trajectory_outside_the_joint_limits_is_refused_naming_joint_limit_and_value(
        planning):
    """Issue 38: waist at 50 rad was executed and the fake arm left its limits."""
    start = here(planning)
    code, text = planning.execute_trajectory(trajectory(start, [50.0] + start[1:]))
    assert code == Codes.INVALID_MOTION_PLAN
    assert "points[1]" in text and "'waist'" in text and "50" in text
    assert "3.1416" in text          # the px100 waist's upper limit, pi
    assert planning.executor.executed == []


def test_a_finger_beyond_its_limit_by_a_millimetre_is_refused(planning):
    start = planning.context.state.positions()["left_finger"]
    code, text = planning.execute_trajectory(trajectory([start], [0.038],
                                                        joints=["left_finger"]))
    assert code == Codes.INVALID_MOTION_PLAN
    assert "'left_finger'" in text and "0.0370" in text
    assert planning.executor.executed == []


def test_the_first_point_may_be_where_fix_start_state_bounds_planned_from(planning):
    """A plan from a start a little outside the bounds (within start_state_max_bounds_error)
    begins there, as FixStartStateBounds prefixes it: moveit_commander executes that plan
    through execute_trajectory, so it is not refused; farther out it is."""
    upper = planning.context.model.bounds["waist"].upper
    code, _ = planning.execute_trajectory(trajectory([upper + 0.05, 0.0, 0.0, 0.0],
                                                     [upper - 0.2, 0.0, 0.0, 0.0]))
    assert code == Codes.SUCCESS
    code, text = planning.execute_trajectory(trajectory([upper + 0.2, 0.0, 0.0, 0.0],
                                                        [upper - 0.2, 0.0, 0.0, 0.0]))
    assert code == Codes.INVALID_MOTION_PLAN and "points[0]" in text


def test_a_point_with_too_few_positions_is_refused_as_moveit_validates_it(planning):
    """As TrajectoryExecutionManager::validate ("Wrong trajectory: #joints != #positions"),
    whose refusal the ExecuteTrajectory capability answers CONTROL_FAILED; it raised an
    IndexError here."""
    start = here(planning)
    code, text = planning.execute_trajectory(trajectory(start, start[:3]))
    assert code == Codes.CONTROL_FAILED
    assert "points[1] has 3 positions for 4 joints" in text
    assert planning.executor.executed == []


def test_a_planned_trajectory_is_executed(planning):
    result, _ = planning.move(joint_goal([0.4, -0.2, 0.3, 0.1], plan_only=True))
    assert result.error_code.val == Codes.SUCCESS
    code, _ = planning.execute_trajectory(ExecuteTrajectoryGoal(
        trajectory=result.planned_trajectory))
    assert code == Codes.SUCCESS
    assert len(planning.executor.executed) == 1


# --- the checks themselves -----------------------------------------------------------

def test_non_finite_names_the_first_non_finite_value_by_its_path():
    from moveit_ros_move_group import validation
    request = MotionPlanRequest()
    request.start_state.joint_state = JointState(name=["a", "b"], position=[1.0, 2.0],
                                                 velocity=[0.0, -INF])
    assert validation.non_finite(request, "request") == \
        "request.start_state.joint_state.velocity[1] (joint 'b') is -inf"
    request.start_state.joint_state.velocity = []
    assert validation.non_finite(request, "request") is None
    request.max_velocity_scaling_factor = NAN
    assert validation.non_finite(request, "r") == "r.max_velocity_scaling_factor is nan"
    assert math.isnan(request.max_velocity_scaling_factor)
