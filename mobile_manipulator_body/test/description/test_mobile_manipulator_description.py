"""The mobile manipulator's three URDFs, without a master."""
import os

import pytest

from urdf_tools import inertia
from urdf_tools.model import load_urdf

URDF = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "urdf")
ARM_JOINTS = ["arm_base_joint", "shoulder_joint", "bottom_wrist_joint", "elbow_joint",
              "top_wrist_joint"]


def load(name):
    return load_urdf(os.path.join(URDF, name))


def principal(link):
    shape, mass = link.collisions[0], link.inertial.mass
    g = shape.geometry
    if g.kind == "box":
        return inertia.solid_box(mass, *g.size)
    axis = "y" if shape.origin.rpy[0] != 0 else "z"
    return inertia.solid_cylinder(mass, g.radius, g.length, axis)


@pytest.mark.parametrize("name", ["robot_arm.urdf", "robot_base.urdf", "mobile_manipulator.urdf"])
def test_every_link_has_the_inertia_of_its_shape(name):
    robot = load(name)
    for link in robot.links.values():
        if link.name == "world":
            continue
        tensor = link.inertial
        assert (tensor.ixx, tensor.iyy, tensor.izz) == pytest.approx(principal(link), rel=1e-12), \
            link.name


def test_the_arm_has_five_limited_joints_with_position_transmissions():
    arm = load("robot_arm.urdf")
    assert arm.root() == "world"  # fixed to the world in the simulator
    for name in ARM_JOINTS:
        joint = arm.joints[name]
        assert joint.type == "revolute" and joint.limit.lower < 0 < joint.limit.upper
        assert joint.limit.effort > 0 and joint.limit.velocity > 0
    interfaces = {t.joints[0]: t.hardware_interfaces[0] for t in arm.transmissions}
    assert interfaces == {j: "hardware_interface/PositionJointInterface" for j in ARM_JOINTS}


def test_the_mobile_manipulator_is_the_arm_on_the_base():
    whole, arm, base = load("mobile_manipulator.urdf"), load("robot_arm.urdf"), load("robot_base.urdf")
    assert set(whole.links) == (set(arm.links) - {"world"}) | set(base.links)
    assert whole.joints["arm_mount_joint"].parent == "base_link"
    assert len(whole.transmissions) == 9  # five arm joints and four wheels
    assert whole.root() == "base_link"
