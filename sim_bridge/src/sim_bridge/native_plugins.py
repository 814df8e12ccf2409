"""Gazebo's C++ model and world plugins, run in sim_bridge's process in lockstep with it.

A ``<plugin filename="libfoo.so">`` that sim_bridge does not emulate in Python is loaded as
Gazebo 11 loads it, through compat/gazebo_dev's plugin API (headers under Gazebo's names,
the library ``gazebo_compat``) and the pybind11 module :mod:`sim_bridge._gazebo_host`:

- found in each folder of ``GAZEBO_PLUGIN_PATH``, then in the ``lib`` folders of catkin's
  ``CMAKE_PREFIX_PATH`` (devel and install spaces), then by dlopen's own search
  (``LD_LIBRARY_PATH``); opened ``RTLD_LAZY | RTLD_GLOBAL``;
- constructed, then ``Load(model, sdf)`` and ``Init()``; a plugin that cannot be found or
  opened, or that throws, is named with its error in one warning, and the model runs
  without it (Gazebo's behaviour). ``sdf`` is a real sdformat element: the ``<plugin>`` with
  its content as strings, inside ``<model name=...>`` (``<world name=...>``);
- each step of :meth:`sim_bridge.world.World.step` signals WorldUpdateBegin (simulated time
  already one step on, as Gazebo's) and the joint controllers before pybullet's step, and
  WorldUpdateEnd after it. What a plugin sets acts on the next pybullet step.

Why in-process through pybind11 rather than a host process stepped over a socket: a plugin
reads the world many times a step (poses, joint states), and each read is a direct call
into this module's :class:`WorldBackend` (a few microseconds), not a round trip; and the
plugin API's objects stay consistent with the world without a copy of its state. The cost:
a plugin that crashes takes the simulator down, as it does gzserver.

Threads: pybullet is touched only from Python, under the interpreter lock. The host signals
the events with the lock released, and every backend call takes it, so plugins' own ROS
threads (roscpp's AsyncSpinner, private callback queues) may call the API at any time, as
they do in Gazebo.

roscpp is initialised once per process, when the first plugin is loaded in a process that
asked for ROS (:func:`use_ros`, which sim_bridge's node calls), under the node name
:data:`ROS_NODE_NAME` (sim_bridge's rospy node is already ``/gazebo``; a second ``/gazebo``
would make the master shut the first down), with an AsyncSpinner on the global queue, as
gazebo_ros's API plugin runs it. Plugins check ``ros::isInitialized()`` as they do in Gazebo;
under ``use_sim_time`` roscpp follows ``/clock`` as any node does.

A model's ``<sensor>``s become the C++ plugins' sensors (SensorManager, ContactSensor,
RaySensor, ImuSensor) when its plugins load, before their ``Load``; they are measured in
:mod:`sim_bridge.native_sensors`.
"""
from __future__ import annotations

import atexit
import xml.etree.ElementTree as ET
from typing import TYPE_CHECKING, Callable, List, Optional, Sequence, Tuple

import pybullet as pb

from sim_bridge.native_sensors import NativeSensors

if TYPE_CHECKING:  # the world imports this module
    from sim_bridge.world import World

# sim_bridge's roscpp node, beside its rospy node /gazebo
ROS_NODE_NAME = "gazebo_plugin_host"

_ros_node_name: Optional[str] = None


def use_ros(node_name: str = ROS_NODE_NAME) -> None:
    """Plugins loaded from now on get roscpp, initialised under ``node_name``."""
    global _ros_node_name
    _ros_node_name = node_name


def _module():
    """The host module; ImportError when the workspace was built without it."""
    from sim_bridge import _gazebo_host
    return _gazebo_host


def element_tree(element: ET.Element, namespace: str = "") -> Tuple:
    """(tag, attributes, text, children) of a ``<plugin>``, as the host module reads it;
    ``namespace`` is added as ``<robotNamespace>`` when the plugin names none, as
    gazebo_ros's spawn adds the request's robot_namespace to every plugin
    (gazebo_ros_api_plugin.cpp:2622-2647, noetic-devel f9e1a46)."""
    def convert(node: ET.Element) -> Tuple:
        return (node.tag, dict(node.attrib), (node.text or "").strip(),
                [convert(child) for child in node])
    tree = convert(element)
    if namespace and element.find("robotNamespace") is None:
        tree[3].append(("robotNamespace", {}, namespace, []))
    return tree


class NativePlugins:
    """The C++ plugins of one world; the host module is imported when the first is loaded."""

    def __init__(self, world: "World"):
        self.world = world
        self._host = None
        self._backend = None
        self.count = 0  # plugins loaded and not removed
        self.sensors = NativeSensors(world)

    def _started(self):
        if self._host is None:
            host = _module()
            self._backend = WorldBackend(host, self.world, self.sensors)
            host.set_backend(self._backend)
            if _ros_node_name and host.init_ros(_ros_node_name):
                atexit.register(host.shutdown_ros)
            self._host = host
        self._host.set_sim_time(self.world.now_ns)
        return self._host

    def _load(self, what: str, load: Callable, without: str) -> bool:
        try:
            host = self._started()
        except ImportError as error:
            self.world.bus.warn(f"{what} is not emulated by sim_bridge and cannot be loaded as "
                                f"a Gazebo C++ plugin: sim_bridge's plugin host is not built "
                                f"({error}; run 'make'); {without}")
            return False
        error = load(host)
        if error:
            self.world.bus.warn(f"{what} not loaded: {error}; {without}")
            return False
        self.count += 1
        self.world.bus.debug(f"{what} loaded (Gazebo C++ plugin)")
        return True

    def load_model_plugin(self, model: str, element: ET.Element, namespace: str = "") -> bool:
        name, filename = element.get("name", ""), element.get("filename", "")
        return self._load(
            f"model '{model}': plugin '{name}' ({filename})",
            lambda host: host.load_model_plugin(model, filename, name,
                                                element_tree(element, namespace)),
            "the model is spawned without it")

    def load_sensor_plugin(self, model: str, sensor: str, element: ET.Element,
                           namespace: str = "") -> bool:
        name, filename = element.get("name", ""), element.get("filename", "")
        return self._load(
            f"model '{model}': sensor '{sensor}': plugin '{name}' ({filename})",
            lambda host: host.load_sensor_plugin(model, sensor, filename, name,
                                                 element_tree(element, namespace)),
            "the sensor runs without it")

    def load_world_plugin(self, world_name: str, element: ET.Element) -> bool:
        name, filename = element.get("name", ""), element.get("filename", "")
        return self._load(
            f"world '{world_name}': plugin '{name}' ({filename})",
            lambda host: host.load_world_plugin(world_name, filename, name,
                                                element_tree(element)),
            "the world runs without it")

    def load_system_plugins(self, filenames: List[str], argv: List[str]) -> None:
        """gzserver's ``-s`` plugins, before the world loads: each made and given
        ``Load(argc, argv)`` with gzserver's command line, then every ``Init()`` (gazebo
        11's gazebo_shared.cc:55-96); one that cannot be loaded, or throws, is named and the
        simulator runs without it."""
        loaded = [filename for filename in filenames if self._load(
            f"system plugin ({filename})",
            lambda host, filename=filename: host.load_system_plugin(filename, argv),
            "the simulator runs without it")]
        if loaded:
            for error in self._host.init_system_plugins():
                self.world.bus.warn(f"{error}; the simulator runs without it")
                self.count -= 1

    def world_created(self) -> None:
        """The world has loaded: ``Events::worldCreated`` (physics/World.cc:414), for the
        plugins loaded so far."""
        if self._host is not None:
            self._host.world_created()

    def begin(self, sim_time_ns: int) -> None:
        if self.count:
            self._host.world_update_begin(sim_time_ns)

    def end(self) -> None:
        if self.count:
            self._host.world_update_end()

    def remove_model(self, model: str) -> None:
        if self._host is not None:
            self.count -= len(self._host.plugin_names(model))
            self._host.remove_model(model)
        self.sensors.forget(model)

    def reset(self) -> None:
        if self._host is not None:
            self._host.reset()

    def close(self) -> None:
        if self._host is not None:
            self._host.close()
            self._host = None
            self._backend = None
            self.count = 0
        self.sensors = NativeSensors(self.world)


def WorldBackend(host, world: "World", sensors: NativeSensors):
    """A gazebo_compat::Backend over ``world`` (the class derives from the host module's
    Backend, so it is made once the module is imported)."""

    class _Backend(host.Backend):
        def world_name(self) -> str:
            return world.world_name

        def step_size(self) -> float:
            return world.step_size

        def model_names(self) -> List[str]:
            return list(world.models)

        def describe(self, model_name: str):
            model = world.model(model_name)
            info = host.ModelInfo()
            info.links = list(model.structure.bodies)
            joints = []
            if model.robot is not None:
                description = model.robot.model
                body_of = model.structure.body_of
                for name in model.structure.joints:
                    joint = description.joints[name]
                    made = host.JointInfo()
                    made.name, made.type = name, joint.type
                    made.parent = body_of.get(joint.parent, "")
                    made.child = body_of.get(joint.child, "")
                    if joint.limit is not None:
                        made.lower, made.upper = joint.limit.lower, joint.limit.upper
                        made.effort, made.velocity = joint.limit.effort, joint.limit.velocity
                    if joint.type == "continuous":  # no stops: Gazebo's ±1e16
                        made.lower, made.upper = -1e16, 1e16
                    joints.append(made)
            info.joints = joints
            return info

        def model_state(self, model_name: str) -> List[float]:
            position, orientation = world.pose(model_name)
            linear, angular = world.twist(model_name)
            return [*position, *orientation, *linear, *angular]

        def link_state(self, model_name: str, link: str) -> List[float]:
            from sim_bridge.world import LinkRef
            ref = LinkRef(model_name, link)
            position, orientation = world.link_pose(ref)
            linear, angular = world.link_twist(ref)
            return [*position, *orientation, *linear, *angular]

        def set_model_pose(self, model_name: str, pose: Sequence[float]) -> None:
            linear, angular = world.twist(model_name)
            world.set_state(model_name, pose[:3], pose[3:], linear, angular)

        def set_model_velocity(self, model_name: str, twist: Sequence[float]) -> None:
            model = world.model(model_name)
            if model.kind == "static":
                return
            world.set_twist(model_name, twist[:3], twist[3:])

        def set_link_velocity(self, model_name: str, link: str, twist: Sequence[float]) -> None:
            model = world.model(model_name)
            if link != model.structure.canonical:
                raise RuntimeError(f"Link::SetLinearVel/SetAngularVel of '{model_name}::{link}'"
                                   " is provided for a model's canonical link only")
            self.set_model_velocity(model_name, twist)

        def add_link_wrench(self, model_name: str, link: str, wrench: Sequence[float],
                            in_link_frame: bool) -> None:
            world.add_link_wrench(model_name, link, wrench[:3], wrench[3:], in_link_frame)

        def set_gravity_mode(self, model_name: str, on: bool) -> None:
            world.set_model_gravity(model_name, on)

        def joint_state(self, model_name: str, joint: str) -> List[float]:
            return list(world.model(model_name).robot.joint_position_velocity(joint))

        def set_joint_velocity(self, model_name: str, joint: str, velocity: float) -> None:
            robot = world.model(model_name).robot
            index = robot.joint_index[joint]
            position = pb.getJointState(robot.id, index, physicsClientId=world.client)[0]
            pb.resetJointState(robot.id, index, position, velocity, physicsClientId=world.client)

        def set_joint_motor(self, model_name: str, joint: str, velocity: float,
                            max_force: float) -> None:
            robot = world.model(model_name).robot
            if max_force <= 0:  # ODE's motor off: the joint's own friction brakes it, as at spawn
                velocity, max_force = 0.0, robot.model.joints[joint].friction
            pb.setJointMotorControl2(robot.id, robot.joint_index[joint], pb.VELOCITY_CONTROL,
                                     targetVelocity=velocity, force=max_force,
                                     physicsClientId=world.client)

        def set_joint_force(self, model_name: str, joint: str, force: float) -> None:
            world.set_step_joint_force(model_name, joint, force)

        def sensors(self, model_name: str):
            found = []
            for reader in sensors.of(model_name).values():
                info = host.SensorInfo()
                info.name, info.type, info.link = reader.name, reader.type, reader.link
                info.update_rate, info.always_on = reader.update_rate, reader.always_on
                if reader.type in ("ray", "gpu_ray"):
                    laser = reader.reader
                    info.angle_min, info.angle_max = laser.angle_min, laser.angle_max
                    info.samples = len(laser.directions)
                    info.range_min, info.range_max = laser.range_min, laser.range_max
                found.append(info)
            return found

        def sensor_contacts(self, model_name: str, sensor: str):
            found = []
            for pair in sensors.contacts(model_name, sensor):
                contact = host.ContactInfo()
                (contact.collision1, contact.collision2, contact.positions, contact.normals,
                 contact.depths, contact.forces, contact.torques) = pair
                found.append(contact)
            return found

        def sensor_ranges(self, model_name: str, sensor: str) -> List[float]:
            return sensors.ranges(model_name, sensor)

        def sensor_imu(self, model_name: str, sensor: str) -> List[float]:
            return sensors.imu(model_name, sensor)

    return _Backend()
