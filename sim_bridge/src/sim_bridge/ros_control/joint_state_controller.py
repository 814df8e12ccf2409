"""``joint_state_controller/JointStateController``: every transmission joint on
``joint_states`` (prismatic ones included) at ``publish_rate`` Hz of simulated time."""
from __future__ import annotations

from sensor_msgs.msg import JointState

from sim_bridge.plugins.base import Rate, stamp
from sim_bridge.ros_control.controller_base import Controller


class JointStateController(Controller):
    def __init__(self, name, params, hardware, io):
        super().__init__(name, params, hardware, io)
        self.rate = Rate(self.number("publish_rate", 50.0))
        self.output = io.bus.publisher(io.topic("joint_states"), JointState, queue_size=1)

    def start(self, now_ns):
        self.rate.reset(now_ns)

    def update(self, now_ns, dt):
        if not self.rate.due(now_ns):
            return
        message = JointState()
        message.header.stamp = stamp(now_ns)
        message.name = list(self.hardware.names)
        message.position = self.hardware.positions.tolist()
        message.velocity = self.hardware.velocities.tolist()
        message.effort = self.hardware.efforts.tolist()
        self.output.publish(message)

    def close(self):
        self.output.unregister()
