"""The mimic joint plugin: a gripper's second finger follows the first, multiplied and
offset, in the joints' true state; a plugin naming a joint the model lacks is left out."""
import pybullet as pb
import pytest

from world_fixtures import run

FINGER = """<link name="{name}"><inertial><mass value="0.05"/><inertia ixx="1e-5" ixy="0"
  ixz="0" iyy="1e-5" iyz="0" izz="1e-5"/></inertial><collision><geometry>
  <box size="0.01 0.01 0.05"/></geometry></collision></link>
  <joint name="{name}_joint" type="prismatic"><parent link="palm"/><child link="{name}"/>
  <origin xyz="0 {y} 0.05"/><axis xyz="0 1 0"/>
  <limit lower="-0.04" upper="0.04" effort="{effort}" velocity="0.5"/></joint>"""


def gripper(plugin):
    return f"""<robot name="gripper"><link name="palm"><inertial><mass value="20"/>
      <inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
      <collision><geometry><box size="0.3 0.3 0.05"/></geometry></collision></link>
      {FINGER.format(name="left", y=0.05, effort=20)}
      {FINGER.format(name="right", y=-0.05, effort=20)}
      <gazebo><plugin name="mimic_right" filename="{plugin}">
        <joint>left_joint</joint><mimicJoint>right_joint</mimicJoint>
        <multiplier>-1.0</multiplier><offset>0.005</offset></plugin></gazebo></robot>"""


def position(model, joint):
    return model.robot.joint_position_velocity(joint)[0]


@pytest.mark.parametrize("plugin", ["libroboticsgroup_upatras_gazebo_mimic_joint_plugin.so",
                                    "libroboticsgroup_gazebo_mimic_joint_plugin.so"])
def test_the_second_finger_follows_the_first(world, plugin):
    model = world.spawn_urdf("gripper", gripper(plugin), (0, 0, 0.03))
    left = model.robot.joint_index["left_joint"]
    for target in (0.03, -0.02):
        pb.setJointMotorControl2(model.robot.id, left, pb.POSITION_CONTROL, targetPosition=target,
                                 force=20, physicsClientId=world.client)
        run(world, 1.0)
        assert position(model, "left_joint") == pytest.approx(target, abs=1e-3)
        assert position(model, "right_joint") == pytest.approx(-target + 0.005, abs=1e-3)


def test_a_mimic_naming_a_joint_the_model_lacks_is_left_out(world, bus):
    xml = gripper("libroboticsgroup_upatras_gazebo_mimic_joint_plugin.so").replace(
        "<mimicJoint>right_joint", "<mimicJoint>thumb_joint")
    world.spawn_urdf("gripper", xml, (0, 0, 0.03))
    assert any("mimic_right" in w and "'thumb_joint'" in w and "not loaded" in w
               for w in bus.warnings)
