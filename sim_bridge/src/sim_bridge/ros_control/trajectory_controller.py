"""``position_controllers/JointTrajectoryController`` and its effort and velocity kin.

As ros_controllers' joint_trajectory_controller:

- parameters: ``joints`` (required); ``gains/<joint>`` (p, i, d, i_clamp, antiwindup;
  effort and velocity kinds, control_toolbox's PID, see :mod:`.pid`); ``velocity_ff/<joint>``
  (0; effort and velocity kinds); ``constraints``: ``goal_time`` (0), ``stopped_velocity_tolerance``
  (0.01), ``<joint>/goal`` and ``<joint>/trajectory`` (0: not checked); ``state_publish_rate``
  (50 Hz), ``action_monitor_rate`` (20 Hz); ``allow_partial_joints_goal`` (false);
  ``stop_trajectory_duration`` (0);
- ``<name>/command`` (trajectory_msgs/JointTrajectory), ``<name>/follow_joint_trajectory``
  (control_msgs/FollowJointTrajectory), ``<name>/state``
  (control_msgs/JointTrajectoryControllerState), ``<name>/query_state``
  (control_msgs/QueryTrajectoryState); goals and commands are refused while the controller
  is not running;
- the trajectory is one list of segments per joint, as Noetic's. A new one is taken at the
  next update: each joint it names follows the current trajectory until the new one starts
  (a future stamp) and is then bridged from the current trajectory's desired state to the
  first point; the joints a partial goal leaves out go on with their current trajectory. A
  new goal or command cancels the active goal;
- tolerances per joint and segment: the path ones (position, velocity; the acceleration
  error is always 0) while a segment of the goal runs: left, the goal aborts and the
  trajectory goes on; the goal ones, latched per joint at or after the last segment's end,
  with ``goal_time`` more to meet them: all met, succeeded; not in time, aborted. A cancel
  holds where the joints are, or with ``stop_trajectory_duration`` decelerates;
- as Noetic's initJointTrajectory (ros_controllers noetic-devel 678b92a
  joint_trajectory_controller/include/joint_trajectory_controller/init_joint_trajectory.h,
  "init" below): times must increase strictly (init:232-239); the points at or before the
  next update are dropped (init:321-363; a first point at time_from_start 0 without a stamp
  is one), and a trajectory left with none is refused with Noetic's "Dropping all N
  trajectory point(s), …" (init:336-342); a continuous joint's new trajectory is shifted by
  whole turns to start within pi of its desired position (init:431-440,
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
from dataclasses import replace
from typing import List, Optional, Tuple

import genpy
import numpy as np
from control_msgs.msg import (FollowJointTrajectoryAction, FollowJointTrajectoryFeedback,
                              FollowJointTrajectoryResult, JointTrajectoryControllerState)
from control_msgs.srv import QueryTrajectoryState, QueryTrajectoryStateResponse
from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint

from sim_bridge.plugins.base import PluginError, Rate, stamp
from sim_bridge.ros_control.controller_base import Controller
from sim_bridge.ros_control.pid import Pid
from sim_bridge.trajectory import (NO_TOLERANCE, Segment, Tolerance, Waypoint, find_segment,
                                   sample_segments)

# initJointTrajectory's refusal of a point whose sizes do not agree (init:395-397, :477-488),
# the goal's error_string (impl:548-552, :630-634)
SIZE_MISMATCH = "Size mismatch in trajectory point position, velocity or acceleration data."
# getSegmentTolerances' default goal velocity tolerance (tol:298-299), rad/s
STOPPED_VELOCITY_TOLERANCE = 0.01

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
        # getSegmentTolerances (tol:290-314): the path's position tolerance, the goal's
        # position and velocity (stopped_velocity_tolerance) ones, goal_time
        constraints = self.params.get("constraints", {}) or {}
        stopped_velocity = float(constraints.get("stopped_velocity_tolerance",
                                                 STOPPED_VELOCITY_TOLERANCE))
        self.default_path = [Tolerance(float((constraints.get(j) or {}).get("trajectory", 0.0)))
                             for j in self.joints]
        self.default_goal = [Tolerance(float((constraints.get(j) or {}).get("goal", 0.0)),
                                       stopped_velocity) for j in self.joints]
        self.default_goal_time = float(constraints.get("goal_time", 0.0))
        # impl:229-231, :320-327: > 0, holding decelerates along a stop trajectory
        self.stop_duration = self.number("stop_trajectory_duration", 0.0)
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
        self._query_service = bus.service(io.topic(f"{name}/query_state"), QueryTrajectoryState,
                                          self._on_query)
        n = len(self.joints)
        # the trajectory followed: one list of segments per joint (curr_trajectory_box_)
        self.segments: List[List[Segment]] = []
        self.goal = None  # the active actionlib goal handle (rt_active_goal_)
        self.successful = np.zeros(n, dtype=bool)  # successful_joint_traj_ (impl:315)
        # desired_state_ at the last update: where a stop trajectory starts (impl:326)
        self.desired = (np.zeros(n), np.zeros(n), np.zeros(n))
        # the state's desired, actual and error time_from_start (impl:786-792)
        self.times_from_start = (0.0, 0.0, 0.0)
        self.running = False
        self._pending: Optional[JointTrajectory] = None
        # time_data_ (impl:354-361): the last update's time and period, and the uptime, the
        # sum of the periods since the controller started, which the segments' times count in
        self.now_ns = 0
        self.period_ns = int(round(hardware.step_size * 1e9))
        self.uptime = 0.0
        types = [hardware.joints[j].joint_type for j in self.joints]
        # angle_wraparound_ (impl:268-269); the error wraps for revolute joints too (impl:782)
        self.wraparound = np.array([t == "continuous" for t in types])
        self.angular = np.array([t in ("continuous", "revolute") for t in types])

    # --- incoming trajectories ------------------------------------------------------------
    def _on_command(self, message: JointTrajectory) -> None:
        """rospy's thread: keep it for the next update (a topic command cancels a goal);
        refused while the controller is not running (impl:488-495)."""
        if not self.running:
            self.io.bus.warn(f"{self.name}/command: Can't accept new commands. Controller is "
                             "not running.")
            return
        self._pending = message

    def _on_goal(self, handle) -> None:
        """goalCB (impl:565-636), in the physics thread (posted by the bus)."""
        goal = handle.get_goal()
        if not self.running:  # impl:571-579
            self.io.bus.warn(f"{self.name}: Can't accept new action goals. Controller is not "
                             "running.")
            handle.set_rejected(Result(error_code=Result.INVALID_GOAL), "")
            return
        try:
            segments = self._build(goal.trajectory, handle, goal)
        except TrajectoryRefused as refusal:
            self.io.bus.warn(f"{self.name}: goal refused: {refusal}")
            handle.set_rejected(Result(error_code=refusal.code, error_string=str(refusal)),
                                str(refusal))
            return
        self._cancel_active("replaced by a new goal")
        handle.set_accepted()
        self.goal = handle
        # Noetic clears these latches only on success or abort (impl:413, :451, :465), so a
        # preempted goal's latches would count for the next one: each goal starts over here
        self.successful[:] = False
        self.segments = segments

    def _on_cancel(self, handle) -> None:
        """cancelCB (impl:638-660): hold (or stop, with stop_trajectory_duration)."""
        if self.goal is not None and handle.get_goal_id().id == self.goal.get_goal_id().id:
            self._hold()
            self.goal.set_canceled(Result(error_code=Result.SUCCESSFUL,
                                          error_string="cancelled"), "cancelled")
            self.goal = None

    def _cancel_active(self, why: str) -> None:
        if self.goal is not None:
            self.goal.set_canceled(Result(error_code=Result.SUCCESSFUL, error_string=why), why)
            self.goal = None

    def _tolerances(self, goal):
        """updateSegmentTolerances (tol:231-267) on the defaults: per joint, a value > 0
        sets, < 0 resets to 0 (not checked), 0 keeps; goal_time_tolerance < 0 is 0, > 0 that
        time, 0 the default."""
        path, goal_state = list(self.default_path), list(self.default_goal)
        for given, tolerances in ((goal.path_tolerance, path),
                                  (goal.goal_tolerance, goal_state)):
            for tolerance in given:
                if tolerance.name in self.joints:
                    k = self.joints.index(tolerance.name)
                    tolerances[k] = _updated(tolerances[k], tolerance)
        requested = goal.goal_time_tolerance.to_sec()
        goal_time = (0.0 if requested < 0 else requested if requested > 0
                     else self.default_goal_time)
        return path, goal_state, goal_time

    def _build(self, message: JointTrajectory, handle=None, goal=None) -> List[List[Segment]]:
        """updateTrajectoryCommand and initJointTrajectory (impl:479-563, init:203-520): the
        new trajectory is taken at the next update (impl:508-512); its times are moved from
        simulated time into the uptime (init:254-270).
        Joints it names follow the current trajectory until it starts (or until the next
        update), then a segment from the current trajectory's state there, the desired one,
        to its first point (init:411-461); joints it leaves out (a partial goal) keep the
        current trajectory, from now on belonging to this goal (init:371-387)."""
        names = list(message.joint_names)
        unknown = [n for n in names if n not in self.joints]
        if unknown or len(set(names)) != len(names):
            raise TrajectoryRefused(Result.INVALID_JOINTS,
                                    f"joints {names} do not match the controller's {self.joints}")
        if not self.allow_partial and set(names) != set(self.joints):
            raise TrajectoryRefused(Result.INVALID_JOINTS,
                                    f"the goal names {names}; this controller needs all of "
                                    f"{self.joints} (allow_partial_joints_goal is false)")
        if not message.points:  # impl:514-520: hold, the goal taken
            return self._hold_segments(handle)
        order = [names.index(j) if j in names else None for j in self.joints]
        times = [p.time_from_start.to_nsec() for p in message.points]
        if any(a >= b for a, b in zip(times, times[1:])):  # init:232-239, msg:119-134
            raise TrajectoryRefused(Result.INVALID_GOAL, "Trajectory message contains "
                                    "waypoints that are not strictly increasing in time.")
        next_ns = self.now_ns + self.period_ns
        start_ns = message.header.stamp.to_nsec() or next_ns  # msg:69-73
        kept = [k for k, t in enumerate(times) if start_ns + t > next_ns]  # msg:150-166
        if not kept:  # init:333-343
            past = (next_ns - (start_ns + times[-1])) / 1e9
            raise TrajectoryRefused(Result.INVALID_GOAL, (
                f"Dropping all {len(times)} trajectory point(s), as they occur before the "
                f"current time.\nLast point is {past:f}s in the past."))
        points = [message.points[k] for k in kept]
        for number, point in zip(kept, points):
            for field in ("positions", "velocities", "accelerations"):
                values = getattr(point, field)
                if values and len(values) != len(names):  # init:395-397, :477-488
                    raise TrajectoryRefused(Result.INVALID_GOAL, SIZE_MISMATCH)
                if values and not all(math.isfinite(v) for v in values):
                    raise TrajectoryRefused(Result.INVALID_GOAL,
                                            f"point {number} has a {field[:-1]} that is not finite")
            if not point.positions:
                raise TrajectoryRefused(Result.INVALID_GOAL, f"point {number} has no positions")
        n = len(self.joints)
        if goal is not None:  # a topic command's segments carry no tolerances (init:460, :493)
            path, goal_state, goal_time = self._tolerances(goal)
        else:
            path, goal_state, goal_time = [NO_TOLERANCE] * n, [NO_TOLERANCE] * n, 0.0
        next_time = self.uptime + self.period_ns / 1e9  # next_update_uptime (impl:512)
        message_start = next_time + (start_ns - next_ns) / 1e9  # o_msg_start_time (init:262)
        bridge_time = max(message_start, next_time)  # init:417 ("Important!")
        result = []
        for k, current in enumerate(self.segments):
            active = find_segment(current, next_time)
            active = 0 if active is None else active
            i = order[k]
            if i is None:
                result.append(current[:active] +
                              [replace(segment, goal=handle) for segment in current[active:]])
                continue
            last = find_segment(current, bridge_time)
            position, velocity, acceleration = sample_segments(current, bridge_time)
            bridge = Waypoint(bridge_time, np.float64(position), np.float64(velocity),
                              np.float64(acceleration))
            offset = 0.0
            if self.wraparound[k]:  # init:431-440, from the desired state
                offset = float(wraparound_offset(position, points[0].positions[i]))
            waypoints = [Waypoint(
                message_start + point.time_from_start.to_sec(),
                np.float64(point.positions[i] + offset),
                np.float64(point.velocities[i]) if point.velocities else None,
                np.float64(point.accelerations[i]) if point.accelerations else None,
                point.time_from_start.to_sec())
                for point in points]
            tolerances = dict(goal=handle, path=path[k], goal_state=goal_state[k],
                              goal_time=goal_time)
            joint = current[active:(active if last is None else last) + 1]
            joint.append(Segment(bridge, waypoints[0], **tolerances))
            joint.extend(Segment(a, b, **tolerances) for a, b in zip(waypoints, waypoints[1:]))
            result.append(joint)
        return result

    def _error(self, desired: np.ndarray, actual: np.ndarray) -> np.ndarray:
        """state_error_.position (impl:782): shortest_angular_distance(actual, desired) for
        revolute and continuous joints; the difference for prismatic ones."""
        return np.where(self.angular, shortest_angular_distance(actual, desired),
                        desired - actual)

    # --- the control loop -----------------------------------------------------------------
    def _current(self):
        indices = [self.hardware.names.index(j) for j in self.joints]
        return (self.hardware.positions[indices].copy(), self.hardware.velocities[indices].copy(),
                self.hardware.efforts[indices].copy())

    def _hold_segments(self, handle=None) -> List[List[Segment]]:
        """setHoldPosition (impl:738-748): HoldTrajectoryBuilder, the joints' positions,
        still (hold_trajectory_builder.h:81-108); with stop_trajectory_duration d > 0,
        StopTrajectoryBuilder (stop_trajectory_builder.h:97-139): from the desired state
        (p, v) to the middle of the quintic from (p, v, 0) to (p, -v, 0) over 2 d, reached in
        d. The hold trajectory's segments carry no tolerances."""
        t = self.uptime
        result = []
        if self.stop_duration == 0.0:
            positions, _, _ = self._current()
            for position in positions:
                state = Waypoint(t, np.float64(position), np.float64(0.0), np.float64(0.0))
                result.append([Segment(state, state, goal=handle)])
            return result
        for position, velocity in zip(self.desired[0], self.desired[1]):
            begin = Waypoint(t, np.float64(position), np.float64(velocity), np.float64(0.0))
            turned = Waypoint(t + 2 * self.stop_duration, np.float64(position),
                              np.float64(-velocity), np.float64(0.0))
            middle = Segment(begin, turned).sample(t + self.stop_duration)
            stop = Waypoint(t + self.stop_duration, *(np.float64(x) for x in middle))
            result.append([Segment(begin, stop, goal=handle)])
        return result

    def _hold(self) -> None:
        self.segments = self._hold_segments()

    def _sample(self, t: float):
        states = np.array([sample_segments(segments, t) for segments in self.segments])
        return states[:, 0].copy(), states[:, 1].copy(), states[:, 2].copy()

    def start(self, now_ns):
        """starting (impl:131-156): the uptime starts at 0; the desired state is the current
        one, held."""
        self.now_ns = now_ns
        self.uptime = 0.0
        positions, velocities, _ = self._current()
        self.desired = (positions, velocities, np.zeros_like(positions))
        self._hold()
        for pid in self.pids or []:  # hia:180-190
            pid.reset()
        self.state_rate.reset(now_ns)
        self.feedback_rate.reset(now_ns)
        self.running = True

    def stop(self, now_ns):
        self.running = False
        self._cancel_active("the controller was stopped")

    def update(self, now_ns, dt):
        """update (impl:345-477): the uptime advances by the period the controller manager
        gives (after a reset_world, the whole simulated time: the trajectory followed is
        sampled that much further on, as Noetic's)."""
        # a command taken in this update was timed from the last one (impl:505-512)
        if self._pending is not None:
            message, self._pending = self._pending, None
            try:
                self.segments = self._build(message)
                self._cancel_active("replaced by a trajectory on the command topic")
            except TrajectoryRefused as refusal:
                self.io.bus.warn(f"{self.name}/command: trajectory ignored: {refusal}")
        self.now_ns = now_ns
        self.period_ns = int(round(dt * 1e9))
        self.uptime += dt
        t = self.uptime
        desired, desired_velocity, desired_acceleration = self._sample(t)
        self.desired = (desired, desired_velocity, desired_acceleration)
        self.times_from_start = self._times_from_start(t)
        actual, actual_velocity, _ = self._current()
        error = self._error(desired, actual)
        velocity_error = desired_velocity - actual_velocity
        if self.goal is not None:
            self._check_tolerances(t, error, velocity_error)
        self._command(desired, desired_velocity, error, velocity_error, dt)
        if self.goal is not None and self.feedback_rate.due(now_ns):
            self.goal.publish_feedback(self._state(FollowJointTrajectoryFeedback, now_ns,
                                                   actual, actual_velocity))
        if self.state_rate.due(now_ns):
            self.state_out.publish(self._state(JointTrajectoryControllerState, now_ns, actual,
                                               actual_velocity))

    def _times_from_start(self, t: float) -> Tuple[float, float, float]:
        """updateStates' time_from_start (impl:786-792), from the first joint's segment at
        ``t``: desired, the segment's start point's time_from_start (quintic_spline_segment.h
        :228; a bridge or hold segment starts at a sampled state's 0); actual, that plus the
        time since the segment's start; error, desired minus actual."""
        segments = self.segments[0]
        index = find_segment(segments, t)
        segment = segments[0 if index is None else index]
        desired = segment.start.time_from_start
        actual = t - segment.start_time + desired
        return desired, actual, desired - actual

    def _command(self, desired, desired_velocity, error, velocity_error, dt):
        for k, joint in enumerate(self.joints):
            handle = self.hardware.joints[joint]
            if self.interface == "position":
                handle.command = float(desired[k])
            else:  # hia:210
                handle.command = float(self.velocity_ff[k] * desired_velocity[k] +
                                       self.pids[k].command(error[k], velocity_error[k], dt))

    def _check_tolerances(self, t, error, velocity_error):
        """impl:373-466, joint by joint, on the segment each follows when it belongs to the
        active goal: before its end, the path tolerance (violated: the goal aborted, "<joint>
        path error <e>", the trajectory goes on); at or after the end of the last, the goal
        tolerance, latched per joint once met; not met ``goal_time`` after the end: aborted,
        "<joint> goal error <e>". The acceleration error is always 0 (impl:784). Every joint's
        latch set: succeeded."""
        for k, joint in enumerate(self.joints):
            if self.goal is None:
                return
            segments = self.segments[k]
            index = find_segment(segments, t)
            if index is None:
                continue
            segment = segments[index]
            if segment.goal is not self.goal:
                continue
            if t < segment.end_time:
                if not segment.path.admits(error[k], velocity_error[k]):
                    self._abort(Result.PATH_TOLERANCE_VIOLATED, f"{joint} path error {error[k]:f}")
            elif index == len(segments) - 1:
                if segment.goal_state.admits(error[k], velocity_error[k]):
                    self.successful[k] = True
                elif t >= segment.end_time + segment.goal_time:
                    self._abort(Result.GOAL_TOLERANCE_VIOLATED,
                                f"{joint} goal error {error[k]:f}")
        if self.goal is not None and np.all(self.successful):
            self.goal.set_succeeded(Result(error_code=Result.SUCCESSFUL), "goal reached")
            self.goal = None
            self.successful[:] = False

    def _abort(self, code: int, text: str) -> None:
        self.goal.set_aborted(Result(error_code=code, error_string=text), text)
        self.goal = None
        self.successful[:] = False

    def _on_query(self, request) -> QueryTrajectoryStateResponse:
        """queryStateService (impl:662-708): the trajectory followed, sampled at the
        request's time; refused while the controller is not running or before the
        trajectory's start."""
        if not self.running:
            raise PluginError(f"{self.name}: Can't sample trajectory. Controller is not running.")
        t = self.uptime + (request.time.to_nsec() - self.now_ns) / 1e9  # impl:674-677
        if any(find_segment(segments, t) is None for segments in self.segments):
            raise PluginError(f"{self.name}: Requested sample time precedes trajectory start "
                              "time.")
        positions, velocities, accelerations = self._sample(t)
        return QueryTrajectoryStateResponse(name=list(self.joints), position=positions.tolist(),
                                            velocity=velocities.tolist(),
                                            acceleration=accelerations.tolist())

    def _state(self, message_class, now_ns, actual, actual_velocity):
        """publishState and setActionFeedback (impl:710-736, :796-819): desired (with its
        accelerations), actual, error."""
        desired, desired_velocity, desired_acceleration = self.desired
        message = message_class()
        message.header.stamp = stamp(now_ns)
        message.joint_names = list(self.joints)
        message.desired = JointTrajectoryPoint(positions=desired.tolist(),
                                               velocities=desired_velocity.tolist(),
                                               accelerations=desired_acceleration.tolist())
        message.actual = JointTrajectoryPoint(positions=actual.tolist(),
                                              velocities=actual_velocity.tolist())
        message.error = JointTrajectoryPoint(
            positions=self._error(desired, actual).tolist(),
            velocities=(desired_velocity - actual_velocity).tolist())
        for point, seconds in zip((message.desired, message.actual, message.error),
                                  self.times_from_start):
            point.time_from_start = genpy.Duration.from_sec(seconds)
        return message

    def close(self):
        self._cancel_active("the controller was unloaded")
        self._subscription.unregister()
        self.state_out.unregister()
        self._query_service.shutdown()


def _updated(tolerance: Tolerance, given) -> Tolerance:
    """updateStateTolerances (tol:211-222): > 0 sets, < 0 resets to 0, 0 keeps."""
    def one(old: float, new: float) -> float:
        return new if new > 0 else 0.0 if new < 0 else old
    return Tolerance(one(tolerance.position, given.position),
                     one(tolerance.velocity, given.velocity),
                     one(tolerance.acceleration, given.acceleration))


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
