"""``libgazebo_ros_imu.so``: gazebo_ros's older IMU, a *model* plugin (in ``<gazebo>
<plugin>``, no ``<sensor>``), reporting one link's motion as sensor_msgs/Imu.

Parameters as gazebo_ros (noetic) reads them: bodyName (the link; required), topicName
(``/default_imu``; empty: neither topic nor service), serviceName (``/default_imu``, a
std_srvs/Empty "calibrate" service that does nothing and succeeds), frameName (the
bodyName as written; used as written, no tf_prefix), gaussianNoise (0), xyzOffset and rpyOffset
(singular; 0), updateRate (0: every step; else at least 1/updateRate s of simulated time
between messages, measured from the last one), robotNamespace. ``alwaysOn`` and nested
``<imu><noise>`` are not read, as upstream.

What it reports (unit-tested):

- linear_acceleration is the link frame's own acceleration, the change of its world
  velocity between two messages over their time: it does NOT include gravity. A robot
  at rest reads (0, 0, 0), not +9.8 on z as ``libgazebo_ros_imu_sensor.so`` or a real
  accelerometer does; a falling one reads -9.8 on z;
- orientation is the link's orientation in the world with the rpyOffset rotation applied
  on the world's side: ``q = q_rpyOffset * q_link``;
- angular velocity and acceleration are given in the sensor's frame (``R(q)ᵀ v``).
  Upstream turns the world's vectors by ``R(q)`` instead of its inverse: right for a level
  link turning about z, wrong for a tilted link or a robot speeding up along any heading
  but 0 (at 90 degrees, forward reads as -x). That is a fault of Gazebo's, not copied;
  a level robot's yaw rate (TurtleBot3's use) reads the same either way;
- Gaussian noise (seeded from the world's seed) is added to the world-frame rate and
  acceleration before the change of frame; every covariance diagonal is gaussianNoise²;
- xyzOffset is read and has no effect (upstream computes a position from it and never
  uses it).

- it computes and publishes only while its topic has a subscriber, as upstream
  (gazebo_plugins/src/gazebo_ros_imu.cpp:236, :337-342): its time and velocity stay
  those of the last message, so the first acceleration heard after a pause spans the
  pause (was: every step, heard or not: 42 us a step for nobody).

Differences: after a world reset the acceleration starts again from the reset (upstream
keeps its old time stamp and reads a spike, or stalls for updateRate > 0).
"""
from __future__ import annotations

from typing import Sequence

import numpy as np
from sensor_msgs.msg import Imu
from std_srvs.srv import Empty, EmptyResponse

from sim_bridge.plugins.base import Plugin, stamp
from sim_bridge.plugins.body_state import (body_link, link_state, q_multiply, q_normalized,
                                           to_sensor, vector3)
from sim_bridge.poses import quaternion_from_rpy

DEFAULT_NAME = "/default_imu"
NO_NOISE = (0.0, 0.0, 0.0)


class GazeboRosImu(Plugin):
    def __init__(self, context, spec):
        super().__init__(context, spec)
        self.body = body_link(self, "bodyName")
        self.topic_name = self.param("topicName", DEFAULT_NAME)
        self.service_name = self.param("serviceName", DEFAULT_NAME)
        self.noise = abs(self.number("gaussianNoise", 0.0))
        self.xyz_offset = vector3(self, "xyzOffset")  # read, unused, as upstream
        self.offset_rotation = quaternion_from_rpy(*vector3(self, "rpyOffset"))
        self.period = 0.0
        rate = self.number("updateRate", 0.0)
        if rate > 0:
            self.period = 1.0 / rate
        self.frame_id = self.param("frameName", self.param("bodyName"))  # as written
        for plural, singular in (("xyzOffsets", "xyzOffset"), ("rpyOffsets", "rpyOffset")):
            if plural in spec.params:
                context.bus.warn(f"model '{context.model_name}': plugin '{spec.name}' "
                                 f"({spec.filename}) reads <{singular}>, not <{plural}> "
                                 "(no gazebo_plugins release reads the plural, p3d "
                                 f"included); <{plural}> is ignored, as Gazebo ignores it")
        self.output = self.service = None
        if self.topic_name:  # upstream: an empty topic name means no topic and no service
            self.output = context.bus.publisher(self.topic(self.topic_name), Imu, queue_size=1)
            self.service = context.bus.service(self.topic(self.service_name), Empty,
                                               self._calibrate)
        # upstream takes the link's velocity when it loads; its time is the next step's
        # start, known at the first step
        self._last_ns = None
        self._last_velocity = link_state(context, self.body)[2]
        self._acceleration = np.zeros(3)

    def _calibrate(self, request):
        return EmptyResponse()  # "imu is always calibrated in sim"

    def _noise(self) -> Sequence[float]:
        if self.noise > 0:
            return self.context.rng.normal(0.0, self.noise, 3)
        return NO_NOISE

    def after_step(self, now_ns: int) -> None:
        if self.output is None:
            return
        if self._last_ns is None:  # loaded one step ago
            self._last_ns = now_ns - int(round(self.context.step_size * 1e9))
        if self.period > 0 and (now_ns - self._last_ns) / 1e9 < self.period:
            return
        if not self.context.bus.listened(self.output):
            # upstream computes nothing while unsubscribed and keeps its last time and
            # velocity (:236, :342), so the first reading heard spans the pause
            return
        _, link_orientation, velocity, angular = link_state(self.context, self.body)
        orientation = q_normalized(q_multiply(self.offset_rotation, link_orientation))
        dt = (now_ns - self._last_ns) / 1e9
        if dt != 0:
            self._acceleration = (velocity - self._last_velocity) / dt
            self._last_velocity = velocity
        # world -> sensor: R(q)^T (upstream: R(q), a fault); the rate's noise drawn first
        rate = to_sensor(orientation, [v + n for v, n in zip(angular, self._noise())])
        acceleration = to_sensor(orientation, [v + n for v, n in zip(self._acceleration,
                                                                     self._noise())])
        message = Imu()
        message.header.stamp = stamp(now_ns)
        message.header.frame_id = self.frame_id
        o = message.orientation
        o.x, o.y, o.z, o.w = orientation
        w = message.angular_velocity
        w.x, w.y, w.z = (float(v) for v in rate)
        a = message.linear_acceleration
        a.x, a.y, a.z = (float(v) for v in acceleration)
        variance = self.noise * self.noise
        diagonal = [variance, 0.0, 0.0, 0.0, variance, 0.0, 0.0, 0.0, variance]
        message.orientation_covariance = list(diagonal)
        message.angular_velocity_covariance = list(diagonal)
        message.linear_acceleration_covariance = list(diagonal)
        self.output.publish(message)
        self._last_ns = now_ns

    def reset(self, now_ns: int) -> None:
        self._last_ns = now_ns
        self._last_velocity = link_state(self.context, self.body)[2]
        self._acceleration = np.zeros(3)
