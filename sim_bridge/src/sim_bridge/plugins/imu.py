"""``<sensor type="imu">`` with ``libgazebo_ros_imu_sensor.so``: orientation, angular
velocity and linear acceleration of the sensor's link, in the sensor's frame.

From the sensor: ``<pose>`` (in the link), ``<update_rate>`` (Hz; 0 every step): when the
sensor measures. From the plugin, as gazebo_ros (noetic-devel f9e1a46,
gazebo_plugins/src/gazebo_ros_imu_sensor.cpp) reads them: topicName (imu_data, :197),
frameName (required: without it the plugin stops loading and publishes nothing, :207-210;
the header's frame as written, no tf_prefix, a leading '/' kept, :204, :138),
updateRateHZ (1 Hz when absent, :221: at most one message per 1/updateRateHZ s of the
sensor's update times, so never faster than the sensor; 0: every step, :99),
gaussianNoise (standard deviation added to each of the orientation quaternion's four
components, which is then not normalised, and to the angular velocity's and the
acceleration's, :111-123; drawn from the world's seeded generator),
xyzOffset, rpyOffset, robotNamespace.

The accelerometer reads specific force, as a real one does: at rest and level it reads
+g upwards (9.8 on z). Acceleration is the change of velocity between the sensor's
updates. A message carries the time of the sensor's last update, as upstream's (:139-140).
"""
from __future__ import annotations

import numpy as np
import pybullet as pb
from sensor_msgs.msg import Imu

from sim_bridge.plugins.base import Plugin, PluginError, Rate, stamp
from sim_bridge.plugins.body_state import to_sensor, vector3
from sim_bridge.poses import pose6_to_position_quaternion, quaternion_from_rpy

# the values a message's noise is drawn for: the quaternion's 4, the acceleration's and the
# angular velocity's 3 each (gazebo_plugins/src/gazebo_ros_imu_sensor.cpp:112-123)
NOISY_VALUES = 10


def _plus_cross(base, w, point, origin):
    """``base + w x (point - origin)`` for 3-vectors, in floats."""
    rx, ry, rz = point[0] - origin[0], point[1] - origin[1], point[2] - origin[2]
    wx, wy, wz = w
    return (base[0] + wy * rz - wz * ry, base[1] + wz * rx - wx * rz,
            base[2] + wx * ry - wy * rx)


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
        frame = self.param("frameName")
        if frame is None:  # gazebo_plugins/src/gazebo_ros_imu_sensor.cpp:207-210, :71-75
            raise PluginError(
                f"sensor '{sensor.name}' needs <frameName> (the messages' frame, e.g. "
                f"<frameName>{self.link}</frameName>): gazebo_ros_imu_sensor stops loading "
                "without it ('missing <frameName>, cannot proceed') and publishes nothing")
        # the sensor measures at its <update_rate>; the plugin publishes a measurement once
        # its time is 1/updateRateHZ past the last message's (1 Hz when absent, 0: every
        # step): gazebo_plugins/src/gazebo_ros_imu_sensor.cpp:97-100, :221
        self.sensor_rate = Rate(self._update_rate(sensor))
        self.publish_period_ns = self._publish_period_ns(self.number("updateRateHZ", 1.0))
        self.noise = self.number("gaussianNoise", 0.0)
        # the header's frame is the tag's text as written: no tf_prefix, a leading '/'
        # kept (gazebo_plugins/src/gazebo_ros_imu_sensor.cpp:204, :138; unlike the laser's,
        # range's and camera's tf::resolve)
        self.frame_id = frame
        self.output = context.bus.publisher(self.topic(self.param("topicName", "imu_data")),
                                            Imu, queue_size=1)
        self._last = None  # (time ns, velocity of the sensor point in the world)
        self._measured = None  # (time ns, orientation, specific force, body rate)
        # upstream's last_time starts at the sensor's LastUpdateTime when the plugin loads:
        # 0, a sensor loaded and not yet updated (gazebo_ros_imu_sensor.cpp:89)
        self._published_ns = 0

    @staticmethod
    def _publish_period_ns(rate_hz: float) -> float:
        """Upstream skips while (sensor time - last) < 1.0 / updateRateHZ (seconds)."""
        return 1e9 / rate_hz if rate_hz > 0 else 0.0

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
            angular = state[7]
            # the link frame's velocity: its centre of mass's plus w x (frame - centre)
            linear = _plus_cross(state[6], angular, state[4], state[0])
        position, orientation = pb.multiplyTransforms(link_position, link_orientation, *self.mount)
        velocity = _plus_cross(linear, angular, position, link_position)
        return orientation, velocity, tuple(float(w) for w in angular)

    def _measure(self, now_ns: int) -> None:
        """The sensor's update: what it reads now (acceleration since its last update).
        In floats: numpy's cross products and 4x4 matrix on 3-vectors cost most of the
        sensor's 7 us a step at 100 Hz (issue 36)."""
        orientation, velocity, angular = self._sensor_state()
        if self._last is None or now_ns <= self._last[0]:
            acceleration = (0.0, 0.0, 0.0)
        else:
            dt = (now_ns - self._last[0]) / 1e9
            acceleration = tuple((v - last) / dt for v, last in zip(velocity, self._last[1]))
        self._last = (now_ns, velocity)
        gravity = self.context.gravity
        specific_force = np.array(to_sensor(orientation, [a - g for a, g in
                                                          zip(acceleration, gravity)]))
        body_rate = np.array(to_sensor(orientation, angular))
        self._measured = (now_ns, orientation, specific_force, body_rate)

    def after_step(self, now_ns: int) -> None:
        if self.sensor_rate.due(now_ns):
            self._measure(now_ns)
        if self._measured is None:
            return
        measured_ns, orientation, specific_force, body_rate = self._measured
        if measured_ns - self._published_ns < self.publish_period_ns:
            return
        self._published_ns = measured_ns
        if not self.context.bus.listened(self.output):
            return  # upstream fills and publishes only while subscribed (:102)
        if self.noise > 0:
            # gazebo_plugins/src/gazebo_ros_imu_sensor.cpp:111-123: one draw for each of the
            # quaternion's x, y, z, w, then the acceleration's and the rate's three; the
            # noisy quaternion is published as it is, not normalised
            noise = self.context.rng.normal(0.0, self.noise, NOISY_VALUES)
            orientation = tuple(np.asarray(orientation) + noise[:4])
            specific_force = specific_force + noise[4:7]
            body_rate = body_rate + noise[7:]
        message = Imu()
        message.header.stamp = stamp(measured_ns)
        message.header.frame_id = self.frame_id
        message.orientation.x, message.orientation.y, message.orientation.z, \
            message.orientation.w = (float(v) for v in orientation)
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
        # time goes on through a reset here, so the last message's time stays
        self.sensor_rate.reset(now_ns)
        self._last = self._measured = None
