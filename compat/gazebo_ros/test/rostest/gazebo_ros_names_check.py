#!/usr/bin/env python3
"""rostest node: empty_world.launch's defaults and spawn_model's flags, as course launch files
use them, in ground truth."""
import os
import signal
import subprocess
import sys
import unittest

import rospy
import rostest
from sensor_msgs.msg import JointState

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sim_checks import Simulator, wait_until  # noqa: E402


def spawn_model(*arguments, stdin=None):
    return subprocess.run(["rosrun", "gazebo_ros", "spawn_model", *arguments], input=stdin,
                          capture_output=True, text=True, timeout=90, check=False)


class GazeboRosNames(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("gazebo_ros_names_check")
        cls.sim = Simulator()
        cls.urdf = rospy.get_param("/robot_description")

    def test_1_the_default_world_loads_paused(self):
        properties = self.sim.properties()
        self.assertIn("ground_plane", properties.model_names)  # worlds/empty.world
        self.assertEqual(properties.sim_time, 0.0)

    def test_2_database_model_at_a_pose(self):
        result = spawn_model("-sdf", "-database", "construction_cone", "-model", "cone",
                             "-x", "1.5", "-y", "-0.5")
        self.assertEqual(result.returncode, 0, result.stderr)
        x, y, _ = self.sim.truth("cone")
        self.assertAlmostEqual(x, 1.5, places=3)
        self.assertAlmostEqual(y, -0.5, places=3)

    def test_3_param_relative_to_a_model_with_a_joint_and_unpause(self):
        states = []
        rospy.Subscriber("/joint_states", JointState, states.append)
        result = spawn_model("-urdf", "-param", "robot_description", "-model", "bot",
                             "-reference_frame", "cone", "-x", "1", "-Y", "0.5",
                             "-J", "left_wheel_joint", "0.7", "-unpause")
        self.assertEqual(result.returncode, 0, result.stderr)
        x, y, yaw = self.sim.truth("bot")
        self.assertAlmostEqual(x, 2.5, delta=0.01)
        self.assertAlmostEqual(y, -0.5, delta=0.01)
        self.assertAlmostEqual(yaw, 0.5, delta=0.01)
        start = self.sim.sim_time()
        self.sim.wait_sim_time(start + 0.1)  # -unpause: time runs

    def test_4_file_and_stdin(self):
        path = os.path.join(os.environ.get("ROS_HOME", "/tmp"), "diff_bot.urdf")
        with open(path, "w", encoding="utf-8") as stream:
            stream.write(self.urdf)
        result = spawn_model("-urdf", "-file", path, "-model", "from_file", "-y", "2")
        self.assertEqual(result.returncode, 0, result.stderr)
        result = spawn_model("-urdf", "-stdin", "-model", "from_stdin", "-y", "-2",
                             "-robot_namespace", "/other", stdin=self.urdf)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertAlmostEqual(self.sim.truth("from_stdin")[1], -2.0, delta=0.01)

    def test_5_bad_input_names_the_cause(self):
        result = spawn_model("-urdf", "-file", "/no/such/robot.urdf", "-model", "x")
        self.assertEqual(result.returncode, 1)
        self.assertIn("/no/such/robot.urdf", result.stderr)
        result = spawn_model("-urdf", "-param", "robot_description", "-model", "late",
                             "-wait", "no_such_model", "-timeout", "1")
        self.assertEqual(result.returncode, 1)
        self.assertIn("no_such_model", result.stderr)
        result = spawn_model("-urdf", "-param", "robot_description", "-model", "bot")
        self.assertEqual(result.returncode, 1)  # the name is taken
        self.assertIn("bot", result.stderr)

    def test_6_bond_deletes_the_model_when_spawn_model_stops(self):
        log_path = os.path.join(os.environ.get("ROS_HOME", "/tmp"), "bonded.log")
        with open(log_path, "w", encoding="utf-8") as log:
            bonded = subprocess.Popen(["rosrun", "gazebo_ros", "spawn_model", "-urdf", "-param",
                                       "robot_description", "-model", "bonded", "-x", "-2",
                                       "-b"], stdout=log, stderr=subprocess.STDOUT,
                                      start_new_session=True)

        def said():
            with open(log_path, encoding="utf-8") as stream:
                return stream.read()

        try:
            # Ctrl-C once it has spawned and stays (as a user presses it)
            wait_until(lambda: "Successfully spawned" in said(), "spawn_model to spawn")
            os.killpg(bonded.pid, signal.SIGINT)
            bonded.wait(timeout=30)
        finally:
            if bonded.poll() is None:
                os.killpg(bonded.pid, signal.SIGKILL)
        wait_until(lambda: "bonded" not in self.sim.properties().model_names,
                   f"the bonded model to be deleted (spawn_model said: {said()!r})")


if __name__ == "__main__":
    rostest.rosrun("gazebo_ros", "gazebo_ros_names", GazeboRosNames)
