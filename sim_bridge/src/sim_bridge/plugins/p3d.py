"""``libgazebo_ros_p3d.so``: a link's true pose and twist, as nav_msgs/Odometry.

Parameters as gazebo_ros (noetic-devel f9e1a46, gazebo_plugins/src/gazebo_ros_p3d.cpp)
reads them: bodyName (the link; required), topicName (required), frameName (world, or a
link of the same model to report relative to), xyzOffset and rpyOffset (singular, as every
gazebo_plugins release spells them, :97 and :105; 0), gaussianNoise (standard deviation
added to the twist alone, seeded; :327-339), updateRate (0: every step), robotNamespace.
The plural ``<xyzOffsets>`` / ``<rpyOffsets>`` are no parameter of it: Gazebo ignores them,
and the spawn names them as tags the plugin does not read.

The maths is Noetic's, in its order (:279-304): relative to a reference link f,
p = R_f^T (p - p_f), q = q_link * q_f^-1, v = R_f (v - v_f), w = R_f (w - w_f) (ignition's
RotateVector, where the position uses RotateVectorReverse); then p = p + xyzOffset (world
axes) and q = q_rpyOffset * q. With world as the frame, the twist is in world axes.
"""
from __future__ import annotations

import numpy as np
import pybullet as pb
from nav_msgs.msg import Odometry

from sim_bridge.plugins.base import Plugin, PluginError, Rate, stamp
from sim_bridge.plugins.body_state import q_inverse, q_multiply, q_normalized, vector3
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
        # singular, as Noetic reads them (gazebo_plugins/src/gazebo_ros_p3d.cpp:97, :105);
        # the plural is no parameter of any release and stays unread (a spawn warning)
        self.offset_position = vector3(self, "xyzOffset")
        self.offset_orientation = quaternion_from_rpy(*vector3(self, "rpyOffset"))
        self.noise = self.number("gaussianNoise", 0.0)
        self.rate = Rate(self.number("updateRate", 0.0))
        self.output = context.bus.publisher(self.topic(topic), Odometry, queue_size=1)

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

    def quiet_until_ns(self, now_ns: int, step_ns: int) -> int:
        return self.rate.quiet_until_ns()  # after_step asks the rate first

    def after_step(self, now_ns: int) -> None:
        # only while someone subscribes, as Noetic's (gazebo_plugins/src/gazebo_ros_p3d.cpp:243);
        # the slots keep their times meanwhile (upstream's last time stays, so its first
        # message heard comes at once, here at the next slot)
        if not self.rate.due(now_ns) or not self.context.bus.listened(self.output):
            return
        robot = self.context.robot
        position, orientation = robot.link_pose(self.body)
        position = np.asarray(position, dtype=float)
        linear, angular = self._link_velocity(self.body)
        if self.reference not in WORLD_FRAMES:
            # Noetic's maths as it is (gazebo_plugins/src/gazebo_ros_p3d.cpp:291-296): the
            # position into the frame (RotateVectorReverse), the frame's rotation taken off on
            # the right (pose.Rot() *= frame.Rot().Inverse()), the velocities turned by the
            # frame's rotation (RotateVector)
            frame_position, frame_orientation = robot.link_pose(self.reference)
            rotation = quaternion_matrix(frame_orientation)
            position = rotation.T @ (position - np.asarray(frame_position, dtype=float))
            orientation = q_multiply(orientation, q_inverse(frame_orientation))
            frame_linear, frame_angular = self._link_velocity(self.reference)
            linear = rotation @ (linear - frame_linear)
            angular = rotation @ (angular - frame_angular)
        # then the offsets on the world's side (gazebo_plugins/src/gazebo_ros_p3d.cpp:301-304)
        position = position + self.offset_position
        orientation = q_normalized(q_multiply(self.offset_orientation, orientation))
        if self.noise > 0:  # the twist alone (gazebo_plugins/src/gazebo_ros_p3d.cpp:327-339)
            rng = self.context.rng
            linear = linear + rng.normal(0.0, self.noise, 3)
            angular = angular + rng.normal(0.0, self.noise, 3)
        message = Odometry()
        message.header.stamp = stamp(now_ns)
        # the frame through tf::resolve with the tf_prefix, the body's link as written
        # (gazebo_plugins/src/gazebo_ros_p3d.cpp:144-146, :254, :258)
        message.header.frame_id = self.frame(self.reference)
        message.child_frame_id = self.body
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
