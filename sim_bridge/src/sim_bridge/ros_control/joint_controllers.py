"""Single-joint controllers with a ``std_msgs/Float64`` on ``<controller>/command``:

- ``position_controllers/JointPositionController``: the command is the joint's position;
- ``velocity_controllers/JointVelocityController``: its velocity;
- ``effort_controllers/JointEffortController``: its effort;
- ``effort_controllers/JointPositionController``: a position, reached through the PID
  under ``pid`` (control_toolbox's, see :mod:`.pid`) on the position error, its derivative
  from the error's difference: Pid::computeCommand(error, dt), as ros_controllers
  noetic-devel 678b92a effort_controllers/src/joint_position_controller.cpp:214;
- ``effort_controllers/JointVelocityController``: a velocity, through the PID the same way
  (effort_controllers/src/joint_velocity_controller.cpp:140);
- the group kin (``position_controllers/JointGroupPositionController``,
  ``velocity_controllers/JointGroupVelocityController``,
  ``effort_controllers/JointGroupEffortController``,
  ``effort_controllers/JointGroupPositionController``): ``joints`` and a
  ``std_msgs/Float64MultiArray``, one value a joint (:class:`GroupController`).

A NaN or inf command is ignored with a throttled warning.
"""
from __future__ import annotations

import math

from std_msgs.msg import Float64, Float64MultiArray

from sim_bridge.plugins.base import PluginError
from sim_bridge.ros_control.controller_base import Controller
from sim_bridge.ros_control.pid import Pid


class SingleJointController(Controller):
    # what the command means: "position", "velocity" or "effort"
    commands = "position"

    def __init__(self, name, params, hardware, io):
        super().__init__(name, params, hardware, io)
        self.claim([str(self.required("joint"))])
        self.handle = hardware.joints[self.joints[0]]
        self.target = 0.0
        self.topic = io.topic(f"{name}/command")
        self._subscription = io.bus.subscriber(self.topic, Float64, self._on_command)

    def _on_command(self, message):
        if not math.isfinite(message.data):
            self.io.bus.warn_throttled(f"{self.topic}:nan", 5.0,
                                       f"{self.topic}: ignoring {message.data}; the command "
                                       "must be a finite number")
            return
        self.target = message.data

    def start(self, now_ns):
        position, _, _ = self.hardware.state(self.handle.name)
        self.target = position if self.commands == "position" else 0.0

    def update(self, now_ns, dt):
        self.handle.command = self.target

    def close(self):
        self._subscription.unregister()


class PositionController(SingleJointController):
    interface = "position"


class VelocityController(SingleJointController):
    interface = "velocity"
    commands = "velocity"


class EffortController(SingleJointController):
    interface = "effort"
    commands = "effort"


class EffortPositionController(SingleJointController):
    interface = "effort"

    def __init__(self, name, params, hardware, io):
        super().__init__(name, params, hardware, io)
        self.pid = Pid(self.params.get("pid", {}), f"controller '{name}'")

    def start(self, now_ns):
        super().start(now_ns)
        self.pid.reset()

    def update(self, now_ns, dt):
        position, _, _ = self.hardware.state(self.handle.name)
        # computeCommand(error, period) (joint_position_controller.cpp:214)
        self.handle.command = self.pid.compute(self.target - position, dt)


class EffortVelocityController(SingleJointController):
    interface = "effort"
    commands = "velocity"

    def __init__(self, name, params, hardware, io):
        super().__init__(name, params, hardware, io)
        self.pid = Pid(self.params.get("pid", {}), f"controller '{name}'")

    def start(self, now_ns):
        super().start(now_ns)
        self.pid.reset()

    def update(self, now_ns, dt):
        _, velocity, _ = self.hardware.state(self.handle.name)
        # computeCommand(error, period) (joint_velocity_controller.cpp:135-140)
        self.handle.command = self.pid.compute(self.target - velocity, dt)


class GroupController(Controller):
    """ros_controllers' forward command group controllers: ``joints`` (a list), a
    ``std_msgs/Float64MultiArray`` on ``<controller>/command`` with one value per joint, in
    order. A command of another length is ignored, named, as ros_controllers does ("Not
    executing!"); so is one with a NaN or inf."""

    commands = "position"

    def __init__(self, name, params, hardware, io):
        super().__init__(name, params, hardware, io)
        joints = self.required("joints")
        if not isinstance(joints, list) or not joints or \
                not all(isinstance(joint, str) for joint in joints):
            raise PluginError(f"controller '{name}': 'joints' must be a list of joint names")
        self.claim(joints)
        self.handles = [hardware.joints[joint] for joint in self.joints]
        self.targets = [0.0] * len(self.joints)
        self.topic = io.topic(f"{name}/command")
        self._subscription = io.bus.subscriber(self.topic, Float64MultiArray, self._on_command)

    def _on_command(self, message):
        values = list(message.data)
        if len(values) != len(self.joints):
            self.io.bus.warn_throttled(
                f"{self.topic}:size", 5.0,
                f"{self.topic}: a command of {len(values)} values for {len(self.joints)} "
                f"joints ({', '.join(self.joints)}); not executing")
            return
        if not all(math.isfinite(value) for value in values):
            self.io.bus.warn_throttled(f"{self.topic}:nan", 5.0,
                                       f"{self.topic}: ignoring {values}; every value must "
                                       "be a finite number")
            return
        self.targets = values

    def start(self, now_ns):
        self.targets = [self.hardware.state(joint)[0] if self.commands == "position" else 0.0
                        for joint in self.joints]

    def update(self, now_ns, dt):
        for handle, target in zip(self.handles, self.targets):
            handle.command = target

    def close(self):
        self._subscription.unregister()


class GroupPositionController(GroupController):
    interface = "position"


class GroupVelocityController(GroupController):
    interface = "velocity"
    commands = "velocity"


class GroupEffortController(GroupController):
    interface = "effort"
    commands = "effort"


class GroupEffortPositionController(GroupController):
    """effort_controllers/JointGroupPositionController: positions through one PID a joint,
    its gains under ``<controller>/<joint>/pid``."""

    interface = "effort"

    def __init__(self, name, params, hardware, io):
        super().__init__(name, params, hardware, io)
        self.pids = [Pid((self.params.get(joint) or {}).get("pid", {}),
                         f"controller '{name}' joint '{joint}'") for joint in self.joints]

    def start(self, now_ns):
        super().start(now_ns)
        for pid in self.pids:
            pid.reset()

    def update(self, now_ns, dt):
        for handle, target, pid in zip(self.handles, self.targets, self.pids):
            position, _, _ = self.hardware.state(handle.name)
            # computeCommand(error, period) (joint_group_position_controller.cpp:171)
            handle.command = pid.compute(target - position, dt)
