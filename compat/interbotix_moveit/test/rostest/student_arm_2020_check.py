#!/usr/bin/env python3
"""rostest node: a 2020 student's mover on moveit_commander against interbotix_moveit.launch
robot_name:=px100 use_fake:=true (dof left at 5): position and pose targets planned and
executed, the gripper point (robot_description's chain on the fake controllers' joint
states) where the targets put it, with the 2020 config's position-only IK; a pose whose
orientation the arm cannot take refused, as MoveIt refuses it."""
import sys
import unittest

import moveit_commander
import numpy as np
import rospy
import rostest
from geometry_msgs.msg import Pose
from sensor_msgs.msg import JointState
from tf import transformations

from urdf_tools.kinematics import link_transform
from urdf_tools.model import parse_urdf

ARM = ["waist", "shoulder", "elbow", "wrist_angle"]
TOLERANCE = 0.001     # m


class StudentMover2020(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        moveit_commander.roscpp_initialize(sys.argv)
        rospy.init_node("student_arm_2020_check")
        cls.arm = moveit_commander.MoveGroupCommander(
            "interbotix_arm", robot_description="px100/robot_description", ns="px100",
            wait_for_servers=60.0)
        cls.model = parse_urdf(rospy.get_param("/px100/robot_description"))

    def gripper(self):
        message = rospy.wait_for_message("/px100/joint_states", JointState, timeout=5.0)
        joints = {n: p for n, p in zip(message.name, message.position) if n in ARM}
        return link_transform(self.model, "px100/base_link", "px100/ee_gripper_link", joints)

    def test_the_2020_kinematics_are_loaded(self):
        solver = rospy.get_param("/px100/robot_description_kinematics/interbotix_arm")
        self.assertEqual(solver["kinematics_solver"],
                         "trac_ik_kinematics_plugin/TRAC_IKKinematicsPlugin")
        self.assertTrue(solver["position_only_ik"])

    def reached(self, target):
        self.assertTrue(self.arm.go(wait=True), target)
        self.arm.clear_pose_targets()
        reached = self.gripper()[:3, 3]
        self.assertLess(np.linalg.norm(reached - target), TOLERANCE, reached)

    def test_a_position_target_is_planned_executed_and_reached(self):
        self.arm.set_position_target([0.2, 0.05, 0.12])
        self.reached([0.2, 0.05, 0.12])

    def test_a_pose_target_with_its_orientation_left_free_is_reached(self):
        """The 2020 config's way to a pose on a 4-joint arm: position-only IK, the goal's
        orientation tolerance opened (set_goal_orientation_tolerance)."""
        self.arm.set_goal_orientation_tolerance(np.pi)
        try:
            self.arm.set_pose_target(self.pose([0.15, -0.08, 0.1], (0.7, 0.2, 1.2)))
            self.reached([0.15, -0.08, 0.1])
        finally:
            self.arm.set_goal_orientation_tolerance(0.001)

    def test_an_orientation_the_arm_cannot_take_is_refused_and_nothing_moves(self):
        """Position-only IK solves the position, and MoveIt's IK sampler then checks the
        goal's orientation constraint too (moveit_core/constraint_samplers/src/
        default_constraint_samplers.cpp l. 630-637, noetic-devel), so a gripper rolled and
        yawed off its heading, which no px100 state gives, is not planned for."""
        before = self.gripper()
        self.arm.set_pose_target(self.pose([0.15, -0.08, 0.1], (0.7, 0.2, 1.2)))
        self.assertFalse(self.arm.go(wait=True))
        self.arm.clear_pose_targets()
        np.testing.assert_allclose(self.gripper(), before, atol=1e-9)

    @staticmethod
    def pose(position, rpy):
        pose = Pose()
        pose.position.x, pose.position.y, pose.position.z = position
        q = transformations.quaternion_from_euler(*rpy)
        pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w = q
        return pose

if __name__ == "__main__":
    rostest.rosrun("interbotix_moveit", "student_arm_2020", StudentMover2020)
