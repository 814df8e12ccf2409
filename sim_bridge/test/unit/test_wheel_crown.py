"""How sim_bridge hands a wheel's collision cylinder to pybullet: crowned (a tread at full
radius, shoulders a little smaller), with nothing else about the robot changed."""
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from sim_bridge.robot_body import SHOULDER_CLEARANCE, TREAD_WIDTH, crown_wheels


def link_with(collisions):
    return ET.fromstring(f"<link name='wheel'>{collisions}</link>")


def pieces(link):
    found = []
    for collision in link.findall("collision"):
        origin = collision.find("origin")
        cylinder = collision.find("geometry/cylinder")
        found.append((np.array([float(v) for v in origin.get("xyz").split()]),
                      float(cylinder.get("length")), float(cylinder.get("radius"))))
    return found


def test_a_wheel_cylinder_becomes_a_tread_between_two_shoulders():
    link = link_with("<collision><origin xyz='0.1 0 0' rpy='1.5707963267948966 0 0'/>"
                     "<geometry><cylinder radius='0.12' length='0.07'/></geometry></collision>")
    crown_wheels(link, np.array([0.0, 1.0, 0.0]))
    tread, *shoulders = pieces(link)
    assert tread[0] == pytest.approx([0.1, 0, 0]) and tread[1:] == (TREAD_WIDTH, 0.12)
    for centre, length, radius in shoulders:
        assert radius == pytest.approx(0.12 - SHOULDER_CLEARANCE)
        assert length == pytest.approx((0.07 - TREAD_WIDTH) / 2)
        # side by side along the wheel's axis (y), together as wide as the wheel
        assert centre[[0, 2]] == pytest.approx([0.1, 0])
        assert abs(centre[1]) + length / 2 == pytest.approx(0.035)
    assert sorted(np.sign(c[1]) for c, _, _ in shoulders) == [-1, 1]


def test_a_cylinder_across_the_joint_axis_and_other_shapes_stay_as_they_are():
    xml = ("<collision><geometry><cylinder radius='0.1' length='0.3'/></geometry></collision>"
           "<collision><geometry><box size='0.1 0.1 0.1'/></geometry></collision>")
    link = link_with(xml)
    crown_wheels(link, np.array([0.0, 1.0, 0.0]))  # this cylinder's axis is z
    assert ET.tostring(link) == ET.tostring(link_with(xml))
