"""The robot as ros_control's controllers see it: the joints that have a transmission, each
with the interface its transmission names (position, velocity or effort).

As gazebo_ros_control's DefaultRobotHWSim: before a controller commands them, position
joints hold where they were when the robot was spawned, velocity joints hold still, effort
joints are free. Commands reach pybullet once per control period: position through its
position motor and velocity through its velocity motor (both limited to the joint's
URDF effort), effort as a joint torque.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Dict, List

import numpy as np
import pybullet as pb

from sim_bridge.plugins.base import PluginError

INTERFACES = {
    "PositionJointInterface": "position",
    "VelocityJointInterface": "velocity",
    "EffortJointInterface": "effort",
}
# a joint whose URDF gives no effort limit gets this much (N m or N)
DEFAULT_EFFORT = 1000.0


def interface_of(name: str) -> str:
    short = name.split("/")[-1]
    if short not in INTERFACES:
        raise PluginError(f"hardware interface '{name}' is not one of "
                          f"{', '.join('hardware_interface/' + i for i in INTERFACES)}")
    return INTERFACES[short]


@dataclass
class JointHandle:
    name: str
    index: int
    interface: str
    effort_limit: float
    command: float = 0.0


class RobotHardware:
    def __init__(self, context, transmissions):
        robot = context.robot
        self.client = context.client
        self.body = robot.id
        self.joints: Dict[str, JointHandle] = {}
        for transmission in transmissions:
            if not transmission.hardware_interfaces:
                raise PluginError(f"transmission '{transmission.name}' names no "
                                  "hardwareInterface")
            interface = interface_of(transmission.hardware_interfaces[0])
            for joint in transmission.joints:
                if joint not in robot.joint_index:
                    raise PluginError(f"transmission '{transmission.name}' names joint "
                                      f"'{joint}', which model '{context.model_name}' does not have")
                limit = robot.model.joints[joint].limit
                effort = limit.effort if limit is not None and limit.effort > 0 else DEFAULT_EFFORT
                self.joints[joint] = JointHandle(joint, robot.joint_index[joint], interface,
                                                 effort)
        self.names: List[str] = list(self.joints)
        self._indices = [self.joints[n].index for n in self.names]
        self.positions = np.zeros(len(self.names))
        self.velocities = np.zeros(len(self.names))
        self.efforts = np.zeros(len(self.names))
        self.hold()

    def hold(self) -> None:
        """DefaultRobotHWSim's resting commands: position joints where they are, velocity
        joints still, effort joints free."""
        self.read()
        for position, handle in zip(self.positions, self.joints.values()):
            handle.command = float(position) if handle.interface == "position" else 0.0
        self.write()

    def read(self) -> None:
        states = pb.getJointStates(self.body, self._indices, physicsClientId=self.client)
        self.positions = np.array([s[0] for s in states])
        self.velocities = np.array([s[1] for s in states])
        self.efforts = np.array([s[3] for s in states])

    def state(self, joint: str):
        i = self.names.index(joint)
        return self.positions[i], self.velocities[i], self.efforts[i]

    def write(self) -> None:
        by_mode: Dict[str, List[JointHandle]] = {}
        for handle in self.joints.values():
            by_mode.setdefault(handle.interface, []).append(handle)
        for interface, handles in by_mode.items():
            indices = [h.index for h in handles]
            if interface == "position":
                pb.setJointMotorControlArray(
                    self.body, indices, pb.POSITION_CONTROL,
                    targetPositions=[h.command for h in handles],
                    forces=[h.effort_limit for h in handles], physicsClientId=self.client)
            elif interface == "velocity":
                pb.setJointMotorControlArray(
                    self.body, indices, pb.VELOCITY_CONTROL,
                    targetVelocities=[h.command for h in handles],
                    forces=[h.effort_limit for h in handles], physicsClientId=self.client)
            else:
                pb.setJointMotorControlArray(
                    self.body, indices, pb.TORQUE_CONTROL,
                    forces=[float(np.clip(h.command, -h.effort_limit, h.effort_limit))
                            for h in handles], physicsClientId=self.client)
