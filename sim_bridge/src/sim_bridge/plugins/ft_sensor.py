"""``libgazebo_ros_ft_sensor.so``: the force and torque a joint carries, as
geometry_msgs/WrenchStamped.

Parameters as gazebo_plugins (noetic): ``jointName`` (required; a joint of the model as
Gazebo builds it, so not a fixed joint it lumps), ``topicName`` (required),
``gaussianNoise`` (0; standard deviation added to each of the six numbers, seeded),
``updateRate`` (0: every step; else a message once at least 1/updateRate s have passed
since the last one, counted from 0, and only while someone subscribes:
gazebo_plugins/src/gazebo_ros_ft_sensor.cpp:173-179, :228), ``robotNamespace``. The
header's frame is the joint's child link, with the ``tf_prefix`` parameter of the plugin's
own namespace (not searched further up) applied.

What the plugin publishes is Gazebo's ``Joint::GetForceTorque(0)`` ``body2Force`` and
``body2Torque``: the load the child's side puts on the joint, i.e. minus the wrench the
joint (its constraint, its friction and any effort on it) applies to the child, in the
child link's axes, the torque about the joint's origin (the child link's origin in a URDF).
A 2 kg arm at rest whose centre of mass is 0.5 m along the child's x reads force
(0, 0, -19.6) and torque (0, 9.8, 0), as in Gazebo's own joint_force_torque test.

pybullet's joint sensor gives the wrench the parent applies to the child through the joint,
in the child's inertial frame, the torque about its centre of mass, without a position or
velocity motor's torque (given apart): turned here into the child link's axes, moved to
the link's origin, the motor's torque on the axis added, and negated.
"""
from __future__ import annotations

import numpy as np
import pybullet as pb
from geometry_msgs.msg import WrenchStamped

from sim_bridge.plugins.base import Plugin, PluginError, Throttle, wrench_stamped
from sim_bridge.poses import quaternion_matrix


class FTSensor(Plugin):
    def __init__(self, context, spec):
        super().__init__(context, spec)
        joint = self.joint("jointName")
        structure = context.structure
        if structure is not None and joint in structure.lumped_by.values():
            raise PluginError(
                f"plugin '{spec.name}' ({spec.filename}): <jointName> '{joint}' is a fixed "
                "joint that Gazebo lumps, so its model has no such joint (keep it with "
                "<preserveFixedJoint>)")
        topic = self.param("topicName")
        if not topic:
            raise PluginError(f"plugin '{spec.name}' ({spec.filename}) needs <topicName>")
        robot = context.robot
        self.index = robot.joint_index[joint]
        self.axis = np.asarray(pb.getJointInfo(robot.id, self.index,
                                               physicsClientId=context.client)[13], dtype=float)
        pb.enableJointForceTorqueSensor(robot.id, self.index, True,
                                        physicsClientId=context.client)
        # the tf_prefix of the plugin's own namespace, not searched upwards
        # (gazebo_plugins/src/gazebo_ros_ft_sensor.cpp:123-126)
        self.frame_id = self.frame(robot.model.joints[joint].child, self.own_tf_prefix())
        self.noise = self.number("gaussianNoise", 0.0)
        # last_time_ is never set at load: common::Time(), 0
        self.throttle = Throttle(self.number("updateRate", 0.0))
        self.output = context.bus.publisher(self.topic(topic), WrenchStamped, queue_size=1)

    def wrench(self):
        """(body2Force, body2Torque) as Gazebo reports them, without noise."""
        robot, client = self.context.robot, self.context.client
        _, _, reaction, motor_torque = pb.getJointState(robot.id, self.index,
                                                        physicsClientId=client)
        link = pb.getLinkState(robot.id, self.index, physicsClientId=client)
        inertial_axes = quaternion_matrix(link[3])  # the inertial frame in the link's
        force = inertial_axes @ np.asarray(reaction[:3])
        torque = inertial_axes @ np.asarray(reaction[3:]) + np.cross(link[2], force) \
            + motor_torque * self.axis
        return -force, -torque

    def after_step(self, now_ns: int) -> None:
        # the rate first, then the subscribers; the time of the last message is kept only
        # when one went out (gazebo_plugins/src/gazebo_ros_ft_sensor.cpp:173-179, :228)
        if not self.throttle.ready(now_ns) or not self.context.bus.listened(self.output):
            return
        self.throttle.mark(now_ns)
        force, torque = self.wrench()
        if self.noise > 0:
            force = force + self.context.rng.normal(0.0, self.noise, 3)
            torque = torque + self.context.rng.normal(0.0, self.noise, 3)
        self.output.publish(wrench_stamped(now_ns, self.frame_id, force, torque))

    def reset(self, now_ns: int) -> None:
        # Noetic's plugin has no Reset; its world's time goes back to 0, and so then does
        # the difference it checks. Here time goes on: the period starts again from now
        self.throttle.mark(now_ns)
