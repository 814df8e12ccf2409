#!/usr/bin/env python3
"""rostest node: in the RB1 warehouse, a robot spawned where the course spawns it (-0.4, -1.35)
rests inside the taped start square, its laser sees the walls around it, and driving forward
at 0.2 m/s for 5 s moves it 1 m, in ground truth (/gazebo/get_model_state)."""
import math
import os
import sys
import unittest

import rospy
import rostest
from geometry_msgs.msg import Twist
from sensor_msgs.msg import LaserScan
from tf.transformations import euler_from_quaternion

from sim_bridge.testing import Simulator, wait_until

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from rb1_workshop_layout import SQUARE, START, SWEEP_RADIUS  # noqa: E402

MODEL = "diff_bot"
LASER_X = 0.15  # the test robot's laser, ahead of its base_footprint
# the walls' inner faces (see worlds/ros2_online_workshop.world)
EAST_WALL, NORTH_WALL = 5.804, 0.45


def yaw_roll_pitch(q):
    roll, pitch, yaw = euler_from_quaternion([q.x, q.y, q.z, q.w])
    return yaw, roll, pitch


class StartSquare(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("start_square_check")
        cls.sim = Simulator()
        cls.command = rospy.Publisher("/cmd_vel", Twist, queue_size=1, latch=True)
        cls.scan = None
        rospy.Subscriber("/scan", LaserScan, cls._on_scan, queue_size=1)
        cls.sim.wait_for_model(MODEL)
        cls.sim.wait_sim_time(cls.sim.sim_time() + 1.0)  # settled on its wheels

    @classmethod
    def _on_scan(cls, message):
        cls.scan = message

    def truth(self):
        pose = self.sim.pose(MODEL)
        return pose.position, yaw_roll_pitch(pose.orientation)

    def fresh_scan(self):
        """The first scan stamped after now (simulated time)."""
        now = self.sim.sim_time()
        wait_until(lambda: self.scan is not None and self.scan.header.stamp.to_sec() > now,
                   "a scan")
        return self.scan

    def beam(self, scan, angle):
        index = int(round((angle - scan.angle_min) / scan.angle_increment))
        return scan.ranges[index]

    def test_1_it_rests_inside_the_square(self):
        position, (yaw, roll, pitch) = self.truth()
        self.assertAlmostEqual(position.x, START[0], delta=0.01)
        self.assertAlmostEqual(position.y, START[1], delta=0.01)
        # all of it: the disc it sweeps turning in place lies inside the tape
        self.assertGreater(position.x - SWEEP_RADIUS, SQUARE["x_min"])
        self.assertLess(position.x + SWEEP_RADIUS, SQUARE["x_max"])
        self.assertGreater(position.y - SWEEP_RADIUS, SQUARE["y_min"])
        self.assertLess(position.y + SWEEP_RADIUS, SQUARE["y_max"])
        # on the floor, level, heading +x, and staying there
        self.assertLess(abs(position.z), 0.005)
        self.assertLess(max(abs(roll), abs(pitch)), 0.01)
        self.assertLess(abs(yaw), 0.01)
        self.sim.wait_sim_time(self.sim.sim_time() + 1.0)
        later, _ = self.truth()
        self.assertLess(math.hypot(later.x - position.x, later.y - position.y), 0.002)

    def test_2_its_laser_sees_the_walls_around_it(self):
        position, _ = self.truth()
        scan = self.fresh_scan()
        self.assertAlmostEqual(self.beam(scan, 0.0), EAST_WALL - (position.x + LASER_X),
                               delta=0.01)
        self.assertAlmostEqual(self.beam(scan, math.pi / 2), NORTH_WALL - position.y,
                               delta=0.01)

    def test_3_forward_1_metre_in_5_seconds_moves_it_1_metre(self):
        self.command.publish(Twist())
        self.sim.wait_sim_time(self.sim.sim_time() + 0.5)
        self.sim.pause()
        start_time = self.sim.sim_time()
        before, (heading, _, _) = self.truth()
        forward = Twist()
        forward.linear.x = 0.2
        self.command.publish(forward)
        self.sim.unpause()
        # at full speed a wall millisecond is many simulated ones: the command may reach
        # the simulator a little after the unpause, and the drive plugin takes it at its next
        # update slot (up to 1/updateRate later, as gazebo_ros_diff_drive). So the speed is
        # judged on the steady part, from 1 s on, and the whole run with that start allowed
        self.sim.wait_sim_time(start_time + 1.0)
        self.sim.pause()
        steady_time = self.sim.sim_time()
        steady, _ = self.truth()
        self.sim.unpause()
        self.sim.wait_sim_time(start_time + 5.0)
        self.sim.pause()
        elapsed = self.sim.sim_time() - start_time
        after, (heading_after, _, _) = self.truth()
        self.command.publish(Twist())
        self.sim.unpause()
        # the pause lands a few wall milliseconds after 5 s, which at full speed is up to a
        # simulated second: the distance is judged against the time that really passed
        self.assertGreaterEqual(elapsed, 5.0)
        self.assertLess(elapsed, 7.0)

        def along(a, b):
            return (b.x - a.x) * math.cos(heading) + (b.y - a.y) * math.sin(heading)
        speed = along(steady, after) / (start_time + elapsed - steady_time)
        self.assertAlmostEqual(speed, forward.linear.x, delta=0.002)
        self.assertAlmostEqual(along(before, after), forward.linear.x * elapsed, delta=0.03)
        dx, dy = after.x - before.x, after.y - before.y
        sideways = -dx * math.sin(heading) + dy * math.cos(heading)
        self.assertLess(abs(sideways), 0.02)
        self.assertLess(abs(heading_after - heading), 0.02)
        # the wall ahead is 1 m nearer
        self.sim.wait_sim_time(self.sim.sim_time() + 0.5)
        stopped, _ = self.truth()
        self.assertAlmostEqual(self.beam(self.fresh_scan(), 0.0),
                               EAST_WALL - (stopped.x + LASER_X), delta=0.01)


if __name__ == "__main__":
    rostest.rosrun("rb1_base_gazebo", "start_square", StartSquare)
