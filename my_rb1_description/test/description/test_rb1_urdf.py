"""The RB1 description against the course's task 1, read from the URDF without a master."""
import math
import os
import subprocess

import numpy as np
import pytest

from urdf_tools import inertia
from urdf_tools.kinematics import link_transform, matrix_rpy
from urdf_tools.model import load_urdf

URDF = os.path.join(os.path.dirname(__file__), "..", "..", "urdf", "my_rb1_robot.urdf")
RELATIVE = 1e-6


@pytest.fixture(scope="module")
def rb1():
    return load_urdf(URDF)


def only_geometry(shapes):
    assert len(shapes) == 1
    return shapes[0].geometry


def test_check_urdf_accepts_it():
    result = subprocess.run(["check_urdf", URDF], capture_output=True, text=True, check=False)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "Successfully Parsed XML" in result.stdout


def test_links_and_joints(rb1):
    assert set(rb1.links) == {"base_footprint", "base_link", "right_wheel", "left_wheel",
                              "front_caster", "back_caster", "front_laser"}
    assert rb1.root() == "base_footprint"
    # one joint per link below the root
    assert sorted(j.child for j in rb1.joints.values()) == sorted(set(rb1.links) - {"base_footprint"})


def test_body_is_a_cylinder_half_a_metre_wide_and_0_3_tall(rb1):
    base = rb1.links["base_link"]
    for geometry in (only_geometry(base.visuals), only_geometry(base.collisions)):
        assert geometry.kind == "cylinder"
        assert geometry.radius * 2 == pytest.approx(0.50)
        assert geometry.length == pytest.approx(0.30)


def test_footprint_is_the_centre_of_the_bottom_of_the_body(rb1):
    transform = link_transform(rb1, "base_footprint", "base_link")
    assert np.allclose(transform[:3, 3], [0.0, 0.0, 0.15])
    assert np.allclose(transform[:3, :3], np.eye(3))


@pytest.mark.parametrize("link, xyz, kind, size", [
    ("right_wheel", (0.0, -0.2, -0.15), "cylinder", 0.025),
    ("left_wheel", (0.0, 0.2, -0.15), "cylinder", 0.025),
    ("front_caster", (0.1, 0.0, -0.15), "sphere", 0.025),
    ("back_caster", (-0.1, 0.0, -0.15), "sphere", 0.025),
])
def test_wheels_and_casters(rb1, link, xyz, kind, size):
    joint = rb1.parent_joint(link)
    assert joint.parent == "base_link"
    assert joint.origin.xyz == pytest.approx(xyz)
    for geometry in (only_geometry(rb1.links[link].visuals),
                     only_geometry(rb1.links[link].collisions)):
        assert geometry.kind == kind
        assert geometry.radius == pytest.approx(size)


@pytest.mark.parametrize("wheel", ["right_wheel", "left_wheel"])
def test_wheels_turn_continuously_about_y(rb1, wheel):
    joint = rb1.parent_joint(wheel)
    assert joint.type == "continuous"
    assert joint.axis == (0.0, 1.0, 0.0)
    # the cylinder's axis lies along y, the axle
    shape = rb1.links[wheel].visuals[0]
    assert shape.origin.rpy == pytest.approx((math.pi / 2, 0.0, 0.0))


def test_laser_is_at_the_front_mounted_upside_down(rb1):
    joint = rb1.parent_joint("front_laser")
    assert (joint.parent, joint.type) == ("base_link", "fixed")
    assert joint.origin.xyz == pytest.approx((0.25, 0.0, 0.075))
    assert joint.origin.rpy == pytest.approx((math.pi, 0.0, 0.0), rel=0, abs=1e-12)
    from_footprint = link_transform(rb1, "base_footprint", "front_laser")
    assert from_footprint[:3, 3] == pytest.approx([0.25, 0.0, 0.225])
    roll, pitch, yaw = matrix_rpy(from_footprint[:3, :3])
    assert abs(abs(roll) - math.pi) < 1e-9 and abs(pitch) < 1e-9 and abs(yaw) < 1e-9


def test_total_mass_is_25_kg(rb1):
    assert rb1.total_mass() == pytest.approx(25.0, rel=RELATIVE)
    assert rb1.links["base_footprint"].inertial is None  # KDL refuses a root with inertia


def expected_principal(link):
    """The formula for the link's own collision shape."""
    geometry = only_geometry(link.collisions)
    mass = link.inertial.mass
    if geometry.kind == "sphere":
        return inertia.solid_sphere(mass, geometry.radius)
    if geometry.kind == "cylinder":
        # wheels lie with the cylinder's axis turned onto y; the rest stand upright
        axis = "y" if link.collisions[0].origin.rpy[0] == pytest.approx(math.pi / 2) else "z"
        return inertia.solid_cylinder(mass, geometry.radius, geometry.length, axis)
    return inertia.solid_box(mass, *geometry.size)


@pytest.mark.parametrize("name", ["base_link", "right_wheel", "left_wheel", "front_caster",
                                  "back_caster", "front_laser"])
def test_each_inertia_equals_its_shape_formula(rb1, name):
    link = rb1.links[name]
    assert link.inertial is not None and link.inertial.mass > 0
    tensor = link.inertial
    assert (tensor.ixy, tensor.ixz, tensor.iyz) == (0.0, 0.0, 0.0)
    assert (tensor.ixx, tensor.iyy, tensor.izz) == pytest.approx(expected_principal(link),
                                                                  rel=RELATIVE)
    assert link.inertial.origin.xyz == (0.0, 0.0, 0.0)


@pytest.mark.parametrize("caster", ["front_caster", "back_caster"])
def test_casters_are_frictionless(rb1, caster):
    properties = rb1.gazebo_properties(caster)
    assert float(properties["mu1"]) == 0.0
    assert float(properties["mu2"]) == 0.0


def test_every_link_is_black_in_gazebo(rb1):
    for name in rb1.links:
        assert rb1.gazebo_properties(name).get("material") == "Gazebo/Black", name
