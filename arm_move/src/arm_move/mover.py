"""The ``mover`` node: reset, step and follow for the PincherX 100, planned by MoveIt.

A client of move_group through moveit_commander, as the homework asks: the arm is
Interbotix's ``interbotix_arm`` group, the gripper ``interbotix_gripper`` with its named
states Open and Closed. The node runs in the arm's namespace (``px100``, where
xsarm_moveit.launch starts move_group); settings are its private parameters
(config/mover.yaml), the scene comes from config/scene.yaml.

At start-up it adds the table and the block (``pick_object``) to the planning scene and
checks they arrived, loads ``~waypoints`` (a list of ``[x, y, z, gripper_open]``), and
offers:

- ``reset`` (arm_move/Reset): puts the RealSense box at a pose (planning scene, and the
  simulation when ``/gazebo/set_model_state`` answers), then moves the arm Home and opens
  the gripper; ``clear_waypoints`` forgets the list. A box pose inside the table or the
  block (GOAL_IN_COLLISION) or reaching below the floor (INVALID_GOAL_CONSTRAINTS) is
  refused naming the pose and what it is in; nothing moves.
- ``step`` (arm_move/Step): moves the gripper point to a position, then opens or closes the
  gripper; only when all of that succeeded is ``[x, y, z, gripper_open]`` appended to
  ``~waypoints``. The arm is a 4-joint arm: it reaches a position with the waist facing it
  and a gripper pitch, which is chosen as the first of a fan (straight down first, then
  further and further from it) that has a collision-free IK solution (move_group's
  ``compute_ik``, seeded with the current state: the nearer elbow wins); the path to those
  joints is move_group's plan. The answer is MoveIt's error code: a target that is not
  finite or is below the floor INVALID_GOAL_CONSTRAINTS, no pitch reaches it
  NO_IK_SOLUTION, every reaching pose touches something GOAL_IN_COLLISION (naming it),
  a planning or execution failure move_group's code.
- ``follow`` (arm_move/Follow): steps through the waypoints once, or (``repeat``) over and
  over in the background until reset or another follow.

The block: closing the gripper with the block between the fingers attaches it to the
gripper (MoveIt's attach_object, the fingers as touch links); opening it detaches it where
it is. A second request while one runs is answered FAILURE (busy).
"""
from __future__ import annotations

import math
import os
import sys
import threading
import time
from dataclasses import dataclass
from typing import Any, Dict, List, Optional, Sequence, Tuple

import actionlib
from actionlib.action_client import CommState
import moveit_commander
import numpy as np
import rospkg
import rospy
import tf.transformations as tft
import yaml
from moveit_msgs.msg import (ExecuteTrajectoryAction, ExecuteTrajectoryGoal, MoveItErrorCodes
                             as Codes, RobotState)
from moveit_msgs.srv import (GetPositionIK, GetPositionIKRequest, GetStateValidity,
                             GetStateValidityRequest)
from sensor_msgs.msg import JointState

from arm_move.scene import (PICK_OBJECT, REALSENSE_BOX, TABLE, floor_height,
                            placement_problem, pose_stamped, unit_quaternion, yaw_quaternion)
from arm_move.srv import Follow, FollowResponse, Reset, ResetResponse, Step, StepResponse
from node_params import between, non_empty, parameter, positive, read

CODE_NAMES = {value: name for name, value in vars(Codes).items()
              if name.isupper() and isinstance(value, int)}
SCENE_POLL = 0.05        # wall s between looks at the planning scene after a change
RESULT_POLL = 0.005      # wall s between looks at a running motion


@dataclass(frozen=True)
class MoverSettings:
    """The mover's settings (private parameters, config/mover.yaml); a bad value stops the
    node naming it."""

    arm_group: str = parameter("interbotix_arm", non_empty, expected="the arm's MoveIt group")
    gripper_group: str = parameter("interbotix_gripper", non_empty,
                                   expected="the gripper's MoveIt group")
    open_state: str = parameter("Open", non_empty, expected="the gripper group's open state")
    closed_state: str = parameter("Closed", non_empty,
                                  expected="the gripper group's closed state")
    frame: str = parameter("px100/base_link", non_empty,
                           expected="the frame of step targets, box poses and the scene")
    preferred_pitch_degrees: float = parameter(
        90.0, between(-180.0, 180.0), expected="the gripper pitch tried first (90: down)")
    pitch_step_degrees: float = parameter(10.0, positive,
                                          expected="degrees > 0 between the pitches tried")
    pitch_range_degrees: List[float] = parameter(
        (-60.0, 150.0), expected="[lowest, highest] gripper pitch tried, degrees")
    ik_timeout: float = parameter(0.02, positive, expected="s > 0 compute_ik tries a pitch")
    planning_time: float = parameter(1.0, positive, expected="s > 0 move_group may plan")
    velocity_scaling: float = parameter(0.5, between(0.0, 1.0),
                                        expected="of the joints' speed limits, 0 to 1")
    acceleration_scaling: float = parameter(0.5, between(0.0, 1.0),
                                            expected="of the joints' acceleration limits")
    execution_timeout: float = parameter(60.0, positive,
                                         expected="s > 0 a motion may take to be done")
    start_timeout: float = parameter(
        60.0, positive, expected="wall s > 0 to wait for move_group at start-up")
    scene_config: str = parameter("", expected="the scene's yaml (empty: config/scene.yaml)")
    waypoints: Any = parameter(
        None, expected="a list of [x, y, z, gripper_open] (gripper_open true or false)")


class Outcome(Exception):
    """Ends a request early with a code and a message."""

    def __init__(self, code: int, message: str):
        super().__init__(message)
        self.code, self.message = code, message


def code_name(code: int) -> str:
    return f"{CODE_NAMES.get(code, 'code')} {code}"


def parse_waypoints(value) -> List[List]:
    """``~waypoints`` as [[x, y, z, open], ...]; ValueError naming the bad entry."""
    if value is None:
        return []
    if not isinstance(value, list):
        raise ValueError(f"~waypoints must be a list of [x, y, z, gripper_open], got {value!r}")
    parsed = []
    for index, entry in enumerate(value):
        if not isinstance(entry, (list, tuple)) or len(entry) != 4:
            raise ValueError(f"~waypoints[{index}] must be [x, y, z, gripper_open], got {entry!r}")
        numbers = [float(v) for v in entry[:3]]
        if not all(math.isfinite(n) for n in numbers):
            raise ValueError(f"~waypoints[{index}] has a position that is not finite: {entry!r}")
        parsed.append(numbers + [bool(entry[3])])
    return parsed


def pitch_fan(settings: MoverSettings) -> List[float]:
    """The gripper pitches tried, radians: the preferred one, then alternately beyond and
    short of it, one step further each time, within the range."""
    low, high = settings.pitch_range_degrees
    preferred, step = settings.preferred_pitch_degrees, settings.pitch_step_degrees
    fan, k = [preferred], 1
    while preferred + k * step <= high or preferred - k * step >= low:
        fan += [p for p in (preferred - k * step, preferred + k * step) if low <= p <= high]
        k += 1
    return [math.radians(p) for p in fan]


class Mover:
    def __init__(self, settings: MoverSettings, scene_config: dict):
        self.settings = settings
        self.scene_config = scene_config
        self.waypoints = parse_waypoints(settings.waypoints)
        self.pitches = pitch_fan(settings)
        self.floor = floor_height(scene_config)
        self._busy = threading.Lock()
        self._cycle: Optional[threading.Thread] = None
        self._stop_cycle = threading.Event()
        self.holding = False
        self.gripper_open: Optional[bool] = None   # as last sent and done; None: unknown

    # --- start-up ------------------------------------------------------------------------
    def start(self) -> None:
        """Connects to move_group (waiting for it at most start_timeout wall seconds), fills
        the planning scene, then offers the services."""
        ns = rospy.get_namespace()
        description = ns + "robot_description"
        deadline = time.monotonic() + self.settings.start_timeout  # wall: paused sims
        while not rospy.has_param(description):
            if time.monotonic() > deadline or rospy.is_shutdown():
                raise RuntimeError(f"no {description} after {self.settings.start_timeout:g} s:"
                                   " start the arm (xsarm_moveit.launch) first")
            time.sleep(SCENE_POLL)
        wait = max(1.0, deadline - time.monotonic())
        self.robot = moveit_commander.RobotCommander(robot_description=description, ns=ns)
        self.arm = moveit_commander.MoveGroupCommander(
            self.settings.arm_group, robot_description=description, ns=ns, wait_for_servers=wait)
        self.gripper = moveit_commander.MoveGroupCommander(
            self.settings.gripper_group, robot_description=description, ns=ns,
            wait_for_servers=wait)
        self.scene = moveit_commander.PlanningSceneInterface(ns=ns, synchronous=True)
        for group in (self.arm, self.gripper):
            group.set_planning_time(self.settings.planning_time)
            group.set_max_velocity_scaling_factor(self.settings.velocity_scaling)
            group.set_max_acceleration_scaling_factor(self.settings.acceleration_scaling)
        self.tip = self.arm.get_end_effector_link()
        self.arm_joints = set(self.arm.get_active_joints())
        self.fingers = self.robot.get_link_names(self.settings.gripper_group)
        self.finger_values = {
            gripper_open: self.gripper.get_named_target_values(state)
            for gripper_open, state in ((True, self.settings.open_state),
                                        (False, self.settings.closed_state))}
        rospy.wait_for_service(ns + "compute_ik", timeout=wait)
        self.ik = rospy.ServiceProxy(ns + "compute_ik", GetPositionIK)
        self.validity = rospy.ServiceProxy(ns + "check_state_validity", GetStateValidity)
        # ActionClient: rospy's SimpleActionClient may miss the end of a goal that is done
        # within a millisecond (the gripper already where it is sent) and wait for ever
        self.executor = actionlib.ActionClient(ns + "execute_trajectory",
                                               ExecuteTrajectoryAction)
        self._goal = None
        if not self.executor.wait_for_server(rospy.Duration(wait)):
            raise RuntimeError(f"move_group's {ns}execute_trajectory does not answer")
        self._fill_scene()
        rospy.Service("reset", Reset, self._serve_reset)
        rospy.Service("step", Step, self._serve_step)
        rospy.Service("follow", Follow, self._serve_follow)
        rospy.loginfo("mover: ready (group %s, tip %s), %d waypoints loaded",
                      self.settings.arm_group, self.tip, len(self.waypoints))

    def _fill_scene(self) -> None:
        """The table (its top table_clearance below the arm's base) and the block, as
        config/scene.yaml has them; checks they arrived."""
        frame, config = self.settings.frame, self.scene_config
        table = np.add(config[TABLE]["center"], (0.0, 0.0, -float(config["table_clearance"])))
        self.scene.add_box(TABLE, pose_stamped(frame, table), config[TABLE]["size"])
        block = config[PICK_OBJECT]
        self.scene.add_box(PICK_OBJECT, pose_stamped(frame, block["position"],
                                                     yaw_quaternion(block.get("yaw", 0.0))),
                           block["size"])
        self._wait_for_scene(lambda: {TABLE, PICK_OBJECT} <=
                             set(self.scene.get_known_object_names()), "the table and the block")
        rospy.loginfo("mover: the planning scene has the %s and the %s", TABLE, PICK_OBJECT)

    def _wait_for_scene(self, condition, what: str) -> None:
        """Waits (a few wall seconds at most) for move_group's scene to show a change: the
        topics that carry it are asynchronous, as MoveIt's tutorial says."""
        deadline = time.monotonic() + 5.0
        while not condition():
            if time.monotonic() > deadline:
                raise RuntimeError(f"the planning scene did not show {what}")
            time.sleep(SCENE_POLL)

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
        position = [pose.position.x, pose.position.y, pose.position.z]
        if not all(math.isfinite(v) for v in position):
            raise Outcome(Codes.INVALID_GOAL_CONSTRAINTS,
                          f"reset: box position {position} is not finite; nothing moved")
        o = pose.orientation
        try:
            orientation = unit_quaternion(o.x, o.y, o.z, o.w)
        except ValueError as error:
            raise Outcome(Codes.INVALID_GOAL_CONSTRAINTS,
                          f"reset: box {error}; nothing moved") from None
        block = self.scene_config[PICK_OBJECT]
        others = {} if self.holding else {
            PICK_OBJECT: (self._object_position(PICK_OBJECT), block["size"])}
        problem = placement_problem(self.scene_config, position, orientation, others)
        if problem is not None:
            where = (f"box pose (position {np.round(position, 4).tolist()}, orientation "
                     f"{np.round(orientation, 4).tolist()})")
            if problem == "floor":
                raise Outcome(Codes.INVALID_GOAL_CONSTRAINTS,
                              f"reset: the {where} reaches below the floor (z {self.floor:g} "
                              f"in {self.settings.frame}); the box was not moved, nothing moved")
            raise Outcome(Codes.GOAL_IN_COLLISION, f"reset: the {where} is inside the "
                          f"{problem}; the box was not moved, nothing moved")
        self.scene.add_box(REALSENSE_BOX, pose_stamped(self.settings.frame, position, orientation),
                           self.scene_config[REALSENSE_BOX]["size"])
        self._wait_for_scene(lambda: REALSENSE_BOX in self.scene.get_known_object_names(),
                             "the RealSense box")
        self._place_in_simulation(position, orientation)
        self._move_gripper(True)
        if self.holding:        # an open gripper lets go of the block
            self._detach_block()
        self.arm.set_named_target("Home")
        self._plan_and_execute(self.arm, "reset: Home")
        if request.clear_waypoints:
            self.waypoints = []
            rospy.set_param("~waypoints", [])
        return Codes.SUCCESS, (f"reset: box at {np.round(position, 3).tolist()}, arm at Home"
                               f"{', waypoints cleared' if request.clear_waypoints else ''}")

    def _object_position(self, name: str) -> Sequence[float]:
        p = self.scene.get_object_poses([name])[name].position
        return (p.x, p.y, p.z)

    def _place_in_simulation(self, position, orientation) -> None:
        """Moves the simulated box too, when a simulator answers (not with fake controllers
        or the real arm): the world's frame is the arm's (worlds/arm_box.world)."""
        try:
            from gazebo_msgs.msg import ModelState
            from gazebo_msgs.srv import SetModelState
            rospy.wait_for_service("/gazebo/set_model_state", timeout=0.5)
        except (ImportError, rospy.ROSException):
            return
        state = ModelState(model_name=REALSENSE_BOX, reference_frame="world")
        state.pose = pose_stamped("world", position, orientation).pose
        answer = rospy.ServiceProxy("/gazebo/set_model_state", SetModelState)(state)
        if not answer.success:
            rospy.logwarn("mover: the simulator did not move the box: %s", answer.status_message)

    # --- step ----------------------------------------------------------------------------
    def _step(self, request):
        target = (request.position.x, request.position.y, request.position.z)
        try:
            described = self._go_to(target, request.gripper_open, "step")
        except Outcome as outcome:
            raise Outcome(outcome.code, f"{outcome.message}; no waypoint stored") from None
        self.waypoints.append([float(v) for v in target] + [bool(request.gripper_open)])
        rospy.set_param("~waypoints", self.waypoints)
        return Codes.SUCCESS, (f"step: gripper at {np.round(target, 3).tolist()}, "
                               f"{'open' if request.gripper_open else 'closed'}; waypoint "
                               f"{len(self.waypoints)} stored ({described})")

    def _go_to(self, target, gripper_open: bool, what: str) -> str:
        """Moves the gripper point to ``target``, then opens or closes the gripper; what was
        chosen. Outcome when it cannot (nothing has moved when planning failed)."""
        if not all(math.isfinite(v) for v in target):
            raise Outcome(Codes.INVALID_GOAL_CONSTRAINTS,
                          f"{what}: target {list(target)} is not a finite position; nothing moved")
        if target[2] < self.floor:
            raise Outcome(Codes.INVALID_GOAL_CONSTRAINTS,
                          f"{what}: target {np.round(target, 3).tolist()} is below the floor "
                          f"(z {self.floor:g} in {self.settings.frame}); nothing moved")
        joints, pitch = self._reaching_joints(target, what)
        grasps = not gripper_open and not self.holding and self._between_fingers(target)
        self._check_gripper_at(joints, gripper_open, grasps, what)
        self.arm.set_joint_value_target(joints)
        planned = self._plan_and_execute(self.arm, what)
        if grasps:
            self._attach_block()
        self._move_gripper(gripper_open)
        if gripper_open and self.holding:
            self._detach_block()
        return (f"gripper pitch {math.degrees(pitch):.0f} deg, waist facing the target, joints "
                f"{np.round(list(joints.values()), 3).tolist()}; {planned}")

    def _reaching_joints(self, target, what: str) -> Tuple[Dict[str, float], float]:
        """The arm's joints putting the gripper point at ``target`` facing it, free of
        collisions, and the pitch; Outcome NO_IK_SOLUTION or GOAL_IN_COLLISION."""
        bearing = math.atan2(target[1], target[0])
        seed = self.robot.get_current_state()     # the same seed for every pitch
        for pitch in self.pitches:
            solution = self._ik(target, pitch, bearing, seed, avoid_collisions=True)
            if solution is not None:
                return solution, pitch
        for pitch in self.pitches:      # reachable, but touching something at every pitch?
            solution = self._ik(target, pitch, bearing, seed, avoid_collisions=False)
            if solution is not None:
                touched = self._contacts(solution)
                raise Outcome(Codes.GOAL_IN_COLLISION,
                              f"{what}: the gripper at {np.round(target, 3).tolist()} would "
                              f"touch {touched or 'something'} at every pitch; nothing moved")
        raise Outcome(Codes.NO_IK_SOLUTION,
                      f"{what}: {np.round(target, 3).tolist()} is out of reach (no IK solution "
                      f"at any gripper pitch from {self.settings.pitch_range_degrees[0]:g} to "
                      f"{self.settings.pitch_range_degrees[1]:g} deg); nothing moved")

    def _ik(self, target, pitch: float, bearing: float, seed: RobotState,
            avoid_collisions: bool) -> Optional[Dict[str, float]]:
        request = GetPositionIKRequest()
        ik = request.ik_request
        ik.group_name = self.settings.arm_group
        ik.ik_link_name = self.tip
        ik.avoid_collisions = avoid_collisions
        ik.timeout = rospy.Duration(self.settings.ik_timeout)
        ik.robot_state = seed
        ik.pose_stamped = pose_stamped(self.settings.frame, target,
                                       tft.quaternion_from_euler(0.0, pitch, bearing))
        answer = self.ik(request)
        if answer.error_code.val != Codes.SUCCESS:
            return None
        state = answer.solution.joint_state
        return {n: p for n, p in zip(state.name, state.position) if n in self.arm_joints}

    def _state(self, joints: Dict[str, float], gripper_open: Optional[bool] = None) -> RobotState:
        values = dict(joints)
        if gripper_open is not None:
            values.update(self.finger_values[gripper_open])
        state = RobotState(is_diff=True)
        state.joint_state = JointState(name=list(values), position=list(values.values()))
        return state

    def _contacts(self, joints: Dict[str, float], gripper_open: Optional[bool] = None,
                  allowed: Sequence[str] = ()) -> List[str]:
        """What the robot at ``joints`` touches (move_group's check_state_validity), each
        pair once, leaving out pairs with a body of ``allowed``."""
        answer = self.validity(GetStateValidityRequest(
            robot_state=self._state(joints, gripper_open)))
        found = []
        for contact in answer.contacts:
            pair = f"{contact.contact_body_1} and {contact.contact_body_2}"
            if pair not in found and not {contact.contact_body_1, contact.contact_body_2} & \
                    set(allowed):
                found.append(pair)
        return found

    def _between_fingers(self, target) -> bool:
        """Whether the block stands between the fingers with the gripper point at
        ``target``: its centre within half its width of it across, and within its height
        of it up or down (the fingertips reach below the gripper point)."""
        if PICK_OBJECT not in self.scene.get_known_object_names():
            return False
        offset = np.abs(np.subtract(self._object_position(PICK_OBJECT), target))
        size = np.asarray(self.scene_config[PICK_OBJECT]["size"], dtype=float)
        return bool(np.all(offset[:2] < size[:2] / 2) and offset[2] < size[2])

    def _check_gripper_at(self, joints, gripper_open: bool, grasps: bool, what: str) -> None:
        """Opening or closing the gripper at the target must be free as well (closing it
        around the block is a grasp): checked before anything moves."""
        touched = self._contacts(joints, gripper_open, allowed=[PICK_OBJECT] if grasps else [])
        if touched:
            raise Outcome(Codes.GOAL_IN_COLLISION,
                          f"{what}: {'opening' if gripper_open else 'closing'} the gripper at "
                          f"the target would touch {', '.join(touched)}; nothing moved")

    def _attach_block(self) -> None:
        self.arm.attach_object(PICK_OBJECT, self.tip, touch_links=self.fingers)
        self._wait_for_scene(lambda: PICK_OBJECT in self.scene.get_attached_objects(),
                             "the block attached")
        self.holding = True
        rospy.loginfo("mover: %s attached to %s", PICK_OBJECT, self.tip)

    def _detach_block(self) -> None:
        self.arm.detach_object(PICK_OBJECT)
        self._wait_for_scene(lambda: PICK_OBJECT not in self.scene.get_attached_objects(),
                             "the block detached")
        self.holding = False
        p = self._object_position(PICK_OBJECT)
        rospy.loginfo("mover: %s detached at %s", PICK_OBJECT, np.round(p, 3).tolist())

    def _move_gripper(self, gripper_open: bool) -> None:
        """Opens or closes the gripper, unless it already is: closed on the block, the
        fingers stop short of the closed state, and a plan from where they stopped starts
        the controller's command there, so the squeeze (the controller's position error)
        would vanish until the plan closes in again; the block falls out meanwhile."""
        if self.gripper_open == gripper_open:
            return
        self.gripper_open = None
        self.gripper.set_named_target(self.settings.open_state if gripper_open
                                      else self.settings.closed_state)
        self._plan_and_execute(self.gripper, "the gripper")
        self.gripper_open = gripper_open

    # --- planning and execution ----------------------------------------------------------
    def _plan_and_execute(self, group, what: str) -> str:
        """move_group's plan to the group's target, executed through execute_trajectory;
        how long each took. Outcome with move_group's code when either fails."""
        group.set_start_state_to_current_state()
        success, trajectory, planning_time, error = group.plan()
        if not success:
            raise Outcome(error.val, f"{what}: move_group could not plan ({code_name(error.val)});"
                                     " nothing moved")
        goal = self._goal = self.executor.send_goal(ExecuteTrajectoryGoal(trajectory=trajectory))
        deadline = rospy.get_time() + self.settings.execution_timeout
        while goal.get_comm_state() != CommState.DONE:
            if rospy.get_time() > deadline or rospy.is_shutdown():
                goal.cancel()
                raise Outcome(Codes.TIMED_OUT, f"{what}: the motion was not done within "
                                               f"{self.settings.execution_timeout:g} s")
            time.sleep(RESULT_POLL)
        result = goal.get_result()
        code = result.error_code.val if result is not None else Codes.PREEMPTED
        if code != Codes.SUCCESS:
            raise Outcome(code, f"{what}: execution failed ({code_name(code)}: "
                                f"{goal.get_goal_status_text()})")
        points = trajectory.joint_trajectory.points
        duration = points[-1].time_from_start.to_sec() if points else 0.0
        return f"planned in {1000 * planning_time:.0f} ms, moved for {duration:.2f} s"

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
                self._go_to((x, y, z), gripper_open, f"follow, waypoint {index + 1}")
            except Outcome as outcome:
                raise Outcome(outcome.code, outcome.message.replace("; nothing moved", "")) \
                    from None

    def _repeat(self, waypoints) -> None:
        with self._busy:
            while not self._stop_cycle.is_set() and not rospy.is_shutdown():
                try:
                    self._go_through(waypoints)
                except Outcome as outcome:
                    if not self._stop_cycle.is_set():
                        rospy.logwarn("mover: the repeating follow stopped: %s", outcome.message)
                    return

    def _end_cycle(self) -> None:
        if self._cycle is not None and self._cycle.is_alive():
            self._stop_cycle.set()
            if self._goal is not None:
                self._goal.cancel()
            self._cycle.join(timeout=self.settings.execution_timeout)
        self._cycle = None
        self._stop_cycle.clear()


def _read_yaml(path: str):
    with open(path, encoding="utf-8") as stream:
        return yaml.safe_load(stream)


def main(argv=None) -> None:
    moveit_commander.roscpp_initialize(argv if argv is not None else sys.argv)
    rospy.init_node("mover", argv=argv)
    package = rospkg.RosPack().get_path("arm_move")
    try:
        settings = read(MoverSettings, prefix="~",
                        defaults=_read_yaml(os.path.join(package, "config", "mover.yaml")))
        scene_config = _read_yaml(settings.scene_config
                                  or os.path.join(package, "config", "scene.yaml"))
        mover = Mover(settings, scene_config)
        mover.start()
    except (ValueError, KeyError, OSError, RuntimeError, rospy.ROSException) as error:
        rospy.logfatal("mover: %s", error)
        sys.exit(1)
    rospy.spin()
    moveit_commander.roscpp_shutdown()
