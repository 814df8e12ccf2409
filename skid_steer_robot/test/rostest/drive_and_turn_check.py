#!/usr/bin/env python3
"""rostest node: the skid-steer robot drives 1 m forward (± 5%) and turns 90 degrees in
place (± 5 degrees), in the simulator's truth. The turn is stopped on odometry, as a
driver would stop it on what the robot says."""
import math
import unittest

import rospy
import rostest
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry

from sim_bridge.poses import yaw_from_quaternion
from gazebo_msgs.srv import GetModelState, GetWorldProperties
from sim_bridge.testing import service_proxy, wait_until


# 1.0 rad/s commanded for 3 s turns it this far in truth (README; measured in sim_bridge's
# World: 105.6 degrees, the same at every heading)
README_TURN_DEGREES = 106.0


class DriveAndTurn(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("drive_and_turn_check")
        cls.state = service_proxy("/gazebo/get_model_state", GetModelState)
        cls.world = service_proxy("/gazebo/get_world_properties", GetWorldProperties)
        cls.command = rospy.Publisher("/cmd_vel", Twist, queue_size=1, latch=True)
        cls.odometry = None
        rospy.Subscriber("/odom", Odometry, lambda m: setattr(cls, "odometry", m))
        wait_until(lambda: cls.state("skid_steer_robot", "").success, "the robot to be spawned")
        wait_until(lambda: cls.world().sim_time > 1.0 and cls.odometry is not None, "odometry")

    def truth(self):
        s = self.state("skid_steer_robot", "").pose
        q = s.orientation
        return s.position.x, s.position.y, yaw_from_quaternion((q.x, q.y, q.z, q.w))

    def run_for(self, linear, angular, seconds):
        twist = Twist()
        twist.linear.x, twist.angular.z = linear, angular
        began = self.world().sim_time
        self.command.publish(twist)
        wait_until(lambda: self.world().sim_time > began + seconds, f"{seconds} s of driving")
        self.command.publish(Twist())
        wait_until(lambda: self.world().sim_time > began + seconds + 1.0, "it to stop")

    def test_1_drives_one_metre_forward(self):
        x0, y0, _ = self.truth()
        self.run_for(0.25, 0.0, 4.0)
        x1, y1, _ = self.truth()
        self.assertAlmostEqual(math.hypot(x1 - x0, y1 - y0), 1.0, delta=0.05)

    def test_2_turns_ninety_degrees_in_place(self):
        x0, y0, yaw0 = self.truth()

        def odom_yaw():
            q = self.odometry.pose.pose.orientation
            return yaw_from_quaternion((q.x, q.y, q.z, q.w))

        start = odom_yaw()
        twist = Twist()
        twist.angular.z = 1.0
        self.command.publish(twist)
        wait_until(lambda: math.remainder(odom_yaw() - start, 2 * math.pi) >= math.radians(88),
                   "odometry to show 88 degrees")
        self.command.publish(Twist())
        began = self.world().sim_time
        wait_until(lambda: self.world().sim_time > began + 1.0, "it to stop")
        x1, y1, yaw1 = self.truth()
        turned = math.degrees(math.remainder(yaw1 - yaw0, 2 * math.pi))
        self.assertAlmostEqual(turned, 90.0, delta=5.0)
        self.assertLess(math.hypot(x1 - x0, y1 - y0), 0.1)

    def test_3_turns_slower_than_commanded_as_the_readme_says(self):
        """1.0 rad/s commanded for 3 s: the README's 106 degrees (the wheels slide sideways)."""
        yaw = self.truth()[2]
        turned = 0.0
        twist = Twist()
        twist.angular.z = 1.0
        began = self.world().sim_time
        self.command.publish(twist)
        while self.world().sim_time < began + 3.0:  # summed: more than half a turn
            rospy.sleep(0.05)
            now = self.truth()[2]
            turned += math.remainder(now - yaw, 2 * math.pi)
            yaw = now
        self.command.publish(Twist())
        self.assertAlmostEqual(math.degrees(turned), README_TURN_DEGREES, delta=10.0)


if __name__ == "__main__":
    rostest.rosrun("skid_steer_robot", "drive_and_turn", DriveAndTurn)
