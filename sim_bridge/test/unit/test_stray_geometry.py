"""A <geometry> holding more than its shape, as public descriptions write it (a <material>
inside a mesh's geometry), read as Gazebo 11 reads it:

- URDF goes through urdfdom (sdformat sdf9 66a8c21 src/urdf/urdf_parser/link.cpp:229-275,
  the parser Gazebo's URDF import, robot_state_publisher and rviz share): the first child
  element is the shape and nothing after it is looked at, silently; a first child that is
  not a shape is "Unknown geometry type" and the robot is refused. Before, urdf_parser_py
  refused the robot for any second element ("needs exactly one shape").
- SDF goes through sdformat 9, which keeps the children its schema knows in document order
  and moves the others after them with a debug line only (src/parser.cc:1075-1111); Gazebo
  builds the first (gazebo 11.10.2 gazebo/physics/Link.cc:692-693). So a stray element is
  ignored wherever it stands. Before, a <material> first was "geometry <material>; sim_bridge
  reads box, ..." and the model was refused.
"""
import pytest

from sim_bridge.sdf_world import load_world
from sim_bridge.world import World
from urdf_tools.model import UrdfError, parse_urdf
from world_fixtures import run

HALF = 0.2  # m: half the cube's side


@pytest.fixture
def cube(tmp_path):
    """A 0.4 m cube as an OBJ file."""
    corners = [(x, y, z) for x in (-HALF, HALF) for y in (-HALF, HALF) for z in (-HALF, HALF)]
    faces = [(1, 3, 4, 2), (5, 6, 8, 7), (1, 2, 6, 5), (3, 7, 8, 4), (1, 5, 7, 3), (2, 4, 8, 6)]
    path = tmp_path / "cube.obj"
    path.write_text("".join(f"v {x} {y} {z}\n" for x, y, z in corners)
                    + "".join("f " + " ".join(map(str, face)) + "\n" for face in faces))
    return str(path)


def robot(geometry):
    return f"""<robot name="crate"><link name="base">
      <inertial><mass value="1"/><inertia ixx="0.03" ixy="0" ixz="0" iyy="0.03" iyz="0"
        izz="0.03"/></inertial>
      <visual><geometry>{geometry}</geometry></visual>
      <collision><geometry>{geometry}</geometry></collision></link></robot>"""


def test_a_material_after_the_mesh_is_ignored_and_the_mesh_collides(world, cube):
    xml = robot(f'<mesh filename="file://{cube}"/><material name="red">'
                '<color rgba="1 0 0 1"/></material>')
    model = parse_urdf(xml, "crate.urdf")
    assert [w for w in model.warnings if "<material> after the <mesh> ignored" in w
            and "link 'base' collision 0 geometry" in w]
    assert model.links["base"].collisions[0].geometry.kind == "mesh"
    world.spawn_urdf("crate", xml, (0, 0, 1.0))
    run(world, 1.5)
    assert world.pose("crate")[0][2] == pytest.approx(HALF, abs=0.005)  # on the cube's face


def test_the_first_of_two_shapes_is_the_shape():
    model = parse_urdf(robot('<box size="1 2 3"/><sphere radius="1"/>'), "two.urdf")
    geometry = model.links["base"].visuals[0].geometry
    assert (geometry.kind, geometry.size) == ("box", (1.0, 2.0, 3.0))
    assert [w for w in model.warnings if "<sphere> after the <box> ignored" in w]


def test_a_material_before_the_shape_is_refused_as_urdfdom_refuses_it(cube):
    with pytest.raises(UrdfError) as error:
        parse_urdf(robot(f'<material name="red"/><mesh filename="file://{cube}"/>'),
                   "first.urdf")
    message = str(error.value)
    assert message.startswith("first.urdf: link 'base' visual 0 geometry")
    assert "<material>" in message and "put the shape first" in message


@pytest.mark.parametrize("before, after", [
    ("", "<material><ambient>1 0 0 1</ambient></material>"),
    ("<material><ambient>1 0 0 1</ambient></material>", ""),
])
def test_an_sdf_geometrys_unknown_element_is_ignored_wherever_it_stands(
        bus, tmp_path, cube, before, after):
    geometry = f"<geometry>{before}<mesh><uri>file://{cube}</uri></mesh>{after}</geometry>"
    path = tmp_path / "crate.world"
    path.write_text(f"""<sdf version="1.6"><world name="w">
      <model name="ground"><static>true</static><link name="l"><collision name="c">
        <geometry><plane><normal>0 0 1</normal></plane></geometry></collision></link></model>
      <model name="crate"><pose>0 0 1 0 0 0</pose><link name="l">
        <collision name="c">{geometry}</collision><visual name="v">{geometry}</visual>
      </link></model></world></sdf>""")
    messages = []
    simulated = World(bus, ray_threads=1)
    simulated.load_world(load_world(str(path), warn=messages.append))
    assert not messages  # sdformat says it at debug level only
    run(simulated, 1.5)
    assert simulated.pose("crate")[0][2] == pytest.approx(HALF, abs=0.005)
    simulated.close()
