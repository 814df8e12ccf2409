#!/usr/bin/env python3
"""rostest node: a robot's own Gazebo C++ plugin (kobuki_style_gazebo_plugins) runs in
sim_bridge with roscpp, as under Gazebo: its topics in the robot's namespace, published by
the simulator's roscpp node beside the rospy node /gazebo, stamped in simulated time; it
drives 0.5 m and turns 90 degrees on its command topic, in ground truth
(/gazebo/get_model_state), by SetParam("vel") and by SetVelocity alike. A base spawned in
spawn_model's default namespace has its topics at the root, and one whose plugin names a
joint it does not have spawns without the plugin, the error named. The plugin's sensors
(plugin-less <sensor>s it finds through SensorManager): the gyro's heading and rate are the
odometry's, the cliff ray reads the floor's distance, the bumper's contacts press the
centre bumper when the base meets a wall."""
import math
import os
import subprocess
import sys
import unittest

import numpy as np
import rosgraph
import rospkg
import rospy
import rostest
from gazebo_msgs.srv import DeleteModel, SpawnModel
from std_srvs.srv import Empty
from geometry_msgs.msg import Pose, Twist
from nav_msgs.msg import Odometry
from rosgraph_msgs.msg import Log
from std_msgs.msg import Float64, UInt8
from tf.transformations import quaternion_from_euler, quaternion_matrix

from sim_bridge.poses import yaw_from_quaternion

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sim_checks import Simulator, angle_difference, wait_until  # noqa: E402

# the two bases, by their model name (= robot namespace): how the plugin drives the wheels
BASES = ("motor_base", "velocity_base")
PLUGIN_NODE = "/gazebo_plugin_host"  # sim_bridge.native_plugins.ROS_NODE_NAME
# spawned by spawn_model without -robot_namespace: the plugin's namespace is "//"
ROOT_BASE = "root_base"
# the commands the test gives: 0.5 m at 0.25 m/s, a quarter turn at pi/4 rad/s, each 2 s
SPEED = 0.25
TURN_RATE = math.pi / 4
RUN = 2.0
# the plugin stops a base whose latest command is older than this (its URDF's
# velocity_command_timeout): the test repeats its command ten times as often
COMMAND_TIMEOUT = 0.6
COMMAND_PERIOD = 0.1
SETTLE = 0.5  # s of simulated time at the commanded speed before a run is measured
TOLERANCE = 0.05  # of the distance or angle: the wheels' slip
# s of simulated time: the odometry plugin publishes at 50 Hz, each stamped with the time
# roscpp has received from /clock at that step
ODOMETRY_PERIOD = 0.02
# the cliff sensor's height above the floor (the URDF's cliff_height), and what its first
# ray reads, 2.5 degrees off the vertical, at the sensor's 1 mm resolution
CLIFF_HEIGHT = 0.04
CLIFF_X = 0.15  # and how far ahead of the base's centre (the URDF's cliff_x)
CLIFF_ANGLE = 0.0436
RANGE_RESOLUTION = 0.001
HEADING_TOLERANCE = 0.01  # rad: the gyro's heading against the true one, at rest
# the bumper test's wall: a static box whose near face is WALL_GAP ahead of the base's centre
WALL_GAP = 0.5
WALL_SIZE = (0.2, 1.0, 0.3)
BODY_RADIUS = 0.175  # the base's round body (the URDF's body_radius)
CONTACT_TOLERANCE = 0.02  # m: where the base stands when the bumper reports
BUMPER_CENTRE = 2  # kobuki_msgs/SensorState's bit


class CppPluginDrive(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("cpp_plugin_drive_check")
        cls.sim = Simulator()
        for base in BASES:
            cls.sim.wait_for_model(base)
        cls.odometry = {}
        cls.bumpers = []
        cls.cliff = []
        rospy.Subscriber(f"/{BASES[0]}/mobile_base/sensors/bumper", UInt8,
                         lambda message: cls.bumpers.append(message.data))
        rospy.Subscriber(f"/{BASES[0]}/mobile_base/sensors/cliff_range", Float64,
                         lambda message: cls.cliff.append(message.data))
        cls.commands = {base: rospy.Publisher(f"/{base}/mobile_base/commands/velocity", Twist,
                                              queue_size=1) for base in BASES}
        for base in BASES:
            rospy.Subscriber(f"/{base}/odom", Odometry,
                             lambda message, b=base: cls.odometry.__setitem__(b, message))
        cls.command = Twist()
        # repeated in simulated time, as a teleop node does
        cls.timer = rospy.Timer(rospy.Duration(COMMAND_PERIOD), cls._repeat_command)
        # roscpp's time is 0 until its /clock subscription has connected to /gazebo (as any
        # node's under use_sim_time): the first stamps may be 0
        wait_until(lambda: all(base in cls.odometry and not cls.odometry[base].header.stamp.is_zero()
                               for base in BASES), "both bases' odometry in simulated time")

    @classmethod
    def _repeat_command(cls, _event):
        for publisher in cls.commands.values():
            publisher.publish(cls.command)

    def _run(self, linear, angular):
        """Both bases at the command, settled, then RUN s measured in ground truth (bracketed
        by pauses). Returns (elapsed simulated time, {base: (truth before, after)})."""
        command = Twist()
        command.linear.x, command.angular.z = linear, angular
        type(self).command = command
        self.sim.wait_sim_time(self.sim.sim_time() + SETTLE)
        self.sim.pause()
        start = self.sim.sim_time()
        before = {base: self.sim.truth(base) for base in BASES}
        self.sim.unpause()
        self.sim.wait_sim_time(start + RUN)
        self.sim.pause()
        elapsed = self.sim.sim_time() - start
        self.moving = dict(self.odometry)  # the last odometry while at the command
        after = {base: self.sim.truth(base) for base in BASES}
        type(self).command = Twist()
        self.sim.unpause()
        self.sim.wait_sim_time(self.sim.sim_time() + SETTLE)  # stopped again
        return elapsed, {base: (before[base], after[base]) for base in BASES}

    def test_1_topics_are_in_the_robots_namespace_on_the_simulators_roscpp_node(self):
        master = rosgraph.Master("/cpp_plugin_drive_check")
        publishers, subscribers, _ = master.getSystemState()
        publishers, subscribers = dict(publishers), dict(subscribers)
        for namespace in (*BASES, ""):  # the third, ROOT_BASE's, at the root
            prefix = f"/{namespace}" if namespace else ""
            self.assertEqual(publishers.get(f"{prefix}/odom"), [PLUGIN_NODE])
            self.assertIn(PLUGIN_NODE, subscribers.get(f"{prefix}/mobile_base/commands/velocity"))
        # use_sim_time: roscpp follows /clock, which the rospy node /gazebo publishes
        self.assertIn(PLUGIN_NODE, subscribers["/clock"])
        self.assertEqual(publishers["/clock"], ["/gazebo"])
        # both nodes registered and answering (a second /gazebo would have shut one down)
        for node in ("/gazebo", PLUGIN_NODE):
            self.assertTrue(rosgraph.Master("/check").lookupNode(node))
        frames = self.odometry[BASES[0]]
        self.assertEqual((frames.header.frame_id, frames.child_frame_id),
                         ("odom", "base_footprint"))

    def test_2_odometry_is_stamped_in_simulated_time(self):
        self.sim.pause()
        paused_at = self.sim.sim_time()
        self.odometry.clear()
        self.sim.unpause()
        wait_until(lambda: BASES[0] in self.odometry, "odometry after the unpause")
        stamp = self.odometry[BASES[0]].header.stamp.to_sec()
        now = self.sim.sim_time()
        self.assertGreaterEqual(stamp, paused_at - ODOMETRY_PERIOD)
        self.assertLessEqual(stamp, now)

    def test_3_half_a_metre_straight(self):
        elapsed, runs = self._run(SPEED, 0.0)
        for base, (before, after) in runs.items():
            travelled = math.hypot(after[0] - before[0], after[1] - before[1])
            rospy.loginfo("%s: %.4f m in %.3f s", base, travelled, elapsed)
            self.assertAlmostEqual(travelled, SPEED * elapsed, delta=SPEED * elapsed * TOLERANCE,
                                   msg=base)
            self.assertLess(abs(angle_difference(after[2], before[2])), TOLERANCE, msg=base)

    def test_4_a_quarter_turn_and_the_gyro_follows_it(self):
        at_rest = {base: (self.sim.truth(base)[2], _yaw(self.odometry[base])) for base in BASES}
        elapsed, runs = self._run(0.0, TURN_RATE)
        for base, (before, after) in runs.items():
            turned = angle_difference(after[2], before[2])
            rospy.loginfo("%s: %.4f rad in %.3f s", base, turned, elapsed)
            self.assertAlmostEqual(turned, TURN_RATE * elapsed,
                                   delta=TURN_RATE * elapsed * TOLERANCE, msg=base)
            # the odometry's turn rate is the gyro's (ImuSensor::AngularVelocity)
            self.assertAlmostEqual(self.moving[base].twist.twist.angular.z, TURN_RATE,
                                   delta=TURN_RATE * TOLERANCE, msg=base)
            # and its heading the gyro's (ImuSensor::Orientation), both at rest again
            true_turn = angle_difference(self.sim.truth(base)[2], at_rest[base][0])
            gyro_turn = angle_difference(_yaw(self.odometry[base]), at_rest[base][1])
            rospy.loginfo("%s: turned %.4f rad, the gyro says %.4f", base, true_turn, gyro_turn)
            self.assertAlmostEqual(gyro_turn, true_turn, delta=HEADING_TOLERANCE, msg=base)

    def test_5_a_command_that_is_not_repeated_stops_after_the_timeout(self):
        self.timer.shutdown()
        start = {base: self.sim.truth(base) for base in BASES}
        forward = Twist()
        forward.linear.x = SPEED
        for publisher in self.commands.values():
            publisher.publish(forward)
        self.sim.wait_sim_time(self.sim.sim_time() + 3 * COMMAND_TIMEOUT)
        middle = {base: self.sim.truth(base) for base in BASES}
        self.sim.wait_sim_time(self.sim.sim_time() + COMMAND_TIMEOUT)
        end = {base: self.sim.truth(base) for base in BASES}
        for base in BASES:
            moved = math.hypot(middle[base][0] - start[base][0], middle[base][1] - start[base][1])
            self.assertGreater(moved, SPEED * COMMAND_TIMEOUT / 2, msg=base)
            self.assertLess(moved, SPEED * COMMAND_TIMEOUT * (1 + TOLERANCE) + 0.01, msg=base)
            still = math.hypot(end[base][0] - middle[base][0], end[base][1] - middle[base][1])
            rospy.loginfo("%s: %.4f m on one command, then %.4f m", base, moved, still)
            self.assertLess(still, 0.005, msg=base)

    def test_6_a_plugin_without_its_joint_is_named_and_the_base_spawns(self):
        warnings = []
        log = rospy.Subscriber("/rosout", Log, lambda message: warnings.append(message.msg)
                               if message.level == Log.WARN else None)
        wait_until(lambda: any(connection.callerid_pub == "/gazebo"
                               for connection in log.impl.connections), "/gazebo's /rosout")
        description = subprocess.run(
            ["xacro", os.path.join(rospkg.RosPack().get_path("kobuki_style_gazebo_plugins"),
                                   "urdf", "kobuki_style.urdf.xacro"),
             "left_wheel_joint_name:=missing_joint"],
            capture_output=True, text=True, check=True).stdout
        spawn = rospy.ServiceProxy("/gazebo/spawn_urdf_model", SpawnModel)
        pose = Pose()
        pose.position.y, pose.orientation.w = -3.0, 1.0
        response = spawn("broken_base", description, "broken_base", pose, "world")
        self.assertTrue(response.success, response.status_message)
        self.sim.wait_for_model("broken_base")
        expected = ("model 'broken_base': plugin 'kobuki_style_controller' "
                    "(libgazebo_ros_kobuki_style.so) not loaded")
        wait_until(lambda: any(expected in w for w in warnings), "the plugin's warning")
        [warning] = [w for w in warnings if expected in w]
        self.assertIn("KobukiStyle(ns = broken_base/): couldn't get wheel hinge joint named "
                      "missing_joint", warning)
        publishers = dict(rosgraph.Master("/check").getSystemState()[0])
        self.assertNotIn("/broken_base/odom", publishers)

    def test_7_the_cliff_ray_reads_the_floor(self):
        """The first ray's length to the floor, from the base's true pose (it leans a little
        on a caster: pybullet's cylinders, the wheels, stand on a 1 mm margin)."""
        self.sim.pause()
        self.cliff.clear()
        pose = self.sim.pose(BASES[0])
        self.sim.unpause()
        wait_until(lambda: self.cliff, "the cliff range")
        p, q = pose.position, pose.orientation
        base = quaternion_matrix((q.x, q.y, q.z, q.w))[:3, :3]
        height = p.z + (base @ np.array([CLIFF_X, 0.0, CLIFF_HEIGHT]))[2]
        # the sensor pitched down a right angle: its ray at angle a runs along
        # (cos a, sin a, 0) of its own axes, which are the base's turned about y
        down = base @ quaternion_matrix(quaternion_from_euler(0.0, math.pi / 2, 0.0))[:3, :3]
        ray = down @ np.array([math.cos(-CLIFF_ANGLE), math.sin(-CLIFF_ANGLE), 0.0])
        expected = height / -ray[2]
        rospy.loginfo("cliff range %.4f m; the floor %.4f m along the ray", self.cliff[0],
                      expected)
        self.assertAlmostEqual(self.cliff[0], expected, delta=RANGE_RESOLUTION)

    def test_8_the_bumper_presses_at_a_wall(self):
        base = BASES[0]
        x, y, yaw = self.sim.truth(base)
        centre = WALL_GAP + WALL_SIZE[0] / 2
        wall = ("<sdf version='1.6'><model name='wall'><static>true</static><link name='link'>"
                "<collision name='collision'><geometry><box><size>{} {} {}</size></box>"
                "</geometry></collision></link></model></sdf>").format(*WALL_SIZE)
        pose = Pose()
        pose.position.x = x + centre * math.cos(yaw)
        pose.position.y = y + centre * math.sin(yaw)
        pose.position.z = WALL_SIZE[2] / 2
        pose.orientation.z, pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
        spawn = rospy.ServiceProxy("/gazebo/spawn_sdf_model", SpawnModel)
        self.assertTrue(spawn("wall", wall, "", pose, "world").success)
        self.bumpers.clear()
        wait_until(lambda: self.bumpers, "the bumpers")
        self.assertEqual(self.bumpers[-1], 0)  # nothing touched yet
        forward = Twist()
        forward.linear.x = SPEED
        type(self).command = forward
        type(self).timer = rospy.Timer(rospy.Duration(COMMAND_PERIOD), self._repeat_command)
        wait_until(lambda: self.bumpers and self.bumpers[-1] != 0, "a bumper pressed")
        self.sim.pause()
        pressed = self.bumpers[-1]
        stands = self.sim.truth(base)
        type(self).command = Twist()
        self.sim.unpause()
        rospy.ServiceProxy("/gazebo/delete_model", DeleteModel)("wall")
        self.assertEqual(pressed, BUMPER_CENTRE)
        ahead = (stands[0] - x) * math.cos(yaw) + (stands[1] - y) * math.sin(yaw)
        rospy.loginfo("%s: bumper %d with its centre %.4f m from the wall", base, pressed,
                      WALL_GAP - ahead)
        self.assertAlmostEqual(WALL_GAP - ahead, BODY_RADIUS, delta=CONTACT_TOLERANCE)

    def test_9_after_a_world_reset_it_drives_again(self):
        """reset_world turns the joints' motors off (as ODE's Joint::Reset); the plugin's
        Reset sets fmax again, as gazebo_ros_diff_drive's does, and both bases drive."""
        rospy.ServiceProxy("/gazebo/reset_world", Empty)()
        self.odometry.clear()
        wait_until(lambda: all(base in self.odometry for base in BASES), "odometry after it")
        for base in BASES:  # its odometry starts over
            position = self.odometry[base].pose.pose.position
            self.assertLess(math.hypot(position.x, position.y), 0.01, msg=base)
        elapsed, runs = self._run(SPEED, 0.0)
        for base, (before, after) in runs.items():
            travelled = math.hypot(after[0] - before[0], after[1] - before[1])
            rospy.loginfo("%s after the reset: %.4f m in %.3f s", base, travelled, elapsed)
            self.assertAlmostEqual(travelled, SPEED * elapsed, delta=SPEED * elapsed * TOLERANCE,
                                   msg=base)


def _yaw(odometry):
    q = odometry.pose.pose.orientation
    return yaw_from_quaternion((q.x, q.y, q.z, q.w))


if __name__ == "__main__":
    rostest.rosrun("gazebo_ros", "cpp_plugin_drive", CppPluginDrive)
