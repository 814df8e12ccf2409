#!/usr/bin/env python3
"""rostest node for failed_execution.test: the fake backend aborts every arm goal part way.
A step that planned fine but whose execution fails answers CONTROL_FAILED naming the
controller's error, the waypoint list stays as it was (the README's promise for any
failure), and the mover keeps serving: the next requests answer too."""
import unittest

import numpy as np
import rospy
import rostest
from geometry_msgs.msg import Point
from sensor_msgs.msg import JointState

from arm_move.kinematics import ARM_JOINTS
from arm_move.msg import MoveItErrorCodes as Codes
from arm_move.srv import Step
from sim_bridge.testing import wait_until


class FailedExecution(unittest.TestCase):
    def test_a_failed_execution_stores_no_waypoint_and_the_mover_keeps_serving(self):
        rospy.init_node("failed_execution_check")
        joints = {}
        rospy.Subscriber("joint_states", JointState,
                         lambda m: joints.update(zip(m.name, m.position)))
        rospy.wait_for_service("step", timeout=60)
        step = rospy.ServiceProxy("step", Step)
        wait_until(lambda: all(j in joints for j in ARM_JOINTS), "joint states")
        before = np.array([joints[j] for j in ARM_JOINTS])
        stored = rospy.get_param("mover/waypoints")

        answer = step(Point(0.15, 0.05, 0.1), True)
        self.assertEqual(answer.error_code.val, Codes.CONTROL_FAILED, answer.message)
        self.assertIn("aborted", answer.message)         # the controller's own words
        self.assertIn("no waypoint stored", answer.message)
        self.assertEqual(rospy.get_param("mover/waypoints"), stored)
        # it did run (the failure came from the driver, not from planning)
        wait_until(lambda: np.abs(np.array([joints[j] for j in ARM_JOINTS]) - before).max()
                   > 0.01, "the arm to have moved part of the way")

        # the mover keeps serving: a second step plans from where the arm stopped and fails
        # the same way; a bad request gets its own answer; the list never changes
        again = step(Point(0.12, -0.05, 0.12), False)
        self.assertEqual(again.error_code.val, Codes.CONTROL_FAILED, again.message)
        bad = step(Point(0.15, float("nan"), 0.1), True)
        self.assertEqual(bad.error_code.val, Codes.INVALID_GOAL_CONSTRAINTS, bad.message)
        self.assertEqual(rospy.get_param("mover/waypoints"), stored)


if __name__ == "__main__":
    rostest.rosrun("arm_move", "failed_execution", FailedExecution)
