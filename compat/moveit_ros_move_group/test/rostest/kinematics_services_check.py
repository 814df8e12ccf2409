#!/usr/bin/env python3
"""rostest node: compute_fk equals robot_state_publisher's TF at the published joint
states; compute_ik's solution, published, puts the gripper where the target was (TF);
unknown links, groups, unreachable and malformed targets get MoveIt's codes, and the node
answers on."""
import math
import unittest

import numpy as np
import rospy
import rostest
import tf2_ros
from geometry_msgs.msg import PoseStamped
from moveit_msgs.msg import MoveItErrorCodes
from moveit_msgs.srv import GetPositionFK, GetPositionIK, GetPositionIKRequest
from sensor_msgs.msg import JointState

TIMEOUT = 20.0            # s: the longest a service or a transform may take to appear
ARM = ["waist", "shoulder", "elbow", "wrist_angle"]
FINGERS = ["left_finger", "right_finger"]
TIP = "px100/ee_gripper_link"


def wait_until(condition, timeout=TIMEOUT, what="a condition"):
    deadline = rospy.get_time() + timeout
    while not rospy.is_shutdown():
        value = condition()
        if value:
            return value
        if rospy.get_time() > deadline:
            raise AssertionError(f"timed out after {timeout:.0f} s waiting for {what}")
        rospy.sleep(0.02)
    raise AssertionError("shut down")


class KinematicsServices(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("kinematics_services_check")
        cls.states = rospy.Publisher("/joint_states", JointState, queue_size=1, latch=True)
        cls.buffer = tf2_ros.Buffer()
        cls.listener = tf2_ros.TransformListener(cls.buffer)
        for name in ("compute_fk", "compute_ik"):
            rospy.wait_for_service(f"/{name}", timeout=TIMEOUT)
        cls.fk = rospy.ServiceProxy("/compute_fk", GetPositionFK)
        cls.ik = rospy.ServiceProxy("/compute_ik", GetPositionIK)

    def publish(self, arm, fingers=(0.02, 0.02)):
        """Publishes the state until TF shows it; the gripper's true position (TF)."""
        message = JointState(name=ARM + FINGERS, position=list(arm) + list(fingers))

        def shown():
            message.header.stamp = rospy.Time.now()
            self.states.publish(message)
            try:
                transform = self.buffer.lookup_transform("world", TIP, rospy.Time(0))
            except tf2_ros.TransformException:
                return None
            # robot_state_publisher has the state once the wrist's frame matches it
            wrist = self.buffer.lookup_transform("px100/forearm_link", "px100/gripper_link",
                                                 rospy.Time(0)).transform.rotation
            angle = 2 * math.atan2(wrist.y, wrist.w)
            return transform.transform.translation if abs(angle - arm[3]) < 1e-6 else None
        return wait_until(shown, what="TF of the published state")

    def test_fk_equals_tf(self):
        arm = [0.4, -0.3, 0.5, 0.2]
        truth = self.publish(arm)
        request = GetPositionFK._request_class()
        request.header.frame_id = "world"
        request.fk_link_names = [TIP, "px100/forearm_link"]
        request.robot_state.joint_state = JointState(name=ARM, position=arm)
        answer = self.fk(request)
        self.assertEqual(answer.error_code.val, MoveItErrorCodes.SUCCESS)
        position = answer.pose_stamped[0].pose.position
        self.assertLess(np.linalg.norm([position.x - truth.x, position.y - truth.y,
                                        position.z - truth.z]), 1e-6)
        request.fk_link_names = ["px100/no_such_link", TIP]
        answer = self.fk(request)
        self.assertEqual(answer.error_code.val, MoveItErrorCodes.INVALID_LINK_NAME)
        self.assertEqual(answer.fk_link_names, [TIP])

    def test_ik_solution_reaches_the_target_in_truth(self):
        rng = np.random.default_rng(11)
        for _ in range(5):
            arm = [rng.uniform(-1.5, 1.5), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0),
                   rng.uniform(-1.0, 1.0)]
            target = self.publish(arm)
            self.publish([0.0, 0.0, 0.0, 0.0])
            request = GetPositionIKRequest()
            request.ik_request.group_name = "interbotix_arm"
            request.ik_request.pose_stamped = PoseStamped()
            request.ik_request.pose_stamped.header.frame_id = "world"
            request.ik_request.pose_stamped.pose.position = target
            request.ik_request.pose_stamped.pose.orientation.w = 1.0
            answer = self.ik(request)
            self.assertEqual(answer.error_code.val, MoveItErrorCodes.SUCCESS)
            solution = dict(zip(answer.solution.joint_state.name,
                                answer.solution.joint_state.position))
            self.assertEqual(set(solution), set(ARM + FINGERS))
            reached = self.publish([solution[j] for j in ARM])
            error = np.linalg.norm([reached.x - target.x, reached.y - target.y,
                                    reached.z - target.z])
            self.assertLess(error, 1e-3, f"IK for {arm}: {error * 1000:.2f} mm off in TF")

    def test_bad_requests_get_their_codes_and_the_node_answers_on(self):
        request = GetPositionIKRequest()
        request.ik_request.group_name = "interbotix_arm"
        request.ik_request.pose_stamped.header.frame_id = "world"
        request.ik_request.pose_stamped.pose.position.x = 1.0     # beyond the arm's reach
        request.ik_request.pose_stamped.pose.orientation.w = 1.0
        self.assertEqual(self.ik(request).error_code.val, MoveItErrorCodes.NO_IK_SOLUTION)
        request.ik_request.pose_stamped.pose.position.x = float("nan")
        self.assertEqual(self.ik(request).error_code.val,
                         MoveItErrorCodes.INVALID_GOAL_CONSTRAINTS)
        request.ik_request.pose_stamped.pose.position.x = 0.2
        request.ik_request.pose_stamped.header.frame_id = "no_such_frame"
        self.assertEqual(self.ik(request).error_code.val,
                         MoveItErrorCodes.FRAME_TRANSFORM_FAILURE)
        request.ik_request.pose_stamped.header.frame_id = "world"
        request.ik_request.group_name = "arm"
        self.assertEqual(self.ik(request).error_code.val, MoveItErrorCodes.INVALID_GROUP_NAME)
        request.ik_request.group_name = "interbotix_gripper"      # no solver: not a chain
        self.assertEqual(self.ik(request).error_code.val, MoveItErrorCodes.NO_IK_SOLUTION)
        request.ik_request.group_name = "interbotix_arm"
        request.ik_request.pose_stamped.pose.position.z = 0.15
        self.assertEqual(self.ik(request).error_code.val, MoveItErrorCodes.SUCCESS)


if __name__ == "__main__":
    rostest.rosrun("moveit_ros_move_group", "kinematics_services", KinematicsServices)
