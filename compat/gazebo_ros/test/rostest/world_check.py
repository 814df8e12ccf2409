#!/usr/bin/env python3
"""rostest node: /clock, pause, reset, model state services, the world's lights, and bad
requests answered with their cause while the simulator keeps running."""
import math
import os
import sys
import unittest

import rospy
import rostest
from geometry_msgs.msg import Pose, Twist, Vector3
from rosgraph_msgs.msg import Clock, Log
from std_msgs.msg import ColorRGBA
from std_srvs.srv import Empty

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sim_checks import Simulator, wait_until  # noqa: E402

from gazebo_msgs.msg import ModelState, ModelStates  # noqa: E402
from sim_bridge.poses import quaternion_from_rpy  # noqa: E402
from gazebo_msgs.srv import (DeleteLight, DeleteModel, GetLightProperties,  # noqa: E402
                             SetLightProperties, SetModelState, SpawnModel)

ROBOT_WITHOUT_JOINT = """<robot name="r"><link name="base"><inertial><mass value="1"/>
<inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
<gazebo><plugin name="drive" filename="libgazebo_ros_diff_drive.so">
<leftJoint>left_wheel_joint</leftJoint><rightJoint>right_wheel_joint</rightJoint>
</plugin></gazebo></robot>"""


def pose(x, y, yaw, z=0.0):
    result = Pose()
    result.position.x, result.position.y, result.position.z = x, y, z
    q = quaternion_from_rpy(0.0, 0.0, yaw)
    result.orientation.x, result.orientation.y, result.orientation.z, result.orientation.w = q
    return result


class World(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("world_check")
        cls.sim = Simulator()
        cls.sim.wait_for_model("diff_bot")
        cls.clock = []
        rospy.Subscriber("/clock", Clock, lambda m: cls.clock.append(m.clock.to_sec()),
                         queue_size=100)
        cls.log = []
        rospy.Subscriber("/rosout", Log, cls.log.append, queue_size=100)
        cls.spawn_urdf = rospy.ServiceProxy("/gazebo/spawn_urdf_model", SpawnModel)
        cls.spawn_sdf = rospy.ServiceProxy("/gazebo/spawn_sdf_model", SpawnModel)
        cls.delete = rospy.ServiceProxy("/gazebo/delete_model", DeleteModel)
        cls.set_state = rospy.ServiceProxy("/gazebo/set_model_state", SetModelState)
        cls.reset = rospy.ServiceProxy("/gazebo/reset_simulation", Empty)
        cls.get_light = rospy.ServiceProxy("/gazebo/get_light_properties", GetLightProperties)
        cls.set_light = rospy.ServiceProxy("/gazebo/set_light_properties", SetLightProperties)
        cls.delete_light = rospy.ServiceProxy("/gazebo/delete_light", DeleteLight)
        cls.command = rospy.Publisher("/cmd_vel", Twist, queue_size=1, latch=True)

    def test_clock_advances_pauses_and_resumes(self):
        wait_until(lambda: len(self.clock) > 3, "/clock messages")
        self.assertGreater(self.clock[-1], self.clock[-3])
        self.sim.pause()
        paused_at = self.sim.sim_time()
        before = self.sim.truth("diff_bot")
        self.command.publish(Twist(linear=Twist().linear.__class__(0.5, 0, 0)))
        count = len(self.clock)
        wait_until(lambda: len(self.clock) > count + 3, "/clock while paused")
        self.assertTrue(all(t == paused_at for t in self.clock[count + 1:]), self.clock[-5:])
        self.assertEqual(self.sim.truth("diff_bot"), before)
        self.sim.unpause()
        self.sim.wait_sim_time(paused_at + 0.5)
        self.command.publish(Twist())
        self.assertGreater(self.clock[-1], paused_at)

    def test_model_states_topic_is_the_ground_truth(self):
        self.sim.pause()
        states = []
        subscriber = rospy.Subscriber("/gazebo/model_states", ModelStates, states.append)
        self.sim.unpause()
        wait_until(lambda: states, "a message on /gazebo/model_states")
        self.sim.pause()  # the robot is at rest: the latest message and the truth agree
        subscriber.unregister()
        latest = states[-1]
        self.assertIn("wall", latest.name)  # static models too, as Gazebo
        index = latest.name.index("diff_bot")
        x, y, _ = self.sim.truth("diff_bot")
        self.assertAlmostEqual(latest.pose[index].position.x, x, delta=0.01)
        self.assertAlmostEqual(latest.pose[index].position.y, y, delta=0.01)
        self.sim.unpause()

    def test_set_and_get_model_state_and_reset(self):
        state = ModelState(model_name="diff_bot", pose=pose(0.5, -0.3, 0.7))
        self.sim.pause()
        answer = self.set_state(state)
        self.assertTrue(answer.success, answer.status_message)
        x, y, yaw = self.sim.truth("diff_bot")
        self.assertAlmostEqual(x, 0.5, delta=1e-6)
        self.assertAlmostEqual(y, -0.3, delta=1e-6)
        self.assertAlmostEqual(yaw, 0.7, delta=1e-6)
        self.sim.unpause()
        before_reset = self.sim.sim_time()
        self.reset()
        after = self.sim.truth("diff_bot")
        self.assertLess(math.hypot(after[0], after[1]), 0.01)
        self.assertGreaterEqual(self.sim.sim_time(), before_reset)  # time never goes back

    def test_the_set_model_state_topic_moves_the_model(self):
        """/gazebo/set_model_state takes set_model_state's request as a message
        (gazebo_ros_api_plugin.cpp:483-489, :1663-1669)."""
        self.sim.pause()
        topic = rospy.Publisher("/gazebo/set_model_state", ModelState, queue_size=10)
        state = ModelState(model_name="diff_bot", pose=pose(-0.4, 0.6, -0.5))
        wait_until(lambda: topic.get_num_connections() > 0, "the simulator's subscription")
        topic.publish(state)
        wait_until(lambda: abs(self.sim.truth("diff_bot")[0] + 0.4) < 1e-6,
                   "the model where the message put it")
        x, y, yaw = self.sim.truth("diff_bot")
        self.assertAlmostEqual(y, 0.6, delta=1e-6)
        self.assertAlmostEqual(yaw, -0.5, delta=1e-6)
        topic.unregister()
        self.sim.unpause()

    def test_a_position_beyond_floats_is_refused_naming_the_value_sent(self):
        """pybullet turns 1e300 into (inf, nan, nan): the answer names what was sent, the
        model stays where it was, and the next request is served."""
        before = self.sim.truth("diff_bot")
        answer = self.set_state(ModelState(model_name="diff_bot", pose=pose(1e300, 0.0, 0.0)))
        self.assertFalse(answer.success)
        self.assertIn("1e+300", answer.status_message)
        self.assertNotIn("nan", answer.status_message)
        after = self.sim.truth("diff_bot")
        self.assertLess(math.hypot(after[0] - before[0], after[1] - before[1]), 0.05)

    def test_nan_command_is_ignored_with_a_warning(self):
        self.sim.wait_sim_time(self.sim.sim_time() + 0.5)
        before = self.sim.truth("diff_bot")
        self.command.publish(Twist(linear=Twist().linear.__class__(float("nan"), 0, 0)))
        wait_until(lambda: any("must be finite" in entry.msg for entry in self.log),
                   "the NaN warning on /rosout")
        self.sim.wait_sim_time(self.sim.sim_time() + 0.5)
        after = self.sim.truth("diff_bot")
        self.assertLess(math.hypot(after[0] - before[0], after[1] - before[1]), 0.01)

    def assert_refused(self, answer, *words):
        self.assertFalse(answer.success)
        for word in words:
            self.assertIn(word, answer.status_message)
        # the simulator keeps running and keeps its robot
        self.assertIn("diff_bot", self.sim.properties().model_names)

    def test_the_worlds_sun_is_a_light_to_get_and_set(self):
        """The test world includes model://sun: get_light_properties gives its diffuse
        0.8 0.8 0.8 1 (gazebo_ros_api_plugin.cpp:1312-1344); set_light_properties
        (:1346-1400) changes what the next get reports; an unknown light, to get or to
        delete (:886-931), answers success false naming the sun."""
        rospy.wait_for_service("/gazebo/get_light_properties", timeout=10)
        sun = self.get_light("sun")
        self.assertTrue(sun.success, sun.status_message)
        # ColorRGBA is single precision: to its 7 digits
        self.assertEqual([round(v, 6) for v in (sun.diffuse.r, sun.diffuse.g, sun.diffuse.b,
                                                sun.diffuse.a)], [0.8, 0.8, 0.8, 1.0])
        answer = self.set_light("sun", True, ColorRGBA(0.5, 0.5, 0.4, 1.0),
                                ColorRGBA(0.2, 0.2, 0.2, 1.0), sun.attenuation_constant,
                                0.05, sun.attenuation_quadratic, Vector3(-0.5, 0.1, -0.9),
                                pose(0, 0, 0, z=10.0))
        self.assertTrue(answer.success, answer.status_message)
        changed = self.get_light("sun")
        self.assertEqual([round(v, 6) for v in (changed.diffuse.r, changed.diffuse.b,
                                                changed.attenuation_linear)], [0.5, 0.4, 0.05])
        for ask in (self.get_light, self.delete_light):
            missing = ask("moon")
            self.assertFalse(missing.success)
            self.assertIn("(lights: sun)", missing.status_message)

    def test_spawning_a_name_in_use_is_refused(self):
        self.assert_refused(self.spawn_urdf("diff_bot", rospy.get_param("/robot_description"),
                                            "", pose(3, 3, 0), ""), "diff_bot", "exists already")

    def test_a_malformed_urdf_is_refused_naming_the_parse_error(self):
        self.assert_refused(self.spawn_urdf("broken", "<robot name='b'><link name='a'>", "",
                                            pose(0, 3, 0), ""), "not well-formed", "line 1")

    def test_an_unknown_model_uri_names_the_paths_searched(self):
        sdf = ("<sdf version='1.6'><model name='m'><static>true</static><include>"
               "<uri>model://no_such_model</uri></include></model></sdf>")
        self.assert_refused(self.spawn_sdf("m", sdf, "", pose(0, 3, 0), ""),
                            "model://no_such_model", "searched", "sim_bridge/models")

    def test_deleting_an_unknown_model_is_refused(self):
        self.assert_refused(self.delete("no_such_model"), "no model named 'no_such_model'")

    def test_a_plugin_naming_a_missing_joint_is_left_out_and_the_model_spawns(self):
        # as Gazebo: the robot loads, the plugin does not run, a warning names the joint
        logged = []
        subscriber = rospy.Subscriber("/rosout", Log, lambda m: logged.append(m.msg))
        answer = self.spawn_urdf("jointless", ROBOT_WITHOUT_JOINT, "", pose(0, 3, 0), "")
        self.assertTrue(answer.success, answer.status_message)
        self.assertIn("jointless", self.sim.properties().model_names)
        wait_until(lambda: any("left_wheel_joint" in m and "not loaded" in m for m in logged),
                   "the warning naming the missing joint")
        subscriber.unregister()

    def test_spawn_and_delete_an_sdf_model(self):
        sdf = ("<sdf version='1.6'><model name='crate'><link name='link'><collision name='c'>"
               "<geometry><box><size>0.3 0.3 0.3</size></box></geometry></collision></link>"
               "</model></sdf>")
        answer = self.spawn_sdf("crate", sdf, "", pose(-2, 0, 0, z=0.15), "")
        self.assertTrue(answer.success, answer.status_message)
        self.sim.wait_sim_time(self.sim.sim_time() + 1.0)
        x, y, _ = self.sim.truth("crate")
        self.assertAlmostEqual(x, -2.0, delta=0.01)
        self.assertTrue(self.delete("crate").success)
        self.assertNotIn("crate", self.sim.properties().model_names)


if __name__ == "__main__":
    rostest.rosrun("gazebo_ros", "world", World)
