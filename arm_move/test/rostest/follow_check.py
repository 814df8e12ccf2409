#!/usr/bin/env python3
"""rostest node for follow.test (fake MoveIt): the waypoints come from the parameter
server; follow once ends at the last one; follow repeat returns at once and the arm keeps
visiting both until reset, which stops it and brings the arm Home."""
import threading
import unittest

import numpy as np
import rospy
import rostest
from geometry_msgs.msg import Point, Pose, Quaternion
from moveit_msgs.msg import MoveItErrorCodes as Codes

from arm_move.srv import Follow, Reset
from arm_truth import ARM_JOINTS, BASE, CLOSED, HOME, TIP, ArmTruth
from sim_bridge.testing import wait_until

BOX_ON_TABLE = Pose(Point(0.16, -0.17, 0.025), Quaternion(0, 0, 0, 1))


class FollowWaypoints(unittest.TestCase):
    def test_once_then_repeating_until_reset(self):
        rospy.init_node("follow_check")
        truth = ArmTruth()
        lock = threading.Lock()
        visits = []  # which waypoint the gripper is at (TF), as it changes

        waypoints = rospy.get_param("mover/waypoints")
        self.assertEqual(len(waypoints), 2)

        def look(_):
            try:
                t = truth.buffer.lookup_transform(BASE, TIP, rospy.Time(0)).transform.translation
            except Exception:  # pylint: disable=broad-except  (no TF yet)
                return
            point = np.array([t.x, t.y, t.z])
            with lock:
                for index, waypoint in enumerate(waypoints):
                    if np.linalg.norm(point - waypoint[:3]) < 0.002 and \
                            (not visits or visits[-1] != index):
                        visits.append(index)
        rospy.Timer(rospy.Duration(0.01), look)
        for name in ("reset", "follow"):
            rospy.wait_for_service(name, timeout=60)
        reset = rospy.ServiceProxy("reset", Reset)
        follow = rospy.ServiceProxy("follow", Follow)
        self.assertEqual(reset(BOX_ON_TABLE, False).error_code.val, Codes.SUCCESS)

        once = follow(False)
        self.assertEqual(once.error_code.val, Codes.SUCCESS, once.message)
        with lock:
            self.assertEqual(visits, [0, 1])
            self.assertAlmostEqual(truth.joints["left_finger"], CLOSED, delta=1e-3)

        repeat = follow(True)
        self.assertEqual(repeat.error_code.val, Codes.SUCCESS, repeat.message)
        self.assertIn("until reset", repeat.message)
        wait_until(lambda: len(visits) >= 6, "three more visits of the cycle", timeout=60)
        self.assertEqual(visits[:6], [0, 1, 0, 1, 0, 1])

        stopped = reset(BOX_ON_TABLE, False)
        self.assertEqual(stopped.error_code.val, Codes.SUCCESS, stopped.message)
        arm = truth.arm()[:len(ARM_JOINTS)]
        with lock:
            count = len(visits)
        np.testing.assert_allclose(arm, HOME, atol=1e-3)
        self.assertEqual(len(rospy.get_param("mover/waypoints")), 2)  # reset kept them
        # and nothing moves any more: a step-free mover holds Home
        wait_until(lambda: len(visits) == count, "the cycle to stay stopped")


if __name__ == "__main__":
    rostest.rosrun("arm_move", "follow", FollowWaypoints)
