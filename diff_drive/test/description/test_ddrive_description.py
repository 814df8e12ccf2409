"""The flipping robot's description, from the xacro and its yaml, without a master."""
import os

import numpy as np
import pytest
import yaml

from urdf_tools import inertia
from urdf_tools.kinematics import link_transform
from urdf_tools.xacro_loader import expand
from urdf_tools.model import parse_urdf

PACKAGE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
XACRO = os.path.join(PACKAGE, "urdf", "ddrive.urdf.xacro")
CONFIG = os.path.join(PACKAGE, "config", "ddrive.yaml")
RELATIVE = 1e-9


@pytest.fixture(scope="module")
def dims():
    with open(CONFIG, encoding="utf-8") as stream:
        return yaml.safe_load(stream)


@pytest.fixture(scope="module")
def ddrive():
    return parse_urdf(expand(XACRO), XACRO)


def test_it_expands_with_the_yaml_and_follows_it(ddrive, dims):
    body = ddrive.links["base_link"].collisions[0].geometry
    assert body.size == pytest.approx((dims["body"]["length"], dims["body"]["width"],
                                       dims["body"]["height"]))
    wheel = ddrive.links["left_wheel"].collisions[0].geometry
    assert (wheel.radius, wheel.length) == pytest.approx((dims["wheel"]["radius"],
                                                          dims["wheel"]["width"]))
    assert ddrive.links["top_caster"].inertial.mass == dims["caster"]["mass"]


def test_another_yaml_makes_another_robot(tmp_path, dims):
    bigger = dict(dims, wheel=dict(dims["wheel"], radius=0.2))
    config = tmp_path / "bigger.yaml"
    config.write_text(yaml.safe_dump(bigger))
    robot = parse_urdf(expand(XACRO, {"config": str(config)}), "bigger")
    assert robot.links["left_wheel"].collisions[0].geometry.radius == 0.2


def principal(link):
    shape = link.collisions[0]
    geometry, mass = shape.geometry, link.inertial.mass
    if geometry.kind == "box":
        return inertia.solid_box(mass, *geometry.size)
    if geometry.kind == "sphere":
        return inertia.solid_sphere(mass, geometry.radius)
    # the wheels' cylinders are turned onto the axle, y
    return inertia.solid_cylinder(mass, geometry.radius, geometry.length, axis="y")


@pytest.mark.parametrize("name", ["base_link", "left_wheel", "right_wheel", "bottom_caster",
                                  "top_caster"])
def test_every_link_has_collision_and_the_inertia_of_its_shape(ddrive, name):
    link = ddrive.links[name]
    assert len(link.collisions) == 1 and len(link.visuals) == 1
    assert link.visuals[0].geometry == link.collisions[0].geometry
    tensor = link.inertial
    assert (tensor.ixy, tensor.ixz, tensor.iyz) == (0.0, 0.0, 0.0)
    assert (tensor.ixx, tensor.iyy, tensor.izz) == pytest.approx(principal(link), rel=RELATIVE)


def test_mirror_symmetric_about_the_horizontal_plane(ddrive):
    """Every link's position reflected in the body's horizontal plane is a link of the same
    shape: the robot is the same robot upside down."""
    placed = []
    for name, link in ddrive.links.items():
        position = link_transform(ddrive, "base_link", name)[:3, 3]
        geometry = link.collisions[0].geometry
        placed.append((position, geometry.kind, geometry.radius, geometry.size))
    for position, kind, radius, size in placed:
        mirrored = position * np.array([1.0, 1.0, -1.0])
        assert any(np.allclose(mirrored, p) and k == kind and r == radius and s == size
                   for p, k, r, s in placed), f"no mirror image of the {kind} at {position}"
    top = link_transform(ddrive, "base_link", "top_caster")[:3, 3]
    assert top[2] > 0  # and the casters are really above and below


def test_wheels_at_the_front_casters_at_the_rear_all_touching_the_ground(ddrive, dims):
    wheel = link_transform(ddrive, "base_link", "left_wheel")[:3, 3]
    caster = link_transform(ddrive, "base_link", "bottom_caster")[:3, 3]
    assert wheel[0] == pytest.approx(dims["body"]["length"] / 2)
    assert caster[0] < 0
    # lowest points of wheel and caster level: it stands flat either way up
    assert wheel[2] - dims["wheel"]["radius"] == pytest.approx(caster[2] - dims["caster"]["radius"])
    assert dims["wheel"]["radius"] * 2 > dims["body"]["height"]  # wheels reach past the body


def test_gazebo_file_frictions_and_drive_from_the_yaml(ddrive, dims):
    assert float(ddrive.gazebo_properties("left_wheel")["mu1"]) > 1.0
    for caster in ("bottom_caster", "top_caster"):
        assert float(ddrive.gazebo_properties(caster)["mu1"]) == 0.0
    (plugin,) = [e for ref, block in ddrive.gazebo for e in block.findall("plugin")]
    params = {child.tag: child.text for child in plugin}
    assert plugin.get("filename") == "libgazebo_ros_diff_drive.so"
    assert float(params["wheelDiameter"]) == pytest.approx(2 * dims["wheel"]["radius"])
    left = link_transform(ddrive, "base_link", "left_wheel")[:3, 3]
    right = link_transform(ddrive, "base_link", "right_wheel")[:3, 3]
    assert float(params["wheelSeparation"]) == pytest.approx(np.linalg.norm(left - right))
    assert (params["commandTopic"], params["odometryTopic"], params["odometryFrame"]) == \
        ("diff/cmd_vel", "diff/odom", "odom")
