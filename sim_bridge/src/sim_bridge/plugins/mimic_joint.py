"""``libroboticsgroup_upatras_gazebo_mimic_joint_plugin.so`` (and its older name
``libroboticsgroup_gazebo_mimic_joint_plugin.so``): one joint follows another, as grippers'
second fingers do.

As the plugin's ROS 1 release reads them (roboticsgroup/roboticsgroup_upatras_gazebo_plugins
master 15187ab, 0.2.0, src/mimic_joint_plugin.cpp; roboticsgroup_gazebo_plugins master
509a32e is the same plugin under the older name): ``joint`` (the leader) and ``mimicJoint``
(the follower), both required (:67-81); ``multiplier`` (1), ``offset`` (0): the follower's
target is ``multiplier * leader + offset`` (:94-102, :161); ``sensitiveness`` (0): a
difference smaller than it is left alone (:104-107, :168); ``maxEffort`` (the follower's
effort limit, :121-129); ``hasPID``; ``robotNamespace`` (only where the PID's gains are
looked up, :61-65).

Without ``<hasPID>`` the follower is *put* at its target before every step, its velocity
kept (Gazebo 9+: ``Joint::SetPosition(0, angle, true)``, :177-178), whatever holds it back,
and its motor is a brake of at most ``maxEffort`` (ODE's ``fmax`` with no target velocity,
:131-138), as Gazebo's. With the tag, whatever its text, a PID of control_toolbox drives the
follower by effort, clamped to ±maxEffort (:83-92, :169-175): its gains are read from the
parameter server under ``<robotNamespace>/<the tag's text>``, or
``<robotNamespace>/gazebo_ros_control/pid_gains/<mimicJoint>`` when the text is empty; where
there is no ``p`` gain the PID stays at zero gains (Pid::init fails and the plugin goes on),
so the follower is free, and a warning says so. Gazebo itself ignores a URDF ``<mimic>``
without this plugin, and so does sim_bridge.
"""
from __future__ import annotations

import pybullet as pb

from sim_bridge.plugins.base import Plugin, PluginError, resolve_topic
from sim_bridge.ros_control.hardware import DEFAULT_EFFORT
from sim_bridge.ros_control.pid import Pid


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
        self._leader = robot.joint_index[self.leader]
        self._follower = robot.joint_index[self.follower]
        self.pid = None
        pid_name = spec.text("hasPID")  # its presence asks for the PID (:84)
        if pid_name is not None:
            self.pid = self._pid(pid_name.strip())
        self._hold_motor()

    def _pid(self, name: str) -> Pid:
        """The PID under the tag's namespace (:86-91), zero gains when it has no p gain."""
        where = resolve_topic(self.namespace,
                              name or f"gazebo_ros_control/pid_gains/{self.follower}")
        gains = self.context.bus.get_param(where, None)
        try:
            return Pid(gains if isinstance(gains, dict) else {},
                       f"plugin '{self.spec.name}' ({self.spec.filename})")
        except PluginError:
            self.context.bus.warn(
                f"model '{self.context.model_name}': plugin '{self.spec.name}' "
                f"({self.spec.filename}): <hasPID> asks for a PID, and {where} has no 'p' "
                f"gain: its gains stay 0 and joint '{self.follower}' is not driven, as in "
                f"Gazebo (set {where}/p, i, d, or leave <hasPID> out to have the follower "
                "put at its target)")
            return Pid({"p": 0.0}, "")

    def _hold_motor(self) -> None:
        """Without the PID, ODE's joint motor with fmax = maxEffort and no target velocity
        brakes the follower between the steps it is put at its target (:131-138); with it,
        the follower is driven by effort alone."""
        pb.setJointMotorControl2(self.context.robot.id, self._follower, pb.VELOCITY_CONTROL,
                                 targetVelocity=0.0,
                                 force=0.0 if self.pid is not None else self.max_effort,
                                 physicsClientId=self.context.client)

    def before_step(self, now_ns: int) -> None:
        client, body = self.context.client, self.context.robot.id
        leader = pb.getJointState(body, self._leader, physicsClientId=client)[0]
        target = self.multiplier * leader + self.offset
        follower, velocity = pb.getJointState(body, self._follower, physicsClientId=client)[:2]
        if not abs(target - follower) >= self.sensitiveness:  # :168
            return
        if self.pid is None:  # SetPosition(0, angle, true): there, the velocity kept
            pb.resetJointState(body, self._follower, target, velocity,
                               physicsClientId=client)
            return
        effort = self.pid.compute(target - follower, self.context.step_size)  # :170-173
        effort = min(max(effort, -self.max_effort), self.max_effort)
        pb.setJointMotorControl2(body, self._follower, pb.TORQUE_CONTROL, force=effort,
                                 physicsClientId=client)

    def reset(self, now_ns: int) -> None:
        if self.pid is not None:
            self.pid.reset()
        self._hold_motor()
