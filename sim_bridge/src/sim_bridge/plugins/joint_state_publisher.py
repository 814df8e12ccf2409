"""``libgazebo_ros_joint_state_publisher.so``: the true state of named joints.

Parameters as gazebo_ros (noetic): jointName (comma-separated joint names; required),
updateRate (100 Hz), robotNamespace. Publishes sensor_msgs/JointState on ``joint_states``
(under the namespace): position, velocity and effort, stamped in simulated time.
"""
from __future__ import annotations

from sensor_msgs.msg import JointState

from sim_bridge.plugins.base import Plugin, PluginError, Rate, stamp


class JointStatePublisher(Plugin):
    ABSENT_NAMESPACE_IS_MODEL = EMPTY_NAMESPACE_IS_MODEL = True  # gazebo_plugins' GazeboRos

    def __init__(self, context, spec):
        super().__init__(context, spec)
        names = [n.strip() for n in (self.param("jointName", "") or "").split(",") if n.strip()]
        if not names:
            raise PluginError(f"plugin '{spec.name}' ({spec.filename}) needs <jointName>, "
                              "the joints to publish, separated by commas")
        missing = [n for n in names if n not in context.robot.joint_index]
        if missing:
            raise PluginError(f"plugin '{spec.name}': <jointName> names joint(s) "
                              f"{', '.join(missing)}, which model '{context.model_name}' "
                              "does not have")
        self.joints = names
        self.rate = Rate(self.number("updateRate", 100.0))
        self.output = context.bus.publisher(self.topic("joint_states"), JointState,
                                            queue_size=1)

    def after_step(self, now_ns: int) -> None:
        if not self.rate.due(now_ns):
            return
        states = self.context.robot.joint_states(self.joints)
        message = JointState()
        message.header.stamp = stamp(now_ns)
        message.name = list(self.joints)
        message.position = [s[0] for s in states]
        message.velocity = [s[1] for s in states]
        message.effort = [s[2] for s in states]
        self.output.publish(message)

    def reset(self, now_ns: int) -> None:
        self.rate.reset(now_ns)
