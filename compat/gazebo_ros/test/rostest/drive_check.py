#!/usr/bin/env python3
"""rostest node: the diff drive moves the robot as commanded, in ground truth, and its
odometry agrees (odometrySource from the ~odometry_source parameter)."""
import math
import os
import sys
import unittest

import rospy
import rostest
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sim_checks import Simulator, angle_difference, drive  # noqa: E402

TOLERANCE = 0.02  # 2 %
# s of simulated time the run may last beyond the commanded duration: the test pauses
# the simulator once it has seen the time pass, which a loaded machine does late; the
# motion is judged over the time it really lasted
OVERRUN = 0.5


class Drive(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("drive_check")
        cls.sim = Simulator()
        cls.sim.wait_for_model("diff_bot")
        cls.command = rospy.Publisher("/cmd_vel", Twist, queue_size=1, latch=True)
        cls.odometry = None
        rospy.Subscriber("/odom", Odometry, cls._on_odometry, queue_size=1)
        cls.sim.wait_sim_time(cls.sim.sim_time() + 0.5)  # let it settle on its wheels

    @classmethod
    def _on_odometry(cls, message):
        cls.odometry = message

    def test_1_straight_1_metre_in_5_seconds(self):
        odom_before = self.odometry.pose.pose.position
        elapsed, before, after = drive(self.sim, self.command, 0.2, 0.0, 5.0)
        self.assertGreaterEqual(elapsed, 5.0)
        self.assertLess(elapsed, 5.0 + OVERRUN)
        travelled = math.hypot(after[0] - before[0], after[1] - before[1])
        self.assertAlmostEqual(travelled, 0.2 * elapsed, delta=0.2 * elapsed * TOLERANCE)
        # odometry, published at 50 Hz, read once the robot has stopped moving
        self.sim.wait_sim_time(self.sim.sim_time() + 1.0)
        stopped = self.sim.truth("diff_bot")
        odom_after = self.odometry.pose.pose.position
        true_run = math.hypot(stopped[0] - before[0], stopped[1] - before[1])
        odom_run = math.hypot(odom_after.x - odom_before.x, odom_after.y - odom_before.y)
        self.assertAlmostEqual(odom_run, true_run, delta=true_run * TOLERANCE)
        # Noetic's diff drive fills the pose's covariance only: the twist's stays 0
        # (gazebo_ros_pkgs noetic-devel f9e1a46 gazebo_plugins/src/gazebo_ros_diff_drive.cpp:461-467)
        self.assertGreater(self.odometry.pose.covariance[0], 0.0)
        self.assertEqual(list(self.odometry.twist.covariance), [0.0] * 36)

    def test_2_turn_2_radians_in_4_seconds(self):
        elapsed, before, after = drive(self.sim, self.command, 0.0, 0.5, 4.0)
        self.assertGreaterEqual(elapsed, 4.0)
        self.assertLess(elapsed, 4.0 + OVERRUN)
        turned = angle_difference(after[2], before[2])
        self.assertAlmostEqual(turned, 0.5 * elapsed, delta=0.5 * elapsed * TOLERANCE)

    def test_3_frictionless_casters_do_not_pull_it_sideways(self):
        elapsed, before, after = drive(self.sim, self.command, 0.4, 0.0, 5.0)
        heading = before[2]
        dx, dy = after[0] - before[0], after[1] - before[1]
        along = dx * math.cos(heading) + dy * math.sin(heading)
        sideways = -dx * math.sin(heading) + dy * math.cos(heading)
        self.assertGreater(along, 1.9)
        self.assertLess(abs(sideways), 0.02)


if __name__ == "__main__":
    rostest.rosrun("gazebo_ros", "drive", Drive)
