"""``position_controllers/JointTrajectoryController`` and its effort and velocity kin.

As ros_controllers' joint_trajectory_controller:

- parameters: ``joints`` (required); ``gains/<joint>`` (p, i, d, i_clamp, antiwindup;
  effort and velocity kinds, control_toolbox's PID, see :mod:`.pid`); ``velocity_ff/<joint>``
  (0; effort and velocity kinds); ``constraints``: ``goal_time`` (0), ``stopped_velocity_tolerance``
  (0.01), ``<joint>/goal`` and ``<joint>/trajectory`` (0: not checked); ``state_publish_rate``
  (50 Hz), ``action_monitor_rate`` (20 Hz); ``allow_partial_joints_goal`` (false);
- ``<name>/command`` (trajectory_msgs/JointTrajectory), ``<name>/follow_joint_trajectory``
  (control_msgs/FollowJointTrajectory), ``<name>/state``
  (control_msgs/JointTrajectoryControllerState);
- a new trajectory replaces the current one from now on and cancels an active goal; a
  goal succeeds once its last point's time has passed with every joint inside its goal
  tolerance, and aborts if that has not happened ``goal_time`` later, or as soon as a
  joint leaves its path tolerance; cancelling holds the joints where they are;
- as Noetic's initJointTrajectory (ros_controllers noetic-devel 678b92a
  joint_trajectory_controller/include/joint_trajectory_controller/init_joint_trajectory.h,
  "init" below): times must increase strictly (init:232-239); the points at or before the
  next update are dropped (init:321-363; a first point at time_from_start 0 without a stamp
  is one), and a trajectory left with none is refused with Noetic's "Dropping all N
  trajectory point(s), …" (init:336-342); a continuous joint's new trajectory is shifted by
  whole turns to start within pi of its current position (init:431-440,
  joint_trajectory_segment.h:222-243);
- the position error of a revolute or continuous joint is the shortest angle from the actual
  to the desired position (joint_trajectory_controller_impl.h:782); a prismatic joint's is
  the difference (Noetic wraps it too, a known fault: ros_controllers issue #432, its Noetic
  fix #623 unmerged; not copied);
- an invalid trajectory (wrong joints, wrong lengths, NaN) is refused with
  INVALID_JOINTS or INVALID_GOAL and a message saying why; the controller keeps going.
  OLD_HEADER_TIMESTAMP is never returned (no Noetic code does).

Output: position kind, the desired position; velocity and effort kinds,
``velocity_ff``·(desired velocity) + PID(position error, velocity error) (ros_controllers
noetic-devel 678b92a joint_trajectory_controller/include/joint_trajectory_controller/
hardware_interface_adapter.h:170-175, :210; the PIDs reset when the controller starts,
:180-190).
"""
from __future__ import annotations

import math
from typing import List, Optional

import numpy as np
from control_msgs.msg import (FollowJointTrajectoryAction, FollowJointTrajectoryFeedback,
                              FollowJointTrajectoryResult, JointTrajectoryControllerState)
from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint

from sim_bridge.plugins.base import PluginError, Rate, stamp
from sim_bridge.ros_control.controller_base import Controller
from sim_bridge.ros_control.pid import Pid
from sim_bridge.trajectory import Trajectory, Waypoint

# initJointTrajectory's refusal of a point whose sizes do not agree (init:395-397, :477-488),
# the goal's error_string (impl:548-552, :630-634)
SIZE_MISMATCH = "Size mismatch in trajectory point position, velocity or acceleration data."

Result = FollowJointTrajectoryResult


class TrajectoryRefused(ValueError):
    def __init__(self, code: int, text: str):
        super().__init__(text)
        self.code = code


class JointTrajectoryController(Controller):
    def __init__(self, name, params, hardware, io):
        super().__init__(name, params, hardware, io)
        joints = self.required("joints")
        if not isinstance(joints, list) or not joints:
            raise PluginError(f"controller '{name}': 'joints' must be a list of joint names")
        self.claim([str(j) for j in joints])
        self.allow_partial = bool(self.params.get("allow_partial_joints_goal", False))
        constraints = self.params.get("constraints", {}) or {}
        self.goal_time = float(constraints.get("goal_time", 0.0))
        self.stopped_velocity = float(constraints.get("stopped_velocity_tolerance", 0.01))
        self.default_goal = np.array([float((constraints.get(j) or {}).get("goal", 0.0))
                                      for j in self.joints])
        self.default_path = np.array([float((constraints.get(j) or {}).get("trajectory", 0.0))
                                      for j in self.joints])
        self.pids: Optional[List[Pid]] = None
        self.velocity_ff = np.zeros(len(self.joints))
        if self.interface in ("effort", "velocity"):
            gains = self.params.get("gains", {}) or {}
            self.pids = [Pid(gains.get(j, {}), f"controller '{name}' joint '{j}' "
                                               f"(parameter gains/{j})") for j in self.joints]
            # controller_nh.param("velocity_ff/<joint>", ..., 0.0) (hia:170-175)
            feed_forward = self.params.get("velocity_ff", {}) or {}
            for k, joint in enumerate(self.joints):
                value = feed_forward.get(joint, 0.0) if isinstance(feed_forward, dict) else 0.0
                if isinstance(value, (int, float)) and not isinstance(value, bool):
                    self.velocity_ff[k] = float(value)
        self.state_rate = Rate(self.number("state_publish_rate", 50.0))
        self.feedback_rate = Rate(self.number("action_monitor_rate", 20.0))
        bus = io.bus
        self.state_out = bus.publisher(io.topic(f"{name}/state"), JointTrajectoryControllerState,
                                       queue_size=1)
        self._subscription = bus.subscriber(io.topic(f"{name}/command"), JointTrajectory,
                                            self._on_command)
        self._server = bus.action_server(io.topic(f"{name}/follow_joint_trajectory"),
                                         FollowJointTrajectoryAction, self._on_goal,
                                         self._on_cancel)
        self.trajectory: Optional[Trajectory] = None
        self.goal = None  # the active actionlib goal handle
        self.goal_tolerance = self.default_goal
        self.path_tolerance = self.default_path
        self.goal_time_tolerance = self.goal_time
        self._pending: Optional[JointTrajectory] = None
        self.now_ns = 0
        self.period_ns = int(round(hardware.step_size * 1e9))
        types = [hardware.joints[j].joint_type for j in self.joints]
        # angle_wraparound_ (impl:268-269); the error wraps for revolute joints too (impl:782)
        self.wraparound = np.array([t == "continuous" for t in types])
        self.angular = np.array([t in ("continuous", "revolute") for t in types])

    # --- incoming trajectories ------------------------------------------------------------
    def _on_command(self, message: JointTrajectory) -> None:
        """rospy's thread: keep it for the next update (a topic command cancels a goal)."""
        self._pending = message

    def _on_goal(self, handle) -> None:
        """Physics thread (posted by the bus)."""
        goal = handle.get_goal()
        try:
            trajectory = self._build(goal.trajectory, self.now_ns)
        except TrajectoryRefused as refusal:
            self.io.bus.warn(f"{self.name}: goal refused: {refusal}")
            handle.set_rejected(Result(error_code=refusal.code, error_string=str(refusal)),
                                str(refusal))
            return
        self._cancel_active("replaced by a new goal")
        handle.set_accepted()
        self.goal = handle
        self.goal_tolerance = self._tolerances(goal.goal_tolerance, self.default_goal)
        self.path_tolerance = self._tolerances(goal.path_tolerance, self.default_path)
        requested = goal.goal_time_tolerance.to_sec()
        self.goal_time_tolerance = requested if requested > 0 else self.goal_time
        self.trajectory = trajectory

    def _on_cancel(self, handle) -> None:
        if self.goal is not None and handle.get_goal_id().id == self.goal.get_goal_id().id:
            self._hold(self.now_ns)
            self.goal.set_canceled(Result(error_code=Result.SUCCESSFUL,
                                          error_string="cancelled"), "cancelled")
            self.goal = None

    def _cancel_active(self, why: str) -> None:
        if self.goal is not None:
            self.goal.set_canceled(Result(error_code=Result.SUCCESSFUL, error_string=why), why)
            self.goal = None

    def _tolerances(self, given, defaults: np.ndarray) -> np.ndarray:
        tolerances = defaults.copy()
        for tolerance in given:
            if tolerance.name in self.joints and tolerance.position != 0:
                tolerances[self.joints.index(tolerance.name)] = \
                    tolerance.position if tolerance.position > 0 else 0.0
        return tolerances

    def _build(self, message: JointTrajectory, now_ns: int) -> Trajectory:
        """initJointTrajectory, with ``now_ns`` the last update: the trajectory is taken at
        the next one (impl:508-509, :538)."""
        names = list(message.joint_names)
        unknown = [n for n in names if n not in self.joints]
        if unknown or len(set(names)) != len(names):
            raise TrajectoryRefused(Result.INVALID_JOINTS,
                                    f"joints {names} do not match the controller's {self.joints}")
        if not self.allow_partial and set(names) != set(self.joints):
            raise TrajectoryRefused(Result.INVALID_JOINTS,
                                    f"the goal names {names}; this controller needs all of "
                                    f"{self.joints} (allow_partial_joints_goal is false)")
        order = [names.index(j) if j in names else None for j in self.joints]
        positions, velocities, _ = self._current()
        times = [p.time_from_start.to_nsec() for p in message.points]
        if any(a >= b for a, b in zip(times, times[1:])):  # init:232-239, msg:119-134
            raise TrajectoryRefused(Result.INVALID_GOAL, "Trajectory message contains "
                                    "waypoints that are not strictly increasing in time.")
        next_ns = now_ns + self.period_ns
        start_ns = message.header.stamp.to_nsec() or next_ns  # msg:69-73
        kept = {k for k, t in enumerate(times) if start_ns + t > next_ns}  # msg:150-166
        if times and not kept:  # init:333-343
            past = (next_ns - (start_ns + times[-1])) / 1e9
            raise TrajectoryRefused(Result.INVALID_GOAL, (
                f"Dropping all {len(times)} trajectory point(s), as they occur before the "
                f"current time.\nLast point is {past:f}s in the past."))
        points = []
        for number, point in enumerate(message.points):
            if number not in kept:
                continue
            for field in ("positions", "velocities", "accelerations"):
                values = getattr(point, field)
                if values and len(values) != len(names):  # init:395-397, :477-488
                    raise TrajectoryRefused(Result.INVALID_GOAL, SIZE_MISMATCH)
                if values and not all(math.isfinite(v) for v in values):
                    raise TrajectoryRefused(Result.INVALID_GOAL,
                                            f"point {number} has a {field[:-1]} that is not finite")
            if not point.positions:
                raise TrajectoryRefused(Result.INVALID_GOAL, f"point {number} has no positions")
            points.append(Waypoint(
                (start_ns + point.time_from_start.to_nsec()) / 1e9,
                self._full(point.positions, order, positions),
                self._full(point.velocities, order, np.zeros(len(self.joints)))
                if point.velocities else None,
                self._full(point.accelerations, order, np.zeros(len(self.joints)))
                if point.accelerations else None))
        if points:  # the wraparound offset of continuous joints (init:431-440)
            offset = np.where(self.wraparound,
                              wraparound_offset(positions, points[0].positions), 0.0)
            for point in points:
                point.positions = point.positions + offset
        return Trajectory(Waypoint(now_ns / 1e9, positions, velocities, np.zeros_like(positions)),
                          points)

    def _error(self, desired: np.ndarray, actual: np.ndarray) -> np.ndarray:
        """state_error_.position (impl:782): shortest_angular_distance(actual, desired) for
        revolute and continuous joints; the difference for prismatic ones."""
        return np.where(self.angular, shortest_angular_distance(actual, desired),
                        desired - actual)

    @staticmethod
    def _full(values, order, fallback) -> np.ndarray:
        return np.array([values[i] if i is not None else fallback[k]
                         for k, i in enumerate(order)], dtype=float)

    # --- the control loop -----------------------------------------------------------------
    def _current(self):
        indices = [self.hardware.names.index(j) for j in self.joints]
        return (self.hardware.positions[indices].copy(), self.hardware.velocities[indices].copy(),
                self.hardware.efforts[indices].copy())

    def _hold(self, now_ns: int) -> None:
        positions, _, _ = self._current()
        self.trajectory = Trajectory(Waypoint(now_ns / 1e9, positions), [])

    def start(self, now_ns):
        self.now_ns = now_ns
        self._hold(now_ns)
        for pid in self.pids or []:  # hia:180-190
            pid.reset()
        self.state_rate.reset(now_ns)
        self.feedback_rate.reset(now_ns)

    def stop(self, now_ns):
        self._cancel_active("the controller was stopped")

    def update(self, now_ns, dt):
        self.now_ns = now_ns
        self.period_ns = int(round(dt * 1e9))
        if self._pending is not None:
            message, self._pending = self._pending, None
            try:
                self.trajectory = self._build(message, now_ns)
                self._cancel_active("replaced by a trajectory on the command topic")
                self.goal_tolerance, self.path_tolerance = self.default_goal, self.default_path
            except TrajectoryRefused as refusal:
                self.io.bus.warn(f"{self.name}/command: trajectory ignored: {refusal}")
        t = now_ns / 1e9
        desired, desired_velocity, _ = self.trajectory.sample(t)
        actual, actual_velocity, _ = self._current()
        error = self._error(desired, actual)
        self._command(desired, desired_velocity, error, desired_velocity - actual_velocity, dt)
        if self.goal is not None:
            self._monitor(t, error, actual_velocity, desired, desired_velocity, actual)
        if self.state_rate.due(now_ns):
            self.state_out.publish(self._state(JointTrajectoryControllerState, now_ns, desired,
                                               desired_velocity, actual, actual_velocity))

    def _command(self, desired, desired_velocity, error, velocity_error, dt):
        for k, joint in enumerate(self.joints):
            handle = self.hardware.joints[joint]
            if self.interface == "position":
                handle.command = float(desired[k])
            else:  # hia:210
                handle.command = float(self.velocity_ff[k] * desired_velocity[k] +
                                       self.pids[k].command(error[k], velocity_error[k], dt))

    def _monitor(self, t, error, actual_velocity, desired, desired_velocity, actual):
        path = self.path_tolerance
        outside_path = (path > 0) & (np.abs(error) > path)
        if np.any(outside_path):
            joint = self.joints[int(np.argmax(outside_path))]
            text = f"joint '{joint}' left its path tolerance"
            self._hold(self.now_ns)
            self.goal.set_aborted(Result(error_code=Result.PATH_TOLERANCE_VIOLATED,
                                         error_string=text), text)
            self.goal = None
            return
        if self.feedback_rate.due(self.now_ns):
            self.goal.publish_feedback(self._state(FollowJointTrajectoryFeedback, self.now_ns,
                                                   desired, desired_velocity, actual,
                                                   actual_velocity))
        end = self.trajectory.end_time
        if t < end:
            return
        goal = self.goal_tolerance
        final_error = self._error(self.trajectory.goal, actual)
        inside = np.all((goal <= 0) | (np.abs(final_error) <= goal))
        stopped = self.stopped_velocity <= 0 or np.all(np.abs(actual_velocity) <=
                                                       self.stopped_velocity)
        if inside and stopped:
            self.goal.set_succeeded(Result(error_code=Result.SUCCESSFUL), "goal reached")
            self.goal = None
        elif t > end + self.goal_time_tolerance:
            worst = self.joints[int(np.argmax(np.abs(final_error)))]
            text = (f"joint '{worst}' is {float(np.max(np.abs(final_error))):.4f} from its goal "
                    f"{self.goal_time_tolerance:g} s after the trajectory's end")
            self.goal.set_aborted(Result(error_code=Result.GOAL_TOLERANCE_VIOLATED,
                                         error_string=text), text)
            self.goal = None

    def _state(self, message_class, now_ns, desired, desired_velocity, actual, actual_velocity):
        message = message_class()
        message.header.stamp = stamp(now_ns)
        message.joint_names = list(self.joints)
        message.desired = JointTrajectoryPoint(positions=desired.tolist(),
                                               velocities=desired_velocity.tolist())
        message.actual = JointTrajectoryPoint(positions=actual.tolist(),
                                              velocities=actual_velocity.tolist())
        message.error = JointTrajectoryPoint(
            positions=self._error(desired, actual).tolist(),
            velocities=(desired_velocity - actual_velocity).tolist())
        return message

    def close(self):
        self._cancel_active("the controller was unloaded")
        self._subscription.unregister()
        self.state_out.unregister()


def shortest_angular_distance(start, end):
    """angles::shortest_angular_distance: normalize_angle(end - start), in (-pi, pi]."""
    difference = np.asarray(end, dtype=float) - np.asarray(start, dtype=float)
    positive = np.fmod(np.fmod(difference, 2 * np.pi) + 2 * np.pi, 2 * np.pi)
    return np.where(positive > np.pi, positive - 2 * np.pi, positive)


def wraparound_offset(previous, following):
    """wraparoundJointOffset (joint_trajectory_segment.h:222-243): whole turns to add to
    ``following`` so that it lies within pi of ``previous``."""
    previous = np.asarray(previous, dtype=float)
    following = np.asarray(following, dtype=float)
    distance = shortest_angular_distance(previous, following)
    at_pi = np.abs(np.abs(distance) - np.pi) < 1e-9  # :234-238
    distance = np.where(at_pi, np.where(following > previous, np.abs(distance),
                                        -np.abs(distance)), distance)
    return (previous + distance) - following


class PositionTrajectoryController(JointTrajectoryController):
    interface = "position"


class VelocityTrajectoryController(JointTrajectoryController):
    interface = "velocity"


class EffortTrajectoryController(JointTrajectoryController):
    interface = "effort"
