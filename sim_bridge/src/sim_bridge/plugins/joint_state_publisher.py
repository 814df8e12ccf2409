"""``libgazebo_ros_joint_state_publisher.so``: the true state of named joints.

As Noetic's plugin (gazebo_ros_pkgs noetic-devel f9e1a46,
gazebo_plugins/src/gazebo_ros_joint_state_publisher.cpp): ``jointName`` (joint names
separated by commas, spaces removed, :61-68), ``updateRate`` (100 Hz, :70-83),
``robotNamespace`` (the model's name when absent or empty, :50-58). Publishes
sensor_msgs/JointState on ``joint_states`` under the namespace (:102): name, position and
velocity, no effort (:147-167), stamped with the time. A message goes out when more than
1/updateRate s have passed since the last one's slot, which then moves on by one period
(:126-143), the first slot the time the model was loaded: 100 Hz on 1 ms steps publishes
11 ms after the load, then every 10 ms.

Where Noetic cannot go on, sim_bridge does: a plugin without ``<jointName>`` publishes empty
messages, as Noetic's (its ROS_ASSERT does nothing, :62), with a warning; a joint the model
lacks, or an empty name in the list, which Noetic logs as fatal and then crashes on
(:90-97, :156), leaves the plugin out with a warning naming it.
"""
from __future__ import annotations

from sensor_msgs.msg import JointState

from sim_bridge.plugins.base import Plugin, PluginError, gazebo_seconds, stamp


class JointStatePublisher(Plugin):
    ABSENT_NAMESPACE_IS_MODEL = EMPTY_NAMESPACE_IS_MODEL = True  # gazebo_plugins' GazeboRos

    def __init__(self, context, spec):
        super().__init__(context, spec)
        text = self.param("jointName")
        if text is None:
            names = []
            context.bus.warn(f"model '{context.model_name}': plugin '{spec.name}' "
                             f"({spec.filename}) has no <jointName>: it publishes empty "
                             "joint states, as Gazebo's does; name the joints, separated by "
                             "commas")
        else:
            names = "".join(text.split()).split(",")  # boost::erase_all(" "), split(",")
        empty = [n for n in names if not n]
        if empty:
            raise PluginError(f"plugin '{spec.name}' ({spec.filename}): <jointName> '{text}' "
                              "has an empty joint name (Gazebo's plugin would crash on it); "
                              "name the joints, separated by commas")
        missing = [n for n in names if n not in context.robot.joint_index]
        if missing:
            raise PluginError(f"plugin '{spec.name}': <jointName> names joint(s) "
                              f"{', '.join(missing)}, which model '{context.model_name}' "
                              "does not have")
        self.joints = names
        rate = self.number("updateRate", 100.0)
        self.period = 1.0 / rate if rate > 0 else 0.0  # :79-83
        self._slot_ns = None  # last_update_time_: the load, then one period on each message
        self.output = context.bus.publisher(self.topic("joint_states"), JointState,
                                            queue_size=1)

    def before_step(self, now_ns: int) -> None:
        if self._slot_ns is None:  # loaded since the last step: the time now (:85-88)
            self._slot_ns = now_ns

    def after_step(self, now_ns: int) -> None:
        if self._slot_ns is None:
            self._slot_ns = now_ns
        if now_ns < self._slot_ns:  # :126-130
            self._slot_ns = now_ns
        if not gazebo_seconds(now_ns - self._slot_ns) > self.period:  # :132-134
            return
        self._slot_ns += int(round(self.period * 1e9))  # :142
        states = self.context.robot.joint_states(self.joints) if self.joints else []
        message = JointState()
        message.header.stamp = stamp(now_ns)
        message.name = list(self.joints)
        message.position = [s[0] for s in states]
        message.velocity = [s[1] for s in states]
        self.output.publish(message)

    def reset(self, now_ns: int) -> None:
        # no Reset in Noetic's plugin; its world's time goes back to 0 and the negative
        # difference restarts the slots (:126-130). Here time goes on: they restart from now
        self._slot_ns = now_ns
