#!/usr/bin/env python3
"""rostest node: a homework-style script on Interbotix's Python API moves the simulated
px100 (``InterbotixManipulatorXS("px100", "arm", "gripper")``): the gripper point, in the
simulator's ground truth (its link states, course_grader's ArmTruth), within 1 cm of a pose
set by components; the fingers, in ground truth, open and close to their limits."""
import unittest

import numpy as np
import rospy
import rostest

from course_grader.hw3_probe import ArmTruth
from interbotix_xs_modules.arm import InterbotixManipulatorXS
from sim_bridge.testing import wait_until
from urdf_tools.model import parse_urdf

BASE, TIP = "px100/base_link", "px100/ee_gripper_link"
FINGERS = ("px100/left_finger_link", "px100/right_finger_link")
POSITION_TOLERANCE = 0.01   # m: the 1 cm
# m a finger may stop short of its limit: the position controller's p (50 N/m, Interbotix's
# px100_position_controllers.yaml) against the URDF's joint friction (0.1 N): 2 mm, and a half
FINGER_SHORT = 0.0025
STARTUP = 60.0              # s: the simulator, its controllers and the driver


class ScriptOnTheSimulatedArm(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("xs_modules_sim_check")
        wait_until(lambda: rospy.has_param("/px100/robot_description"), "the description",
                   timeout=STARTUP)
        rospy.wait_for_service("/px100/get_robot_info", timeout=STARTUP)
        cls.bot = InterbotixManipulatorXS("px100", "arm", "gripper", moving_time=1.5,
                                          init_node=False)
        cls.model = parse_urdf(rospy.get_param("/px100/robot_description"))
        cls.truth = ArmTruth("px100", cls.model, STARTUP)

    def settled_point(self, link_from=BASE, link_to=TIP):
        """The true point once it moves less than 0.5 mm in 0.2 s (simulated)."""
        last = [self.truth.point_in(link_from, link_to)]

        def still():
            rospy.sleep(0.2)
            now = self.truth.point_in(link_from, link_to)
            moved = np.linalg.norm(now - last[0])
            last[0] = now
            return moved < 5e-4
        wait_until(still, "the arm to settle", timeout=30.0)
        return last[0]

    def finger_gap(self):
        left = self.settled_point(BASE, FINGERS[0])
        right = self.settled_point(BASE, FINGERS[1])
        return float(np.linalg.norm(left - right))

    def test_1_a_pose_by_components_is_where_the_true_gripper_goes(self):
        self.bot.arm.go_to_home_pose()
        for target in ([0.2, 0.0, 0.15], [0.15, 0.1, 0.1]):
            _, found = self.bot.arm.set_ee_pose_components(x=target[0], y=target[1],
                                                           z=target[2], pitch=0.3)
            self.assertTrue(found, target)
            error = np.linalg.norm(self.settled_point() - target)
            self.assertLess(error, POSITION_TOLERANCE, f"{target}: {1000 * error:.1f} mm")

    def test_2_the_true_fingers_open_and_close(self):
        """Each finger's joint runs from its lower to its upper limit (15 to 37 mm from the
        gripper's middle): the fingers' links that far apart, each within FINGER_SHORT."""
        limit = self.model.joints["left_finger"].limit
        self.bot.gripper.close()
        closed = self.finger_gap()
        self.assertLess(abs(closed - 2 * limit.lower), 2 * FINGER_SHORT, closed)
        self.bot.gripper.open()
        opened = self.finger_gap()
        self.assertLess(abs(opened - 2 * limit.upper), 2 * FINGER_SHORT, opened)
        self.bot.gripper.close()
        self.assertAlmostEqual(self.finger_gap(), closed, delta=0.002)

    def test_3_sleep(self):
        self.bot.arm.go_to_sleep_pose()
        sleep = self.settled_point()
        self.assertLess(sleep[2], 0.1)   # folded down over its base


if __name__ == "__main__":
    rostest.rosrun("interbotix_xsarm_control", "xs_modules_simulated_arm",
                   ScriptOnTheSimulatedArm)
