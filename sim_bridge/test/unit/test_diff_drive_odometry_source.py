"""gazebo_ros_diff_drive's <odometrySource> as Noetic reads it: an exact, case-sensitive
lookup in {"encoder": ENCODER, "world": WORLD} (gazebo_ros_pkgs noetic-devel f9e1a46,
gazebo_plugins/src/gazebo_ros_diff_drive.cpp:104-107 with GazeboRos::getParameter,
gazebo_plugins/include/gazebo_plugins/gazebo_ros_utils.h:281-293): any other text keeps the
default, world, with a warning. Told apart by behaviour: the robot is carried 2 m by
set_model_state without turning its wheels; world odometry follows it, encoder odometry
does not."""
import pytest

from world_fixtures import run


def odometry_after_a_carry(world, bus, xml):
    """odom's x after the robot, at rest at the origin, is put 2 m ahead."""
    world.spawn_urdf("bot", xml, (0, 0, 0))
    run(world, 0.2)
    position, orientation = world.pose("bot")
    world.set_state("bot", (position[0] + 2.0, position[1], position[2]), orientation)
    run(world, 0.1)
    return bus.last("/odom").pose.pose.position.x


def test_encoder_selects_the_encoders(world, bus, diff_bot_xml):
    """gazebo_plugins/src/gazebo_ros_diff_drive.cpp:105: "encoder" is ENCODER."""
    assert abs(odometry_after_a_carry(world, bus, diff_bot_xml(odometry_source="encoder"))) \
        < 0.01
    assert not [w for w in bus.warnings if "odometrySource" in w]


def test_world_selects_the_truth(world, bus, diff_bot_xml):
    """gazebo_plugins/src/gazebo_ros_diff_drive.cpp:106: "world" is WORLD."""
    assert odometry_after_a_carry(world, bus, diff_bot_xml(odometry_source="world")) \
        == pytest.approx(2.0, abs=0.01)
    assert not [w for w in bus.warnings if "odometrySource" in w]


@pytest.mark.parametrize("written", ["Encoder", "ENCODER", "0", "1", "World", "odometry"])
def test_any_other_text_is_world_with_a_warning(world, bus, diff_bot_xml, written):
    """gazebo_plugins/include/gazebo_plugins/gazebo_ros_utils.h:285-287: a text that is no
    key of the map (case counts) warns "no matching key" and keeps the default,
    gazebo_plugins/src/gazebo_ros_diff_drive.cpp:107 WORLD (before: "0", "Encoder" and
    "ENCODER" selected the encoders; "1" was world without a warning)."""
    assert odometry_after_a_carry(world, bus, diff_bot_xml(odometry_source=written)) \
        == pytest.approx(2.0, abs=0.01)
    (warning,) = [w for w in bus.warnings if "<odometrySource>" in w]
    assert f"'{written}'" in warning and "world" in warning
