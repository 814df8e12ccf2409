"""libgazebo_ros_imu.so, libhector_gazebo_ros_imu.so and libhector_gazebo_ros_gps.so on
pybullet.DIRECT, against ground truth and against upstream's formulas written out here
independently of the plugins (test/data/imu_gps_bot.urdf.xacro: a frictionless box turned
and moved by planar_move, with frame-only links on fixed joints)."""
import math
import os
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from geometry_msgs.msg import Twist
from std_srvs.srv import EmptyRequest, EmptyResponse

from sim_bridge.gazebo_tags import PluginSpec
from sim_bridge.plugins import MODEL_PLUGINS, PluginError
from sim_bridge.plugins.base import PluginContext
from sim_bridge.poses import quaternion_matrix, yaw_from_quaternion
from sim_bridge.sdf_world import LinkSpec, ModelSpec, ShapeSpec
from sim_bridge.world import World
from urdf_tools.xacro_loader import expand

from recording_bus import RecordingBus
from world_fixtures import DATA, run

RATE = 0.5  # rad/s, the turn commanded in the turning tests
IMU_ARM = 0.1  # m, imu_link ahead of the box's vertical axis
GPS_HEIGHT = 0.2  # m, gps_link above base_link
REFERENCE = (40.4168, -3.7038, 650.0)  # the fixture's latitude, longitude, altitude


def bot_xml(**arguments):
    return expand(os.path.join(DATA, "imu_gps_bot.urdf.xacro"),
                  {k: str(v) for k, v in arguments.items()})


def make_world(bus, seed=0):
    world = World(bus, seed=seed, ray_threads=1)
    world.add_sdf_model(ModelSpec("ground", True, links=[
        LinkSpec("link", collisions=[ShapeSpec("plane")])]))
    return world


def spawn(world, **arguments):
    model = world.spawn_urdf("bot", bot_xml(**arguments), (0, 0, 0.001))
    run(world, 0.5)
    return model


@pytest.fixture
def bot(world):
    return spawn(world)


def command(bus, forward=0.0, turn=0.0):
    message = Twist()
    message.linear.x, message.angular.z = forward, turn
    bus.subscriptions["/cmd_vel"](message)


def vector(v):
    return np.array([v.x, v.y, v.z])


def quaternion(q):
    return np.array([q.x, q.y, q.z, q.w])


def same_rotation(a, b, tolerance=1e-6):
    return abs(abs(float(np.dot(a, b))) - 1.0) < tolerance


def readings(bus, topic, field):
    return np.array([vector(getattr(m, field)) for m in bus.published[topic]])


# --- the plugin-less sensor ------------------------------------------------------------------
def test_a_plugin_less_sensor_warns_only_when_no_model_plugin_reads_its_link(bus, bot):
    assert not [w for w in bus.warnings if "'imu'" in w]  # TurtleBot3's: read by imu_plugin
    (bumper,) = [w for w in bus.warnings if "'bumper'" in w]  # nobody reads base_link
    assert "has no plugin" in bumper


# --- libgazebo_ros_imu.so ----------------------------------------------------------------
def test_old_imu_at_rest_reads_no_gravity_as_upstream(bus, bot):
    # upstream: acceleration = Δv/Δt of the link in the world, turned by its orientation;
    # at rest Δv = 0, so all three read 0 (no +9.8: that is the sensor plugin's)
    imu = bus.last("/imu")
    assert imu.header.frame_id == "imu_link"
    assert np.abs(vector(imu.linear_acceleration)).max() < 1e-3
    assert np.abs(vector(imu.angular_velocity)).max() < 1e-4
    _, truth = bot.robot.link_pose("imu_link")
    assert same_rotation(quaternion(imu.orientation), truth)
    assert list(imu.linear_acceleration_covariance) == [0.0] * 9
    assert len(bus.published["/imu"]) == 500  # updateRate 0: every 1 ms step of 0.5 s
    assert isinstance(bus.services["/imu_service"](EmptyRequest()), EmptyResponse)
    assert "/default_imu" in bus.services  # tilted_imu's serviceName, upstream's default


def test_old_imu_reads_a_free_fall_as_minus_g(world, bus):
    world.set_physics(world.step_size, world.max_update_rate, (0.0, 0.0, -9.8))
    # without planar_move, which holds the box's vertical velocity at 0 as Noetic's does
    world.spawn_urdf("bot", bot_xml(planar_move="false"), (0, 0, 5.0))
    run(world, 0.1)
    assert vector(bus.last("/imu").linear_acceleration) == pytest.approx((0, 0, -9.8), abs=1e-3)
    assert vector(bus.last("/hector_imu").linear_acceleration) == \
        pytest.approx((0, 0, 0), abs=1e-3)  # hector: specific force, weightless in a fall


def test_old_imu_turning_reads_the_rate_and_the_acceleration_in_its_frame(world, bus, bot):
    command(bus, turn=RATE)
    run(world, 1.0)
    imu = bus.last("/imu")
    assert vector(imu.angular_velocity) == pytest.approx((0, 0, RATE), abs=1e-3)
    # the truth: imu_link circles the axis at IMU_ARM, centripetal ω² r toward the axis
    _, orientation = bot.robot.link_pose("imu_link")
    yaw = yaw_from_quaternion(orientation)
    centripetal = -RATE ** 2 * IMU_ARM * np.array([math.cos(yaw), math.sin(yaw), 0.0])
    # in the sensor's frame (upstream turns it by R(q) instead of R(q)^T: not copied)
    expected = quaternion_matrix(orientation).T @ centripetal
    assert vector(imu.linear_acceleration) == pytest.approx(expected, abs=2e-3)
    assert vector(imu.linear_acceleration)[:2] == \
        pytest.approx((-RATE ** 2 * IMU_ARM, 0.0), abs=2e-3)
    hector = bus.last("/hector_imu")
    assert vector(hector.linear_acceleration)[:2] == \
        pytest.approx((-RATE ** 2 * IMU_ARM, 0.0), abs=2e-3)


def test_old_imu_on_a_tilted_link_reads_the_rate_in_its_frame(world, bus, bot):
    command(bus, turn=RATE)
    run(world, 1.0)
    _, orientation = bot.robot.link_pose("tilted_link")
    world_rate = np.array([0.0, 0.0, RATE])
    in_sensor = quaternion_matrix(orientation).T @ world_rate  # what a gyroscope reads
    assert vector(bus.last("/tilted_imu").angular_velocity) == pytest.approx(in_sensor, abs=1e-3)
    assert vector(bus.last("/hector_tilted").angular_velocity) == \
        pytest.approx(in_sensor, abs=1e-3)
    assert in_sensor == pytest.approx((-RATE, 0, 0), abs=1e-5)  # z of the world is -x here


def test_old_imu_update_rate_waits_a_period_since_the_last_message(world, bus):
    spawn(world, imu_rate=30)
    stamps = [m.header.stamp.to_nsec() for m in bus.published["/imu"]]
    # 1/30 s = 33.3 ms; on 1 ms steps the first step at least that late is 34 ms after
    assert np.diff(stamps).tolist() == [34_000_000] * (len(stamps) - 1)
    assert stamps[0] == 34_000_000 and len(stamps) == 14


def test_old_imu_noise_is_seeded():
    def noisy(seed):
        recording = RecordingBus()
        simulated = make_world(recording, seed)
        try:
            spawn(simulated, imu_noise=0.1)
            return readings(recording, "/imu", "angular_velocity")
        finally:
            simulated.close()

    first, again, other = noisy(7), noisy(7), noisy(8)
    assert np.array_equal(first, again)
    assert not np.allclose(first, other)
    assert np.std(first[:, 2]) == pytest.approx(0.1, rel=0.15)


def test_old_imu_after_a_reset_reads_no_spike(world, bus, bot):
    command(bus, forward=0.5)
    run(world, 0.3)
    before = len(bus.published["/imu"])
    # planar_move keeps its command across a reset, as Noetic's has no Reset
    # (gazebo_plugins/include/gazebo_plugins/gazebo_ros_planar_move.h:47-56): stop it first
    command(bus)
    world.reset()  # back at rest where spawned: no jump from 0.5 m/s to 0 in one step
    run(world, 0.01)
    after = readings(bus, "/imu", "linear_acceleration")[before:]
    assert len(after) == 10
    assert after[:, :2] == pytest.approx(np.zeros((10, 2)), abs=1e-3)  # no 500 m/s² jump
    # 1 mm above the ground, held there by planar_move, which sets the vertical velocity
    # to 0 every update as Noetic's (gazebo_plugins/src/gazebo_ros_planar_move.cpp:204-207):
    # the reset's rest, then -g dt after each step's gravity, the same every step, so
    # upstream's reading (no gravity in it) is -g once, then 0
    assert after[:, 2] == pytest.approx([-9.8] + [0.0] * 9, abs=1e-3)


# --- libhector_gazebo_ros_imu.so --------------------------------------------------------
def test_hector_imu_at_rest_reads_gravity_upwards(bus, bot):
    messages = bus.published["/hector_imu"]
    assert len(messages) == 50  # updateRate 100 over 0.5 s
    assert messages[0].header.stamp.to_nsec() == 10_000_000  # multiples of the period
    first = messages[0]  # no time step yet: zero acceleration and rate
    assert vector(first.linear_acceleration) == pytest.approx((0, 0, 0))
    imu = messages[-1]
    assert imu.header.frame_id == "imu_link"
    assert vector(imu.linear_acceleration) == pytest.approx((0, 0, 9.8), abs=1e-3)
    assert np.abs(vector(imu.angular_velocity)).max() < 1e-4
    _, truth = bot.robot.link_pose("imu_link")
    assert same_rotation(quaternion(imu.orientation), truth)
    assert vector(bus.last("/hector_tilted").linear_acceleration) == \
        pytest.approx((-9.8, 0, 0), abs=1e-3)  # pitched a quarter turn: up is -x
    assert "/hector_imu/calibrate" in bus.services and "/hector_imu/bias" in bus.published


def test_hector_imu_turning_reads_the_rate(world, bus, bot):
    command(bus, turn=RATE)
    run(world, 1.0)
    assert vector(bus.last("/hector_imu").angular_velocity) == \
        pytest.approx((0, 0, RATE), abs=1e-3)


def test_hector_imu_offsets_bias_topic_and_orientation_error(world, bus):
    spawn(world, hector_accel_offset="0.1 0.2 0.3", hector_rate_offset="0.01 0.02 0.03",
          hector_noise="0.05 0.05 0.05")
    imu, bias = bus.last("/hector_imu"), bus.last("/hector_imu/bias")
    assert vector(bias.linear_acceleration) == pytest.approx((0.1, 0.2, 0.3))
    assert vector(bias.angular_velocity) == pytest.approx((0.01, 0.02, 0.03))
    # hector's pseudo-AHRS: roll error bias_y / 2g, pitch error -bias_x / 2g (level link)
    tilt = np.array([0.5 * 0.2 / 9.8, -0.5 * 0.1 / 9.8, 0.0, 1.0])
    assert quaternion(bias.orientation) == pytest.approx(tilt / np.linalg.norm(tilt))
    assert imu.linear_acceleration_covariance[0] == pytest.approx(0.0025)
    assert imu.orientation_covariance[0] == pytest.approx(0.0025 / 9.8 ** 2)
    assert imu.orientation_covariance[8] == 0.0
    # the offsets show in the mean over the half second's readings
    # (after 0.1 s: the box lands from its 1 mm spawn height within the first 20 ms)
    accelerations = readings(bus, "/hector_imu", "linear_acceleration")[10:]
    rates = readings(bus, "/hector_imu", "angular_velocity")[10:]
    assert accelerations.mean(axis=0) == pytest.approx((0.1, 0.2, 10.1), abs=0.03)
    assert rates.mean(axis=0) == pytest.approx((0.01, 0.02, 0.03), abs=0.03)


def test_hector_calibrate_zeroes_the_gyroscope_drift(world, bus):
    spawn(world, hector_rate_offset="0.01 0.02 0.03")
    hector = next(p for p in world.model("bot").plugins if p.spec.name == "hector_imu")
    hector.rate_model.current_drift = np.array([0.5, 0.5, 0.5])
    bus.services["/hector_imu/calibrate"](EmptyRequest())
    run(world, 0.02)
    assert vector(bus.last("/hector_imu/bias").angular_velocity) == \
        pytest.approx((0.01, 0.02, 0.03))


def test_hector_imu_noise_is_seeded():
    def noisy(seed):
        recording = RecordingBus()
        simulated = make_world(recording, seed)
        try:
            spawn(simulated, hector_noise="0.1 0.1 0.1")
            return readings(recording, "/hector_imu", "linear_acceleration")
        finally:
            simulated.close()

    first, again, other = noisy(3), noisy(3), noisy(4)
    assert np.array_equal(first, again)
    assert not np.allclose(first, other)


# --- libhector_gazebo_ros_gps.so ---------------------------------------------------------
def radii(latitude):
    """hector's flat-earth radii (WGS84), from the formulas, not from the plugin."""
    a, f = 6378137.0, 1 / 298.257223563
    e2 = f * (2 - f)
    w = 1 - e2 * math.sin(math.radians(latitude)) ** 2
    return a * (1 - e2) / w ** 1.5, a * math.cos(math.radians(latitude)) / math.sqrt(w)


def test_gps_reads_the_reference_at_the_origin(bus, bot):
    fixes = bus.published["/fix"]
    assert [m.header.stamp.to_nsec() for m in fixes] == [250_000_000, 500_000_000]  # 4 Hz
    fix = fixes[-1]
    assert (fix.latitude, fix.longitude) == pytest.approx(REFERENCE[:2], abs=1e-9)
    position, _ = bot.robot.link_pose("gps_link")
    assert fix.altitude == pytest.approx(REFERENCE[2] + position[2], abs=1e-9)
    assert position[2] == pytest.approx(GPS_HEIGHT, abs=2e-3)
    assert fix.header.frame_id == "gps_link"
    assert (fix.status.status, fix.status.service) == (0, 0)
    assert fix.position_covariance_type == 2 and list(fix.position_covariance) == [0.0] * 9
    assert bus.last("/fix_velocity").header.frame_id == "gps_link"


@pytest.mark.parametrize("heading", [0.0, 90.0, 30.0])
@pytest.mark.parametrize("east, north", [(100.0, 0.0), (0.0, 100.0)])
def test_gps_moves_by_the_right_degrees_for_100_m(world, bus, heading, east, north):
    spawn(world, gps_heading=heading)
    start, orientation = world.pose("bot")
    world.set_state("bot", (start[0] + east, start[1] + north, start[2]), orientation)
    run(world, 0.25)
    fix = bus.last("/fix")
    radius_north, radius_east = radii(REFERENCE[0])
    x, y = east, north  # the world's axes; hector: x is the heading's direction, y 90° left
    psi = math.radians(heading)
    expected_latitude = REFERENCE[0] + math.degrees(
        (math.cos(psi) * x + math.sin(psi) * y) / radius_north)
    expected_longitude = REFERENCE[1] - math.degrees(
        (-math.sin(psi) * x + math.cos(psi) * y) / radius_east)
    assert fix.latitude == pytest.approx(expected_latitude, abs=1e-10)
    assert fix.longitude == pytest.approx(expected_longitude, abs=1e-10)
    if heading == 0.0 and east:  # x north: 100 m is 0.0009° of latitude (111 km a degree)
        assert fix.latitude - REFERENCE[0] == pytest.approx(100 / 111_030, rel=2e-3)
        assert fix.longitude == pytest.approx(REFERENCE[1], abs=1e-12)
    if heading == 0.0 and north:  # y west: longitude falls, 85 km a degree at 40.4°
        assert fix.longitude - REFERENCE[1] == pytest.approx(-100 / 84_940, rel=2e-3)


def test_gps_velocity_is_turned_by_the_heading(world, bus):
    spawn(world, gps_heading=90.0)
    command(bus, forward=1.0)
    run(world, 0.5)
    # heading 90°: the world's x points east; hector's formula puts east at -y
    assert vector(bus.last("/fix_velocity").vector) == pytest.approx((0.0, -1.0, 0.0),
                                                                     abs=5e-3)


def test_gps_noise_is_seeded_and_sets_the_covariance():
    def noisy(seed):
        recording = RecordingBus()
        simulated = make_world(recording, seed)
        try:
            spawn(simulated, gps_noise="1 1 1")
            run(simulated, 1.0)
            fixes = recording.published["/fix"]
            return np.array([(m.latitude, m.longitude, m.altitude) for m in fixes]), fixes[-1]
        finally:
            simulated.close()

    (first, fix), (again, _), (other, _) = noisy(5), noisy(5), noisy(6)
    assert np.array_equal(first, again)
    assert not np.allclose(first, other, rtol=0, atol=1e-9)
    assert list(fix.position_covariance) == [1.0, 0, 0, 0, 1.0, 0, 0, 0, 1.0]


# --- refusals --------------------------------------------------------------------------------
def build(world, filename, **params):
    """The plugin ``filename`` built on the spawned bot with ``params``."""
    context = PluginContext(world.client, world.model("bot").robot, "bot", "", RecordingBus(),
                            np.random.default_rng(0), world.step_size)
    spec = PluginSpec("probe", filename, params, ET.Element("plugin"))
    return MODEL_PLUGINS[filename](context, spec)


@pytest.mark.parametrize("filename", ["libgazebo_ros_imu.so", "libhector_gazebo_ros_imu.so",
                                      "libhector_gazebo_ros_gps.so"])
def test_a_body_the_model_lacks_is_refused_naming_it(world, bot, filename):
    with pytest.raises(PluginError) as error:
        build(world, filename, bodyName="no_such_link")
    for word in ("'probe'", filename, "<bodyName>", "'no_such_link'", "model 'bot'",
                 "imu_link"):  # the links it does have
        assert word in str(error.value)
    assert build(world, filename, bodyName="bot::gps_link").body == "gps_link"  # scoped


def test_old_imu_needs_a_body_hectors_take_the_canonical_link(world, bot):
    with pytest.raises(PluginError, match="'probe'.*needs <bodyName>"):
        build(world, "libgazebo_ros_imu.so")
    assert build(world, "libhector_gazebo_ros_imu.so").body == "base_link"
    assert build(world, "libhector_gazebo_ros_gps.so").body == "base_link"


@pytest.mark.parametrize("params, words, attribute, default", [
    ({"referenceLatitude": "north"}, "<referenceLatitude> 'north' is not a number",
     "latitude", 49.9),
    ({"status": "1.5"}, "<status> '1.5' is not a whole number from -128 to 127", "status", 0),
])
def test_gps_values_that_cannot_be_read_take_the_default_named(world, bot, params, words,
                                                               attribute, default):
    plugin = build(world, "libhector_gazebo_ros_gps.so", **params)
    (warning,) = plugin.context.bus.warnings
    assert words in warning and f"its default, {default}" in warning
    assert getattr(plugin, attribute) == pytest.approx(default)


def test_gps_noise_that_cannot_be_read_is_named_and_taken_as_none(world, bot):
    plugin = build(world, "libhector_gazebo_ros_gps.so", gaussianNoise="1 2")
    assert "<gaussianNoise> '1 2' is not three numbers" in plugin.context.bus.warnings[0]
    assert not plugin.position_model.gaussian_noise.any()


def test_a_gps_topic_written_empty_is_refused(world, bot):
    with pytest.raises(PluginError, match="<topicName> is empty"):
        build(world, "libhector_gazebo_ros_gps.so", topicName="")


def plugin_robot(plugin):
    return (f"<robot name='r'><link name='base_link'><inertial><mass value='1'/>"
            f"<inertia ixx='0.01' ixy='0' ixz='0' iyy='0.01' iyz='0' izz='0.01'/></inertial>"
            f"</link><gazebo>{plugin}</gazebo></robot>")


def test_old_imu_takes_singular_offsets_and_its_frame_as_written(world, bus):
    world.spawn_urdf("r", plugin_robot(
        "<plugin name='old' filename='libgazebo_ros_imu.so'><bodyName>r::base_link</bodyName>"
        "<xyzOffsets>0 0 1</xyzOffsets></plugin>"), (0, 0, 1))
    assert any("<xyzOffset>, not <xyzOffsets>" in w for w in bus.warnings)
    run(world, 0.01)
    assert bus.last("/default_imu").header.frame_id == "r::base_link"  # as written


def test_hector_plugins_default_to_the_canonical_link(world, bus):
    world.spawn_urdf("r", plugin_robot(
        "<plugin name='imu' filename='libhector_gazebo_ros_imu.so'/>"
        "<plugin name='gps' filename='libhector_gazebo_ros_gps.so'/>"), (0, 0, 1))
    run(world, 0.25)
    assert bus.last("/imu").header.frame_id == "base_link"
    fix = bus.last("/fix")
    assert fix.header.frame_id == "/world"  # hector's default frameId
    assert (fix.latitude, fix.longitude) == pytest.approx((49.9, 8.9), abs=1e-4)

