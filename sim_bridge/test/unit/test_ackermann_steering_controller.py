"""ackermann_steering_controller/AckermannSteeringController on pybullet.DIRECT, row by row
against ROS Noetic: cmd_vel to the rear wheel's speed and the steering angle, the circle that
follows, the odometry from the rear wheel and the steering angle, its multipliers, the
timeout, the limits, the geometry from the URDF and the configurations that do not load.
Motion is checked on the truth: the base's pose and twist and the joints from pybullet.

Upstream: ros-controls/ros_controllers noetic-devel 678b92a, ackermann_steering_controller/
src/ackermann_steering_controller.cpp ("ASC"), src/odometry.cpp, and diff_drive_controller's
speed_limiter.cpp, which it uses.

The robot, a steer bot laid out as upstream's (ackermann_steering_controller/test/common/urdf/
ackermann_steering_bot.xacro: rear_wheel_joint and front_steer_joint on the centre line,
wheels beside them), which upstream drives through a fake hardware, not Gazebo: one driven
rear wheel on rear_wheel_joint at the base's origin, two free rear wheels beside it, and one
wheel on front_steer_joint WHEELBASE ahead. Free side wheels, not one rigid axle: an axle
without a differential scrubs in a turn (tried: a circle 21 % wider than the geometry's)."""
import math

import numpy as np
import pybullet as pb
import pytest
from controller_manager_msgs.srv import (ListControllersRequest, LoadControllerRequest,
                                         SwitchControllerRequest)
from geometry_msgs.msg import Twist

from recording_bus import RecordingBus
from sim_bridge.ros_control import INTERFACE_NAMES
from sim_bridge.sdf_world import LinkSpec, ModelSpec, ShapeSpec
from sim_bridge.world import World
from world_fixtures import run

ROBOT = "steer_bot"
MANAGER = f"/{ROBOT}/controller_manager"
NAME = "ackermann_controller"
CONTROLLER = f"/{ROBOT}/{NAME}"
TYPE = "ackermann_steering_controller/AckermannSteeringController"
RADIUS = 0.1      # the wheels' (m)
WHEELBASE = 0.4   # rear axle to steering joint, along x (m)
TRACK = 0.3       # between the rear wheels (m)
STEER_LIMIT = 0.6  # the steering joint's URDF limit (rad)
SETTLE = 0.3      # s on the ground before a test drives


WHEEL_WIDTH = 0.04
WHEEL_MASS = 0.5
BASE_MASS = 4.0
BASE_SIZE = (0.6, 0.25, 0.06)
BASE_HEIGHT = 0.08  # the body's centre above the rear axle (m)


def _inertia(ixx, iyy, izz):
    return f'<inertia ixx="{ixx}" ixy="0" ixz="0" iyy="{iyy}" iyz="0" izz="{izz}"/>'


def _wheel_link(name, geometry=None):
    """A wheel on an axis along y: its cylinder's axis is its frame's z turned by pi/2."""
    geometry = geometry or f'<cylinder radius="{RADIUS}" length="{WHEEL_WIDTH}"/>'
    across = WHEEL_MASS * (3 * RADIUS ** 2 + WHEEL_WIDTH ** 2) / 12
    return f"""  <link name="{name}">
    <collision><origin rpy="{math.pi / 2} 0 0"/><geometry>{geometry}</geometry></collision>
    <inertial><mass value="{WHEEL_MASS}"/>{_inertia(across, WHEEL_MASS * RADIUS ** 2 / 2, across)}
    </inertial>
  </link>
"""


def _joint(name, kind, parent, child, xyz, axis, limit=""):
    return f"""  <joint name="{name}" type="{kind}">
    <parent link="{parent}"/><child link="{child}"/><origin xyz="{xyz}"/><axis xyz="{axis}"/>
    {limit}
  </joint>
"""


def _transmission(joint_name, interface):
    return f"""  <transmission name="{joint_name}_transmission">
    <type>transmission_interface/SimpleTransmission</type>
    <joint name="{joint_name}">
      <hardwareInterface>hardware_interface/{interface}</hardwareInterface>
    </joint>
    <actuator name="{joint_name}_motor"><mechanicalReduction>1</mechanicalReduction></actuator>
  </transmission>
"""


def steer_bot_urdf(rear_interface="VelocityJointInterface",
                   steer_interface="PositionJointInterface", rear_shape=None):
    """The steer bot; the two transmissions' interfaces as given; ``rear_shape``: the driven
    rear wheel's collision geometry in place of its cylinder."""
    x, y, z = BASE_SIZE
    body = _inertia(BASE_MASS * (y * y + z * z) / 12, BASE_MASS * (x * x + z * z) / 12,
                    BASE_MASS * (x * x + y * y) / 12)
    side_wheels = "".join(
        _wheel_link(f"rear_{side}_wheel")
        + _joint(f"rear_{side}_wheel_joint", "continuous", "base_link", f"rear_{side}_wheel",
                 f"0 {offset} 0", "0 1 0")
        for side, offset in (("left", TRACK / 2), ("right", -TRACK / 2)))
    return f"""<?xml version="1.0"?>
<robot name="{ROBOT}">
  <link name="base_link">
    <collision><origin xyz="{WHEELBASE / 2} 0 {BASE_HEIGHT}"/>
      <geometry><box size="{x} {y} {z}"/></geometry></collision>
    <inertial><origin xyz="{WHEELBASE / 2} 0 {BASE_HEIGHT}"/><mass value="{BASE_MASS}"/>{body}
    </inertial>
  </link>
{_wheel_link("rear_wheel", rear_shape)}
{_joint("rear_wheel_joint", "continuous", "base_link", "rear_wheel", "0 0 0", "0 1 0",
        '<limit effort="20" velocity="30"/>')}
{side_wheels}
  <link name="steer_link">
    <inertial><mass value="0.1"/>{_inertia(1e-4, 1e-4, 1e-4)}</inertial>
  </link>
{_joint("front_steer_joint", "revolute", "base_link", "steer_link", f"{WHEELBASE} 0 0",
        "0 0 1", f'<limit lower="{-STEER_LIMIT}" upper="{STEER_LIMIT}" effort="10" '
        'velocity="5"/>')}
{_wheel_link("front_wheel")}
{_joint("front_wheel_joint", "continuous", "steer_link", "front_wheel", "0 0 0", "0 1 0")}
{_transmission("rear_wheel_joint", rear_interface)}
{_transmission("front_steer_joint", steer_interface)}
  <gazebo>
    <plugin name="gazebo_ros_control" filename="libgazebo_ros_control.so">
      <robotNamespace>/{ROBOT}</robotNamespace>
    </plugin>
  </gazebo>
</robot>"""


def controller_params(**params):
    controller = {"type": TYPE, "rear_wheel": "rear_wheel_joint",
                  "front_steer": "front_steer_joint"}
    controller.update(params)
    return {key: value for key, value in controller.items() if value is not None}


def steer_bot(start=True, urdf=None, bus_class=RecordingBus, **params):
    """The steer bot on the ground with an AckermannSteeringController with ``params`` (None
    drops a key), loaded (and started) before the first step, then settled."""
    bus = bus_class({CONTROLLER: controller_params(**params)})
    world = World(bus, ray_threads=1)
    world.add_sdf_model(ModelSpec("ground", True, links=[
        LinkSpec("link", collisions=[ShapeSpec("plane")])]))
    model = world.spawn_urdf(ROBOT, urdf or steer_bot_urdf(), position=(0, 0, RADIUS),
                             namespace="")
    assert bus.services[f"{MANAGER}/load_controller"](LoadControllerRequest(NAME)).ok, \
        bus.warnings
    if start:
        switch(bus)
        run(world, SETTLE)
    return world, bus, model


def load_only(urdf=None, **params):
    """Whether the controller with ``params`` loads on the steer bot (``urdf`` in its place),
    and the warnings."""
    bus = RecordingBus({CONTROLLER: controller_params(**params)})
    world = World(bus, ray_threads=1)
    world.spawn_urdf(ROBOT, urdf or steer_bot_urdf(), namespace="")
    loaded = bus.services[f"{MANAGER}/load_controller"](LoadControllerRequest(NAME)).ok
    world.close()
    return loaded, bus.warnings


def switch(bus):
    assert bus.services[f"{MANAGER}/switch_controller"](
        SwitchControllerRequest(start_controllers=[NAME], strictness=2)).ok


def drive(bus, linear, angle=0.0):
    command = Twist()
    command.linear.x, command.angular.z = linear, angle
    bus.subscriptions[f"{CONTROLLER}/cmd_vel"](command)


def drive_for(world, bus, seconds, linear, angle=0.0, every=0.2, track=None):
    """Sends the command every ``every`` s (within cmd_vel_timeout) for ``seconds``;
    ``track``: a list the base's true (x, y) is appended to every ``every`` s."""
    for _ in range(int(round(seconds / every))):
        drive(bus, linear, angle)
        run(world, every)
        if track is not None:
            track.append(base(world)[:2])


def base(world):
    """The base's true x, y, yaw, forward speed and yaw rate."""
    position, orientation = world.pose(ROBOT)
    yaw = pb.getEulerFromQuaternion(orientation)[2]
    linear, angular = world.twist(ROBOT)
    forward = linear[0] * math.cos(yaw) + linear[1] * math.sin(yaw)
    return position[0], position[1], yaw, forward, angular[2]


def joint(model, name):
    """A joint's true position and velocity."""
    return model.robot.joint_position_velocity(name)


def odometry(bus):
    message = bus.last(f"{CONTROLLER}/odom")
    q = message.pose.pose.orientation
    yaw = 2.0 * math.atan2(q.z, q.w)
    return (message.pose.pose.position.x, message.pose.pose.position.y, yaw,
            message.twist.twist.linear.x, message.twist.twist.angular.z)


def circle_radius(points):
    """The radius of the circle through ``points`` (x, y) that fits them best (Kasa's
    algebraic least squares: x² + y² + D x + E y + F = 0)."""
    xy = np.asarray(points)
    a = np.column_stack([xy[:, 0], xy[:, 1], np.ones(len(xy))])
    b = -(xy[:, 0] ** 2 + xy[:, 1] ** 2)
    d, e, f = np.linalg.lstsq(a, b, rcond=None)[0]
    return math.sqrt(d * d / 4 + e * e / 4 - f)


def seconds(stamp):
    return stamp.secs + stamp.nsecs * 1e-9


def turn_rate(linear, angle, separation=WHEELBASE):
    """The bicycle model's yaw rate (odometry.cpp:90 per second)."""
    return linear * math.tan(angle) / separation


# --- cmd_vel to the joints, and the motion that follows ------------------------------------

def test_cmd_vel_turns_the_rear_wheel_at_speed_over_radius_and_sets_the_steering_angle():
    """ASC:333-335: the rear wheel's command is linear.x / wheel_radius (0.3 m/s: 3 rad/s),
    the steering joint's position angular.z itself (0.4 rad), not a turn rate. The base
    goes at 0.3 m/s. Before: the type was not emulated (no load)."""
    world, bus, model = steer_bot()
    drive_for(world, bus, 1.0, 0.3, 0.4)
    assert joint(model, "rear_wheel_joint")[1] == pytest.approx(0.3 / RADIUS, rel=1e-3)
    assert joint(model, "front_steer_joint")[0] == pytest.approx(0.4, abs=1e-3)
    assert base(world)[3] == pytest.approx(0.3, rel=0.02)
    world.close()


@pytest.mark.parametrize("linear, angle", [(0.3, 0.4), (0.2, -0.25)])
def test_the_robot_drives_the_circle_of_wheelbase_over_tan_angle(linear, angle):
    """ASC:333-335 with the car's geometry: the rear axle (the base's origin) follows a
    circle of WHEELBASE / tan(angular.z) (0.946 m at 0.4 rad; v / angular.z would be
    0.75 m), at linear.x * tan(angular.z) / WHEELBASE rad/s, within 2 %. The radius is fitted
    to the base's true positions over 4 s."""
    world, bus, _ = steer_bot()
    drive_for(world, bus, 0.6, linear, angle)  # the steering set, the speed reached
    track = []
    yaw0 = base(world)[2]
    drive_for(world, bus, 4.0, linear, angle, track=track)
    expected = WHEELBASE / math.tan(abs(angle))
    assert circle_radius(track) == pytest.approx(expected, rel=0.02)
    assert abs(circle_radius(track) - linear / abs(angle)) > 0.1 * expected
    assert (base(world)[2] - yaw0) / 4.0 == pytest.approx(turn_rate(linear, angle), rel=0.02)
    world.close()


def test_the_odometry_follows_the_truth_along_a_straight_and_an_arc():
    """odometry.cpp:73-110, :137-165: the rear wheel's travel (its position × the radius)
    integrated along the arc of tan(steering angle) × travel / separation: after 1 s
    straight and 3 s on an arc the odometry's pose is where the base truly went, within
    1 cm and 0.01 rad; its twist the true speed and yaw rate."""
    world, bus, _ = steer_bot()
    x0, y0, yaw0 = base(world)[:3]
    drive_for(world, bus, 1.0, 0.3)
    drive_for(world, bus, 3.0, 0.3, 0.3)
    x, y, yaw, linear, angular = odometry(bus)
    true_x, true_y, true_yaw, forward, rate = base(world)
    assert math.hypot(x - (true_x - x0), y - (true_y - y0)) < 0.01
    assert yaw == pytest.approx(true_yaw - yaw0, abs=0.01)
    assert yaw > 0.6  # it did turn
    assert linear == pytest.approx(forward, abs=0.005)
    assert angular == pytest.approx(rate, abs=0.005)
    world.close()


@pytest.mark.parametrize("window", [None, 40])
def test_the_published_twist_is_the_rolling_mean_of_the_rear_wheels_position_changes(window):
    """ASC:172-177, odometry.cpp:95-107: each update's speed is the rear wheel's travel
    since the last over the time between; the published twist the mean of the last
    velocity_rolling_window_size (10) of them. Five updates after a stop the twist still
    carries the window's older samples."""
    params = {"publish_rate": 1000.0}  # every update publishes (ASC:280)
    if window is not None:
        params["velocity_rolling_window_size"] = window
    size = window or 10
    world, bus, model = steer_bot(**params)
    drive_for(world, bus, 0.6, 0.3)
    drive(bus, 0.3)
    positions = []
    for k in range(size + 60):
        if k == size + 55:
            drive(bus, 0.0)  # the last five updates see the wheel stopped
        positions.append(joint(model, "rear_wheel_joint")[0])  # what the next update reads
        world.step()
    speeds = [RADIUS * (b - a) / world.step_size
              for a, b in zip(positions[-size - 1:], positions[-size:])]
    expected = sum(speeds) / size
    assert abs(joint(model, "rear_wheel_joint")[1]) < 0.01  # stopped
    assert expected == pytest.approx(0.3 * (size - 4) / size, abs=0.01)
    assert odometry(bus)[3] == pytest.approx(expected, abs=1e-6)
    world.close()


@pytest.mark.parametrize("params, linear_scale, angle_scale, separation_scale", [
    ({"wheel_radius_multiplier": 2.0}, 2.0, 1.0, 1.0),
    ({"wheel_separation_h_multiplier": 2.0}, 1.0, 1.0, 2.0),
    ({"steer_pos_multiplier": 0.5}, 1.0, 0.5, 1.0),
])
def test_the_multipliers_scale_the_odometry_only(params, linear_scale, angle_scale,
                                                separation_scale):
    """ASC:160-170, :231-235, :275, :333: the radius and separation multipliers and
    steer_pos_multiplier change what the odometry makes of the joints; the rear wheel is
    still commanded linear.x / wheel_radius (the radius as given) and the steering joint
    angular.z, so the base goes as without them."""
    world, bus, model = steer_bot(**params)
    drive_for(world, bus, 1.5, 0.3, 0.3)
    assert joint(model, "rear_wheel_joint")[1] == pytest.approx(0.3 / RADIUS, rel=1e-3)
    assert base(world)[4] == pytest.approx(turn_rate(0.3, 0.3), rel=0.02)
    linear, angular = odometry(bus)[3:]
    assert linear == pytest.approx(0.3 * linear_scale, rel=0.01)
    assert angular == pytest.approx(
        turn_rate(0.3 * linear_scale, 0.3 * angle_scale, WHEELBASE * separation_scale), rel=0.01)
    world.close()


def test_open_loop_odometry_integrates_the_commands_taking_the_angle_as_a_turn_rate():
    """ASC:158, :262-265, odometry.cpp:112-122: open_loop integrates the last limited command
    (linear.x, angular.z): the steering angle (0.3 rad) becomes the odometry's yaw rate, as
    written, while the base turns at 0.3 tan(0.3) / 0.4 = 0.23 rad/s."""
    world, bus, _ = steer_bot(open_loop=True)
    drive_for(world, bus, 1.0, 0.3, 0.3)
    linear, angular = odometry(bus)[3:]
    assert (linear, angular) == (pytest.approx(0.3), pytest.approx(0.3))
    assert base(world)[4] == pytest.approx(turn_rate(0.3, 0.3), rel=0.02)
    world.close()


# --- the geometry from the URDF ------------------------------------------------------------

def test_the_separation_and_radius_come_from_the_urdf_when_not_given():
    """ASC:218-229, :447-449, :454-463: without wheel_separation_h the odometry turns by
    tan(angle) × travel / |x of the rear wheel joint − x of the steering joint| (0.4 m);
    without wheel_radius the rear wheel is turned at v / its link's first collision's
    cylinder radius (0.1 m). Given, they are used as they are: 0.8 m halves the odometry's
    turn, 0.05 m doubles the wheel's speed (the base goes at 0.4 m/s, the odometry says
    0.2)."""
    world, bus, model = steer_bot()
    drive_for(world, bus, 1.0, 0.2, 0.3)
    assert odometry(bus)[4] == pytest.approx(turn_rate(0.2, 0.3), rel=0.01)
    assert joint(model, "rear_wheel_joint")[1] == pytest.approx(0.2 / RADIUS, rel=1e-3)
    world.close()
    world, bus, model = steer_bot(wheel_separation_h=2 * WHEELBASE, wheel_radius=RADIUS / 2)
    drive_for(world, bus, 1.0, 0.2, 0.3)
    assert joint(model, "rear_wheel_joint")[1] == pytest.approx(0.2 / (RADIUS / 2), rel=1e-3)
    assert base(world)[3] == pytest.approx(0.4, rel=0.02)
    assert odometry(bus)[3] == pytest.approx(0.2, rel=0.01)
    assert odometry(bus)[4] == pytest.approx(turn_rate(0.2, 0.3, 2 * WHEELBASE), rel=0.01)
    world.close()


def test_a_rear_wheel_not_a_cylinder_is_refused_unless_the_radius_is_given():
    """getWheelRadius, isCylinder (ASC:58-104, :454-463): the rear wheel link's first
    collision must be a cylinder ("Wheel link rear_wheel is NOT modeled as a cylinder!"; a
    sphere will not do, unlike the diff drive's); with wheel_radius given the URDF is not
    read for it and the controller loads."""
    urdf = steer_bot_urdf(rear_shape=f'<sphere radius="{RADIUS}"/>')
    loaded, warnings = load_only(urdf)
    assert not loaded
    assert any("Wheel link rear_wheel is NOT modeled as a cylinder!" in w
               and "does not have cylinder geometry" in w for w in warnings), warnings
    assert load_only(urdf, wheel_radius=RADIUS)[0]


# --- configurations that do not load -------------------------------------------------------

@pytest.mark.parametrize("params, cause", [
    ({"rear_wheel": "this_joint_does_not_exist"},
     "this_joint_does_not_exist couldn't be retrieved from model description"),
    ({"front_steer": ""}, " couldn't be retrieved from model description"),
    ({"rear_wheel": "", "wheel_separation_h": WHEELBASE, "wheel_radius": RADIUS},
     "Could not find resource '' in 'hardware_interface::VelocityJointInterface'."),
    ({"front_steer": "front_wheel_joint", "wheel_separation_h": WHEELBASE},
     "Could not find resource 'front_wheel_joint' in "
     "'hardware_interface::PositionJointInterface'."),
])
def test_a_missing_rear_wheel_or_front_steer_joint_is_refused_naming_it(params, cause):
    """ASC:218-229, :417-435, :246, :250 (upstream's fail, no_wheel and no_steer tests): a
    joint the URDF lacks fails the lookup of the separation; with the geometry given, a joint
    without a transmission on the interface fails getHandle ("Could not find resource ...",
    resource_manager.h:113-121), and the load fails (controller_manager.cpp:323-338)."""
    loaded, warnings = load_only(**params)
    assert not loaded
    assert any(cause in w and f"cannot load '{NAME}'" in w for w in warnings), warnings


@pytest.mark.parametrize("rear, steer, resource", [
    ("PositionJointInterface", "PositionJointInterface",
     "Could not find resource 'rear_wheel_joint' in 'hardware_interface::VelocityJointInterface'"),
    ("VelocityJointInterface", "VelocityJointInterface",
     "Could not find resource 'front_steer_joint' in "
     "'hardware_interface::PositionJointInterface'"),
])
def test_joints_on_the_wrong_interfaces_are_refused(rear, steer, resource):
    """ASC:129-135, :246, :250: the rear wheel's handle comes from the VelocityJointInterface,
    the steering's from the PositionJointInterface; DefaultRobotHWSim registers a joint on
    its transmission's interface only (gazebo_ros_pkgs f9e1a46 default_robot_hw_sim.cpp
    :153-186), so another interface fails the load."""
    loaded, warnings = load_only(steer_bot_urdf(rear, steer))
    assert not loaded
    assert any(resource in w for w in warnings), warnings


def test_the_joints_names_default_to_rear_wheel_joint_and_front_steer_joint():
    """ASC:143-148: without rear_wheel and front_steer the joints are rear_wheel_joint and
    front_steer_joint (the steer bot's): the controller loads and drives."""
    world, bus, model = steer_bot(rear_wheel=None, front_steer=None)
    drive_for(world, bus, 0.6, 0.3, 0.2)
    assert joint(model, "front_steer_joint")[0] == pytest.approx(0.2, abs=1e-3)
    assert base(world)[3] == pytest.approx(0.3, rel=0.02)
    world.close()


def test_the_manager_lists_the_type_and_its_claims_on_two_interfaces():
    """The spawner loads it by type (list_controller_types names it); list_controllers
    reports the claims of a MultiInterfaceController<PositionJointInterface,
    VelocityJointInterface> (ASC header :64-67): the steering joint on the position
    interface, then the rear wheel on the velocity one (ros_control 633c374
    controller_interface/internal/robothw_interfaces.h:123-143)."""
    world, bus, _ = steer_bot(start=False)
    types = bus.services[f"{MANAGER}/list_controller_types"](None).types
    assert TYPE in types
    state, = bus.services[f"{MANAGER}/list_controllers"](ListControllersRequest()).controller
    assert state.type == TYPE
    assert [(r.hardware_interface, list(r.resources)) for r in state.claimed_resources] == [
        (INTERFACE_NAMES["position"], ["front_steer_joint"]),
        (INTERFACE_NAMES["velocity"], ["rear_wheel_joint"])]
    world.close()


# --- timeout and limits --------------------------------------------------------------------

@pytest.mark.parametrize("timeout, travel", [(None, 0.15), (0.2, 0.06)])
def test_cmd_vel_timeout_stops_the_wheel_and_straightens_the_steering(timeout, travel):
    """ASC:116, :180, :313-321: a command older than cmd_vel_timeout (0.5 s, or as given)
    is 0 for both: one command at 0.3 m/s and 0.3 rad moves the base about 0.3 m/s × the
    timeout; then the rear wheel stands and the steering is back at 0."""
    world, bus, model = steer_bot(cmd_vel_timeout=timeout)
    x0, y0 = base(world)[:2]
    drive(bus, 0.3, 0.3)
    run(world, 0.1)
    assert joint(model, "front_steer_joint")[0] == pytest.approx(0.3, abs=1e-3)
    run(world, 1.0)
    x, y, _, forward, _ = base(world)
    assert math.hypot(x - x0, y - y0) == pytest.approx(travel, abs=0.01)
    assert abs(forward) < 0.005
    assert joint(model, "front_steer_joint")[0] == pytest.approx(0.0, abs=1e-3)
    world.close()


def test_velocity_limits_clamp_the_speed_and_the_steering_angle():
    """ASC:197-216 (diff drive's limiter, speed_limiter.cpp:86-96): linear/x max_velocity 0.2
    and angular/z max_velocity 0.2 hold a command of 0.5 m/s and 0.5 rad to 0.2 m/s and
    0.2 rad; min_velocity defaults to −max: −0.5 m/s reverses at 0.2 m/s."""
    limits = {"has_velocity_limits": True, "max_velocity": 0.2}
    world, bus, model = steer_bot(linear={"x": limits}, angular={"z": limits})
    drive_for(world, bus, 1.0, 0.5, 0.5)
    assert base(world)[3] == pytest.approx(0.2, rel=0.02)
    assert joint(model, "front_steer_joint")[0] == pytest.approx(0.2, abs=1e-3)
    drive_for(world, bus, 1.0, -0.5, -0.5)
    assert base(world)[3] == pytest.approx(-0.2, rel=0.02)
    assert joint(model, "front_steer_joint")[0] == pytest.approx(-0.2, abs=1e-3)
    world.close()


def test_acceleration_and_jerk_limits_ramp_the_speed_and_the_steering():
    """speed_limiter.cpp:98-135 on ASC's commands: angular/z max_acceleration 1 rad/s² turns
    the steering by 0.1 rad each 0.1 s toward a command of 0.5 rad (pybullet's position
    motor trails the ramp by a constant lag); linear/x max_jerk 5 m/s³ gives the n-th command
    from rest max_jerk × dt² × n(n+1) (0.0505 m/s at n = 100, 1 ms)."""
    world, bus, model = steer_bot(
        linear={"x": {"has_jerk_limits": True, "max_jerk": 5.0}},
        angular={"z": {"has_acceleration_limits": True, "max_acceleration": 1.0}})
    drive(bus, 0.5, 0.5)
    run(world, 0.1)
    dt = world.step_size
    n = int(round(0.1 / dt))
    assert joint(model, "rear_wheel_joint")[1] * RADIUS == pytest.approx(
        5.0 * dt * dt * n * (n + 1), rel=0.03)
    steer = joint(model, "front_steer_joint")[0]
    run(world, 0.1)
    assert joint(model, "front_steer_joint")[0] - steer == pytest.approx(0.1, abs=1e-3)
    world.close()


# --- publishing ----------------------------------------------------------------------------

def test_odometry_goes_out_at_the_publish_rate_with_the_frames_and_covariances_given():
    """ASC:152-156, :188-195, :280-308, :468-513: odom at publish_rate (10 Hz: ten in 1 s)
    from odom_frame_id to base_frame_id as written, the covariance diagonals given, and the
    same pose on /tf while enable_odom_tf."""
    diagonal = [0.001, 0.001, 1000000.0, 1000000.0, 1000000.0, 1000.0]  # upstream's test yaml
    world, bus, _ = steer_bot(publish_rate=10.0, odom_frame_id="my_odom",
                              base_frame_id="my_base", pose_covariance_diagonal=diagonal,
                              twist_covariance_diagonal=diagonal)
    before = len(bus.published.get(f"{CONTROLLER}/odom", []))
    drive_for(world, bus, 1.0, 0.3)
    messages = bus.published[f"{CONTROLLER}/odom"]
    assert len(messages) - before == 10
    last = messages[-1]
    assert (last.header.frame_id, last.child_frame_id) == ("my_odom", "my_base")
    assert [last.pose.covariance[7 * i] for i in range(6)] == diagonal
    assert [last.twist.covariance[7 * i] for i in range(6)] == diagonal
    transform = bus.published["/tf"][-1]
    assert (transform.header.frame_id, transform.child_frame_id) == ("my_odom", "my_base")
    assert transform.transform.translation.x == last.pose.pose.position.x > 0.25
    world.close()


def test_enable_odom_tf_false_sends_no_transform():
    """ASC:194, :300: enable_odom_tf false: the odometry goes out, /tf does not."""
    world, bus, _ = steer_bot(enable_odom_tf=False)
    drive_for(world, bus, 0.4, 0.3)
    assert bus.published[f"{CONTROLLER}/odom"]
    assert "/tf" not in bus.published
    world.close()


def test_publish_cmd_is_not_a_parameter_of_noetics_ackermann_controller():
    """ASC:125-257 read no publish_cmd (diff_drive_controller's, DDC:161, :276): with it set
    nothing goes out on cmd_vel_out."""
    world, bus, _ = steer_bot(publish_cmd=True)
    drive_for(world, bus, 0.4, 0.3)
    assert [t for t in bus.advertised if t.startswith(CONTROLLER + "/")] == [
        f"{CONTROLLER}/odom"]
    world.close()


# --- cmd_vel's other cases -----------------------------------------------------------------

@pytest.mark.parametrize("allow, publishers, moves", [(False, 2, False), (True, 2, True)])
def test_a_second_cmd_vel_publisher_brakes_when_only_one_is_allowed(allow, publishers, moves):
    """ASC:184, :368-374: with allow_multiple_cmd_vel_publishers false and two publishers a
    command is not taken ("Detected 2 publishers. Only 1 publisher is allowed. Going to
    brake.")."""
    from test_ros_control_diff_drive import CountingBus
    CountingBus.publishers = publishers
    world, bus, _ = steer_bot(bus_class=CountingBus, allow_multiple_cmd_vel_publishers=allow)
    x0 = base(world)[0]
    drive_for(world, bus, 0.4, 0.3)
    assert (base(world)[0] - x0 > 0.05) == moves
    assert any("Detected 2 publishers. Only 1 publisher is allowed. Going to brake." in w
               for w in bus.warnings) == (not moves)
    world.close()


def test_a_command_before_the_controller_runs_is_refused_and_stopping_brakes():
    """ASC:339-361, :386-389: not running, cmd_vel is refused ("Can't accept new commands.
    Controller is not running."); started, the base stays; stopped, the rear wheel's and the
    steering's commands are set to 0 once: the wheel stops; the steering's 0 passes the
    joint's saturation handle, which writes back a command one step's velocity limit (5
    rad/s × 1 ms) from the last, and nothing commands it again: it stays at 0.295 rad
    (DefaultRobotHWSim, gazebo_ros_pkgs f9e1a46 default_robot_hw_sim.cpp:302-307; ros_control
    633c374 joint_limits_interface.h:91-112)."""
    world, bus, model = steer_bot(start=False)
    drive(bus, 0.3, 0.3)
    assert any("Can't accept new commands. Controller is not running." in w
               for w in bus.warnings)
    switch(bus)
    x0 = base(world)[0]
    run(world, 0.3)
    assert base(world)[0] == pytest.approx(x0, abs=1e-3)
    drive(bus, 0.3, 0.3)
    run(world, 0.3)
    assert joint(model, "front_steer_joint")[0] == pytest.approx(0.3, abs=1e-3)
    assert bus.services[f"{MANAGER}/switch_controller"](
        SwitchControllerRequest(stop_controllers=[NAME], strictness=2)).ok
    run(world, 0.2)
    assert joint(model, "front_steer_joint")[0] == pytest.approx(0.295, abs=1e-3)
    assert abs(joint(model, "rear_wheel_joint")[1]) < 0.01
    world.close()


def test_a_nan_command_is_ignored():
    """ASC:363-379 takes a NaN and sends it to the joints, which would wreck the physics;
    sim_bridge ignores it, saying so (doc/ros_control.md's AckermannSteeringController
    table), and the last command goes on."""
    world, bus, _ = steer_bot()
    drive(bus, 0.3)
    drive(bus, math.nan, 0.2)
    run(world, 0.3)
    assert any("Received NaN in velocity command. Ignoring." in w for w in bus.warnings)
    assert base(world)[3] == pytest.approx(0.3, rel=0.02)
    world.close()
