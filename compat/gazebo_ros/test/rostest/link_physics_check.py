#!/usr/bin/env python3
"""rostest node: gazebo_ros's link, model-property, physics, wrench and effort services
against ground truth: a wrench of F for d seconds changes a free body's velocity by F·d/m,
clearing it stops it, an effort turns a joint, zero gravity makes a dropped body float,
a mass set by set_link_properties halves what a wrench does,
link_states agrees with get_link_state, and bad names answer success false naming them
while the simulator keeps running."""
import os
import sys
import time
import unittest

import rospy
import rostest
from geometry_msgs.msg import Point, Pose, Vector3, Wrench

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sim_checks import Simulator, wait_until  # noqa: E402

from gazebo_msgs.msg import LinkState, LinkStates, PerformanceMetrics  # noqa: E402
from gazebo_msgs.srv import (ApplyBodyWrench, ApplyJointEffort, BodyRequest,  # noqa: E402
                             DeleteModel, GetLinkProperties, GetLinkState,
                             GetModelProperties, GetPhysicsProperties, JointRequest,
                             SetLinkProperties, SetLinkState, SetPhysicsProperties,
                             SpawnModel)
from sim_bridge.poses import quaternion_from_rpy, yaw_from_quaternion  # noqa: E402
from sim_bridge.testing import service_proxy  # noqa: E402
from std_srvs.srv import Empty  # noqa: E402

MASS = 2.0  # kg, the free box's
BOX = f"""<sdf version='1.6'><model name='box'><link name='link'>
<inertial><mass>{MASS}</mass><inertia><ixx>0.0133</ixx><iyy>0.0133</iyy><izz>0.0133</izz>
</inertia></inertial><collision name='c'><geometry><box><size>0.2 0.2 0.2</size></box>
</geometry></collision></link></model></sdf>"""
# a disc turning about z on a stand fixed to the world: I = 0.2 kg m²
ROTOR = """<robot name="rotor"><link name="world"/>
<link name="stand"><inertial><mass value="1"/>
<inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
<joint name="fix" type="fixed"><parent link="world"/><child link="stand"/>
<origin xyz="0 0 0.5"/></joint>
<link name="disc"><inertial><mass value="2"/>
<inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.2"/></inertial></link>
<joint name="spin" type="continuous"><parent link="stand"/><child link="disc"/>
<axis xyz="0 0 1"/></joint></robot>"""
DIFF_BOT_LINKS = ["base_footprint", "left_wheel", "right_wheel"]


def pose(x, y, z=0.0, yaw=0.0):
    result = Pose()
    result.position.x, result.position.y, result.position.z = x, y, z
    q = quaternion_from_rpy(0.0, 0.0, yaw)
    result.orientation.x, result.orientation.y, result.orientation.z, result.orientation.w = q
    return result


def position(pose_message):
    return (pose_message.position.x, pose_message.position.y, pose_message.position.z)


class LinkAndPhysics(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("link_physics_check")
        cls.sim = Simulator()
        cls.sim.wait_for_model("diff_bot")
        name = "/gazebo/"
        cls.get_link = service_proxy(name + "get_link_state", GetLinkState)
        cls.set_link = service_proxy(name + "set_link_state", SetLinkState)
        cls.get_link_properties = service_proxy(name + "get_link_properties",
                                                GetLinkProperties)
        cls.set_link_properties = service_proxy(name + "set_link_properties",
                                                SetLinkProperties)
        cls.properties = service_proxy(name + "get_model_properties", GetModelProperties)
        cls.get_physics = service_proxy(name + "get_physics_properties", GetPhysicsProperties)
        cls.set_physics = service_proxy(name + "set_physics_properties", SetPhysicsProperties)
        cls.wrench = service_proxy(name + "apply_body_wrench", ApplyBodyWrench)
        cls.clear_wrenches = service_proxy(name + "clear_body_wrenches", BodyRequest)
        cls.effort = service_proxy(name + "apply_joint_effort", ApplyJointEffort)
        cls.clear_efforts = service_proxy(name + "clear_joint_forces", JointRequest)
        cls.spawn_sdf = service_proxy(name + "spawn_sdf_model", SpawnModel)
        cls.spawn_urdf = service_proxy(name + "spawn_urdf_model", SpawnModel)
        cls.delete = service_proxy(name + "delete_model", DeleteModel)
        cls.reset_world = service_proxy(name + "reset_world", Empty)

    def setUp(self):
        self.sim.unpause()

    # --- helpers ----------------------------------------------------------------------
    def spawn_box(self, name, x, y, z):
        answer = self.spawn_sdf(name, BOX, "", pose(x, y, z), "")
        self.assertTrue(answer.success, answer.status_message)
        self.addCleanup(self.delete, name)

    def velocity(self, model):
        state = self.sim.get_state(model, "")
        self.assertTrue(state.success, state.status_message)
        return state.twist.linear

    def run_for(self, seconds):
        """Runs the simulator ``seconds`` of simulated time from now, then pauses it; the
        simulated time that really passed (the pause lands a little later)."""
        start = self.sim.sim_time()
        self.sim.unpause()
        self.sim.wait_sim_time(start + seconds)
        self.sim.pause()
        return self.sim.sim_time() - start

    def restore_physics(self, saved):
        answer = self.set_physics(saved.time_step, saved.max_update_rate, saved.gravity,
                                  saved.ode_config)
        self.assertTrue(answer.success, answer.status_message)

    # --- model properties and link states ---------------------------------------------
    def test_model_properties_list_the_diff_bots_links_and_joints(self):
        answer = self.properties("diff_bot")
        self.assertTrue(answer.success, answer.status_message)
        # Gazebo lumps base_link, casters and laser (fixed joints) into base_footprint
        self.assertEqual(answer.body_names, DIFF_BOT_LINKS)
        self.assertEqual(answer.canonical_body_name, "base_footprint")
        self.assertEqual(answer.joint_names, ["left_wheel_joint", "right_wheel_joint"])
        self.assertIn("left_wheel_collision", answer.geom_names)
        self.assertFalse(answer.is_static)
        self.assertTrue(self.properties("wall").is_static)

    def test_link_states_agree_with_get_link_state(self):
        messages = []
        subscriber = rospy.Subscriber("/gazebo/link_states", LinkStates, messages.append)
        wait_until(lambda: messages, "a message on /gazebo/link_states")
        self.sim.pause()  # the robot is at rest: the latest message and the truth agree
        subscriber.unregister()
        latest = messages[-1]
        for link in ("wall::link", "ground_plane::link"):
            self.assertIn(link, latest.name)
        robot_links = [n for n in latest.name if n.startswith("diff_bot::")]
        self.assertEqual(robot_links, [f"diff_bot::{link}" for link in DIFF_BOT_LINKS])
        for name in robot_links:
            answer = self.get_link(name, "")
            self.assertTrue(answer.success, answer.status_message)
            published = position(latest.pose[latest.name.index(name)])
            for got, expected in zip(position(answer.link_state.pose), published):
                self.assertAlmostEqual(got, expected, delta=1e-3)
        plain = self.get_link("left_wheel", "")  # as gazebo_ros: the plain name works too
        self.assertTrue(plain.success, plain.status_message)
        self.assertEqual(position(plain.link_state.pose),
                         position(self.get_link("diff_bot::left_wheel", "").link_state.pose))

    def test_link_state_relative_to_another_link(self):
        answer = self.get_link("diff_bot::left_wheel", "diff_bot::base_footprint")
        self.assertTrue(answer.success, answer.status_message)
        # the wheel joint: 0.17 m left of base_link, which is 0.08 m above base_footprint,
        # and 0.03 m below it
        for got, expected in zip(position(answer.link_state.pose), (0.0, 0.17, 0.05)):
            self.assertAlmostEqual(got, expected, delta=2e-3)
        self.assertEqual(answer.link_state.reference_frame, "diff_bot::base_footprint")

    def test_set_link_state_of_the_base_link_moves_the_robot(self):
        self.sim.pause()
        self.addCleanup(self.reset_world)
        state = LinkState(link_name="diff_bot::base_footprint", pose=pose(0.5, -0.3, 0.0, 0.7))
        answer = self.set_link(state)
        self.assertTrue(answer.success, answer.status_message)
        x, y, yaw = self.sim.truth("diff_bot")
        self.assertAlmostEqual(x, 0.5, delta=1e-6)
        self.assertAlmostEqual(y, -0.3, delta=1e-6)
        self.assertAlmostEqual(yaw, 0.7, delta=1e-6)

    # --- wrenches and efforts ---------------------------------------------------------
    def test_a_wrench_changes_a_free_bodys_velocity_by_f_d_over_m(self):
        self.sim.pause()
        self.spawn_box("thrown_box", -3.0, 3.0, 30.0)  # falling freely: no friction
        force, seconds = 4.0, 0.5
        start = rospy.Time.from_sec(self.sim.sim_time() + 0.1)
        answer = self.wrench("thrown_box::link", "", Point(),
                             Wrench(force=Vector3(force, 0, 0)), start,
                             rospy.Duration.from_sec(seconds))
        self.assertTrue(answer.success, answer.status_message)
        self.run_for(0.1 + seconds + 0.2)
        self.assertAlmostEqual(self.velocity("thrown_box").x, force * seconds / MASS,
                               delta=0.02 * force * seconds / MASS)

    def test_a_link_of_twice_the_mass_takes_half_the_velocity(self):
        """get_link_properties gives the box's 2 kg; set_link_properties to 4 kg (moments
        doubled, the centre of mass its own, gravity on); 4 N for 0.5 s then move it at
        0.5 m/s, not 1 (gazebo_ros_api_plugin.cpp:1174-1230, :1402-1430)."""
        self.sim.pause()
        self.spawn_box("heavy_box", 3.0, -3.0, 30.0)  # falling freely: no friction
        got = self.get_link_properties("heavy_box::link")
        self.assertTrue(got.success, got.status_message)
        self.assertAlmostEqual(got.mass, MASS)
        answer = self.set_link_properties("heavy_box::link", got.com, True, 2 * MASS,
                                          2 * got.ixx, 0.0, 0.0, 2 * got.iyy, 0.0,
                                          2 * got.izz)
        self.assertTrue(answer.success, answer.status_message)
        self.assertAlmostEqual(self.get_link_properties("heavy_box::link").mass, 2 * MASS)
        force, seconds = 4.0, 0.5
        start = rospy.Time.from_sec(self.sim.sim_time() + 0.1)
        answer = self.wrench("heavy_box::link", "", Point(),
                             Wrench(force=Vector3(force, 0, 0)), start,
                             rospy.Duration.from_sec(seconds))
        self.assertTrue(answer.success, answer.status_message)
        self.run_for(0.1 + seconds + 0.2)
        self.assertAlmostEqual(self.velocity("heavy_box").x, force * seconds / (2 * MASS),
                               delta=0.02 * force * seconds / (2 * MASS))
        moved = self.set_link_properties("heavy_box::link", pose(0, 0, 0.1), True, MASS,
                                          got.ixx, 0.0, 0.0, got.iyy, 0.0, got.izz)
        self.assertFalse(moved.success)
        self.assertIn("cannot move it", moved.status_message)

    def test_clearing_a_wrench_stops_it(self):
        self.sim.pause()
        self.spawn_box("pushed_box", -3.0, -3.0, 30.0)
        answer = self.wrench("pushed_box::link", "world", Point(),
                             Wrench(force=Vector3(2.0, 0, 0)), rospy.Time(),
                             rospy.Duration(-1))  # until cleared
        self.assertTrue(answer.success, answer.status_message)
        self.run_for(0.3)
        self.clear_wrenches("pushed_box::link")
        cleared_at = self.velocity("pushed_box").x
        self.assertGreater(cleared_at, 0.2)  # 2 N on 2 kg for 0.3 s: 0.3 m/s
        self.run_for(0.3)
        self.assertAlmostEqual(self.velocity("pushed_box").x, cleared_at, delta=1e-3)

    def test_an_effort_turns_a_joint(self):
        self.sim.pause()
        answer = self.spawn_urdf("rotor", ROTOR, "", pose(-3.0, 0.0), "")
        self.assertTrue(answer.success, answer.status_message)
        self.addCleanup(self.delete, "rotor")
        before = self.get_link("rotor::disc", "").link_state.pose.orientation
        answer = self.effort("rotor::spin", 0.5, rospy.Time(), rospy.Duration.from_sec(0.4))
        self.assertTrue(answer.success, answer.status_message)
        elapsed = self.run_for(0.6)
        state = self.get_link("rotor::disc", "").link_state
        # 0.5 N m on 0.2 kg m² for 0.4 s: 1 rad/s, after turning 0.2 rad, then 1 rad/s for
        # the rest of the time that really passed before the pause landed
        self.assertAlmostEqual(state.twist.angular.z, 1.0, delta=0.02)
        after = state.pose.orientation
        turned = yaw_from_quaternion((after.x, after.y, after.z, after.w)) - \
            yaw_from_quaternion((before.x, before.y, before.z, before.w))
        self.assertAlmostEqual(turned, 0.2 + 1.0 * (elapsed - 0.4), delta=0.02)
        answer = self.effort("spin", 0.5, rospy.Time(), rospy.Duration(-1))
        self.assertTrue(answer.success, answer.status_message)
        self.clear_efforts("spin")
        self.run_for(0.2)
        self.assertAlmostEqual(self.get_link("rotor::disc", "").link_state.twist.angular.z,
                               1.0, delta=0.02)

    # --- physics ----------------------------------------------------------------------
    def test_without_gravity_a_dropped_body_floats(self):
        saved = self.get_physics()
        self.assertTrue(saved.success, saved.status_message)
        self.assertEqual((saved.gravity.x, saved.gravity.y, saved.gravity.z), (0.0, 0.0, -9.8))
        self.assertAlmostEqual(saved.time_step, 0.001)
        self.sim.pause()
        self.addCleanup(self.restore_physics, saved)
        answer = self.set_physics(saved.time_step, saved.max_update_rate, Vector3(0, 0, 0),
                                  saved.ode_config)
        self.assertTrue(answer.success, answer.status_message)
        self.assertEqual(self.get_physics().gravity, Vector3(0, 0, 0))
        self.spawn_box("balloon", -3.0, 1.5, 1.0)
        self.run_for(1.0)
        state = self.sim.get_state("balloon", "")
        self.assertAlmostEqual(state.pose.position.z, 1.0, delta=1e-3)
        self.assertAlmostEqual(state.twist.linear.z, 0.0, delta=1e-3)
        self.restore_physics(saved)
        self.run_for(0.3)
        self.assertLess(self.velocity("balloon").z, -2.0)  # falls again

    def test_max_update_rate_paces_the_simulation(self):
        saved = self.get_physics()
        self.assertAlmostEqual(saved.max_update_rate * saved.time_step, 1.0)  # real time
        self.addCleanup(self.restore_physics, saved)
        answer = self.set_physics(saved.time_step, 250.0, saved.gravity, saved.ode_config)
        self.assertTrue(answer.success, answer.status_message)
        self.assertEqual(self.get_physics().max_update_rate, 250.0)
        start_sim, start_wall = self.sim.sim_time(), time.monotonic()
        time.sleep(2.0)
        sim_rate = (self.sim.sim_time() - start_sim) / (time.monotonic() - start_wall)
        # 250 steps of 1 ms per second: a quarter of real time (a busy machine: less)
        self.assertGreater(sim_rate, 0.0)
        self.assertLess(sim_rate, 0.35)

    def test_performance_metrics_measure_the_real_time_factor(self):
        """/gazebo/performance_metrics (gazebo_ros_api_plugin.cpp:410-417, :230-253) while
        someone listens: the real time factor against what this node measures of /clock
        over wall time, and the laser at its <update_rate> 20 on the link it is lumped
        into."""
        received = []
        subscriber = rospy.Subscriber("/gazebo/performance_metrics", PerformanceMetrics,
                                      received.append)
        self.addCleanup(subscriber.unregister)
        start_sim, start_wall = self.sim.sim_time(), time.monotonic()
        wait_until(lambda: len(received) >= 2, "two messages on /gazebo/performance_metrics")
        measured = (self.sim.sim_time() - start_sim) / (time.monotonic() - start_wall)
        latest = received[-1]
        self.assertAlmostEqual(latest.real_time_factor, measured, delta=0.25)
        laser = [s for s in latest.sensors if s.name == "diff_bot::base_footprint::laser_sensor"]
        self.assertEqual(len(laser), 1, [s.name for s in latest.sensors])
        self.assertEqual(laser[0].sim_update_rate, 20.0)
        self.assertEqual(laser[0].fps, -1.0)

    # --- bad requests -----------------------------------------------------------------
    def assert_refused(self, answer, *words):
        self.assertFalse(answer.success)
        for word in words:
            self.assertIn(word, answer.status_message)
        self.assertIn("diff_bot", self.sim.properties().model_names)  # still running

    def test_bad_names_answer_success_false_naming_them(self):
        self.assert_refused(self.get_link("diff_bot::base_link", ""), "GetLinkState",
                            "'base_link'", "lumps it into 'base_footprint'")
        self.assert_refused(self.get_link("no_such_link", ""), "'no_such_link'")
        self.assert_refused(self.get_link("diff_bot::left_wheel", "nowhere"), "'nowhere'")
        self.assert_refused(self.set_link(LinkState(link_name="diff_bot::left_wheel",
                                                    pose=pose(0, 0, 1))),
                            "SetLinkState", "left_wheel_joint")
        self.assert_refused(self.properties("no_such_model"), "GetModelProperties",
                            "'no_such_model'")
        self.assert_refused(self.wrench("no_such_model::link", "", Point(), Wrench(),
                                        rospy.Time(), rospy.Duration(1)),
                            "ApplyBodyWrench", "'no_such_model'")
        self.assert_refused(self.wrench("wall::link", "", Point(),
                                        Wrench(force=Vector3(1, 0, 0)), rospy.Time(),
                                        rospy.Duration(1)), "static model 'wall'")
        self.assert_refused(self.effort("no_such_joint", 1.0, rospy.Time(), rospy.Duration(1)),
                            "ApplyJointEffort", "'no_such_joint'")
        saved = self.get_physics()
        self.assert_refused(self.set_physics(0.0, 1000.0, Vector3(0, 0, -9.8),
                                             saved.ode_config),
                            "SetPhysicsProperties", "time_step")
        # a rate whose pacing would sleep 1e9 s a step, a step under the clock's nanosecond
        self.assert_refused(self.set_physics(saved.time_step, 1e-9, saved.gravity,
                                             saved.ode_config),
                            "SetPhysicsProperties", "max_update_rate 1e-09 is too slow")
        self.assert_refused(self.set_physics(1e-12, saved.max_update_rate, saved.gravity,
                                             saved.ode_config),
                            "SetPhysicsProperties", "time_step 1e-12 is below a nanosecond")
        now = self.get_physics()
        self.assertEqual((now.time_step, now.max_update_rate, now.gravity),
                         (saved.time_step, saved.max_update_rate, saved.gravity))
        # no answer fields: the call returns, the simulator logs the cause
        self.clear_wrenches("no_such_model::link")
        self.clear_efforts("no_such_joint")
        self.assertIn("diff_bot", self.sim.properties().model_names)


if __name__ == "__main__":
    rostest.rosrun("gazebo_ros", "link_and_physics", LinkAndPhysics)
