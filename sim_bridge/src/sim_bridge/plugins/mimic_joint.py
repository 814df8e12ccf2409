"""``libroboticsgroup_upatras_gazebo_mimic_joint_plugin.so`` (and its older name
``libroboticsgroup_gazebo_mimic_joint_plugin.so``): one joint follows another, as grippers'
second fingers do.

Parameters as the plugin reads them: ``joint`` (the leader, required), ``mimicJoint`` (the
follower, required), ``multiplier`` (1), ``offset`` (0): the follower is held at
``multiplier * leader + offset``; ``maxEffort`` (the follower's URDF effort limit, else
DEFAULT_EFFORT, as
ros_control's joints here): the most force or torque holding it; ``sensitiveness`` (0): a difference
smaller than this is left alone. ``hasPID`` asks the original for a PID from
gazebo_ros_control's gains; here the follower is always held by pybullet's position motor
(a stiff PID), so a follower with a PID behaves as one without. Gazebo itself ignores a
URDF ``<mimic>`` without this plugin, and so does sim_bridge.
"""
from __future__ import annotations

import pybullet as pb

from sim_bridge.plugins.base import Plugin, PluginError
from sim_bridge.ros_control.hardware import DEFAULT_EFFORT


class MimicJoint(Plugin):
    def __init__(self, context, spec):
        super().__init__(context, spec)
        robot = context.robot
        self.leader = self.joint("joint")
        self.follower = self.joint("mimicJoint")
        if self.leader == self.follower:
            raise PluginError(f"plugin '{spec.name}' ({spec.filename}): <joint> and "
                              f"<mimicJoint> are the same joint, '{self.leader}'")
        self.multiplier = self.number("multiplier", 1.0)
        self.offset = self.number("offset", 0.0)
        limit = robot.model.joints[self.follower].limit
        self.max_effort = self.number(
            "maxEffort", limit.effort if limit is not None and limit.effort > 0 else DEFAULT_EFFORT)
        self.sensitiveness = self.number("sensitiveness", 0.0)
        self.flag("hasPID", False)  # read: the follower is held by a position motor either way
        self._leader = robot.joint_index[self.leader]
        self._follower = robot.joint_index[self.follower]

    def before_step(self, now_ns: int) -> None:
        client, body = self.context.client, self.context.robot.id
        leader = pb.getJointState(body, self._leader, physicsClientId=client)[0]
        target = self.multiplier * leader + self.offset
        follower = pb.getJointState(body, self._follower, physicsClientId=client)[0]
        if abs(target - follower) < self.sensitiveness:
            return
        pb.setJointMotorControl2(body, self._follower, pb.POSITION_CONTROL,
                                 targetPosition=target, force=self.max_effort,
                                 physicsClientId=client)
