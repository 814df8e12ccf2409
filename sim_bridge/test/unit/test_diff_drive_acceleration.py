"""libgazebo_ros_diff_drive.so's wheelAcceleration: m/s^2 at the wheel's rim, as gazebo_ros
reads it; `false` (seen in students' files) means no limit, as Gazebo reads it as 0. The
ramp is Noetic's (gazebo_ros_pkgs noetic-devel f9e1a46,
gazebo_plugins/src/gazebo_ros_diff_drive.cpp:277-306): at each update slot each wheel's
instructed speed moves from its measured speed's difference to the target by at most
wheelAcceleration times the seconds since the last update (0.021 s for the test robot's
50 Hz on 1 ms steps: slots 20 ms apart, each more than a period after the last), and while
either wheel is within 0.01 m/s of its target both are set to their targets at once.
Checked on pybullet's true wheel joint speeds."""
import pytest
from geometry_msgs.msg import Twist

from world_fixtures import run

WHEEL_RADIUS = 0.05  # diff_bot.urdf.xacro's wheelDiameter 0.1 m
SEPARATION = 0.34  # its wheelSeparation
PERIOD_STEPS = 20  # its updateRate 50 Hz on the world's 1 ms steps
SLOT_SECONDS = 0.021  # what each slot sees since the last: more than the 20 ms period


def drive(bus, speed):
    message = Twist()
    message.linear.x = speed
    bus.subscriptions["/cmd_vel"](message)


def rim_speeds(world):
    """(left, right) true wheel speeds at the rim, m/s."""
    states = world.model("bot").robot.joint_states(["left_wheel_joint", "right_wheel_joint"])
    return tuple(velocity * WHEEL_RADIUS for _, velocity, _ in states)


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


def test_the_ramp_moves_at_the_update_slots_by_the_acceleration_times_their_time(
        world, bus, diff_bot_xml):
    """1 m/s^2: each slot adds 1 x 0.021 m/s to both wheels and the speed holds between
    slots (the joint motors keep their target). Before: 0.001 m/s more every 1 ms step."""
    world.spawn_urdf("bot", diff_bot_xml(wheel_acceleration="1.0"), (0, 0, 0))
    run(world, 0.5)
    drive(bus, 0.5)
    speeds = []
    for _ in range(12 * PERIOD_STEPS):
        world.step()
        speeds.append(rim_speeds(world)[0])
    first = next(i for i, speed in enumerate(speeds) if speed > SLOT_SECONDS / 2)
    assert first < PERIOD_STEPS
    for slot in range(10):
        held = speeds[first + slot * PERIOD_STEPS:first + (slot + 1) * PERIOD_STEPS]
        assert held == pytest.approx([(slot + 1) * SLOT_SECONDS] * PERIOD_STEPS, abs=1e-3)


def test_a_wheel_at_its_target_lets_the_other_skip_the_ramp(world, bus, diff_bot_xml):
    """A turn about the left wheel from rest: its target, 0, is within 0.01 m/s of its
    speed, so both wheels are set to their targets at once and the right one is at
    0.34 m/s within a period, whatever wheelAcceleration (0.1 m/s^2) says (:284-289).
    Before: the right wheel ramped at 0.1 m/s^2 and had 0.005 m/s after 50 ms."""
    world.spawn_urdf("bot", diff_bot_xml(wheel_acceleration="0.1"), (0, 0, 0))
    run(world, 0.5)
    message = Twist()
    message.angular.z = 1.0
    message.linear.x = message.angular.z * SEPARATION / 2.0
    bus.subscriptions["/cmd_vel"](message)
    run(world, 0.05)
    left, right = rim_speeds(world)
    assert right == pytest.approx(message.angular.z * SEPARATION, rel=0.02)
    assert left == pytest.approx(0.0, abs=0.01)
