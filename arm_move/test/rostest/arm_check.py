#!/usr/bin/env python3
"""rostest node for arm.test (fake MoveIt): reset brings the arm Home; a step below the
floor answers INVALID_GOAL_CONSTRAINTS and moves nothing; a reachable step answers
SUCCESS, the gripper point (TF from the reported joints) ends within 2 mm of it, the
gripper is closed, the waypoint is stored."""
import unittest

import numpy as np
import rospy
import rostest
from geometry_msgs.msg import Point, Pose, Quaternion
from moveit_msgs.msg import MoveItErrorCodes as Codes

from arm_move.srv import Reset, Step
from arm_truth import CLOSED, HOME, ArmTruth

BOX_ON_TABLE = Pose(Point(0.16, -0.17, 0.025), Quaternion(0, 0, 0, 1))


class ArmMover(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("arm_check")
        cls.truth = ArmTruth()
        for name in ("reset", "step"):
            rospy.wait_for_service(name, timeout=90)
        cls.reset = rospy.ServiceProxy("reset", Reset)
        cls.step = rospy.ServiceProxy("step", Step)

    def test_reset_then_a_step_below_the_floor_then_a_reachable_step(self):
        answer = self.reset(BOX_ON_TABLE, True)
        self.assertEqual(answer.error_code.val, Codes.SUCCESS, answer.message)
        np.testing.assert_allclose(self.truth.arm()[:4], HOME, atol=1e-3)

        before = self.truth.arm()
        below = self.step(Point(0.15, 0.0, -1.0), True)
        self.assertEqual(below.error_code.val, Codes.INVALID_GOAL_CONSTRAINTS, below.message)
        self.assertIn("floor", below.message)
        np.testing.assert_allclose(self.truth.arm(), before, atol=1e-6)
        self.assertEqual(rospy.get_param("mover/waypoints"), [])

        target = (0.15, 0.05, 0.08)
        reached = self.step(Point(*target), False)
        self.assertEqual(reached.error_code.val, Codes.SUCCESS, reached.message)
        np.testing.assert_allclose(self.truth.gripper(), target, atol=2e-3)
        self.assertAlmostEqual(self.truth.joints["left_finger"], CLOSED, delta=1e-3)
        stored = rospy.get_param("mover/waypoints")
        self.assertEqual(len(stored), 1)
        np.testing.assert_allclose(stored[0][:3], target)
        self.assertFalse(stored[0][3])


if __name__ == "__main__":
    rostest.rosrun("arm_move", "arm", ArmMover)
