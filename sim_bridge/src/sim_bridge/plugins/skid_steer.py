"""``libgazebo_ros_skid_steer_drive.so``: four driven wheels, the two of each side together.

Parameters, names and defaults as gazebo_ros (noetic) reads them:

leftFrontJoint (left_front_joint), rightFrontJoint (right_front_joint),
leftRearJoint (left_rear_joint), rightRearJoint (right_rear_joint), wheelSeparation
(0.4 m), wheelDiameter (0.15 m), torque (5 N m), commandTopic (cmd_vel), odometryTopic
(odom), odometryFrame (odom), robotBaseFrame (base_footprint), broadcastTF (false),
updateRate (100 Hz: the odometry's rate, and the update slots at which the last cmd_vel
reaches the wheels, :class:`UpdateSlots`), covariance_x (0.0001), covariance_y (0.0001), covariance_yaw
(0.01), robotNamespace.

As in Gazebo, odometry is the true pose of the robot (a skid-steer robot's wheels slip
when it turns, so their speeds say little), with the given covariances on the pose's and
the twist's diagonals (gazebo_plugins/src/gazebo_ros_skid_steer_drive.cpp:208-230,
:460-465, :481-486), and position.z 0: Noetic's message never sets it (:453-454), while
the transform, when broadcastTF, has the true z (:441-448).
"""
from __future__ import annotations

import pybullet as pb

from sim_bridge.drive_kinematics import wheel_speeds
from sim_bridge.plugins.base import Rate, UpdateSlots
from sim_bridge.plugins.drive_base import DriveBase, covariance


class SkidSteer(DriveBase):
    def __init__(self, context, spec):
        super().__init__(context, spec, spec.text("commandTopic", "cmd_vel"),
                         spec.text("odometryTopic", "odom"))
        self.left = [self.joint("leftFrontJoint", "left_front_joint"),
                     self.joint("leftRearJoint", "left_rear_joint")]
        self.right = [self.joint("rightFrontJoint", "right_front_joint"),
                      self.joint("rightRearJoint", "right_rear_joint")]
        self.separation, self.radius = self.wheel_geometry(0.4, 0.15)
        self.torque = self.number("torque", 5.0)
        self.broadcast_tf = self.flag("broadcastTF", False)
        update_rate = self.number("updateRate", 100.0)
        self.rate = Rate(update_rate)  # the odometry
        self.slots = UpdateSlots(update_rate)  # the wheels' commands
        # gazebo_plugins/src/gazebo_ros_skid_steer_drive.cpp:208-230, on both diagonals
        # (:460-465, :481-486)
        self.covariance = covariance(self.number("covariance_x", 0.0001),
                                     self.number("covariance_y", 0.0001),
                                     self.number("covariance_yaw", 0.01))
        robot = context.robot
        self._joints = [robot.joint_index[j] for j in self.left + self.right]
        self.applied = None

    def quiet_until_ns(self, now_ns: int, step_ns: int) -> int:
        # the wheels' slots before the step (its start), the odometry's rate after it
        return min(self.slots.quiet_until_ns(now_ns) + step_ns, self.rate.quiet_until_ns())

    def before_step(self, now_ns: int) -> None:
        """Noetic's rate branch (gazebo_plugins/src/gazebo_ros_skid_steer_drive.cpp:350-383):
        the last command reaches the wheels at the update slots only."""
        if self.slots.due(now_ns) is None:
            return
        left, right = wheel_speeds(*self.command, self.separation, self.radius)
        targets = (left, left, right, right)
        if targets != self.applied:
            pb.setJointMotorControlArray(self.context.robot.id, self._joints, pb.VELOCITY_CONTROL,
                                         targetVelocities=list(targets),
                                         forces=[self.torque] * 4,
                                         physicsClientId=self.context.client)
            self.applied = targets

    def after_step(self, now_ns: int) -> None:
        if self.rate.due(now_ns):
            # gazebo_plugins/src/gazebo_ros_skid_steer_drive.cpp:453-454: position.z is
            # never set in the message; the transform has the pose's z (:441-448)
            self.publish_world_odometry(now_ns, self.covariance, self.broadcast_tf,
                                        message_z=0.0)

    def reset(self, now_ns: int) -> None:
        """Noetic's plugin has no Reset (gazebo_plugins/include/gazebo_plugins/
        gazebo_ros_skid_steer_drive.h:68-77 declares none, so ModelPlugin's empty one runs): after reset_world the wheels keep turning at the last
        command and the updates keep their schedule."""
