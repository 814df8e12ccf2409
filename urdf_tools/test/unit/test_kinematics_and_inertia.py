"""urdf_tools.kinematics and urdf_tools.inertia against hand-worked values."""
import math

import numpy as np
import pytest

from urdf_tools import inertia
from urdf_tools.kinematics import axis_angle_matrix, link_transform, matrix_rpy, rpy_matrix
from urdf_tools.model import parse_urdf

ARM = """<robot name="arm">
  <link name="base"/><link name="upper"/><link name="slider"/>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/>
    <origin xyz="0 0 1"/><axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="slide" type="prismatic"><parent link="upper"/><child link="slider"/>
    <origin xyz="1 0 0"/><axis xyz="1 0 0"/><limit lower="0" upper="1" effort="1" velocity="1"/></joint>
</robot>"""


def test_rpy_round_trip_and_axis_convention():
    for rpy in [(0.1, -0.2, 0.3), (math.pi, 0.0, 0.0), (0.0, 0.5, -2.0)]:
        back = matrix_rpy(rpy_matrix(*rpy))
        assert np.allclose(rpy_matrix(*back), rpy_matrix(*rpy))
    # yaw pi/2 turns x onto y (counter-clockwise, REP 103)
    assert np.allclose(rpy_matrix(0, 0, math.pi / 2) @ [1, 0, 0], [0, 1, 0])
    # roll pi turns y onto -y and z onto -z (a sensor mounted upside down)
    assert np.allclose(rpy_matrix(math.pi, 0, 0) @ [0, 1, 0], [0, -1, 0])
    assert np.allclose(axis_angle_matrix([0, 0, 1], math.pi / 2), rpy_matrix(0, 0, math.pi / 2))


def test_forward_kinematics_through_revolute_and_prismatic_joints():
    model = parse_urdf(ARM)
    tip = link_transform(model, "base", "slider", {"shoulder": math.pi / 2, "slide": 0.5})
    assert np.allclose(tip[:3, 3], [0.0, 1.5, 1.0])
    assert np.allclose(link_transform(model, "base", "slider")[:3, 3], [1.0, 0.0, 1.0])


def test_inertia_formulas():
    assert inertia.solid_box(12.0, 1.0, 2.0, 3.0) == pytest.approx((13.0, 10.0, 5.0))
    assert inertia.solid_cylinder(12.0, 1.0, 2.0) == pytest.approx((7.0, 7.0, 6.0))
    assert inertia.solid_cylinder(12.0, 1.0, 2.0, axis="y") == pytest.approx((7.0, 6.0, 7.0))
    assert inertia.solid_sphere(5.0, 1.0) == pytest.approx((2.0, 2.0, 2.0))
    with pytest.raises(ValueError):
        inertia.solid_cylinder(1.0, 1.0, 1.0, axis="w")
