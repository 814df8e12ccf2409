#!/usr/bin/env python3
"""rostest node: what test/visual_tools_demo.cpp (a MoveItVisualTools user in MoveIt's tutorial
style) publishes, against the truth: marker kinds, namespaces, frame, sizes and colours as
rviz_visual_tools noetic-devel 3.9.1 makes them; the trajectory line's spheres and cylinders
against urdf_tools' forward kinematics of the trajectory's waypoints (1e-6 m); the
DisplayTrajectory and DisplayRobotState; and prompt() holding the node until a sensor_msgs/Joy
"next" arrives on /rviz_visual_tools_gui. Run by visual_tools.test (the Setup-Assistant
fixture's six-axis arm, a link traced) and visual_tools_interbotix.test (the px100 in its
namespace, the group's end-effector tip traced)."""
import threading
import time
import unittest

import numpy as np
import rospy
import rostest
from moveit_msgs.msg import DisplayRobotState, DisplayTrajectory
from sensor_msgs.msg import Joy
from tf.transformations import quaternion_matrix
from visualization_msgs.msg import Marker, MarkerArray

from urdf_tools.kinematics import link_transform
from urdf_tools.model import parse_urdf

# The node checked, its markers' frame, the link it traces and where its robot is described
# (~node, ~base_frame, ~tip_link, ~robot_description); the defaults are the six-axis fixture's
DEFAULTS = {"node": "/visual_tools_demo", "base_frame": "base_link", "tip_link": "tool0",
            "robot_description": "/robot_description"}
FK_TOLERANCE = 1e-6  # m
STARTUP_TIMEOUT = 60.0  # s: the node loads the model and waits for this checker's subscriptions
RELEASE_TIMEOUT = 10.0  # s: "next" is looked at every 0.25 s (remote_control.cpp l. 159)
# How long the node must stay in prompt() after a button that is not "next": more than the
# remote control's 0.25 s poll, so that a wrongly released wait would have published by then
HOLD_WINDOW = 1.0  # s

# rviz_visual_tools' colours (rviz_visual_tools.cpp l. 376-507) and sizes (l. 665-707)
RED = (0.8, 0.1, 0.1, 1.0)
GREEN = (0.1, 0.8, 0.1, 1.0)
BLUE = (0.1, 0.1, 0.8, 1.0)
WHITE = (1.0, 1.0, 1.0, 1.0)
LIME_GREEN = (0.6, 1.0, 0.2, 1.0)
ORANGE = (1.0, 0.5, 0.0, 1.0)
YELLOW = (1.0, 1.0, 0.0, 1.0)
SMALL, MEDIUM, LARGE, XLARGE = 0.0075, 0.01, 0.025, 0.05
TRAJECTORY_LINE_RADIUS = 0.005  # moveit_visual_tools.cpp l. 1360

# The Joy buttons (remote_control.cpp l. 65-87)
NEXT, STOP = 1, 4
JOY_BUTTONS = 5


def wait_until(condition, what, timeout):
    deadline = time.monotonic() + timeout
    while not condition():
        if time.monotonic() > deadline:
            raise AssertionError("timed out after %.0f s waiting for %s" % (timeout, what))
        if rospy.is_shutdown():
            raise AssertionError("shut down while waiting for %s" % what)
        time.sleep(0.01)


def rgba(color):
    return (color.r, color.g, color.b, color.a)


def position(pose):
    return np.array([pose.position.x, pose.position.y, pose.position.z])


def rotation(pose):
    q = pose.orientation
    return quaternion_matrix([q.x, q.y, q.z, q.w])[:3, :3]


class VisualTools(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("visual_tools_check")
        cls.lock = threading.Lock()
        cls.markers = []  # every marker in arrival order
        cls.trajectories = []
        cls.robot_states = []
        # The display topics first: the node waits for all three before publishing
        rospy.Subscriber("/move_group/display_planned_path", DisplayTrajectory, cls._keep(cls.trajectories))
        rospy.Subscriber(cls.setting("node") + "/display_robot_state", DisplayRobotState,
                         cls._keep(cls.robot_states))
        rospy.Subscriber("/rviz_visual_tools", MarkerArray, cls._on_markers, queue_size=100)
        cls.joy = rospy.Publisher("/rviz_visual_tools_gui", Joy, queue_size=10)

        cls.model = parse_urdf(rospy.get_param(cls.setting("robot_description")))
        base, tip = cls.setting("base_frame"), cls.setting("tip_link")
        cls.joints = [j.name for j in cls.model.chain(base, tip) if j.movable]
        flat = rospy.get_param(cls.setting("node") + "/trajectory")
        cls.waypoints = [flat[i:i + len(cls.joints)] for i in range(0, len(flat), len(cls.joints))]
        cls.tip_positions = [link_transform(cls.model, base, tip, dict(zip(cls.joints, w)))[:3, 3]
                             for w in cls.waypoints]

        wait_until(lambda: cls.lamp() is not None, "the node to wait in prompt() (its red lamp)", STARTUP_TIMEOUT)

    @staticmethod
    def setting(name):
        return rospy.get_param("~" + name, DEFAULTS[name])

    @classmethod
    def _keep(cls, into):
        def keep(msg):
            with cls.lock:
                into.append(msg)
        return keep

    @classmethod
    def _on_markers(cls, array):
        with cls.lock:
            cls.markers.extend(array.markers)

    @classmethod
    def named(cls, ns):
        with cls.lock:
            return [m for m in cls.markers if m.ns == ns and m.action == Marker.ADD]

    @classmethod
    def lamp(cls):
        lamps = cls.named("Waiting")
        return lamps[-1] if lamps else None

    @classmethod
    def texts(cls, text):
        return [m for m in cls.named("Text") if m.text == text]

    def assertColor(self, marker, color):
        np.testing.assert_allclose(rgba(marker.color), color, atol=1e-6)

    def assertScale(self, marker, x, y, z):
        np.testing.assert_allclose([marker.scale.x, marker.scale.y, marker.scale.z], [x, y, z], atol=1e-9)

    def test_every_marker_is_in_the_base_frame(self):
        with self.lock:
            frames = {m.header.frame_id for m in self.markers}
        self.assertEqual(frames, {self.setting("base_frame")})

    def test_delete_all_markers_comes_first(self):
        with self.lock:
            first = self.markers[0]
        self.assertEqual((first.ns, first.action), ("deleteAllMarkers", Marker.DELETEALL))

    def test_title_is_a_static_text(self):
        (title,) = self.texts("MoveItVisualTools Demo")
        self.assertEqual((title.type, title.id), (Marker.TEXT_VIEW_FACING, 0))
        self.assertScale(title, 0, 0, XLARGE)  # only a text's height counts (l. 2522-2523)
        self.assertColor(title, WHITE)
        np.testing.assert_allclose(position(title.pose), [0, 0, 1.0])

    def test_labelled_axis_is_three_cylinders_and_a_text(self):
        origin = np.array([0.28, -0.2, 0.5])
        frame = quaternion_matrix([0, 0, np.sin(0.15), np.cos(0.15)])[:3, :3]  # 0.3 rad about z
        length = MEDIUM * 10  # an axis is ten radii long (l. 1449-1450)
        cylinders = self.named("pose1")
        self.assertEqual([c.type for c in cylinders], [Marker.CYLINDER] * 3)
        for cylinder, axis, color in zip(cylinders, range(3), (RED, GREEN, BLUE)):
            self.assertColor(cylinder, color)
            self.assertScale(cylinder, MEDIUM, MEDIUM, length)
            np.testing.assert_allclose(position(cylinder.pose), origin + frame[:, axis] * length / 2, atol=1e-9)
            # a cylinder lies along its own z (upstream's y cylinder's z points along -y, l. 1484)
            self.assertAlmostEqual(abs(rotation(cylinder.pose)[:, 2] @ frame[:, axis]), 1.0, places=9)
        (label,) = self.texts("pose1")
        self.assertNotEqual(label.id, 0, "the label is not a static text")
        self.assertScale(label, 0, 0, LARGE)  # one size up from the axis' (l. 1443)
        np.testing.assert_allclose(position(label.pose), origin - 0.05, atol=1e-9)

    def test_arrow_is_ten_sizes_long(self):
        (arrow,) = self.named("Arrow")
        self.assertEqual(arrow.type, Marker.ARROW)
        self.assertScale(arrow, LARGE * 10, LARGE, LARGE)
        self.assertColor(arrow, RED)
        np.testing.assert_allclose(position(arrow.pose), [0, 0.4, 0.3])

    def test_cuboid_spans_its_corners(self):
        (cuboid,) = self.named("Cuboid")
        self.assertEqual(cuboid.type, Marker.CUBE)
        self.assertScale(cuboid, 0.1, 0.2, 0.1)
        np.testing.assert_allclose(position(cuboid.pose), [0.35, 0.4, 0.05], atol=1e-9)
        self.assertColor(cuboid, BLUE)

    def test_line_is_a_two_point_strip(self):
        (line,) = self.named("Line")
        self.assertEqual(line.type, Marker.LINE_STRIP)
        self.assertEqual([(p.x, p.y, p.z) for p in line.points], [(0, 0, 0), (0, 0, 0.5)])
        self.assertScale(line, SMALL, 0, 0)
        self.assertColor(line, YELLOW)

    def test_trajectory_line_spheres_are_the_tip_forward_kinematics(self):
        spheres = self.named("Sphere")
        self.assertEqual(len(spheres), len(self.waypoints))
        for sphere, expected in zip(spheres, self.tip_positions):
            self.assertEqual(sphere.type, Marker.SPHERE)
            self.assertScale(sphere, MEDIUM, MEDIUM, MEDIUM)
            self.assertColor(sphere, LIME_GREEN)
            np.testing.assert_allclose(position(sphere.pose), expected, atol=FK_TOLERANCE)
        self.assertEqual(len({s.id for s in spheres}), len(spheres), "each sphere its own id")

    def test_trajectory_line_cylinders_join_consecutive_tips(self):
        cylinders = self.named("Path")
        self.assertEqual(len(cylinders), len(self.waypoints) - 1)
        for cylinder, start, end in zip(cylinders, self.tip_positions, self.tip_positions[1:]):
            self.assertEqual(cylinder.type, Marker.CYLINDER)
            self.assertColor(cylinder, LIME_GREEN)
            self.assertScale(cylinder, TRAJECTORY_LINE_RADIUS, TRAJECTORY_LINE_RADIUS, np.linalg.norm(end - start))
            np.testing.assert_allclose(position(cylinder.pose), (start + end) / 2, atol=FK_TOLERANCE)
            along = rotation(cylinder.pose)[:, 2]
            np.testing.assert_allclose(along, (end - start) / np.linalg.norm(end - start), atol=FK_TOLERANCE)

    def test_display_trajectory_holds_the_waypoints(self):
        with self.lock:
            (display,) = self.trajectories
        self.assertEqual(display.model_id, self.model.name)
        (trajectory,) = display.trajectory
        self.assertEqual(list(trajectory.joint_trajectory.joint_names), self.joints)
        np.testing.assert_allclose([p.positions for p in trajectory.joint_trajectory.points], self.waypoints)
        start = dict(zip(display.trajectory_start.joint_state.name, display.trajectory_start.joint_state.position))
        self.assertEqual({name: start[name] for name in self.joints}, {name: 0.0 for name in self.joints})

    def test_robot_state_is_the_last_waypoint_in_orange(self):
        with self.lock:
            (shown,) = self.robot_states
        positions = dict(zip(shown.state.joint_state.name, shown.state.joint_state.position))
        np.testing.assert_allclose([positions[name] for name in self.joints], self.waypoints[-1])
        self.assertEqual({h.id for h in shown.highlight_links}, set(self.model.links))
        for highlight in shown.highlight_links:
            np.testing.assert_allclose(rgba(highlight.color), ORANGE, atol=1e-6)

    def test_z_prompt_holds_until_next(self):
        # Last (unittest runs tests by name): it releases the node.
        self.assertColor(self.lamp(), RED)
        wait_until(lambda: self.joy.get_num_connections() > 0, "the remote control's subscription", RELEASE_TIMEOUT)
        stop = Joy(buttons=[1 if b == STOP else 0 for b in range(JOY_BUTTONS)])
        self.joy.publish(stop)
        deadline = time.monotonic() + HOLD_WINDOW
        while time.monotonic() < deadline:
            self.assertEqual(self.texts("Demo finished"), [], "the node went on without 'next'")
            self.assertColor(self.lamp(), RED)
            time.sleep(0.01)

        self.joy.publish(Joy(buttons=[1 if b == NEXT else 0 for b in range(JOY_BUTTONS)]))
        wait_until(lambda: self.texts("Demo finished"), "the node to go on after 'next'", RELEASE_TIMEOUT)
        self.assertColor(self.lamp(), GREEN)
        (done,) = self.texts("Demo finished")
        self.assertEqual(done.id, 0)


if __name__ == "__main__":
    rostest.rosrun("moveit_visual_tools", "visual_tools", VisualTools)
