#!/usr/bin/env python3
"""rostest node: spawn requests the simulator refuses (an SDF model including itself, a
pose of NaN, a box of negative size, a negative mass, an SDF over the size limit, a robot
of 10,000 links) each answer success: false with the cause and the value; a laser of 10^9
beams is left out with a warning naming it and the robot spawns; after all of them the
simulator serves a valid spawn, which falls onto the ground (ground truth)."""
import math
import os
import shutil
import sys
import tempfile
import unittest

import rospy
import rostest
from geometry_msgs.msg import Pose
from rosgraph_msgs.msg import Log

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sim_checks import Simulator, wait_until  # noqa: E402

from gazebo_msgs.srv import SpawnModel  # noqa: E402
from sim_bridge.plugins.laser import MAX_BEAMS  # noqa: E402
from sim_bridge.sdf_world import MAX_INCLUDE_DEPTH  # noqa: E402
from urdf_tools.model import MAX_DESCRIPTION_BYTES, MAX_LINKS  # noqa: E402
from urdf_tools.xacro_loader import expand  # noqa: E402

import rospkg  # noqa: E402

BOX_LINK = """<link name="body"><inertial><mass>1</mass><inertia><ixx>0.01</ixx>
<iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
<collision name="c"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision>
</link>"""
# the box's half height: where it rests on the ground plane
REST_Z = 0.1
# how close to rest the box must come, m
AT_REST = 0.005


def pose(x, y, z):
    result = Pose()
    result.position.x, result.position.y, result.position.z = x, y, z
    result.orientation.w = 1.0
    return result


class DescriptionLimits(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("description_limits_check")
        cls.sim = Simulator()
        cls.log = []
        rospy.Subscriber("/rosout", Log, lambda m: cls.log.append(m.msg), queue_size=100)
        rospy.wait_for_service("/gazebo/spawn_sdf_model", timeout=60)
        rospy.wait_for_service("/gazebo/spawn_urdf_model", timeout=60)
        cls.spawn_sdf = rospy.ServiceProxy("/gazebo/spawn_sdf_model", SpawnModel)
        cls.spawn_urdf = rospy.ServiceProxy("/gazebo/spawn_urdf_model", SpawnModel)
        cls.folder = tempfile.mkdtemp(prefix="description_limits_")

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.folder, ignore_errors=True)

    def refused(self, spawn, name, xml, *words):
        answer = spawn(name, xml, "", pose(0, 0, 1), "")
        self.assertFalse(answer.success, answer.status_message)
        for word in words:
            self.assertIn(word, answer.status_message)
        self.assertNotIn(name, self.sim.properties().model_names)
        return answer.status_message

    def test_a_model_including_itself_names_the_chain(self):
        selfie = os.path.join(self.folder, "selfie")
        os.makedirs(selfie)
        with open(os.path.join(selfie, "model.sdf"), "w", encoding="utf-8") as stream:
            stream.write(f'<sdf version="1.6"><model name="selfie"><static>true</static>'
                         f'<include><uri>file://{selfie}</uri></include></model></sdf>')
        self.refused(self.spawn_sdf, "selfie",
                     f'<sdf version="1.6"><model name="m"><include><uri>file://{selfie}'
                     '</uri></include></model></sdf>',
                     "SpawnModel: ", "includes itself", f"file://{selfie} -> file://{selfie}")
        self.assertGreater(MAX_INCLUDE_DEPTH, 1)

    def test_a_pose_of_nan_names_model_and_value(self):
        self.refused(self.spawn_sdf, "nan_pose",
                     f'<model name="m"><link name="body"><pose>0 nan 0 0 0 0</pose></link>'
                     '</model>', "model 'm' link 'body' <pose> '0 nan 0 0 0 0'",
                     "not 6 finite numbers")

    def test_a_box_of_negative_size_and_a_negative_mass_are_refused(self):
        self.refused(self.spawn_sdf, "negative_box",
                     f'<model name="m">{BOX_LINK.replace("0.2 0.2 0.2", "0.2 -0.2 0.2")}'
                     '</model>', "link 'body' collision 'c' box size '0.2 -0.2 0.2' must be "
                     "positive")
        self.refused(self.spawn_sdf, "negative_mass",
                     f'<model name="m">{BOX_LINK.replace("<mass>1</mass>", "<mass>-1</mass>")}'
                     '</model>', "link 'body' has a negative mass (-1 kg)")

    def test_a_description_over_the_size_limit_names_the_limit(self):
        padding = "<!--" + "x" * MAX_DESCRIPTION_BYTES + "-->"
        self.refused(self.spawn_sdf, "huge", f'<model name="m">{padding}{BOX_LINK}</model>',
                     f"at most {MAX_DESCRIPTION_BYTES}")

    def test_a_robot_of_ten_thousand_links_is_refused(self):
        parts = ['<robot name="chain">']
        for index in range(10_000):
            parts.append(f'<link name="l{index}"/>')
            if index:
                parts.append(f'<joint name="j{index}" type="fixed"><parent link="l{index - 1}"/>'
                             f'<child link="l{index}"/></joint>')
        self.refused(self.spawn_urdf, "chain", "".join(parts) + "</robot>",
                     "10000 links", f"at most {MAX_LINKS} (MAX_LINKS)")

    def test_a_laser_of_a_billion_beams_is_left_out_and_the_robot_spawns(self):
        data = os.path.join(rospkg.RosPack().get_path("sim_bridge"), "test", "data")
        xml = expand(os.path.join(data, "diff_bot.urdf.xacro"), {"laser_samples": "1e9"})
        answer = self.spawn_urdf("big_laser", xml, "", pose(3, 3, 0.1), "")
        self.assertTrue(answer.success, answer.status_message)
        wait_until(lambda: any("sensor 'laser_sensor'" in entry and "1000000000 x 1" in entry
                               and f"at most {MAX_BEAMS}" in entry for entry in self.log),
                   "the warning naming the laser, its beams and the limit on /rosout")
        self.assertNotIn("/scan", [topic for topic, _ in rospy.get_published_topics()])

    def test_z_the_simulator_still_serves_a_valid_spawn(self):
        answer = self.spawn_sdf("ok_box", f'<model name="ok_box">{BOX_LINK}</model>', "",
                                pose(-2, -2, 1), "")
        self.assertTrue(answer.success, answer.status_message)
        wait_until(lambda: abs(self.sim.pose("ok_box").position.z - REST_Z) < AT_REST,
                   "the box to rest on the ground")
        position = self.sim.pose("ok_box").position
        self.assertLess(math.hypot(position.x + 2, position.y + 2), AT_REST)


if __name__ == "__main__":
    rostest.rosrun("gazebo_ros", "description_limits", DescriptionLimits)
