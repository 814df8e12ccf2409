"""What the drive plugins share: a Twist command in, odometry and TF out.

A command with NaN or inf is ignored with a throttled warning (the robot keeps its last
good command); ``world_odometry`` is Gazebo's "world" source: the true pose, and the
twist in the body frame.
"""
from __future__ import annotations

import math
from typing import Optional, Sequence, Tuple

from geometry_msgs.msg import TransformStamped, Twist
from nav_msgs.msg import Odometry

from sim_bridge.plugins.base import Plugin, PluginError, stamp
from sim_bridge.poses import yaw_from_quaternion


def covariance(x: float, y: float, yaw: float, others: float = 1e12) -> list:
    """A 6x6 pose or twist covariance, row-major: x, y, yaw given; z, roll, pitch unknown."""
    matrix = [0.0] * 36
    for index, value in ((0, x), (7, y), (14, others), (21, others), (28, others), (35, yaw)):
        matrix[index] = value
    return matrix


class DriveBase(Plugin):
    def __init__(self, context, spec, command_topic: str, odometry_topic: Optional[str]):
        """``odometry_topic`` None: no odometry publisher (``odom_out`` None)."""
        super().__init__(context, spec)
        self.odom_frame = self.frame(self.param("odometryFrame", "odom"))
        self.base_frame = self.frame(self.param("robotBaseFrame", "base_footprint"))
        self.command_topic = self.topic(command_topic)
        self.command: Tuple[float, float] = (0.0, 0.0)
        self.odom_out = None if odometry_topic is None else \
            context.bus.publisher(self.topic(odometry_topic), Odometry, queue_size=1)
        self._subscription = context.bus.subscriber(self.command_topic, Twist, self._on_command)

    def wheel_geometry(self, separation_default: float, diameter_default: float):
        """(wheelSeparation, wheel radius) from the plugin, both checked positive."""
        separation = self.number("wheelSeparation", separation_default)
        radius = self.number("wheelDiameter", diameter_default) / 2.0
        if separation <= 0 or radius <= 0:
            raise PluginError(f"plugin '{self.spec.name}': wheelSeparation and wheelDiameter "
                              "must be positive")
        return separation, radius

    def odometry_listened(self, with_tf: bool) -> bool:
        """Whether anyone receives the odometry or, when it is sent as TF, /tf: building
        the message for nobody cost 26 us (a quarter of the simulator's fixed cost per
        simulated second at a 1/240 s step, profiled)."""
        bus = self.context.bus
        return (self.odom_out is not None and bus.listened(self.odom_out)) or \
            (with_tf and bus.listened())

    def publish_world_odometry(self, now_ns: int, covariance_matrix: list, with_tf: bool,
                               message_z: Optional[float] = None) -> None:
        """The true pose as odometry (Gazebo's "world" source), and as TF when asked;
        ``message_z``, when given, is the message's position.z (the TF keeps the true z)."""
        if not self.odometry_listened(with_tf):
            return
        position, orientation, twist = self.world_odometry()
        true_z = position[2]
        if message_z is not None:
            position = (position[0], position[1], message_z)
        odometry = self.odometry_message(now_ns, position, orientation, twist,
                                         covariance_matrix, covariance_matrix)
        self.odom_out.publish(odometry)
        if with_tf:
            transform = self.odometry_transform(odometry)
            transform.transform.translation.z = true_z
            self.context.bus.send_transforms([transform])

    def _on_command(self, message: Twist) -> None:
        """rospy's thread: checks and stores the command, nothing else."""
        if self.finite_command(linear_x=message.linear.x, angular_z=message.angular.z):
            self.command = (message.linear.x, message.angular.z)

    def finite_command(self, **values: float) -> bool:
        """True when every value is finite; otherwise a throttled warning naming them."""
        if all(math.isfinite(v) for v in values.values()):
            return True
        listed = ", ".join(f"{name.replace('_', '.')}={value}" for name, value in values.items())
        self.context.bus.warn_throttled(
            f"{self.command_topic}:nan", 5.0,
            f"{self.command_topic}: ignoring a command with {listed}; all must be finite numbers")
        return False

    def odometry_message(self, now_ns: int, position: Sequence[float],
                         orientation: Sequence[float], twist: Sequence[float],
                         pose_covariance: list, twist_covariance: list) -> Odometry:
        """``twist`` = (forward, sideways, yaw rate) in the body frame."""
        message = Odometry()
        message.header.stamp = stamp(now_ns)
        message.header.frame_id = self.odom_frame
        message.child_frame_id = self.base_frame
        pose = message.pose.pose
        pose.position.x, pose.position.y, pose.position.z = position
        pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w = \
            orientation
        message.twist.twist.linear.x, message.twist.twist.linear.y = twist[0], twist[1]
        message.twist.twist.angular.z = twist[2]
        message.pose.covariance = pose_covariance
        message.twist.covariance = twist_covariance
        return message

    def world_odometry(self):
        """(position, orientation, body twist) of the robot's root link, from the world."""
        position, orientation = self.context.robot.base_pose()
        linear, angular = self.context.robot.base_twist()
        yaw = yaw_from_quaternion(orientation)
        forward = math.cos(yaw) * linear[0] + math.sin(yaw) * linear[1]
        sideways = math.cos(yaw) * linear[1] - math.sin(yaw) * linear[0]
        return position, orientation, (forward, sideways, angular[2])

    def odometry_transform(self, odometry: Odometry) -> TransformStamped:
        transform = TransformStamped()
        transform.header = odometry.header
        transform.child_frame_id = odometry.child_frame_id
        position = odometry.pose.pose.position
        transform.transform.translation.x = position.x
        transform.transform.translation.y = position.y
        transform.transform.translation.z = position.z
        transform.transform.rotation = odometry.pose.pose.orientation
        return transform

    def reset(self, now_ns: int) -> None:
        self.command = (0.0, 0.0)
