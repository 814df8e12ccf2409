"""``<sensor type="imu">`` with ``libgazebo_ros_imu_sensor.so``: orientation, angular
velocity and linear acceleration of the sensor's link, in the sensor's frame.

From the sensor: ``<pose>`` (in the link), ``<update_rate>`` (Hz; 0 every step). From the
plugin, as gazebo_ros (noetic): topicName (imu), frameName (the link), updateRateHZ
(overrides update_rate when given), gaussianNoise (standard deviation on angular
velocity and acceleration, seeded), xyzOffset, rpyOffset, robotNamespace.

The accelerometer reads specific force, as a real one does: at rest and level it reads
+g upwards (9.8 on z). Acceleration is the change of velocity over the update period.
"""
from __future__ import annotations

import numpy as np
import pybullet as pb
from sensor_msgs.msg import Imu

from sim_bridge.plugins.base import Plugin, PluginError, Rate, stamp
from sim_bridge.plugins.body_state import vector3
from sim_bridge.poses import pose6_to_position_quaternion, quaternion_from_rpy, quaternion_matrix


class ImuSensor(Plugin):
    ABSENT_NAMESPACE_IS_MODEL = True  # gazebo_ros_imu_sensor: "/<model>/" when absent

    def __init__(self, context, spec, sensor):
        super().__init__(context, spec)
        self.link = sensor.link
        if self.link not in context.robot.link_index:
            raise PluginError(f"sensor '{sensor.name}' is on link '{self.link}', which the model "
                              "does not have")
        pose_text = sensor.element.findtext("pose")
        pose = [float(v) for v in pose_text.split()] if pose_text else [0.0] * 6
        position, orientation = pose6_to_position_quaternion(pose)
        offset = vector3(self, "xyzOffset")
        rpy = vector3(self, "rpyOffset")
        self.mount = pb.multiplyTransforms(position, orientation, offset, quaternion_from_rpy(*rpy))
        rate = self.number("updateRateHZ", self._update_rate(sensor))
        self.rate = Rate(rate)
        self.noise = self.number("gaussianNoise", 0.0)
        self.frame_id = self.frame(self.param("frameName", self.link))
        self.output = context.bus.publisher(self.topic(self.param("topicName", "imu")), Imu,
                                            queue_size=1)
        self._last = None  # (time ns, velocity of the sensor point in the world)

    def _update_rate(self, sensor) -> float:
        """The sensor's <update_rate> (0, every step, when absent or unreadable: Gazebo's
        SDF parser reports such a value and keeps the default)."""
        text = (sensor.element.findtext("update_rate") or "").strip()
        if not text:
            return 0.0
        try:
            rate = float(text)
        except ValueError:
            rate = float("nan")
        return rate if np.isfinite(rate) and rate >= 0 else \
            self.unreadable("update_rate", text, "a rate in Hz", 0.0)

    def _sensor_state(self):
        robot = self.context.robot
        index = robot.link_index[self.link]
        if index == -1:
            link_position, link_orientation = robot.base_pose()
            linear, angular = robot.base_twist()
        else:
            state = pb.getLinkState(robot.id, index, computeLinkVelocity=1,
                                    physicsClientId=self.context.client)
            link_position, link_orientation = state[4], state[5]
            angular = np.asarray(state[7])
            linear = np.asarray(state[6]) + np.cross(angular, np.asarray(state[4]) - state[0])
        position, orientation = pb.multiplyTransforms(link_position, link_orientation, *self.mount)
        velocity = linear + np.cross(angular, np.asarray(position) - np.asarray(link_position))
        return orientation, velocity, angular

    def after_step(self, now_ns: int) -> None:
        if not self.rate.due(now_ns):
            return
        orientation, velocity, angular = self._sensor_state()
        if self._last is None or now_ns <= self._last[0]:
            acceleration = np.zeros(3)
        else:
            acceleration = (velocity - self._last[1]) / ((now_ns - self._last[0]) / 1e9)
        self._last = (now_ns, velocity)
        to_sensor = quaternion_matrix(orientation).T
        specific_force = to_sensor @ (acceleration - np.asarray(self.context.gravity))
        body_rate = to_sensor @ angular
        if self.noise > 0:
            specific_force = specific_force + self.context.rng.normal(0.0, self.noise, 3)
            body_rate = body_rate + self.context.rng.normal(0.0, self.noise, 3)
        message = Imu()
        message.header.stamp = stamp(now_ns)
        message.header.frame_id = self.frame_id
        message.orientation.x, message.orientation.y, message.orientation.z, \
            message.orientation.w = orientation
        message.angular_velocity.x, message.angular_velocity.y, message.angular_velocity.z = \
            (float(v) for v in body_rate)
        message.linear_acceleration.x, message.linear_acceleration.y, \
            message.linear_acceleration.z = (float(v) for v in specific_force)
        variance = self.noise * self.noise
        diagonal = [variance, 0, 0, 0, variance, 0, 0, 0, variance]
        message.orientation_covariance = list(diagonal)
        message.angular_velocity_covariance = list(diagonal)
        message.linear_acceleration_covariance = list(diagonal)
        self.output.publish(message)

    def reset(self, now_ns: int) -> None:
        self.rate.reset(now_ns)
        self._last = None
