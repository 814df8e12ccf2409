"""gazebo_ros_planar_move as Noetic's (gazebo_ros_pkgs noetic-devel f9e1a46,
gazebo_plugins/src/gazebo_ros_planar_move.cpp), checked by what arrives on the topics in
simulated time: the model's vertical velocity is set to 0 every update (:204-207); the
odometry is sent on /tf every time it is published, with no tag to turn it off (:279-282);
its covariance is hard-coded, the twist's left 0 (:292-297); an odometryRate of 0 or less
publishes nothing (:212); position.z is never set (:285-286); the twist is the difference
of the pose between two publications (:300-322); cmdTimeout of 0 or more zeroes the
command once it is older than that (:189-197)."""
import math

import pytest
from geometry_msgs.msg import Twist

from sim_bridge.poses import yaw_from_quaternion
from world_fixtures import run

POSE_COVARIANCE = [0.0] * 36
for _index, _value in ((0, 1e-5), (7, 1e-5), (14, 1e12), (21, 1e12), (28, 1e12), (35, 1e-3)):
    POSE_COVARIANCE[_index] = _value


def robot(*parameters: str) -> str:
    """A frictionless 4 kg box moved by planar_move with the given plugin parameters."""
    return f"""<robot name="box_bot">
      <link name="base_link">
        <collision><origin xyz="0 0 0.05"/><geometry><box size="0.4 0.4 0.1"/></geometry>
        </collision>
        <inertial><origin xyz="0 0 0.05"/><mass value="4"/>
          <inertia ixx="0.0567" ixy="0" ixz="0" iyy="0.0567" iyz="0" izz="0.1067"/></inertial>
      </link>
      <gazebo reference="base_link"><mu1>0</mu1><mu2>0</mu2></gazebo>
      <gazebo><plugin name="move" filename="libgazebo_ros_planar_move.so">
        {''.join(parameters)}</plugin></gazebo></robot>"""


def command(bus, forward=0.0, sideways=0.0, turn=0.0):
    message = Twist()
    message.linear.x, message.linear.y, message.angular.z = forward, sideways, turn
    bus.subscriptions["/cmd_vel"](message)


def odometry_transforms(bus):
    return [t for t in bus.published.get("/tf", []) if t.child_frame_id == "base_footprint"]


def test_the_vertical_velocity_is_set_to_zero_every_update(world, bus):
    """gazebo_plugins/src/gazebo_ros_planar_move.cpp:204-207: SetLinearVel(x', y', 0) every
    world update, so a model spawned 1 m up does not fall: each step starts at rest
    vertically and gravity moves it g dt² (about 10 um a 1 ms step). Before: its vertical
    velocity was kept and it fell to the ground."""
    world.spawn_urdf("bot", robot(), (0, 0, 1.0))
    run(world, 0.5)
    (_, _, z), _ = world.pose("bot")
    assert z == pytest.approx(1.0 - 500 * 9.8 * 0.001 ** 2, abs=1e-4)
    command(bus, forward=0.2, sideways=0.1)
    run(world, 0.5)
    (x, y, z), _ = world.pose("bot")
    assert (x, y) == pytest.approx((0.1, 0.05), abs=1e-3)
    assert z > 0.989


def test_the_odometry_is_always_sent_on_tf_and_publish_odometry_tf_is_not_read(world, bus):
    """gazebo_plugins/src/gazebo_ros_planar_move.cpp:279-282: publishOdometry sends
    odom → base_footprint every time, and Load (:44-127) reads no <publishOdometryTf>, so
    false turns nothing off; the spawn names the tag as one the plugin does not read.
    Before: the tag was read and false sent no transform."""
    world.spawn_urdf("bot", robot("<publishOdometryTf>false</publishOdometryTf>"), (0, 0, 0))
    run(world, 0.5)
    odometry = bus.published["/odom"]
    transforms = odometry_transforms(bus)
    assert len(transforms) == len(odometry) == 9  # 20 Hz: every 51 ms
    last = transforms[-1]
    assert last.header.frame_id == "odom" and last.header.stamp == odometry[-1].header.stamp
    assert any("does not read <publishOdometryTf>" in w for w in bus.warnings)


def test_the_covariance_is_hard_coded_and_the_tags_are_not_read(world, bus):
    """gazebo_plugins/src/gazebo_ros_planar_move.cpp:292-297: the pose covariance is
    1e-5, 1e-5, 1e12, 1e12, 1e12, 1e-3 on the diagonal whatever the file says; the twist's
    is never set (all 0); Load reads no <covariance_x>, <covariance_y>, <covariance_yaw>.
    Before: the three tags set both diagonals (defaults 0.0001, 0.0001, 0.01)."""
    world.spawn_urdf("bot", robot("<covariance_x>0.5</covariance_x>",
                                  "<covariance_y>0.5</covariance_y>",
                                  "<covariance_yaw>0.5</covariance_yaw>"), (0, 0, 0))
    run(world, 0.2)
    odometry = bus.last("/odom")
    assert list(odometry.pose.covariance) == POSE_COVARIANCE
    assert list(odometry.twist.covariance) == [0.0] * 36
    (warning,) = [w for w in bus.warnings if "does not read" in w]
    assert all(f"<covariance_{axis}>" in warning for axis in ("x", "y", "yaw"))


@pytest.mark.parametrize("rate", ["0", "-1"])
def test_an_odometry_rate_of_zero_or_less_publishes_nothing(world, bus, rate):
    """gazebo_plugins/src/gazebo_ros_planar_move.cpp:212: odometry (and its TF) only when
    odometry_rate_ > 0. The command still moves the model (:204-208). Before: 0 and less
    published every step."""
    world.spawn_urdf("bot", robot(f"<odometryRate>{rate}</odometryRate>"), (0, 0, 0))
    command(bus, forward=0.2)
    run(world, 0.5)
    assert "/odom" not in bus.published and not odometry_transforms(bus)
    assert world.pose("bot")[0][0] == pytest.approx(0.1, abs=1e-3)


def test_odometry_is_published_once_more_than_a_period_has_passed(world, bus):
    """gazebo_plugins/src/gazebo_ros_planar_move.cpp:218-228: published when the time since
    the last publication (the load at first) is more than 1/odometryRate, then that time
    becomes the last: 20 Hz on 1 ms steps is every 51 ms, stamped with the simulated time.
    Before: at the first step and every 50 ms."""
    world.spawn_urdf("bot", robot(), (0, 0, 0))
    run(world, 0.5)
    stamps = [m.header.stamp.to_nsec() for m in bus.published["/odom"]]
    assert stamps == [51_000_000 * k for k in range(1, 10)]


def test_the_odometry_position_z_is_zero_and_the_tf_has_the_true_height(world, bus):
    """gazebo_plugins/src/gazebo_ros_planar_move.cpp:285-286: the message's position gets x
    and y only (z stays 0); the transform (:277-282) has the true z. Before: the true z in
    both."""
    world.spawn_urdf("bot", robot(), (1.0, 2.0, 0.3))
    run(world, 0.153)  # the third message's step
    odometry = bus.last("/odom")
    assert odometry.header.stamp.to_nsec() == world.now_ns
    position = odometry.pose.pose.position
    (x, y, z), _ = world.pose("bot")
    assert (position.x, position.y, position.z) == pytest.approx((x, y, 0.0), abs=1e-6)
    assert position.z == 0.0
    assert odometry_transforms(bus)[-1].transform.translation.z == pytest.approx(z, abs=1e-4)
    assert z > 0.29


def test_the_odometry_twist_is_the_pose_difference_between_publications(world, bus):
    """gazebo_plugins/src/gazebo_ros_planar_move.cpp:300-322: linear = (p - p_last) / dt in
    the world, turned by the current yaw into the body (x = cos ψ dx + sin ψ dy, y = cos ψ dy
    - sin ψ dx); angular.z = the unwrapped change of yaw / dt; p_last the pose at the last
    publication (the load's at first), dt the time since. Before: the body's true velocity
    (turning at 0.5 rad/s, 3 mm/s off sideways)."""
    world.spawn_urdf("bot", robot(), (0, 0, 0))
    command(bus, forward=0.2, sideways=0.1, turn=0.5)
    poses = {0: world.pose("bot")}
    for _ in range(400):
        world.step()
        poses[world.now_ns] = world.pose("bot")
    messages = bus.published["/odom"]
    assert len(messages) == 7
    last_ns = 0
    for message in messages:
        now_ns = message.header.stamp.to_nsec()
        (x0, y0, _), q0 = poses[last_ns]
        (x1, y1, _), q1 = poses[now_ns]
        dt = (now_ns - last_ns) / 1e9
        yaw0, yaw1 = yaw_from_quaternion(q0), yaw_from_quaternion(q1)
        vx, vy = (x1 - x0) / dt, (y1 - y0) / dt
        twist = message.twist.twist
        assert twist.linear.x == pytest.approx(math.cos(yaw1) * vx + math.sin(yaw1) * vy,
                                               abs=1e-6)
        assert twist.linear.y == pytest.approx(math.cos(yaw1) * vy - math.sin(yaw1) * vx,
                                               abs=1e-6)
        assert twist.angular.z == pytest.approx(math.remainder(yaw1 - yaw0, math.tau) / dt,
                                                abs=1e-5)
        last_ns = now_ns
    # the chord of the turn, not the tangent: the sideways speed differs from the 0.1
    # commanded by about v ω dt / 2
    assert abs(messages[-1].twist.twist.linear.y - 0.1) > 1e-3


def test_a_turn_faster_than_the_odometry_can_tell_reports_the_command(world, bus):
    """gazebo_plugins/src/gazebo_ros_planar_move.cpp:303-307: when the commanded rate
    exceeds π/dt the change of yaw is ambiguous and angular.z is the command itself."""
    world.spawn_urdf("bot", robot(), (0, 0, 0))
    command(bus, turn=100.0)
    run(world, 0.2)
    assert bus.last("/odom").twist.twist.angular.z == 100.0


def displacement_after_a_command(world, bus, timeout=None, seconds=0.5):
    parameters = [] if timeout is None else [f"<cmdTimeout>{timeout}</cmdTimeout>"]
    world.spawn_urdf("bot", robot(*parameters), (0, 0, 0))
    run(world, 0.1)
    start = world.pose("bot")[0][0]
    command(bus, forward=0.2)
    run(world, seconds)
    return world.pose("bot")[0][0] - start


def test_a_cmd_timeout_of_zero_keeps_a_command_for_one_update(world, bus):
    """gazebo_plugins/src/gazebo_ros_planar_move.cpp:189-197: a timeout of 0 or more is
    active, and the command is zeroed once now - its arrival > the timeout: with 0, from the
    update after the one it arrived for (0.2 m/s for one 1 ms step: 0.2 mm). Before: 0 was
    no timeout, and the model went on at 0.2 m/s."""
    assert displacement_after_a_command(world, bus, "0") == pytest.approx(0.0002, abs=1e-5)


def test_a_cmd_timeout_stops_the_model_and_the_command_stays_zeroed(world, bus):
    """gazebo_plugins/src/gazebo_ros_planar_move.cpp:189-197: x_, y_, rot_ are set to 0 once
    the command is older than cmdTimeout (0.2 s here): 0.2 m/s for 0.2 s (and the update at
    exactly 0.2 s, not yet older), then at rest."""
    assert displacement_after_a_command(world, bus, "0.2") == pytest.approx(0.0402, abs=1e-5)


def test_no_cmd_timeout_keeps_the_command(world, bus):
    """gazebo_plugins/src/gazebo_ros_planar_move.cpp:117: cmdTimeout defaults to -1, and a
    negative timeout is off (:189)."""
    assert displacement_after_a_command(world, bus) == pytest.approx(0.1, abs=1e-4)


def test_reset_world_keeps_the_command_and_the_last_odometry_pose(world, bus):
    """Noetic's plugin has no Reset (gazebo_plugins/include/gazebo_plugins/
    gazebo_ros_planar_move.h:47-56 declares Load, UpdateChild and FiniChild only): after
    reset_world the model moves on at the last command from its spawn pose, and the first
    odometry after it measures its twist from the last pose published before the reset
    (:300-302), so it reports the jump back. Before: the command was dropped (the model
    stood) and the odometry started over from the reset pose."""
    world.spawn_urdf("bot", robot(), (0, 0, 0))
    command(bus, forward=0.5)
    run(world, 1.0)
    (x_before, _, _), _ = world.pose("bot")
    published = len(bus.published["/odom"])
    world.reset()
    run(world, 0.06)  # one odometry period (more than 1/20 s) and a step
    first = bus.published["/odom"][published]
    assert first.twist.twist.linear.x < -5.0  # about -x_before over 51 ms: the jump back
    run(world, 0.94)
    (x, _, _), _ = world.pose("bot")
    assert x == pytest.approx(0.5, abs=0.01)
    assert x_before == pytest.approx(0.5, abs=0.01)
