"""The sensor rows of sim_bridge/README.md's plugin tables that had no test of their own:
the camera's clip planes, the old IMU's listeners and the tags it does not read, hector's
xyzOffset, its IMU's and GNSS's reset, and the services and dynamic_reconfigure servers the
tables say are not offered. Each checks the row's statement against pybullet's own state
(issue 30: a test per row that can fail)."""
import numpy as np
import pytest
from geometry_msgs.msg import Twist

from sim_bridge.poses import quaternion_matrix
from sim_bridge.world import World
from test_camera import CAMERA_HEIGHT, camera_of, crate
from test_camera import robot as camera_robot
from test_hector_parameters import radii
from test_hector_parameters import spawn as spawn_hector
from world_fixtures import run

WRITTEN_CLIP = "<near>0.05</near><far>50</far>"  # what test_camera's robot writes
CAMERA_X = 0.1  # m: the camera ahead of the robot's centre (test_camera's sensor pose)
CRATE_HALF_DEPTH = 0.25  # m: test_camera's crates are 0.5 m deep
BACKGROUND = 255  # TinyRenderer's clear colour, white on every channel
HECTOR_LATITUDE, HECTOR_LONGITUDE = 49.9, 8.9  # hector's GNSS reference defaults


def clipped_camera(world, near, far, face):
    """An image and depth from test_camera's robot with ``<clip>`` near and far, of a red
    crate whose face is ``face`` m ahead of the camera and nothing else in view (a world
    without the ground plane, which pybullet draws)."""
    world.add_sdf_model(crate("red", CAMERA_X + face + CRATE_HALF_DEPTH, 0.0, (1, 0, 0, 1)))
    world.spawn_urdf("cam_bot", camera_robot().replace(
        WRITTEN_CLIP, f"<near>{near}</near><far>{far}</far>"), (0, 0, CAMERA_HEIGHT))
    return camera_of(world).capture()


def red_pixels(rgb):
    return int(((rgb[:, :, 0] > 150) & (rgb[:, :, 1] < 80) & (rgb[:, :, 2] < 80)).sum())


@pytest.mark.parametrize("near, far, face, drawn", [
    (1.0, 50.0, 0.55, False), (0.05, 50.0, 0.55, True),  # inside near / beyond it
    (0.05, 5.0, 6.0, False), (0.05, 50.0, 6.0, True)])   # beyond far / within it
def test_nothing_nearer_than_near_or_farther_than_far_is_drawn(bus, near, far, face, drawn):
    """<clip> near and far (sdformat sdf9 sdf/1.6/camera.sdf:28-34): a crate 0.55 m ahead
    fills the image with near 0.05 and is not there at all with near 1.0 (every pixel the
    background, no depth); one 6 m ahead is seen with far 50, not with far 5."""
    world = World(bus, ray_threads=1)
    try:
        rgb, depth = clipped_camera(world, near, far, face)
    finally:
        world.close()
    if drawn:
        assert red_pixels(rgb) > 100
        assert np.nanmin(depth) == pytest.approx(face, abs=0.02)
    else:
        assert red_pixels(rgb) == 0
        assert (rgb == BACKGROUND).all() and np.isinf(depth).all()


# --- libgazebo_ros_imu.so ------------------------------------------------------------------
def old_imu_robot(extra=""):
    """A 1 kg box resting on the ground with gazebo_ros_imu on its link, and ``extra`` in
    the plugin."""
    return (f"<robot name='r'><link name='base_link'><inertial><mass value='1'/>"
            f"<inertia ixx='0.01' ixy='0' ixz='0' iyy='0.01' iyz='0' izz='0.01'/></inertial>"
            f"<collision><geometry><box size='0.2 0.2 0.2'/></geometry></collision></link>"
            f"<gazebo><plugin name='imu' filename='libgazebo_ros_imu.so'>"
            f"<bodyName>base_link</bodyName><topicName>imu</topicName>{extra}</plugin>"
            f"</gazebo></robot>")


def test_the_old_imu_computes_only_while_heard_and_its_first_reading_spans_the_pause(
        world, bus):
    """(subscribers): Noetic's plugin computes and publishes only while subscribed and keeps
    its last time and velocity meanwhile (gazebo_plugins/src/gazebo_ros_imu.cpp:236,
    :269-276, :337-342), so its first reading after a pause in listening spans the pause.
    A box at rest, unheard, lifted and pushed to 1 m/s: nothing goes out, and the first
    reading heard is the change of velocity since the plugin loaded over that whole time
    (was: every step computed and sent for nobody, the first heard reading one step's)."""
    bus.unheard.add("/imu")
    world.spawn_urdf("r", old_imu_robot(), (0, 0, 0.1), namespace="/")
    loaded_ns = world.now_ns  # upstream's last_time_: the load's (the next step's start)
    run(world, 0.05)
    world.set_state("r", (0, 0, 0.5), (0, 0, 0, 1), (1.0, 0, 0))
    run(world, 0.01)
    assert "/imu" not in bus.published
    bus.unheard.clear()
    run(world, world.step_size)
    assert len(bus.published["/imu"]) == 1
    heard = bus.last("/imu").linear_acceleration
    pause = (world.now_ns - loaded_ns) / 1e9
    velocity = world.twist("r")[0]  # the box is level: its axes are the world's
    assert (heard.x, heard.y, heard.z) == pytest.approx(
        tuple(v / pause for v in velocity), rel=1e-3, abs=1e-3)
    assert heard.x == pytest.approx(1.0 / pause, rel=1e-2)
    run(world, world.step_size)  # heard from now on: one step's change, gravity's fall
    heard = bus.last("/imu").linear_acceleration
    assert (heard.x, heard.y, heard.z) == pytest.approx((0, 0, -9.8), abs=1e-3)


def test_always_on_and_the_imu_noise_element_are_not_read(world, bus):
    """TurtleBot3 writes <alwaysOn> and a sensor-style <imu><noise> inside the model
    plugin; Noetic's gazebo_ros_imu reads neither (gazebo_plugins/src/gazebo_ros_imu.cpp:
    Load reads only :69-136's tags): alwaysOn false still publishes, and the noise written
    adds nothing (a box at rest reads exactly no rate and no acceleration, covariance 0)."""
    noise = ("<imu><noise><type>gaussian</type>"
             "<rate><mean>0.5</mean><stddev>0.3</stddev></rate>"
             "<accel><mean>1.0</mean><stddev>1.0</stddev></accel></noise></imu>")
    world.spawn_urdf("r", old_imu_robot("<alwaysOn>false</alwaysOn>" + noise), (0, 0, 0.1),
                     namespace="/")
    run(world, 0.3)  # settled on the ground
    imu = bus.last("/imu")
    rate, acceleration = imu.angular_velocity, imu.linear_acceleration
    assert (rate.x, rate.y, rate.z) == pytest.approx((0, 0, 0), abs=1e-4)
    assert (acceleration.x, acceleration.y, acceleration.z) == pytest.approx((0, 0, 0),
                                                                             abs=1e-3)
    assert list(imu.angular_velocity_covariance) == [0.0] * 9


# --- libhector_gazebo_ros_imu.so -------------------------------------------------------------
def spin(bus, world, rate):
    """The hector test robot on planar_move, turned at ``rate`` rad/s about z."""
    message = Twist()
    message.angular.z = rate
    bus.subscriptions["/cmd_vel"](message)


def hector_robot_on_planar_move(world, imu):
    """test_hector_parameters' box, with planar_move to turn it and two hector IMUs on its
    link: ``plain`` and ``offset`` (``imu`` added to the latter); in the air, where
    planar_move holds it, so that no friction brakes the turn."""
    from test_hector_parameters import plugin_robot
    world.spawn_urdf("r", plugin_robot(
        "<plugin name='move' filename='libgazebo_ros_planar_move.so'/>"
        "<plugin name='plain' filename='libhector_gazebo_ros_imu.so'>"
        "<topicName>plain</topicName></plugin>"
        f"<plugin name='offset' filename='libhector_gazebo_ros_imu.so'>"
        f"<topicName>offset</topicName>{imu}</plugin>"), (0, 0, 0.5), namespace="/")


def test_hector_reads_xyz_offset_to_no_effect(world, bus):
    """xyzOffset is read into the offset pose (hector_gazebo_plugins/src/gazebo_ros_imu.cpp:
    131-144) whose position is never used: the line that would add it is commented out
    (:296): an IMU 1 m off the turning axis reads what the one on it reads, with no
    centripetal acceleration (w^2 r = 1 m/s^2 at 1 rad/s)."""
    hector_robot_on_planar_move(world, "<xyzOffset>1 0 0</xyzOffset>")
    spin(bus, world, 1.0)
    run(world, 1.0)
    plain, offset = bus.published["/plain"], bus.published["/offset"]
    assert len(plain) == len(offset) > 0
    for a, b in zip(plain, offset):
        assert (b.linear_acceleration.x, b.linear_acceleration.y, b.linear_acceleration.z) \
            == (a.linear_acceleration.x, a.linear_acceleration.y, a.linear_acceleration.z)
    last = offset[-1]
    assert last.angular_velocity.z == pytest.approx(1.0, abs=1e-3)
    assert np.hypot(last.linear_acceleration.x, last.linear_acceleration.y) < 0.05
    assert not [w for w in bus.warnings if "xyzOffset" in w]


def hector(world, name):
    return next(p for p in world.model("r").plugins if p.spec.name == name)


def test_hector_imu_reset_starts_its_timer_state_and_drifts_again(world, bus):
    """Reset (hector_gazebo_plugins/src/gazebo_ros_imu.cpp:227-242): the timer's last
    update is forgotten, so the first update after it has dt 0 and reads no acceleration
    (update_timer.h:133-136 gives 0 without a last update); the last velocity and
    orientation start again; the three error models draw their drifts anew (with no
    <Drift> given: 0). Without the reset the first reading would be +g on z and the drifts
    those set before it."""
    spawn_hector(world, imu="<accelOffset>0.1 0 0</accelOffset>")
    run(world, 0.3)
    assert bus.last("/imu").linear_acceleration.z == pytest.approx(9.8, abs=1e-3)
    imu = hector(world, "imu")
    imu.accel_model.current_drift = np.array([0.5, 0.5, 0.5])
    imu.rate_model.current_drift = np.array([0.2, 0.2, 0.2])
    imu.yaw_model.current_drift = np.array([0.3])
    world.reset()
    before = len(bus.published["/imu"])
    run(world, world.step_size)
    (first,) = bus.published["/imu"][before:]
    accel = first.linear_acceleration
    assert (accel.x, accel.y, accel.z) == pytest.approx((0.1, 0, 0))  # the offset alone
    bias = bus.last("/imu/bias")
    assert (bias.angular_velocity.x, bias.angular_velocity.y, bias.angular_velocity.z) == \
        pytest.approx((0, 0, 0))
    assert bias.orientation.z == pytest.approx(0.0, abs=1e-12)  # no heading error
    run(world, 0.1)
    _, orientation = world.pose("r")
    up = quaternion_matrix(orientation).T @ np.array([0, 0, 9.8])
    accel = bus.last("/imu").linear_acceleration
    assert (accel.x - 0.1, accel.y, accel.z) == pytest.approx(tuple(up), abs=1e-3)


# --- libhector_gazebo_ros_gps.so -----------------------------------------------------------
def test_hector_gps_reset_draws_both_drifts_anew(world, bus):
    """Reset (hector_gazebo_plugins/src/gazebo_ros_gps.cpp:215-220): the timer and the
    position's and velocity's error models start again: drifts of 10 m north and 1 m/s
    set before it are gone after it (no <drift> given: drawn as 0), and the fix is the
    reference again, where the box stands."""
    spawn_hector(world)
    gps = hector(world, "gps")
    gps.position_model.current_drift = np.array([10.0, 0.0, 0.0])
    gps.velocity_model.current_drift = np.array([1.0, 0.0, 0.0])
    run(world, 0.25)
    radius_north, _ = radii(HECTOR_LATITUDE)
    north = np.radians(bus.last("/fix").latitude - HECTOR_LATITUDE) * radius_north
    assert north == pytest.approx(10.0, abs=1e-3)  # the drift is in the fix before
    world.reset()
    run(world, 0.25)
    fix, velocity = bus.last("/fix"), bus.last("/fix_velocity").vector
    assert (fix.latitude, fix.longitude) == pytest.approx((HECTOR_LATITUDE, HECTOR_LONGITUDE),
                                                          abs=1e-9)
    assert (velocity.x, velocity.y, velocity.z) == pytest.approx((0, 0, 0), abs=1e-3)


# --- what the tables say is not offered ------------------------------------------------------
def test_hectors_set_bias_reference_and_reconfigure_services_are_not_offered(world, bus):
    """hector's IMU offers set_accel_bias and set_rate_bias (hector_gazebo_plugins/SetBias,
    gazebo_ros_imu.cpp:202-203) and dynamic_reconfigure servers under <topicName>/accel,
    /rate, /yaw (:205-213); its GNSS set_reference_geopose (gazebo_ros_gps.cpp:177) and
    servers under <topicName>/position, /velocity, /status (:179-185): none is offered
    here, only the IMU's calibrate."""
    spawn_hector(world)
    run(world, 0.01)
    assert list(bus.services) == ["/imu/calibrate"]
    assert not [t for t in bus.advertised if "parameter" in t or "set_" in t]


def test_the_cameras_imager_rate_reconfigure_is_not_offered(world, bus):
    """GazeboRosCameraUtils starts a dynamic_reconfigure server for imager_rate under the
    camera's name (gazebo_plugins/src/gazebo_ros_camera_utils.cpp:61-70, :304-319): not
    offered, the camera's only topics are its image and info."""
    world.spawn_urdf("cam_bot", camera_robot(), (0, 0, CAMERA_HEIGHT))
    run(world, 0.15)
    assert not bus.services
    assert sorted(set(bus.advertised)) == ["/front/camera_info", "/front/image_raw"]
