"""``MoveGroupCommander``: one group's planning and execution through move_group's ROS
interfaces, as MoveIt's MoveGroupInterface uses them (the ``move_group`` action for plan
and go, ``execute_trajectory`` for execute, ``compute_cartesian_path``,
``attached_collision_object``, ``trajectory_execution_event``); named targets from the SRDF;
the current state from ``joint_states``; IK for a pose given as a joint target solved here,
as MoveIt solves it in the client. Signatures, defaults and return values are Noetic's
(``plan()`` returns ``(success, trajectory, planning_time, error_code)``)."""
from __future__ import annotations

import copy
import math
import random
import time
from typing import Dict, List, Optional

import actionlib
import numpy as np
import rospy
from geometry_msgs.msg import Pose, PoseStamped
from moveit_msgs.msg import (AttachedCollisionObject, CollisionObject, Constraints,
                             ExecuteTrajectoryAction, ExecuteTrajectoryGoal, JointConstraint,
                             MotionPlanRequest, MoveGroupAction, MoveGroupGoal,
                             MoveItErrorCodes, OrientationConstraint, PickupAction,
                             PlaceAction, PlannerInterfaceDescription, PositionConstraint,
                             RobotState, RobotTrajectory)
from moveit_msgs.srv import (GetCartesianPath, GetCartesianPathRequest,
                             QueryPlannerInterfaces)
from sensor_msgs.msg import JointState
from shape_msgs.msg import SolidPrimitive
from std_msgs.msg import String
from tf.transformations import (euler_from_quaternion, quaternion_from_euler,
                                quaternion_matrix)
from trajectory_msgs.msg import JointTrajectory

from moveit_commander import _shared, conversions
from moveit_commander.exception import MoveItCommanderException
from moveit_core.planning_scene import matrix_pose as _matrix_pose
from moveit_core.time_parameterization import joint_trajectory, limits_of, time_path

ACTIONS = (("move_group", MoveGroupAction), ("pickup", PickupAction), ("place", PlaceAction),
           ("execute_trajectory", ExecuteTrajectoryAction))
DEFAULT_PLANNING_TIME = 5.0


def _pose_matrix(pose: Pose) -> np.ndarray:
    o = pose.orientation
    q = np.array([o.x, o.y, o.z, o.w], dtype=float)
    matrix = quaternion_matrix(q / (np.linalg.norm(q) or 1.0))
    matrix[:3, 3] = (pose.position.x, pose.position.y, pose.position.z)
    return matrix


class MoveGroupCommander:
    """Execution of simple commands for a particular group."""

    def __init__(self, name: str, robot_description: str = "robot_description", ns: str = "",
                 wait_for_servers: float = 5.0):
        self._robot = _shared.robot(robot_description, ns)
        self._model = self._robot.model
        self._group = _shared.group_or_raise(self._robot, name)
        self._name, self._ns = name, ns
        self._clients = {}
        self._goal = None      # the handle of the last goal sent (kept: rospy drops its
                               # state machine when the handle is collected)
        deadline = time.monotonic() + wait_for_servers if wait_for_servers > 0 else None
        for action, kind in ACTIONS:   # one deadline for the four, as MoveIt's
            # ActionClient, not SimpleActionClient: see _shared.result_of
            client = actionlib.ActionClient(_shared._name(ns, action), kind)
            if deadline is None:
                connected = client.wait_for_server()
            else:   # (a zero Duration would wait for ever)
                left = max(0.001, deadline - time.monotonic())
                connected = client.wait_for_server(rospy.Duration(left))
            if not connected:
                raise RuntimeError(f"Unable to connect to move_group action server "
                                   f"'{action}' within allotted time ({wait_for_servers:g}s)")
            self._clients[action] = client
        self._events = rospy.Publisher(_shared._name(ns, "trajectory_execution_event"), String,
                                       queue_size=1)
        self._attached = rospy.Publisher(_shared._name(ns, "attached_collision_object"),
                                         AttachedCollisionObject, queue_size=100)
        kinematics = self._robot.kinematics.get(name, {}) or {}
        self._joint_tolerance = float(kinematics.get("goal_joint_tolerance", 1e-4))
        self._position_tolerance = float(kinematics.get("goal_position_tolerance", 1e-4))
        self._orientation_tolerance = float(kinematics.get("goal_orientation_tolerance", 1e-3))
        planning = self._robot.planning
        self._velocity_scaling = float(planning.get("default_velocity_scaling_factor", 0.1))
        self._acceleration_scaling = float(planning.get("default_acceleration_scaling_factor",
                                                        0.1))
        self._planning_time = DEFAULT_PLANNING_TIME
        self._attempts = 1
        self._planner_id = ""
        self._pipeline_id = ""
        self._workspace = None
        self._start_state: Optional[RobotState] = None
        self._path_constraints: Optional[Constraints] = None
        self._trajectory_constraints = None
        self._eef = self._group.tip_link if self._group.is_chain else ""
        self._pose_frame = self._model.model_frame
        self._target_kind = "joint"
        self._joint_target: Dict[str, float] = {
            j: self._model.bounds[j].default() for j in self._group.variables}
        self._pose_targets: Dict[str, List[PoseStamped]] = {}
        self._position_only: Dict[str, bool] = {}
        self._orientation_only: Dict[str, bool] = {}
        self._remembered: Dict[str, List[float]] = {}
        self._replan = False
        self._look = False
        self._solver = None
        self._support_surface = ""

    # --- the group ---------------------------------------------------------------------

    def get_name(self) -> str:
        return self._name

    def get_active_joints(self) -> List[str]:
        return list(self._group.variables)

    def get_joints(self) -> List[str]:
        return list(self._group.joints)

    def get_variable_count(self) -> int:
        return len(self._group.variables)

    def has_end_effector_link(self) -> bool:
        return bool(self._eef)

    def get_end_effector_link(self) -> str:
        return self._eef

    def set_end_effector_link(self, link_name: str) -> None:
        if not self._eef or not link_name:
            raise MoveItCommanderException("Unable to set end effector link")
        self._eef = link_name

    def get_interface_description(self) -> PlannerInterfaceDescription:
        proxy = rospy.ServiceProxy(_shared._name(self._ns, "query_planner_interface"),
                                   QueryPlannerInterfaces)
        try:
            found = proxy().planner_interfaces
        except rospy.ServiceException:
            return PlannerInterfaceDescription()
        return found[0] if found else PlannerInterfaceDescription()

    def get_pose_reference_frame(self) -> str:
        return self._pose_frame

    def set_pose_reference_frame(self, reference_frame: str) -> None:
        self._pose_frame = reference_frame

    def get_planning_frame(self) -> str:
        return self._model.model_frame

    # --- the current state -------------------------------------------------------------

    def get_current_joint_values(self) -> List[float]:
        positions = self._robot.positions()
        return [positions[j] for j in self._group.variables]

    def get_current_state(self) -> RobotState:
        return _shared.state_message(self._robot)

    def get_current_state_bounded(self) -> RobotState:
        state = self.get_current_state()
        state.joint_state.position = [
            self._model.bounds[n].clamp(p) for n, p in zip(state.joint_state.name,
                                                          state.joint_state.position)]
        return state

    def _link_pose(self, positions, link: str) -> np.ndarray:
        poses = self._model.link_poses(positions)
        return poses.get(link, np.eye(4))

    def get_current_pose(self, end_effector_link: str = "") -> PoseStamped:
        link = end_effector_link or self._eef
        if not link:
            raise MoveItCommanderException("There is no end effector to get the pose of")
        stamped = PoseStamped(pose=_matrix_pose(self._link_pose(self._robot.positions(), link)))
        stamped.header.frame_id = self._model.model_frame
        stamped.header.stamp = rospy.Time.now()
        return stamped

    def get_current_rpy(self, end_effector_link: str = "") -> List[float]:
        o = self.get_current_pose(end_effector_link).pose.orientation
        return list(euler_from_quaternion([o.x, o.y, o.z, o.w]))

    def get_random_joint_values(self) -> List[float]:
        return [random.uniform(*self._range(j)) for j in self._group.variables]

    def _range(self, joint: str):
        b = self._model.bounds[joint]
        return (b.lower, b.upper) if b.bounded else (-math.pi, math.pi)

    def get_random_pose(self, end_effector_link: str = "") -> PoseStamped:
        link = end_effector_link or self._eef
        if not link:
            raise MoveItCommanderException("There is no end effector to get the pose of")
        state = dict(self._robot.positions(), **dict(zip(self._group.variables,
                                                         self.get_random_joint_values())))
        stamped = PoseStamped(pose=_matrix_pose(self._link_pose(state, link)))
        stamped.header.frame_id = self._model.model_frame
        return stamped

    def set_start_state_to_current_state(self) -> None:
        self._start_state = None

    def set_start_state(self, msg: RobotState) -> None:
        self._start_state = copy.deepcopy(msg)

    # --- joint targets -----------------------------------------------------------------

    def get_joint_value_target(self) -> List[float]:
        return [self._joint_target[j] for j in self._group.variables]

    def set_joint_value_target(self, arg1, arg2=None, arg3=None) -> None:
        """A joint target from a JointState, a joint name and value(s), a Pose or
        PoseStamped (solved by IK here; ``arg2`` the link, ``arg3`` approximate), a dict,
        or a list of every variable's value."""
        if isinstance(arg1, RobotState):
            arg1 = arg1.joint_state
        if isinstance(arg1, JointState):
            values = dict(zip(arg1.name, arg1.position))
        elif isinstance(arg1, str):
            if arg2 is None:
                raise MoveItCommanderException("Joint value expected when joint name specified")
            values = {arg1: arg2[0] if isinstance(arg2, (list, tuple)) else arg2}
        elif isinstance(arg1, (Pose, PoseStamped)):
            values = self._ik_target(arg1, arg2 or self._eef)
        elif isinstance(arg1, dict):
            values = dict(arg1)
        elif hasattr(arg1, "__iter__"):
            listed = [float(v) for v in arg1]
            if len(listed) != len(self._group.variables):
                raise MoveItCommanderException(
                    f"Expected {len(self._group.variables)} joint values, got {len(listed)}")
            values = dict(zip(self._group.variables, listed))
        else:
            raise MoveItCommanderException(f"Unsupported argument of type {type(arg1)}")
        self._set_joints(values)

    def _set_joints(self, values: Dict[str, float]) -> None:
        for name, value in values.items():
            if name not in self._group.variables:
                raise MoveItCommanderException(f"Error setting joint target: '{name}' is not "
                                               f"a joint of group '{self._name}'")
            bounds = self._model.bounds[name]
            if not math.isfinite(value) or not bounds.contains(value, self._joint_tolerance):
                raise MoveItCommanderException(
                    f"Error setting joint target. Does your IK solver support approximate IK? "
                    f"(joint '{name}' = {value} is outside its bounds {bounds.lower:.4f} to "
                    f"{bounds.upper:.4f})")
        self._joint_target.update({n: float(v) for n, v in values.items()})
        self._target_kind = "joint"

    def _ik_target(self, pose, link: str) -> Dict[str, float]:
        if self._solver is None:
            self._solver = _shared.solver(self._robot, self._name)
        if self._solver is None:
            raise MoveItCommanderException("Error setting joint target. Is the IK solver "
                                           "functional? (no solver for this group)")
        stamped = pose if isinstance(pose, PoseStamped) else PoseStamped(pose=pose)
        positions = self._robot.positions()
        frame = stamped.header.frame_id or self._pose_frame
        target = self._frame(frame, positions) @ _pose_matrix(stamped.pose)
        base = self._link_pose(positions, self._solver.base)
        solution = self._solver.inverse(np.linalg.inv(base) @ target,
                                        [positions[j] for j in self._solver.joints])
        if solution is None:
            raise MoveItCommanderException("Error setting joint target. Is the IK solver "
                                           "functional?")
        return self._solver.state(solution)

    def _frame(self, frame: str, positions) -> np.ndarray:
        if frame in ("", self._model.model_frame, self._model.root_link):
            return np.eye(4)
        poses = self._model.link_poses(positions)
        if frame not in poses:
            raise MoveItCommanderException(f"frame '{frame}' is not a link of the robot")
        return poses[frame]

    def set_named_target(self, name: str) -> None:
        if name in self._remembered:
            self.set_joint_value_target(self._remembered[name])
            return
        try:
            values = self._model.named_state(self._name, name)
        except ValueError:
            raise MoveItCommanderException(f"Unable to set target {name}") from None
        self._set_joints(values)

    def get_named_targets(self) -> List[str]:
        return [s.name for s in self._model.srdf.group_states if s.group == self._name]

    def get_named_target_values(self, target: str) -> Dict[str, float]:
        try:
            return self._model.named_state(self._name, target)
        except ValueError:
            return {}

    def remember_joint_values(self, name: str, values=None) -> None:
        self._remembered[name] = list(values) if values is not None else \
            self.get_current_joint_values()

    def get_remembered_joint_values(self) -> Dict[str, List[float]]:
        return dict(self._remembered)

    def forget_joint_values(self, name: str) -> None:
        self._remembered.pop(name, None)

    def set_random_target(self) -> None:
        self._set_joints(dict(zip(self._group.variables, self.get_random_joint_values())))

    # --- pose targets ------------------------------------------------------------------

    def _stamped(self, pose) -> PoseStamped:
        if isinstance(pose, PoseStamped):
            return copy.deepcopy(pose)
        stamped = PoseStamped()
        stamped.header.frame_id = self._pose_frame
        if isinstance(pose, Pose):
            stamped.pose = copy.deepcopy(pose)
        else:
            stamped.pose = conversions.list_to_pose(pose)
        return stamped

    def _need_eef(self, end_effector_link: str) -> str:
        link = end_effector_link or self._eef
        if not link:
            raise MoveItCommanderException("There is no end effector to set the pose for")
        return link

    def set_pose_target(self, pose, end_effector_link: str = "") -> None:
        link = self._need_eef(end_effector_link)
        self._pose_targets[link] = [self._stamped(pose)]
        self._position_only[link] = self._orientation_only[link] = False
        self._target_kind = "pose"

    def set_pose_targets(self, poses, end_effector_link: str = "") -> None:
        link = self._need_eef(end_effector_link)
        self._pose_targets[link] = [self._stamped(p) for p in poses]
        self._position_only[link] = self._orientation_only[link] = False
        self._target_kind = "pose"

    def _current_target(self, link: str) -> PoseStamped:
        if link in self._pose_targets:
            return self._pose_targets[link][0]
        return self.get_current_pose(link)

    def set_position_target(self, xyz, end_effector_link: str = "") -> None:
        link = self._need_eef(end_effector_link)
        if len(xyz) != 3:
            raise MoveItCommanderException("Expected 3 elements in xyz")
        target = self._current_target(link)
        target.pose.position.x, target.pose.position.y, target.pose.position.z = \
            (float(v) for v in xyz)
        self._pose_targets[link] = [target]
        self._position_only[link], self._orientation_only[link] = True, False
        self._target_kind = "pose"

    def set_orientation_target(self, q, end_effector_link: str = "") -> None:
        link = self._need_eef(end_effector_link)
        if len(q) != 4:
            raise MoveItCommanderException("Expected 4 elements in q: x, y, z, w")
        target = self._current_target(link)
        o = target.pose.orientation
        o.x, o.y, o.z, o.w = (float(v) for v in q)
        self._pose_targets[link] = [target]
        self._orientation_only[link], self._position_only[link] = True, False
        self._target_kind = "pose"

    def set_rpy_target(self, rpy, end_effector_link: str = "") -> None:
        if len(rpy) != 3:
            raise MoveItCommanderException("Expected 3 elements in rpy")
        self.set_orientation_target(list(quaternion_from_euler(*rpy)), end_effector_link)

    def shift_pose_target(self, axis: int, value: float, end_effector_link: str = "") -> None:
        link = self._need_eef(end_effector_link)
        current = self.get_current_pose(link)
        values = conversions.pose_to_list(current.pose)
        rpy = list(euler_from_quaternion(values[3:]))
        pose = values[:3] + rpy
        pose[axis] += value
        self.set_pose_target(pose, link)

    def clear_pose_target(self, end_effector_link: str) -> None:
        self._pose_targets.pop(end_effector_link, None)

    def clear_pose_targets(self) -> None:
        self._pose_targets.clear()
        self._target_kind = "joint"

    # --- settings ----------------------------------------------------------------------

    def get_goal_tolerance(self):
        return (self._joint_tolerance, self._position_tolerance, self._orientation_tolerance)

    def get_goal_joint_tolerance(self) -> float:
        return self._joint_tolerance

    def get_goal_position_tolerance(self) -> float:
        return self._position_tolerance

    def get_goal_orientation_tolerance(self) -> float:
        return self._orientation_tolerance

    def set_goal_tolerance(self, value: float) -> None:
        self._joint_tolerance = self._position_tolerance = self._orientation_tolerance = \
            float(value)

    def set_goal_joint_tolerance(self, value: float) -> None:
        self._joint_tolerance = float(value)

    def set_goal_position_tolerance(self, value: float) -> None:
        self._position_tolerance = float(value)

    def set_goal_orientation_tolerance(self, value: float) -> None:
        self._orientation_tolerance = float(value)

    def allow_looking(self, value: bool) -> None:
        self._look = bool(value)

    def allow_replanning(self, value: bool) -> None:
        self._replan = bool(value)

    def get_known_constraints(self) -> List[str]:
        return []

    def get_path_constraints(self) -> Constraints:
        return copy.deepcopy(self._path_constraints) or Constraints()

    def set_path_constraints(self, value) -> None:
        if value is None:
            self.clear_path_constraints()
        elif isinstance(value, Constraints):
            self._path_constraints = copy.deepcopy(value)
        else:
            raise MoveItCommanderException("Unable to set path constraints "
                                           "(no constraints database here)")

    def clear_path_constraints(self) -> None:
        self._path_constraints = None

    def get_trajectory_constraints(self):
        return copy.deepcopy(self._trajectory_constraints)

    def set_trajectory_constraints(self, value) -> None:
        self._trajectory_constraints = copy.deepcopy(value)

    def clear_trajectory_constraints(self) -> None:
        self._trajectory_constraints = None

    def set_constraints_database(self, host, port) -> None:
        rospy.logwarn("moveit_commander: no constraints database here (warehouse not provided)")

    def set_planning_time(self, seconds: float) -> None:
        if seconds > 0:
            self._planning_time = float(seconds)

    def get_planning_time(self) -> float:
        return self._planning_time

    def set_planning_pipeline_id(self, planning_pipeline: str) -> None:
        if planning_pipeline != self._pipeline_id:
            self._pipeline_id = planning_pipeline
            self._planner_id = ""

    def get_planning_pipeline_id(self) -> str:
        return self._pipeline_id

    def set_planner_id(self, planner_id: str) -> None:
        self._planner_id = planner_id

    def get_planner_id(self) -> str:
        return self._planner_id

    def set_num_planning_attempts(self, num_planning_attempts: int) -> None:
        self._attempts = int(num_planning_attempts)

    def set_workspace(self, ws) -> None:
        if len(ws) == 0:
            self._workspace = None
        elif len(ws) == 4:
            self._workspace = [ws[0], ws[1], 0.0, ws[2], ws[3], 0.0]
        elif len(ws) == 6:
            self._workspace = list(ws)
        else:
            raise MoveItCommanderException("Expected 0, 4 or 6 values in list")

    def set_max_velocity_scaling_factor(self, value: float) -> None:
        if not 0 < value <= 1:
            raise MoveItCommanderException("Expected value in the range from 0 to 1 for "
                                           "scaling factor")
        self._velocity_scaling = float(value)

    def set_max_acceleration_scaling_factor(self, value: float) -> None:
        if not 0 < value <= 1:
            raise MoveItCommanderException("Expected value in the range from 0 to 1 for "
                                           "scaling factor")
        self._acceleration_scaling = float(value)

    # --- requests ----------------------------------------------------------------------

    def _goal_constraints(self) -> List[Constraints]:
        if self._target_kind == "joint" or not self._pose_targets:
            return [Constraints(joint_constraints=[JointConstraint(
                joint_name=j, position=self._joint_target[j],
                tolerance_above=self._joint_tolerance, tolerance_below=self._joint_tolerance,
                weight=1.0) for j in self._group.variables])]
        goals = []
        for link, poses in self._pose_targets.items():
            for stamped in poses:
                constraints = Constraints()
                if not self._orientation_only.get(link):
                    position = PositionConstraint(link_name=link, weight=1.0)
                    position.header = stamped.header
                    position.constraint_region.primitives = [SolidPrimitive(
                        type=SolidPrimitive.SPHERE, dimensions=[self._position_tolerance])]
                    region = Pose(position=stamped.pose.position)
                    region.orientation.w = 1.0
                    position.constraint_region.primitive_poses = [region]
                    constraints.position_constraints.append(position)
                if not self._position_only.get(link):
                    orientation = OrientationConstraint(
                        link_name=link, orientation=stamped.pose.orientation, weight=1.0,
                        absolute_x_axis_tolerance=self._orientation_tolerance,
                        absolute_y_axis_tolerance=self._orientation_tolerance,
                        absolute_z_axis_tolerance=self._orientation_tolerance)
                    orientation.header = stamped.header
                    constraints.orientation_constraints.append(orientation)
                goals.append(constraints)
        return goals

    def construct_motion_plan_request(self) -> MotionPlanRequest:
        request = MotionPlanRequest(
            group_name=self._name, num_planning_attempts=self._attempts,
            max_velocity_scaling_factor=self._velocity_scaling,
            max_acceleration_scaling_factor=self._acceleration_scaling,
            allowed_planning_time=self._planning_time, pipeline_id=self._pipeline_id,
            planner_id=self._planner_id)
        if self._workspace:
            w = request.workspace_parameters
            w.header.frame_id = self._model.model_frame
            (w.min_corner.x, w.min_corner.y, w.min_corner.z, w.max_corner.x, w.max_corner.y,
             w.max_corner.z) = self._workspace
        if self._start_state is not None:
            request.start_state = copy.deepcopy(self._start_state)
        else:
            request.start_state.is_diff = True
        request.goal_constraints = self._goal_constraints()
        if self._path_constraints is not None:
            request.path_constraints = copy.deepcopy(self._path_constraints)
        return request

    def _target_from(self, joints) -> None:
        """go()'s and plan()'s argument as a target."""
        if joints is None:
            return
        if isinstance(joints, JointState):
            self.set_joint_value_target(joints)
        elif isinstance(joints, (Pose, PoseStamped)):
            self.set_pose_target(joints)
        elif isinstance(joints, str) and joints in self._remembered:
            self.set_joint_value_target(self._remembered[joints])
        else:
            self.set_joint_value_target(joints)

    def _send(self, plan_only: bool, wait: bool = True):
        goal = MoveGroupGoal(request=self.construct_motion_plan_request())
        goal.planning_options.plan_only = plan_only
        goal.planning_options.look_around = self._look
        goal.planning_options.replan = self._replan
        goal.planning_options.planning_scene_diff.is_diff = True
        goal.planning_options.planning_scene_diff.robot_state.is_diff = True
        self._goal = self._clients["move_group"].send_goal(goal)
        if not wait:
            return None
        return _shared.result_of(self._goal)

    def go(self, joints=None, wait: bool = True) -> bool:
        """Plans to the target (or ``joints``: a joint target, a Pose, a remembered name)
        and executes it; with ``wait``, blocks and answers whether it succeeded."""
        if isinstance(joints, bool):
            wait, joints = joints, None
        self._target_from(joints)
        result = self._send(plan_only=False, wait=wait)
        if not wait:
            return True
        return result is not None and result.error_code.val == MoveItErrorCodes.SUCCESS

    def plan(self, joints=None):
        """(success, RobotTrajectory, planning_time, MoveItErrorCodes), as Noetic's."""
        self._target_from(joints)
        result = self._send(plan_only=True)
        if result is None:
            error = MoveItErrorCodes(val=MoveItErrorCodes.FAILURE)
            return False, RobotTrajectory(), 0.0, error
        return (result.error_code.val == MoveItErrorCodes.SUCCESS, result.planned_trajectory,
                result.planning_time, result.error_code)

    def compute_cartesian_path(self, waypoints, eef_step, *args, avoid_collisions=True,
                               path_constraints=None, jump_threshold=None):
        """(RobotTrajectory, fraction). Noetic 1.1.16's signature is
        ``(waypoints, eef_step, avoid_collisions=True, path_constraints=None)``; scripts
        written for earlier releases pass ``jump_threshold`` third (a float such as 0.0):
        that is read as the jump threshold (the service checks jumps itself), not as
        avoid_collisions."""
        if args:
            third = args[0]
            if isinstance(third, bool):
                avoid_collisions = third
            else:
                jump_threshold = third
                if len(args) > 1:
                    avoid_collisions = args[1]
            if len(args) > (2 if jump_threshold is not None else 1):
                path_constraints = args[-1]
        request = GetCartesianPathRequest(group_name=self._name, link_name=self._eef,
                                          waypoints=list(waypoints), max_step=float(eef_step),
                                          jump_threshold=float(jump_threshold or 0.0),
                                          avoid_collisions=bool(avoid_collisions))
        request.header.frame_id = self._pose_frame
        request.header.stamp = rospy.Time.now()
        if self._start_state is not None:
            request.start_state = copy.deepcopy(self._start_state)
        else:
            request.start_state.is_diff = True
        if path_constraints is not None:
            request.path_constraints = path_constraints
        proxy = rospy.ServiceProxy(_shared._name(self._ns, "compute_cartesian_path"),
                                   GetCartesianPath)
        try:
            response = proxy(request)
        except rospy.ServiceException as error:
            rospy.logerr("compute_cartesian_path: %s", error)
            return RobotTrajectory(), -1.0
        if response.error_code.val != MoveItErrorCodes.SUCCESS:
            return response.solution, -1.0
        return response.solution, response.fraction

    def execute(self, plan_msg, wait: bool = True) -> bool:
        if isinstance(plan_msg, JointTrajectory):
            plan_msg = RobotTrajectory(joint_trajectory=plan_msg)
        self._goal = self._clients["execute_trajectory"].send_goal(
            ExecuteTrajectoryGoal(trajectory=plan_msg))
        if not wait:
            return True
        result = _shared.result_of(self._goal)
        return result is not None and result.error_code.val == MoveItErrorCodes.SUCCESS

    def stop(self) -> None:
        self._events.publish(String(data="stop"))

    # --- attached objects --------------------------------------------------------------

    def attach_object(self, object_name: str, link_name: str = "", touch_links=None) -> bool:
        link = link_name or self._eef or (self._group.links[0] if self._group.links else "")
        message = AttachedCollisionObject(link_name=link,
                                          touch_links=list(touch_links or [link]))
        message.object.id = object_name
        message.object.operation = CollisionObject.ADD
        self._attached.publish(message)
        return True

    def detach_object(self, name: str = "") -> bool:
        links = [name] if name in self._group.links else \
            (list(self._group.links) if not name else [""])
        for link in links:
            message = AttachedCollisionObject(link_name=link)
            message.object.id = "" if name in self._group.links or not name else name
            message.object.operation = CollisionObject.REMOVE
            self._attached.publish(message)
        return True

    def pick(self, object_name, grasp=None, plan_only=False):
        return self._refused("pickup")

    def place(self, object_name, location=None, plan_only=False):
        return self._refused("place")

    def set_support_surface_name(self, value: str) -> None:
        self._support_surface = value

    def _refused(self, action: str) -> int:
        rospy.logerr("moveit_commander: %s is not provided by this move_group", action)
        return MoveItErrorCodes.FAILURE

    # --- local computations ------------------------------------------------------------

    def retime_trajectory(self, ref_state_in, traj_in, velocity_scaling_factor=1.0,
                          acceleration_scaling_factor=1.0,
                          algorithm="iterative_time_parameterization") -> RobotTrajectory:
        """The trajectory's waypoints timed again (iterative parabolic time
        parameterization, whichever ``algorithm`` is named)."""
        joints = list(traj_in.joint_trajectory.joint_names)
        positions = [p.positions for p in traj_in.joint_trajectory.points]
        velocity, acceleration = limits_of(self._model, joints)
        timed = time_path(positions, velocity, acceleration, velocity_scaling_factor,
                          acceleration_scaling_factor)
        return RobotTrajectory(joint_trajectory=joint_trajectory(timed, joints))

    def get_jacobian_matrix(self, joint_values, reference_point=None) -> np.ndarray:
        """The tip's 6 x n Jacobian in the model frame, by finite differences of the
        forward kinematics."""
        link = self._eef or self._group.tip_link
        base = dict(self._robot.positions(), **dict(zip(self._group.variables, joint_values)))
        offset = np.append(np.asarray(reference_point or [0, 0, 0], dtype=float), 1.0)
        here = self._link_pose(base, link)
        columns = []
        for joint in self._group.variables:
            moved = dict(base, **{joint: base[joint] + 1e-6})
            there = self._link_pose(moved, link)
            linear = ((there @ offset) - (here @ offset))[:3] / 1e-6
            rotation = (there[:3, :3] @ here[:3, :3].T - np.eye(3)) / 1e-6
            columns.append(np.concatenate([linear, [rotation[2, 1], rotation[0, 2],
                                                    rotation[1, 0]]]))
        return np.array(columns).T

    def enforce_bounds(self, robot_state_msg: RobotState) -> RobotState:
        state = copy.deepcopy(robot_state_msg)
        state.joint_state.position = [
            self._model.bounds[n].clamp(p) if n in self._model.bounds else p
            for n, p in zip(state.joint_state.name, state.joint_state.position)]
        return state
