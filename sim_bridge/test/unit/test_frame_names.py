"""A sensor plugin's <frameName> written with a leading '/' (``/base_scan``, as many public
robot packages write it), as each of Noetic's plugins makes the header's frame
(gazebo_ros_pkgs noetic-devel f9e1a46):

- the laser, the GPU laser and the range sensor pass it through tf::resolve with the
  tf_prefix (gazebo_plugins/src/gazebo_ros_laser.cpp:138, gazebo_ros_gpu_laser.cpp:141,
  gazebo_ros_range.cpp:203; ros/geometry noetic-devel fe344b6, tf/src/tf.cpp:159-185): a
  leading '/' makes the name absolute, the slash dropped and no prefix added; any other
  name gets the prefix;
- the IMU sensor puts the text in the header as written
  (gazebo_plugins/src/gazebo_ros_imu_sensor.cpp:204, :138): the slash kept, no prefix.
"""
import pytest

from world_fixtures import run

LASER = """<sensor type="ray" name="scanner"><update_rate>20</update_rate>
  <ray><scan><horizontal><samples>5</samples><min_angle>-0.1</min_angle>
  <max_angle>0.1</max_angle></horizontal></scan><range><min>0.1</min><max>5</max></range></ray>
  <plugin name="p" filename="{library}"><topicName>out</topicName>
  <frameName>{frame}</frameName></plugin></sensor>"""
RANGE = LASER.replace("{library}", "libgazebo_ros_range.so")
IMU = """<sensor type="imu" name="imu"><update_rate>100</update_rate>
  <plugin name="p" filename="libgazebo_ros_imu_sensor.so"><topicName>out</topicName>
  <updateRateHZ>100</updateRateHZ><frameName>{frame}</frameName></plugin></sensor>"""


def robot(sensor: str) -> str:
    return f"""<robot name="r"><link name="base"><inertial><mass value="1"/>
      <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
      <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision></link>
      <gazebo reference="base">{sensor}</gazebo></robot>"""


RESOLVED = [  # (written, tf_prefix, header) through tf::resolve
    ("/base_scan", "", "base_scan"),
    ("/base_scan", "r1", "base_scan"),
    ("base_scan", "r1", "r1/base_scan"),
    ("base_scan", "", "base_scan"),
]


@pytest.mark.parametrize("sensor", [
    LASER.replace("{library}", "libgazebo_ros_laser.so"),
    LASER.replace("{library}", "libgazebo_ros_gpu_laser.so"),
    RANGE,
], ids=["laser", "gpu_laser", "range"])
@pytest.mark.parametrize("written, tf_prefix, header", RESOLVED)
def test_a_rays_frame_goes_through_tf_resolve(world, bus, sensor, written, tf_prefix, header):
    world.spawn_urdf("r", robot(sensor.replace("{frame}", written)), (0, 0, 0.1),
                     tf_prefix=tf_prefix)
    run(world, 0.1)
    assert bus.last("/out").header.frame_id == header


@pytest.mark.parametrize("written, tf_prefix", [
    ("/imu_link", ""), ("/imu_link", "r1"), ("imu_link", "r1"), ("imu_link", "")])
def test_the_imus_frame_is_as_written(world, bus, written, tf_prefix):
    """Before: through tf::resolve as the laser's ('/imu_link' became 'imu_link', 'imu_link'
    with the prefix r1 'r1/imu_link')."""
    world.spawn_urdf("r", robot(IMU.replace("{frame}", written)), (0, 0, 0.1),
                     tf_prefix=tf_prefix)
    run(world, 0.1)
    assert bus.last("/out").header.frame_id == written
