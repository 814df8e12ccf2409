"""libgazebo_ros_diff_drive.so's wheelAcceleration: m/s^2 at the wheel's rim, as gazebo_ros
reads it; `false` (seen in students' files) means no limit, as Gazebo reads it as 0."""
import pytest
from geometry_msgs.msg import Twist

from world_fixtures import run


def drive(bus, speed):
    message = Twist()
    message.linear.x = speed
    bus.subscriptions["/cmd_vel"](message)


def true_speed(world):
    linear, _ = world.twist("bot")
    return linear[0]


def test_the_base_speeds_up_at_the_rim_acceleration(world, bus, diff_bot_xml):
    world.spawn_urdf("bot", diff_bot_xml(wheel_acceleration="1.0"), (0, 0, 0))
    run(world, 0.5)
    drive(bus, 0.5)
    run(world, 0.2)
    # 1 m/s^2 for 0.2 s: 0.2 m/s (the wheels' radius is 0.05 m; in rad/s^2 it would be 0.01)
    assert true_speed(world) == pytest.approx(0.2, abs=0.03)
    run(world, 0.8)
    assert true_speed(world) == pytest.approx(0.5, abs=0.02)


@pytest.mark.parametrize("written", ["0", "false", "False"])
def test_zero_or_false_is_no_limit(world, bus, diff_bot_xml, written):
    world.spawn_urdf("bot", diff_bot_xml(wheel_acceleration=written), (0, 0, 0))
    run(world, 0.5)
    drive(bus, 0.5)
    run(world, 0.2)
    assert true_speed(world) == pytest.approx(0.5, abs=0.03)
