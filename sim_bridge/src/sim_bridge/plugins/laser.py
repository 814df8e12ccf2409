"""``<sensor type="ray|gpu_ray">`` with ``libgazebo_ros_laser.so`` / ``libgazebo_ros_gpu_laser.so``.

From the sensor: ``<pose>`` (in the link's frame), ``<update_rate>`` (Hz; 0 every step),
``<ray><scan><horizontal>`` samples, min_angle, max_angle; ``<range>`` min, max,
resolution; ``<noise>`` gaussian mean and stddev (drawn from the world's seeded generator).
From the plugin: topicName (/world), frameName (/world), robotNamespace — gazebo_ros's
defaults, odd as they are; write both.

Rays are cast in the sensor's frame from the link's true pose, rotation included, from
``range min`` to ``range max`` (as Gazebo's rays start at the minimum range). A ray that
hits nothing reads ``+inf`` (REP 117), not Gazebo's max range; stamps are simulated time.
As Noetic's plugin, the sensor scans only while its topic has a subscriber (the plugin
turns the sensor off at load and takes its scans from the first subscriber on:
gazebo_plugins/src/gazebo_ros_laser.cpp:154-155, :158-176): the slots keep their times,
so a subscriber sees the same scans whenever it came. As Noetic's plugins fill the
message (gazebo_ros_pkgs noetic-devel f9e1a46, gazebo_plugins/src/gazebo_ros_laser.cpp:188-205,
gazebo_ros_gpu_laser.cpp:193-210):
time_increment and scan_time 0; the intensities the sensor's, one per range, which Gazebo's
ray sensor gives the ``<laser_retro>`` of what each ray hits, 0 without one or without a
hit: all 0 here (``<laserRetro>`` is not emulated).

A sensor of more than :data:`MAX_BEAMS` beams (horizontal × vertical samples) is not
loaded: as with any plugin that cannot run as written, the robot spawns without it and a
warning names the sensor, the count and the limit (``plugins._build``); Gazebo would load
it, and take the machine down with it.
"""
from __future__ import annotations

import math

import numpy as np
import pybullet as pb
from sensor_msgs.msg import LaserScan

from sim_bridge.plugins.base import PluginError, Rate, SensorPlugin, stamp

# The most beams (horizontal x vertical samples) one sensor may cast. Real 2D scanners have
# about 1000 (Hokuyo UTM-30LX 1081, SICK LMS1xx 1141), the courses' 720. Every beam is cast
# every scan: 720 cost 2.9 ms a scan on the 2-core VM, so 10,000 cost about 40 ms (a 10 Hz
# sensor: 40% of a core); 10^6 slowed the simulator to 0.06x real time, and 10^9 asked
# for 24 GB of ray directions until the kernel killed it.
MAX_BEAMS = 10_000


def _number(element, path: str, default: float, sensor: str) -> float:
    text = element.findtext(path) if element is not None else None
    if text is None or not text.strip():
        return default
    try:
        return float(text)
    except ValueError:
        raise PluginError(f"sensor '{sensor}': <{path}> '{text}' is not a number") from None


def _count(element, path: str, default: int, sensor: str) -> int:
    """A number of samples: a whole number, at least 1 (``1e3`` reads as 1000)."""
    value = _number(element, path, default, sensor)
    if not (math.isfinite(value) and value >= 1 and value == int(value)):
        raise PluginError(f"sensor '{sensor}': <{path}> '{element.findtext(path)}' must be a "
                          "whole number of at least 1")
    return int(value)


class Laser(SensorPlugin):
    EMPTY_NAMESPACE_IS_MODEL = True  # gazebo_plugins' GetRobotNamespace

    def __init__(self, context, spec, sensor):
        super().__init__(context, spec, sensor)
        element = sensor.element
        name = sensor.name
        ray = element.find("ray")
        if ray is None:
            raise PluginError(f"sensor '{name}' of type {sensor.type} needs a <ray> element")
        samples = _count(ray, "scan/horizontal/samples", 640, name)
        # read for the count only: the emulated laser scans one plane, as gazebo_ros_laser
        vertical = _count(ray, "scan/vertical/samples", 1, name)
        if samples * vertical > MAX_BEAMS:
            raise PluginError(f"sensor '{name}': {samples} x {vertical} samples "
                              f"(horizontal x vertical) = {samples * vertical} beams; "
                              f"sim_bridge casts at most {MAX_BEAMS} per sensor (MAX_BEAMS)")
        self.angle_min = _number(ray, "scan/horizontal/min_angle", 0.0, name)
        self.angle_max = _number(ray, "scan/horizontal/max_angle", 0.0, name)
        self.range_min = _number(ray, "range/min", 0.0, name)
        self.range_max = _number(ray, "range/max", 0.0, name)
        if not 0 <= self.range_min < self.range_max:
            raise PluginError(f"sensor '{name}': needs 0 <= range min < range max "
                              f"(got {self.range_min}, {self.range_max})")
        self.resolution = _number(ray, "range/resolution", 0.0, name)
        noise = ray.find("noise")
        self.noise_mean = _number(noise, "mean", 0.0, name)
        self.noise_stddev = _number(noise, "stddev", 0.0, name)
        if noise is not None and (noise.findtext("type") or "gaussian").strip() != "gaussian":
            raise PluginError(f"sensor '{name}': only gaussian noise is modelled")
        update_rate = _number(element, "update_rate", 0.0, name)
        self.rate = Rate(update_rate)
        # the time between scans (tools/bench reads it); not the message's scan_time,
        # which Noetic's plugins leave 0 (gazebo_plugins/src/gazebo_ros_laser.cpp:195)
        self.scan_time = 1.0 / update_rate if update_rate > 0 else context.step_size
        angles = (np.linspace(self.angle_min, self.angle_max, samples) if samples > 1
                  else np.array([self.angle_min]))
        self.increment = (self.angle_max - self.angle_min) / (samples - 1) if samples > 1 else 0.0
        self.directions = np.stack([np.cos(angles), np.sin(angles), np.zeros(samples)], axis=1)
        self.frame_id = self.frame(self.param("frameName", "/world"))
        self.output = context.bus.publisher(self.topic(self.param("topicName", "/world")),
                                            LaserScan, queue_size=1)

    def measure(self) -> np.ndarray:
        """One scan's ranges (metres; +inf where nothing is within range)."""
        position, orientation = self.sensor_pose()
        # pybullet's matrix of the quaternion: the same as tf.transformations' (to the
        # last bit or two), in 1 us instead of 5
        rotation = np.array(pb.getMatrixFromQuaternion(orientation)).reshape(3, 3)
        world_directions = self.directions @ rotation.T
        ranges = self.context.cast_rays(position, world_directions, self.range_min,
                                        self.range_max)
        hit = np.isfinite(ranges)
        if self.noise_stddev > 0 or self.noise_mean != 0:
            ranges[hit] += self.context.rng.normal(self.noise_mean, self.noise_stddev,
                                                   int(hit.sum()))
        if self.resolution > 0:
            ranges[hit] = np.round(ranges[hit] / self.resolution) * self.resolution
        return ranges

    def quiet_until_ns(self, now_ns: int, step_ns: int) -> int:
        return self.rate.quiet_until_ns()  # after_step asks the rate first

    def after_step(self, now_ns: int) -> None:
        if not self.rate.due(now_ns) or not self.context.bus.listened(self.output):
            return
        message = LaserScan()
        message.header.stamp = stamp(now_ns)
        message.header.frame_id = self.frame_id
        message.angle_min = self.angle_min
        message.angle_max = self.angle_max
        message.angle_increment = self.increment
        # gazebo_plugins/src/gazebo_ros_laser.cpp:194-195 (gazebo_ros_gpu_laser.cpp:199-200):
        # "instantaneous simulator scan", time_increment and scan_time 0
        message.time_increment = 0.0
        message.scan_time = 0.0
        message.range_min = self.range_min
        message.range_max = self.range_max
        message.ranges = self.measure().tolist()
        # gazebo_plugins/src/gazebo_ros_laser.cpp:202-205 (gazebo_ros_gpu_laser.cpp:207-210):
        # the sensor's intensities, one per range: each ray's <laser_retro>, 0 without one
        # or without a hit (not emulated: all 0)
        message.intensities = [0.0] * len(message.ranges)
        self.output.publish(message)

    def reset(self, now_ns: int) -> None:
        self.rate.reset(now_ns)
