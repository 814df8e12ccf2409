"""Gazebo plugins emulated by sim_bridge, found by the ``filename`` a URDF gives.

``MODEL_PLUGINS`` maps a model plugin's filename to its class; ``SENSOR_PLUGINS`` maps a
sensor plugin's filename to its class and the sensor types it serves. Another model or
sensor plugin is loaded as Gazebo's C++ plugin from the plugin path
(:mod:`sim_bridge.native_plugins`, which warns, naming it, when it cannot be, and the robot
runs without it); an emulated sensor plugin on a sensor of a type it does not serve gets one
warning that names it, and the robot runs without it; so does a plugin that cannot run as
written (see ``_build``).

A ``<sensor>`` without a plugin publishes nothing to ROS, in Gazebo as here. It warns,
unless a model plugin reads its link (``<bodyName>``): TurtleBot3 marks its ``imu_link``
with a plugin-less ``<sensor type="imu">`` and reads it with ``libgazebo_ros_imu.so``,
which is as intended and gets a debug note at most; so does a sensor of a model with a
Gazebo C++ plugin, which may read it (Kobuki's reads its bumpers, cliff rays and gyro).
"""
from __future__ import annotations

import dataclasses
from typing import Callable, List, Set

from sim_bridge.gazebo_tags import GazeboTags, PluginSpec
from sim_bridge.plugins.base import Plugin, PluginContext, PluginError, TrackingBus
from sim_bridge.plugins.bumper import Bumper
from sim_bridge.plugins.camera import Camera, DepthCamera, MultiCamera
from sim_bridge.plugins.diff_drive import DiffDrive
from sim_bridge.plugins.f3d import F3D
from sim_bridge.plugins.ft_sensor import FTSensor
from sim_bridge.plugins.gazebo_ros_imu import GazeboRosImu
from sim_bridge.plugins.hector_gps import HectorGps
from sim_bridge.plugins.hector_imu import HectorImu
from sim_bridge.plugins.imu import ImuSensor
from sim_bridge.plugins.joint_state_publisher import JointStatePublisher
from sim_bridge.plugins.laser import Laser
from sim_bridge.plugins.mimic_joint import MimicJoint
from sim_bridge.plugins.p3d import P3D
from sim_bridge.plugins.planar_move import PlanarMove
from sim_bridge.plugins.range import Range
from sim_bridge.plugins.skid_steer import SkidSteer
from sim_bridge.ros_control import RosControl

MODEL_PLUGINS = {
    "libgazebo_ros_diff_drive.so": DiffDrive,
    "libgazebo_ros_skid_steer_drive.so": SkidSteer,
    "libgazebo_ros_joint_state_publisher.so": JointStatePublisher,
    "libgazebo_ros_p3d.so": P3D,
    "libgazebo_ros_f3d.so": F3D,
    "libgazebo_ros_ft_sensor.so": FTSensor,
    "libgazebo_ros_planar_move.so": PlanarMove,
    "libgazebo_ros_control.so": RosControl,
    "libgazebo_ros_imu.so": GazeboRosImu,
    "libhector_gazebo_ros_imu.so": HectorImu,
    "libhector_gazebo_ros_gps.so": HectorGps,
    "libroboticsgroup_upatras_gazebo_mimic_joint_plugin.so": MimicJoint,
    "libroboticsgroup_gazebo_mimic_joint_plugin.so": MimicJoint,
}
# model plugins whose <bodyName> defaults to the model's canonical link when absent
BODY_DEFAULTS_TO_CANONICAL = ("libhector_gazebo_ros_imu.so", "libhector_gazebo_ros_gps.so")
SENSOR_PLUGINS = {
    "libgazebo_ros_laser.so": (Laser, ("ray", "gpu_ray")),
    "libgazebo_ros_gpu_laser.so": (Laser, ("ray", "gpu_ray")),
    "libgazebo_ros_imu_sensor.so": (ImuSensor, ("imu",)),
    "libgazebo_ros_range.so": (Range, ("ray", "gpu_ray")),
    "libgazebo_ros_camera.so": (Camera, ("camera",)),
    "libgazebo_ros_bumper.so": (Bumper, ("contact",)),
    "libgazebo_ros_openni_kinect.so": (DepthCamera, ("depth",)),
    "libgazebo_ros_depth_camera.so": (DepthCamera, ("depth",)),
    "libgazebo_ros_multicamera.so": (MultiCamera, ("multicamera",)),
}


# Tags that plugins of an older release read and Noetic's read no more: many packages still
# carry them. Noetic's plugins ignore them silently; here they are a --verbose note, never
# acted on (acting on one would turn a robot as no Noetic user sees it turn).
RETIRED_TAGS = {
    # kinetic-devel's gazebo_ros_diff_drive.cpp read it (default true: the wheels' speeds
    # swapped); melodic-devel and noetic-devel read no such tag (gazebo_ros_diff_drive.cpp,
    # getWheelVelocities: left = v - w s/2, right = v + w s/2)
    "legacyMode": "Kinetic's gazebo_ros_diff_drive swapped the wheels' speeds when it was "
                  "true; Noetic's plugins read no such tag (dropped in Melodic)",
    # kinetic-devel's gazebo_ros_control_plugin.cpp:116-117 read it (where robotParam is
    # looked up); melodic-devel and noetic-devel (f9e1a46) read no such tag
    "legacyModeNS": "Kinetic's gazebo_ros_control looked robotParam up by it; Noetic's "
                    "reads no such tag (dropped in Melodic)",
}


def links_read_by_model_plugins(tags: GazeboTags, canonical: str) -> Set[str]:
    """The links that emulated model plugins read through ``<bodyName>``."""
    links = set()
    for spec in tags.plugins:
        if spec.filename not in MODEL_PLUGINS:
            continue
        body = spec.params.get("bodyName")  # not marked read: the plugin reads it itself
        if body is None and spec.filename in BODY_DEFAULTS_TO_CANONICAL:
            body = canonical
        if body:
            links.add(body.rpartition("::")[2])
    return links


def _build(context: PluginContext, spec: PluginSpec, what: str,
           make: Callable[[PluginContext], Plugin], built: List[Plugin]) -> None:
    """Builds one plugin on a bus that keeps what it opens. A plugin that cannot run as
    written (a joint the model lacks, no transmission, a bad number) is left out with a
    warning naming it and the cause, and whatever it opened is closed: Gazebo loads the
    robot, says the plugin will not run, and the rest works."""
    tracking = TrackingBus(context.bus)
    try:
        built.append(make(dataclasses.replace(context, bus=tracking)))
    except PluginError as error:
        tracking.close_all()
        context.bus.warn(f"model '{context.model_name}': {what} not loaded: {error}; the "
                         "model is spawned without it")
        return
    context.bus.debug(f"model '{context.model_name}': {what} loaded: "
                      f"{spec.summary() or 'no parameters'}")
    unread = spec.unread()
    for tag in [tag for tag in unread if tag in RETIRED_TAGS]:
        unread.remove(tag)
        context.bus.debug(f"model '{context.model_name}': {what} ignores <{tag}>: "
                          f"{RETIRED_TAGS[tag]}")
    if unread:  # e.g. <torque> where Noetic's plugin reads <wheelTorque>
        context.bus.warn(f"model '{context.model_name}': {what} does not read "
                         f"{', '.join(f'<{tag}>' for tag in unread)} (not a parameter of "
                         "the gazebo_ros plugin sim_bridge emulates); ignored")


def create_plugins(context: PluginContext, tags: GazeboTags) -> List[Plugin]:
    plugins: List[Plugin] = []
    try:
        _create_plugins(context, tags, plugins)
    except Exception:  # an error of ours: close what was built, the spawn is refused
        for plugin in plugins:
            plugin.close()
        raise
    return plugins


def _create_plugins(context: PluginContext, tags: GazeboTags, plugins: List[Plugin]) -> None:
    read_links = links_read_by_model_plugins(tags, context.robot.model.root())
    for spec in tags.plugins:
        plugin_class = MODEL_PLUGINS.get(spec.filename)
        if plugin_class is None:  # a Gazebo C++ plugin: the world loads it once the model
            continue              # is in it (sim_bridge.native_plugins)
        _build(context, spec, f"plugin '{spec.name}' ({spec.filename})",
               lambda tracked, cls=plugin_class, spec=spec: cls(tracked, spec), plugins)
    # a Gazebo C++ model plugin may read any sensor through SensorManager (Kobuki's reads
    # its plugin-less bumpers, cliff rays and gyro: sim_bridge.native_sensors)
    native = any(spec.filename not in MODEL_PLUGINS for spec in tags.plugins)
    for sensor in tags.sensors:
        if not sensor.plugins and sensor.link in read_links:
            context.bus.debug(f"model '{context.model_name}': sensor '{sensor.name}' has no "
                              f"plugin; its link '{sensor.link}' is read by a model plugin")
        elif not sensor.plugins and native:
            context.bus.debug(f"model '{context.model_name}': sensor '{sensor.name}' has no "
                              "plugin; the model's C++ plugins may read it")
        elif not sensor.plugins:
            context.bus.warn(f"model '{context.model_name}': sensor '{sensor.name}' has no "
                             "plugin, so nothing publishes it; ignored")
        for spec in sensor.plugins:
            entry = SENSOR_PLUGINS.get(spec.filename)
            if entry is None:  # a Gazebo C++ sensor plugin: the world loads it once the
                continue       # model is in it (sim_bridge.native_plugins)
            if sensor.type not in entry[1]:
                context.bus.warn(f"model '{context.model_name}': sensor '{sensor.name}' of type "
                                 f"'{sensor.type}' with plugin {spec.filename} is not emulated "
                                 "by sim_bridge; ignored")
                continue
            _build(context, spec,
                   f"sensor '{sensor.name}' plugin '{spec.name}' ({spec.filename})",
                   lambda tracked, cls=entry[0], spec=spec, sensor=sensor:
                   cls(tracked, spec, sensor), plugins)


__all__ = ["create_plugins", "MODEL_PLUGINS", "SENSOR_PLUGINS", "PluginError"]
