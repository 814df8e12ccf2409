"""The seven dd_robot steps: each is the one before plus what its step adds."""
import math
import os

import pytest

from urdf_tools import inertia
from urdf_tools.model import load_urdf

URDF = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "urdf")
FILES = ["dd_robot.urdf"] + [f"dd_robot{n}.urdf" for n in range(2, 8)]


@pytest.fixture(scope="module")
def steps():
    return {n: load_urdf(os.path.join(URDF, name)) for n, name in enumerate(FILES, start=1)}


def test_step_1_is_the_box(steps):
    (box,) = steps[1].links.values()
    assert box.visuals[0].geometry.size == (0.5, 0.5, 0.25)


def test_step_2_adds_wheels_on_continuous_joints(steps):
    assert set(steps[2].links) == {"base_link", "left_wheel", "right_wheel"}
    for side, y in (("left", 0.3), ("right", -0.3)):
        joint = steps[2].joints[f"joint_{side}_wheel"]
        assert (joint.type, joint.axis, joint.origin.xyz) == ("continuous", (0.0, 1.0, 0.0),
                                                              (0.0, y, 0.0))
        wheel = steps[2].links[f"{side}_wheel"].visuals[0]
        assert (wheel.geometry.radius, wheel.geometry.length) == (0.2, 0.1)
        assert wheel.origin.rpy == pytest.approx((math.pi / 2, 0.0, 0.0))


def test_step_3_adds_the_caster(steps):
    assert set(steps[3].links) - set(steps[2].links) == {"caster"}
    assert steps[3].links["caster"].visuals[0].geometry.radius == 0.05
    assert steps[3].joints["joint_caster"].origin.xyz == (0.2, 0.0, -0.125)


def test_step_4_adds_colours(steps):
    assert all(v.material is None for link in steps[3].links.values() for v in link.visuals)
    assert {v.material for link in steps[4].links.values() for v in link.visuals} == \
        {"blue", "black", "white"}
    assert steps[4].materials["blue"] == (0.0, 0.0, 0.8, 1.0)


def test_step_5_adds_collisions_equal_to_the_visuals(steps):
    assert all(not link.collisions for link in steps[4].links.values())
    for link in steps[5].links.values():
        assert [c.geometry for c in link.collisions] == [v.geometry for v in link.visuals]
        assert [c.origin for c in link.collisions] == [v.origin for v in link.visuals]


def test_step_6_adds_masses_and_the_shapes_inertias(steps):
    assert all(link.inertial is None for link in steps[5].links.values())
    robot = steps[6]
    expected = {"base_link": inertia.solid_box(5.0, 0.5, 0.5, 0.25),
                "left_wheel": inertia.solid_cylinder(0.5, 0.2, 0.1, axis="y"),
                "right_wheel": inertia.solid_cylinder(0.5, 0.2, 0.1, axis="y"),
                "caster": inertia.solid_sphere(0.5, 0.05)}
    for name, principal in expected.items():
        tensor = robot.links[name].inertial
        assert (tensor.ixx, tensor.iyy, tensor.izz) == pytest.approx(principal, rel=1e-12)
    assert robot.total_mass() == pytest.approx(6.5)


def test_step_7_adds_gazebo_colours_and_the_drive(steps):
    robot = steps[7]
    assert robot.gazebo_properties("base_link")["material"] == "Gazebo/Blue"
    assert robot.gazebo_properties("left_wheel")["material"] == "Gazebo/Black"
    assert robot.gazebo_properties("caster")["material"] == "Gazebo/Red"
    (plugin,) = [e for _, block in robot.gazebo for e in block.findall("plugin")]
    params = {child.tag: child.text for child in plugin}
    assert float(params["wheelDiameter"]) == 2 * robot.links["left_wheel"].collisions[0].geometry.radius
    assert float(params["wheelSeparation"]) == pytest.approx(0.6)
    # the rest is step 6 unchanged
    assert set(robot.links) == set(steps[6].links) and set(robot.joints) == set(steps[6].joints)
