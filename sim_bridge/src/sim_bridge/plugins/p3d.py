"""``libgazebo_ros_p3d.so``: a link's true pose and twist, as nav_msgs/Odometry.

Parameters as gazebo_ros (noetic): bodyName (the link; required), topicName (required),
frameName (world, or a link of the same model to report relative to), xyzOffsets,
rpyOffsets (a fixed offset applied to the reported pose), gaussianNoise (standard
deviation added to position and velocities, seeded), updateRate (0: every step),
robotNamespace. Velocities are in the reporting frame.
"""
from __future__ import annotations

import math

import numpy as np
import pybullet as pb
from nav_msgs.msg import Odometry

from sim_bridge.plugins.base import Plugin, PluginError, Rate, stamp
from sim_bridge.poses import quaternion_from_rpy, quaternion_matrix

WORLD_FRAMES = ("world", "/world", "map", "/map")


class P3D(Plugin):
    def __init__(self, context, spec):
        super().__init__(context, spec)
        robot = context.robot
        self.body = self.param("bodyName")
        if not self.body or self.body not in robot.link_index:
            raise PluginError(f"plugin '{spec.name}' ({spec.filename}) needs <bodyName>, a link "
                              f"of model '{context.model_name}' (got '{self.body}')")
        topic = self.param("topicName")
        if not topic:
            raise PluginError(f"plugin '{spec.name}' ({spec.filename}) needs <topicName>")
        self.reference = self.param("frameName", "world")
        if self.reference not in WORLD_FRAMES and self.reference not in robot.link_index:
            raise PluginError(f"plugin '{spec.name}': <frameName> '{self.reference}' is neither "
                              "world nor a link of the model")
        self.offset_position = self._vector("xyzOffsets")
        self.offset_orientation = quaternion_from_rpy(*self._vector("rpyOffsets"))
        self.noise = self.number("gaussianNoise", 0.0)
        self.rate = Rate(self.number("updateRate", 0.0))
        self.output = context.bus.publisher(self.topic(topic), Odometry, queue_size=1)

    def _vector(self, tag: str):
        text = self.param(tag, "0 0 0") or "0 0 0"
        try:
            values = [float(v) for v in text.split()]
        except ValueError:
            values = []
        if len(values) != 3 or not all(math.isfinite(v) for v in values):
            return list(self.unreadable(tag, text, "three numbers (x y z)", (0.0, 0.0, 0.0)))
        return values

    def _link_velocity(self, link: str):
        robot = self.context.robot
        index = robot.link_index[link]
        if index == -1:
            return robot.base_twist()
        state = pb.getLinkState(robot.id, index, computeLinkVelocity=1,
                                physicsClientId=self.context.client)
        # state[6] is the centre of mass's velocity; move it to the link frame's origin
        com, frame = np.asarray(state[0]), np.asarray(state[4])
        angular = np.asarray(state[7])
        return np.asarray(state[6]) + np.cross(angular, frame - com), angular

    def after_step(self, now_ns: int) -> None:
        if not self.rate.due(now_ns):
            return
        robot = self.context.robot
        position, orientation = robot.link_pose(self.body)
        position, orientation = pb.multiplyTransforms(position, orientation,
                                                      self.offset_position,
                                                      self.offset_orientation)
        linear, angular = self._link_velocity(self.body)
        if self.reference not in WORLD_FRAMES:
            frame_position, frame_orientation = robot.link_pose(self.reference)
            inverse = pb.invertTransform(frame_position, frame_orientation)
            position, orientation = pb.multiplyTransforms(*inverse, position, orientation)
            rotation = quaternion_matrix(frame_orientation).T
            frame_linear, frame_angular = self._link_velocity(self.reference)
            linear, angular = rotation @ (linear - frame_linear), rotation @ (angular - frame_angular)
        position = np.asarray(position, dtype=float)
        if self.noise > 0:
            rng = self.context.rng
            position = position + rng.normal(0.0, self.noise, 3)
            linear = linear + rng.normal(0.0, self.noise, 3)
            angular = angular + rng.normal(0.0, self.noise, 3)
        message = Odometry()
        message.header.stamp = stamp(now_ns)
        message.header.frame_id = (self.reference if self.reference in WORLD_FRAMES
                                   else self.frame(self.reference))
        message.child_frame_id = self.frame(self.body)
        pose = message.pose.pose
        pose.position.x, pose.position.y, pose.position.z = position.tolist()
        pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w = \
            orientation
        twist = message.twist.twist
        twist.linear.x, twist.linear.y, twist.linear.z = (float(v) for v in linear)
        twist.angular.x, twist.angular.y, twist.angular.z = (float(v) for v in angular)
        variance = self.noise * self.noise
        message.pose.covariance = [variance if i % 7 == 0 else 0.0 for i in range(36)]
        message.twist.covariance = list(message.pose.covariance)
        self.output.publish(message)

    def reset(self, now_ns: int) -> None:
        self.rate.reset(now_ns)
