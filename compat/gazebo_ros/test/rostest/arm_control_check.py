#!/usr/bin/env python3
"""rostest node: a JointTrajectoryController arm reaches commanded positions within
0.01 rad, through the action and through the command topic; /joint_states has every
transmission joint, the prismatic finger included."""
import os
import sys
import unittest

import actionlib
import rospy
import rostest
from control_msgs.msg import FollowJointTrajectoryAction, FollowJointTrajectoryGoal
from control_msgs.msg import FollowJointTrajectoryResult
from controller_manager_msgs.srv import ListControllers
from sensor_msgs.msg import JointState
from std_msgs.msg import Float64
from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sim_checks import TIMEOUT, Simulator, wait_until  # noqa: E402


def trajectory(positions, seconds):
    return JointTrajectory(joint_names=["pan", "lift"], points=[JointTrajectoryPoint(
        positions=positions, time_from_start=rospy.Duration(seconds))])


class ArmControl(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("arm_control_check")
        cls.sim = Simulator()
        cls.sim.wait_for_model("arm_bot")
        cls.joints = None
        rospy.Subscriber("/arm_bot/joint_states", JointState,
                         lambda m: setattr(cls, "joints", m), queue_size=1)
        rospy.wait_for_service("/arm_bot/controller_manager/list_controllers", timeout=TIMEOUT)
        lister = rospy.ServiceProxy("/arm_bot/controller_manager/list_controllers",
                                    ListControllers)
        wait_until(lambda: sum(c.state == "running" for c in lister().controller) == 3,
                   "the spawner to start three controllers")
        cls.client = actionlib.SimpleActionClient("/arm_bot/arm_controller/follow_joint_trajectory",
                                                  FollowJointTrajectoryAction)
        assert cls.client.wait_for_server(rospy.Duration(TIMEOUT))

    def position(self, joint):
        self.sim.wait_sim_time(self.sim.sim_time() + 0.1)  # a fresh joint_states message
        return self.joints.position[self.joints.name.index(joint)]

    def test_0_spawned_with_the_given_joint_positions_and_holding_them(self):
        self.sim.wait_sim_time(self.sim.sim_time() + 0.5)
        self.assertAlmostEqual(self.position("pan"), -0.2, delta=0.01)
        self.assertAlmostEqual(self.position("lift"), 0.3, delta=0.01)

    def test_1_action_goal_is_reached(self):
        self.client.send_goal(FollowJointTrajectoryGoal(trajectory=trajectory([1.2, -0.6], 2.0)))
        self.assertTrue(self.client.wait_for_result(rospy.Duration(TIMEOUT)))
        result = self.client.get_result()
        self.assertEqual(result.error_code, FollowJointTrajectoryResult.SUCCESSFUL,
                         result.error_string)
        self.assertAlmostEqual(self.position("pan"), 1.2, delta=0.01)
        self.assertAlmostEqual(self.position("lift"), -0.6, delta=0.01)

    def test_2_command_topic(self):
        publisher = rospy.Publisher("/arm_bot/arm_controller/command", JointTrajectory,
                                    queue_size=1, latch=True)
        publisher.publish(trajectory([-0.4, 0.3], 1.0))
        wait_until(lambda: abs(self.position("pan") + 0.4) < 0.01 and
                   abs(self.position("lift") - 0.3) < 0.01, "the arm at (-0.4, 0.3)")

    def test_3_prismatic_finger_in_joint_states(self):
        publisher = rospy.Publisher("/arm_bot/finger_controller/command", Float64, queue_size=1,
                                    latch=True)
        publisher.publish(Float64(0.025))
        wait_until(lambda: abs(self.position("finger_joint") - 0.025) < 0.001,
                   "the finger at 0.025 m")
        # in name order, as Noetic's joint_state_controller walks the hardware's std::map
        # (ros_controllers noetic-devel 678b92a joint_state_controller.cpp:56)
        self.assertEqual(self.joints.name, ["finger_joint", "lift", "pan"])


if __name__ == "__main__":
    rostest.rosrun("gazebo_ros", "arm_control", ArmControl)
