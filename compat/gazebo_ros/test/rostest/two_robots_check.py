#!/usr/bin/env python3
"""rostest node: two robots in two namespaces drive independently, each on its own topics
and frames."""
import math
import os
import sys
import unittest

import rospy
import rostest
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import LaserScan

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sim_checks import Simulator, angle_difference, wait_until  # noqa: E402


class TwoRobots(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("two_robots_check")
        cls.sim = Simulator()
        cls.sim.wait_for_model("robot1")
        cls.sim.wait_for_model("robot2")
        cls.last = {}
        for name in ("robot1", "robot2"):
            rospy.Subscriber(f"/{name}/odom", Odometry,
                             lambda m, n=name: cls.last.__setitem__(f"{n}/odom", m))
            rospy.Subscriber(f"/{name}/scan", LaserScan,
                             lambda m, n=name: cls.last.__setitem__(f"{n}/scan", m))
        cls.commands = {name: rospy.Publisher(f"/{name}/cmd_vel", Twist, queue_size=1, latch=True)
                        for name in ("robot1", "robot2")}

    def test_each_robot_obeys_its_own_command(self):
        self.sim.wait_sim_time(self.sim.sim_time() + 0.5)
        before = {name: self.sim.truth(name) for name in ("robot1", "robot2")}
        forward, turn = Twist(), Twist()
        forward.linear.x = 0.3
        turn.angular.z = 0.5
        self.sim.pause()
        start = self.sim.sim_time()
        self.commands["robot1"].publish(forward)
        self.commands["robot2"].publish(turn)
        self.sim.unpause()
        self.sim.wait_sim_time(start + 2.0)
        self.sim.pause()
        after = {name: self.sim.truth(name) for name in ("robot1", "robot2")}
        for publisher in self.commands.values():
            publisher.publish(Twist())
        self.sim.unpause()
        moved1 = math.hypot(after["robot1"][0] - before["robot1"][0],
                            after["robot1"][1] - before["robot1"][1])
        moved2 = math.hypot(after["robot2"][0] - before["robot2"][0],
                            after["robot2"][1] - before["robot2"][1])
        turned1 = abs(angle_difference(after["robot1"][2], before["robot1"][2]))
        turned2 = angle_difference(after["robot2"][2], before["robot2"][2])
        self.assertAlmostEqual(moved1, 0.6, delta=0.03)
        self.assertLess(turned1, 0.02)
        self.assertAlmostEqual(turned2, 1.0, delta=0.05)
        self.assertLess(moved2, 0.02)

    def test_topics_and_frames_are_the_robots_own(self):
        wait_until(lambda: all(k in self.last for k in ("robot1/odom", "robot2/odom",
                                                          "robot1/scan", "robot2/scan")),
                   "odometry and scans of both robots")
        for name in ("robot1", "robot2"):
            odometry = self.last[f"{name}/odom"]
            self.assertEqual(odometry.header.frame_id, f"{name}/odom")
            self.assertEqual(odometry.child_frame_id, f"{name}/base_footprint")
            self.assertEqual(self.last[f"{name}/scan"].header.frame_id, f"{name}/laser")


if __name__ == "__main__":
    rostest.rosrun("gazebo_ros", "two_robots", TwoRobots)
