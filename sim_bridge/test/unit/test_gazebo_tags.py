"""The <gazebo> tag reader: values as text or as attributes, fdir1 as a direction; tags
Gazebo reads that sim_bridge does not emulate are named, once each."""
import pybullet as pb
import pytest

from sim_bridge.gazebo_tags import read_gazebo_tags
from urdf_tools.model import parse_urdf
from world_fixtures import run

ROBOT = """<robot name="r">
  <link name="base"><inertial><mass value="1"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="wheel"><inertial><mass value="1"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <joint name="axle" type="continuous"><parent link="base"/><child link="wheel"/></joint>
  <gazebo reference="wheel">
    <mu1 value="0.5"/>
    <mu2>0.25</mu2>
    <kp value="1e6"/>
    <fdir1>1 0 0</fdir1>
    <maxContacts>4</maxContacts>
    <maxVel>0.1</maxVel>
    <material value="Gazebo/Red"/>
  </gazebo>
  <gazebo reference="base"><maxVel>0.2</maxVel></gazebo>
  <gazebo reference="axle"><provideFeedback>true</provideFeedback></gazebo>
  <gazebo>
    <static>false</static>
    <plugin name="drive" filename="libgazebo_ros_diff_drive.so">
      <leftJoint value="axle"/>
      <rightJoint>axle</rightJoint>
    </plugin>
  </gazebo>
</robot>"""


def tags():
    return read_gazebo_tags(parse_urdf(ROBOT, "test robot"))


def test_attribute_values_read_like_text():
    surface = tags().surfaces["wheel"]
    assert (surface.mu1, surface.mu2, surface.kp) == (0.5, 0.25, 1e6)
    assert surface.fdir1 == (1.0, 0.0, 0.0)
    assert surface.material == "Gazebo/Red"
    plugin = tags().plugins[0]
    assert plugin.text("leftJoint") == "axle" and plugin.text("rightJoint") == "axle"


def test_tags_not_emulated_are_named_once_with_where_first_seen():
    assert tags().not_emulated == {"maxContacts": "link 'wheel'", "maxVel": "link 'wheel'",
                                   "provideFeedback": "joint 'axle'",
                                   "static": "the robot's <gazebo>"}


def test_the_world_warns_once_per_tag(world, bus):
    world.spawn_urdf("r", ROBOT, (0, 0, 0.5))
    warnings = [w for w in bus.warnings if "not emulated" in w]
    assert len([w for w in warnings if "<maxVel>" in w]) == 1
    assert any("<maxContacts> in link 'wheel'" in w for w in warnings)
    assert not any("<fdir1>" in w for w in warnings)  # emulated: sim_bridge.tyre_friction


def test_preserve_fixed_joint_is_not_reported_as_ignored(world, bus):
    """sim_bridge honours it (model_structure keeps the joint's link): warning that it is
    ignored contradicted the README (found trying a student's RB1)."""
    robot = ROBOT.replace('<gazebo reference="axle"><provideFeedback>true</provideFeedback></gazebo>',
                          '<gazebo reference="axle"><preserveFixedJoint>true</preserveFixedJoint>'
                          '</gazebo>')
    world.spawn_urdf("r", robot, (0, 0, 0.5))
    assert not [w for w in bus.warnings if "preserveFixedJoint" in w]


HEAVY_CRATE = """<robot name="crate"><link name="base"><inertial><mass value="100"/>
  <inertia ixx="0.667" ixy="0" ixz="0" iyy="0.667" iyz="0" izz="0.667"/></inertial>
  <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision></link>
  <gazebo reference="base"><kd>100</kd></gazebo></robot>"""


def test_kd_without_kp_keeps_sdfs_default_stiffness(world):
    """A link giving kd alone keeps SDF's kp, 1e12 (sdformat sdf9 66a8c21,
    sdf/1.6/surface.sdf:188), which pybullet holds: a 100 kg crate rests 10 micrometres
    deep and still (pybullet's own body state). Before, 1e6 was taken: it sank 0.5 mm and
    went on rocking at about 1 mm/s."""
    world.spawn_urdf("crate", HEAVY_CRATE, (0.0, 0.0, 0.15))
    run(world, 1.0)
    body = world.models["crate"].robot.id
    depths, speeds = [], []
    for _ in range(500):
        world.step()
        depths.append(0.1 - pb.getBasePositionAndOrientation(
            body, physicsClientId=world.client)[0][2])
        speeds.append(abs(pb.getBaseVelocity(body, physicsClientId=world.client)[0][2]))
    assert max(depths) < 5e-5
    assert max(speeds) < 1e-4


def _box_link(name, size, mass=0.1):
    return (f'<link name="{name}"><inertial><mass value="{mass}"/><inertia ixx="1e-4" '
            f'ixy="0" ixz="0" iyy="1e-4" iyz="0" izz="1e-4"/></inertial><collision><geometry>'
            f'<box size="{size}"/></geometry></collision></link>')


def _gripper(blocks):
    """Two fingers on prismatic joints sliding towards each other on a base fixed to the
    world, a mast on a revolute joint, and a plate lumped into the base (fixed joint) where
    the fingers pass over it. ``blocks``: the robot's <gazebo> blocks."""
    finger = '<limit lower="-0.3" upper="0.3" effort="100" velocity="10"/>'
    return f"""<robot name="gripper"><link name="world"/>
      {_box_link("base", "0.6 0.1 0.02", 1.0)}
      <joint name="fix" type="fixed"><parent link="world"/><child link="base"/>
        <origin xyz="0 0 0.5"/></joint>
      {_box_link("plate", "0.3 0.06 0.02")}
      <joint name="plate_joint" type="fixed"><parent link="base"/><child link="plate"/>
        <origin xyz="0 0 0.04"/></joint>
      {_box_link("left", "0.02 0.04 0.04")}
      <joint name="left_joint" type="prismatic"><parent link="base"/><child link="left"/>
        <origin xyz="-0.1 0 0.04"/><axis xyz="1 0 0"/>{finger}</joint>
      {_box_link("right", "0.02 0.04 0.04")}
      <joint name="right_joint" type="prismatic"><parent link="base"/><child link="right"/>
        <origin xyz="0.1 0 0.04"/><axis xyz="1 0 0"/>{finger}</joint>
      {_box_link("mast", "0.02 0.02 0.2")}
      <joint name="mast_joint" type="revolute"><parent link="base"/><child link="mast"/>
        <origin xyz="0.25 0 0.12"/><axis xyz="0 0 1"/>{finger}</joint>
      {blocks}</robot>"""


def _squeeze(world, blocks):
    """Pushes the fingers towards each other for 1 s: their distance apart (m, centre to
    centre) as pybullet's joints say."""
    world.spawn_urdf("gripper", _gripper(blocks), (0.0, 0.0, 0.0))
    world.apply_joint_effort("gripper::left_joint", 2.0)
    world.apply_joint_effort("gripper::right_joint", -2.0)
    run(world, 1.0)
    robot = world.models["gripper"].robot
    left = pb.getJointState(robot.id, robot.joint_index["left_joint"],
                            physicsClientId=world.client)[0]
    right = pb.getJointState(robot.id, robot.joint_index["right_joint"],
                             physicsClientId=world.client)[0]
    return (0.1 + right) - (-0.1 + left)


FINGER_WIDTH = 0.02


@pytest.mark.parametrize("blocks, collide", [
    ("", False),
    ('<gazebo reference="left"><selfCollide>true</selfCollide></gazebo>', True),
    ('<gazebo reference="mast"><selfCollide>true</selfCollide></gazebo>', False),
    ("<gazebo><self_collide>true</self_collide></gazebo>", True),
    ("<gazebo><self_collide>true</self_collide></gazebo>"
     '<gazebo reference="left"><selfCollide>false</selfCollide></gazebo>'
     '<gazebo reference="right"><selfCollide>false</selfCollide></gazebo>', False),
    ("<gazebo><selfCollide>true</selfCollide></gazebo>", False),
])
def test_two_links_collide_when_either_sets_self_collide(world, blocks, collide):
    """sdformat sdf9 66a8c21 sdf/1.6/link.sdf:17-19: two links of a model collide if either
    sets self_collide, never when a joint connects them; a model's self_collide
    (model.sdf:13-15) is every link's unless the link says otherwise. Gazebo's URDF
    conversion writes a link's <selfCollide> as its self_collide (parser_urdf.cc:1397-1412,
    :2092-2096) and copies a robot-level <self_collide> into the model (:2279-2287); a
    robot-level <selfCollide> is read and written nowhere (:2257-2290). The fingers stop
    against each other (pybullet's joints) exactly when that rule says so; they never
    touch the plate lumped into the base they slide on, nor the base. Before, any link's
    selfCollide made every pair collide (the mast's made the fingers collide), and a
    robot-level <selfCollide> too."""
    apart = _squeeze(world, blocks)
    if collide:
        assert apart == pytest.approx(FINGER_WIDTH, abs=2e-3)
    else:
        assert apart < 0.0  # passed through each other
