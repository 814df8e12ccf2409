"""urdf_tools.model: what is parsed, and that broken files are named with their fault."""
import pytest

from urdf_tools.model import UrdfError, parse_urdf

TWO_LINKS = """<robot name="r">
  <material name="red"><color rgba="1 0 0 1"/></material>
  <link name="base">
    <visual><origin xyz="0 0 0.1"/><geometry><box size="1 2 3"/></geometry>
      <material name="red"/></visual>
    <collision><geometry><cylinder radius="0.5" length="2"/></geometry></collision>
    <inertial><mass value="2"/><inertia ixx="1" ixy="0" ixz="0" iyy="2" iyz="0" izz="3"/></inertial>
  </link>
  <link name="wheel"/>
  <joint name="axle" type="continuous">
    <parent link="base"/><child link="wheel"/>
    <origin xyz="0 0.2 0" rpy="0 0 1"/><axis xyz="0 1 0"/>
    <dynamics damping="0.1" friction="0.2"/>
  </joint>
  <gazebo reference="wheel"><mu1>0.5</mu1><material>Gazebo/Black</material></gazebo>
  <gazebo><plugin name="p" filename="libx.so"/></gazebo>
  <transmission name="t"><joint name="axle"><hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface></joint></transmission>
</robot>"""


def test_parses_links_joints_and_gazebo_blocks():
    model = parse_urdf(TWO_LINKS, "two.urdf")
    assert model.name == "r" and model.root() == "base"
    base = model.links["base"]
    assert base.visuals[0].geometry.size == (1.0, 2.0, 3.0)
    assert base.visuals[0].origin.xyz == (0.0, 0.0, 0.1)
    assert base.collisions[0].geometry.kind == "cylinder"
    assert base.inertial.mass == 2.0 and base.inertial.izz == 3.0
    assert model.materials["red"] == (1.0, 0.0, 0.0, 1.0)
    axle = model.joints["axle"]
    assert (axle.type, axle.axis, axle.origin.rpy) == ("continuous", (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))
    assert (axle.damping, axle.friction) == (0.1, 0.2)
    assert model.gazebo_properties("wheel") == {"mu1": "0.5", "material": "Gazebo/Black"}
    assert [ref for ref, _ in model.gazebo] == ["wheel", None]
    assert model.transmissions[0].joints == ("axle",)
    assert model.chain("base", "wheel") == [axle]
    assert model.total_mass() == 2.0


@pytest.mark.parametrize("text, fault", [
    ("<robot name='r'><link name='a'>", "not well-formed XML"),
    ("<model/>", "not <robot>"),
    ("<robot name='r'/>", "no links"),
    ("<robot name='r'><link name='a'/><link name='a'/></robot>", "defined twice"),
    ("<robot name='r'><link name='a'/><joint name='j' type='fixed'><parent link='a'/>"
     "<child link='b'/></joint></robot>", "link 'b', which is not defined"),
    ("<robot name='r'><link name='a'/><link name='b'/></robot>", "one tree"),
    ("<robot name='r'><link name='a'/><link name='b'/><joint name='j' type='hinge'>"
     "<parent link='a'/><child link='b'/></joint></robot>", "type 'hinge'"),
    ("<robot name='r'><link name='a'><visual><geometry><box size='1 x 1'/></geometry>"
     "</visual></link></robot>", "box size '1 x 1'"),
    ("<robot name='r'><link name='a'><inertial><mass value='nan'/><inertia ixx='1' ixy='0' "
     "ixz='0' iyy='1' iyz='0' izz='1'/></inertial></link></robot>", "finite"),
])
def test_broken_descriptions_name_the_source_and_the_fault(text, fault):
    with pytest.raises(UrdfError) as error:
        parse_urdf(text, "broken.urdf")
    assert str(error.value).startswith("broken.urdf: ")
    assert fault in str(error.value)
