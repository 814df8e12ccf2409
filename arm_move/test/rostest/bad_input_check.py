#!/usr/bin/env python3
"""rostest node for bad_input.test (fake MoveIt): NaN in a step target, a zero-length
quaternion in reset, follow with no waypoints, a target inside the RealSense box, one out
of reach, and a second request while one runs. Each answer names the cause; nothing
moves; the waypoint list is unchanged; afterwards a good step still works."""
import threading
import unittest

import numpy as np
import rospy
import rostest
from geometry_msgs.msg import Point, Pose, Quaternion
from sensor_msgs.msg import JointState

from moveit_msgs.msg import MoveItErrorCodes as Codes

from arm_move.srv import Follow, Reset, Step
from arm_truth import ARM_JOINTS, FINGERS as FINGER_JOINTS
from sim_bridge.testing import wait_until

BOX_ON_TABLE = Pose(Point(0.16, -0.17, 0.025), Quaternion(0, 0, 0, 1))


class BadInput(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("bad_input_check")
        cls.joints, cls.received = {}, [0]

        def on_joint_states(message):
            cls.joints.update(zip(message.name, message.position))
            cls.received[0] += 1
        rospy.Subscriber("joint_states", JointState, on_joint_states)
        for name in ("reset", "step", "follow"):
            rospy.wait_for_service(name, timeout=60)
        cls.reset = rospy.ServiceProxy("reset", Reset)
        cls.step = rospy.ServiceProxy("step", Step)
        cls.follow = rospy.ServiceProxy("follow", Follow)
        answer = cls.reset(BOX_ON_TABLE, True)
        assert answer.error_code.val == Codes.SUCCESS, answer.message
        count = cls.received[0]  # the state after the motion, not one from its last moment
        wait_until(lambda: cls.received[0] >= count + 10, "joint states after the reset")

    def state(self):
        names = ARM_JOINTS + FINGER_JOINTS
        wait_until(lambda: all(j in self.joints for j in names), "joint states")
        return np.array([self.joints[j] for j in names])

    def assert_refused(self, answer, code, words):
        self.assertEqual(answer.error_code.val, code, answer.message)
        for word in words:
            self.assertIn(word, answer.message)

    def assert_nothing_changed(self, before):
        # ten more joint states (0.1 s at the fake controllers' 100 Hz): a motion would show
        count = self.received[0]
        wait_until(lambda: self.received[0] >= count + 10, "ten more joint states")
        np.testing.assert_allclose(self.state(), before, atol=1e-9)
        self.assertEqual(rospy.get_param("mover/waypoints"), [])

    def test_1_nan_in_a_step_target(self):
        before = self.state()
        self.assert_refused(self.step(Point(0.15, float("nan"), 0.1), True),
                            Codes.INVALID_GOAL_CONSTRAINTS, ["not a finite", "nothing moved"])
        self.assert_nothing_changed(before)

    def test_2_zero_length_quaternion_in_reset(self):
        before = self.state()
        bad = Pose(Point(0.16, -0.17, 0.025), Quaternion(0, 0, 0, 0))
        self.assert_refused(self.reset(bad, True), Codes.INVALID_GOAL_CONSTRAINTS,
                            ["zero-length quaternion"])
        self.assert_nothing_changed(before)

    def test_3_follow_without_waypoints(self):
        before = self.state()
        self.assert_refused(self.follow(False), Codes.INVALID_MOTION_PLAN, ["no waypoints"])
        self.assert_refused(self.follow(True), Codes.INVALID_MOTION_PLAN, ["no waypoints"])
        self.assert_nothing_changed(before)

    def test_4_targets_inside_the_box_and_out_of_reach(self):
        before = self.state()
        self.assert_refused(self.step(Point(0.16, -0.17, 0.02), True), Codes.GOAL_IN_COLLISION,
                            ["realsense_box"])
        self.assert_refused(self.step(Point(0.6, 0.0, 0.1), True), Codes.NO_IK_SOLUTION,
                            ["out of reach"])
        self.assert_nothing_changed(before)

    def test_5_a_second_request_while_one_runs_is_refused(self):
        answers = {}
        first = threading.Thread(target=lambda: answers.update(
            first=self.step(Point(0.0, 0.2, 0.1), True)))
        first.start()
        # ask again while the first one moves the arm (it takes about a second)
        wait_until(lambda: abs(self.joints["waist"]) > 0.05, "the first step to move")
        second = self.step(Point(0.15, 0.0, 0.1), True)
        first.join(timeout=30)
        self.assert_refused(second, Codes.FAILURE, ["busy"])
        self.assertEqual(answers["first"].error_code.val, Codes.SUCCESS, answers["first"].message)
        self.assertEqual(len(rospy.get_param("mover/waypoints")), 1)  # only the first


if __name__ == "__main__":
    rostest.rosrun("arm_move", "bad_input", BadInput)
