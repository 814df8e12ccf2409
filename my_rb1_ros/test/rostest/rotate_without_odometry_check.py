#!/usr/bin/env python3
"""rostest node: with no odometry, /rotate_robot answers failure within its odometry
timeout and the robot does not move."""
import math
import os
import sys
import time
import unittest

import rospy
import rostest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rb1_checks import TIMEOUT, Truth  # noqa: E402

from my_rb1_ros.srv import Rotate  # noqa: E402

ODOM_TIMEOUT = 5.0  # config/rotate_service.yaml


class RotateWithoutOdometry(unittest.TestCase):
    def test_failure_within_the_timeout_and_no_motion(self):
        rospy.init_node("rotate_without_odometry_check")
        truth = Truth()
        rospy.wait_for_service("/rotate_robot", timeout=TIMEOUT)
        truth.wait_sim_time(1.0)
        x0, y0, _, _, yaw0 = truth.pose()
        started = time.monotonic()
        answer = rospy.ServiceProxy("/rotate_robot", Rotate)(90).result
        waited = time.monotonic() - started
        self.assertTrue(answer.startswith("failure"), answer)
        self.assertIn("no odometry", answer)
        self.assertLess(waited, ODOM_TIMEOUT + 1.0)
        truth.wait_sim_time(truth.sim_time() + 0.5)
        x1, y1, _, _, yaw1 = truth.pose()
        self.assertLess(math.hypot(x1 - x0, y1 - y0), 0.005)
        self.assertLess(abs(math.degrees(yaw1 - yaw0)), 0.1)


if __name__ == "__main__":
    rostest.rosrun("my_rb1_ros", "rotate_without_odometry", RotateWithoutOdometry)
