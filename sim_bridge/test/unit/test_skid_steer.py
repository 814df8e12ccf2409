"""gazebo_ros_skid_steer_drive's odometry as Noetic's (gazebo_ros_pkgs noetic-devel f9e1a46,
gazebo_plugins/src/gazebo_ros_skid_steer_drive.cpp): the message's position.z is never set
(:453-454), while the transform has the true z (:441-448); the covariance is read from
<covariance_x>, <covariance_y>, <covariance_yaw> (defaults 0.0001, 0.0001, 0.01,
:208-230) onto both the pose's and the twist's diagonals, z, roll and pitch 1e12
(:460-465, :481-486)."""
import os

import pytest
from geometry_msgs.msg import Twist

from urdf_tools.xacro_loader import expand
from world_fixtures import DATA, run

TAG = "<broadcastTF>true</broadcastTF>"


def skid_bot(*parameters: str) -> str:
    xml = expand(os.path.join(DATA, "skid_bot.urdf.xacro"))
    assert TAG in xml
    return xml.replace(TAG, TAG + "".join(parameters))


def diagonal(matrix):
    return [matrix[i * 7] for i in range(6)]


def fall(world, xml, seconds=0.1):
    """Spawns the robot 1 m up and lets it fall: its true pose at every step, by time."""
    world.spawn_urdf("skid", xml, (0, 0, 1.0))
    poses = {}
    for _ in range(int(round(seconds / world.step_size))):
        world.step()
        poses[world.now_ns] = world.pose("skid")
    return poses


def test_the_odometry_position_z_is_zero_and_the_tf_has_the_true_height(world, bus):
    """gazebo_plugins/src/gazebo_ros_skid_steer_drive.cpp:453-454: the message's position
    gets x and y, z is never set (0); the broadcast transform (:441-448) has the pose's z.
    Before: the true z in the message too."""
    poses = fall(world, skid_bot())
    messages = bus.published["/odom"]
    transforms = [t for t in bus.published["/tf"] if t.child_frame_id == "base_footprint"]
    assert len(messages) == len(transforms) >= 9
    for message, transform in zip(messages, transforms):
        (x, y, z), _ = poses[message.header.stamp.to_nsec()]
        position = message.pose.pose.position
        assert (position.x, position.y) == pytest.approx((x, y), abs=1e-9)
        assert position.z == 0.0
        assert transform.transform.translation.z == pytest.approx(z, abs=1e-9)
    assert transforms[-1].transform.translation.z < 0.97  # falling: z is not 0 there


def test_the_covariance_tags_are_read_onto_both_diagonals(world, bus):
    """gazebo_plugins/src/gazebo_ros_skid_steer_drive.cpp:208-230 read <covariance_x>,
    <covariance_y>, <covariance_yaw>; :460-465 and :481-486 put them on the pose's and the
    twist's diagonals, 1e12 for z, roll and pitch."""
    fall(world, skid_bot("<covariance_x>0.5</covariance_x>", "<covariance_y>0.25</covariance_y>",
                         "<covariance_yaw>0.125</covariance_yaw>"))
    odometry = bus.last("/odom")
    expected = [0.5, 0.25, 1e12, 1e12, 1e12, 0.125]
    assert diagonal(odometry.pose.covariance) == expected
    assert diagonal(odometry.twist.covariance) == expected
    assert not [w for w in bus.warnings if "does not read" in w]


def test_the_covariance_defaults(world, bus):
    """gazebo_plugins/src/gazebo_ros_skid_steer_drive.cpp:208 (0.0001), :216 (0.0001),
    :224 (0.01)."""
    fall(world, skid_bot())
    odometry = bus.last("/odom")
    expected = [0.0001, 0.0001, 1e12, 1e12, 1e12, 0.01]
    assert diagonal(odometry.pose.covariance) == expected
    assert diagonal(odometry.twist.covariance) == expected
    off_diagonal = [v for i, v in enumerate(odometry.pose.covariance) if i % 7]
    assert off_diagonal == [0.0] * 30


def wheel_speeds(world, name="skid"):
    """The four wheels' true joint speeds (rad/s): left front, right front, left rear,
    right rear."""
    robot = world.model(name).robot
    joints = [f"{wheel}_wheel_joint" for wheel in ("left_front", "right_front", "left_rear",
                                                   "right_rear")]
    return [velocity for _, velocity, _ in robot.joint_states(joints)]


def test_reset_world_keeps_the_last_command(world, bus):
    """Noetic's plugin has no Reset (gazebo_plugins/include/gazebo_plugins/
    gazebo_ros_skid_steer_drive.h:68-77 declares Load, UpdateChild and FiniChild only), so
    after reset_world the wheels go on at the last command's speed from the spawn pose.
    Before: the command was dropped and the wheels stopped."""
    world.spawn_urdf("skid", skid_bot(), (0, 0, 0.1))
    run(world, 0.3)
    message = Twist()
    message.linear.x = 0.4
    bus.subscriptions["/cmd_vel"](message)
    run(world, 0.5)
    world.reset()
    assert wheel_speeds(world) == pytest.approx([0.0] * 4, abs=1e-9)  # reset: at rest
    run(world, 0.5)
    assert wheel_speeds(world) == pytest.approx([0.4 / 0.08] * 4, rel=0.02)
    (x, _, _), _ = world.pose("skid")
    assert x > 0.1


def test_a_command_just_after_an_update_reaches_the_wheels_one_period_later(world, bus):
    """gazebo_plugins/src/gazebo_ros_skid_steer_drive.cpp:350-352, :363-382: the wheels get
    the last command only in UpdateChild's rate branch (updateRate 100 Hz: every 10 steps of
    1 ms). A stop given just after a slot's step keeps the wheels turning for the rest of the
    period. Before: it reached them at the very next step."""
    world.spawn_urdf("skid", skid_bot(), (0, 0, 0.1))
    run(world, 0.3)
    period_steps = 10
    target = 0.4 / 0.08
    message = Twist()
    message.linear.x = 0.4
    bus.subscriptions["/cmd_vel"](message)
    for first in range(1, period_steps + 2):
        world.step()
        if wheel_speeds(world)[0] > 0.5 * target:
            break
    assert first <= period_steps
    run(world, 20 * period_steps * world.step_size)  # settled, just after a slot
    assert wheel_speeds(world) == pytest.approx([target] * 4, rel=0.02)
    bus.subscriptions["/cmd_vel"](Twist())
    speeds = []
    for _ in range(period_steps):
        world.step()
        speeds.append(wheel_speeds(world)[0])
    assert speeds[:-1] == pytest.approx([target] * (period_steps - 1), rel=0.02)
    assert speeds[-1] < 0.5 * target
