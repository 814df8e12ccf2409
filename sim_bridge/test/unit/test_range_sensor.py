"""gazebo_ros_range: a sonar's reading is the distance to the nearest thing in its cone, as
the world has it; nothing in range reads +inf (REP 117)."""
import math

import pytest

from sim_bridge.sdf_world import LinkSpec, ModelSpec, ShapeSpec
from world_fixtures import run

SONAR_X = 0.15  # m: the sonar's offset ahead of the body's centre


def robot(plugin="", yaw=0.0):
    return f"""<robot name="sonar_bot"><link name="base">
      <inertial><mass value="5"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0"
        izz="0.1"/></inertial>
      <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision></link>
    <gazebo reference="base"><sensor type="ray" name="sonar">
      <pose>{SONAR_X} 0 0 0 0 {yaw}</pose><update_rate>20</update_rate>
      <ray><scan><horizontal><samples>5</samples><min_angle>-0.15</min_angle>
        <max_angle>0.15</max_angle></horizontal><vertical><samples>5</samples>
        <min_angle>0</min_angle><max_angle>0.15</max_angle></vertical></scan>
        <range><min>0.02</min><max>4.0</max><resolution>0.01</resolution></range></ray>
      <plugin name="sonar_plugin" filename="libgazebo_ros_range.so">
        <topicName>sonar/front</topicName><frameName>sonar_link</frameName>
        <radiation>infrared</radiation><fov>0.3</fov>{plugin}</plugin>
    </sensor></gazebo></robot>"""


def post(name, x, y):
    box = ShapeSpec("box", size=(0.1, 0.1, 1.0))
    return ModelSpec(name, True, pose=(x, y, 0.5, 0, 0, 0),
                     links=[LinkSpec("link", collisions=[box], visuals=[box])])


def test_the_floor_in_the_cone_is_what_it_reads(world, bus):
    # the same sonar with its cone reaching 0.15 rad down, 0.1 m above the floor: the floor
    # is met 0.1 / tan(0.15) = 0.66 m ahead, nearer than the post at 2 m
    world.add_sdf_model(post("ahead", 2.05, 0.0))
    world.spawn_urdf("sonar_bot", robot().replace("<min_angle>0</min_angle>",
                                                  "<min_angle>-0.15</min_angle>"), (0, 0, 0.1))
    run(world, 0.1)
    height = world.pose("sonar_bot")[0][2]
    assert bus.last("/sonar/front").range == pytest.approx(height / math.sin(0.15), abs=0.01)


def test_the_nearest_thing_in_the_cone_is_read(world, bus):
    world.add_sdf_model(post("ahead", 2.05, 0.0))      # face at x = 2.0
    world.add_sdf_model(post("aside", 1.05, 1.0))      # outside the +-0.15 rad cone
    world.spawn_urdf("sonar_bot", robot(), (0, 0, 0.1))
    run(world, 0.1)
    message = bus.last("/sonar/front")
    x = world.pose("sonar_bot")[0][0]
    assert message.range == pytest.approx(2.0 - (x + SONAR_X), abs=0.005)
    assert message.header.frame_id == "sonar_link"
    assert message.radiation_type == message.INFRARED and message.field_of_view == 0.3
    assert (message.min_range, message.max_range) == (0.02, 4.0)


def test_a_post_off_the_axis_but_in_the_cone_is_seen(world, bus):
    # at 1 m, the cone's edge ray (0.15 rad) passes 0.15 m aside: a post there is seen
    world.add_sdf_model(post("edge", 1.05, 0.14))
    world.spawn_urdf("sonar_bot", robot(), (0, 0, 0.1))
    run(world, 0.1)
    assert bus.last("/sonar/front").range < 1.0


def test_nothing_in_range_reads_infinity(world, bus):
    world.add_sdf_model(post("behind", -2.0, 0.0))
    world.spawn_urdf("sonar_bot", robot(), (0, 0, 0.1))
    run(world, 0.1)
    assert math.isinf(bus.last("/sonar/front").range)


ULTRASOUND, INFRARED = 0, 1  # sensor_msgs/Range


@pytest.mark.parametrize("written, radiation_type", [
    (None, ULTRASOUND), ("ultrasound", ULTRASOUND), ("infrared", INFRARED)])
def test_radiation_as_written(world, bus, written, radiation_type):
    """gazebo_plugins/src/gazebo_ros_range.cpp:127-134: <radiation> absent is ultrasound;
    :170-173: "ultrasound" is ULTRASOUND, "infrared" (as any other text) INFRARED."""
    tag = "" if written is None else f"<radiation>{written}</radiation>"
    world.spawn_urdf("sonar_bot", robot().replace("<radiation>infrared</radiation>", tag),
                     (0, 0, 0.1))
    run(world, 0.1)
    assert bus.last("/sonar/front").radiation_type == radiation_type
    assert not [w for w in bus.warnings if "<radiation>" in w]


@pytest.mark.parametrize("written", ["Ultrasound", "ULTRASOUND", "sonar", "laser", ""])
def test_any_text_but_ultrasound_is_infrared_and_named(world, bus, written):
    """gazebo_plugins/src/gazebo_ros_range.cpp:170-173 compare the text with "ultrasound"
    exactly; anything else, an empty tag included, is INFRARED, silently there (before:
    lower-cased, and an unknown text was ULTRASOUND). Here a warning names the text and
    what it reads as."""
    world.spawn_urdf("sonar_bot", robot().replace(
        "<radiation>infrared</radiation>", f"<radiation>{written}</radiation>"), (0, 0, 0.1))
    run(world, 0.1)
    assert bus.last("/sonar/front").radiation_type == INFRARED
    (warning,) = [w for w in bus.warnings if "<radiation>" in w]
    assert f"'{written}'" in warning and "INFRARED" in warning
