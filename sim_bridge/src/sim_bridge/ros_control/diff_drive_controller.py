"""``diff_drive_controller/DiffDriveController``: two velocity-controlled wheel joints.

Parameters as ros_controllers': ``left_wheel``, ``right_wheel`` (a joint or a list of
joints; required), ``wheel_separation`` and ``wheel_radius`` (read from the URDF when not
given), ``wheel_separation_multiplier``, ``wheel_radius_multiplier`` (1), ``publish_rate``
(50 Hz), ``pose_covariance_diagonal``, ``twist_covariance_diagonal`` (6 numbers each),
``base_frame_id`` (base_link), ``odom_frame_id`` (odom), ``enable_odom_tf`` (true),
``cmd_vel_timeout`` (0.5 s), ``linear/x`` and ``angular/z`` limits (``has_velocity_limits``,
``max_velocity``, ``min_velocity``). Topics ``<controller>/cmd_vel`` and
``<controller>/odom``; odometry integrated from the wheels' encoders.
"""
from __future__ import annotations

import math

import numpy as np
from geometry_msgs.msg import TransformStamped, Twist
from nav_msgs.msg import Odometry

from sim_bridge.drive_kinematics import body_twist, integrate, wheel_speeds
from sim_bridge.plugins.base import PluginError, Rate, stamp
from sim_bridge.poses import quaternion_from_rpy
from sim_bridge.ros_control.controller_base import Controller
from urdf_tools.kinematics import link_transform


def _joint_list(value, what: str, name: str):
    joints = value if isinstance(value, list) else [value]
    if not joints or not all(isinstance(j, str) for j in joints):
        raise PluginError(f"controller '{name}': '{what}' must name a joint or a list of joints")
    return joints


class DiffDriveController(Controller):
    interface = "velocity"

    def __init__(self, name, params, hardware, io):
        super().__init__(name, params, hardware, io)
        self.left = _joint_list(self.required("left_wheel"), "left_wheel", name)
        self.right = _joint_list(self.required("right_wheel"), "right_wheel", name)
        self.claim(self.left + self.right)
        model = io.robot.model
        separation = self.params.get("wheel_separation")
        radius = self.params.get("wheel_radius")
        if separation is None:
            root = model.root()
            left = link_transform(model, root, model.joints[self.left[0]].child)[:3, 3]
            right = link_transform(model, root, model.joints[self.right[0]].child)[:3, 3]
            separation = float(np.linalg.norm(left - right))
        if radius is None:
            radius = self._radius_from_urdf(model, model.joints[self.left[0]].child)
        self.separation = float(separation) * self.number("wheel_separation_multiplier", 1.0)
        self.radius = float(radius) * self.number("wheel_radius_multiplier", 1.0)
        self.rate = Rate(self.number("publish_rate", 50.0))
        self.timeout_ns = int(self.number("cmd_vel_timeout", 0.5) * 1e9)
        # as written, no tf_prefix (ros_controllers noetic-devel 678b92a,
        # diff_drive_controller/src/diff_drive_controller.cpp:245-249, 708-709, 732-733)
        self.base_frame = str(self.params.get("base_frame_id", "base_link"))
        self.odom_frame = str(self.params.get("odom_frame_id", "odom"))
        self.publish_tf = bool(self.params.get("enable_odom_tf", True))
        self.pose_covariance = self._diagonal("pose_covariance_diagonal")
        self.twist_covariance = self._diagonal("twist_covariance_diagonal")
        self.limits = {axis: self.params.get(axis.split("/")[0], {}).get(axis.split("/")[1], {})
                       for axis in ("linear/x", "angular/z")}
        self.topic = io.topic(f"{name}/cmd_vel")
        self.odom_out = io.bus.publisher(io.topic(f"{name}/odom"), Odometry, queue_size=1)
        self._subscription = io.bus.subscriber(self.topic, Twist, self._on_command)
        self.command = (0.0, 0.0)
        self._commanded_ns = None
        self.pose = (0.0, 0.0, 0.0)
        self.twist = (0.0, 0.0)

    @staticmethod
    def _radius_from_urdf(model, link: str) -> float:
        for shape in model.links[link].collisions:
            if shape.geometry.kind in ("cylinder", "sphere"):
                return shape.geometry.radius
        raise PluginError(f"wheel link '{link}' has no cylinder or sphere collision; give "
                          "wheel_radius")

    def _diagonal(self, key: str):
        values = self.params.get(key, [0.0] * 6)
        if not isinstance(values, list) or len(values) != 6:
            raise PluginError(f"controller '{self.name}': '{key}' must be 6 numbers")
        matrix = [0.0] * 36
        for i, value in enumerate(values):
            matrix[i * 7] = float(value)
        return matrix

    def _on_command(self, message: Twist):
        linear, angular = message.linear.x, message.angular.z
        if not (math.isfinite(linear) and math.isfinite(angular)):
            self.io.bus.warn_throttled(f"{self.topic}:nan", 5.0,
                                       f"{self.topic}: ignoring linear.x={linear}, "
                                       f"angular.z={angular}; both must be finite numbers")
            return
        self.command = (linear, angular)
        self._commanded_ns = -1  # stamped by the next update (simulated time)

    def _limit(self, axis: str, value: float) -> float:
        limits = self.limits[axis]
        if limits.get("has_velocity_limits"):
            high = float(limits.get("max_velocity", math.inf))
            low = float(limits.get("min_velocity", -high))
            value = min(max(value, low), high)
        return value

    def start(self, now_ns):
        self.command = (0.0, 0.0)
        self.rate.reset(now_ns)

    def update(self, now_ns, dt):
        if self._commanded_ns == -1:
            self._commanded_ns = now_ns
        linear, angular = self.command
        if self._commanded_ns is not None and now_ns - self._commanded_ns > self.timeout_ns:
            linear = angular = 0.0
        left, right = wheel_speeds(self._limit("linear/x", linear),
                                   self._limit("angular/z", angular), self.separation,
                                   self.radius)
        for joint in self.left:
            self.hardware.joints[joint].command = left
        for joint in self.right:
            self.hardware.joints[joint].command = right
        left_speed = np.mean([self.hardware.state(j)[1] for j in self.left])
        right_speed = np.mean([self.hardware.state(j)[1] for j in self.right])
        self.twist = body_twist(left_speed, right_speed, self.separation, self.radius)
        self.pose = integrate(*self.pose, *self.twist, dt)
        if self.rate.due(now_ns):
            self._publish(now_ns)

    def _publish(self, now_ns):
        x, y, yaw = self.pose
        orientation = quaternion_from_rpy(0.0, 0.0, yaw)
        message = Odometry()
        message.header.stamp = stamp(now_ns)
        message.header.frame_id = self.odom_frame
        message.child_frame_id = self.base_frame
        message.pose.pose.position.x, message.pose.pose.position.y = x, y
        q = message.pose.pose.orientation
        q.x, q.y, q.z, q.w = orientation
        message.twist.twist.linear.x, message.twist.twist.angular.z = self.twist
        message.pose.covariance = self.pose_covariance
        message.twist.covariance = self.twist_covariance
        self.odom_out.publish(message)
        if self.publish_tf:
            transform = TransformStamped()
            transform.header = message.header
            transform.child_frame_id = self.base_frame
            transform.transform.translation.x, transform.transform.translation.y = x, y
            transform.transform.rotation = message.pose.pose.orientation
            self.io.bus.send_transforms([transform])

    def close(self):
        self._subscription.unregister()
        self.odom_out.unregister()
