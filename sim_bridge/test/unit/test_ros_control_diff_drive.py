"""diff_drive_controller/DiffDriveController on pybullet.DIRECT, row by row against ROS
Noetic: the odometry from the wheels' position changes and its rolling mean, open loop, the
radius and separation multipliers, the speed limiter, and the optional topics. Motion is
checked on the truth: the base's pose and twist and the wheels' positions from pybullet.

Upstream: ros-controls/ros_controllers noetic-devel 678b92a, diff_drive_controller/src/
diff_drive_controller.cpp ("DDC"), odometry.cpp, speed_limiter.cpp."""
import math

import pybullet as pb
import pytest
from controller_manager_msgs.srv import LoadControllerRequest, SwitchControllerRequest
from geometry_msgs.msg import Twist
from std_msgs.msg import Bool

from recording_bus import RecordingBus
from sim_bridge.sdf_world import LinkSpec, ModelSpec, ShapeSpec
from sim_bridge.world import World
from urdf_tools.xacro_loader import expand
from world_fixtures import DATA, run

MANAGER = "/bot/controller_manager"  # no robotNamespace, none requested: the model's name
CONTROLLER = "/bot/base_controller"
RADIUS = 0.05      # diff_bot's wheels
SEPARATION = 0.34  # diff_bot's wheel joints, 0.17 m either side
PLUGIN = '<plugin filename="libgazebo_ros_control.so" name="gazebo_ros_control"/>'  # as expanded
E_STOP_PLUGIN = ('<plugin filename="libgazebo_ros_control.so" name="gazebo_ros_control">'
                 '<eStopTopic>e_stop</eStopTopic></plugin>')
SETTLE = 0.3  # s on the ground before a test drives


class CountingBus(RecordingBus):
    """A bus whose subscriptions say how many publishers they have (rospy's
    Subscriber.get_num_connections), as many as ``publishers``."""

    publishers = 1

    def subscriber(self, topic, msg_class, callback):
        handle = super().subscriber(topic, msg_class, callback)
        handle.get_num_connections = lambda: self.publishers
        return handle


def diff_bot(start=True, e_stop=False, bus_class=RecordingBus, edit=None, **params):
    """diff_bot on wheel transmissions with a DiffDriveController with ``params``, loaded
    (and started) before the first step, then settled on the ground. ``edit``: (old, new)
    text replaced in the robot's description."""
    controller = {"type": "diff_drive_controller/DiffDriveController",
                  "left_wheel": "left_wheel_joint", "right_wheel": "right_wheel_joint"}
    controller.update(params)
    bus = bus_class({CONTROLLER: controller})
    world = World(bus, ray_threads=1)
    world.add_sdf_model(ModelSpec("ground", True, links=[
        LinkSpec("link", collisions=[ShapeSpec("plane")])]))
    urdf = expand(f"{DATA}/diff_bot.urdf.xacro", {"drive": "ros_control"})
    if e_stop:
        assert PLUGIN in urdf
        urdf = urdf.replace(PLUGIN, E_STOP_PLUGIN)
    if edit is not None:
        assert edit[0] in urdf
        urdf = urdf.replace(*edit)
    model = world.spawn_urdf("bot", urdf, namespace="")
    load = bus.services[f"{MANAGER}/load_controller"]
    assert load(LoadControllerRequest("base_controller")).ok, bus.warnings
    if start:
        switch(bus)
        run(world, SETTLE)
    return world, bus, model


def load_only(edit=None, **params):
    """Whether a DiffDriveController with ``params`` loads on diff_bot (its description
    with ``edit``, (old, new), replaced), and the warnings."""
    controller = {"type": "diff_drive_controller/DiffDriveController",
                  "left_wheel": "left_wheel_joint", "right_wheel": "right_wheel_joint"}
    controller.update(params)
    bus = RecordingBus({CONTROLLER: controller})
    world = World(bus, ray_threads=1)
    urdf = expand(f"{DATA}/diff_bot.urdf.xacro", {"drive": "ros_control"})
    if edit is not None:
        assert edit[0] in urdf
        urdf = urdf.replace(*edit)
    world.spawn_urdf("bot", urdf, namespace="")
    loaded = bus.services[f"{MANAGER}/load_controller"](
        LoadControllerRequest("base_controller")).ok
    world.close()
    return loaded, bus.warnings


def switch(bus):
    assert bus.services[f"{MANAGER}/switch_controller"](
        SwitchControllerRequest(start_controllers=["base_controller"], strictness=2)).ok


def drive(bus, linear, angular=0.0):
    command = Twist()
    command.linear.x, command.angular.z = linear, angular
    bus.subscriptions[f"{CONTROLLER}/cmd_vel"](command)


def drive_for(world, bus, seconds, linear, angular=0.0, every=0.2):
    """Sends the command every ``every`` s (within cmd_vel_timeout) for ``seconds``."""
    for _ in range(int(round(seconds / every))):
        drive(bus, linear, angular)
        run(world, every)


def wheels(model):
    return [model.robot.joint_position_velocity(j)[0]
            for j in ("left_wheel_joint", "right_wheel_joint")]


def base(world):
    """The base's true x, y, yaw, forward speed and yaw rate."""
    position, orientation = world.pose("bot")
    yaw = pb.getEulerFromQuaternion(orientation)[2]
    linear, angular = world.twist("bot")
    forward = linear[0] * math.cos(yaw) + linear[1] * math.sin(yaw)
    return position[0], position[1], yaw, forward, angular[2]


def odometry(bus):
    message = bus.last(f"{CONTROLLER}/odom")
    q = message.pose.pose.orientation
    yaw = 2.0 * math.atan2(q.z, q.w)
    return (message.pose.pose.position.x, message.pose.pose.position.y, yaw,
            message.twist.twist.linear.x, message.twist.twist.angular.z)


def seconds(stamp):
    return stamp.secs + stamp.nsecs * 1e-9


# --- odometry ------------------------------------------------------------------------------

@pytest.mark.parametrize("window", [None, 5, 50])
def test_the_published_twist_is_the_rolling_mean_of_the_wheels_position_changes(window):
    """odometry.cpp:74-110: each update's linear speed is the wheels' mean travel since the
    last update over the time between, from their positions; the published one the mean of
    the last velocity_rolling_window_size of them (10 by default, DDC:229-234). Five updates
    after a stop the wheels stand still, and the twist still carries the window's older
    samples. Before: the wheels' instantaneous velocity, 0 there."""
    params = {"publish_rate": 1000.0}  # every update publishes (DDC:430)
    if window is not None:
        params["velocity_rolling_window_size"] = window
    size = window or 10
    world, bus, model = diff_bot(**params)
    drive_for(world, bus, 0.4, 0.2)
    drive(bus, 0.2)
    positions = []
    for k in range(size + 60):
        if k == size + 55:
            drive(bus, 0.0)  # the last five updates see the wheels stopped
        positions.append(wheels(model))  # what the next update reads
        world.step()
    dt = world.step_size
    speeds = [RADIUS * ((b[0] - a[0]) + (b[1] - a[1])) / 2.0 / dt
              for a, b in zip(positions[-size - 1:], positions[-size:])]
    expected = sum(speeds) / size
    assert abs(model.robot.joint_position_velocity("left_wheel_joint")[1]) < 0.01  # stopped
    assert expected == pytest.approx(0.2 * (size - 4) / size, abs=0.01)
    assert odometry(bus)[3] == pytest.approx(expected, abs=1e-6)
    world.close()


def test_the_pose_is_the_wheels_travel_integrated_and_follows_the_base():
    """odometry.cpp:74-93, :153-166: a drive forward, then an arc: the pose is the exact arc
    of the wheels' travel, which on firm ground is where the base really is."""
    world, bus, model = diff_bot()
    start = base(world)
    drive_for(world, bus, 1.0, 0.2)
    drive_for(world, bus, 1.0, 0.2, 0.5)
    x, y, yaw = odometry(bus)[:3]
    true_x, true_y, true_yaw = base(world)[:3]
    assert math.hypot(x - (true_x - start[0]), y - (true_y - start[1])) < 0.01
    assert yaw == pytest.approx(true_yaw - start[2], abs=0.02)
    assert yaw == pytest.approx(0.5, abs=0.02)
    world.close()


def test_wheels_not_at_zero_when_first_read_count_as_travelled():
    """odometry.cpp:48-60, :67-86: the wheels' previous positions start at 0 and init keeps
    them, so wheels spawned at 2 rad give a first step of 2 rad: 0.1 m forward that the base
    never went. Before: from the velocities, nothing."""
    world, bus, model = diff_bot(start=False)
    world.set_joint_positions("bot", {"left_wheel_joint": 2.0, "right_wheel_joint": 2.0})
    before = base(world)
    switch(bus)
    run(world, SETTLE)
    assert odometry(bus)[0] == pytest.approx(2.0 * RADIUS, abs=1e-3)
    assert base(world)[0] == pytest.approx(before[0], abs=1e-3)
    world.close()


@pytest.mark.parametrize("open_loop", [True, False])
def test_open_loop_odometry_integrates_the_commands_not_the_wheels(open_loop):
    """DDC:204, :404-406, odometry.cpp:112-122: open_loop integrates the last limited
    command. With the wheels held by the emergency stop the base stays, the open-loop
    odometry goes on at 0.2 m/s, the wheels' stays at 0. Before: open_loop not read."""
    world, bus, model = diff_bot(e_stop=True, open_loop=open_loop, publish_rate=1000.0)
    start, start_wheels = base(world), wheels(model)
    bus.subscriptions["/bot/e_stop"](Bool(True))
    drive_for(world, bus, 1.0, 0.2)
    assert base(world)[0] == pytest.approx(start[0], abs=1e-3)
    assert wheels(model) == pytest.approx(start_wheels, abs=1e-3)
    x, _, _, linear, _ = odometry(bus)
    assert x == pytest.approx(0.2 if open_loop else 0.0, abs=0.002)
    assert linear == pytest.approx(0.2 if open_loop else 0.0, abs=1e-4)
    world.close()


@pytest.mark.parametrize("params, true_yaw", [
    ({"left_wheel_radius_multiplier": 1.1}, 2.0 * 0.2 * (1 - 1 / 1.1) / SEPARATION),
    ({"right_wheel_radius_multiplier": 1.1}, -2.0 * 0.2 * (1 - 1 / 1.1) / SEPARATION),
    ({"wheel_radius_multiplier": 1.0, "left_wheel_radius_multiplier": 1.1}, 0.0),
])
def test_a_sides_radius_multiplier_turns_the_robot_its_odometry_goes_straight(params, true_yaw):
    """DDC:210-227, :296-299, :492-493: each side's radius is wheel_radius times its
    multiplier, for the wheels' speeds and the odometry alike; wheel_radius_multiplier,
    when set, is both. A left radius taken 10 % large turns the left wheel slower: the base
    turns left while its odometry, measuring with the same radius, sees a straight line.
    Before: only wheel_radius_multiplier was read."""
    world, bus, model = diff_bot(**params)
    start = base(world)
    drive_for(world, bus, 2.0, 0.2)
    drive(bus, 0.0)
    run(world, 0.1)
    assert base(world)[2] - start[2] == pytest.approx(true_yaw, abs=0.01)
    assert odometry(bus)[2] == pytest.approx(0.0, abs=1e-3)
    world.close()


def test_the_separation_multiplier_scales_the_turn_the_wheels_make():
    """DDC:206, :296, :492-493: wheel speeds for a turn use the multiplied separation: at 2
    the base turns at twice the command, and the odometry (dividing by the same) says the
    command. Passes before too (the multiplier was read)."""
    world, bus, model = diff_bot(wheel_separation_multiplier=2.0)
    start = base(world)
    drive_for(world, bus, 0.4, 0.0, 1.0)
    assert base(world)[2] - start[2] == pytest.approx(0.8, abs=0.03)
    assert odometry(bus)[2] == pytest.approx(0.4, abs=0.025)  # published at 50 Hz
    world.close()


LEFT_WHEEL_JOINT = ('<joint name="left_wheel_joint" type="continuous">\n'
                    '    <parent link="base_link"/>\n'
                    '    <child link="left_wheel"/>\n'
                    '    <origin xyz="0 0.17 -0.03"/>')  # as expanded
# the same wheel, 0.17 m out, on a hub 0.07 m out: its joint's origin is 0.1 m from the hub
LEFT_WHEEL_ON_A_HUB = (
    '<link name="left_hub"><inertial><mass value="0.1"/>'
    '<inertia ixx="1e-5" ixy="0" ixz="0" iyy="1e-5" iyz="0" izz="1e-5"/></inertial></link>'
    '<joint name="left_hub_joint" type="fixed"><parent link="base_link"/>'
    '<child link="left_hub"/><origin xyz="0 0.07 0"/></joint>'
    '<joint name="left_wheel_joint" type="continuous">'
    '<parent link="left_hub"/><child link="left_wheel"/><origin xyz="0 0.1 -0.03"/>')


def test_the_separation_from_the_urdf_is_between_the_wheel_joints_origins_as_written():
    """DDC:661-674: the distance between the two joints' origins, each in its own parent
    link's frame. A left wheel hung 0.1 m out on a hub 0.07 m out gives 0.27 m (the wheels
    are 0.34 m apart): a turn at 1 rad/s turns the base at 0.27/0.34 of it, while the
    odometry, dividing by the same 0.27, says 1 rad/s. Before: 0.34 m, the links' distance."""
    world, bus, model = diff_bot(edit=(LEFT_WHEEL_JOINT, LEFT_WHEEL_ON_A_HUB),
                                 publish_rate=1000.0)
    start = base(world)
    drive_for(world, bus, 0.5, 0.0, 1.0, every=0.25)
    assert base(world)[2] - start[2] == pytest.approx(0.5 * 0.27 / SEPARATION, abs=0.02)
    assert odometry(bus)[2] == pytest.approx(0.5, abs=0.01)
    world.close()


def test_the_radius_from_the_urdf_is_the_wheels_first_collisions():
    """DDC:128-143, :676-684: the left wheel link's first <collision> (urdfdom's
    link->collision) must be a cylinder or a sphere; a box before the cylinder fails the
    load, naming the link. Before: the first cylinder or sphere among them was taken."""
    box_first = ('<link name="left_wheel">', '<link name="left_wheel"><collision><geometry>'
                 '<box size="0.01 0.01 0.01"/></geometry></collision>')
    loaded, warnings = load_only(edit=box_first)
    assert not loaded
    assert any("Wheel link left_wheel is NOT modeled as a cylinder or sphere!" in w
               for w in warnings)
    assert load_only(edit=box_first, wheel_radius=0.05)[0]


# --- the speed limiter ---------------------------------------------------------------------

@pytest.mark.parametrize("switch_on", ["has_velocity_limits", "has_acceleration_limits",
                                       "has_jerk_limits"])
def test_a_limit_switched_on_without_its_bounds_holds_the_robot(switch_on):
    """DDC:255-263: each maximum defaults to SpeedLimiter's 0.0 (speed_limiter.h:61-71) and
    each minimum to minus the maximum read: a limit on without its numbers clamps the
    velocity, its change, or the change of its change to 0. The base does not move. Before:
    velocity unlimited without max_velocity, the other two not read: it drove."""
    world, bus, model = diff_bot(linear={"x": {switch_on: True}})
    start = base(world)
    drive_for(world, bus, 1.0, 0.2)
    assert base(world)[0] == pytest.approx(start[0], abs=1e-3)
    world.close()


@pytest.mark.parametrize("limits, command, expected", [
    ({"max_velocity": 0.1}, 0.3, 0.1),
    ({"max_velocity": 0.1}, -0.3, -0.1),            # min_velocity: -max_velocity
    ({"max_velocity": 0.1, "min_velocity": -0.05}, -0.3, -0.05),
])
def test_velocity_limits_clamp_the_command(limits, command, expected):
    """speed_limiter.cpp:86-96, DDC:258-259: the base's true speed is the clamped command.
    Passes before too (velocity limits with their bounds were read)."""
    world, bus, model = diff_bot(linear={"x": dict(limits, has_velocity_limits=True)})
    drive_for(world, bus, 0.6, command)
    assert base(world)[3] == pytest.approx(expected, abs=0.005)
    world.close()


def test_acceleration_limits_ramp_the_speed_up_and_down():
    """speed_limiter.cpp:98-113, DDC:260-261: the command changes by at most
    max_acceleration * period per update (and min_acceleration, -max by default, braking):
    at 0.5 m/s^2 the base is at 0.1 m/s 0.2 s after a 0.2 m/s command, at 0.2 after 0.6 s,
    and back at 0.1 m/s 0.2 s after a stop. Before: not read, 0.2 m/s at once."""
    world, bus, model = diff_bot(linear={"x": {"has_acceleration_limits": True,
                                               "max_acceleration": 0.5}})
    drive_for(world, bus, 0.2, 0.2)
    assert base(world)[3] == pytest.approx(0.1, abs=0.01)
    drive_for(world, bus, 0.4, 0.2)
    assert base(world)[3] == pytest.approx(0.2, abs=0.01)
    drive_for(world, bus, 0.2, 0.0)
    assert base(world)[3] == pytest.approx(0.1, abs=0.01)
    world.close()


def test_jerk_limits_grow_the_speed_as_noetics_formula_does():
    """speed_limiter.cpp:115-135: the change of the command's change is held within
    max_jerk * 2 * period^2, so from rest the n-th update's command is
    max_jerk * period^2 * n * (n + 1) (about max_jerk * t^2, twice a true jerk ramp's): at
    1 m/s^3, 0.2 s after a 0.2 m/s command, 0.0402 m/s, which the base really has. Before:
    not read, 0.2 m/s."""
    world, bus, model = diff_bot(publish_cmd=True, linear={"x": {"has_jerk_limits": True,
                                                                 "max_jerk": 1.0}})
    drive(bus, 0.2)
    updates = 200
    for _ in range(updates):
        world.step()
    dt = world.step_size
    limited = bus.last(f"{CONTROLLER}/cmd_vel_out").twist.linear.x
    assert limited == pytest.approx(1.0 * dt * dt * updates * (updates + 1), rel=1e-6)
    assert base(world)[3] == pytest.approx(limited, abs=0.005)
    world.close()


def test_angular_limits_ramp_and_clamp_the_turn():
    """DDC:265-273: angular/z has the same limits: at 1 rad/s^2 up to 0.5 rad/s, a 2 rad/s
    command turns the base at 0.25 rad/s after 0.25 s and 0.5 rad/s after 1 s. Before: the
    velocity limit alone, 0.5 rad/s at once."""
    world, bus, model = diff_bot(angular={"z": {"has_velocity_limits": True, "max_velocity": 0.5,
                                                "has_acceleration_limits": True,
                                                "max_acceleration": 1.0}})
    drive_for(world, bus, 0.25, 0.0, 2.0, every=0.25)
    assert base(world)[4] == pytest.approx(0.25, abs=0.02)
    drive_for(world, bus, 0.75, 0.0, 2.0, every=0.25)
    assert base(world)[4] == pytest.approx(0.5, abs=0.02)
    world.close()


# --- commands ------------------------------------------------------------------------------

def test_cmd_vel_timeout_brakes_after_its_seconds():
    """DDC:237, :463-471: a command older than cmd_vel_timeout (here 0.2 s) is 0: one
    command at 0.2 m/s moves the base 0.04 m. Passes before too (it was read)."""
    world, bus, model = diff_bot(cmd_vel_timeout=0.2)
    start = base(world)
    drive(bus, 0.2)
    run(world, 1.0)
    assert base(world)[0] - start[0] == pytest.approx(0.04, abs=0.004)
    world.close()


@pytest.mark.parametrize("allow, publishers, moves", [
    (False, 2, False), (False, 1, True), (True, 2, True)])
def test_a_second_cmd_vel_publisher_brakes_when_only_one_is_allowed(allow, publishers, moves):
    """DDC:156, :241, :536-543: with allow_multiple_cmd_vel_publishers false and more than
    one publisher on cmd_vel, a command is not taken ("Detected 2 publishers. Only 1
    publisher is allowed. Going to brake."): the base stays. Before: not read, it drove."""
    CountingBus.publishers = publishers
    world, bus, model = diff_bot(bus_class=CountingBus, allow_multiple_cmd_vel_publishers=allow)
    start = base(world)
    drive_for(world, bus, 0.4, 0.2)
    assert (base(world)[0] - start[0] > 0.05) == moves
    warned = [w for w in bus.warnings
              if "Detected 2 publishers. Only 1 publisher is allowed. Going to brake." in w]
    assert bool(warned) == (not moves)
    world.close()


def test_a_command_before_the_controller_runs_is_refused():
    """DDC:532-535, :561-564: a loaded controller not started refuses cmd_vel ("Can't accept
    new commands. Controller is not running."); started, the base stays. Before: taken
    silently."""
    world, bus, model = diff_bot(start=False)
    drive(bus, 0.2)
    assert any("Can't accept new commands. Controller is not running." in w
               for w in bus.warnings)
    switch(bus)
    start = base(world)
    run(world, 0.3)
    assert base(world)[0] == pytest.approx(start[0], abs=1e-3)
    world.close()


def test_a_nan_command_is_ignored_with_noetics_words():
    """DDC:545-549: "Received NaN in velocity command. Ignoring.", and the last command goes
    on. Before: another text."""
    world, bus, model = diff_bot()
    drive(bus, 0.2)
    drive(bus, math.nan)
    run(world, 0.3)
    assert "Received NaN in velocity command. Ignoring." in bus.warnings
    assert base(world)[3] == pytest.approx(0.2, abs=0.01)
    world.close()


def test_unequal_wheel_lists_do_not_load():
    """DDC:182-188: as many left wheels as right ones, or the controller does not load."""
    loaded, warnings = load_only(left_wheel=["left_wheel_joint"],
                                 right_wheel=["right_wheel_joint", "left_wheel_joint"])
    assert not loaded
    assert any("#left wheels (1) != #right wheels (2)." in w for w in warnings)


# --- what it publishes ---------------------------------------------------------------------

def test_publish_cmd_sends_the_limited_command_on_cmd_vel_out():
    """DDC:161, :276, :305-308, :483-489: with publish_cmd, each update's command after the
    limits goes out as a TwistStamped on cmd_vel_out, stamped with the update's time; the
    base moves at it. Without it nothing is advertised there. Before: not read."""
    world, bus, model = diff_bot()
    assert f"{CONTROLLER}/cmd_vel_out" not in bus.advertised
    world.close()
    world, bus, model = diff_bot(publish_cmd=True, linear={"x": {"has_velocity_limits": True,
                                                                 "max_velocity": 0.1}})
    drive_for(world, bus, 0.4, 0.3, 0.5)
    message = bus.last(f"{CONTROLLER}/cmd_vel_out")
    assert (message.twist.linear.x, message.twist.angular.z) == (0.1, 0.5)
    assert seconds(message.header.stamp) == pytest.approx(world.now - world.step_size)
    assert base(world)[3] == pytest.approx(0.1, abs=0.005)
    world.close()


def test_the_wheel_joint_controller_state_reports_the_wheels():
    """DDC:162, :279, :311-342, :765-834: with publish_wheel_joint_controller_state, every
    update a control_msgs/JointTrajectoryControllerState on wheel_joint_controller_state:
    the wheels (left, then right), their actual positions as read, the desired velocities
    the limited command's (0.2 m/s: 4 rad/s each), the desired effort NaN. Before: not
    read."""
    world, bus, model = diff_bot()
    assert f"{CONTROLLER}/wheel_joint_controller_state" not in bus.advertised
    world.close()
    world, bus, model = diff_bot(publish_wheel_joint_controller_state=True)
    drive_for(world, bus, 0.4, 0.2)
    read = wheels(model)  # what the next update reads
    world.step()
    state = bus.last(f"{CONTROLLER}/wheel_joint_controller_state")
    assert state.joint_names == ["left_wheel_joint", "right_wheel_joint"]
    assert list(state.actual.positions) == pytest.approx(read, abs=1e-9)
    assert list(state.actual.velocities) == pytest.approx([0.2 / RADIUS] * 2, abs=0.05)
    assert list(state.desired.velocities) == pytest.approx([0.2 / RADIUS] * 2, abs=1e-9)
    assert all(math.isnan(e) for e in state.desired.effort)
    assert [d - a for d, a in zip(state.desired.positions, state.actual.positions)] == \
        pytest.approx(list(state.error.positions), abs=1e-9)
    world.close()


def test_odometry_goes_out_one_period_after_the_start_then_every_period():
    """DDC:198-202, :430-432, :511: a message when the time is past the last one's plus the
    period, which then moves on by one period: at 10 Hz, started at 0, at 0.101 s, 0.201 s,
    ... (1 ms steps). Before: at 0, 0.1, 0.2."""
    world, bus, model = diff_bot(publish_rate=10.0)
    stamps = [seconds(m.header.stamp) for m in bus.published[f"{CONTROLLER}/odom"]]
    step = world.step_size
    assert stamps == pytest.approx([0.1 * (k + 1) + step for k in range(len(stamps))])
    assert len(stamps) == 2  # updates at 0 ... 0.299 s (SETTLE): 0.101 and 0.201
    world.close()


@pytest.mark.parametrize("enable", [True, False])
def test_enable_odom_tf_sends_odom_to_base_as_the_odometry_says(enable):
    """DDC:159, :251, :449-458, :729-733: odom -> base_link on /tf with the odometry's pose,
    when enable_odom_tf (true by default). Passes before too (it was read)."""
    world, bus, model = diff_bot(**({} if enable else {"enable_odom_tf": False}))
    drive_for(world, bus, 0.4, 0.2)
    transforms = [t for t in bus.published.get("/tf", []) if t.child_frame_id == "base_link"]
    assert bool(transforms) == enable
    if enable:
        last = transforms[-1]
        assert last.header.frame_id == "odom"
        assert last.transform.translation.x == pytest.approx(odometry(bus)[0])
    world.close()


def test_covariances_are_the_diagonals_given():
    """DDC:692-728: the six numbers on each matrix's diagonal."""
    pose = [0.001, 0.002, 1e6, 1e6, 1e6, 0.03]
    twist = [0.004, 0.005, 1e6, 1e6, 1e6, 0.06]
    world, bus, model = diff_bot(pose_covariance_diagonal=pose, twist_covariance_diagonal=twist)
    message = bus.last(f"{CONTROLLER}/odom")
    assert [message.pose.covariance[i * 7] for i in range(6)] == pose
    assert [message.twist.covariance[i * 7] for i in range(6)] == twist
    assert sum(message.twist.covariance) == pytest.approx(sum(twist))
    world.close()


@pytest.mark.parametrize("given, diagonal", [
    (None, [0.0] * 6),
    ([0.1, 0.2], [0.1, 0.2, 0.0, 0.0, 0.0, 0.0]),
    ([0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7], [0.1, 0.2, 0.3, 0.4, 0.5, 0.6]),
])
def test_a_covariance_list_short_or_absent_reads_zeros_for_what_is_missing(given, diagonal):
    """DDC:692-717 with its ROS_ASSERTs compiled out (a release build): the first six
    entries through XmlRpcValue, whose missing entries read 0.0 (ros_comm noetic-devel
    845f746 XmlRpcValue.cpp:81-118). Before: a list of other than six refused the load."""
    params = {} if given is None else {"pose_covariance_diagonal": given}
    world, bus, model = diff_bot(**params)
    message = bus.last(f"{CONTROLLER}/odom")
    assert [message.pose.covariance[i * 7] for i in range(6)] == diagonal
    world.close()


@pytest.mark.parametrize("given", [[0.001, 0.001, 1000000, 1e6, 1e6, 0.03], 0.1])
def test_a_covariance_entry_not_a_double_fails_the_load(given):
    """XmlRpcValue throws on an int (or a scalar for a list), and controller_manager fails
    the load (controller_manager.cpp:323-333). Before: taken."""
    loaded, warnings = load_only(twist_covariance_diagonal=given)
    assert not loaded
    assert any("Exception thrown while initializing controller 'base_controller'" in w
               for w in warnings)
