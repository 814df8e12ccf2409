#!/usr/bin/env python3
"""rostest node: what a homework-3 script does with Interbotix's Python API
(``InterbotixManipulatorXS("px100", "arm", "gripper")``: home, poses by components, a single
joint, a Cartesian move, the gripper, sleep) on the driver that xsarm_control.launch starts,
each result checked on the driver's joint states through robot_description's own chain
(urdf_tools, not Modern Robotics: the module solves with that), and bad requests refused
with the driver running on."""
import math
import subprocess
import time
import unittest

import numpy as np
import rospkg
import rospy
import rostest
from interbotix_xs_msgs.msg import JointGroupCommand
from interbotix_xs_msgs.srv import RobotInfo
from sensor_msgs.msg import JointState
from tf import transformations

from interbotix_xs_modules.arm import InterbotixManipulatorXS
from urdf_tools.kinematics import link_transform
from urdf_tools.model import parse_urdf

ARM = ["waist", "shoulder", "elbow", "wrist_angle"]
MOVING_TIME = 1.0     # s a move (the module's default is 2)
POSITION_TOLERANCE = 0.01   # m: the 1 cm
SLEEP = [0, -1.88, 1.5, 0.8]


class XsModulesOnTheDriver(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("xs_modules_check")
        cls.bot = InterbotixManipulatorXS("px100", "arm", "gripper", moving_time=MOVING_TIME,
                                          init_node=False)
        cls.model = parse_urdf(rospy.get_param("/px100/robot_description"))

    def states(self):
        """The driver's next joint states (name -> position), published after now."""
        message = rospy.wait_for_message("/px100/joint_states", JointState, timeout=5.0)
        return dict(zip(message.name, message.position))

    def gripper_pose(self):
        return link_transform(self.model, "px100/base_link", "px100/ee_gripper_link",
                              {n: v for n, v in self.states().items() if n in ARM})

    def assert_arm_at(self, expected, tolerance=1e-4):
        states = self.states()
        np.testing.assert_allclose([states[n] for n in ARM], expected, atol=tolerance)

    def test_1_home_then_a_pose_by_components(self):
        self.bot.arm.go_to_home_pose()
        self.assert_arm_at([0, 0, 0, 0])
        _, found = self.bot.arm.set_ee_pose_components(x=0.2, z=0.15)
        self.assertTrue(found)
        pose = self.gripper_pose()
        self.assertLess(np.linalg.norm(pose[:3, 3] - [0.2, 0.0, 0.15]), POSITION_TOLERANCE)
        # a pose off the x axis, tilted down: the 4-joint arm faces it (yaw = atan2(y, x))
        _, found = self.bot.arm.set_ee_pose_components(x=0.15, y=0.1, z=0.1, pitch=0.5)
        self.assertTrue(found)
        pose = self.gripper_pose()
        self.assertLess(np.linalg.norm(pose[:3, 3] - [0.15, 0.1, 0.1]), POSITION_TOLERANCE)
        roll, pitch, yaw = transformations.euler_from_matrix(pose, "sxyz")
        self.assertAlmostEqual(pitch, 0.5, delta=0.01)
        self.assertAlmostEqual(yaw, math.atan2(0.1, 0.15), delta=0.01)
        self.assertAlmostEqual(roll, 0.0, delta=0.01)

    def test_2_an_unreachable_pose_is_refused_and_nothing_moves(self):
        before = self.states()
        _, found = self.bot.arm.set_ee_pose_components(x=1.0, z=0.1)
        self.assertFalse(found)
        self.assert_arm_at([before[n] for n in ARM])

    def test_3_a_single_joint_and_a_cartesian_move(self):
        self.bot.arm.go_to_home_pose()
        self.assertTrue(self.bot.arm.set_single_joint_position("waist", 0.6))
        self.assertAlmostEqual(self.states()["waist"], 0.6, delta=1e-4)
        start = self.gripper_pose()[:3, 3]
        self.assertTrue(self.bot.arm.set_ee_cartesian_trajectory(z=-0.05))
        end = self.gripper_pose()[:3, 3]
        self.assertLess(np.linalg.norm(end - (start + [0, 0, -0.05])), 0.005)
        # beyond its limits the joint is refused
        self.assertFalse(self.bot.arm.set_single_joint_position("elbow", 3.0))

    def test_4_the_gripper_opens_and_closes_to_its_fingers_limits(self):
        upper = self.model.joints["left_finger"].limit.upper
        lower = self.model.joints["left_finger"].limit.lower
        self.bot.gripper.open()
        self.assertGreaterEqual(self.states()["left_finger"], upper - 1e-3)
        self.bot.gripper.close()
        self.assertLessEqual(self.states()["left_finger"], lower + 1e-3)
        self.assertAlmostEqual(self.states()["right_finger"], -self.states()["left_finger"])

    def test_5_sleep_pose(self):
        self.bot.arm.go_to_sleep_pose()
        self.assert_arm_at(SLEEP)

    def test_6_bad_requests_are_refused_and_the_driver_runs_on(self):
        before = self.states()
        publisher = rospy.Publisher("/px100/commands/joint_group", JointGroupCommand,
                                    queue_size=1, latch=True)
        publisher.publish(JointGroupCommand("arm", [0.3, 0.3]))
        publisher.publish(JointGroupCommand("arm", [float("nan")] * 4))
        info = rospy.ServiceProxy("/px100/get_robot_info", RobotInfo)
        with self.assertRaises(rospy.ServiceException) as refused:
            info("group", "legs")
        self.assertIn("The 'legs' joint/group does not exist", str(refused.exception))
        deadline = time.monotonic() + 1.0
        while time.monotonic() < deadline:     # a second of states: nothing moved
            states = self.states()
            self.assertEqual([states[n] for n in ARM], [before[n] for n in ARM])
        self.assertEqual(info("group", "arm").num_joints, 4)

    def test_7_a_driver_that_cannot_start_says_why_and_ends(self):
        """In a namespace of their own: the real arm's driver, and the simulated driver told
        to drive a simulator that is not there."""
        config = rospkg.RosPack().get_path("interbotix_xsarm_control") + "/config/px100.yaml"
        runs = {
            "real": ["rosrun", "interbotix_xs_sdk", "xs_sdk", "__ns:=/real_arm"],
            "no simulator": ["rosrun", "interbotix_xs_sdk", "xs_sdk_sim", "__ns:=/no_sim",
                             f"_motor_configs:={config}", "_simulator:=true",
                             "_simulator_timeout:=1"]}
        said = {}
        for name, command in runs.items():
            run = subprocess.run(command, capture_output=True, text=True, timeout=60,
                                 check=False)
            self.assertEqual(run.returncode, 1, run.stdout + run.stderr)
            said[name] = run.stdout + run.stderr
        self.assertIn("the driver for the real arm (Dynamixel servos on /dev/ttyDXL) is not in "
                      "this workspace", said["real"])
        self.assertIn("waist_controller", said["no simulator"])
        self.assertIn("use_position_controllers:=true", said["no simulator"])
        # the driver under test is untouched
        self.assertEqual(rospy.ServiceProxy("/px100/get_robot_info", RobotInfo)(
            "group", "arm").num_joints, 4)


if __name__ == "__main__":
    rostest.rosrun("interbotix_xsarm_control", "xs_modules_fake_joints", XsModulesOnTheDriver)
