"""The skid-steer robot's description, from its xacro, without a master."""
import os

import pytest

from urdf_tools import inertia
from urdf_tools.xacro_loader import load

XACRO = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "urdf", "robot.xacro")
WHEELS = ("front_left", "front_right", "rear_left", "rear_right")


@pytest.fixture(scope="module")
def robot():
    return load(XACRO)


def test_four_wheels_on_continuous_joints_with_limits_and_dynamics(robot):
    for prefix in WHEELS:
        joint = robot.joints[f"{prefix}_wheel_joint"]
        assert (joint.type, joint.axis) == ("continuous", (0.0, 1.0, 0.0))
        assert joint.limit.effort > 0 and joint.limit.velocity > 0
        assert joint.damping > 0 and joint.friction > 0


def test_inertias_by_formula(robot):
    body = robot.links["base_link"]
    size = body.collisions[0].geometry.size
    assert (body.inertial.ixx, body.inertial.iyy, body.inertial.izz) == \
        pytest.approx(inertia.solid_box(body.inertial.mass, *size), rel=1e-12)
    for prefix in WHEELS:
        wheel = robot.links[f"{prefix}_wheel"]
        g = wheel.collisions[0].geometry
        assert (wheel.inertial.ixx, wheel.inertial.iyy, wheel.inertial.izz) == pytest.approx(
            inertia.solid_cylinder(wheel.inertial.mass, g.radius, g.length, axis="y"), rel=1e-12)


def test_gazebo_colours_friction_and_the_skid_steer_plugin(robot):
    assert robot.gazebo_properties("base_link") == {"material": "Gazebo/Red", "mu1": "0.2",
                                                     "mu2": "0.2"}
    for prefix in WHEELS:
        assert robot.gazebo_properties(f"{prefix}_wheel")["material"] == "Gazebo/Yellow"
    (plugin,) = [e for _, block in robot.gazebo for e in block.findall("plugin")]
    params = {child.tag: child.text for child in plugin}
    assert plugin.get("filename") == "libgazebo_ros_skid_steer_drive.so"
    radius = robot.links["front_left_wheel"].collisions[0].geometry.radius
    assert float(params["wheelDiameter"]) == pytest.approx(2 * radius)
    left = robot.joints["front_left_wheel_joint"].origin.xyz[1]
    right = robot.joints["front_right_wheel_joint"].origin.xyz[1]
    assert float(params["wheelSeparation"]) == pytest.approx(left - right)
    assert (params["commandTopic"], params["odometryTopic"]) == ("cmd_vel", "odom")
