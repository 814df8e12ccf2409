"""gazebo_ros_bumper: what touches the named collision, with the force it bears, as the
world has it (a 2 kg crate resting on a bumper plate presses it with 2 g newtons), in the
world's coordinates whatever <frameName> says, as Noetic's (gazebo_ros_pkgs noetic-devel
f9e1a46, gazebo_plugins/src/gazebo_ros_bumper.cpp)."""
import pytest

from sim_bridge.sdf_world import LinkSpec, ModelSpec, ShapeSpec
from world_fixtures import run

G = 9.8
CRATE_MASS = 2.0


def robot(collision="base_link_fixed_joint_lump__bumper_collision", frame=""):
    return f"""<robot name="bot">
      <link name="base_link"><inertial><mass value="10"/><inertia ixx="0.2" ixy="0" ixz="0"
        iyy="0.2" iyz="0" izz="0.2"/></inertial>
        <collision><geometry><box size="0.4 0.4 0.2"/></geometry></collision></link>
      <joint name="bumper_joint" type="fixed"><parent link="base_link"/><child link="bumper"/>
        <origin xyz="0 0 0.11"/></joint>
      <link name="bumper"><inertial><mass value="0.1"/><inertia ixx="1e-3" ixy="0" ixz="0"
        iyy="1e-3" iyz="0" izz="1e-3"/></inertial>
        <collision><geometry><box size="0.3 0.3 0.02"/></geometry></collision></link>
      <gazebo reference="bumper"><sensor name="plate" type="contact">
        <update_rate>50</update_rate><contact><collision>{collision}</collision></contact>
        <plugin name="plate_plugin" filename="libgazebo_ros_bumper.so">
          <bumperTopicName>plate_bumper</bumperTopicName>{frame}</plugin>
      </sensor></gazebo></robot>"""


def crate(x=0.0, y=0.0):
    box = ShapeSpec("box", size=(0.2, 0.2, 0.2))
    return ModelSpec("crate", False, pose=(x, y, 0.35, 0, 0, 0), links=[LinkSpec(
        "link", collisions=[box], visuals=[box], mass=CRATE_MASS,
        inertia=(0.013, 0.013, 0.013))])


def test_a_crate_on_the_plate_presses_it_with_its_weight(world, bus):
    world.spawn_urdf("bot", robot(), (0, 0, 0.1))
    run(world, 0.1)
    assert bus.last("/plate_bumper").states == []  # nothing on it yet: an empty list
    world.add_sdf_model(crate())
    run(world, 1.0)
    message = bus.last("/plate_bumper")
    assert message.header.frame_id == "world"
    (state,) = message.states
    assert state.collision1_name == "bot::base_link::base_link_fixed_joint_lump__bumper_collision"
    assert state.collision2_name.startswith("crate::")
    # the crate's weight on the plate: straight down, 2 g newtons
    assert state.total_wrench.force.z == pytest.approx(-CRATE_MASS * G, rel=0.02)
    assert abs(state.total_wrench.force.x) < 0.1 and abs(state.total_wrench.force.y) < 0.1
    # from the crate into the plate: down
    assert all(n.z == pytest.approx(-1.0, abs=1e-6) for n in state.contact_normals)
    assert all(p.z == pytest.approx(0.22, abs=0.005) for p in state.contact_positions)


def test_frame_name_names_the_header_only_and_the_contacts_stay_in_the_world(world, bus):
    """gazebo_plugins/src/gazebo_ros_bumper.cpp:151: <frameName> is the header's frame_id;
    the code that would move the contacts into that link is commented out (:155-187,
    :193-201) and the frame used is the identity (:202-208), so positions, normals and
    wrenches (:266-315) are in the world's coordinates. Before: in the named link's frame
    (the plate's top face 0.01 m above it)."""
    world.spawn_urdf("bot", robot(frame="<frameName>bumper</frameName>"), (1.0, 2.0, 0.1))
    world.add_sdf_model(crate(1.0, 2.0))
    run(world, 1.0)
    message = bus.last("/plate_bumper")
    assert message.header.frame_id == "bumper"
    (state,) = message.states
    # the plate's top face, 0.22 m above the ground, under the crate at (1, 2)
    assert all(p.z == pytest.approx(0.22, abs=0.005) for p in state.contact_positions)
    assert all(abs(p.x - 1.0) <= 0.1 + 1e-3 and abs(p.y - 2.0) <= 0.1 + 1e-3
               for p in state.contact_positions)
    assert all(n.z == pytest.approx(-1.0, abs=1e-6) for n in state.contact_normals)
    assert state.total_wrench.force.z == pytest.approx(-CRATE_MASS * G, rel=0.02)


@pytest.mark.parametrize("frame", ["base_scan", "map", "/odom"])
def test_any_frame_name_is_the_header_as_written_without_a_warning(world, bus, frame):
    """gazebo_plugins/src/gazebo_ros_bumper.cpp:95-101, :116: whatever <frameName> names, a
    link of the model or not, is the header's frame through tf::resolve (a leading slash
    dropped); nothing is looked up, nothing warned. Before: a name that is no link of the
    model warned and became world."""
    world.spawn_urdf("bot", robot(frame=f"<frameName>{frame}</frameName>"), (0, 0, 0.1))
    run(world, 0.1)
    assert bus.last("/plate_bumper").header.frame_id == frame.lstrip("/")
    assert not [w for w in bus.warnings if "frameName" in w]


@pytest.mark.parametrize("frame, expected", [("", "world"), ("<frameName>bumper</frameName>",
                                                              "bumper"),
                                             ("<frameName></frameName>", "")])
def test_the_header_frame_gets_the_tf_prefix(world, bus, frame, expected):
    """gazebo_plugins/src/gazebo_ros_bumper.cpp:95-99 (default world), :113-116: the frame
    is tf::resolve(tf_prefix, frameName): world with prefix r1 is r1/world, an empty tag
    is the prefix and a slash (tf/src/tf.cpp:159-185). Before: world kept as written, an
    empty tag read as world."""
    world.spawn_urdf("bot", robot(frame=frame), (0, 0, 0.1), tf_prefix="r1")
    run(world, 0.1)
    assert bus.last("/plate_bumper").header.frame_id == f"r1/{expected}"


def test_a_collision_the_model_lacks_leaves_the_sensor_out_naming_it(world, bus):
    world.spawn_urdf("bot", robot(collision="front_bumper_collision"), (0, 0, 0.1))
    assert any("'front_bumper_collision' is no collision of model 'bot'" in w
               for w in bus.warnings)
    assert "bot" in world.models


def test_a_named_collision_is_found_by_sdformats_name_for_it(world, bus):
    """A URDF collision with a name (Kobuki's <collision name="base">) is named after it by
    sdformat 9: lumped into base_link after base_link's own,
    'base_link_fixed_joint_lump__shell_collision_1' (gazebosim/sdformat sdf9 9ee2d4f
    src/parser_urdf.cc:2880-2901, :3168-3179), and the sensor that names it feels the crate
    (before: refused, as no link is called 'shell')."""
    xml = robot("base_link_fixed_joint_lump__shell_collision_1").replace(
        '<collision><geometry><box size="0.3 0.3 0.02"/>',
        '<collision name="shell"><geometry><box size="0.3 0.3 0.02"/>')
    world.spawn_urdf("bot", xml, (0, 0, 0.1))
    world.add_sdf_model(crate())
    run(world, 1.0)
    assert not [w for w in bus.warnings if "shell" in w or "unknown attribute" in w]
    (state,) = bus.last("/plate_bumper").states
    assert state.collision1_name == \
        "bot::base_link::base_link_fixed_joint_lump__shell_collision_1"
    assert state.total_wrench.force.z == pytest.approx(-CRATE_MASS * G, rel=0.02)
