"""Gazebo's names for a model's parts: sdformat's lumping of fixed joints, kept joints,
collision names. No pybullet."""
from sim_bridge.model_structure import sdf_structure, urdf_structure
from sim_bridge.sdf_world import LinkSpec, ModelSpec, ShapeSpec
from urdf_tools.model import parse_urdf

ROTOR = """<robot name="rotor">
  <link name="world"/>
  <link name="base"><inertial><mass value="1"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <joint name="fix" type="fixed"><parent link="world"/><child link="base"/>
    <origin xyz="0 0 0.5"/></joint>
  <link name="disc"><collision><geometry><cylinder radius="0.3" length="0.05"/></geometry>
    </collision><inertial><mass value="2"/>
    <inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.2"/></inertial></link>
  <joint name="spin" type="continuous"><parent link="base"/><child link="disc"/>
    <axis xyz="0 0 1"/></joint>
</robot>"""


def test_fixed_joints_are_lumped_into_their_parent(diff_bot_xml):
    structure = urdf_structure(parse_urdf(diff_bot_xml()))
    # base_link hangs on base_footprint by a fixed joint, casters and laser on base_link
    assert structure.bodies == ("base_footprint", "left_wheel", "right_wheel")
    assert structure.canonical == "base_footprint"
    assert structure.joints == ("left_wheel_joint", "right_wheel_joint")
    assert structure.body_of["laser"] == "base_footprint"
    assert structure.lumped_by == {"base_link": "base_joint", "back_caster": "back_caster_joint",
                                   "front_caster": "front_caster_joint",
                                   "laser": "laser_joint"}
    assert structure.links_of("base_footprint") == ["base_footprint", "base_link",
                                                     "back_caster", "front_caster", "laser"]
    # sdformat's names: the lumped link's own name inside, an index after the first
    assert structure.geoms == (
        "base_footprint_fixed_joint_lump__base_link_collision",
        "base_footprint_fixed_joint_lump__back_caster_collision_1",
        "base_footprint_fixed_joint_lump__front_caster_collision_2",
        "base_footprint_fixed_joint_lump__laser_collision_3",
        "left_wheel_collision", "right_wheel_collision")


def test_preserve_fixed_joint_keeps_the_link_and_its_joint(diff_bot_xml):
    xml = diff_bot_xml().replace(
        "</robot>", '<gazebo reference="laser_joint"><preserveFixedJoint>true'
                    "</preserveFixedJoint></gazebo></robot>")
    structure = urdf_structure(parse_urdf(xml))
    assert structure.bodies == ("base_footprint", "laser", "left_wheel", "right_wheel")
    assert structure.joints == ("laser_joint", "left_wheel_joint", "right_wheel_joint")
    assert "laser_collision" in structure.geoms
    assert "laser" not in structure.lumped_by


def test_a_robot_fixed_to_the_world_keeps_that_joint_and_has_no_world_link():
    structure = urdf_structure(parse_urdf(ROTOR))
    assert structure.bodies == ("base", "disc")
    assert structure.joints == ("fix", "spin")
    assert structure.geoms == ("disc_collision",)


def test_sdf_models_are_their_links():
    spec = ModelSpec("crates", True, links=[
        LinkSpec("a", collisions=[ShapeSpec("box"), ShapeSpec("box")]), LinkSpec("b")])
    structure = sdf_structure(spec)
    assert structure.bodies == ("a", "b") and structure.joints == ()
    assert structure.geoms == ("a_collision", "a_collision_1")


def test_a_chain_of_a_thousand_links_is_walked_without_recursion():
    # found by the spawn fuzzer: 999 links lumped one into the next overflowed Python's stack
    links = "".join(f'<link name="l{i}"><collision><geometry><box size="1 1 1"/></geometry>'
                    f'</collision></link>' for i in range(999))
    fixed = "".join(f'<joint name="j{i}" type="fixed"><parent link="l{i}"/>'
                    f'<child link="l{i + 1}"/></joint>' for i in range(998))
    lumped = urdf_structure(parse_urdf(f'<robot name="r">{links}{fixed}</robot>', "chain"))
    assert lumped.bodies == ("l0",) and len(lumped.geoms) == 999
    assert lumped.geoms[1] == "l0_fixed_joint_lump__l1_collision_1"
    hinged = "".join(f'<joint name="j{i}" type="revolute"><parent link="l{i}"/>'
                     f'<child link="l{i + 1}"/><limit lower="0" upper="1" effort="1" '
                     f'velocity="1"/></joint>' for i in range(998))
    jointed = urdf_structure(parse_urdf(f'<robot name="r">{links}{hinged}</robot>', "chain"))
    assert len(jointed.bodies) == 999 and jointed.joints[-1] == "j997"


def test_named_collisions_are_named_as_sdformat_9_names_them():
    """sdformat 9 (gazebosim/sdformat sdf9 9ee2d4f src/parser_urdf.cc:2880-2901,
    :3168-3179): <name or link>_collision, _N after the first, prefixed with the Gazebo
    link's name and _fixed_joint_lump__ unless it begins with that link's name: Kobuki's
    'base' lumped into base_footprint, and a named collision of a link of its own too."""
    xml = """<robot name="k">
      <link name="base_footprint"/>
      <joint name="base_joint" type="fixed"><parent link="base_footprint"/>
        <child link="base_link"/></joint>
      <link name="base_link">
        <collision name="base"><geometry><box size="1 1 1"/></geometry></collision>
        <collision><geometry><box size="1 1 1"/></geometry></collision></link>
      <joint name="wheel_joint" type="continuous"><parent link="base_link"/>
        <child link="wheel"/><axis xyz="0 1 0"/></joint>
      <link name="wheel">
        <collision name="tyre"><geometry><sphere radius="0.1"/></geometry></collision>
        <collision name="wheel_hub"><geometry><sphere radius="0.1"/></geometry></collision>
      </link>
    </robot>"""
    model = parse_urdf(xml, "k")
    assert model.warnings == []  # a collision's name is URDF, not an unknown attribute
    structure = urdf_structure(model)
    assert structure.geoms == (
        "base_footprint_fixed_joint_lump__base_collision",
        "base_footprint_fixed_joint_lump__base_link_collision_1",
        "wheel_fixed_joint_lump__tyre_collision",
        "wheel_hub_collision_1")
    assert structure.geom_links["base_footprint_fixed_joint_lump__base_collision"] == \
        "base_link"
    assert structure.geom_links["wheel_hub_collision_1"] == "wheel"
