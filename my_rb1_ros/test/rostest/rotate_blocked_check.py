#!/usr/bin/env python3
"""rostest node: a robot that does not turn while commanded (its commands reach nothing)
makes /rotate_robot answer failure (blocked) instead of waiting for ever."""
import os
import sys
import unittest

import rospy
import rostest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rb1_checks import TIMEOUT, Truth  # noqa: E402

from my_rb1_ros.srv import Rotate  # noqa: E402


class RotateBlocked(unittest.TestCase):
    def test_blocked_rotation_fails_and_says_so(self):
        rospy.init_node("rotate_blocked_check")
        truth = Truth()
        rospy.wait_for_service("/rotate_robot", timeout=TIMEOUT)
        truth.wait_sim_time(1.0)
        started = truth.sim_time()
        answer = rospy.ServiceProxy("/rotate_robot", Rotate)(90).result
        self.assertTrue(answer.startswith("failure"), answer)
        self.assertIn("does not turn", answer)
        # stall_seconds (2 s) after the start, not the whole time allowed for 90 degrees
        self.assertLess(truth.sim_time() - started, 4.0)


if __name__ == "__main__":
    rostest.rosrun("my_rb1_ros", "rotate_blocked", RotateBlocked)
