#!/usr/bin/env python3
"""rostest node: the RB1 in the warehouse (tasks 2 and 3) against the simulator's truth."""
import math
import os
import sys
import unittest

import numpy as np
import rospy
import rostest
import tf2_ros
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import LaserScan

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rb1_checks import SQUARE_X, SQUARE_Y, START, TIMEOUT, Truth, wait_until  # noqa: E402

from sim_bridge.poses import quaternion_matrix  # noqa: E402

# rb1_base_gazebo's room (models/rb1_workshop_room): the walls' inner faces, world frame (m).
# From the start square the east wall is 6.2 m ahead and the south wall 3.9 m to the right,
# with free floor between.
EAST_WALL_X = 5.804
SOUTH_WALL_Y = -5.251
RB1_RADIUS = 0.25  # m: the body's footprint, which must lie inside the square
AHEAD_CONE = math.radians(3)   # beams this close to straight ahead, seen from the laser
RIGHT_CONE = math.radians(3)   # beams this close to the right (the scan's last 3 degrees)


class Warehouse(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("warehouse_check")
        cls.truth = Truth()
        cls.odometry, cls.scans = [], []
        rospy.Subscriber("/odom", Odometry, cls.odometry.append, queue_size=200)
        rospy.Subscriber("/scan", LaserScan, cls.scans.append, queue_size=50)
        cls.buffer = tf2_ros.Buffer()
        cls.listener = tf2_ros.TransformListener(cls.buffer)
        cls.command = rospy.Publisher("/cmd_vel", Twist, queue_size=1, latch=True)

    def test_1_spawned_level_in_the_taped_square(self):
        self.truth.wait_sim_time(2.0)
        x, y, roll, pitch, _ = self.truth.pose()
        self.assertLess(math.hypot(x - START[0], y - START[1]), 0.1)
        # the whole body inside the tape (the west side is the wall)
        self.assertTrue(SQUARE_X[0] + RB1_RADIUS < x < SQUARE_X[1] - RB1_RADIUS, x)
        self.assertTrue(SQUARE_Y[0] + RB1_RADIUS < y < SQUARE_Y[1] - RB1_RADIUS, y)
        self.assertLess(abs(math.degrees(roll)), 1.0)
        self.assertLess(abs(math.degrees(pitch)), 1.0)

    def scan_points_in_odom(self, scan):
        """The scan's points and the laser's origin, in odom."""
        stamped = self.buffer.lookup_transform("odom", scan.header.frame_id, rospy.Time(0),
                                               rospy.Duration(TIMEOUT))
        t = stamped.transform
        rotation = quaternion_matrix((t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w))
        offset = np.array([t.translation.x, t.translation.y, t.translation.z])
        ranges = np.array(scan.ranges)
        angles = scan.angle_min + np.arange(len(ranges)) * scan.angle_increment
        local = np.stack([ranges * np.cos(angles), ranges * np.sin(angles),
                          np.zeros(len(ranges))], axis=1)
        return local @ rotation.T + offset, offset

    def test_2_scan_in_front_laser_at_20_hz_matching_the_warehouse(self):
        wait_until(lambda: len(self.scans) > 10, "scans on /scan")
        scan = self.scans[-1]
        self.assertEqual(scan.header.frame_id, "front_laser")
        stamps = [s.header.stamp.to_sec() for s in self.scans[-10:]]
        np.testing.assert_allclose(np.diff(stamps), 0.05, atol=1e-6)
        # the robot stands still at the start facing +x: odom is the world (odometrySource
        # world). Directions are taken from the laser (0.25 m ahead of the centre), whose
        # field of view ends at its right.
        points, laser = self.scan_points_in_odom(scan)
        finite = np.isfinite(points[:, 0])
        heading = np.arctan2(points[:, 1] - laser[1], points[:, 0] - laser[0])
        ahead = finite & (np.abs(heading) < AHEAD_CONE)
        right = finite & (np.abs(heading + math.pi / 2) < RIGHT_CONE)
        self.assertTrue(ahead.any() and right.any())
        # the walls where the scan puts them (median over the beams: 1 cm noise each)
        self.assertAlmostEqual(float(np.median(points[ahead, 0])), EAST_WALL_X, delta=0.03)
        self.assertAlmostEqual(float(np.median(points[right, 1])), SOUTH_WALL_Y, delta=0.03)

    def test_3_odometry_at_20_hz_or_more_in_odom_and_base_footprint(self):
        count = len(self.odometry)
        start = self.truth.sim_time()
        self.truth.wait_sim_time(start + 2.0)
        recent = [m for m in self.odometry[count:]
                  if m.header.stamp.to_sec() > start + 0.1]
        self.assertGreaterEqual(len(recent), 0.95 * 20 * 1.9)
        self.assertEqual(recent[-1].header.frame_id, "odom")
        self.assertEqual(recent[-1].child_frame_id, "base_footprint")

    def test_4_cmd_vel_moves_it(self):
        x0, y0, *_ = self.truth.pose()
        forward = Twist()
        forward.linear.x = 0.2
        start = self.truth.sim_time()
        self.command.publish(forward)
        self.truth.wait_sim_time(start + 3.0)
        self.command.publish(Twist())
        x1, y1, *_ = self.truth.pose()
        self.assertGreaterEqual(math.hypot(x1 - x0, y1 - y0), 0.55)


if __name__ == "__main__":
    rostest.rosrun("my_rb1_ros", "warehouse", Warehouse)
