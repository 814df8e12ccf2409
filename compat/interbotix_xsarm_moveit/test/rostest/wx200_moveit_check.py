#!/usr/bin/env python3
"""rostest node: a student-style moveit_commander script on the wx200: the named states
Home, Upright and Sleep, and a pose target (the pose of a joint state the arm can take),
each reached by the gripper point within 1 cm and the pose's orientation within 0.05 rad,
measured by robot_description's own chain (urdf_tools) on the joint states the robot
reports: the fake controllers', or the simulator's joint_state_controller's (its joints'
true positions)."""
import sys
import unittest

import moveit_commander
import numpy as np
import rospy
import rostest
from controller_manager_msgs.srv import ListControllers
from sensor_msgs.msg import JointState
from std_srvs.srv import Empty
from tf import transformations

from sim_bridge.testing import wait_until
from urdf_tools.kinematics import link_transform
from urdf_tools.model import parse_urdf

ARM = ["waist", "shoulder", "elbow", "wrist_angle", "wrist_rotate"]
BASE, TIP = "wx200/base_link", "wx200/ee_gripper_link"
POSITION_TOLERANCE = 0.01      # m: the 1 cm
ORIENTATION_TOLERANCE = 0.05   # rad
STARTUP = 90.0                 # s (wall)


class Wx200UnderMoveIt(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        moveit_commander.roscpp_initialize(sys.argv)
        rospy.init_node("wx200_moveit_check")
        if rospy.get_param("~simulated"):
            # the world starts paused; played once the arm's controllers run, as Interbotix's
            # README has the user press play when everything has come up
            wait_until(cls.controllers_running, "the arm's controllers", timeout=STARTUP)
            rospy.ServiceProxy("/gazebo/unpause_physics", Empty)()
        cls.arm = moveit_commander.MoveGroupCommander(
            "interbotix_arm", robot_description="wx200/robot_description", ns="wx200",
            wait_for_servers=STARTUP)
        cls.model = parse_urdf(rospy.get_param("/wx200/robot_description"))

    @staticmethod
    def controllers_running():
        try:
            rospy.wait_for_service("/wx200/controller_manager/list_controllers", timeout=1.0)
            listed = rospy.ServiceProxy("/wx200/controller_manager/list_controllers",
                                        ListControllers)().controller
        except (rospy.ROSException, rospy.ServiceException):
            return False
        return {"arm_controller", "gripper_controller"} <= {c.name for c in listed
                                                            if c.state == "running"}

    def reported(self):
        """The gripper's pose by the joints the robot reports, once they are still."""
        last = None
        for _ in range(100):
            message = rospy.wait_for_message("/wx200/joint_states", JointState, timeout=10.0)
            now = np.array([dict(zip(message.name, message.position))[n] for n in ARM])
            if last is not None and np.max(np.abs(now - last)) < 1e-3:
                break
            last = now
            rospy.sleep(0.1)
        return link_transform(self.model, BASE, TIP, dict(zip(ARM, now)))

    def move(self, what):
        """Plans to the target set, then executes (what arm.go does), saying which failed."""
        planned, plan, _, error = self.arm.plan()
        self.assertTrue(planned, f"{what}: planning failed with MoveIt code {error.val}")
        self.assertTrue(self.arm.execute(plan, wait=True), f"{what}: execution failed")

    def assert_pose(self, expected, what):
        reached = self.reported()
        error = np.linalg.norm(reached[:3, 3] - expected[:3, 3])
        self.assertLess(error, POSITION_TOLERANCE, f"{what}: {1000 * error:.1f} mm away")
        turn = transformations.rotation_from_matrix(
            _homogeneous(expected[:3, :3].T @ reached[:3, :3]))[0]
        self.assertLess(abs(turn), ORIENTATION_TOLERANCE, f"{what}: turned {turn:.3f} rad")

    def test_named_states(self):
        for name in ("Upright", "Sleep", "Home"):
            self.arm.set_named_target(name)
            self.move(name)
            values = self.arm.get_named_target_values(name)
            self.assert_pose(link_transform(self.model, BASE, TIP, values), name)

    def test_a_pose_target(self):
        joints = dict(zip(ARM, [0.4, 0.2, -0.3, 0.5, 0.6]))
        target = link_transform(self.model, BASE, TIP, joints)
        self.arm.set_pose_reference_frame(BASE)
        self.arm.set_pose_target(list(target[:3, 3]) +
                                 list(transformations.euler_from_matrix(target, "sxyz")))
        self.move("the pose target")
        self.arm.clear_pose_targets()
        self.assert_pose(target, "the pose target")


def _homogeneous(rotation):
    matrix = np.identity(4)
    matrix[:3, :3] = rotation
    return matrix


if __name__ == "__main__":
    rostest.rosrun("interbotix_xsarm_moveit", "wx200_moveit", Wx200UnderMoveIt)
