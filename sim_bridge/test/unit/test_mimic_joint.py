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


# --- as the plugin's ROS 1 release (roboticsgroup_upatras_gazebo_plugins 15187ab,
# src/mimic_joint_plugin.cpp) -------------------------------------------------------------------
UPATRAS = "libroboticsgroup_upatras_gazebo_mimic_joint_plugin.so"


def drive_leader(world, model, target):
    pb.setJointMotorControl2(model.robot.id, model.robot.joint_index["left_joint"],
                             pb.POSITION_CONTROL, targetPosition=target, force=20,
                             physicsClientId=world.client)


def with_tags(tags):
    return gripper(UPATRAS).replace("<offset>0.005</offset>", f"<offset>0.005</offset>{tags}")


def test_without_a_pid_the_follower_is_put_at_its_target_whatever_its_effort(world, bus):
    """No <hasPID>: Joint::SetPosition(0, angle, true) before every step (:177-178) puts the
    follower at multiplier * leader + offset whatever maxEffort says, which only sets the
    motor's fmax (:131-138): a 0.001 N limit does not hold it back (before: a motor of
    0.001 N, which moved it by 1 cm in a second)."""
    model = world.spawn_urdf("gripper", with_tags("<maxEffort>0.001</maxEffort>"),
                             (0, 0, 0.03))
    drive_leader(world, model, 0.03)
    run(world, 1.0)
    assert position(model, "left_joint") == pytest.approx(0.03, abs=1e-3)
    assert position(model, "right_joint") == pytest.approx(-0.03 + 0.005, abs=1e-4)


def test_with_a_pid_the_follower_is_driven_by_effort_from_its_gains(world, bus):
    """<hasPID> with an empty text: a control_toolbox PID from
    <robotNamespace>/gazebo_ros_control/pid_gains/<mimicJoint> (:83-92), its effort
    clamped to maxEffort (:169-175); the spawn's namespace is the plugin's."""
    bus.params["/r1/gazebo_ros_control/pid_gains/right_joint"] = {"p": 50.0, "d": 1.0}
    model = world.spawn_urdf("gripper", with_tags("<hasPID></hasPID>"), (0, 0, 0.03),
                             namespace="/r1")
    drive_leader(world, model, 0.03)
    run(world, 1.5)
    assert position(model, "right_joint") == pytest.approx(-0.03 + 0.005, abs=1e-3)
    assert not [w for w in bus.warnings if "mimic" in w]


@pytest.mark.parametrize("tag, where", [("<hasPID/>", "/gazebo_ros_control/pid_gains/right_joint"),
                                        ("<hasPID>false</hasPID>", "/false")])
def test_a_pid_without_gains_leaves_the_follower_free(world, bus, tag, where):
    """The tag's presence asks for the PID, whatever its text (:84): "false" is the gains'
    namespace. Without a p gain there, Pid::init fails and the gains stay 0 (control_toolbox
    pid.cpp): the follower is not driven (before: <hasPID>false</hasPID> or none held it
    at its target). A warning names where the gains were looked for."""
    model = world.spawn_urdf("gripper", with_tags(tag), (0, 0, 0.03))
    drive_leader(world, model, 0.03)
    run(world, 1.0)
    assert position(model, "left_joint") == pytest.approx(0.03, abs=1e-3)
    assert position(model, "right_joint") == pytest.approx(0.0, abs=1e-3)
    (warning,) = [w for w in bus.warnings if "hasPID" in w]
    assert f"{where} has no 'p' gain" in warning


def test_a_difference_below_sensitiveness_is_left_alone(world, bus):
    """fabs(target - follower) >= sensitiveness acts (:168): with 0.02 m, the follower at 0
    and its target 0.005 stays; a leader put at 0.03 (target -0.025) moves it there."""
    model = world.spawn_urdf("gripper", with_tags("<sensitiveness>0.02</sensitiveness>"),
                             (0, 0, 0.03))
    run(world, 0.5)
    assert position(model, "right_joint") == pytest.approx(0.0, abs=1e-4)
    drive_leader(world, model, 0.03)  # held there, after a jump
    pb.resetJointState(model.robot.id, model.robot.joint_index["left_joint"], 0.03,
                       physicsClientId=world.client)
    run(world, 0.5)
    assert position(model, "right_joint") == pytest.approx(-0.025, abs=1e-4)
