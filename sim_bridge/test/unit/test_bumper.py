"""gazebo_ros_bumper: what touches the named collision, with the force it bears, as the
world has it (a 2 kg crate resting on a bumper plate presses it with 2 g newtons)."""
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


def crate():
    box = ShapeSpec("box", size=(0.2, 0.2, 0.2))
    return ModelSpec("crate", False, pose=(0, 0, 0.35, 0, 0, 0), links=[LinkSpec(
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


def test_contacts_in_a_link_frame(world, bus):
    world.spawn_urdf("bot", robot(frame="<frameName>bumper</frameName>"), (0, 0, 0.1))
    world.add_sdf_model(crate())
    run(world, 1.0)
    (state,) = bus.last("/plate_bumper").states
    assert bus.last("/plate_bumper").header.frame_id == "bumper"
    # the plate's top face, 0.01 m above the bumper link's origin
    assert all(p.z == pytest.approx(0.01, abs=0.005) for p in state.contact_positions)


def test_a_collision_the_model_lacks_leaves_the_sensor_out_naming_it(world, bus):
    world.spawn_urdf("bot", robot(collision="front_bumper_collision"), (0, 0, 0.1))
    assert any("'front_bumper_collision' is no collision of model 'bot'" in w
               for w in bus.warnings)
    assert "bot" in world.models
