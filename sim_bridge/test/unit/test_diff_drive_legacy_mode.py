"""gazebo_ros_diff_drive's legacyMode, as Noetic's plugin reads it: true when missing (with a
warning), swapping the wheels' speeds, which an old package's swapped wheel names rely on; a
robot with its wheels named right turns the wrong way without <legacyMode>false</legacyMode>,
in Gazebo and here. Checked in the true heading."""
import math

from geometry_msgs.msg import Twist

from sim_bridge.poses import rpy_from_quaternion
from world_fixtures import run

LEGACY_FALSE = "<legacyMode>false</legacyMode>"
LEFT, RIGHT = "<leftJoint>left_wheel_joint</leftJoint>", "<rightJoint>right_wheel_joint</rightJoint>"


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


def swapped(xml):
    """An old package: the right wheel named as the plugin's left, and legacyMode true."""
    assert LEFT in xml and RIGHT in xml and LEGACY_FALSE in xml
    return (xml.replace(LEGACY_FALSE, "<legacyMode>true</legacyMode>")
            .replace(LEFT, "<leftJoint>right_wheel_joint</leftJoint>")
            .replace(RIGHT, "<rightJoint>left_wheel_joint</rightJoint>"))


def test_false_turns_as_commanded(world, bus, diff_bot_xml):
    assert turn(world, bus, diff_bot_xml()) > 0.3
    assert not [w for w in bus.warnings if "legacyMode" in w]


def test_missing_is_true_and_said_so_and_turns_a_rightly_named_robot_backwards(
        world, bus, diff_bot_xml):
    assert turn(world, bus, diff_bot_xml().replace(LEGACY_FALSE, "")) < -0.3
    (warning,) = [w for w in bus.warnings if "legacyMode" in w]
    assert "defaults to true" in warning and LEGACY_FALSE in warning


def test_true_turns_an_old_package_with_swapped_names_as_commanded(world, bus, diff_bot_xml):
    turned = turn(world, bus, swapped(diff_bot_xml(odometry_source="encoder")))
    assert turned > 0.3
    # its encoder odometry reads the wheels through the same swap: it turns as the robot did
    odometry = bus.last("/odom").pose.pose.orientation
    believed = rpy_from_quaternion((odometry.x, odometry.y, odometry.z, odometry.w))[2]
    assert abs(believed - turned) < 0.1 * abs(turned)
