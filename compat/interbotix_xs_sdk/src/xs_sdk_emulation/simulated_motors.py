"""The motors of ``xs_sdk_sim``: joint commands in each joint's operating mode, moved at the
driver's timer as Interbotix's simulated driver moves them (interbotix_ros_core noetic
172841f, ``interbotix_xs_sdk/scripts/xs_sdk_sim``):

- 20 Hz (``timer_hz``, l. 19, 46); a position command whose ``profile_velocity`` (the
  time-based profile's moving time, ms) exceeds 300 (``move_thresh``, l. 21) is cut into
  round(profile_velocity / 1000 * 20 + 1) evenly spaced waypoints from where the joint is,
  one a tick; a shorter one is reached at the next tick (``robot_write_joint_command``,
  l. 209-213);
- ``velocity`` mode adds command / 20 a tick, ``pwm`` and ``current`` command / 2000, until
  a command of 0 (``robot_update_joint_states``, l. 457-466);
- a gripper's horn angle moves its fingers through the linkage (``gripper_linkage``), the
  right finger at minus the left; ``linear_position`` commands the distance between them.

Nothing here talks to ROS: ``sim_node`` serves it. Bad commands raise :class:`CommandError`
with the real driver's words (``src/xs_sdk_obj.cpp``: "does not exist" l. 71, 181, 220;
"Number of commands" l. 239; "Invalid command for argument" l. 73, 146) where it has them."""
from __future__ import annotations

import math
import threading
from typing import Dict, List, Optional, Sequence, Tuple

import numpy as np

from xs_sdk_emulation.configs import Mode, MotorConfig
from xs_sdk_emulation.gripper_linkage import finger_distance, horn_angle

TIMER_HZ = 20               # xs_sdk_sim l. 19: self.timer_hz
MOVE_THRESHOLD_MS = 300     # xs_sdk_sim l. 21: self.move_thresh
EFFORT_SCALE = 2000.0       # xs_sdk_sim l. 465: pwm and current move command / 2000 a tick
MODES = ("position", "ext_position", "current_based_position", "linear_position",
         "velocity", "pwm", "current")          # xs_sdk_obj.cpp robot_set_joint_operating_mode
PROFILE_REGISTERS = {"Profile_Velocity": "profile_velocity",
                     "Profile_Acceleration": "profile_acceleration"}


class CommandError(ValueError):
    """A command or request the driver refuses; the message says why."""


def _missing(name: str) -> CommandError:
    return CommandError(f"The '{name}' joint/group does not exist. Was it added to the motor "
                        "config file?")


class SimulatedMotors:
    """Every joint of the motor config and its gripper fingers, at their sleep positions."""

    def __init__(self, config: MotorConfig,
                 finger_limits: Optional[Dict[str, Tuple[float, float]]] = None,
                 state_order: Optional[Sequence[str]] = None):
        """``finger_limits``: left finger -> (lower, upper); given, a gripper's horn stops
        where its fingers reach them (the simulated arm's end stops). ``state_order``: the
        joint states' names when another publishes them (the simulator), for get_robot_info's
        indices; else these motors' own order."""
        self.config = config
        self.finger_limits = finger_limits
        self.lock = threading.Lock()
        self.names: List[str] = list(config.joint_order)
        self.positions: List[float] = [config.sleep_positions[n] for n in config.joint_order]
        for gripper_name in [n for n in config.joint_order if n in config.grippers]:
            gripper = config.grippers[gripper_name]
            distance = self._finger(gripper_name, config.sleep_positions[gripper_name])
            self.names += [gripper.left_finger, gripper.right_finger]
            self.positions += [distance, -distance]
        self.index = {name: i for i, name in enumerate(self.names)}
        # get_robot_info's: where the joint states have each joint
        self.state_index = self.index if state_order is None else \
            {name: i for i, name in enumerate(state_order)}
        self.joint_modes: Dict[str, Mode] = {}
        self.group_modes: Dict[str, Mode] = {}
        self.commands: Dict[str, object] = {}   # joint -> a value, or waypoints (last first)
        for group, mode in config.group_modes.items():
            self.set_operating_modes("group", group, mode.mode, mode.profile_type,
                                     mode.profile_velocity, mode.profile_acceleration)
        for joint, mode in config.single_modes.items():
            if joint in config.motor_ids:
                self.joint_modes[joint] = Mode(**vars(mode))

    # --- modes and registers ---------------------------------------------------------------
    def joints(self, cmd_type: str, name: str) -> List[str]:
        """The motors a 'group' or 'single' request names; CommandError for another."""
        if cmd_type == "group":
            if name not in self.config.groups:
                raise _missing(name)
            return list(self.config.groups[name])
        if cmd_type == "single":
            if name not in self.config.motor_ids:
                raise _missing(name)
            return [name]
        raise CommandError(f"Invalid command for argument 'cmd_type' ({cmd_type!r}): "
                           "'group' or 'single'")

    def set_operating_modes(self, cmd_type: str, name: str, mode: str, profile_type: str,
                            profile_velocity: int, profile_acceleration: int) -> None:
        if mode not in MODES:
            raise CommandError(f"Invalid command for argument 'mode' ({mode!r}) while setting "
                               f"the operating mode for '{name}': one of {', '.join(MODES)}")
        with self.lock:
            for joint in self.joints(cmd_type, name):
                self.joint_modes[joint] = Mode(mode, profile_type, int(profile_velocity),
                                               int(profile_acceleration))
            if cmd_type == "group":
                self.group_modes[name] = Mode(mode, profile_type, int(profile_velocity),
                                              int(profile_acceleration))

    def set_register(self, cmd_type: str, name: str, register: str, value: int) -> None:
        """Only the profile registers mean anything without motors (as upstream's)."""
        attribute = PROFILE_REGISTERS.get(register)
        with self.lock:
            joints = self.joints(cmd_type, name)
            if attribute is None:
                return
            for joint in joints:
                setattr(self.joint_modes[joint], attribute, int(value))
            if cmd_type == "group":
                setattr(self.group_modes[name], attribute, int(value))

    def get_register(self, cmd_type: str, name: str, register: str) -> List[int]:
        attribute = PROFILE_REGISTERS.get(register)
        with self.lock:
            joints = self.joints(cmd_type, name)
            if attribute is None:
                return []
            return [int(getattr(self.joint_modes[joint], attribute)) for joint in joints]

    def mode_of(self, cmd_type: str, name: str) -> Mode:
        with self.lock:
            self.joints(cmd_type, name)
            return (self.group_modes if cmd_type == "group" else self.joint_modes)[name]

    # --- commands --------------------------------------------------------------------------
    def write_group(self, name: str, commands: Sequence[float]) -> None:
        joints = self.joints("group", name)
        if len(commands) != len(joints):
            raise CommandError(f"Number of commands ({len(commands)}) does not match the number "
                               f"of joints in group '{name}' ({len(joints)}). Will not execute.")
        self._check_finite(name, commands)
        for joint, command in zip(joints, commands):
            self.write_joint(joint, command)

    def write_joint(self, name: str, command: float) -> None:
        self.joints("single", name)
        self._check_finite(name, [command])
        with self.lock:
            mode = self.joint_modes[name]
            if "position" in mode.mode and mode.profile_velocity > MOVE_THRESHOLD_MS:
                steps = int(round(mode.profile_velocity / 1000.0 * TIMER_HZ + 1))
                here = self.positions[self.index[name]]
                self.commands[name] = list(np.linspace(float(command), here, steps))
            else:
                self.commands[name] = float(command)

    @staticmethod
    def _check_finite(name: str, commands: Sequence[float]) -> None:
        if not all(math.isfinite(c) for c in commands):
            raise CommandError(f"a command for '{name}' is not finite ({list(commands)}); "
                               "nothing was sent to the motors")

    def tick(self) -> Tuple[List[str], List[float]]:
        """One timer period: every joint with a command moves; the joint states."""
        with self.lock:
            for joint in list(self.commands):
                mode = self.joint_modes[joint].mode
                if "position" in mode:
                    queued = self.commands[joint]
                    if isinstance(queued, list):
                        value = queued.pop()
                        if not queued:
                            del self.commands[joint]
                    else:
                        value = queued
                        del self.commands[joint]
                    self._set_position(joint, value, linear=(mode == "linear_position"))
                else:
                    value = self.commands[joint]
                    if value == 0:
                        del self.commands[joint]
                        continue
                    step = value / TIMER_HZ if mode == "velocity" else value / EFFORT_SCALE
                    here = self.positions[self.index[joint]]
                    self._set_position(joint, here + step, linear=False)
            return list(self.names), list(self.positions)

    def _finger(self, gripper: str, angle: float) -> float:
        linkage = self.config.grippers[gripper]
        return finger_distance(angle, linkage.horn_radius, linkage.arm_length)

    def _set_position(self, joint: str, value: float, linear: bool) -> None:
        gripper = self.config.grippers.get(joint)
        if gripper is None:
            self.positions[self.index[joint]] = value
            return
        if linear:      # the command is the distance between the fingers
            angle = horn_angle(value, gripper.horn_radius, gripper.arm_length)
            finger = value / 2.0
        else:
            angle, finger = value, self._finger(joint, value)
        limits = (self.finger_limits or {}).get(gripper.left_finger)
        if limits is not None and not limits[0] <= finger <= limits[1]:
            # at an end stop: the fingers at their limit, the horn where that puts them
            finger = min(max(finger, limits[0]), limits[1])
            angle = horn_angle(2.0 * finger, gripper.horn_radius, gripper.arm_length)
        self.positions[self.index[joint]] = angle
        self.positions[self.index[gripper.left_finger]] = finger
        self.positions[self.index[gripper.right_finger]] = -finger

    # --- what get_robot_info answers --------------------------------------------------------
    def robot_info(self, cmd_type: str, name: str, limits: Optional[Dict[str, tuple]]) -> Dict:
        """``limits``: joint -> (lower, upper, velocity) from robot_description, or None when
        there is none (the lists stay empty, as upstream's). A gripper answers for its left
        finger: its name, limits, joint state index, and the finger's distance at horn angle 0
        as its sleep position."""
        joints = self.joints(cmd_type, name)
        mode = self.mode_of(cmd_type, name)
        info = {"mode": mode.mode, "profile_type": mode.profile_type, "joint_names": [],
                "joint_ids": [], "joint_lower_limits": [], "joint_upper_limits": [],
                "joint_velocity_limits": [], "joint_sleep_positions": [],
                "joint_state_indices": [], "num_joints": len(joints),
                "name": list(self.config.groups) if "all" in name else [name]}
        for joint in joints:
            info["joint_ids"].append(self.config.motor_ids[joint])
            named = joint
            if joint in self.config.grippers:
                info["joint_sleep_positions"].append(self._finger(joint, 0.0))
                named = self.config.grippers[joint].left_finger
            else:
                info["joint_sleep_positions"].append(self.config.sleep_positions[joint])
            info["joint_names"].append(named)
            # -1: a joint the simulator's joint states do not carry
            info["joint_state_indices"].append(self.state_index.get(named, -1))
            if limits is not None:
                if named not in limits:
                    raise CommandError(f"robot_description has no joint '{named}' with limits")
                lower, upper, velocity = limits[named]
                info["joint_lower_limits"].append(lower)
                info["joint_upper_limits"].append(upper)
                info["joint_velocity_limits"].append(velocity)
        return info
