"""``libhector_gazebo_ros_imu.so``: hector_gazebo_plugins' IMU, a model plugin, with
hector's error model (hector_sensor_model.py) on the accelerometer, the gyroscope and
the heading.

Parameters as hector_gazebo_plugins (melodic-devel, its last ROS 1 line) reads them:

- bodyName (default: the model's canonical link, its URDF root), frameId (the link's
  name, used as written), topicName (``imu``), biasTopicName (``<topicName>/bias``),
  serviceName (``<topicName>/calibrate``), robotNamespace;
- accelOffset, accelDrift, accelDriftFrequency, accelGaussianNoise, accelScaleError and
  the same with ``rate`` (three numbers each, m/s² and rad/s), yawOffset, yawDrift,
  yawDriftFrequency, yawGaussianNoise, yawScaleError (one number each, rad);
- gaussianNoise (gazebo_ros_imu's name): when not 0, the accelerometer's and the
  gyroscope's Gaussian noise on every axis;
- rpyOffset (the sensor's rotation, applied on the world's side of the link's:
  ``q = q_rpyOffset * q_link``); xyzOffset is read and has no effect, as upstream;
- updateRate (0: every step), updatePeriod, updateOffset.

What it publishes, as hector computes it:

- ``linear_acceleration``: specific force in the sensor's frame, the link's acceleration
  minus gravity, turned into the sensor's axes: at rest and level it reads +9.8 on z
  (like libgazebo_ros_imu_sensor.so; unlike libgazebo_ros_imu.so);
- ``angular_velocity``: the rotation between this update's orientation and the last one's,
  divided by the time between them, in the sensor's frame (the shorter way round);
- ``orientation``: the sensor's orientation in the world, tilted by the accelerometer's
  bias (roll and pitch errors of ``bias_y / 2|g|`` and ``-bias_x / 2|g|``, bias in world
  axes) and turned about z by the heading's bias (offset plus drift; yawGaussianNoise
  only sets the covariance, as upstream);
- covariances: rate and acceleration diagonals are the squared noises; orientation's
  are accel noise² / |g|² for x and y (-1 without gravity) and yawGaussianNoise² for z;
- both the acceleration and the rate are hector's error model applied to the truth; the
  first message after loading or a reset reads zero acceleration and rate plus errors
  (hector has no time step to differentiate over yet);
- on ``<biasTopicName>``, a sensor_msgs/Imu with the orientation error, the gyroscope's
  bias and the accelerometer's bias.

The calibrate service (std_srvs/Empty) sets the gyroscope's drift to zero, as upstream.
Not emulated: hector's ``<topicName>/set_accel_bias`` and ``set_rate_bias`` services
(hector_gazebo_plugins/SetBias) and its dynamic_reconfigure servers. Without gravity the
tilt error is left out (upstream divides by zero).
"""
from __future__ import annotations

import math

import numpy as np
from sensor_msgs.msg import Imu
from std_srvs.srv import Empty, EmptyResponse

from sim_bridge.plugins.base import Plugin, stamp
from sim_bridge.plugins.body_state import (IDENTITY, body_link, link_state, q_from_wxyz,
                                           q_inverse, q_multiply, q_normalized, vector3)
from sim_bridge.plugins.hector_sensor_model import SensorModel, UpdateTimer
from sim_bridge.poses import quaternion_from_rpy, quaternion_matrix


class HectorImu(Plugin):
    def __init__(self, context, spec):
        super().__init__(context, spec)
        self.body = body_link(self, "bodyName", context.robot.model.root())
        self.frame_id = self.param("frameId", self.param("bodyName") or self.body)
        topic = self.param("topicName", "imu")
        bias_topic = self.param("biasTopicName", f"{topic}/bias" if topic else "")
        service = self.param("serviceName", f"{topic}/calibrate")
        self.accel_model = SensorModel(self, "accel", 3)
        self.rate_model = SensorModel(self, "rate", 3)
        self.yaw_model = SensorModel(self, "yaw", 1)
        legacy_noise = self.number("gaussianNoise", 0.0)
        if legacy_noise != 0.0:
            self.accel_model.gaussian_noise = np.full(3, legacy_noise)
            self.rate_model.gaussian_noise = np.full(3, legacy_noise)
        self.xyz_offset = vector3(self, "xyzOffset")  # read, unused, as upstream
        self.offset_rotation = quaternion_from_rpy(*vector3(self, "rpyOffset"))
        self.timer = UpdateTimer(self, 0.0)
        bus = context.bus
        self.output = (bus.publisher(self.topic(topic), Imu, queue_size=10) if topic else None)
        self.bias_output = (bus.publisher(self.topic(bias_topic), Imu, queue_size=10)
                            if bias_topic else None)
        self.service = (bus.service(self.topic(service), Empty, self._calibrate)
                        if service else None)
        self.orientation = IDENTITY  # hector's state: the last update's orientation...
        self.velocity = np.zeros(3)  # ...velocity, acceleration and rate
        self.accel = np.zeros(3)
        self.rate = np.zeros(3)

    def _calibrate(self, request):
        self.rate_model.reset(0.0)
        return EmptyResponse()

    def after_step(self, now_ns: int) -> None:
        if not self.timer.due(now_ns):
            return
        dt = self.timer.elapsed(now_ns)
        _, link_orientation, velocity, _ = link_state(self.context, self.body)
        orientation = q_normalized(q_multiply(self.offset_rotation, link_orientation))
        gravity = np.asarray(self.context.gravity, float)
        gravity_length = float(np.linalg.norm(gravity))
        to_sensor = quaternion_matrix(orientation).T
        if dt > 0:
            self.accel = to_sensor @ ((velocity - self.velocity) / dt - gravity)
        self.velocity = velocity
        delta = q_multiply(q_inverse(self.orientation), orientation)
        self.orientation = orientation
        if dt > 0:
            if delta[3] < 0:  # the shorter way round
                delta = tuple(-c for c in delta)
            axis = np.asarray(delta[:3], float)
            norm = float(np.linalg.norm(axis))
            angle = 2.0 * math.acos(min(max(delta[3], -1.0), 1.0))
            in_sensor = axis / norm * angle / dt if norm > 0 else np.zeros(3)
            self.rate = quaternion_matrix(self.offset_rotation).T @ in_sensor
        self.accel = self.accel_model(self.accel, dt)
        self.rate = self.rate_model(self.rate, dt)
        self.yaw_model.update(dt)
        # the accelerometer's bias and the heading's as an orientation error (a pseudo-AHRS)
        accel_drift = quaternion_matrix(link_orientation) @ self.accel_model.bias
        yaw_error = float(self.yaw_model.bias[0])
        tilt = IDENTITY
        if gravity_length > 0:
            tilt = q_from_wxyz(1.0, 0.5 * accel_drift[1] / gravity_length,
                               -0.5 * accel_drift[0] / gravity_length, 0.0)
        error = q_normalized(q_multiply(
            q_from_wxyz(math.cos(yaw_error / 2), 0.0, 0.0, math.sin(yaw_error / 2)), tilt))
        reported = q_multiply(error, orientation)

        message = Imu()
        message.header.stamp = stamp(now_ns)
        message.header.frame_id = self.frame_id
        _set_quaternion(message.orientation, reported)
        _set_vector(message.angular_velocity, self.rate)
        _set_vector(message.linear_acceleration, self.accel)
        rate_noise2 = self.rate_model.gaussian_noise ** 2
        accel_noise2 = self.accel_model.gaussian_noise ** 2
        message.angular_velocity_covariance = _diagonal(rate_noise2)
        message.linear_acceleration_covariance = _diagonal(accel_noise2)
        if gravity_length > 0:
            tilt_variance = accel_noise2[:2] / gravity_length ** 2
        else:
            tilt_variance = (-1.0, -1.0)
        message.orientation_covariance = _diagonal(
            (tilt_variance[0], tilt_variance[1], float(self.yaw_model.gaussian_noise[0]) ** 2))
        if self.output is not None:
            self.output.publish(message)
        if self.bias_output is not None:
            bias = Imu()
            bias.header = message.header
            _set_quaternion(bias.orientation, error)
            _set_vector(bias.angular_velocity, self.rate_model.bias)
            _set_vector(bias.linear_acceleration, self.accel_model.bias)
            self.bias_output.publish(bias)

    def reset(self, now_ns: int) -> None:
        self.timer.reset()
        self.orientation = IDENTITY
        self.velocity = np.zeros(3)
        self.accel = np.zeros(3)  # the rate is kept, as upstream
        self.accel_model.reset()
        self.rate_model.reset()
        self.yaw_model.reset()


def _set_quaternion(target, q) -> None:
    target.x, target.y, target.z, target.w = (float(c) for c in q)


def _set_vector(target, v) -> None:
    target.x, target.y, target.z = (float(c) for c in v)


def _diagonal(values) -> list:
    a, b, c = (float(v) for v in values)
    return [a, 0.0, 0.0, 0.0, b, 0.0, 0.0, 0.0, c]
