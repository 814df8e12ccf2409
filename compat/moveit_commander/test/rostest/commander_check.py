#!/usr/bin/env python3
"""rostest node: moveit_commander as MoveIt's Python tutorial and students' movers use it,
against move_group on fake controllers. Named, joint and position targets reached in
truth (robot_state_publisher's TF and /joint_states); plan() returns Noetic's 4-tuple; a
target in a box fails with its code; PlanningSceneInterface adds, lists, attaches and
removes synchronously; an old-style compute_cartesian_path call (jump_threshold third)
follows the line; bad requests raise MoveItCommanderException."""
import sys
import unittest

import moveit_commander
import numpy as np
import rospy
import rostest
import tf2_ros
from geometry_msgs.msg import PoseStamped
from moveit_msgs.msg import MoveItErrorCodes, RobotTrajectory

ARM = ["waist", "shoulder", "elbow", "wrist_angle"]
TIP = "px100/ee_gripper_link"
TIMEOUT = 20.0


class Commander(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        moveit_commander.roscpp_initialize(sys.argv)
        rospy.init_node("commander_check", anonymous=True)
        cls.buffer = tf2_ros.Buffer()
        cls.listener = tf2_ros.TransformListener(cls.buffer)
        cls.robot = moveit_commander.RobotCommander()
        cls.scene = moveit_commander.PlanningSceneInterface(synchronous=True)
        cls.arm = moveit_commander.MoveGroupCommander("interbotix_arm", wait_for_servers=TIMEOUT)
        cls.arm.set_max_velocity_scaling_factor(1.0)
        cls.arm.set_max_acceleration_scaling_factor(1.0)

    def gripper_in_truth(self, timeout=5.0):
        """The gripper's position in TF once /joint_states have settled."""
        deadline = rospy.get_time() + timeout
        last = None
        while rospy.get_time() < deadline:
            t = self.buffer.lookup_transform("world", TIP, rospy.Time(0),
                                             rospy.Duration(1.0)).transform.translation
            here = np.array([t.x, t.y, t.z])
            if last is not None and np.linalg.norm(here - last) < 1e-6:
                return here
            last = here
            rospy.sleep(0.1)
        return last

    def test_1_the_robot_and_its_groups(self):
        self.assertEqual(sorted(self.robot.get_group_names()),
                         ["interbotix_arm", "interbotix_gripper"])
        self.assertEqual(self.robot.get_planning_frame(), "world")
        self.assertEqual(self.arm.get_end_effector_link(), TIP)
        self.assertEqual(self.arm.get_active_joints(), ARM)
        self.assertEqual(self.arm.get_named_targets(), ["Home", "Sleep"])
        self.assertEqual(self.robot.get_joint("elbow").bounds()[1], self.robot.elbow.max_bound())

    def test_2_named_and_joint_targets_reached(self):
        self.arm.set_named_target("Sleep")
        self.assertTrue(self.arm.go(wait=True))
        np.testing.assert_allclose(self.arm.get_current_joint_values(),
                                   [0.0, -1.88, 1.5, 0.8], atol=0.01)
        target = [0.3, -0.2, 0.3, 0.1]
        success, trajectory, seconds, code = self.arm.plan(target)
        self.assertTrue(success)
        self.assertIsInstance(trajectory, RobotTrajectory)
        self.assertEqual(code.val, MoveItErrorCodes.SUCCESS)
        self.assertGreater(seconds, 0.0)
        self.assertTrue(self.arm.execute(trajectory, wait=True))
        np.testing.assert_allclose(self.arm.get_current_joint_values(), target, atol=0.01)

    def test_3_a_position_target_reached_in_truth(self):
        goal = [0.16, -0.08, 0.1]
        self.arm.set_position_target(goal)
        self.assertTrue(self.arm.go(wait=True))
        self.arm.stop()
        self.arm.clear_pose_targets()
        reached = self.gripper_in_truth()
        self.assertLess(np.linalg.norm(reached - goal), 0.001, reached)
        pose = self.arm.get_current_pose().pose.position
        self.assertLess(np.linalg.norm(np.array([pose.x, pose.y, pose.z]) - reached), 1e-4)

    def test_4_the_scene_and_a_target_inside_a_box(self):
        box = PoseStamped()
        box.header.frame_id = "world"
        box.pose.position.x, box.pose.position.z = 0.18, 0.05
        box.pose.orientation.w = 1.0
        self.scene.add_box("crate", box, size=(0.06, 0.06, 0.06))
        self.assertIn("crate", self.scene.get_known_object_names())
        self.assertEqual(list(self.scene.get_objects(["crate"])), ["crate"])
        self.arm.set_position_target([0.18, 0.0, 0.05])
        success, _, _, code = self.arm.plan()
        self.arm.clear_pose_targets()
        self.assertFalse(success)
        self.assertEqual(code.val, MoveItErrorCodes.PLANNING_FAILED)  # as MoveIt answers it
        self.scene.attach_box(TIP, "tool", PoseStamped(header=box.header), size=(0.01, 0.01, 0.01),
                              touch_links=["px100/left_finger_link", "px100/right_finger_link",
                                           "px100/gripper_bar_link", "px100/gripper_link"])
        self.assertIn("tool", self.scene.get_attached_objects())
        self.scene.remove_attached_object(TIP, "tool")
        self.scene.remove_world_object("tool")
        self.scene.remove_world_object("crate")
        self.assertEqual(self.scene.get_known_object_names(), [])

    def test_5_an_old_style_cartesian_path(self):
        self.arm.set_named_target("Home")
        self.assertTrue(self.arm.go(wait=True))
        start = self.arm.get_current_pose().pose
        end = self.arm.get_current_pose().pose
        end.position.z -= 0.05
        plan, fraction = self.arm.compute_cartesian_path([end], 0.01, 0.0)
        self.assertAlmostEqual(fraction, 1.0)
        self.assertTrue(self.arm.execute(plan, wait=True))
        reached = self.gripper_in_truth()
        self.assertLess(np.linalg.norm(reached - [start.position.x, start.position.y,
                                                  start.position.z - 0.05]), 0.001)

    def test_6_bad_requests_raise(self):
        with self.assertRaises(moveit_commander.MoveItCommanderException):
            self.arm.set_named_target("Rest")
        with self.assertRaises(moveit_commander.MoveItCommanderException):
            self.arm.set_joint_value_target([0.0, 3.0, 0.0, 0.0])
        with self.assertRaises(moveit_commander.MoveItCommanderException):
            self.arm.set_max_velocity_scaling_factor(1.5)
        with self.assertRaises(RuntimeError):
            moveit_commander.MoveGroupCommander("arm")


if __name__ == "__main__":
    rostest.rosrun("moveit_commander", "commander", Commander)
