"""gazebo_ros_ft_sensor against mechanics: an arm at rest loads its joint with its weight
and the weight's moment about the joint (Gazebo's body2Force and body2Torque: the child's
load on the joint, in the child's axes, about the joint's origin), whatever the joint's
angle or mounting; an arm spun by an effort pulls outward by m w^2 r and reads the effort
back on its axis."""
import math

import numpy as np
import pytest

from world_fixtures import run

SECOND = 1_000_000_000
MASS, REACH = 2.0, 0.5  # kg; m from the joint to the arm's centre of mass, along its x
IZZ = 0.01  # kg m^2 about the centre of mass


def post(mount_rpy="0 0 0", noise=""):
    """A post fixed to the world with an arm on a vertical revolute joint 1 m up."""
    inertia = f'ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="{IZZ}"'
    return f"""<robot name="post"><link name="world"/>
      <joint name="anchor" type="fixed"><parent link="world"/><child link="post"/></joint>
      <link name="post"><inertial><mass value="10"/><inertia {inertia}/></inertial></link>
      <joint name="shoulder" type="revolute"><parent link="post"/><child link="arm"/>
        <origin xyz="0 0 1" rpy="{mount_rpy}"/><axis xyz="0 0 1"/>
        <limit lower="-10" upper="10" effort="100" velocity="100"/></joint>
      <link name="arm"><inertial><origin xyz="{REACH} 0 0"/><mass value="{MASS}"/>
        <inertia {inertia}/></inertial></link>
      <gazebo><plugin name="ft" filename="libgazebo_ros_ft_sensor.so">
        <jointName>shoulder</jointName><topicName>shoulder_wrench</topicName>{noise}
      </plugin></gazebo></robot>"""


def reading(bus):
    wrench = bus.last("/shoulder_wrench").wrench
    return (np.array([wrench.force.x, wrench.force.y, wrench.force.z]),
            np.array([wrench.torque.x, wrench.torque.y, wrench.torque.z]))


@pytest.mark.parametrize("mount_rpy, angle", [("0 0 0", 0.0), ("0 0 1.5708", 0.0),
                                              ("0 0 0", 2.0)])
def test_an_arm_at_rest_loads_its_joint_with_its_weight(world, bus, mount_rpy, angle):
    world.spawn_urdf("post", post(mount_rpy), (0, 0, 0))
    world.model("post").robot.reset_joints({"shoulder": angle})
    run(world, 0.2)
    force, torque = reading(bus)
    weight = MASS * 9.8
    assert bus.last("/shoulder_wrench").header.frame_id == "arm"
    assert force == pytest.approx((0, 0, -weight), abs=1e-3)
    # the weight at 0.5 m along the arm's x turns it about its -y; the load is the opposite
    assert torque == pytest.approx((0, REACH * weight, 0), abs=1e-3)


def test_a_spun_arm_pulls_outward_and_reads_the_effort_on_its_axis(world, bus):
    world.spawn_urdf("post", post(), (0, 0, 0))
    effort = 0.5  # N m
    world.apply_joint_effort("shoulder", effort, duration_ns=SECOND)
    run(world, 0.3)
    force, torque = reading(bus)
    (_, speed, _), = world.model("post").robot.joint_states(["shoulder"])
    # the arm's centre of mass accelerates along its y at alpha r and towards the axis at
    # w^2 r; the joint pushes it so, and the load is the opposite
    alpha = effort / (IZZ + MASS * REACH ** 2)
    assert speed == pytest.approx(alpha * 0.3, rel=0.02)
    assert force == pytest.approx((MASS * speed ** 2 * REACH, -MASS * alpha * REACH,
                                   -MASS * 9.8), rel=0.02, abs=1e-3)
    assert torque[2] == pytest.approx(-effort, rel=0.01)


def test_noise_and_rate(world, bus):
    world.spawn_urdf("post", post(noise="<gaussianNoise>0.5</gaussianNoise>"
                                        "<updateRate>50</updateRate>"), (0, 0, 0))
    run(world, 1.0)
    messages = bus.published["/shoulder_wrench"]
    assert len(messages) == pytest.approx(50, abs=1)
    forces = np.array([m.wrench.force.z for m in messages[5:]])
    assert forces.mean() == pytest.approx(-MASS * 9.8, abs=0.3)
    assert forces.std() == pytest.approx(0.5, rel=0.3)


def test_the_world_joint_carries_the_whole_robot(world, bus):
    world.spawn_urdf("post", post().replace("<jointName>shoulder", "<jointName>anchor"),
                     (0, 0, 0))
    run(world, 0.2)
    force, torque = reading(bus)
    assert force == pytest.approx((0, 0, -(10 + MASS) * 9.8), abs=1e-3)
    assert torque == pytest.approx((0, REACH * MASS * 9.8, 0), abs=1e-3)


def test_a_lumped_joint_is_refused(world, bus):
    tool = """<joint name="tool_mount" type="fixed"><parent link="arm"/><child link="tool"/>
      </joint><link name="tool"><inertial><mass value="0.1"/><inertia ixx="1e-4" ixy="0"
      ixz="0" iyy="1e-4" iyz="0" izz="1e-4"/></inertial></link><gazebo>"""
    xml = post().replace("<jointName>shoulder", "<jointName>tool_mount").replace(
        "<gazebo>", tool)
    world.spawn_urdf("post", xml, (0, 0, 0))
    (warning,) = [w for w in bus.warnings if "libgazebo_ros_ft_sensor.so" in w]
    assert "'tool_mount' is a fixed joint that Gazebo lumps" in warning
    assert "not loaded" in warning
