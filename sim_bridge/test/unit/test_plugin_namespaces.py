"""Where a spawned model's plugins live, as Gazebo places them: gazebo_ros's spawn service
gives the request's namespace ("/" from spawn_model at the top level) to every plugin that
names none and keeps a plugin's own <robotNamespace>; what a plugin makes of an empty tag, or
of none when the request named none, is the plugin's (gazebo_plugins' GazeboRos class: the
model's name; GetRobotNamespace, the laser's: the model's name for an empty tag only)."""
import os

import pytest
from urdf_tools.xacro_loader import expand

from world_fixtures import DATA, run

ABSENT, EMPTY = None, ""


@pytest.mark.parametrize("own,spawned_in,drive_under,laser_under", [
    (ABSENT, "/r1", "/r1", "/r1"),
    (ABSENT, "/", "", ""),                   # spawn_model at the top level
    (ABSENT, "", "/bot", ""),                # a request naming no namespace
    (EMPTY, "/r1", "/bot", "/bot"),
    (EMPTY, "/", "/bot", "/bot"),
    ("/", "/r1", "", ""),                    # the top level, whatever the request says
    ("/team_a", "/r1", "/team_a", "/team_a"),
    ("team_a", "", "/team_a", "/team_a"),
])
def test_the_plugins_namespace_is_gazebos(world, bus, diff_bot_xml, own, spawned_in,
                                          drive_under, laser_under):
    if own is ABSENT:
        xml = diff_bot_xml()
        assert "robotNamespace" not in xml
    else:
        xml = diff_bot_xml(namespace="@ns@").replace("@ns@", own)
    world.spawn_urdf("bot", xml, position=(0, 0, 0.1), namespace=spawned_in)
    run(world, 0.1)
    assert f"{drive_under}/cmd_vel" in bus.subscriptions, sorted(bus.subscriptions)
    assert f"{drive_under}/odom" in bus.published, sorted(bus.published)
    assert f"{laser_under}/scan" in bus.published, sorted(bus.published)


def sensor_bot_xml(camera_namespace):
    """The sensor test robot, its camera's <robotNamespace> set (None: absent)."""
    xml = expand(os.path.join(DATA, "sensor_bot.urdf.xacro"), {})
    if camera_namespace is None:
        return xml
    return xml.replace("<cameraName>front_camera</cameraName>",
                       f"<robotNamespace>{camera_namespace}</robotNamespace>"
                       "<cameraName>front_camera</cameraName>")


@pytest.mark.parametrize("own,spawned_in,camera_under", [
    (ABSENT, "/", "/front_camera"),
    (ABSENT, "", "/front_camera"),
    (EMPTY, "/", "/sensors/front_camera"),   # GazeboRosCameraUtils: GetRobotNamespace
    ("/", "/r1", "/front_camera"),
])
def test_a_cameras_namespace_is_gazebos(world, bus, own, spawned_in, camera_under):
    world.spawn_urdf("sensors", sensor_bot_xml(own), position=(0, 0, 0.1),
                     namespace=spawned_in)
    run(world, 0.2)
    assert f"{camera_under}/image_raw" in bus.published, sorted(bus.published)
