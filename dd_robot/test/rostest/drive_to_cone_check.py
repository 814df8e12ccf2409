#!/usr/bin/env python3
"""rostest node: dd_robot7 drives 1 m towards the cone, in the simulator's truth (± 5%)."""
import math
import unittest

import rospy
import rostest
from geometry_msgs.msg import Twist

from gazebo_msgs.srv import GetModelState, GetWorldProperties
from sim_bridge.testing import service_proxy, wait_until

CONE = (-3.0, 0.0)


class DriveToCone(unittest.TestCase):
    def test_drives_one_metre_towards_the_cone(self):
        rospy.init_node("drive_to_cone_check")
        state = service_proxy("/gazebo/get_model_state", GetModelState)
        clock = service_proxy("/gazebo/get_world_properties", GetWorldProperties)
        wait_until(lambda: state("dd_robot", "").success, "dd_robot to be spawned")
        wait_until(lambda: clock().sim_time > 1.0, "it to settle")

        def position():
            p = state("dd_robot", "").pose.position
            return p.x, p.y

        start = position()
        command = rospy.Publisher("/cmd_vel", Twist, queue_size=1, latch=True)
        towards = Twist()
        towards.linear.x = -0.25  # the cone is behind it, on -x
        began = clock().sim_time
        command.publish(towards)
        wait_until(lambda: clock().sim_time > began + 4.0, "4 s of driving")
        command.publish(Twist())
        wait_until(lambda: clock().sim_time > began + 5.0, "it to stop")
        end = position()
        travelled = math.dist(start, end)
        closer = math.dist(start, CONE) - math.dist(end, CONE)
        self.assertAlmostEqual(travelled, 1.0, delta=0.05)
        self.assertAlmostEqual(closer, travelled, delta=0.02)  # straight at it


if __name__ == "__main__":
    rostest.rosrun("dd_robot", "drive_to_cone", DriveToCone)
