#!/usr/bin/env python3
"""rostest node: the mobile manipulator's documented commands, as typed, against the
simulator's truth: the arm reaches its targets and comes home within 0.01 rad; the base
drives 0.3 m/s (± 5%) for as long as its commands last (0.9 m in 3 s) with the arm on it."""
import math
import subprocess
import unittest

import rospy
import rostest
from controller_manager_msgs.srv import ListControllers
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import JointState

from gazebo_msgs.srv import GetModelState, GetWorldProperties
from sim_bridge.testing import service_proxy, wait_until

CMD_VEL_TIMEOUT = 0.5   # s, config/base_control.yaml
JOINTS = ["arm_base_joint", "shoulder_joint", "bottom_wrist_joint", "elbow_joint", "top_wrist_joint"]
MOVE = ("rostopic pub /arm_controller/command trajectory_msgs/JointTrajectory '{joint_names: "
        "[\"arm_base_joint\",\"shoulder_joint\",\"bottom_wrist_joint\",\"elbow_joint\","
        "\"top_wrist_joint\"], points: [{positions: [%s], time_from_start: [1,0]}]}' -1")


class MobileManipulator(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("mobile_manipulator_check")
        cls.joints = None
        rospy.Subscriber("/joint_states", JointState, lambda m: setattr(cls, "joints", m))
        listing = service_proxy("/controller_manager/list_controllers", ListControllers)
        wait_until(lambda: sum(c.state == "running" for c in listing().controller) == 3,
                   "the spawner to start three controllers")
        cls.state = service_proxy("/gazebo/get_model_state", GetModelState)
        cls.world = service_proxy("/gazebo/get_world_properties", GetWorldProperties)

    def arm_at(self, targets):
        if self.joints is None:
            return False
        positions = dict(zip(self.joints.name, self.joints.position))
        return all(abs(positions[j] - t) < 0.01 for j, t in zip(JOINTS, targets))

    def command_arm(self, positions):
        typed = MOVE % ", ".join(str(p) for p in positions)
        result = subprocess.run(typed, shell=True, capture_output=True, text=True, timeout=60)
        self.assertEqual(result.returncode, 0, result.stderr)

    def test_1_arm_moves_and_comes_home(self):
        targets = [-0.1, 0.5, 0.02, 0.0, 0.0]
        self.command_arm(targets)
        wait_until(lambda: self.arm_at(targets), "the arm at the documented pose")
        self.command_arm([0, 0, 0, 0, 0])
        wait_until(lambda: self.arm_at([0.0] * 5), "the arm at home")

    def test_2_base_drives_with_the_arm_on_it(self):
        def position():
            p = self.state("mobile_manipulator", "").pose.position
            return p.x, p.y

        odometry = []
        rospy.Subscriber("/robot_base_velocity_controller/odom", Odometry, odometry.append)
        start = position()
        command = rospy.Publisher("/robot_base_velocity_controller/cmd_vel", Twist, queue_size=1)
        forward = Twist()
        forward.linear.x = 0.3
        sent = []   # simulated times of the commands

        def send(_):
            command.publish(forward)
            sent.append(rospy.get_rostime().to_sec())

        # cmd_vel_timeout is 0.5 s: keep commanding, as a teleop does
        timer = rospy.Timer(rospy.Duration(0.05), send)
        began = self.world().sim_time
        wait_until(lambda: self.world().sim_time > began + 3.0, "3 s of driving")
        timer.shutdown()
        command.publish(Twist())
        stopped_at = rospy.get_rostime().to_sec()
        wait_until(lambda: self.world().sim_time > began + 4.5, "the base to stop")
        travelled = math.dist(start, position())
        # each command drives until the next or for cmd_vel_timeout (0.5 s), whichever comes
        # first: on a busy machine this node may send late while the simulation runs on, and
        # the base rightly stops in the gap (3 s when nothing is late: 0.9 m)
        driven = sum(min(later - earlier, CMD_VEL_TIMEOUT)
                     for earlier, later in zip(sent, sent[1:] + [stopped_at]))
        self.assertGreater(driven, 2.0, f"commands covered only {driven:.2f} s of driving")
        self.assertAlmostEqual(travelled, 0.3 * driven, delta=0.05 * 0.3 * driven)
        # the controller's odometry says so too
        wait_until(lambda: odometry, "odometry on /robot_base_velocity_controller/odom")
        self.assertEqual(odometry[-1].header.frame_id, "odom")
        self.assertAlmostEqual(odometry[-1].pose.pose.position.x, travelled, delta=0.05)


if __name__ == "__main__":
    rostest.rosrun("mobile_manipulator_body", "mobile_manipulator", MobileManipulator)
