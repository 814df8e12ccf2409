"""The driver's two YAML files, read once: the motor config (``interbotix_xsarm_control/
config/<robot_model>.yaml``: joint order, sleep positions, groups, grippers, motor IDs, the
joint state topic) and the mode config (``modes.yaml``: each group's and single joint's
operating mode and profile). Keys and defaults as ``xs_sdk_sim`` reads them
(``robot_get_motor_configs``): a group or single without a mode is in ``position`` mode
with a ``velocity`` profile of 0 and 0."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Dict, List

import yaml

ALL = "all"    # the group every driver adds: every joint, in joint_order


class ConfigError(ValueError):
    """A config file that cannot be used; the message names the file and the key."""


@dataclass(frozen=True)
class Gripper:
    horn_radius: float
    arm_length: float
    left_finger: str
    right_finger: str


@dataclass
class Mode:
    """A joint's or group's operating mode and profile (the motors' registers)."""
    mode: str = "position"
    profile_type: str = "velocity"
    profile_velocity: int = 0
    profile_acceleration: int = 0


@dataclass
class MotorConfig:
    joint_order: List[str]
    sleep_positions: Dict[str, float]
    motor_ids: Dict[str, int]
    groups: Dict[str, List[str]]
    grippers: Dict[str, Gripper]
    joint_state_topic: str
    group_modes: Dict[str, Mode] = field(default_factory=dict)
    single_modes: Dict[str, Mode] = field(default_factory=dict)


def _mode(entry) -> Mode:
    entry = entry or {}
    return Mode(str(entry.get("operating_mode", "position")),
                str(entry.get("profile_type", "velocity")),
                int(entry.get("profile_velocity", 0)), int(entry.get("profile_acceleration", 0)))


def _load(path: str, what: str):
    try:
        with open(path, encoding="utf-8") as stream:
            return yaml.safe_load(stream) or {}
    except OSError as error:
        raise ConfigError(f"{what} file at '{path}' was not found ({error.strerror})") from None
    except yaml.YAMLError as error:
        raise ConfigError(f"{what} file at '{path}' has a bad format: {error}") from None


def read(motor_configs: str, mode_configs: str) -> MotorConfig:
    """Both files; a missing mode config means every joint in position mode (as upstream:
    it logs that it was not found and goes on)."""
    motors = _load(motor_configs, "Motor Config")
    try:
        modes = _load(mode_configs, "Mode Config")
    except ConfigError:
        modes = {}
    try:
        order = [str(name) for name in motors["joint_order"]]
        sleep = [float(value) for value in motors["sleep_positions"]]
        ids = {name: int(motors["motors"][name]["ID"]) for name in order}
        topic = str(motors["joint_state_publisher"]["topic_name"])
    except (KeyError, TypeError, ValueError) as error:
        raise ConfigError(f"Motor Config file at '{motor_configs}' lacks or mistypes "
                          f"{error}") from None
    if len(order) != len(sleep):
        raise ConfigError(f"Motor Config file at '{motor_configs}': Length of joint_order list "
                          f"({len(order)}) does not match length of sleep_positions list "
                          f"({len(sleep)})")
    groups = {ALL: list(order)}
    groups.update({str(name): [str(j) for j in joints]
                   for name, joints in (motors.get("groups") or {}).items()})
    unknown = sorted({j for joints in groups.values() for j in joints} - set(order))
    if unknown:
        raise ConfigError(f"Motor Config file at '{motor_configs}': groups name joints that "
                          f"are not in joint_order: {', '.join(unknown)}")
    grippers = {str(name): Gripper(float(g["horn_radius"]), float(g["arm_length"]),
                                   str(g["left_finger"]), str(g["right_finger"]))
                for name, g in (motors.get("grippers") or {}).items()}
    group_modes = {name: _mode((modes.get("groups") or {}).get(name)) for name in groups}
    single_modes = {str(name): _mode(entry) for name, entry in (modes.get("singles") or {}).items()}
    return MotorConfig(order, dict(zip(order, sleep)), ids, groups, grippers, topic,
                       group_modes, single_modes)
