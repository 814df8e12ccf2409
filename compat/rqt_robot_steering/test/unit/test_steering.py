"""robot_steering.steering: rqt_robot_steering's defaults, parameters and publishing rule."""
import pytest

from robot_steering.steering import (PAGE_STEP, SINGLE_STEP, CommandGate, Settings,
                                     angular_label, clamp_range, linear_label, make_twist,
                                     read_settings, slider_position, slider_velocity,
                                     topic_problem)


def params(**values):
    """A stand-in for rospy.get_param over the given private parameters."""
    def get_param(name, default):
        assert name.startswith("~"), name
        return values.get(name[1:], default)
    return get_param


def test_defaults_are_upstreams():
    assert Settings() == Settings(topic="/cmd_vel", vx_max=1.0, vx_min=-1.0,
                                  vw_max=3.0, vw_min=-3.0)
    assert read_settings(params()) == (Settings(), [])


def test_parameters_override_every_default():
    settings, warnings = read_settings(params(
        default_topic="/robot/cmd_vel", default_vx_max=0.5, default_vx_min=-0.25,
        default_vw_max=1, default_vw_min="-1.5"))
    assert warnings == []
    assert settings == Settings("/robot/cmd_vel", 0.5, -0.25, 1.0, -1.5)


@pytest.mark.parametrize("name, value, field, expected, says", [
    ("default_vx_max", 12.0, "vx_max", 10.0, "~default_vx_max must lie between 0.0 and 10.0"),
    ("default_vx_max", -1.0, "vx_max", 0.0, "~default_vx_max must lie between 0.0 and 10.0"),
    ("default_vx_min", 0.5, "vx_min", 0.0, "~default_vx_min must lie between -10.0 and 0.0"),
    ("default_vw_min", -20, "vw_min", -10.0, "~default_vw_min must lie between -10.0 and 0.0"),
    ("default_vw_max", "fast", "vw_max", 3.0, "~default_vw_max: 'fast' is not a number; expected a number between 0.0 and 10.0; using 3.0"),
    ("default_vw_max", True, "vw_max", 3.0, "~default_vw_max: True is a boolean, not a number"),
    ("default_vx_min", float("nan"), "vx_min", -1.0, "~default_vx_min: nan is not a finite number"),
    ("default_vx_min", "nan", "vx_min", -1.0, "~default_vx_min: 'nan' is not a finite number"),
])
def test_a_bad_range_is_named_and_replaced(name, value, field, expected, says):
    settings, warnings = read_settings(params(**{name: value}))
    assert getattr(settings, field) == expected
    assert len(warnings) == 1 and says in warnings[0]


def test_ranges_keep_two_decimals_as_the_spin_boxes():
    settings, warnings = read_settings(params(default_vx_max=0.123, default_vw_min=-0.456))
    assert (settings.vx_max, settings.vw_min) == (0.12, -0.46)
    assert warnings == []
    assert clamp_range(0.57, 0.0, 10.0) == 0.57


def test_a_topic_that_is_not_a_string_falls_back_to_cmd_vel():
    settings, warnings = read_settings(params(default_topic=5))
    assert settings.topic == "/cmd_vel"
    assert "~default_topic: 5 is not text; expected a topic name; using /cmd_vel" in warnings[0]


def test_an_illegal_topic_is_kept_with_a_warning():
    settings, warnings = read_settings(params(default_topic="cmd vel"))
    assert settings.topic == "cmd vel"
    assert "'cmd vel' is not a legal topic name" in warnings[0]


def test_an_empty_topic_is_allowed_and_publishes_nothing():
    settings, warnings = read_settings(params(default_topic=""))
    assert settings.topic == "" and warnings == []
    assert "no topic" in topic_problem("")


@pytest.mark.parametrize("topic", ["/cmd_vel", "cmd_vel", "~cmd_vel", "/robot/cmd_vel"])
def test_legal_topics(topic):
    assert topic_problem(topic) is None


def test_the_global_namespace_is_no_topic():
    assert "'/' is the global namespace" in topic_problem("/")


@pytest.mark.parametrize("topic", ["cmd vel", "1cmd", "/a//b", "cmd-vel"])
def test_illegal_topics(topic):
    assert "is not a legal topic name" in topic_problem(topic)


def test_slider_positions_are_thousandths():
    assert slider_position(1.0) == 1000
    assert slider_position(-3.0) == -3000
    assert slider_position(0.57) == 570  # 0.57 * 1000 is 569.99...: rounded, not cut
    assert slider_velocity(300) == pytest.approx(0.3)
    assert slider_velocity(SINGLE_STEP) == pytest.approx(0.01)
    assert slider_velocity(PAGE_STEP) == pytest.approx(0.1)
    assert all(slider_position(slider_velocity(p)) == p for p in range(-10000, 10001, 7))


def test_labels():
    assert linear_label(0.3) == "0.30 m/s"
    assert linear_label(-1.0) == "-1.00 m/s"
    assert angular_label(3.0) == "3.00 rad/s"


def test_twist_has_only_forward_and_turn():
    twist = make_twist(0.25, -1.5)
    assert (twist.linear.x, twist.linear.y, twist.linear.z) == (0.25, 0.0, 0.0)
    assert (twist.angular.x, twist.angular.y, twist.angular.z) == (0.0, 0.0, -1.5)


def commands(gate, *offers):
    """What the gate lets through, as (x, z) pairs or None."""
    out = []
    for x, z in offers:
        twist = gate.offer(x, z)
        out.append(None if twist is None else (twist.linear.x, twist.angular.z))
    return out


def test_non_zero_commands_are_repeated():
    gate = CommandGate()
    assert commands(gate, (0.3, 0.0), (0.3, 0.0), (0.3, 1.0)) == [
        (0.3, 0.0), (0.3, 0.0), (0.3, 1.0)]
    assert gate.published == 3


def test_zero_goes_out_once_then_again_after_a_non_zero():
    gate = CommandGate()
    assert commands(gate, (0, 0), (0, 0), (0.1, 0), (0, 0), (0, 0)) == [
        (0.0, 0.0), None, (0.1, 0.0), (0.0, 0.0), None]
    assert gate.published == 3


def test_stop_pressed_lets_one_more_zero_through():
    gate = CommandGate()
    assert commands(gate, (0, 0), (0, 0)) == [(0.0, 0.0), None]
    gate.stop_pressed()
    assert commands(gate, (0, 0), (0, 0)) == [(0.0, 0.0), None]
