"""gazebo_ros_imu_sensor as Noetic's (gazebo_ros_pkgs noetic-devel f9e1a46,
gazebo_plugins/src/gazebo_ros_imu_sensor.cpp): its default topic, its own rate
(updateRateHZ, 1 Hz when absent) throttling the sensor's updates, and no IMU at all
without <frameName>. Each test checks the messages that arrive: on which topic, at what
simulated times, with which stamps."""
import numpy as np
import pytest

from world_fixtures import run


def imu_robot(plugin, sensor_rate="<update_rate>100</update_rate>"):
    """A box resting on the floor with an IMU sensor on it; ``plugin``: the
    libgazebo_ros_imu_sensor.so plugin's parameters."""
    return f"""<robot name="r"><link name="base"><inertial><mass value="1"/>
      <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
      <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision></link>
      <gazebo reference="base"><sensor name="imu" type="imu">{sensor_rate}
        <plugin name="imu_plugin" filename="libgazebo_ros_imu_sensor.so">{plugin}</plugin>
      </sensor></gazebo></robot>"""


def stamps(bus, topic):
    return np.array([m.header.stamp.to_sec() for m in bus.published.get(topic, [])])


def test_the_default_topic_is_imu_data(world, bus):
    """No <topicName>: gazebo_plugins/src/gazebo_ros_imu_sensor.cpp:197 sets imu_data
    (before: imu). The messages arrive on /imu_data, at rest reading +g upwards."""
    world.spawn_urdf("r", imu_robot("<frameName>base</frameName>"
                                    "<updateRateHZ>100</updateRateHZ>"), (0, 0, 0.1))
    run(world, 0.5)
    assert "/imu" not in bus.published
    message = bus.last("/imu_data")
    assert message.header.frame_id == "base"
    assert message.linear_acceleration.z == pytest.approx(9.8, abs=0.05)


@pytest.mark.parametrize("sensor_rate", ["<update_rate>100</update_rate>", ""])
def test_without_update_rate_hz_it_publishes_once_a_second(world, bus, sensor_rate):
    """No <updateRateHZ>: gazebo_plugins/src/gazebo_ros_imu_sensor.cpp:221 sets 1.0, and
    :99 skips every world update until the sensor's last update time is 1/updateRateHZ
    past the last message's (before: the sensor's <update_rate>, or every step). The
    sensor at 100 Hz, or at every step: one message a second of simulated time, stamped
    at whole seconds."""
    world.spawn_urdf("r", imu_robot("<topicName>imu</topicName><frameName>base</frameName>",
                                    sensor_rate), (0, 0, 0.1))
    run(world, 5.5)
    assert stamps(bus, "/imu") == pytest.approx([1.0, 2.0, 3.0, 4.0, 5.0], abs=1e-9)


def test_update_rate_hz_above_the_sensors_rate_gives_the_sensors_rate(world, bus):
    """gazebo_plugins/src/gazebo_ros_imu_sensor.cpp:97-100 compare the sensor's last update
    time, so <updateRateHZ> 200 on a 50 Hz sensor publishes each of its updates, 50 a
    second (before: 200, <updateRateHZ> replaced the sensor's rate)."""
    world.spawn_urdf("r", imu_robot("<topicName>imu</topicName><frameName>base</frameName>"
                                    "<updateRateHZ>200</updateRateHZ>",
                                    "<update_rate>50</update_rate>"), (0, 0, 0.1))
    run(world, 1.0)
    times = stamps(bus, "/imu")
    assert len(times) == pytest.approx(50, abs=1)
    assert np.diff(times) == pytest.approx(0.02, abs=1e-9)


def test_update_rate_hz_0_publishes_every_world_update_with_the_sensors_stamp(world, bus):
    """<updateRateHZ> 0: gazebo_plugins/src/gazebo_ros_imu_sensor.cpp:99 skips no world
    update, and :139-140 stamp each message with the sensor's last update time: on a
    100 Hz sensor, a message every 1 ms step, ten to each stamp (before: each stamped with
    its own step)."""
    world.spawn_urdf("r", imu_robot("<topicName>imu</topicName><frameName>base</frameName>"
                                    "<updateRateHZ>0</updateRateHZ>"), (0, 0, 0.1))
    run(world, 0.1)
    times = stamps(bus, "/imu")
    assert len(times) == int(round(0.1 / world.step_size))
    assert len(set(np.round(times, 6))) == pytest.approx(10, abs=1)


def test_without_frame_name_nothing_is_published_and_the_cause_is_named(world, bus):
    """No <frameName>: gazebo_plugins/src/gazebo_ros_imu_sensor.cpp:207-210 log 'missing
    <frameName>, cannot proceed' and :71-75 stop loading: no topic, no message (before:
    published in the link's frame). Here the spawn's warning names the plugin, the tag and
    what to write; the robot runs without the IMU."""
    world.spawn_urdf("r", imu_robot("<topicName>imu</topicName>"
                                    "<updateRateHZ>100</updateRateHZ>"), (0, 0, 0.1))
    assert "r" in world.models
    (warning,) = [w for w in bus.warnings if "not loaded" in w]
    assert "libgazebo_ros_imu_sensor.so" in warning and "<frameName>" in warning
    assert "publishes nothing" in warning
    run(world, 1.5)
    assert not [t for t in bus.published if "imu" in t]


def test_gaussian_noise_is_added_to_each_quaternion_component_and_not_normalised(world, bus):
    """gazebo_plugins/src/gazebo_ros_imu_sensor.cpp:111-123: N(0, gaussianNoise) is added
    to the orientation's x, y, z and w as to the rates and accelerations, and the quaternion
    goes out as it is. At rest and level (true orientation the identity), over 300 messages
    each component scatters by about the noise around its true value and the norms are not
    1. Before: the orientation was the true one, exactly (no scatter, norm 1)."""
    noise = 0.1
    world.spawn_urdf("r", imu_robot("<frameName>base</frameName><updateRateHZ>100"
                                    f"</updateRateHZ><gaussianNoise>{noise}</gaussianNoise>"),
                     (0, 0, 0.1))
    run(world, 3.0)
    messages = bus.published["/imu_data"][-300:]
    quaternions = np.array([(m.orientation.x, m.orientation.y, m.orientation.z,
                             m.orientation.w) for m in messages])
    assert quaternions.mean(axis=0) == pytest.approx([0, 0, 0, 1], abs=4 * noise / 300 ** 0.5)
    assert quaternions.std(axis=0) == pytest.approx([noise] * 4, rel=0.15)
    norms = np.linalg.norm(quaternions, axis=1)
    assert np.abs(norms - 1.0).max() > noise
    rates = np.array([(m.angular_velocity.x, m.angular_velocity.y, m.angular_velocity.z)
                      for m in messages])
    assert rates.std(axis=0) == pytest.approx([noise] * 3, rel=0.15)
    assert list(messages[-1].orientation_covariance) == pytest.approx(
        [noise ** 2, 0, 0, 0, noise ** 2, 0, 0, 0, noise ** 2])
