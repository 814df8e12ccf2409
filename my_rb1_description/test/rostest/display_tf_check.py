#!/usr/bin/env python3
"""rostest node: the TF tree of display.launch equals the URDF, and the wheel joints move."""
import math
import unittest

import numpy as np
import rospy
import rostest
import tf2_ros
from sensor_msgs.msg import JointState
from tf.transformations import quaternion_matrix

from urdf_tools.kinematics import axis_angle_matrix, link_transform
from urdf_tools.model import parse_urdf

TIMEOUT = rospy.Duration(10.0)


class DisplayTf(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("display_tf_check")
        cls.model = parse_urdf(rospy.get_param("/robot_description"), "robot_description")
        cls.buffer = tf2_ros.Buffer()
        cls.listener = tf2_ros.TransformListener(cls.buffer)
        cls.commands = rospy.Publisher("test_joint_command", JointState, queue_size=1, latch=True)

    def lookup(self, child):
        stamped = self.buffer.lookup_transform("base_footprint", child, rospy.Time(0), TIMEOUT)
        t = stamped.transform
        return (np.array([t.translation.x, t.translation.y, t.translation.z]),
                quaternion_matrix((t.rotation.x, t.rotation.y, t.rotation.z,
                                   t.rotation.w))[:3, :3])

    def test_every_frame_is_where_the_urdf_puts_it(self):
        for link in self.model.links:
            if link == "base_footprint":
                continue
            expected = link_transform(self.model, "base_footprint", link)
            translation, rotation = self.lookup(link)
            np.testing.assert_allclose(translation, expected[:3, 3], atol=1e-6, err_msg=link)
            np.testing.assert_allclose(rotation, expected[:3, :3], atol=1e-6, err_msg=link)
        # the numbers the course gives, spelled out
        translation, rotation = self.lookup("front_laser")
        np.testing.assert_allclose(translation, [0.25, 0.0, 0.225], atol=1e-6)
        np.testing.assert_allclose(rotation, np.diag([1.0, -1.0, -1.0]), atol=1e-6)  # roll pi

    def test_left_wheel_frame_follows_a_joint_command(self):
        angle = 1.0
        wanted = axis_angle_matrix([0, 1, 0], angle)
        deadline = rospy.Time.now() + TIMEOUT
        rotation = None
        while not rospy.is_shutdown() and rospy.Time.now() < deadline:
            self.commands.publish(JointState(name=["left_wheel_joint"], position=[angle]))
            rospy.sleep(0.1)
            _, rotation = self.lookup("left_wheel")
            if np.allclose(rotation, wanted, atol=1e-6):
                break
        np.testing.assert_allclose(rotation, wanted, atol=1e-6)
        # the other wheel stays where it was
        _, right = self.lookup("right_wheel")
        np.testing.assert_allclose(right, np.eye(3), atol=1e-6)
        self.assertAlmostEqual(math.atan2(rotation[0, 2], rotation[0, 0]), angle, places=6)


if __name__ == "__main__":
    rostest.rosrun("my_rb1_description", "display_tf", DisplayTf)
