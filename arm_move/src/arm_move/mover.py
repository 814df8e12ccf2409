"""The ``mover`` node: reset, step and follow for the px100, with MoveIt's error codes.

Runs in the arm's namespace (``px100``). At start-up it reads its settings once (private
parameters from config/mover.yaml; the arm and scene from config/px100.yaml and
config/scene.yaml unless ``~robot_config`` / ``~scene_config`` name others), adds the
table to its planning scene and checks it is there, loads ``~waypoints`` (a list of
``[x, y, z, gripper_open]``; none: empty), waits for the arm's joint states and for the
two trajectory controllers' action servers (``arm_controller`` and ``gripper_controller``
``/follow_joint_trajectory``, as the simulator's ros_control, the fake executor, or a
real driver provide them) and only then offers its services:

- ``reset`` (arm_move/Reset): places the RealSense box (planning scene, and the simulation
  when ``/gazebo/set_model_state`` answers), then moves the arm to Home around it, gripper
  open; ``clear_waypoints`` forgets the list. A box pose inside the table or another
  scene object (GOAL_IN_COLLISION) or reaching below the floor (INVALID_GOAL_CONSTRAINTS)
  is refused naming the pose and what it is in; nothing moves.
- ``step`` (arm_move/Step): plans the gripper point to a position, moves, then opens or
  closes the gripper; only when all of that succeeded is ``[x, y, z, gripper_open]``
  appended to ``~waypoints``. A planning failure moves nothing; a failed execution
  (CONTROL_FAILED, TIMED_OUT) may leave the arm part of the way; either way the list stays
  as it was and the code says why (see
  arm_move.planner: below the floor or NaN → INVALID_GOAL_CONSTRAINTS, out of reach →
  NO_IK_SOLUTION, inside an object → GOAL_IN_COLLISION...).
- The block (``pick_object``) is in the planning scene from the start, where
  config/scene.yaml puts it. Closing the gripper around it attaches it to the hand (as
  MoveIt's attachObject): from then on it moves with the hand and is checked against the
  scene and the arm; opening the gripper detaches it where it is.
- ``follow`` (arm_move/Follow): goes through the waypoints in order, once (the call returns
  when done) or repeating in the background until ``reset`` or another ``follow``.
  No waypoints: INVALID_MOTION_PLAN, nothing moves.

A request while another runs is refused (FAILURE, "busy"). The scene and each planned
path are published as markers (``planning_scene``, ``planned_path``).
"""
from __future__ import annotations

import math
import os
import sys
import threading
import time
from dataclasses import dataclass
from typing import List, Optional

import actionlib
import numpy as np
import rospkg
import rospy
import yaml
from control_msgs.msg import FollowJointTrajectoryAction, FollowJointTrajectoryGoal
from sensor_msgs.msg import JointState
from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint
from visualization_msgs.msg import Marker, MarkerArray

import tf.transformations as tft

from arm_move.collision import Box, fingers_around
from arm_move.kinematics import ARM_JOINTS, FINGER_JOINTS
from arm_move.markers import path_marker, scene_markers
from arm_move.msg import MoveItErrorCodes as Codes
from arm_move.planner import ArmPlanner, Plan, planner_from_config, settings_from
from node_params import non_empty, non_negative, parameter, positive
from arm_move.scene_config import (PICK_OBJECT, REALSENSE_BOX, TABLE, empty_scene, pick_box,
                                   table_box, unit_quaternion)
from arm_move.srv import (Follow, FollowResponse, Reset, ResetResponse, Step, StepResponse)

# how often (wall s) start-up checks whether the joint states have come
POLL_PERIOD = 0.05


def _server_within(client: actionlib.SimpleActionClient, timeout: float) -> bool:
    """Whether ``client``'s action server answers within ``timeout`` wall seconds. Start-up
    is bounded in wall time: a simulator running many times faster than real time used up a
    simulated 10 s before the controller spawner (a process starting in wall time) had
    loaded the controllers, and with physics paused simulated time would never run out."""
    answered: List[bool] = []
    waiting = threading.Thread(target=lambda: answered.append(client.wait_for_server()),
                               daemon=True)
    waiting.start()
    waiting.join(timeout)
    return bool(answered and answered[0])


@dataclass(frozen=True)
class MoverSettings:
    """The mover's own settings (the planner's are PlannerSettings); see config/mover.yaml.
    Read with node_params: a bad value stops the node naming it."""

    planning_frame: str = parameter("px100/base_link", non_empty,
                                    expected="the frame plans and markers are in")
    collision_padding: float = parameter(
        0.005, non_negative, expected="metres >= 0 the arm keeps from everything")
    action_timeout: float = parameter(
        10.0, positive, expected="wall seconds > 0 to wait for the controllers' action servers "
                                 "at start-up (arm.launch's driver_timeout)")
    execution_margin: float = parameter(
        5.0, non_negative, expected="seconds >= 0 a motion may run past its planned time")
    robot_config: str = parameter("", expected="the arm's yaml (empty: config/px100.yaml)")
    scene_config: str = parameter("", expected="the scene's yaml (empty: config/scene.yaml)")


class Outcome(Exception):
    """Ends a request early with a code and a message."""

    def __init__(self, code: int, message: str):
        super().__init__(message)
        self.code, self.message = code, message


def _read_yaml(path: str):
    with open(path) as stream:
        return yaml.safe_load(stream)


def parse_waypoints(value) -> List[List[float]]:
    """``~waypoints`` as [[x, y, z, open], ...]; ValueError naming the bad entry."""
    if value is None:
        return []
    if not isinstance(value, list):
        raise ValueError(f"~waypoints must be a list of [x, y, z, gripper_open], got {value!r}")
    parsed = []
    for index, entry in enumerate(value):
        if not isinstance(entry, (list, tuple)) or len(entry) != 4:
            raise ValueError(f"~waypoints[{index}] must be [x, y, z, gripper_open], got {entry!r}")
        x, y, z, gripper_open = entry
        numbers = [float(x), float(y), float(z)]
        if not all(math.isfinite(n) for n in numbers):
            raise ValueError(f"~waypoints[{index}] has a position that is not finite: {entry!r}")
        parsed.append(numbers + [bool(gripper_open)])
    return parsed


class Mover:
    def __init__(self, settings: MoverSettings, planner: ArmPlanner, scene_config: dict,
                 waypoints: List[List[float]]):
        self.settings = settings
        self.planner = planner
        self.k = planner.k
        self.scene_config = scene_config
        self.scene = empty_scene(scene_config)
        self.finger_length = float(planner.model.finger_length)
        self.waypoints = waypoints
        self._busy = threading.Lock()
        self._state_lock = threading.Lock()
        self._positions = {}
        self._state_stamp = None
        self._cycle: Optional[threading.Thread] = None
        self._stop_cycle = threading.Event()

    # --- start-up ------------------------------------------------------------------------
    def start(self) -> None:
        frame = self.settings.planning_frame
        self._scene_topic = rospy.Publisher("planning_scene", MarkerArray, queue_size=1,
                                            latch=True)
        self._path_topic = rospy.Publisher("planned_path", Marker, queue_size=1, latch=True)
        self.scene.add(table_box(self.scene_config))
        self.scene.add(pick_box(self.scene_config))
        for name in (TABLE, PICK_OBJECT):  # what MoveIt users do: check the objects arrived
            if name not in self.scene.boxes:
                raise RuntimeError(f"the {name} did not reach the planning scene")
        self._publish_scene()
        rospy.loginfo("mover: planning scene has the %s and the %s (frame %s)", TABLE,
                      PICK_OBJECT, frame)
        rospy.Subscriber("joint_states", JointState, self._on_joint_states, queue_size=10)
        timeout = self.settings.action_timeout
        self.arm = actionlib.SimpleActionClient("arm_controller/follow_joint_trajectory",
                                                FollowJointTrajectoryAction)
        self.gripper = actionlib.SimpleActionClient("gripper_controller/follow_joint_trajectory",
                                                    FollowJointTrajectoryAction)
        for name, client in (("arm_controller", self.arm), ("gripper_controller", self.gripper)):
            if not _server_within(client, timeout):
                raise RuntimeError(
                    f"no driver answers on {rospy.resolve_name(name)}/follow_joint_trajectory "
                    f"after {timeout:.0f} s. A driver must provide "
                    f"{rospy.resolve_name('joint_states')} (sensor_msgs/JointState of "
                    f"{', '.join(ARM_JOINTS + FINGER_JOINTS)}) and the control_msgs/"
                    "FollowJointTrajectory actions arm_controller/follow_joint_trajectory "
                    "(the four arm joints) and gripper_controller/follow_joint_trajectory "
                    "(the fingers) in this namespace; or start arm.launch with use_sim:=true")
        self._wait_for_joint_states(timeout)
        rospy.Service("reset", Reset, self._serve_reset)
        rospy.Service("step", Step, self._serve_step)
        rospy.Service("follow", Follow, self._serve_follow)
        rospy.loginfo("mover: ready, %d waypoints loaded", len(self.waypoints))

    def _on_joint_states(self, message: JointState) -> None:
        with self._state_lock:
            self._positions.update(zip(message.name, message.position))
            self._state_stamp = message.header.stamp

    def _wait_for_fresh_state(self, since) -> None:
        """After a motion: waits (briefly) for joint states stamped after it ended, so that
        the next plan starts from where the arm is, not from where it was on its way."""
        deadline = rospy.get_time() + 1.0
        rate = rospy.Rate(100)
        while not rospy.is_shutdown() and rospy.get_time() < deadline:
            with self._state_lock:
                if self._state_stamp is not None and self._state_stamp >= since:
                    return
            rate.sleep()
        rospy.logwarn("mover: no joint states newer than the end of the last motion")

    def _wait_for_joint_states(self, timeout: float) -> None:
        deadline = time.monotonic() + timeout  # wall time: see _server_within
        while not rospy.is_shutdown() and time.monotonic() < deadline:
            if all(name in self._positions for name in ARM_JOINTS + FINGER_JOINTS):
                return
            time.sleep(POLL_PERIOD)
        raise RuntimeError(f"no joint states for {', '.join(ARM_JOINTS + FINGER_JOINTS)} on "
                           f"{rospy.resolve_name('joint_states')} after {timeout:.0f} s")

    def current(self):
        with self._state_lock:
            arm = np.array([self._positions[name] for name in ARM_JOINTS])
            finger = float(np.mean([self._positions[name] for name in FINGER_JOINTS]))
        return arm, finger

    # --- services ------------------------------------------------------------------------
    def _serve(self, handler, response_class, request, stops_cycle: bool):
        if stops_cycle:
            self._end_cycle()
        if not self._busy.acquire(blocking=False):
            return response_class(Codes(Codes.FAILURE), "busy: another request is running; "
                                  "try again when it has finished")
        try:
            code, message = handler(request)
        except Outcome as outcome:
            code, message = outcome.code, outcome.message
        finally:
            self._busy.release()
        (rospy.loginfo if code == Codes.SUCCESS else rospy.logwarn)("mover: %s", message)
        return response_class(Codes(code), message)

    def _serve_reset(self, request):
        return self._serve(self._reset, ResetResponse, request, stops_cycle=True)

    def _serve_step(self, request):
        return self._serve(self._step, StepResponse, request, stops_cycle=False)

    def _serve_follow(self, request):
        return self._serve(self._follow, FollowResponse, request, stops_cycle=True)

    # --- reset ---------------------------------------------------------------------------
    def _reset(self, request):
        pose = request.box_pose
        position = np.array([pose.position.x, pose.position.y, pose.position.z])
        if not np.all(np.isfinite(position)):
            raise Outcome(Codes.INVALID_GOAL_CONSTRAINTS,
                          f"reset: box position {position.tolist()} is not finite")
        o = pose.orientation
        try:
            orientation = unit_quaternion(o.x, o.y, o.z, o.w)
        except ValueError as error:
            raise Outcome(Codes.INVALID_GOAL_CONSTRAINTS, f"reset: box {error}") from None
        size = self.scene_config[REALSENSE_BOX]["size"]
        box = Box(REALSENSE_BOX, position, orientation, size)
        arm, finger = self.current()
        trial = empty_scene(self.scene_config)
        for other in self.scene.boxes.values():
            if other.name != REALSENSE_BOX:
                trial.add(other)
        if self.scene.attached is not None:  # reset opens the gripper: it lets go
            trial.add(self._held_box(arm))
        self._check_placement(box, trial, pose)
        trial.add(box)
        plan = self.planner.plan_to_joints(arm, self.k.finger_max, self.k.named_poses["home"],
                                           trial)
        if plan.code == Codes.START_STATE_IN_COLLISION:
            plan = Plan(plan.code, f"{plan.message} with the box there; the box was not moved")
        self._require(plan, "reset")
        self.scene = trial
        self._publish_scene()
        self._place_in_simulation(position, pose.orientation)
        self._execute_gripper(self.k.finger_max)
        self._execute(plan)
        if request.clear_waypoints:
            self.waypoints = []
            rospy.set_param("~waypoints", [])
        return Codes.SUCCESS, (f"reset: box at {position.round(3).tolist()}, arm at Home"
                               f"{', waypoints cleared' if request.clear_waypoints else ''}")

    def _check_placement(self, box: Box, scene, pose) -> None:
        """Refuses a box pose below the floor or inside an obstacle of ``scene`` (the table,
        the block): the planner would believe it there while physics threw the simulated
        box out onto the floor. Resting on the table is fine (it may sink in by the held
        object's contact tolerance, as a set-down block may)."""
        hit = scene.placement_conflict(box, self.planner.model.contact_tolerance)
        if hit is None:
            return
        o = pose.orientation
        where = (f"box pose (position {np.round(box.center, 4).tolist()}, orientation "
                 f"{np.round([o.x, o.y, o.z, o.w], 4).tolist()})")
        if hit == "floor":
            raise Outcome(Codes.INVALID_GOAL_CONSTRAINTS,
                          f"reset: the {where} reaches below the floor (z "
                          f"{scene.floor_z:g} in {self.settings.planning_frame}); the box was "
                          "not moved, nothing moved")
        raise Outcome(Codes.GOAL_IN_COLLISION,
                      f"reset: the {where} is inside the {hit}; the box was not moved, "
                      "nothing moved")

    def _place_in_simulation(self, position, orientation) -> None:
        """Moves the simulated box too, when a simulator answers (not on the fake or the
        real robot): its pose in the world is the arm's base frame raised by the table."""
        try:
            from gazebo_msgs.msg import ModelState
            from gazebo_msgs.srv import SetModelState
            rospy.wait_for_service("/gazebo/set_model_state", timeout=0.5)
        except (ImportError, rospy.ROSException):
            return
        state = ModelState(model_name=REALSENSE_BOX, reference_frame="world")
        state.pose.position.x, state.pose.position.y = position[0], position[1]
        state.pose.position.z = position[2] + float(self.scene_config["table_height"])
        state.pose.orientation = orientation
        answer = rospy.ServiceProxy("/gazebo/set_model_state", SetModelState)(state)
        if not answer.success:
            rospy.logwarn("mover: the simulator did not move the box: %s", answer.status_message)

    # --- step ----------------------------------------------------------------------------
    def _step(self, request):
        target = (request.position.x, request.position.y, request.position.z)
        plan, grasps = self.move_to(target, request.gripper_open, "step")
        rospy.loginfo("mover: step %s", plan.message)
        try:
            self._execute(plan)
            self._execute_gripper(self._finger_for(request.gripper_open))
            self._grasp_or_release(plan.path[-1], request.gripper_open, grasps)
        except Outcome as outcome:
            # the waypoint is stored only once the motion is done: a failed step leaves the
            # list as it was (the arm may have moved part of the way)
            raise Outcome(outcome.code, f"step: {outcome.message}; no waypoint stored") from None
        waypoint = [float(v) for v in target] + [bool(request.gripper_open)]
        self.waypoints.append(waypoint)
        rospy.set_param("~waypoints", self.waypoints)
        return Codes.SUCCESS, (f"step: gripper at {np.round(target, 3).tolist()}, "
                               f"{'open' if request.gripper_open else 'closed'}; waypoint "
                               f"{len(self.waypoints)} stored (planned in "
                               f"{1000 * plan.planning_seconds:.0f} ms: {plan.message})")

    def _finger_for(self, gripper_open: bool) -> float:
        return self.k.finger_max if gripper_open else self.k.finger_min

    def move_to(self, target, gripper_open: bool, what: str):
        """Plans to a target: the plan, and whether closing the gripper there grasps the
        block; Outcome when it cannot be done (nothing has moved)."""
        arm, finger = self.current()
        block = self.scene.boxes.get(PICK_OBJECT)
        # approaching the block to grasp it, or leaving it after letting go, the gripper may
        # touch it (MoveIt's pick and place allow the end effector's touch links that on
        # approach and retreat); elsewhere it is an obstacle like any other
        self.scene.touch_allowed = PICK_OBJECT if block is not None and any(
            fingers_around(block, point, self.k.finger_max, self.finger_length)
            for point in (target, self.k.gripper_point(arm))) else None
        plan = self.planner.plan_to_position(arm, finger, target, self.scene)
        self._require(plan, what)
        # the gripper opens or closes at the target: that must be free as well, except that
        # closing it around the block is a grasp
        goal, opening = plan.path[-1], self._finger_for(gripper_open)
        hit = self.planner.model.collision(goal, opening, self.scene)
        grasps = not gripper_open and self.scene.touch_allowed == PICK_OBJECT and \
            self._grasps(goal, opening)
        if hit and not grasps:
            raise Outcome(Codes.GOAL_IN_COLLISION, f"{what}: {'opening' if gripper_open else 'closing'}"
                          f" the gripper at the target would touch {hit}")
        self._publish_path(plan)
        return plan, grasps

    def _grasps(self, q, opening: float) -> bool:
        """Whether closing the gripper at q closes it on the block: the block's centre lies
        between the fingers, and the closed fingers would touch it."""
        block = self.scene.boxes.get(PICK_OBJECT)
        if block is None or self.scene.attached is not None:
            return False
        origin, axes = self.planner.model.hand_frames(np.asarray(q)[None])
        if abs(float((block.center - origin[0]) @ axes[0][:, 1])) >= self.k.finger_max:
            return False
        alone = empty_scene(self.scene_config)
        alone.add(block)
        return self.planner.model.collision(q, opening, alone) == PICK_OBJECT

    def _held_box(self, q) -> Box:
        """The attached block as a scene box where the hand at q holds it."""
        attached = self.scene.attached
        centre, rotation = self.planner.model.attached_pose(attached, q)
        matrix = np.eye(4)
        matrix[:3, :3] = rotation
        return Box(attached.name, centre, tuple(tft.quaternion_from_matrix(matrix)),
                   attached.size)

    def _grasp_or_release(self, q, gripper_open: bool, grasps: bool) -> None:
        """After the gripper moved at q: a grasp attaches the block to the hand (MoveIt's
        attachObject); opening the gripper detaches a held block where it is."""
        if grasps:
            block = self.scene.boxes[PICK_OBJECT]
            self.scene.remove(PICK_OBJECT)
            self.scene.attached = self.planner.model.attach(PICK_OBJECT, block, q)
            rospy.loginfo("mover: %s attached to the gripper", PICK_OBJECT)
        elif gripper_open and self.scene.attached is not None:
            box = self._held_box(q)
            self.scene.attached = None
            self.scene.add(box)
            rospy.loginfo("mover: %s detached at %s", box.name, np.round(box.center, 3).tolist())
        else:
            return
        self._publish_scene()

    @staticmethod
    def _require(plan: Plan, what: str) -> None:
        if not plan.ok:
            raise Outcome(plan.code, f"{what}: {plan.message}; nothing moved")

    # --- follow --------------------------------------------------------------------------
    def _follow(self, request):
        if not self.waypoints:
            raise Outcome(Codes.INVALID_MOTION_PLAN, "follow: there are no waypoints (add some "
                          "with step, or load them into ~waypoints); nothing moved")
        waypoints = [list(w) for w in self.waypoints]
        if request.repeat:
            self._stop_cycle.clear()
            self._cycle = threading.Thread(target=self._repeat, args=(waypoints,), daemon=True)
            self._cycle.start()
            return Codes.SUCCESS, (f"follow: cycling through {len(waypoints)} waypoints until "
                                   "reset or follow")
        self._go_through(waypoints)
        return Codes.SUCCESS, f"follow: went through {len(waypoints)} waypoints"

    def _go_through(self, waypoints) -> None:
        for index, (x, y, z, gripper_open) in enumerate(waypoints):
            if self._stop_cycle.is_set():
                raise Outcome(Codes.PREEMPTED, "follow: stopped")
            try:
                plan, grasps = self.move_to((x, y, z), gripper_open,
                                            f"follow, waypoint {index + 1}")
            except Outcome as outcome:
                raise Outcome(outcome.code, outcome.message.replace("; nothing moved", "")) from None
            self._execute(plan)
            self._execute_gripper(self._finger_for(gripper_open))
            self._grasp_or_release(plan.path[-1], gripper_open, grasps)

    def _repeat(self, waypoints) -> None:
        with self._busy:
            while not self._stop_cycle.is_set() and not rospy.is_shutdown():
                try:
                    self._go_through(waypoints)
                except Outcome as outcome:
                    if outcome.code != Codes.PREEMPTED:
                        rospy.logwarn("mover: the repeating follow stopped: %s", outcome.message)
                    return

    def _end_cycle(self) -> None:
        if self._cycle is not None and self._cycle.is_alive():
            self._stop_cycle.set()
            self.arm.cancel_all_goals()
            self.gripper.cancel_all_goals()
            self._cycle.join(timeout=self.settings.action_timeout)
        self._cycle = None
        self._stop_cycle.clear()

    # --- execution -----------------------------------------------------------------------
    def _execute(self, plan: Plan) -> None:
        trajectory = JointTrajectory(joint_names=list(ARM_JOINTS))
        for t, p, v in zip(plan.times, plan.positions, plan.velocities):
            trajectory.points.append(JointTrajectoryPoint(
                positions=[float(x) for x in p], velocities=[float(x) for x in v],
                time_from_start=rospy.Duration(t)))
        self._run(self.arm, trajectory, "the arm")

    def _execute_gripper(self, opening: float) -> None:
        _, finger = self.current()
        duration = max(0.2, abs(opening - finger) / self.k.finger_speed)
        trajectory = JointTrajectory(joint_names=list(FINGER_JOINTS))
        trajectory.points.append(JointTrajectoryPoint(positions=[opening, opening],
                                                      velocities=[0.0, 0.0],
                                                      time_from_start=rospy.Duration(duration)))
        self._run(self.gripper, trajectory, "the gripper")

    def _run(self, client, trajectory: JointTrajectory, what: str) -> None:
        if self._stop_cycle.is_set():
            raise Outcome(Codes.PREEMPTED, "stopped")
        goal = FollowJointTrajectoryGoal(trajectory=trajectory)
        duration = trajectory.points[-1].time_from_start.to_sec()
        client.send_goal(goal)
        if not client.wait_for_result(rospy.Duration(duration + self.settings.execution_margin)):
            client.cancel_goal()
            raise Outcome(Codes.TIMED_OUT, f"{what} did not finish its motion within "
                          f"{duration + self.settings.execution_margin:.1f} s")
        if self._stop_cycle.is_set():
            raise Outcome(Codes.PREEMPTED, "stopped")
        self._wait_for_fresh_state(rospy.Time.now())
        result = client.get_result()
        if result is None or result.error_code != 0:
            detail = result.error_string if result is not None else "no result"
            raise Outcome(Codes.CONTROL_FAILED, f"{what}'s controller failed: {detail}")

    # --- markers -------------------------------------------------------------------------
    def _publish_scene(self) -> None:
        held = []
        if self.scene.attached is not None and self._positions:
            held = [self._held_box(self.current()[0])]
        self._scene_topic.publish(scene_markers(self.scene, self.settings.planning_frame,
                                                rospy.Time.now(), held))

    def _publish_path(self, plan: Plan) -> None:
        points = [self.k.gripper_point(q) for q in plan.positions]
        self._path_topic.publish(path_marker(points, self.settings.planning_frame,
                                             rospy.Time.now()))


def main(argv=None) -> None:
    rospy.init_node("mover", argv=argv)
    package = rospkg.RosPack().get_path("arm_move")
    try:
        values = _read_yaml(os.path.join(package, "config", "mover.yaml"))
        values.update(rospy.get_param("~", {}))
        # every setting named as the private parameter it is (the yaml's are loaded as such)
        settings = settings_from(MoverSettings, values, "~")
        robot = _read_yaml(settings.robot_config
                           or os.path.join(package, "config", "px100.yaml"))
        scene_config = _read_yaml(settings.scene_config
                                  or os.path.join(package, "config", "scene.yaml"))
        waypoints = parse_waypoints(rospy.get_param("~waypoints", None))
        planner = planner_from_config(robot, values, "~")
        mover = Mover(settings, planner, scene_config, waypoints)
        mover.start()
    except (ValueError, KeyError, OSError, RuntimeError) as error:
        rospy.logfatal("mover: %s", error)
        sys.exit(1)
    rospy.spin()
