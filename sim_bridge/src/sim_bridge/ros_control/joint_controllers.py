"""Single-joint controllers with a ``std_msgs/Float64`` on ``<controller>/command``:

- ``position_controllers/JointPositionController``: the command is the joint's position;
- ``velocity_controllers/JointVelocityController``: its velocity;
- ``effort_controllers/JointEffortController``: its effort;
- ``effort_controllers/JointPositionController``: a position, reached through the PID
  under ``pid`` (p, i, d, i_clamp);
- ``effort_controllers/JointVelocityController``: a velocity, through the PID.

A NaN or inf command is ignored with a throttled warning.
"""
from __future__ import annotations

import math

from std_msgs.msg import Float64

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
        position, velocity, _ = self.hardware.state(self.handle.name)
        self.handle.command = self.pid.command(self.target - position, -velocity, dt)


class EffortVelocityController(SingleJointController):
    interface = "effort"
    commands = "velocity"

    def __init__(self, name, params, hardware, io):
        super().__init__(name, params, hardware, io)
        self.pid = Pid(self.params.get("pid", {}), f"controller '{name}'")
        self._last_error = 0.0

    def start(self, now_ns):
        super().start(now_ns)
        self.pid.reset()

    def update(self, now_ns, dt):
        _, velocity, _ = self.hardware.state(self.handle.name)
        error = self.target - velocity
        rate = (error - self._last_error) / dt if dt > 0 else 0.0
        self._last_error = error
        self.handle.command = self.pid.command(error, rate, dt)
