"""``moveit_simple_controller_manager/MoveItSimpleControllerManager``: execution through
the robot's (or the simulator's) controllers. Each ``controller_list`` entry (``name``,
``action_ns``, ``type``: FollowJointTrajectory or GripperCommand, ``joints``) is an action
client of ``<name>/<action_ns>`` in move_group's namespace; an entry missing one of them
is left out with an error naming it, as MoveIt does, and so is a controller whose action
server does not answer within ``trajectory_execution/controller_connection_timeout``
(15 s). A GripperCommand controller is sent the last point's position of its
``command_joint`` (its first joint) with ``max_effort``."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Dict, List, Sequence

import actionlib
from actionlib.action_client import CommState
import rospy
from actionlib_msgs.msg import GoalStatus
from control_msgs.msg import (FollowJointTrajectoryAction, FollowJointTrajectoryGoal,
                              GripperCommandAction, GripperCommandGoal)

PLUGIN = "moveit_simple_controller_manager/MoveItSimpleControllerManager"
CONNECTION_TIMEOUT = 15.0        # s, controller_connection_timeout's default
TYPES = {"FollowJointTrajectory": FollowJointTrajectoryAction,
         "GripperCommand": GripperCommandAction}


@dataclass
class SimpleController:
    name: str
    joints: List[str]
    kind: str
    client: object
    max_effort: float = 0.0
    command_joint: str = ""


class Run:
    """One goal sent to a controller. Its state is read from the goal's handle: rospy's
    SimpleActionClient drops the transitions of a goal that ends within a millisecond (a
    gripper already where it is sent) when they come before send_goal has stored the
    handle, and its done callback never came: the execution waited for ever."""

    def __init__(self, handle):
        self.handle = handle

    def done(self) -> bool:
        return self.handle.get_comm_state() == CommState.DONE

    @property
    def succeeded(self) -> bool:
        return self.done() and self.handle.get_goal_status() == GoalStatus.SUCCEEDED

    def stop(self) -> None:
        if not self.done():
            self.handle.cancel()


class SimpleControllerManager:
    def __init__(self, entries: Sequence[dict], connection_timeout: float = CONNECTION_TIMEOUT):
        self.controllers: Dict[str, SimpleController] = {}
        for index, entry in enumerate(entries or []):
            missing = [k for k in ("name", "type", "joints") if not (isinstance(entry, dict)
                                                                    and entry.get(k))]
            if missing or "action_ns" not in entry:
                rospy.logerr("controller_list entry %d lacks %s: left out (%s)", index + 1,
                             ", ".join(missing + (["action_ns"] if isinstance(entry, dict) and
                                                  "action_ns" not in entry else [])), entry)
                continue
            kind = str(entry["type"])
            if kind not in TYPES:
                rospy.logerr("controller '%s': type '%s' is not one of %s: left out",
                             entry["name"], kind, ", ".join(TYPES))
                continue
            action = f"{entry['name']}/{entry['action_ns']}" if entry["action_ns"] \
                else str(entry["name"])
            client = actionlib.ActionClient(action, TYPES[kind])
            if not client.wait_for_server(rospy.Duration(connection_timeout)):
                rospy.logerr("controller '%s': no action server '%s' answered within %.0f s: "
                             "left out", entry["name"], rospy.resolve_name(action),
                             connection_timeout)
                continue
            joints = [str(j) for j in entry["joints"]]
            self.controllers[str(entry["name"])] = SimpleController(
                str(entry["name"]), joints, kind, client, float(entry.get("max_effort", 0.0)),
                str(entry.get("command_joint", joints[0])))

    def joints_of(self, name: str) -> List[str]:
        return self.controllers[name].joints

    def start(self, name: str, joints: Sequence[str], trajectory) -> Run:
        controller = self.controllers[name]
        if controller.kind == "FollowJointTrajectory":
            goal = FollowJointTrajectoryGoal(trajectory=trajectory)
        else:
            goal = GripperCommandGoal()
            last = trajectory.points[-1].positions
            goal.command.position = last[list(joints).index(controller.command_joint)] \
                if controller.command_joint in joints else last[0]
            goal.command.max_effort = controller.max_effort
        return Run(controller.client.send_goal(goal))
