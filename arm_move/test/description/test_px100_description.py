"""The px100's description and its world without a master: the published kinematics and
limits, the URDF agreeing with the planner's kinematics, inertias from their shapes, and
arm_box.world holding what config/scene.yaml says."""
import math
import os
import xml.etree.ElementTree as ET

import numpy as np
import pytest
import yaml

from arm_move.kinematics import ARM_JOINTS, ArmKinematics
from urdf_tools import inertia
from urdf_tools.kinematics import link_transform
from urdf_tools.model import parse_urdf
from urdf_tools.xacro_loader import expand

PACKAGE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
XACRO = os.path.join(PACKAGE, "urdf", "px100.urdf.xacro")
WORLD = os.path.join(PACKAGE, "worlds", "arm_box.world")


def read(name):
    with open(os.path.join(PACKAGE, "config", name), encoding="utf-8") as stream:
        return yaml.safe_load(stream)


@pytest.fixture(scope="module")
def px100():
    return parse_urdf(expand(XACRO), XACRO)


@pytest.fixture(scope="module")
def kinematics():
    return ArmKinematics.from_config(read("px100.yaml"))


def gripper_point(model, positions):
    return link_transform(model, "px100/base_link", "px100/ee_gripper_link", positions)[:3, 3]


def test_home_puts_the_gripper_point_where_trossen_publishes_it(px100):
    assert gripper_point(px100, {}) == pytest.approx((0.2486, 0.0, 0.1931), abs=1e-4)


def test_the_published_offsets(px100):
    joints = px100.joints
    assert joints["waist"].origin.xyz == pytest.approx((0, 0, 0.05085))
    assert joints["shoulder"].origin.xyz == pytest.approx((0, 0, 0.04225))
    assert joints["elbow"].origin.xyz == pytest.approx((0.035, 0, 0.1))
    assert joints["wrist_angle"].origin.xyz == pytest.approx((0.1, 0, 0))
    assert sum(joints[name].origin.xyz[0] for name in ("ee_arm", "gripper_bar", "ee_gripper")) \
        == pytest.approx(0.063 + 0.023 + 0.027575)


@pytest.mark.parametrize("joint, degrees", [("waist", (-180, 180)), ("shoulder", (-111, 107)),
                                            ("elbow", (-121, 92)), ("wrist_angle", (-100, 123))])
def test_arm_limits_and_speed(px100, joint, degrees):
    limit = px100.joints[joint].limit
    assert (limit.lower, limit.upper) == pytest.approx(tuple(map(math.radians, degrees)))
    assert limit.velocity == pytest.approx(math.pi)


def test_mirrored_prismatic_fingers(px100):
    left, right = px100.joints["left_finger"], px100.joints["right_finger"]
    assert left.type == right.type == "prismatic"
    assert tuple(left.axis) == pytest.approx(tuple(-a for a in right.axis))
    for finger in (left, right):
        assert (finger.limit.lower, finger.limit.upper) == pytest.approx((0.015, 0.037))
    for opening in (0.015, 0.037):
        ends = [link_transform(px100, "px100/base_link", f"px100/{side}_finger_link",
                               {f"{side}_finger": opening})[:3, 3] for side in ("left", "right")]
        assert ends[0][1] == pytest.approx(opening) and ends[1][1] == pytest.approx(-opening)


def test_the_urdf_and_the_planners_kinematics_agree(px100, kinematics):
    rng = np.random.default_rng(3)
    for q in rng.uniform(kinematics.lower, kinematics.upper, size=(200, 4)):
        urdf = gripper_point(px100, dict(zip(ARM_JOINTS, q)))
        assert urdf == pytest.approx(kinematics.gripper_point(q), abs=1e-9)


def test_named_poses(kinematics):
    assert kinematics.named_poses["home"] == (0.0, 0.0, 0.0, 0.0)
    assert kinematics.named_poses["sleep"] == pytest.approx((0.0, -1.88, 1.5, 0.8))
    for pose in kinematics.named_poses.values():
        assert kinematics.within_limits(pose)


def test_every_link_with_a_body_has_its_shapes_inertia(px100):
    bodies = [link for link in px100.links.values() if link.collisions]
    assert len(bodies) == 8
    for link in bodies:
        geometry, mass = link.collisions[0].geometry, link.inertial.mass
        if geometry.kind == "box":
            expected = inertia.solid_box(mass, *geometry.size)
        else:
            expected = inertia.solid_cylinder(mass, geometry.radius, geometry.length)
        actual = (link.inertial.ixx, link.inertial.iyy, link.inertial.izz)
        assert actual == pytest.approx(tuple(expected), rel=1e-9), link.name
        assert link.inertial.origin == link.collisions[0].origin, link.name


def _model(world, name):
    model = world.find(f".//model[@name='{name}']")
    assert model is not None, name
    return model


def _numbers(element, path):
    return [float(v) for v in element.find(path).text.split()]


def _check_free_body(model, spec, table_height):
    """A world model against its yaml entry: size, place on the table, mass, a solid box's
    inertia."""
    size = _numbers(model, ".//collision/geometry/box/size")
    assert size == pytest.approx(spec["size"])
    assert _numbers(model, "pose")[:3] == pytest.approx(
        np.array(spec["position"]) + (0, 0, table_height))
    assert float(model.find(".//inertial/mass").text) == spec["mass"]
    inertias = [float(model.find(f".//inertia/{axis}").text) for axis in ("ixx", "iyy", "izz")]
    assert inertias == pytest.approx(tuple(inertia.solid_box(spec["mass"], *size)), rel=1e-5)


def test_the_world_holds_the_scene_of_the_yaml():
    scene = read("scene.yaml")
    world = ET.parse(WORLD).getroot()
    height = scene["table_height"]
    table = _model(world, "table")
    assert _numbers(table, ".//collision/geometry/box/size") == pytest.approx(scene["table"]["size"])
    centre = np.array(scene["table"]["center"]) + (0, 0, height)
    assert _numbers(table, "pose")[:3] == pytest.approx(centre)

    box = scene["realsense_box"]
    assert box["size"] == pytest.approx((0.14, 0.09, 0.05)) and box["mass"] == 0.1
    for name in ("realsense_box", "pick_object"):
        _check_free_body(_model(world, name), scene[name], height)
    spec = scene["pick_object"]
    # the block fits the open gripper and is squeezed by the closed one
    finger = read("px100.yaml")["finger"]
    assert 2 * finger["min"] < spec["size"][1] < 2 * finger["max"]
