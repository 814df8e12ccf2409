"""Single-joint controllers with a ``std_msgs/Float64`` on ``<controller>/command``:

- ``position_controllers/JointPositionController``: the command is the joint's position;
- ``velocity_controllers/JointVelocityController``: its velocity;
- ``effort_controllers/JointEffortController``: its effort;
- ``effort_controllers/JointPositionController`` and ``velocity_controllers/
  JointPositionController``: a position, reached through the PID under ``pid``
  (control_toolbox's, see :mod:`.pid`) whose output is the joint's effort or velocity
  command (:class:`PidPositionController`, as ros_controllers noetic-devel 678b92a
  effort_controllers/src/joint_position_controller.cpp and
  velocity_controllers/src/joint_position_controller.cpp, the same code on another
  interface): the command is clamped to the URDF's ``<limit lower upper>`` for revolute and
  prismatic joints (enforceJointLimits, :253-267), the error is
  shortest_angular_distance_with_large_limits for a revolute joint, shortest_angular_distance
  for a continuous one, the difference for a prismatic one (:181-198), the PID's
  computeCommand(error, dt) (:214); ``<controller>/state`` (control_msgs/
  JointControllerState) every 10 updates, the first on the first (:219-244);
- ``effort_controllers/JointVelocityController``: a velocity, through the PID the same way
  (effort_controllers/src/joint_velocity_controller.cpp:133-168, its ``state`` too);
- the group kin (``position_controllers/JointGroupPositionController``,
  ``velocity_controllers/JointGroupVelocityController``,
  ``effort_controllers/JointGroupEffortController``,
  ``effort_controllers/JointGroupPositionController``): ``joints`` and a
  ``std_msgs/Float64MultiArray``, one value a joint (:class:`GroupController`); the effort
  group position controller clamps and wraps as the single one
  (effort_controllers/src/joint_group_position_controller.cpp:123-200), with no ``state``.

A NaN or inf command is ignored with a throttled warning.
"""
from __future__ import annotations

import math

from control_msgs.msg import JointControllerState
from std_msgs.msg import Float64, Float64MultiArray

from sim_bridge.plugins.base import PluginError, stamp
from sim_bridge.ros_control.angles import (shortest_angular_distance,
                                           shortest_angular_distance_with_large_limits)
from sim_bridge.ros_control.controller_base import Controller
from sim_bridge.ros_control.pid import Pid

# the PID controllers publish their state once every this many updates, the first on the
# first update (loop_count_ % 10 == 0: effort_controllers/src/joint_position_controller.cpp:220,
# velocity_controllers/src/joint_position_controller.cpp:221,
# effort_controllers/src/joint_velocity_controller.cpp:144)
STATE_EVERY_UPDATES = 10


class UrdfJoint:
    """What the PID position controllers read from the URDF joint (``urdf.getJoint``): its
    type and ``<limit lower upper>`` (joint_position_controller.cpp:82-93)."""

    def __init__(self, robot, joint: str):
        description = robot.model.joints[joint]
        self.type = description.type
        limit = description.limit
        # a revolute or prismatic joint without <limit> does not parse in urdfdom; here it
        # is taken as unbounded
        self.lower = limit.lower if limit is not None and limit.lower is not None else -math.inf
        self.upper = limit.upper if limit is not None and limit.upper is not None else math.inf

    def enforce_limits(self, command: float) -> float:
        """enforceJointLimits (joint_position_controller.cpp:253-267): revolute and prismatic
        joints' commands within [lower, upper]."""
        if self.type in ("revolute", "prismatic"):
            if command > self.upper:
                return self.upper
            if command < self.lower:
                return self.lower
        return command

    def position_error(self, current: float, command: float) -> float:
        """The position error (joint_position_controller.cpp:181-198)."""
        if self.type == "revolute":
            return shortest_angular_distance_with_large_limits(current, command, self.lower,
                                                               self.upper)
        if self.type == "continuous":
            return shortest_angular_distance(current, command)
        return command - current


class StatePublisher:
    """``<controller>/state``, control_msgs/JointControllerState (queue 1), every
    ``STATE_EVERY_UPDATES`` updates counted from the controller's construction (loop_count_
    is not reset by starting); the gains as getGains gives them (i_clamp is i_max)."""

    def __init__(self, io, name: str, pid: Pid):
        self.pid = pid
        self.loop_count = 0
        self.output = io.bus.publisher(io.topic(f"{name}/state"), JointControllerState,
                                       queue_size=1)

    def update(self, now_ns: int, dt: float, set_point: float, process_value: float,
               process_value_dot: float, error: float, command: float) -> None:
        if self.loop_count % STATE_EVERY_UPDATES == 0:
            pid = self.pid
            message = JointControllerState(
                set_point=set_point, process_value=process_value,
                process_value_dot=process_value_dot, error=error, time_step=dt,
                command=command, p=pid.p, i=pid.i, d=pid.d, i_clamp=pid.i_max,
                antiwindup=pid.antiwindup)
            message.header.stamp = stamp(now_ns)
            self.output.publish(message)
        self.loop_count += 1

    def close(self) -> None:
        self.output.unregister()


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


class PidPositionController(SingleJointController):
    """A position through the PID, its output the joint's effort (``effort_controllers``)
    or velocity (``velocity_controllers``) command."""

    def __init__(self, name, params, hardware, io):
        super().__init__(name, params, hardware, io)
        self.pid = Pid(self.params.get("pid", {}), f"controller '{name}'")
        self.urdf = UrdfJoint(io.robot, self.handle.name)
        self.state = StatePublisher(io, name, self.pid)

    def start(self, now_ns):
        position, _, _ = self.hardware.state(self.handle.name)
        self.target = self.urdf.enforce_limits(position)  # starting (:151-164)
        self.pid.reset()

    def update(self, now_ns, dt):
        position, velocity, _ = self.hardware.state(self.handle.name)
        target = self.urdf.enforce_limits(self.target)
        error = self.urdf.position_error(position, target)
        command = self.pid.compute(error, dt)  # computeCommand(error, period) (:214)
        self.handle.command = command
        self.state.update(now_ns, dt, target, position, velocity, error, command)

    def close(self):
        super().close()
        self.state.close()


class EffortPositionController(PidPositionController):
    interface = "effort"


class VelocityPositionController(PidPositionController):
    interface = "velocity"


class EffortVelocityController(SingleJointController):
    interface = "effort"
    commands = "velocity"

    def __init__(self, name, params, hardware, io):
        super().__init__(name, params, hardware, io)
        self.pid = Pid(self.params.get("pid", {}), f"controller '{name}'")
        self.state = StatePublisher(io, name, self.pid)

    def start(self, now_ns):
        super().start(now_ns)
        self.pid.reset()

    def update(self, now_ns, dt):
        _, velocity, _ = self.hardware.state(self.handle.name)
        error = self.target - velocity
        # computeCommand(error, period) (joint_velocity_controller.cpp:135-140)
        command = self.pid.compute(error, dt)
        self.handle.command = command
        # its state leaves process_value_dot at 0 (:148-153)
        self.state.update(now_ns, dt, self.target, velocity, 0.0, error, command)

    def close(self):
        super().close()
        self.state.close()


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
    its gains under ``<controller>/<joint>/pid``; limits and error as the single one."""

    interface = "effort"

    def __init__(self, name, params, hardware, io):
        super().__init__(name, params, hardware, io)
        self.pids = [Pid((self.params.get(joint) or {}).get("pid", {}),
                         f"controller '{name}' joint '{joint}'") for joint in self.joints]
        self.urdfs = [UrdfJoint(io.robot, joint) for joint in self.joints]

    def start(self, now_ns):
        # starting (joint_group_position_controller.cpp:123-133): the clamped positions
        self.targets = [urdf.enforce_limits(self.hardware.state(joint)[0])
                        for joint, urdf in zip(self.joints, self.urdfs)]
        for pid in self.pids:
            pid.reset()

    def update(self, now_ns, dt):
        for handle, target, pid, urdf in zip(self.handles, self.targets, self.pids, self.urdfs):
            position, _, _ = self.hardware.state(handle.name)
            error = urdf.position_error(position, urdf.enforce_limits(target))  # :145-167
            # computeCommand(error, period) (:171)
            handle.command = pid.compute(error, dt)
