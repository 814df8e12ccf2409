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
        cls.joints, cls.received = {}, [0]

        def on_joint_states(message):
            cls.joints.update(zip(message.name, message.position))
            cls.received[0] += 1
        rospy.Subscriber("joint_states", JointState, on_joint_states)
        for name in ("reset", "step"):
            rospy.wait_for_service(name, timeout=60)
        cls.reset = rospy.ServiceProxy("reset", Reset)
        cls.step = rospy.ServiceProxy("step", Step)

    def arm(self):
        """The arm's joints from a state published after this call (not one from a motion's
        last moments)."""
        count = self.received[0]
        wait_until(lambda: self.received[0] >= count + 2, "fresh joint states")
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
