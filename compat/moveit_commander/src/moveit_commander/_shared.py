"""What the commanders of one process share, as MoveIt's C++ core shares them: the robot
model of each ``robot_description`` (read once from the parameter server) and the current
state from ``joint_states`` (MoveIt's CurrentStateMonitor)."""
from __future__ import annotations

import threading
import time
from typing import Dict, Tuple

import rospy
from actionlib.action_client import CommState
from sensor_msgs.msg import JointState

from moveit_commander.exception import MoveItCommanderException
from moveit_commander.roscpp_initializer import ensure_node
from moveit_core import robot_model
from moveit_core.robot_model import RobotModel

STATE_WAIT = 1.0        # s: the longest a state getter waits (getCurrentState's default wait,
                        # move_group_interface.cpp:661)
STATE_POLL = 0.005      # s: how often the wait looks at what joint_states brought

_LOCK = threading.Lock()
_MODELS: Dict[Tuple[str, str], "Robot"] = {}


def _name(ns: str, name: str) -> str:
    return rospy.names.ns_join(ns, name) if ns else name


class Robot:
    """A robot description's model, kinematics settings and current state."""

    def __init__(self, description: str, ns: str):
        ensure_node()
        # as MoveIt's RDFLoader: the description searched for from the node up, apart from
        # ``ns`` (Interbotix's movers pass robot_description="px100/robot_description" and
        # ns="px100"); the interfaces and joint_states are in ``ns``
        description = rospy.search_param(description) or description
        try:
            urdf = rospy.get_param(description)
            srdf = rospy.get_param(description + "_semantic")
        except KeyError as error:
            raise RuntimeError(f"Robot model parameter not found! Did you remap '{description}'? "
                               f"(the parameter {error} is not set: start the config "
                               "package's launch file first)") from None
        self.kinematics = rospy.get_param(description + "_kinematics", {}) or {}
        self.planning = rospy.get_param(description + "_planning", {}) or {}
        try:
            self.model: RobotModel = robot_model.load(
                str(urdf), str(srdf), self.planning.get("joint_limits", {}))
        except ValueError as error:
            raise RuntimeError(f"the robot model cannot be built: {error}") from error
        self.ns = ns
        self._positions: Dict[str, float] = {}
        self._stamps: Dict[str, float] = {}
        self._lock = threading.Lock()
        rospy.Subscriber(_name(ns, "joint_states"), JointState, self._update, queue_size=25)

    def _update(self, message: JointState) -> None:
        if len(message.name) != len(message.position):
            return
        stamp = message.header.stamp.to_sec()
        with self._lock:
            for name, value in zip(message.name, message.position):
                self._positions[name] = float(value)
                self._stamps[name] = stamp

    def positions(self, wait: float = STATE_WAIT) -> Dict[str, float]:
        """Every variable's current position, as MoveGroupInterface's getCurrentState
        (move_group_interface.cpp:661-680 on noetic-devel) takes it: waits up to ``wait`` s
        until every joint heard so far has been heard in a ``joint_states`` message stamped
        no earlier than the call (CurrentStateMonitor::waitForCurrentState(ros::Time::now(), wait),
        current_state_monitor.cpp:272-292), so that a state asked for right after a motion
        is the state after it, not the one a lagging subscriber last delivered. On timeout
        MoveIt logs what it logs there and answers nothing (an empty list, an identity pose);
        this answers the last state heard after the same messages (joints never heard at
        their defaults)."""
        wanted = set(self.model.variables)
        since = rospy.Time.now().to_sec()
        deadline = time.monotonic() + wait
        while True:
            with self._lock:
                # joints never heard do not count, unless none was
                # (current_state_monitor.cpp:95-114)
                heard = [self._stamps[j] for j in wanted if j in self._stamps]
                stale = not heard or min(heard) < since
                missing = wanted - set(self._positions)
                known = dict(self._positions)
            if not stale or time.monotonic() > deadline or rospy.is_shutdown():
                break
            time.sleep(STATE_POLL)
        if stale:
            rospy.loginfo_throttle(5.0, "Didn't receive robot state (joint angles) with recent "
                                   f"timestamp within {wait:g} seconds.\nCheck clock "
                                   "synchronization if your are running ROS across multiple "
                                   "machines!")
            rospy.logerr_throttle(5.0, "Failed to fetch current robot state")
        if missing:
            rospy.logwarn_throttle(5.0, "moveit_commander: no joint state heard for %s on %s "
                                   "within %.1f s", sorted(missing),
                                   rospy.resolve_name(_name(self.ns, "joint_states")), wait)
        return self.model.complete(known)


def state_message(shared: "Robot"):
    """The current state as a RobotState message: every single-dof joint, in model order."""
    from moveit_msgs.msg import RobotState
    model = shared.model
    positions = shared.positions()
    names = [j for j in model.joint_order if j in model.bounds]
    state = RobotState()
    state.joint_state = JointState(name=names, position=[positions[j] for j in names])
    state.joint_state.header.frame_id = model.model_frame
    return state


def robot(description: str = "robot_description", ns: str = "") -> Robot:
    key = (description, ns)
    with _LOCK:
        if key not in _MODELS:
            _MODELS[key] = Robot(description, ns)
        return _MODELS[key]


def group_or_raise(shared: Robot, name: str):
    try:
        return shared.model.group(name)
    except ValueError:
        raise RuntimeError(f"Group '{name}' was not found.") from None


def solver(shared: Robot, group: str):
    """The group's local IK solver (from robot_description_kinematics), or None."""
    from moveit_kinematics.kdl_solver import KdlSolver, SolverSettings
    entry = shared.kinematics.get(group)
    if not entry:
        return None
    try:
        return KdlSolver(shared.model, group, SolverSettings.from_parameters(entry))
    except (ValueError, TypeError):
        return None


def error(message: str) -> MoveItCommanderException:
    return MoveItCommanderException(message)


RESULT_POLL = 0.002      # wall s between looks at a goal's state


def result_of(handle):
    """The result of the goal whose ClientGoalHandle is ``handle``, waiting until it comes
    or ROS shuts down. Not SimpleActionClient's wait_for_result: a server that answers
    within a millisecond (a plan of one point) may deliver the goal's transitions before
    send_goal has stored its handle; rospy's simple client then drops them ("Got a
    transition callback on a goal handle that we're not tracking") and waits for ever."""
    while not rospy.is_shutdown() and handle.get_comm_state() != CommState.DONE:
        time.sleep(RESULT_POLL)
    return handle.get_result()
