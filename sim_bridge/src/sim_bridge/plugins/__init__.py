"""Gazebo plugins emulated by sim_bridge, found by the ``filename`` a URDF gives.

``MODEL_PLUGINS`` maps a model plugin's filename to its class; ``SENSOR_PLUGINS`` maps a
sensor plugin's filename to its class and the sensor types it serves. Anything else gets
one warning that names it, and the robot runs without it.
"""
from __future__ import annotations

from typing import List

from sim_bridge.gazebo_tags import GazeboTags
from sim_bridge.plugins.base import Plugin, PluginContext, PluginError
from sim_bridge.plugins.diff_drive import DiffDrive
from sim_bridge.plugins.imu import ImuSensor
from sim_bridge.plugins.joint_state_publisher import JointStatePublisher
from sim_bridge.plugins.laser import Laser
from sim_bridge.plugins.p3d import P3D
from sim_bridge.plugins.planar_move import PlanarMove
from sim_bridge.plugins.skid_steer import SkidSteer
from sim_bridge.ros_control import RosControl

MODEL_PLUGINS = {
    "libgazebo_ros_diff_drive.so": DiffDrive,
    "libgazebo_ros_skid_steer_drive.so": SkidSteer,
    "libgazebo_ros_joint_state_publisher.so": JointStatePublisher,
    "libgazebo_ros_p3d.so": P3D,
    "libgazebo_ros_planar_move.so": PlanarMove,
    "libgazebo_ros_control.so": RosControl,
}
SENSOR_PLUGINS = {
    "libgazebo_ros_laser.so": (Laser, ("ray", "gpu_ray")),
    "libgazebo_ros_gpu_laser.so": (Laser, ("ray", "gpu_ray")),
    "libgazebo_ros_imu_sensor.so": (ImuSensor, ("imu",)),
}


def create_plugins(context: PluginContext, tags: GazeboTags) -> List[Plugin]:
    plugins: List[Plugin] = []
    for spec in tags.plugins:
        plugin_class = MODEL_PLUGINS.get(spec.filename)
        if plugin_class is None:
            context.bus.warn(f"model '{context.model_name}': plugin '{spec.name}' "
                             f"({spec.filename}) is not emulated by sim_bridge; ignored")
            continue
        plugins.append(plugin_class(context, spec))
    for sensor in tags.sensors:
        if not sensor.plugins:
            context.bus.warn(f"model '{context.model_name}': sensor '{sensor.name}' has no "
                             "plugin, so nothing publishes it; ignored")
        for spec in sensor.plugins:
            entry = SENSOR_PLUGINS.get(spec.filename)
            if entry is None or sensor.type not in entry[1]:
                context.bus.warn(f"model '{context.model_name}': sensor '{sensor.name}' of type "
                                 f"'{sensor.type}' with plugin {spec.filename} is not emulated "
                                 "by sim_bridge; ignored")
                continue
            plugins.append(entry[0](context, spec, sensor))
    return plugins


__all__ = ["create_plugins", "MODEL_PLUGINS", "SENSOR_PLUGINS", "PluginError"]
