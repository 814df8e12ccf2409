"""``libgazebo_ros_f3d.so``: the force and torque applied to a link from outside, as
geometry_msgs/WrenchStamped ("force feedback ground truth").

Parameters as gazebo_plugins (noetic): ``bodyName`` (required; a link of the model as Gazebo
builds it, so not one that a fixed joint lumps into its parent), ``topicName`` (required),
``frameName`` (world; only the header's frame_id, with the ``tf_prefix`` parameter of the
plugin's own namespace, not searched further up, applied: the plugin reports
in world axes whatever it says), ``robotNamespace``.

What Gazebo's plugin reads is the link's force and torque accumulators at the start of each
step (``Link::WorldForce``, ``WorldTorque``): what ``apply_body_wrench`` and other plugins
push on the link for that step, in world axes, the torque about its centre of mass;
contacts, joints and gravity are not in it. So here: the wrenches acting on the link for
the step that starts now, summed. Published every step while someone subscribes.
"""
from __future__ import annotations

from geometry_msgs.msg import WrenchStamped

from sim_bridge.plugins.base import Plugin, PluginError, wrench_stamped


class F3D(Plugin):
    def __init__(self, context, spec):
        super().__init__(context, spec)
        self.body = self.param("bodyName")
        structure = context.structure
        if not self.body or self.body not in context.robot.link_index:
            raise PluginError(f"plugin '{spec.name}' ({spec.filename}) needs <bodyName>, a link "
                              f"of model '{context.model_name}' (got '{self.body}')")
        if structure is not None and self.body not in structure.bodies:
            holder = structure.body_of.get(self.body, "?")
            raise PluginError(
                f"plugin '{spec.name}' ({spec.filename}): <bodyName> '{self.body}' is lumped "
                f"into link '{holder}' by fixed joint '{structure.lumped_by.get(self.body)}', "
                "so Gazebo's model has no such link (name the holder, or keep the joint with "
                "<preserveFixedJoint>)")
        topic = self.param("topicName")
        if not topic:
            raise PluginError(f"plugin '{spec.name}' ({spec.filename}) needs <topicName>")
        # the tf_prefix of the plugin's own namespace, not searched upwards (:112-115)
        self.frame_id = self.frame(self.param("frameName", "world"), self.own_tf_prefix())
        self.output = context.bus.publisher(self.topic(topic), WrenchStamped, queue_size=1)

    def after_step(self, now_ns: int) -> None:
        if not self.context.bus.listened(self.output):
            return
        force, torque = self.context.applied_wrench(self.body)
        self.output.publish(wrench_stamped(now_ns, self.frame_id, force, torque))
