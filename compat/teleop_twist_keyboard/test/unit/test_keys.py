"""keyboard_teleop.keys: teleop_twist_keyboard's keys and defaults."""
import pytest

from keyboard_teleop.keys import Teleop


@pytest.mark.parametrize("key, command", [
    ("i", (0.5, 0.0)), (",", (-0.5, 0.0)), ("j", (0.0, 1.0)), ("l", (0.0, -1.0)),
    ("u", (0.5, 1.0)), ("o", (0.5, -1.0)), ("m", (-0.5, -1.0)), (".", (-0.5, 1.0)),
    ("k", (0.0, 0.0)), ("p", (0.0, 0.0)),
])
def test_direction_keys(key, command):
    teleop = Teleop()
    teleop.press("i")
    teleop.press(key)
    assert teleop.command == pytest.approx(command)


def test_speed_keys_scale_by_ten_percent():
    teleop = Teleop()
    teleop.press("u")
    teleop.press("q")
    assert teleop.command == pytest.approx((0.55, 1.1))  # the direction stays
    teleop.press("x")
    assert (teleop.linear_speed, teleop.angular_speed) == pytest.approx((0.495, 1.1))
    teleop.press("c")
    assert teleop.angular_speed == pytest.approx(0.99)
    teleop.press("z")
    assert (teleop.linear_speed, teleop.angular_speed) == pytest.approx((0.4455, 0.891))
