"""sim_bridge.drive_kinematics against worked examples."""
import math

import pytest

from sim_bridge.drive_kinematics import body_twist, integrate, limit_change, wheel_speeds


def test_wheel_speeds_and_back():
    left, right = wheel_speeds(0.2, 0.5, 0.4, 0.025)
    assert (left, right) == pytest.approx(((0.2 - 0.1) / 0.025, (0.2 + 0.1) / 0.025))
    assert body_twist(left, right, 0.4, 0.025) == pytest.approx((0.2, 0.5))


def test_turning_left_spins_the_right_wheel_faster():
    left, right = wheel_speeds(0.0, 1.0, 0.4, 0.05)
    assert right > 0 > left


def test_integrate_along_a_straight_line_and_a_quarter_circle():
    assert integrate(0, 0, 0, 1.0, 0.0, 2.0) == pytest.approx((2.0, 0.0, 0.0))
    # quarter circle of radius 1 counter-clockwise from the origin heading +x
    x, y, theta = integrate(0, 0, 0, 1.0, 1.0, math.pi / 2)
    assert (x, y, theta) == pytest.approx((1.0, 1.0, math.pi / 2))


def test_limit_change():
    assert limit_change(0.0, 10.0, 1.0) == 1.0
    assert limit_change(0.0, -10.0, 1.0) == -1.0
    assert limit_change(0.0, 10.0, 0.0) == 10.0  # no limit
