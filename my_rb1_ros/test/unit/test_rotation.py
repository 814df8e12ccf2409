"""my_rb1_ros.rotation: accumulated yaw and the speed law."""
import math

import pytest

from my_rb1_ros.rotation import RotationGains, YawAccumulator, angular_speed, time_allowed

GAINS = RotationGains(gain=1.5, max_speed=0.8, min_speed=0.05, tolerance=math.radians(0.3))


def test_full_turns_count_across_the_seam():
    yaw = YawAccumulator()
    readings = [math.atan2(math.sin(a), math.cos(a))
                for a in [i * 0.3 for i in range(0, 40)]]  # 12 rad counter-clockwise
    for reading in readings:
        yaw.update(reading)
    assert yaw.total == pytest.approx(11.7)
    for reading in reversed(readings):  # and back, clockwise
        yaw.update(reading)
    assert yaw.total == pytest.approx(0.0, abs=1e-9)


def test_speed_slows_near_the_goal_and_keeps_the_sign():
    assert angular_speed(math.pi, GAINS) == GAINS.max_speed
    assert angular_speed(-math.pi, GAINS) == -GAINS.max_speed
    assert angular_speed(0.2, GAINS) == pytest.approx(0.3)
    assert angular_speed(0.01, GAINS) == GAINS.min_speed
    assert angular_speed(math.radians(0.2), GAINS) == 0.0


def test_time_allowed_grows_with_the_angle():
    assert time_allowed(math.pi / 2, GAINS, 5.0, 2.0) < time_allowed(4 * math.pi, GAINS, 5.0, 2.0)
    assert time_allowed(0.0, GAINS, 5.0, 2.0) == 5.0
