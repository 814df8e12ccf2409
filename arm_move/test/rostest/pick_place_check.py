#!/usr/bin/env python3
"""rostest node for pick_place.test: reset moves the simulated RealSense box where it is
asked; after one follow of config/waypoints.yaml on the physics simulation, the block's
true position (the simulator's) is within 3 cm of the drop-off place, and it was lifted
on the way (it did not slide there)."""
import math
import threading
import unittest

import rospy
import rostest

from arm_move.msg import MoveItErrorCodes as Codes
from arm_move.srv import Follow, Reset
from geometry_msgs.msg import Point, Pose, Quaternion
from gazebo_msgs.msg import ModelStates
from sim_bridge.poses import yaw_from_quaternion
from gazebo_msgs.srv import GetModelState

TABLE_HEIGHT = 0.75
DROP_OFF = (0.17, -0.02)       # in px100/base_link, as the last waypoints of the yaml
# the box a little further right than the world puts it, turned 0.4 rad
BOX_YAW = 0.4
BOX_ON_TABLE = Pose(Point(0.15, -0.19, 0.025),
                    Quaternion(0, 0, math.sin(BOX_YAW / 2), math.cos(BOX_YAW / 2)))


class PickAndPlace(unittest.TestCase):
    def test_the_block_ends_at_the_drop_off_place(self):
        rospy.init_node("pick_place_check")
        heights, lock = [], threading.Lock()

        def on_states(states):
            if "pick_object" in states.name:
                with lock:
                    heights.append(states.pose[states.name.index("pick_object")].position)
        rospy.Subscriber("/gazebo/model_states", ModelStates, on_states, queue_size=10)
        for name in ("reset", "follow"):
            rospy.wait_for_service(name, timeout=90)
        waypoints = rospy.get_param("mover/waypoints")
        self.assertEqual(waypoints[-2][:2], list(DROP_OFF))
        answer = rospy.ServiceProxy("reset", Reset)(BOX_ON_TABLE, False)
        self.assertEqual(answer.error_code.val, Codes.SUCCESS, answer.message)
        box = rospy.ServiceProxy("/gazebo/get_model_state", GetModelState)("realsense_box", "")
        self.assertAlmostEqual(box.pose.position.x, BOX_ON_TABLE.position.x, delta=0.005)
        self.assertAlmostEqual(box.pose.position.y, BOX_ON_TABLE.position.y, delta=0.005)
        q = box.pose.orientation
        self.assertAlmostEqual(yaw_from_quaternion((q.x, q.y, q.z, q.w)), BOX_YAW, delta=0.02)
        answer = rospy.ServiceProxy("follow", Follow)(False)
        self.assertEqual(answer.error_code.val, Codes.SUCCESS, answer.message)
        with lock:
            final, highest = heights[-1], max(p.z for p in heights)
        distance = ((final.x - DROP_OFF[0]) ** 2 + (final.y - DROP_OFF[1]) ** 2) ** 0.5
        rospy.loginfo("pick_place_check: block at (%.3f, %.3f, %.3f), %.3f m from the drop-off "
                      "place; lifted %.3f m", final.x, final.y, final.z, distance,
                      highest - (TABLE_HEIGHT + 0.02))
        self.assertLess(distance, 0.03)
        self.assertAlmostEqual(final.z, TABLE_HEIGHT + 0.02, delta=0.005)  # on the table
        self.assertGreater(highest, TABLE_HEIGHT + 0.02 + 0.03)  # carried, not pushed


if __name__ == "__main__":
    rostest.rosrun("arm_move", "pick_place", PickAndPlace)
