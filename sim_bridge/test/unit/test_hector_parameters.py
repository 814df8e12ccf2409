"""hector_gazebo_plugins' IMU and GPS, parameter by parameter as their ROS 1 release reads
them (tu-darmstadt-ros-pkg/hector_gazebo melodic-devel de947fb, the branch Noetic's 0.5.4
is released from: hector_gazebo_plugins/src/gazebo_ros_imu.cpp, gazebo_ros_gps.cpp,
include/hector_gazebo_plugins/update_timer.h, sensor_model.h). test_imu_gps_plugins.py
checks the physics; this file the parameters the README's tables name."""
import math

import numpy as np
import pytest

from sim_bridge.plugins.body_state import q_multiply
from sim_bridge.poses import quaternion_from_rpy
from test_imu_gps_plugins import radii
from world_fixtures import run

ABSENT = None


def stamps_ms(bus, topic):
    return [round(m.header.stamp.to_nsec() / 1e6) for m in bus.published.get(topic, [])]


def plugin_robot(plugins):
    """A 0.2 m box resting on the ground, its link base_link, with ``plugins``."""
    return (f"<robot name='r'><link name='base_link'><inertial><mass value='1'/>"
            f"<inertia ixx='0.01' ixy='0' ixz='0' iyy='0.01' iyz='0' izz='0.01'/></inertial>"
            f"<collision><geometry><box size='0.2 0.2 0.2'/></geometry></collision>"
            f"</link><gazebo>{plugins}</gazebo></robot>")


def spawn(world, imu="", gps="", namespace="/", **kwargs):
    world.spawn_urdf("r", plugin_robot(
        f"<plugin name='imu' filename='libhector_gazebo_ros_imu.so'>{imu}</plugin>"
        f"<plugin name='gps' filename='libhector_gazebo_ros_gps.so'>{gps}</plugin>"),
        (0, 0, 0.1), namespace=namespace, **kwargs)


def vector(v):
    return np.array([v.x, v.y, v.z])


# --- the update timer ------------------------------------------------------------------------
def test_update_period_is_an_sdf_time_of_seconds_and_nanoseconds(world, bus):
    """updatePeriod is read as an sdf::Time (update_timer.h:62-71), ``_in >> sec >> nsec``
    (sdformat sdf9 include/sdf/Types.hh:185-191): "0 250000000" is 0.25 s, 4 Hz (before:
    unreadable, every step); "0.25" is 0 s, every step, as in Gazebo, with a warning (before:
    4 Hz)."""
    spawn(world, imu="<updatePeriod>0 250000000</updatePeriod>",
          gps="<updatePeriod>0.25</updatePeriod>")
    run(world, 0.55)
    assert stamps_ms(bus, "/imu") == [250, 500]
    assert len(bus.published["/fix"]) == 550
    (warning,) = [w for w in bus.warnings if "updatePeriod" in w]
    assert "'0.25'" in warning and "every step" in warning and "gps" in warning


def test_update_offset_shifts_the_multiples_of_the_period(world, bus):
    """updateOffset, an sdf::Time too (update_timer.h:73-82): updates where
    (t - offset + step/2) mod period < step (:141-156): 4 Hz offset 5 ms is 5, 255, 505 ms
    (before: the offset unreadable, 0: 250, 500)."""
    spawn(world, gps="<updateOffset>0 5000000</updateOffset>")
    run(world, 0.55)
    assert stamps_ms(bus, "/fix") == [5, 255, 505]
    assert not [w for w in bus.warnings if "updateOffset" in w]


# --- robotNamespace ------------------------------------------------------------------------
@pytest.mark.parametrize("own, spawned_in, under", [
    (ABSENT, "/r1", "/r1"), (ABSENT, "", ""), ("", "/r1", ""), ("team", "/r1", "/team")])
def test_the_namespace_is_the_tag_as_written(world, bus, own, spawned_in, under):
    """robotNamespace as written, "" when absent (gazebo_ros_imu.cpp:75-78,
    gazebo_ros_gps.cpp:70-73); the spawn request's goes to a plugin without one."""
    tag = "" if own is ABSENT else f"<robotNamespace>{own}</robotNamespace>"
    spawn(world, imu=tag, gps=tag, namespace=spawned_in)
    run(world, 0.25)
    for topic in ("imu", "imu/bias", "fix", "fix_velocity"):
        assert f"{under}/{topic}" in bus.published, sorted(bus.published)
    assert f"{under}/imu/calibrate" in bus.services


# --- libhector_gazebo_ros_imu.so -------------------------------------------------------------
def test_an_empty_imu_topic_publishes_nothing_and_calibrates_at_the_root(world, bus):
    """topicName "": no topic (gazebo_ros_imu.cpp:189-190), no bias topic (its default is
    empty then, :108-111), and the service <topicName>/calibrate is "/calibrate" (:113-116,
    :199-200)."""
    spawn(world, imu="<topicName></topicName>")
    run(world, 0.01)
    assert not [t for t in bus.published if "imu" in t]
    assert list(bus.services) == ["/calibrate"]


def test_scale_errors_yaw_errors_and_the_old_noise_parameter(world, bus):
    """accelScaleError multiplies the reading (sensor_model.h:52-53); yawOffset turns the
    orientation about the world's z (gazebo_ros_imu.cpp:370-387); yawGaussianNoise sets
    the orientation's z variance only (:430); gaussianNoise, gazebo_ros_imu's name, is both
    the accelerometer's and the gyroscope's noise when not 0 (:122-129, covariances
    :161-176)."""
    spawn(world, imu="<accelScaleError>1 1 2</accelScaleError><yawOffset>0.1</yawOffset>"
                     "<yawGaussianNoise>0.2</yawGaussianNoise>"
                     "<gaussianNoise>0.05</gaussianNoise>")
    run(world, 0.3)
    imu = bus.last("/imu")
    accelerations = np.array([vector(m.linear_acceleration) for m in
                              bus.published["/imu"][100:]])
    assert accelerations.mean(axis=0)[2] == pytest.approx(2 * 9.8, abs=0.03)
    bias = bus.last("/imu/bias").orientation
    assert (bias.x, bias.y, bias.z, bias.w) == pytest.approx(
        (0, 0, math.sin(0.05), math.cos(0.05)))
    assert imu.orientation_covariance[8] == pytest.approx(0.04)
    assert imu.linear_acceleration_covariance[0] == pytest.approx(0.0025)
    assert imu.angular_velocity_covariance[4] == pytest.approx(0.0025)


def test_rpy_offset_turns_on_the_worlds_side(world, bus):
    """rpyOffset (a quaternion read from roll pitch yaw, gazebo_ros_imu.cpp:146-159):
    rot = offset * link (:297); the link turned 1 rad about z."""
    spawn(world, imu="<rpyOffset>0.3 0 0</rpyOffset>",
          orientation=quaternion_from_rpy(0, 0, 1.0))
    run(world, 0.01)
    q = bus.last("/imu").orientation
    _, link = world.model("r").robot.link_pose("base_link")
    expected = q_multiply(quaternion_from_rpy(0.3, 0, 0), link)
    assert abs(np.dot((q.x, q.y, q.z, q.w), expected)) == pytest.approx(1.0, abs=1e-6)


# --- libhector_gazebo_ros_gps.so -------------------------------------------------------------
def test_the_position_and_velocity_offsets(world, bus):
    """offset (position, m) and velocityOffset (m/s) of the two error models
    (gazebo_ros_gps.cpp:156-157, :257-258): 10 m along the world's x is 10 m north at
    heading 0 (:277); the velocity's y as written (:281)."""
    spawn(world, gps="<offset>10 0 0</offset><velocityOffset>0 1 0</velocityOffset>")
    run(world, 0.25)
    radius_north, _ = radii(49.9)
    assert bus.last("/fix").latitude == pytest.approx(
        49.9 + math.degrees(10 / radius_north), abs=1e-10)
    assert vector(bus.last("/fix_velocity").vector) == pytest.approx((0, 1, 0), abs=1e-3)


def test_the_velocitys_drift_is_integrated_into_the_positions(world, bus):
    """After each fix the position's drift grows by dt times the velocity's
    (gazebo_ros_gps.cpp:269-271): a velocity drift of 1 m/s along x, updates at 0.25 s
    steps: the fixes at 0.75 and 1 s are 0.25 and 0.5 m north."""
    spawn(world)
    gps = next(p for p in world.model("r").plugins if p.spec.name == "gps")
    gps.velocity_model.current_drift = np.array([1.0, 0.0, 0.0])
    run(world, 1.0)
    radius_north, _ = radii(49.9)
    north = [math.radians(m.latitude - 49.9) * radius_north for m in bus.published["/fix"]]
    # (both drifts also decay by exp(-dt / 3600 s) an update)
    assert north == pytest.approx([0, 0, 0.25, 0.5], abs=1e-3)


def test_world_spherical_coordinates_are_not_read_and_a_warning_says_so(world, bus):
    """useWorldSphericalCoordinates (gazebo_ros_gps.cpp:101-113) takes the world's
    <spherical_coordinates>, which sim_bridge does not read: the plugin's reference stays,
    and a warning says so."""
    spawn(world, gps="<useWorldSphericalCoordinates>true</useWorldSphericalCoordinates>")
    run(world, 0.25)
    assert any("useWorldSphericalCoordinates is not emulated" in w for w in bus.warnings)
    assert bus.last("/fix").latitude == pytest.approx(49.9, abs=1e-4)
