"""A kinematic stand-in for the arm's controllers, as MoveIt's fake controllers: no
physics, the joints follow each trajectory exactly.

In the arm's namespace it offers ``arm_controller/follow_joint_trajectory`` (waist,
shoulder, elbow, wrist_angle) and ``gripper_controller/follow_joint_trajectory``
(left_finger, right_finger), and publishes ``joint_states`` for all six at ``~rate``.
The arm starts in the named pose ``~initial_pose`` (sleep), the gripper open. A goal with
unknown joints, mismatched lengths or non-finite numbers is refused (INVALID_JOINTS /
INVALID_GOAL); a new goal on a controller replaces the one running, which is preempted.
Trajectories are sampled as the simulator's JointTrajectoryController samples them
(sim_bridge.trajectory), on the ROS clock. ``~abort_after`` (s; negative, the default:
never) makes it a failing driver for tests: every arm goal is aborted that long into its
motion with PATH_TOLERANCE_VIOLATED, as a controller whose path tolerance was exceeded.
"""
from __future__ import annotations

import math
import os
import sys
import threading
from dataclasses import dataclass
from typing import Dict, Sequence

import actionlib
import numpy as np
import rospkg
import rospy
import yaml
from control_msgs.msg import (FollowJointTrajectoryAction, FollowJointTrajectoryResult)
from sensor_msgs.msg import JointState

from arm_move.kinematics import ARM_JOINTS, FINGER_JOINTS
from node_params import ParameterError, non_empty, parameter, positive, read
from sim_bridge.trajectory import Trajectory, Waypoint

Result = FollowJointTrajectoryResult


@dataclass(frozen=True)
class ExecutorSettings:
    """The private parameters, read with node_params (a bad one stops the node, named)."""

    robot_config: str = parameter("", expected="the arm's yaml (empty: config/px100.yaml)")
    initial_pose: str = parameter("sleep", non_empty,
                                  expected="a named pose of the arm's yaml (e.g. sleep, home)")
    rate: float = parameter(50.0, positive,
                            expected="Hz > 0 of joint_states and of trajectory sampling")
    abort_after: float = parameter(
        -1.0, expected="seconds into each arm motion to abort it (negative: never)")


class FakeController:
    """One controller: its joints' positions, and the trajectory they follow."""

    def __init__(self, name: str, joints: Sequence[str], positions: Dict[str, float],
                 lock: threading.Lock, rate: float, publish_state, abort_after: float = -1.0):
        self.publish_state = publish_state  # called once a goal is reached, before the result
        self.joints = list(joints)
        self.positions = positions
        self.lock = lock
        self.rate = rate
        self.abort_after = abort_after
        self.server = actionlib.SimpleActionServer(f"{name}/follow_joint_trajectory",
                                                   FollowJointTrajectoryAction,
                                                   execute_cb=self._execute, auto_start=False)
        self.server.start()

    def _refuse(self, code: int, text: str) -> None:
        rospy.logwarn("fake_executor: %s", text)
        self.server.set_aborted(Result(error_code=code, error_string=text), text)

    def _execute(self, goal) -> None:
        trajectory = goal.trajectory
        if sorted(trajectory.joint_names) != sorted(self.joints):
            return self._refuse(Result.INVALID_JOINTS, f"joints {trajectory.joint_names} are "
                                f"not this controller's {self.joints}")
        order = [trajectory.joint_names.index(j) for j in self.joints]
        points = []
        for point in trajectory.points:
            if len(point.positions) != len(self.joints) or \
                    (point.velocities and len(point.velocities) != len(self.joints)):
                return self._refuse(Result.INVALID_GOAL, "a point's lengths do not match the joints")
            values = list(point.positions) + list(point.velocities)
            if not all(math.isfinite(v) for v in values):
                return self._refuse(Result.INVALID_GOAL, "a point is not finite")
            points.append(Waypoint(point.time_from_start.to_sec(),
                                   np.array([point.positions[i] for i in order]),
                                   np.array([point.velocities[i] for i in order])
                                   if point.velocities else None))
        if not points:
            return self.server.set_succeeded(Result(error_code=Result.SUCCESSFUL))
        with self.lock:
            start = np.array([self.positions[j] for j in self.joints])
        plan = Trajectory(Waypoint(0.0, start, np.zeros(len(start))), points)
        began = rospy.get_time()
        rate = rospy.Rate(self.rate)
        while not rospy.is_shutdown():
            if self.server.is_preempt_requested():
                self.server.set_preempted(Result(error_code=Result.SUCCESSFUL), "preempted")
                return
            elapsed = rospy.get_time() - began
            positions, _, _ = plan.sample(elapsed)
            with self.lock:
                self.positions.update(zip(self.joints, map(float, positions)))
            if 0.0 <= self.abort_after <= elapsed:
                self.publish_state()
                text = f"aborted {self.abort_after:.2f} s into the motion (~abort_after)"
                rospy.logwarn("fake_executor: %s", text)
                self.server.set_aborted(Result(error_code=Result.PATH_TOLERANCE_VIOLATED,
                                               error_string=text), text)
                return
            if elapsed >= plan.end_time:
                break
            rate.sleep()
        self.publish_state()  # whoever hears the result can read the final state already
        self.server.set_succeeded(Result(error_code=Result.SUCCESSFUL))


def main(argv=None) -> None:
    rospy.init_node("fake_executor", argv=argv)
    package = rospkg.RosPack().get_path("arm_move")
    try:
        settings = read(ExecutorSettings)
        config_path = settings.robot_config or os.path.join(package, "config", "px100.yaml")
        with open(config_path) as stream:
            config = yaml.safe_load(stream)
        poses = sorted(config["named_poses"])
        if settings.initial_pose not in poses:
            raise ParameterError("~initial_pose", settings.initial_pose,
                                 f"is not a named pose of {config_path}",
                                 f"one of {', '.join(poses)}")
    except (ValueError, KeyError, OSError, TypeError) as error:
        rospy.logfatal("fake_executor: %s", error)
        sys.exit(1)
    pose_name, rate, abort_after = settings.initial_pose, settings.rate, settings.abort_after
    positions = dict(zip(ARM_JOINTS, map(float, config["named_poses"][pose_name])))
    positions.update({j: float(config["finger"]["max"]) for j in FINGER_JOINTS})
    lock = threading.Lock()
    publisher = rospy.Publisher("joint_states", JointState, queue_size=10)
    names = list(ARM_JOINTS + FINGER_JOINTS)

    def publish_state():
        with lock:
            state = JointState(name=names, position=[positions[n] for n in names])
        state.header.stamp = rospy.Time.now()
        try:
            publisher.publish(state)
        except rospy.ROSException:  # shutting down
            pass

    FakeController("arm_controller", ARM_JOINTS, positions, lock, rate, publish_state,
                   abort_after)
    FakeController("gripper_controller", FINGER_JOINTS, positions, lock, rate, publish_state)
    rospy.loginfo("fake_executor: joints follow trajectories exactly, starting at %s%s", pose_name,
                  f"; arm goals abort after {abort_after} s" if abort_after >= 0 else "")
    ticker = rospy.Rate(rate)
    while not rospy.is_shutdown():
        publish_state()
        try:
            ticker.sleep()
        except rospy.ROSInterruptException:
            break
