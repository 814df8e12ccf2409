#!/usr/bin/env python3
"""rostest node on ddrive.launch paused:=true: time stands still until unpaused; the world
holds what it should; diff/odom agrees with the truth while the robot drives upright."""
import math
import unittest

import rospy
import rostest
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from rosgraph_msgs.msg import Clock
from std_srvs.srv import Empty

from sim_bridge.poses import quaternion_matrix
from gazebo_msgs.srv import GetModelState, GetWorldProperties
from sim_bridge.testing import service_proxy, wait_until

class DdriveWorld(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("ddrive_world_check")
        cls.properties = service_proxy("/gazebo/get_world_properties", GetWorldProperties)
        cls.get_state = service_proxy("/gazebo/get_model_state", GetModelState)
        cls.clock = []
        rospy.Subscriber("/clock", Clock, lambda m: cls.clock.append(m.clock.to_sec()))
        cls.odometry = None
        rospy.Subscriber("/diff/odom", Odometry, lambda m: setattr(cls, "odometry", m))
        wait_until(lambda: "ddrive" in cls.properties().model_names, "the robot to be spawned")

    def test_1_clock_stands_still_until_unpaused(self):
        wait_until(lambda: len(self.clock) >= 3, "/clock while paused")
        count = len(self.clock)
        wait_until(lambda: len(self.clock) >= count + 3, "more /clock while paused")
        self.assertEqual(len(set(self.clock)), 1, self.clock[-5:])
        rospy.ServiceProxy("/gazebo/unpause_physics", Empty)()
        wait_until(lambda: self.clock[-1] > self.clock[0] + 0.5, "/clock to advance")

    def test_2_the_world_holds_barriers_boxes_and_asphalt(self):
        names = self.properties().model_names
        self.assertGreaterEqual(sum("jersey_barrier" in n for n in names), 2, names)
        self.assertGreaterEqual(sum("cardboard_box" in n for n in names), 3, names)
        self.assertIn("asphalt_plane", names)

    def truth(self):
        state = self.get_state("ddrive", "")
        p, q = state.pose.position, state.pose.orientation
        return p.x, p.y, quaternion_matrix((q.x, q.y, q.z, q.w))[2, 2]

    def sim_time(self):
        return self.properties().sim_time

    def test_3_odometry_agrees_with_the_truth_driving_upright(self):
        command = rospy.Publisher("/diff/cmd_vel", Twist, queue_size=1, latch=True)
        wait_until(lambda: self.odometry is not None, "diff/odom")
        self.assertEqual(self.odometry.header.frame_id, "odom")
        start_truth, start_odom = self.truth(), self.odometry.pose.pose.position
        forward = Twist()
        forward.linear.x = 0.4
        began = self.sim_time()
        command.publish(forward)
        wait_until(lambda: self.sim_time() > began + 6.0, "6 s of driving")
        command.publish(Twist())
        stop = self.sim_time()
        wait_until(lambda: self.sim_time() > stop + 1.0, "the robot to stop")
        end_truth, end_odom = self.truth(), self.odometry.pose.pose.position
        self.assertGreater(end_truth[2], 0.99)  # still upright
        true_run = math.hypot(end_truth[0] - start_truth[0], end_truth[1] - start_truth[1])
        odom_run = math.hypot(end_odom.x - start_odom.x, end_odom.y - start_odom.y)
        self.assertGreater(true_run, 2.0)
        self.assertAlmostEqual(odom_run, true_run, delta=0.05 * true_run)


if __name__ == "__main__":
    rostest.rosrun("diff_drive", "ddrive_world", DdriveWorld)
