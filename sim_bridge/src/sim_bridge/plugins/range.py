"""``<sensor type="ray">`` with ``libgazebo_ros_range.so``: a sonar or infrared ranger,
sensor_msgs/Range.

The sensor's rays as Gazebo casts them (``<ray><scan>`` horizontal and vertical samples,
min_angle and max_angle; ``<range>`` min and max; ``<pose>`` in the link's frame;
``<update_rate>``), the reading the nearest of them, as gazebo_ros_range takes it. From the
plugin, with gazebo_ros_range's defaults: ``topicName`` (/range), ``frameName`` (/world; the
model's tf_prefix applied), ``radiation`` (ultrasound when absent; exactly ``ultrasound`` is
ULTRASOUND and any other text INFRARED, as upstream compares it), ``fov``
(0.05 rad, reported in the message), ``gaussianNoise`` (0, added to a reading within range,
seeded), ``updateRate`` (0: the sensor's). Nothing within range reads ``+inf`` (REP 117), where
Gazebo reports the maximum range, as sim_bridge's laser does. As Noetic's plugin, the sensor
measures only while its topic has a subscriber (gazebo_ros_pkgs noetic-devel f9e1a46,
gazebo_plugins/src/gazebo_ros_range.cpp:220: off at load; :228-241: on from the first
subscriber to the last); the update slots keep their times.
"""
from __future__ import annotations

import numpy as np
import pybullet as pb
from sensor_msgs.msg import Range as RangeMessage

from sim_bridge.plugins.base import PluginError, Rate, SensorPlugin, stamp
from sim_bridge.plugins.laser import MAX_BEAMS, _count, _number



class Range(SensorPlugin):
    def __init__(self, context, spec, sensor):
        super().__init__(context, spec, sensor)
        name, element = sensor.name, sensor.element
        ray = element.find("ray")
        if ray is None:
            raise PluginError(f"sensor '{name}' of type {sensor.type} needs a <ray> element")
        horizontal = _count(ray, "scan/horizontal/samples", 1, name)
        vertical = _count(ray, "scan/vertical/samples", 1, name)
        if horizontal * vertical > MAX_BEAMS:
            raise PluginError(f"sensor '{name}': {horizontal} x {vertical} rays; sim_bridge "
                              f"casts at most {MAX_BEAMS} per sensor (MAX_BEAMS)")
        yaws = np.linspace(_number(ray, "scan/horizontal/min_angle", 0.0, name),
                           _number(ray, "scan/horizontal/max_angle", 0.0, name), horizontal)
        pitches = np.linspace(_number(ray, "scan/vertical/min_angle", 0.0, name),
                              _number(ray, "scan/vertical/max_angle", 0.0, name), vertical)
        yaw, pitch = (grid.ravel() for grid in np.meshgrid(yaws, pitches))
        # Gazebo's ray directions: yaw about z, then pitch (positive up)
        self.directions = np.stack([np.cos(pitch) * np.cos(yaw), np.cos(pitch) * np.sin(yaw),
                                    np.sin(pitch)], axis=1)
        self.range_min = _number(ray, "range/min", 0.0, name)
        self.range_max = _number(ray, "range/max", 0.0, name)
        if not 0 <= self.range_min < self.range_max:
            raise PluginError(f"sensor '{name}': needs 0 <= range min < range max "
                              f"(got {self.range_min}, {self.range_max})")
        plugin_rate = self.number("updateRate", 0.0)
        self.rate = Rate(plugin_rate if plugin_rate > 0 else
                         _number(element, "update_rate", 0.0, name))
        # absent: ultrasound; then exactly "ultrasound" is ULTRASOUND and any other text
        # INFRARED (gazebo_plugins/src/gazebo_ros_range.cpp:127-134, :170-173)
        radiation = self.param("radiation", "ultrasound")
        if radiation not in ("ultrasound", "infrared"):
            context.bus.warn(
                f"model '{context.model_name}': plugin '{spec.name}' ({spec.filename}): "
                f"<radiation> '{radiation}' reads as INFRARED, as gazebo_ros_range reads every "
                "text but exactly 'ultrasound'; write 'ultrasound' or 'infrared'")
        self.noise = self.number("gaussianNoise", 0.0)
        self.message = RangeMessage()
        self.message.header.frame_id = self.frame(self.param("frameName", "/world"))
        self.message.radiation_type = (RangeMessage.ULTRASOUND if radiation == "ultrasound"
                                       else RangeMessage.INFRARED)
        self.message.field_of_view = self.number("fov", 0.05)
        self.message.min_range, self.message.max_range = self.range_min, self.range_max
        self.output = context.bus.publisher(self.topic(self.param("topicName", "/range")),
                                            RangeMessage, queue_size=1)

    def measure(self) -> float:
        """The nearest ray's distance (m), noise added; +inf when nothing is in range."""
        position, orientation = self.sensor_pose()
        rotation = np.array(pb.getMatrixFromQuaternion(orientation)).reshape(3, 3)
        nearest = float(np.min(self.context.cast_rays(position, self.directions @ rotation.T,
                                                      self.range_min, self.range_max)))
        if np.isfinite(nearest) and self.noise > 0:
            nearest = min(nearest + float(self.context.rng.normal(0.0, self.noise)),
                          self.range_max)
        return nearest

    def quiet_until_ns(self, now_ns: int, step_ns: int) -> int:
        return self.rate.quiet_until_ns()  # after_step asks the rate first

    def after_step(self, now_ns: int) -> None:
        if not self.rate.due(now_ns) or not self.context.bus.listened(self.output):
            return
        self.message.header.stamp = stamp(now_ns)
        self.message.range = self.measure()
        self.output.publish(self.message)
