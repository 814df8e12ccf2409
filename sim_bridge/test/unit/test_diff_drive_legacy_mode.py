"""gazebo_ros_diff_drive's wheel speeds as Noetic's plugin computes them, whatever
``<legacyMode>`` says: Noetic reads no such tag (gazebo_plugins noetic-devel,
gazebo_ros_diff_drive.cpp, getWheelVelocities: the joint <leftJoint> names turns at
v - w s/2, the one <rightJoint> names at v + w s/2; only kinetic-devel read legacyMode,
default true, and swapped them). So +w turns a robot whose <leftJoint> is its left wheel
counter-clockwise with the tag missing, true or false, and a Kinetic-era package that swapped
its joints' names (relying on legacyMode) turns clockwise, as on Noetic's Gazebo. Checked in
the true heading."""
import math

import pytest
from geometry_msgs.msg import Twist

from sim_bridge.poses import rpy_from_quaternion
from world_fixtures import run

LEGACY_FALSE = "<legacyMode>false</legacyMode>"
LEFT, RIGHT = "<leftJoint>left_wheel_joint</leftJoint>", "<rightJoint>right_wheel_joint</rightJoint>"
WRITTEN = {"missing": "", "true": "<legacyMode>true</legacyMode>", "false": LEGACY_FALSE}


def yaw(world):
    return rpy_from_quaternion(world.pose("bot")[1])[2]


def turn(world, bus, xml, rate=0.5, seconds=1.0):
    """The true heading change (rad) after turning at ``rate`` for ``seconds``."""
    world.spawn_urdf("bot", xml, (0, 0, 0.06))
    run(world, 0.3)
    start = yaw(world)
    twist = Twist()
    twist.angular.z = rate
    bus.subscriptions["/cmd_vel"](twist)
    run(world, seconds)
    return math.remainder(yaw(world) - start, 2 * math.pi)


def believed_yaw(bus):
    odometry = bus.last("/odom").pose.pose.orientation
    return rpy_from_quaternion((odometry.x, odometry.y, odometry.z, odometry.w))[2]


def swapped(xml):
    """A Kinetic-era package: the right wheel named as the plugin's left, legacyMode true."""
    assert LEFT in xml and RIGHT in xml and LEGACY_FALSE in xml
    return (xml.replace(LEGACY_FALSE, WRITTEN["true"])
            .replace(LEFT, "<leftJoint>right_wheel_joint</leftJoint>")
            .replace(RIGHT, "<rightJoint>left_wheel_joint</rightJoint>"))


@pytest.mark.parametrize("written", sorted(WRITTEN))
def test_plus_w_turns_counter_clockwise_whatever_legacy_mode_says(world, bus, diff_bot_xml,
                                                                  written):
    xml = diff_bot_xml().replace(LEGACY_FALSE, WRITTEN[written])
    assert (LEGACY_FALSE in xml) == (written == "false")
    turned = turn(world, bus, xml)
    assert 0.3 < turned < 0.6, f"legacyMode {written}: turned {turned:+.3f} rad for +0.5 rad/s"
    assert not [w for w in bus.warnings if "legacyMode" in w]
    notes = [d for d in bus.debugs if "<legacyMode>" in d]
    assert len(notes) == (0 if written == "missing" else 1)
    assert all("ignores <legacyMode>" in note and "Noetic" in note for note in notes)


def test_a_kinetic_package_with_swapped_joint_names_turns_clockwise_as_on_noetic(
        world, bus, diff_bot_xml):
    turned = turn(world, bus, swapped(diff_bot_xml(odometry_source="encoder")))
    assert turned < -0.3
    # Noetic's encoder odometry reads the joints as named (UpdateOdometryEncoder): the joint
    # called left spins backwards, so it believes the robot turned counter-clockwise
    believed = believed_yaw(bus)
    assert believed > 0.3 and abs(believed + turned) < 0.1 * abs(turned)
