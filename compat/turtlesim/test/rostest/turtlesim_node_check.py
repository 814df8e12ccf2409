#!/usr/bin/env python3
"""rostest node: ``rosrun turtlesim turtlesim_node`` on a virtual screen (Xvfb, started here
as the workspace's e2e tests start it: tools/headless.py), driven through its topics and
services as the tutorials drive it, its window captured with ImageMagick.

Facts checked are turtlesim 0.10.2's (ros/ros_tutorials noetic-devel db63288): turtle1 in
the middle (turtle_frame.cpp:114), 0.016 m per 16 ms update at 1 m/s (:59, :255,
turtle.cpp:157-163) for one second of wall time after a command (turtle.cpp:148-153), the
wall's clamp and warning (turtle.cpp:165-173), spawn's naming and refusal (turtle_frame.cpp
:134-200), kill, reset (:273-281), clear and the background parameters (:64-75, :202-214),
set_pen (turtle.cpp:75-91), the teleports (turtle.cpp:117-146), color_sensor
(turtle.cpp:185-192) and mimic (tutorials/mimic.cpp:17-31, started by the .test file with
the roslaunch tutorial's remaps).
"""
import contextlib
import math
import os
import subprocess
import sys
import tempfile
import threading
import time
import unittest

import rosgraph
import rospy
import rostest
from geometry_msgs.msg import Twist
from std_srvs.srv import Empty
from turtlesim.msg import Color, Pose
from turtlesim.srv import Kill, SetPen, Spawn, TeleportAbsolute, TeleportRelative

from course_grader.screenshot import capture, find_window
from sim_bridge.testing import wait_until

# tools/ of this workspace (not a package): its Xvfb start and pixel counts
REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.realpath(__file__))))))
sys.path.insert(0, os.path.join(REPO, "tools"))
import headless  # noqa: E402

WAIT = 30.0  # s (wall): the longest any one condition may take
DT = 0.016  # m per update at 1 m/s
WIDTH = 499 / 45  # m
CENTRE = WIDTH / 2
BACKGROUND = (69, 86, 255)
PEN = (179, 184, 255)


class Turtles:
    """The latest pose and colour of each turtle, and every pose of one turtle recorded
    while ``record`` names it."""

    def __init__(self):
        self.poses, self.colours, self._subscribers = {}, {}, {}
        self.recorded, self.record = [], None
        self._lock = threading.Lock()

    def watch(self, name):
        if name in self._subscribers:
            return
        self._subscribers[name] = (
            rospy.Subscriber(f"/{name}/pose", Pose, self._pose, name, queue_size=200),
            rospy.Subscriber(f"/{name}/color_sensor", Color,
                             lambda colour: self.colours.__setitem__(name, colour),
                             queue_size=1))

    def _pose(self, pose, name):
        with self._lock:
            self.poses[name] = pose
            if self.record == name:
                self.recorded.append((time.monotonic(), pose))

    def at(self, name, x, y, theta=None, tolerance=1e-4):
        pose = self.poses.get(name)
        return pose is not None and abs(pose.x - x) < tolerance and abs(pose.y - y) < tolerance \
            and (theta is None or abs(pose.theta - theta) < tolerance)


def services_of(name):
    """The services the master lists under /<name>/."""
    state = rosgraph.Master("/turtlesim_node_check").getSystemState()
    return sorted(service for service, _ in state[2] if service.startswith(f"/{name}/"))


class TurtlesimNode(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("turtlesim_node_check")
        cls.stack = contextlib.ExitStack()
        cls.display = cls.stack.enter_context(headless.virtual_display(800, 600))
        cls.folder = os.environ.get("ROS_HOME") or cls.stack.enter_context(
            tempfile.TemporaryDirectory())
        cls.log_path = os.path.join(cls.folder, "turtlesim_node.log")
        with open(cls.log_path, "w", encoding="utf-8") as log:
            cls.node = subprocess.Popen(["rosrun", "turtlesim", "turtlesim_node"],
                                        env=dict(os.environ, DISPLAY=cls.display),
                                        stdout=log, stderr=subprocess.STDOUT)
        cls.turtles = Turtles()
        cls.turtles.watch("turtle1")
        cls.cmd_vel = rospy.Publisher("/turtle1/cmd_vel", Twist, queue_size=10)
        for service in ("/reset", "/clear", "/spawn", "/kill", "/turtle1/teleport_absolute"):
            rospy.wait_for_service(service, timeout=WAIT)
        cls.reset = rospy.ServiceProxy("/reset", Empty)
        cls.clear = rospy.ServiceProxy("/clear", Empty)
        cls.spawn = rospy.ServiceProxy("/spawn", Spawn)
        cls.kill = rospy.ServiceProxy("/kill", Kill)

    @classmethod
    def tearDownClass(cls):
        cls.node.terminate()
        try:
            cls.node.wait(timeout=WAIT)
        except subprocess.TimeoutExpired:
            cls.node.kill()
            cls.node.wait()
        cls.stack.close()

    def setUp(self):
        self.assertIsNone(self.node.poll(), self.node_log())
        rospy.set_param("/turtlesim/background_r", BACKGROUND[0])
        rospy.set_param("/turtlesim/background_g", BACKGROUND[1])
        rospy.set_param("/turtlesim/background_b", BACKGROUND[2])
        self.reset()
        wait_until(lambda: self.turtles.at("turtle1", CENTRE, CENTRE, 0.0),
                   "turtle1 in the middle after reset", WAIT)

    def node_log(self):
        with open(self.log_path, encoding="utf-8", errors="replace") as log:
            return log.read()

    def turtle_service(self, name, service, kind):
        rospy.wait_for_service(f"/{name}/{service}", timeout=WAIT)
        return rospy.ServiceProxy(f"/{name}/{service}", kind)

    def drive(self, name, linear, angular=0.0):
        """Publishes one Twist on turtle1/cmd_vel; the wall time it was sent, once turtle
        ``name``'s pose shows the velocities. Sent again while it does not within a few
        seconds (a connection to turtle1's subscriber of before a reset, closing, may take
        the first one)."""
        wait_until(lambda: self.cmd_vel.get_num_connections() > 0, "turtlesim on cmd_vel",
                   WAIT)
        twist = Twist()
        twist.linear.x, twist.angular.z = linear, angular
        for _ in range(5):
            sent = time.monotonic()
            self.cmd_vel.publish(twist)
            try:
                wait_until(lambda: self.turtles.poses[name].linear_velocity == linear
                           and self.turtles.poses[name].angular_velocity == angular,
                           f"{name} driven at {linear} m/s, {angular} rad/s", 3.0)
                return sent
            except AssertionError:
                continue
        raise AssertionError(f"{name} never drove at {linear} m/s, {angular} rad/s")

    def test_a_start_as_upstream(self):
        self.assertEqual([rospy.get_param(f"/turtlesim/background_{c}") for c in "rgb"],
                         list(BACKGROUND))
        pose = self.turtles.poses["turtle1"]
        self.assertAlmostEqual(pose.x, 5.544445, places=5)
        self.assertEqual((pose.linear_velocity, pose.angular_velocity), (0.0, 0.0))
        wait_until(lambda: "turtle1" in self.turtles.colours, "turtle1's color_sensor", WAIT)
        colour = self.turtles.colours["turtle1"]
        self.assertEqual((colour.r, colour.g, colour.b), BACKGROUND)
        self.assertEqual(services_of("turtle1"), ["/turtle1/set_pen",
                                                  "/turtle1/teleport_absolute",
                                                  "/turtle1/teleport_relative"])
        self.assertIn("Starting turtlesim with node name /turtlesim", self.node_log())

    def test_b_one_command_drives_one_second_at_v_dt_per_update(self):
        turtles = self.turtles
        with turtles._lock:
            turtles.recorded, turtles.record = [], "turtle1"
        sent = self.drive("turtle1", 1.0)
        wait_until(lambda: turtles.recorded[-1][1].linear_velocity == 0.0,
                   "turtle1 stopping a second after the command", WAIT)
        turtles.record = None
        moving = [(t, p) for t, p in turtles.recorded if p.linear_velocity == 1.0]
        xs = [CENTRE] + [p.x for _, p in moving]
        steps = [b - a for a, b in zip(xs, xs[1:])]
        # each update moves 1.0 m/s x 0.016 s (a pose lost on the way shows as two steps)
        for step in steps:
            self.assertAlmostEqual(step / DT, round(step / DT), delta=1e-3, msg=steps)
        self.assertGreater(sum(round(step / DT) == 1 for step in steps), len(steps) // 2)
        travelled = turtles.poses["turtle1"].x - CENTRE
        self.assertAlmostEqual(travelled, xs[-1] - CENTRE, places=5)
        # one second of wall time at 1 m/s: 62 or 63 updates of 16 ms, fewer when the
        # machine is slow to run the Qt timer (upstream's fixed step: the turtle lags then)
        self.assertLessEqual(travelled, 64 * DT)
        self.assertGreater(travelled, 0.5)
        stopped_after = moving[-1][0] - sent
        self.assertGreater(stopped_after, 0.95, "the command lasts one second")
        self.assertLess(stopped_after, 2.0, "the command lasts one second")
        pose = turtles.poses["turtle1"]
        self.assertAlmostEqual(pose.y, CENTRE, places=5)
        self.assertEqual(pose.theta, 0.0)

    def test_c_spawn_names_and_refuses(self):
        self.assertEqual(self.spawn(1.0, 1.0, 0.0, "").name, "turtle2")
        self.assertEqual(self.spawn(1.0, 2.0, 0.5, "leo").name, "leo")
        self.turtles.watch("leo")
        wait_until(lambda: self.turtles.at("leo", 1.0, 2.0, 0.5), "leo at (1, 2, 0.5)", WAIT)
        with self.assertRaises(rospy.ServiceException) as refused:
            self.spawn(3.0, 3.0, 0.0, "leo")
        self.assertIn("a turtle named 'leo' already exists", str(refused.exception))
        wait_until(lambda: "A turtled named [leo] already exists" in self.node_log(),
                   "upstream's error in the log", WAIT)
        self.assertEqual(self.spawn(1.0, 1.0, 0.0, "").name, "turtle3")
        with self.assertRaises(rospy.ServiceException) as illegal:
            self.spawn(1.0, 1.0, 0.0, "my turtle")
        self.assertIn("'my turtle' is not a legal ROS name", str(illegal.exception))

    def test_d_kill_removes_a_turtles_topics_and_refuses_the_unknown(self):
        self.spawn(1.0, 1.0, 0.0, "leo")
        self.assertEqual(len(services_of("leo")), 3)
        self.kill("leo")
        wait_until(lambda: services_of("leo") == [], "leo's services gone", WAIT)
        with self.assertRaises(rospy.ServiceException):
            self.kill("leo")
        self.assertIn("Tried to kill turtle [leo], which does not exist", self.node_log())
        self.assertEqual(self.spawn(1.0, 1.0, 0.0, "leo").name, "leo")  # the name is free

    def test_e_teleports_and_the_wall(self):
        absolute = self.turtle_service("turtle1", "teleport_absolute", TeleportAbsolute)
        relative = self.turtle_service("turtle1", "teleport_relative", TeleportRelative)
        absolute(2.0, 3.0, 1.0)
        wait_until(lambda: self.turtles.at("turtle1", 2.0, 3.0, 1.0), "turtle1 at (2, 3, 1)",
                   WAIT)
        relative(1.0, 0.5)
        wait_until(lambda: self.turtles.at("turtle1", 2.0 + math.cos(1.5), 3.0 + math.sin(1.5),
                                           1.5), "turtle1 one metre along 1.5 rad", WAIT)
        absolute(-1.0, 4.0, 0.0)
        wait_until(lambda: self.turtles.at("turtle1", 0.0, 4.0, 0.0), "turtle1 clamped to x=0",
                   WAIT)
        wait_until(lambda: "Oh no! I hit the wall! (Clamping from [x=-1.000000" in
                   self.node_log(), "upstream's warning", WAIT)
        absolute(3.0, 20.0, 0.0)  # above the top: stopped there by the y flip
        wait_until(lambda: self.turtles.at("turtle1", 3.0, WIDTH), "turtle1 at the top", WAIT)

    def colour_under(self, name, rgb):
        def reads():
            colour = self.turtles.colours.get(name)
            return colour is not None and (colour.r, colour.g, colour.b) == rgb
        wait_until(reads, f"{name}'s color_sensor reading {rgb}", WAIT)

    def test_f_pen_clear_and_background(self):
        self.turtles.watch("turtle1")
        absolute = self.turtle_service("turtle1", "teleport_absolute", TeleportAbsolute)
        set_pen = self.turtle_service("turtle1", "set_pen", SetPen)
        self.colour_under("turtle1", BACKGROUND)
        absolute(3.0, 3.0, 0.0)  # the jump is drawn with the default pen
        self.colour_under("turtle1", PEN)
        set_pen(255, 0, 0, 5, 0)
        absolute(4.0, 4.0, 0.0)
        self.colour_under("turtle1", (255, 0, 0))
        set_pen(0, 255, 0, 5, 1)  # off: nothing drawn
        absolute(8.0, 2.0, 0.0)
        self.colour_under("turtle1", BACKGROUND)
        absolute(3.5, 3.5, 0.0)  # back on the red line, read, not drawn
        self.colour_under("turtle1", (255, 0, 0))
        rospy.set_param("/turtlesim/background_r", 10)
        rospy.set_param("/turtlesim/background_g", 20)
        rospy.set_param("/turtlesim/background_b", 30)
        self.clear()
        self.colour_under("turtle1", (10, 20, 30))
        rospy.set_param("/turtlesim/background_g", "green")  # named, and its default used
        self.clear()
        self.colour_under("turtle1", (10, 86, 30))
        wait_until(lambda: "~background_g: 'green' is not a number" in self.node_log(),
                   "the bad parameter named in the log", WAIT)

    def test_g_reset_starts_over(self):
        self.spawn(1.0, 1.0, 0.0, "")
        self.spawn(1.0, 1.0, 0.0, "leo")
        absolute = self.turtle_service("turtle1", "teleport_absolute", TeleportAbsolute)
        absolute(2.0, 2.0, 2.0)
        wait_until(lambda: self.turtles.at("turtle1", 2.0, 2.0, 2.0), "turtle1 moved", WAIT)
        self.colour_under("turtle1", PEN)
        self.reset()
        wait_until(lambda: self.turtles.at("turtle1", CENTRE, CENTRE, 0.0),
                   "turtle1 back in the middle", WAIT)
        self.colour_under("turtle1", BACKGROUND)
        self.assertEqual((services_of("leo"), services_of("turtle2")), ([], []))
        self.assertEqual(self.spawn(1.0, 1.0, 0.0, "").name, "turtle2")  # counting from 0

    def test_h_mimic_follows_turtle1(self):
        """mimic.cpp through the roslaunch tutorial's remaps (input:=turtle1,
        output:=follower): the follower is commanded with turtle1's velocities."""
        self.spawn(2.0, 2.0, 0.0, "follower")
        self.turtles.watch("follower")
        wait_until(lambda: self.turtles.at("follower", 2.0, 2.0, 0.0), "the follower", WAIT)
        self.drive("follower", 1.0, 1.0)  # through mimic
        wait_until(lambda: self.turtles.poses["turtle1"].linear_velocity == 0.0,
                   "turtle1 stopping", WAIT)
        wait_until(lambda: self.turtles.poses["follower"].linear_velocity == 0.0,
                   "the follower stopping", WAIT)
        one, follower = self.turtles.poses["turtle1"], self.turtles.poses["follower"]
        # the same arc, a few updates behind: about the same turn
        self.assertGreater(follower.theta, 0.5)
        self.assertAlmostEqual(follower.theta, one.theta, delta=0.2)

    def test_i_the_window_shows_the_turtle_and_its_trail(self):
        absolute = self.turtle_service("turtle1", "teleport_absolute", TeleportAbsolute)
        set_pen = self.turtle_service("turtle1", "set_pen", SetPen)
        absolute(CENTRE, 9.0, 0.0)  # a straight 3.46 m (155 px) trail up, default pen
        set_pen(255, 0, 0, 5, 0)
        absolute(9.0, 9.0, -math.pi / 2)  # 3.46 m right, red, 5 px
        wait_until(lambda: self.turtles.at("turtle1", 9.0, 9.0, -math.pi / 2, 1e-3),
                   "turtle1 at the corner", WAIT)
        path = os.path.join(self.folder, "turtlesim_window.png")

        def shot():
            window = find_window(self.display, "TurtleSim")
            if window is None:
                return None
            capture(self.display, path,
                    f"{window.width}x{window.height}+{window.x}+{window.y}")
            return window if headless.pixels_near(path, "#ff0000", "1%") > 0 else None

        window = wait_until_value(shot, "the window showing the red trail")
        self.assertEqual((window.width, window.height), (500, 500))
        length = 3.46 * 45
        default_trail = headless.pixels_near(path, "#b3b8ff", "1%")
        red_trail = headless.pixels_near(path, "#ff0000", "1%")
        self.assertGreater(default_trail, 0.9 * 3 * length, path)
        self.assertLess(default_trail, 1.1 * 3 * length + 30, path)
        # the turtle covers the red trail's end
        self.assertGreater(red_trail, 0.9 * 5 * length - 5 * 25, path)
        background = headless.pixels_near(path, "#4556ff", "1%")
        turtle = 500 * 500 - background - default_trail - red_trail
        self.assertGreater(turtle, 300, f"the turtle drawn in {path}")
        self.assertLess(turtle, 45 * 45, path)


def wait_until_value(condition, what):
    found = []
    wait_until(lambda: found.append(condition()) or found[-1], what, WAIT)
    return found[-1]


if __name__ == "__main__":
    rostest.rosrun("turtlesim", "turtlesim_node", TurtlesimNode)
