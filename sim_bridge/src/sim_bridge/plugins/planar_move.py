"""``libgazebo_ros_planar_move.so``: moves the model in the plane as commanded, holonomic.

Parameters as gazebo_ros (noetic): commandTopic (cmd_vel), odometryTopic (odom),
odometryFrame (odom), robotBaseFrame (base_footprint), odometryRate (20 Hz),
publishOdometryTf (true), cmdTimeout (-1: none; else seconds after which the last
command lapses), covariance_x, covariance_y, covariance_yaw (0.0001, 0.0001, 0.01),
robotNamespace. linear.x, linear.y and angular.z of the command (body frame) set the
model's velocity every step; its vertical motion is left to physics.
"""
from __future__ import annotations

import math

import pybullet as pb

from sim_bridge.plugins.base import Rate
from sim_bridge.plugins.drive_base import DriveBase, covariance
from sim_bridge.poses import yaw_from_quaternion


class PlanarMove(DriveBase):
    def __init__(self, context, spec):
        super().__init__(context, spec, spec.text("commandTopic", "cmd_vel"),
                         spec.text("odometryTopic", "odom"))
        self.rate = Rate(self.number("odometryRate", 20.0))
        self.publish_tf = self.flag("publishOdometryTf", True)
        self.timeout_ns = int(self.number("cmdTimeout", -1.0) * 1e9)
        self.covariance = covariance(self.number("covariance_x", 0.0001),
                                     self.number("covariance_y", 0.0001),
                                     self.number("covariance_yaw", 0.01))
        self.sideways = 0.0
        self._commanded_ns = None

    def _on_command(self, message) -> None:
        if self.finite_command(linear_x=message.linear.x, linear_y=message.linear.y,
                               angular_z=message.angular.z):
            self.command = (message.linear.x, message.angular.z)
            self.sideways = message.linear.y
            self._commanded_ns = -1  # stamped by the next step (simulated time)

    def before_step(self, now_ns: int) -> None:
        if self._commanded_ns == -1:
            self._commanded_ns = now_ns
        forward, turn = self.command
        sideways = self.sideways
        if self.timeout_ns > 0 and self._commanded_ns is not None and \
                now_ns - self._commanded_ns > self.timeout_ns:
            forward = sideways = turn = 0.0
        robot = self.context.robot
        _, orientation = robot.base_pose()
        linear, _ = robot.base_twist()
        yaw = yaw_from_quaternion(orientation)
        world_x = forward * math.cos(yaw) - sideways * math.sin(yaw)
        world_y = forward * math.sin(yaw) + sideways * math.cos(yaw)
        pb.resetBaseVelocity(robot.id, [world_x, world_y, float(linear[2])], [0.0, 0.0, turn],
                             physicsClientId=self.context.client)

    def after_step(self, now_ns: int) -> None:
        if self.rate.due(now_ns):
            self.publish_world_odometry(now_ns, self.covariance, self.publish_tf)

    def reset(self, now_ns: int) -> None:
        super().reset(now_ns)
        self.sideways = 0.0
        self._commanded_ns = None
        self.rate.reset(now_ns)
