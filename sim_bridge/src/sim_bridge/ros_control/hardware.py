"""The robot as ros_control's controllers see it: the joints that have a transmission, each
with the interface its transmission names (position, velocity or effort).

As gazebo_ros_control's DefaultRobotHWSim (gazebo_ros_pkgs noetic-devel f9e1a46,
gazebo_ros_control/src/default_robot_hw_sim.cpp; "hw_sim" below), with its joint limits
(ros_control noetic-devel 633c374, joint_limits_interface; "JLI" below):

- limits: registerJointLimits (hw_sim:393-510) reads the URDF ``<limit>`` (JLI
  joint_limits_urdf.h:48-76: position limits for revolute and prismatic joints, the velocity
  and effort limits always) and then ``<robotNamespace>/joint_limits/<joint>`` on the
  parameter server (JLI joint_limits_rosparam.h:75-169, hw_sim:69, :425-426). A joint with
  neither gets no limit at all: its effort limit is DBL_MAX (hw_sim:404, :428-429);
  ``effort="0"`` is a limit of 0 (hw_sim:453-454).
- every command passes the saturation handle of its interface before it reaches the joint
  (hw_sim:302-307, :485-508): a velocity command is clamped to ±``velocity``
  (VelocityJointSaturationHandle, JLI joint_limits_interface.h:425-455); a position command
  to [lower, upper] and, from the previous command, by at most ``velocity``·dt a write
  (PositionJointSaturationHandle, :91-112); an effort command to ±``effort``, and to 0 in
  the direction that would push the joint further past a position limit or past its
  velocity limit (EffortJointSaturationHandle, :285-306).
- position joints move to their command whatever their effort limit: Gazebo sets their
  position (hw_sim:320-326, ``SetPosition``, kinematic); here pybullet's position motor with
  no force limit follows it. Velocity joints: the velocity motor with the effort limit as
  its most force (hw_sim:240, :363); 0 leaves the joint free, as ODE's ``fmax`` 0 does.
  Effort joints: the (saturated) command as a joint torque (hw_sim:313-318).
- ``<robotNamespace>/gazebo_ros_control/pid_gains/<joint>`` (control_toolbox's Pid gains,
  see :mod:`.pid`) on a position or velocity joint: the joint becomes effort-driven
  (hw_sim:216-233), its command reached through that PID every write, computeCommand(error,
  dt), the effort clamped to ±the effort limit (hw_sim:328-353, :370-380); the position error
  shortest_angular_distance_with_limits within the joint's position limits for a revolute
  joint, shortest_angular_distance for a continuous one, the difference otherwise. Gains
  without a numeric ``p`` leave the joint as it was (Pid::init fails), named in a warning.
- before a controller commands them, position joints hold where they were spawned (or set
  by ``spawn_model -J`` or ``set_model_configuration``), velocity joints hold still, effort
  joints are free. Here sim_bridge differs on purpose: Noetic's position command starts at
  0 (hw_sim:138) and is written every step (hw_sim:320-326), so until a controller starts a
  position-controlled arm is driven to 0 and a spawn or ``-J`` pose is lost, a known fault
  (gazebo_ros_pkgs issue #93, open, labelled bug) that the design does not copy
  (sim_bridge/doc/ros_control.md, "Where sim_bridge differs on purpose").

- the emergency stop (:meth:`RobotHardware.write` with ``e_stop``, hw_sim:287-300, :315,
  :359-375): position commands are the positions read when it began, efforts 0, velocity
  commands 0 (a velocity PID's error is -velocity).

Not read: ``<safety_controller>`` soft limits (hw_sim:420-421, :456-482).
"""
from __future__ import annotations

import math
import sys
from dataclasses import dataclass
from typing import Any, Dict, Iterable, List, Mapping, Optional, Tuple

import numpy as np
import pybullet as pb

from sim_bridge.plugins.base import PluginError, resolve_topic
from sim_bridge.ros_control.angles import (shortest_angular_distance,
                                           shortest_angular_distance_with_limits)
from sim_bridge.ros_control.pid import Pid

INTERFACES = {
    "PositionJointInterface": "position",
    "VelocityJointInterface": "velocity",
    "EffortJointInterface": "effort",
}
# DefaultRobotHWSim's effort limit for a joint with no limit at all: DBL_MAX (hw_sim:404)
UNLIMITED = math.inf
# its position limits for the PID's error when the joint has none: ±DBL_MAX (hw_sim:402-403)
NO_POSITION_LIMIT = sys.float_info.max
# the mimic joint plugin's fallback force (plugins/mimic_joint.py imports it); ros_control's
# joints do not use it
DEFAULT_EFFORT = 1000.0


# the namespace DefaultRobotHWSim expects before an interface's name; the bare name is
# accepted, with a deprecation warning (hw_sim:153-186)
INTERFACE_PREFIX = "hardware_interface/"


def interface_of(name: str, joint: str = "", warn=None) -> str:
    """The command interface a ``<hardwareInterface>`` names: ``hardware_interface/<Name>``
    or the bare ``<Name>`` (deprecated: warned), nothing else (hw_sim:153-186)."""
    short = name[len(INTERFACE_PREFIX):] if name.startswith(INTERFACE_PREFIX) else name
    if short not in INTERFACES:
        raise PluginError(f"No matching hardware interface found for '{name}' while loading "
                          f"interfaces for {joint}: it must be one of "
                          f"{', '.join(INTERFACE_PREFIX + i for i in INTERFACES)}")
    if short == name and warn is not None:
        warn(f"Deprecated syntax, please prepend '{INTERFACE_PREFIX}' to '{name}' within the "
             f"<hardwareInterface> tag in joint '{joint}'.")
    return INTERFACES[short]


def parsed_transmissions(transmissions, warn) -> List[Tuple[str, str, str]]:
    """(transmission, joint, hardware interface) for each transmission ros_control's
    TransmissionParser keeps (ros_control noetic-devel 633c374 transmission_interface/src/
    transmission_parser.cpp:57-113) and DefaultRobotHWSim takes (hw_sim:88-141): a
    ``<type>`` with text, joints with a ``<hardwareInterface>`` (others are dropped,
    :155-175), an ``<actuator>`` with a name (:195-258), one joint only, its first
    interface. The others are skipped, each named in a warning, as upstream logs them."""
    kept = []
    for transmission in transmissions:
        name = transmission.name
        if not name:  # :63-76
            warn("No name attribute specified for transmission.")
            continue
        if transmission.type is None:  # :79-85
            warn(f"No type element found in transmission '{name}'.")
            continue
        if not transmission.type:  # :86-91
            warn(f"Skipping empty type element in transmission '{name}'.")
            continue
        joints = []
        for joint, interfaces in zip(transmission.joints, transmission.joint_interfaces):
            if not joint:  # :134-147
                warn("Empty name attribute specified for joint.")
            elif not interfaces:  # :170-175
                warn(f"No valid hardware interface element found in joint '{joint}'.")
            else:
                joints.append((joint, interfaces))
        if not joints:  # :95-100
            warn(f"Failed to load joints for transmission '{name}'.")
            continue
        if None in transmission.actuators or not any(transmission.actuators):  # :103-108
            warn(f"Failed to load actuators for transmission '{name}'.")
            continue
        if len(joints) > 1:  # hw_sim:97-103
            warn(f"Transmission {name} has more than one joint. Currently the default robot "
                 "hardware simulation interface only supports one.")
            continue
        joint, interfaces = joints[0]
        if len(interfaces) > 1:  # hw_sim:124-130
            warn(f"Joint {joint} of transmission {name} specifies multiple hardware "
                 "interfaces. Currently the default robot hardware simulation interface only "
                 "supports one. Using the first entry")
        kept.append((name, joint, interfaces[0]))
    return kept


@dataclass
class JointLimits:
    """joint_limits_interface::JointLimits (JLI joint_limits.h:36-51)."""

    min_position: float = 0.0
    max_position: float = 0.0
    max_velocity: float = 0.0
    max_acceleration: float = 0.0
    max_jerk: float = 0.0
    max_effort: float = 0.0
    has_position_limits: bool = False
    has_velocity_limits: bool = False
    has_acceleration_limits: bool = False
    has_jerk_limits: bool = False
    has_effort_limits: bool = False
    angle_wraparound: bool = False


@dataclass
class SoftJointLimits:
    """joint_limits_interface::SoftJointLimits (JLI joint_limits.h), from the URDF's
    ``<safety_controller>`` only: getSoftJointLimits (JLI joint_limits_urdf.h:84-97);
    DefaultRobotHWSim never reads them from the parameter server (hw_sim:408-426)."""

    min_position: float
    max_position: float
    k_position: float
    k_velocity: float


def urdf_soft_limits(joint) -> Optional[SoftJointLimits]:
    """getSoftJointLimits(urdf_joint, soft_limits) (JLI joint_limits_urdf.h:84-97): None
    when the joint has no ``<safety_controller>``."""
    safety = getattr(joint, "safety", None)
    if safety is None:
        return None
    return SoftJointLimits(safety.soft_lower_limit, safety.soft_upper_limit,
                           safety.k_position, safety.k_velocity)


def urdf_limits(joint, limits: JointLimits) -> bool:
    """getJointLimits(urdf_joint, limits) (JLI joint_limits_urdf.h:48-76): False when the
    joint has no ``<limit>``."""
    if joint.limit is None:
        return False
    limits.has_position_limits = joint.type in ("revolute", "prismatic")
    if limits.has_position_limits:
        limits.min_position, limits.max_position = joint.limit.lower, joint.limit.upper
    if not limits.has_position_limits and joint.type == "continuous":
        limits.angle_wraparound = True
    limits.has_velocity_limits, limits.max_velocity = True, joint.limit.velocity
    limits.has_acceleration_limits = False
    limits.has_effort_limits, limits.max_effort = True, joint.limit.effort
    return True


def _is_number(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def rosparam_limits(params: Any, limits: JointLimits) -> bool:
    """getJointLimits(joint_name, nh, limits) (JLI joint_limits_rosparam.h:75-169) on the
    dict under ``joint_limits/<joint>``: False when there is none. A ``has_*`` that is not a
    bool, or a value that is not a number, is not read (roscpp's getParam fails on them)."""
    if params is None:
        return False
    if not isinstance(params, Mapping):
        return True  # the parameter exists (hasParam): nothing in it is read

    def flag(key):
        value = params.get(key)
        return value if isinstance(value, bool) else None

    def number(key):
        value = params.get(key)
        return float(value) if _is_number(value) else None

    has = flag("has_position_limits")
    if has is not None:  # :97-114
        if not has:
            limits.has_position_limits = False
        low, high = number("min_position"), number("max_position")
        if has and low is not None and high is not None:
            limits.has_position_limits, limits.min_position, limits.max_position = True, low, high
        wrap = flag("angle_wraparound")
        if not has and wrap is not None:
            limits.angle_wraparound = wrap
    for kind, key in (("velocity", "max_velocity"), ("acceleration", "max_acceleration"),
                      ("jerk", "max_jerk"), ("effort", "max_effort")):  # :116-166
        has = flag(f"has_{kind}_limits")
        if has is None:
            continue
        if not has:
            setattr(limits, f"has_{kind}_limits", False)
        value = number(key)
        if has and value is not None:
            setattr(limits, f"has_{kind}_limits", True)
            setattr(limits, key, value)
    return True


def _saturate(value: float, low: float, high: float) -> float:
    """internal::saturate (JLI joint_limits_interface.h:53-57): min(max(v, low), high)."""
    return min(max(value, low), high)


@dataclass
class JointHandle:
    name: str
    index: int
    interface: str
    joint_type: str  # the URDF's: revolute, continuous, prismatic
    # DefaultRobotHWSim's joint_effort_limits_: the limit's max_effort, else DBL_MAX
    effort_limit: float
    # the limits of its saturation handle; None: no handle (a joint with no limits)
    limits: Optional[JointLimits] = None
    # a <safety_controller>'s: the soft-limits handle replaces the saturation one
    # (hw_sim:456-482)
    soft: Optional[SoftJointLimits] = None
    command: float = 0.0
    # the handles' prev_cmd_: position (NaN until the first write), velocity (0.0)
    previous: float = math.nan
    # gazebo_ros_control/pid_gains/<joint>: POSITION_PID or VELOCITY_PID (hw_sim:216-233)
    pid: Optional[Pid] = None
    # registerJointLimits' lower and upper limits, for the PID's error (hw_sim:401-403, :448-452)
    lower_limit: float = -NO_POSITION_LIMIT
    upper_limit: float = NO_POSITION_LIMIT
    # the effort the last write applied (SetForce: an effort joint's saturated command, 0
    # during the emergency stop; a PID joint's), what readSim's GetForce(0) reads back
    applied_effort: float = 0.0

    def pid_effort(self, position: float, velocity: float, period: float,
                   e_stop: bool = False) -> float:
        """POSITION_PID and VELOCITY_PID (hw_sim:328-353, :370-380): the PID's effort toward
        the (saturated) command, clamped to ±the effort limit."""
        if self.interface == "velocity":
            error = -velocity if e_stop else self.command - velocity
        elif self.joint_type == "revolute":
            error = shortest_angular_distance_with_limits(position, self.command,
                                                          self.lower_limit, self.upper_limit)
        elif self.joint_type == "continuous":
            error = shortest_angular_distance(position, self.command)
        else:
            error = self.command - position
        effort = self.pid.compute(error, period)
        return _saturate(effort, -self.effort_limit, self.effort_limit)

    def saturate(self, position: float, velocity: float, period: float) -> None:
        """The saturation handle's enforceLimits on ``command`` (hw_sim:302-307), or the
        soft-limits handle's when the joint has a ``<safety_controller>``."""
        limits = self.limits
        if limits is None:
            return
        if self.soft is not None:
            self._enforce_soft_limits(position, velocity, period)
            return
        if self.interface == "position":  # PositionJointSaturationHandle (JLI :91-112)
            if math.isnan(self.previous):
                self.previous = position
            low, high = ((limits.min_position, limits.max_position)
                         if limits.has_position_limits else (-math.inf, math.inf))
            if limits.has_velocity_limits:
                step = limits.max_velocity * period
                low, high = max(self.previous - step, low), min(self.previous + step, high)
            self.command = _saturate(self.command, low, high)
            self.previous = self.command
        elif self.interface == "velocity":  # VelocityJointSaturationHandle (JLI :425-455)
            low, high = -limits.max_velocity, limits.max_velocity
            if limits.has_acceleration_limits:
                step = limits.max_acceleration * period
                low, high = max(self.previous - step, low), min(self.previous + step, high)
            self.command = _saturate(self.command, low, high)
            self.previous = self.command
        else:  # EffortJointSaturationHandle (JLI :285-306)
            low, high = -limits.max_effort, limits.max_effort
            if limits.has_position_limits:
                if position < limits.min_position:
                    low = 0.0
                elif position > limits.max_position:
                    high = 0.0
            if velocity < -limits.max_velocity:
                low = 0.0
            elif velocity > limits.max_velocity:
                high = 0.0
            self.command = _saturate(self.command, low, high)

    def _soft_velocity_bounds(self, position: float, max_velocity: float) -> Tuple[float, float]:
        """The velocities the soft limits allow at ``position``: -k_position times the
        distance past each soft limit, within ±max_velocity; no position limits (a
        continuous joint): ±max_velocity (JLI joint_limits_interface.h:203-219, :360-376,
        :493-506)."""
        if not self.limits.has_position_limits:
            return -max_velocity, max_velocity
        soft = self.soft
        return (_saturate(-soft.k_position * (position - soft.min_position),
                          -max_velocity, max_velocity),
                _saturate(-soft.k_position * (position - soft.max_position),
                          -max_velocity, max_velocity))

    def _enforce_soft_limits(self, position: float, velocity: float, period: float) -> None:
        limits = self.limits
        if self.interface == "position":  # PositionJointSoftLimitsHandle (JLI :188-241)
            if math.isnan(self.previous):
                self.previous = position
            low_velocity, high_velocity = self._soft_velocity_bounds(self.previous,
                                                                     limits.max_velocity)
            low = self.previous + low_velocity * period
            high = self.previous + high_velocity * period
            if limits.has_position_limits:  # a soft limit beyond the hard one (:226-231)
                low, high = max(low, limits.min_position), min(high, limits.max_position)
            self.command = _saturate(self.command, low, high)
            self.previous = self.command
        elif self.interface == "velocity":  # VelocityJointSoftLimitsHandle (JLI :488-517)
            max_velocity = limits.max_velocity if limits.has_velocity_limits else math.inf
            low, high = self._soft_velocity_bounds(position, max_velocity)
            if limits.has_acceleration_limits:
                step = limits.max_acceleration * period
                low, high = max(velocity - step, low), min(velocity + step, high)
            self.command = _saturate(self.command, low, high)
        else:  # EffortJointSoftLimitsHandle (JLI :348-392)
            low_velocity, high_velocity = self._soft_velocity_bounds(position,
                                                                     limits.max_velocity)
            low = _saturate(-self.soft.k_velocity * (velocity - low_velocity),
                            -limits.max_effort, limits.max_effort)
            high = _saturate(-self.soft.k_velocity * (velocity - high_velocity),
                             -limits.max_effort, limits.max_effort)
            self.command = _saturate(self.command, low, high)

    def reset_saturation(self) -> None:
        """PositionJointSaturationHandle::reset (JLI :117-119): the next write starts from
        where the joint is. Velocity: from standing still."""
        self.previous = math.nan if self.interface == "position" else 0.0


class RobotHardware:
    def __init__(self, context, transmissions, namespace: str = ""):
        robot = context.robot
        self.client = context.client
        self.body = robot.id
        self.step_size = context.step_size
        self.joints: Dict[str, JointHandle] = {}
        for transmission, joint, name in parsed_transmissions(transmissions, context.bus.warn):
            interface = interface_of(name, joint, context.bus.warn)
            if joint not in robot.joint_index:  # hw_sim:191-197
                raise PluginError(f"transmission '{transmission}' names joint '{joint}', which "
                                  f"model '{context.model_name}' does not have")
            description = robot.model.joints[joint]
            limits = self._limits(context.bus, namespace, description, interface)
            effort = (limits.max_effort if limits is not None and limits.has_effort_limits
                      else UNLIMITED)  # hw_sim:404, :453-454
            handle = JointHandle(joint, robot.joint_index[joint], interface,
                                 description.type, effort, limits,
                                 soft=urdf_soft_limits(description) if limits else None)
            if handle.soft is not None and interface == "position" \
                    and not limits.has_velocity_limits:  # JLI :172-176
                raise PluginError(f"Cannot enforce limits for joint '{joint}'. It has no "
                                  "velocity limits specification.")
            if limits is not None and limits.has_position_limits:  # hw_sim:448-452
                handle.lower_limit = limits.min_position
                handle.upper_limit = limits.max_position
            if interface != "effort":
                handle.pid = self._pid_gains(context.bus, namespace, joint)
            self.joints[joint] = handle
        self.names: List[str] = list(self.joints)
        self._indices = [self.joints[n].index for n in self.names]
        self.positions = np.zeros(len(self.names))
        self.velocities = np.zeros(len(self.names))
        self.efforts = np.zeros(len(self.names))
        # the positions the emergency stop holds, while it is on
        self._held_positions: Optional[List[float]] = None
        self.hold()

    @staticmethod
    def _limits(bus, namespace: str, joint, interface: str) -> Optional[JointLimits]:
        """registerJointLimits (hw_sim:393-510): the URDF's limits, then the parameter
        server's ``joint_limits/<joint>`` in the robot's namespace; None when neither."""
        limits = JointLimits()
        has_limits = urdf_limits(joint, limits)  # hw_sim:411-423
        name = f"joint_limits/{joint.name}"
        params = bus.get_param(resolve_topic(namespace, name), None)
        if params is None:  # a parameter tree given whole (the RecordingBus keeps it so)
            tree = bus.get_param(resolve_topic(namespace, "joint_limits"), None)
            params = tree.get(joint.name) if isinstance(tree, Mapping) else None
        if rosparam_limits(params, limits):  # hw_sim:425-426
            has_limits = True
        if not has_limits:  # hw_sim:428-429
            return None
        # the handles' constructors throw without these (JLI :172-176, :267-276, :411-415):
        # Gazebo's plugin does not load the robot's controls
        if interface in ("velocity", "effort") and not limits.has_velocity_limits:
            raise PluginError(f"Cannot enforce limits for joint '{joint.name}'. It has no "
                              "velocity limits specification.")
        if interface == "effort" and not limits.has_effort_limits:
            raise PluginError(f"Cannot enforce limits for joint '{joint.name}'. It has no "
                              "efforts limits specification.")
        return limits

    @staticmethod
    def _pid_gains(bus, namespace: str, joint: str) -> Optional[Pid]:
        """``<robotNamespace>/gazebo_ros_control/pid_gains/<joint>`` (hw_sim:220-222): a Pid,
        or None when there are none (the joint is set directly) or they have no ``p``."""
        path = resolve_topic(namespace, f"gazebo_ros_control/pid_gains/{joint}")
        gains = bus.get_param(path, None)
        if gains is None:  # a parameter tree given whole (the RecordingBus keeps it so)
            tree = bus.get_param(resolve_topic(namespace, "gazebo_ros_control/pid_gains"), None)
            gains = tree.get(joint) if isinstance(tree, Mapping) else None
        if gains is None:
            return None
        try:
            return Pid(gains, f"'{path}'")
        except PluginError as error:
            bus.warn(f"{error}; joint '{joint}' is driven without a PID")
            return None

    def hold(self, keep: Iterable[str] = ()) -> None:
        """The resting commands: position joints where they are (Noetic: 0, hw_sim:138, a
        fault not copied, see the module's docstring), velocity joints still, effort joints
        free; the joints in ``keep`` (a running controller's) keep their commands and their
        saturation's previous command."""
        keep = set(keep)
        self.read()
        for position, handle in zip(self.positions, self.joints.values()):
            if handle.name in keep:
                continue
            handle.command = float(position) if handle.interface == "position" else 0.0
            handle.reset_saturation()
        self.write(self.step_size)

    def read(self) -> None:
        # pybullet answers None for no joints (every transmission skipped)
        states = pb.getJointStates(self.body, self._indices,
                                   physicsClientId=self.client) if self._indices else []
        self.positions = np.array([s[0] for s in states])
        self.velocities = np.array([s[1] for s in states])
        # an effort joint's effort is the force its last command applied (readSim's
        # GetForce(0) after writeSim's SetForce, hw_sim:281, :316): pybullet's applied
        # torque of a torque-controlled joint is the braking motor of its URDF friction
        # a PID-driven joint's, likewise, the effort its PID applied
        self.efforts = np.array([h.applied_effort if h.interface == "effort" or h.pid is not None
                                 else s[3] for s, h in zip(states, self.joints.values())])

    def state(self, joint: str):
        i = self.names.index(joint)
        return self.positions[i], self.velocities[i], self.efforts[i]

    def write(self, period: Optional[float] = None, e_stop: bool = False) -> None:
        """writeSim (hw_sim:285-383): the limits, then the commands to pybullet; with
        ``e_stop``, position joints held at the positions read when it began (hw_sim:287-300),
        efforts and velocities 0 (:315, :359-375)."""
        period = self.step_size if period is None else period
        if e_stop and self._held_positions is None:  # last_joint_position_command_ (:290-294)
            self._held_positions = [float(p) for p in self.positions]
        elif not e_stop:
            self._held_positions = None
        by_mode: Dict[str, List[JointHandle]] = {}
        for k, handle in enumerate(self.joints.values()):
            position, velocity = float(self.positions[k]), float(self.velocities[k])
            if e_stop and handle.interface == "position":
                handle.command = self._held_positions[k]
            handle.saturate(position, velocity, period)
            if handle.interface == "effort":  # SetForce(0) during the stop (hw_sim:315)
                handle.applied_effort = 0.0 if e_stop else handle.command
            if handle.pid is not None:
                handle.applied_effort = handle.pid_effort(position, velocity, period, e_stop)
                by_mode.setdefault("pid", []).append(handle)
            else:
                by_mode.setdefault(handle.interface, []).append(handle)
        for interface, handles in by_mode.items():
            indices = [h.index for h in handles]
            if interface == "pid":  # SetForce(the PID's effort) (hw_sim:351, :379)
                pb.setJointMotorControlArray(
                    self.body, indices, pb.TORQUE_CONTROL,
                    forces=[h.applied_effort for h in handles], physicsClientId=self.client)
            elif interface == "position":  # SetPosition: no force limit (hw_sim:320-326)
                pb.setJointMotorControlArray(
                    self.body, indices, pb.POSITION_CONTROL,
                    targetPositions=[h.command for h in handles],
                    forces=[UNLIMITED] * len(handles), physicsClientId=self.client)
            elif interface == "velocity":  # fmax = the effort limit (hw_sim:240, :363)
                pb.setJointMotorControlArray(
                    self.body, indices, pb.VELOCITY_CONTROL,
                    targetVelocities=[0.0 if e_stop else h.command for h in handles],
                    forces=[h.effort_limit for h in handles], physicsClientId=self.client)
            else:  # SetForce (hw_sim:313-318)
                pb.setJointMotorControlArray(
                    self.body, indices, pb.TORQUE_CONTROL,
                    forces=[h.applied_effort for h in handles], physicsClientId=self.client)
