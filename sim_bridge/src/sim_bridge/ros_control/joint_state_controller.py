"""``joint_state_controller/JointStateController`` on ``joint_states`` in the robot's
namespace, as ros_controllers' (noetic-devel 678b92a,
joint_state_controller/src/joint_state_controller.cpp, "jsc" below):

- ``publish_rate`` (Hz of simulated time) is required: without it the controller does not
  load, "Parameter 'publish_rate' not set" (jsc:64-67); 0 or less loads and never publishes
  (jsc:105). The first update publishes (jsc:94).
- ``joints``: which joints, in that order (jsc:52-57); without it every transmission joint,
  sorted by name, as hardware_interface's getNames walks a std::map (jsc:56; ros_control
  noetic-devel 633c374 hardware_interface/include/hardware_interface/internal/
  resource_manager.h:77-86, :147). A name the hardware lacks: the controller does not load.
- ``extra_joints``: a list of ``{name, position, velocity, effort}`` appended with those
  fixed values (0 when left out); an entry without a name, with a value that is not a double
  or with a name already published is named in a warning and left out (jsc:129-201).
"""
from __future__ import annotations

from sensor_msgs.msg import JointState

from sim_bridge.plugins.base import PluginError, Rate, stamp
from sim_bridge.ros_control.controller_base import Controller


class JointStateController(Controller):
    def __init__(self, name, params, hardware, io):
        super().__init__(name, params, hardware, io)
        joints = self.params.get("joints")
        if isinstance(joints, list) and all(isinstance(j, str) for j in joints):  # jsc:52
            missing = [j for j in joints if j not in hardware.joints]
            if missing:  # getHandle throws (resource_manager.h:113-124)
                raise PluginError(f"Could not find resource '{missing[0]}' in "
                                  "'hardware_interface::JointStateInterface'.")
            self.names = list(joints)
        else:
            self.names = sorted(hardware.names)  # jsc:56
        rate = self.params.get("publish_rate")
        if isinstance(rate, bool) or not isinstance(rate, (int, float)):  # jsc:64-67
            raise PluginError("Parameter 'publish_rate' not set")
        self.rate = Rate(float(rate)) if rate > 0 else None  # jsc:105
        self._indices = [hardware.names.index(j) for j in self.names]
        self.extra = self._extra_joints()
        self.output = io.bus.publisher(io.topic("joint_states"), JointState, queue_size=1)

    def _extra_joints(self):
        """addExtraJoints (jsc:129-201): (name, position, velocity, effort) tuples."""
        given = self.params.get("extra_joints")
        if given is None:
            return []
        warn = self.io.bus.warn
        if not isinstance(given, list):
            warn(f"{self.name}: Extra joints specification is not an array. Ignoring.")
            return []
        extra, names = [], list(self.names)
        for element in given:
            if not isinstance(element, dict):
                warn(f"{self.name}: Extra joint specification is not a struct, but rather "
                     f"'{element!r}'. Ignoring.")
                continue
            if "name" not in element:
                warn(f"{self.name}: Extra joint does not specify name. Ignoring.")
                continue
            name = str(element["name"])
            if name in names:
                warn(f"{self.name}: Joint state interface already contains specified extra "
                     f"joint '{name}'.")
                continue
            values, valid = [], True
            for key in ("position", "velocity", "effort"):
                value = element.get(key, 0.0)
                if not isinstance(value, float):  # XmlRpc TypeDouble only
                    warn(f"{self.name}: Extra joint '{name}' does not specify a valid default "
                         f"{key}. Ignoring.")
                    valid = False
                    break
                values.append(value)
            if valid:
                extra.append((name, *values))
                names.append(name)
        return extra

    def start(self, now_ns):
        if self.rate is not None:
            self.rate.reset(now_ns)

    def update(self, now_ns, dt):
        if self.rate is None or not self.rate.due(now_ns):
            return
        message = JointState()
        message.header.stamp = stamp(now_ns)
        message.name = self.names + [e[0] for e in self.extra]
        message.position = self.hardware.positions[self._indices].tolist() + \
            [e[1] for e in self.extra]
        message.velocity = self.hardware.velocities[self._indices].tolist() + \
            [e[2] for e in self.extra]
        message.effort = self.hardware.efforts[self._indices].tolist() + \
            [e[3] for e in self.extra]
        self.output.publish(message)

    def close(self):
        self.output.unregister()
