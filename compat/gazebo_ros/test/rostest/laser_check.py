#!/usr/bin/env python3
"""rostest node: the laser against the test world's known geometry, mounted upside down."""
import math
import os
import sys
import unittest

import numpy as np
import rospy
import rostest
import tf2_ros
from sensor_msgs.msg import LaserScan

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sim_checks import Simulator, wait_until  # noqa: E402

from sim_bridge.poses import quaternion_matrix  # noqa: E402


SCAN_PERIOD = 0.05  # s: the fixture's laser updates at 20 Hz


class Laser(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("laser_check")
        cls.sim = Simulator()
        cls.sim.wait_for_model("diff_bot")
        cls.scans = []
        rospy.Subscriber("/scan", LaserScan, cls.scans.append, queue_size=50)
        cls.buffer = tf2_ros.Buffer()
        cls.listener = tf2_ros.TransformListener(cls.buffer)
        cls.started = cls.sim.sim_time()
        cls.sim.wait_sim_time(cls.started + 1.0)  # settled, scans arriving
        wait_until(lambda: len(cls.scans) > 5, "scans on /scan")

    def test_centre_beam_reads_the_wall_2_metres_ahead(self):
        scan = self.scans[-1]
        self.assertEqual(scan.header.frame_id, "laser")
        self.assertEqual(len(scan.ranges), 361)
        centre = scan.ranges[180]
        self.assertAlmostEqual(scan.angle_min + 180 * scan.angle_increment, 0.0, places=6)
        self.assertAlmostEqual(centre, 2.00, delta=0.01)

    def test_a_beam_with_nothing_in_range_reads_inf(self):
        scan = self.scans[-1]
        # upside down, the first beam (sensor's -90 degrees) looks to the robot's left, where
        # the post stands; the last looks right, where nothing is within 10 m
        self.assertEqual(scan.ranges[-1], math.inf)

    def test_scans_are_stamped_in_simulated_time_at_20_hz(self):
        # At real_time_factor 0 the simulator outruns the wire: the laser's publisher keeps
        # one scan queued (as gazebo_ros_laser's), so some scans are dropped. Every stamp is
        # still on the 20 Hz grid, and scans that got through back to back are 0.05 s apart.
        stamps = [s.header.stamp.to_sec() for s in self.scans]
        periods = np.diff(stamps) / SCAN_PERIOD
        np.testing.assert_allclose(periods, np.round(periods), atol=1e-4)
        self.assertGreaterEqual(np.round(periods).min(), 1)
        self.assertEqual(np.round(periods).min(), 1, "no two scans 0.05 s apart")
        # simulated time (wall time would be decades ahead), and recent: the simulator runs
        # many times faster than real time here, so "how recent" is bounded by when the
        # test began, not by a wall-clock latency
        self.assertLessEqual(self.started, stamps[-1])
        self.assertLessEqual(stamps[-1], self.sim.sim_time())

    def test_upside_down_sensor_sees_the_left_post_on_the_left(self):
        scan = self.scans[-1]
        stamped = self.buffer.lookup_transform("base_link", "laser", rospy.Time(0),
                                               rospy.Duration(10.0))
        t = stamped.transform
        rotation = quaternion_matrix((t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w))
        offset = np.array([t.translation.x, t.translation.y, t.translation.z])
        angles = scan.angle_min + np.arange(len(scan.ranges)) * scan.angle_increment
        ranges = np.array(scan.ranges)
        hit = np.isfinite(ranges) & (ranges < 1.5)  # near things: the post, not the wall
        points = np.stack([ranges[hit] * np.cos(angles[hit]), ranges[hit] * np.sin(angles[hit]),
                           np.zeros(int(hit.sum()))], axis=1) @ rotation.T + offset
        self.assertGreater(len(points), 0, "the post was not seen")
        # the post's face is 0.95 m to the left of the robot's centre line
        self.assertTrue(np.all(points[:, 1] > 0.9), points)
        self.assertAlmostEqual(float(points[:, 1].min()), 0.95, delta=0.02)


if __name__ == "__main__":
    rostest.rosrun("gazebo_ros", "laser", Laser)
