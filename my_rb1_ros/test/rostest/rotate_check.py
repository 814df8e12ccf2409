#!/usr/bin/env python3
"""rostest node: /rotate_robot turns the RB1 by the requested angle, measured in the
simulator's truth with full turns counted; a second request during a rotation and an angle
beyond the limit are refused."""
import math
import os
import sys
import threading
import unittest

import rospy
import rostest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rb1_checks import TIMEOUT, Truth, wait_until  # noqa: E402

from my_rb1_ros.srv import Rotate  # noqa: E402

ANGLES = (-90, 90, 180, -180, 270, 360, 45, 0, -720)


class RotateRobot(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("rotate_check")
        cls.truth = Truth()
        rospy.wait_for_service("/rotate_robot", timeout=TIMEOUT)
        cls.rotate = rospy.ServiceProxy("/rotate_robot", Rotate)
        cls.truth.wait_sim_time(1.0)  # settled on its wheels

    def rotation(self, degrees):
        """(answer, true rotation in degrees) of one call."""
        before = self.truth.accumulated_yaw()
        answer = self.rotate(degrees).result
        self.truth.wait_sim_time(self.truth.sim_time() + 0.5)  # whatever coasting remains
        return answer, math.degrees(self.truth.accumulated_yaw() - before)

    def test_1_every_angle_within_a_degree(self):
        for degrees in ANGLES:
            with self.subTest(degrees=degrees):
                answer, turned = self.rotation(degrees)
                self.assertTrue(answer.startswith("success"), answer)
                self.assertIn(f"rotated {degrees} degrees", answer)
                self.assertAlmostEqual(turned, degrees, delta=1.0)

    def test_2_a_second_request_is_refused_and_the_first_completes(self):
        first = {}
        before = self.truth.accumulated_yaw()
        worker = threading.Thread(target=lambda: first.update(answer=self.rotate(360).result))
        worker.start()
        wait_until(lambda: abs(self.truth.accumulated_yaw() - before) > math.radians(20),
                   "the first rotation to be under way")
        second = self.rotate(90).result
        self.assertTrue(second.startswith("failure"), second)
        self.assertIn("another rotation is running", second)
        worker.join(TIMEOUT)
        self.truth.wait_sim_time(self.truth.sim_time() + 0.5)
        self.assertTrue(first["answer"].startswith("success"), first["answer"])
        self.assertAlmostEqual(math.degrees(self.truth.accumulated_yaw() - before), 360.0,
                               delta=1.0)

    def test_3_an_angle_beyond_the_limit_is_refused_without_moving(self):
        x0, y0, _, _, _ = self.truth.pose()
        answer, turned = self.rotation(4000)
        self.assertTrue(answer.startswith("failure"), answer)
        self.assertIn("4000", answer)
        self.assertLess(abs(turned), 0.1)
        x1, y1, _, _, _ = self.truth.pose()
        self.assertLess(math.hypot(x1 - x0, y1 - y0), 0.005)


if __name__ == "__main__":
    rostest.rosrun("my_rb1_ros", "rotate", RotateRobot)
