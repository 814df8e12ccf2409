"""What the checks of arm_move's rostests know of the arm without the mover: the gripper
point from TF (robot_state_publisher on the reported joint states, the URDF's kinematics)
and the joint states themselves."""
import threading

import numpy as np
import rospy
import tf2_ros
from sensor_msgs.msg import JointState

from sim_bridge.testing import wait_until

ARM_JOINTS = ["waist", "shoulder", "elbow", "wrist_angle"]
FINGERS = ["left_finger", "right_finger"]
BASE, TIP = "px100/base_link", "px100/ee_gripper_link"
HOME = [0.0, 0.0, 0.0, 0.0]
OPEN, CLOSED = 0.037, 0.015       # the left finger in Interbotix's Open and Closed states


class ArmTruth:
    def __init__(self):
        self.buffer = tf2_ros.Buffer()
        self.listener = tf2_ros.TransformListener(self.buffer)
        self.joints, self.received = {}, 0
        self._lock = threading.Lock()
        rospy.Subscriber("joint_states", JointState, self._on_joint_states)

    def _on_joint_states(self, message):
        with self._lock:
            self.joints.update(zip(message.name, message.position))
            self.received += 1

    def fresh(self, count: int = 3):
        """Waits for ``count`` joint states published after this call."""
        start = self.received
        wait_until(lambda: self.received >= start + count, "fresh joint states")

    def arm(self):
        self.fresh()
        with self._lock:
            return np.array([self.joints[j] for j in ARM_JOINTS + FINGERS])

    def gripper(self):
        """The gripper point in the arm's base frame, from a TF after fresh joint states."""
        self.fresh()
        stamp = rospy.Time.now()
        wait_until(lambda: self.buffer.can_transform(BASE, TIP, stamp), "the gripper's TF")
        t = self.buffer.lookup_transform(BASE, TIP, stamp).transform.translation
        return np.array([t.x, t.y, t.z])
