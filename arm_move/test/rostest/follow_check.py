#!/usr/bin/env python3
"""rostest node for follow.test (fake backend): the waypoints come from the parameter
server; follow once ends at the last one; follow repeat returns at once and the arm keeps
visiting both until reset, which stops it and brings the arm Home."""
import threading
import unittest

import numpy as np
import rospkg
import rospy
import rostest
from geometry_msgs.msg import Point, Pose, Quaternion
from sensor_msgs.msg import JointState

from arm_move.kinematics import ARM_JOINTS, ArmKinematics
from arm_move.msg import MoveItErrorCodes as Codes
from arm_move.srv import Follow, Reset
from sim_bridge.testing import wait_until

BOX_ON_TABLE = Pose(Point(0.16, -0.17, 0.025), Quaternion(0, 0, 0, 1))


class FollowWaypoints(unittest.TestCase):
    def test_once_then_repeating_until_reset(self):
        rospy.init_node("follow_check")
        kinematics = ArmKinematics.from_file(
            rospkg.RosPack().get_path("arm_move") + "/config/px100.yaml")
        joints, lock = {}, threading.Lock()
        visits = []  # which waypoint the gripper is at, as it changes

        waypoints = rospy.get_param("mover/waypoints")
        self.assertEqual(len(waypoints), 2)

        def on_joint_states(message):
            with lock:
                joints.update(zip(message.name, message.position))
                if all(j in joints for j in ARM_JOINTS):
                    point = kinematics.gripper_point([joints[j] for j in ARM_JOINTS])
                    for index, waypoint in enumerate(waypoints):
                        if np.linalg.norm(point - waypoint[:3]) < 0.002 and \
                                (not visits or visits[-1] != index):
                            visits.append(index)
        rospy.Subscriber("joint_states", JointState, on_joint_states)
        for name in ("reset", "follow"):
            rospy.wait_for_service(name, timeout=60)
        reset = rospy.ServiceProxy("reset", Reset)
        follow = rospy.ServiceProxy("follow", Follow)
        self.assertEqual(reset(BOX_ON_TABLE, False).error_code.val, Codes.SUCCESS)

        once = follow(False)
        self.assertEqual(once.error_code.val, Codes.SUCCESS, once.message)
        with lock:
            self.assertEqual(visits, [0, 1])
            self.assertLess(joints["left_finger"], 0.016)  # closed at the last one

        repeat = follow(True)
        self.assertEqual(repeat.error_code.val, Codes.SUCCESS, repeat.message)
        self.assertIn("until reset", repeat.message)
        wait_until(lambda: len(visits) >= 6, "three more visits of the cycle", timeout=60)
        self.assertEqual(visits[:6], [0, 1, 0, 1, 0, 1])

        stopped = reset(BOX_ON_TABLE, False)
        self.assertEqual(stopped.error_code.val, Codes.SUCCESS, stopped.message)
        with lock:
            arm, count = np.array([joints[j] for j in ARM_JOINTS]), len(visits)
        np.testing.assert_allclose(arm, kinematics.named_poses["home"], atol=1e-3)
        self.assertEqual(len(rospy.get_param("mover/waypoints")), 2)  # reset kept them
        # and nothing moves any more: a step-free mover holds Home
        wait_until(lambda: len(visits) == count, "the cycle to stay stopped")


if __name__ == "__main__":
    rostest.rosrun("arm_move", "follow", FollowWaypoints)
