#!/usr/bin/env python3
# arm.test: the step service with fake moveit
import unittest

import rospy
import rostest
from geometry_msgs.msg import Point
from moveit_msgs.msg import MoveItErrorCodes

from arm_move.srv import Step


class TestStep(unittest.TestCase):
    def setUp(self):
        rospy.wait_for_service("/px100/step", timeout=100)
        self.step = rospy.ServiceProxy("/px100/step", Step)

    def test_into_the_ground(self):
        resp = self.step(Point(0.2, 0.0, -0.05), True)
        self.assertNotEqual(resp.error_code.val, MoveItErrorCodes.SUCCESS)

    def test_reachable(self):
        resp = self.step(Point(0.2, 0.0, 0.15), True)
        self.assertEqual(resp.error_code.val, MoveItErrorCodes.SUCCESS)


if __name__ == "__main__":
    rospy.init_node("test_step")
    rostest.rosrun("arm_move", "test_step", TestStep)
