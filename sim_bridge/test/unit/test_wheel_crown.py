"""How sim_bridge hands a wheel's collision cylinder to pybullet: crowned (a tread at full
radius around a core a little smaller), with nothing else about the robot changed."""
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from sim_bridge.robot_body import CORE_CLEARANCE, TREAD_WIDTH, crown_wheels


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


def test_a_wheel_cylinder_becomes_a_tread_around_a_smaller_core():
    rpy = "1.5707963267948966 0 0"
    link = link_with(f"<collision><origin xyz='0.1 0 0' rpy='{rpy}'/>"
                     "<geometry><cylinder radius='0.12' length='0.07'/></geometry></collision>")
    crown_wheels(link, np.array([0.0, 1.0, 0.0]))
    tread, core = pieces(link)
    assert tread[1:] == (TREAD_WIDTH, 0.12)
    assert core[1:] == (0.07, pytest.approx(0.12 - CORE_CLEARANCE))
    # both where the wheel was, turned as it was
    for centre, _, _ in (tread, core):
        assert centre == pytest.approx([0.1, 0, 0])
    for collision in link.findall("collision"):
        turned = [float(v) for v in collision.find("origin").get("rpy").split()]
        assert turned == pytest.approx([float(v) for v in rpy.split()])


def test_a_cylinder_across_the_joint_axis_and_other_shapes_stay_as_they_are():
    xml = ("<collision><geometry><cylinder radius='0.1' length='0.3'/></geometry></collision>"
           "<collision><geometry><box size='0.1 0.1 0.1'/></geometry></collision>")
    link = link_with(xml)
    crown_wheels(link, np.array([0.0, 1.0, 0.0]))  # this cylinder's axis is z
    assert ET.tostring(link) == ET.tostring(link_with(xml))
