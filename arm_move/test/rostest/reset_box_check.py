#!/usr/bin/env python3
"""rostest node for reset_box.test (physics): a reset with the box inside the table is
GOAL_IN_COLLISION naming the pose and the table, one reaching below the floor is
INVALID_GOAL_CONSTRAINTS; neither moves the simulated box (its true pose, the simulator's,
is unchanged) nor the arm; a good reset afterwards puts the box where it was asked."""
import math
import unittest

import rospy
import rostest
from geometry_msgs.msg import Point, Pose, Quaternion
from gazebo_msgs.srv import GetModelState

from moveit_msgs.msg import MoveItErrorCodes as Codes

from arm_move.srv import Reset
from sim_bridge.testing import service_proxy, wait_until

BOX = "realsense_box"
IN_THE_TABLE = Pose(Point(0.16, -0.17, -0.1), Quaternion(0, 0, 0, 1))
BELOW_THE_FLOOR = Pose(Point(0.9, 0.0, -0.76), Quaternion(0, 0, 0, 1))
ON_THE_TABLE = Pose(Point(0.15, -0.19, 0.025), Quaternion(0, 0, 0, 1))
# how far a resting box may move while nothing touches it (physics' settling), m
AT_REST = 0.002
# how close a placed box comes to the requested place once it has settled, m
PLACED = 0.005


class ResetBox(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("reset_box_check")
        cls.reset = service_proxy("reset", Reset, timeout=90)
        cls.state = service_proxy("/gazebo/get_model_state", GetModelState)

    def box(self):
        state = self.state(BOX, "")
        self.assertTrue(state.success, state.status_message)
        return state.pose.position

    def assert_box_still(self, before):
        after = self.box()
        self.assertLess(math.dist((after.x, after.y, after.z), (before.x, before.y, before.z)),
                        AT_REST, (before, after))

    def test_1_inside_the_table_is_refused_and_nothing_moves(self):
        before = self.box()
        answer = self.reset(IN_THE_TABLE, False)
        self.assertEqual(answer.error_code.val, Codes.GOAL_IN_COLLISION, answer.message)
        for words in ("position [0.16, -0.17, -0.1]", "inside the table", "not moved"):
            self.assertIn(words, answer.message)
        self.assert_box_still(before)

    def test_2_below_the_floor_is_refused_and_nothing_moves(self):
        before = self.box()
        answer = self.reset(BELOW_THE_FLOOR, False)
        self.assertEqual(answer.error_code.val, Codes.INVALID_GOAL_CONSTRAINTS, answer.message)
        self.assertIn("below the floor", answer.message)
        self.assertIn("position [0.9, 0.0, -0.76]", answer.message)
        self.assert_box_still(before)

    def test_3_a_good_reset_still_places_the_box(self):
        answer = self.reset(ON_THE_TABLE, True)
        self.assertEqual(answer.error_code.val, Codes.SUCCESS, answer.message)
        goal = (ON_THE_TABLE.position.x, ON_THE_TABLE.position.y, ON_THE_TABLE.position.z)
        wait_until(lambda: math.dist(goal, (lambda p: (p.x, p.y, p.z))(self.box())) < PLACED,
                   f"the simulated box within {PLACED} m of {goal}")


if __name__ == "__main__":
    rostest.rosrun("arm_move", "reset_box", ResetBox)
