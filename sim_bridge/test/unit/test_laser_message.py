"""The LaserScan as gazebo_ros_laser and gazebo_ros_gpu_laser fill it (gazebo_ros_pkgs
noetic-devel f9e1a46, gazebo_plugins/src/gazebo_ros_laser.cpp:188-205,
gazebo_plugins/src/gazebo_ros_gpu_laser.cpp:193-210): time_increment and scan_time are 0
whatever the sensor's rate ("instantaneous simulator scan"), and the intensities are the
sensor's, one per range: Gazebo's ray sensor gives each ray the <laser_retro> of what it
hits, 0 for a surface without one and for a ray that hits nothing (sim_bridge does not
emulate <laserRetro>, so all read 0)."""
import math

import pytest

from sim_bridge.sdf_world import LinkSpec, ModelSpec, ShapeSpec
from world_fixtures import run


@pytest.mark.parametrize("filename", ["libgazebo_ros_laser.so", "libgazebo_ros_gpu_laser.so"])
def test_scan_time_is_zero_and_an_intensity_comes_with_every_range(world, bus, diff_bot_xml,
                                                                    filename):
    """gazebo_plugins/src/gazebo_ros_laser.cpp:194-195 (gpu: :199-200) set time_increment
    and scan_time to 0; :202-205 (gpu: :207-210) copy the intensities, as many as the
    ranges. Before: scan_time 1/update_rate (0.05 s) and no intensities."""
    xml = diff_bot_xml().replace("libgazebo_ros_laser.so", filename)
    world.add_sdf_model(ModelSpec("wall", True, pose=(3.2, 0, 0.5, 0, 0, 0), links=[LinkSpec(
        "link", collisions=[ShapeSpec("box", size=(0.4, 1.0, 1.0))])]))
    world.spawn_urdf("bot", xml, (0, 0, 0))
    run(world, 0.5)
    scans = bus.published["/scan"]
    assert len(scans) >= 10  # the sensor's 20 Hz
    for scan in scans:
        assert scan.scan_time == 0.0 and scan.time_increment == 0.0
        assert len(scan.intensities) == len(scan.ranges) == 361
        assert set(scan.intensities) == {0.0}
    last = scans[-1]
    assert last.header.frame_id == "laser"
    assert last.header.stamp.to_nsec() <= world.now_ns
    ranges = last.ranges
    assert ranges[180] == pytest.approx(2.85, abs=0.01)  # the wall ahead: a hit reads 0
    assert math.isinf(ranges[0])  # nothing to the right: no hit, 0 too
