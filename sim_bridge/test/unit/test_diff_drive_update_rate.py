"""gazebo_ros_diff_drive reads cmd_vel into the wheels only in UpdateChild's rate branch, as
Noetic's (gazebo_ros_pkgs noetic-devel f9e1a46, gazebo_plugins/src/gazebo_ros_diff_drive.cpp:
269-271 the branch, :277-289 the command to the joints, :307 the next slot one period on): a
command given just after a slot reaches the wheels at the next one, 1/updateRate later.
Checked on pybullet's true wheel joint speeds, step by step (the test robot's updateRate is
50 Hz: 20 steps of 1 ms)."""
import pytest
from geometry_msgs.msg import Twist

from world_fixtures import run

PERIOD_STEPS = 20  # diff_bot.urdf.xacro's updateRate 50 Hz on the world's 1 ms steps
WHEEL_RADIUS = 0.05  # diff_bot.urdf.xacro's wheelDiameter 0.1 m


def command(bus, linear):
    message = Twist()
    message.linear.x = linear
    bus.subscriptions["/cmd_vel"](message)


def left_wheel_speed(world):
    [(_, velocity, _)] = world.model("bot").robot.joint_states(["left_wheel_joint"])
    return velocity


def steps_until(world, predicate, limit):
    """Steps one at a time until ``predicate(world)``; how many steps that took (None: not
    within ``limit``)."""
    for count in range(1, limit + 1):
        world.step()
        if predicate(world):
            return count
    return None


def test_a_command_just_after_an_update_reaches_the_wheels_one_period_later(world, bus,
                                                                           diff_bot_xml):
    """The first command from rest shows at some slot (at most a period away); a stop given
    just after that slot's step keeps the wheels at speed for the rest of the period and
    reaches them at the next slot, PERIOD_STEPS steps on. Before: the stop reached the
    wheels at the very next step."""
    world.spawn_urdf("bot", diff_bot_xml(), (0, 0, 0))
    run(world, 0.5)
    target = 0.3 / WHEEL_RADIUS
    command(bus, 0.3)
    first = steps_until(world, lambda w: left_wheel_speed(w) > 0.5 * target, PERIOD_STEPS + 1)
    assert first is not None
    # let the wheels settle at speed, ending just after a slot (a whole number of periods)
    run(world, 10 * PERIOD_STEPS * world.step_size)
    assert left_wheel_speed(world) == pytest.approx(target, rel=0.02)
    command(bus, 0.0)
    speeds = []
    for _ in range(PERIOD_STEPS):
        world.step()
        speeds.append(left_wheel_speed(world))
    assert speeds[:-1] == pytest.approx([target] * (PERIOD_STEPS - 1), rel=0.02)
    assert speeds[-1] < 0.5 * target
