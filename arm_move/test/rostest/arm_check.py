#!/usr/bin/env python3
"""rostest node for arm.test (fake backend): reset, then a step below the floor gets
INVALID_GOAL_CONSTRAINTS (what the mover documents for it) and moves nothing, then a
reachable step succeeds, the joints end where the gripper point is the target, and the
waypoint is stored."""
import unittest

import numpy as np
import rospy
import rostest
from geometry_msgs.msg import Point, Pose, Quaternion
from sensor_msgs.msg import JointState

from arm_move.kinematics import ARM_JOINTS, ArmKinematics
from arm_move.msg import MoveItErrorCodes as Codes
from arm_move.srv import Reset, Step
from sim_bridge.testing import wait_until

import rospkg

BOX_ON_TABLE = Pose(Point(0.16, -0.17, 0.025), Quaternion(0, 0, 0, 1))


class ArmMover(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("arm_check")
        path = rospkg.RosPack().get_path("arm_move") + "/config/px100.yaml"
        cls.kinematics = ArmKinematics.from_file(path)
        cls.joints = {}
        rospy.Subscriber("joint_states", JointState,
                         lambda m: cls.joints.update(zip(m.name, m.position)))
        for name in ("reset", "step"):
            rospy.wait_for_service(name, timeout=60)
        cls.reset = rospy.ServiceProxy("reset", Reset)
        cls.step = rospy.ServiceProxy("step", Step)

    def arm(self):
        wait_until(lambda: all(j in self.joints for j in ARM_JOINTS), "joint states")
        return np.array([self.joints[j] for j in ARM_JOINTS])

    def test_reset_then_a_step_below_the_floor_then_a_reachable_step(self):
        answer = self.reset(BOX_ON_TABLE, True)
        self.assertEqual(answer.error_code.val, Codes.SUCCESS, answer.message)
        np.testing.assert_allclose(self.arm(), self.kinematics.named_poses["home"], atol=1e-3)

        before = self.arm()
        below = self.step(Point(0.15, 0.0, -1.0), True)
        self.assertEqual(below.error_code.val, Codes.INVALID_GOAL_CONSTRAINTS, below.message)
        self.assertIn("floor", below.message)
        np.testing.assert_allclose(self.arm(), before, atol=1e-6)
        self.assertEqual(rospy.get_param("mover/waypoints"), [])

        target = (0.15, 0.05, 0.08)
        reached = self.step(Point(*target), False)
        self.assertEqual(reached.error_code.val, Codes.SUCCESS, reached.message)
        np.testing.assert_allclose(self.kinematics.gripper_point(self.arm()), target, atol=2e-3)
        self.assertLess(self.joints["left_finger"], 0.016)  # closed
        stored = rospy.get_param("mover/waypoints")
        self.assertEqual(len(stored), 1)
        np.testing.assert_allclose(stored[0][:3], target)
        self.assertFalse(stored[0][3])


if __name__ == "__main__":
    rostest.rosrun("arm_move", "arm", ArmMover)
