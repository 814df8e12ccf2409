#!/usr/bin/env python3
"""rostest node: in the RB1 warehouse, a robot spawned where the course spawns it (-0.4, -1.35)
rests inside the taped start square, its laser sees the walls around it, and driving forward
at 0.2 m/s for 5 s moves it 1 m, in ground truth (/gazebo/get_model_state)."""
import math
import os
import sys
import time
import unittest

import rospy
import rostest
from gazebo_msgs.srv import GetModelState, GetWorldProperties
from geometry_msgs.msg import Twist
from sensor_msgs.msg import LaserScan
from std_srvs.srv import Empty

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from rb1_workshop_layout import SQUARE, START, SWEEP_RADIUS  # noqa: E402

MODEL = "diff_bot"
TIMEOUT = 60.0  # wall seconds any one wait may take
LASER_X = 0.15  # the test robot's laser, ahead of its base_footprint
# the walls' inner faces (see worlds/ros2_online_workshop.world)
EAST_WALL, NORTH_WALL = 5.804, 0.45


def wait_until(condition, what, interval=0.001):
    end = time.monotonic() + TIMEOUT
    while not rospy.is_shutdown():
        if condition():
            return
        if time.monotonic() > end:
            raise AssertionError(f"timed out after {TIMEOUT:.0f} s waiting for {what}")
        time.sleep(interval)


def yaw_roll_pitch(q):
    yaw = math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))
    roll = math.atan2(2 * (q.w * q.x + q.y * q.z), 1 - 2 * (q.x * q.x + q.y * q.y))
    pitch = math.asin(max(-1.0, min(1.0, 2 * (q.w * q.y - q.z * q.x))))
    return yaw, roll, pitch


class StartSquare(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("start_square_check")
        for name in ("get_model_state", "get_world_properties", "pause_physics",
                     "unpause_physics"):
            rospy.wait_for_service(f"/gazebo/{name}", timeout=TIMEOUT)
        cls.get_state = rospy.ServiceProxy("/gazebo/get_model_state", GetModelState)
        cls.properties = rospy.ServiceProxy("/gazebo/get_world_properties", GetWorldProperties)
        cls.pause = rospy.ServiceProxy("/gazebo/pause_physics", Empty)
        cls.unpause = rospy.ServiceProxy("/gazebo/unpause_physics", Empty)
        cls.command = rospy.Publisher("/cmd_vel", Twist, queue_size=1, latch=True)
        cls.scan = None
        rospy.Subscriber("/scan", LaserScan, cls._on_scan, queue_size=1)
        wait_until(lambda: MODEL in cls.properties().model_names, f"model '{MODEL}'")
        cls.wait_sim_time(cls.sim_time() + 1.0)  # settled on its wheels

    @classmethod
    def _on_scan(cls, message):
        cls.scan = message

    @classmethod
    def sim_time(cls):
        return cls.properties().sim_time

    @classmethod
    def wait_sim_time(cls, target):
        wait_until(lambda: cls.sim_time() >= target, f"simulated time {target:.2f} s")

    def truth(self):
        state = self.get_state(MODEL, "")
        self.assertTrue(state.success, state.status_message)
        return state.pose.position, yaw_roll_pitch(state.pose.orientation)

    def fresh_scan(self):
        """The first scan stamped after now (simulated time)."""
        now = self.sim_time()
        wait_until(lambda: self.scan is not None and self.scan.header.stamp.to_sec() > now,
                   "a scan", interval=0.01)
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
        self.wait_sim_time(self.sim_time() + 1.0)
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
        self.wait_sim_time(self.sim_time() + 0.5)
        self.pause()
        start_time = self.sim_time()
        before, (heading, _, _) = self.truth()
        forward = Twist()
        forward.linear.x = 0.2
        self.command.publish(forward)
        self.unpause()
        self.wait_sim_time(start_time + 5.0)
        self.pause()
        elapsed = self.sim_time() - start_time
        after, (heading_after, _, _) = self.truth()
        self.command.publish(Twist())
        self.unpause()
        self.assertLess(abs(elapsed - 5.0), 0.05)
        dx, dy = after.x - before.x, after.y - before.y
        along = dx * math.cos(heading) + dy * math.sin(heading)
        sideways = -dx * math.sin(heading) + dy * math.cos(heading)
        self.assertAlmostEqual(along, 1.0, delta=0.02)
        self.assertLess(abs(sideways), 0.02)
        self.assertLess(abs(heading_after - heading), 0.02)
        # the wall ahead is 1 m nearer
        self.wait_sim_time(self.sim_time() + 0.5)
        stopped, _ = self.truth()
        self.assertAlmostEqual(self.beam(self.fresh_scan(), 0.0),
                               EAST_WALL - (stopped.x + LASER_X), delta=0.01)


if __name__ == "__main__":
    rostest.rosrun("rb1_base_gazebo", "start_square", StartSquare)
