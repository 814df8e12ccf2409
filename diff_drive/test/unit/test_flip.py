"""The flip routine's logic without a master: its schedule, its settings, its flip count."""
import math
import os

import pytest

from diff_drive.flip import (FlipCounter, FlipSettings, commanded_speed, load_defaults,
                             up_axis_z)

PACKAGE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DEFAULTS = os.path.join(PACKAGE, "config", "flip.yaml")


def settings(**changes):
    values = dict(speed=2.0, leg_time=1.5, rate=20.0)
    values.update(changes)
    return FlipSettings.from_mapping(values, "test")


def test_the_packaged_defaults_are_complete_and_valid():
    read = FlipSettings.from_mapping(load_defaults(DEFAULTS), DEFAULTS)
    assert read.speed > 0 and read.leg_time > 0 and read.rate > 0


def test_legs_alternate_in_sign_at_full_speed():
    flip = settings()
    speeds = [commanded_speed(flip, 0.1 + 1.5 * leg) for leg in range(6)]
    assert speeds == [2.0, -2.0, 2.0, -2.0, 2.0, -2.0]
    # the reversal is sudden: full speed one way just before, full speed the other after
    assert commanded_speed(flip, 1.499) == 2.0 and commanded_speed(flip, 1.501) == -2.0


@pytest.mark.parametrize("name, value", [("speed", 0.0), ("speed", -1.0),
                                         ("leg_time", float("nan")), ("rate", "fast"),
                                         ("rate", True), ("leg_time", float("inf"))])
def test_a_bad_setting_is_refused_by_name(name, value):
    with pytest.raises(ValueError, match=f"^test: {name}: "):
        settings(**{name: value})


def test_a_missing_setting_is_named():
    with pytest.raises(ValueError, match="/flip: rate is not set"):
        FlipSettings.from_mapping(dict(speed=1.0, leg_time=1.0), "/flip")


def test_an_unreadable_defaults_file_is_named(tmp_path):
    with pytest.raises(ValueError, match="nowhere.yaml"):
        load_defaults(str(tmp_path / "nowhere.yaml"))
    empty = tmp_path / "empty.yaml"
    empty.write_text("")
    with pytest.raises(ValueError, match="empty.yaml"):
        load_defaults(str(empty))


def test_up_axis_from_quaternion():
    assert up_axis_z(0, 0, 0, 1) == pytest.approx(1.0)
    half = math.sqrt(0.5)
    assert up_axis_z(0, half, 0, half) == pytest.approx(0.0)  # on its nose
    assert up_axis_z(0, 1, 0, 0) == pytest.approx(-1.0)  # pitched over
    assert up_axis_z(0, 0, 1, 0) == pytest.approx(1.0)  # turned round, not flipped


def test_the_counter_counts_sign_changes_past_the_dead_band():
    counter = FlipCounter(dead_band=0.2)
    readings = [1.0, 0.5, 0.1, -0.1, 0.1, -0.6, -1.0, -0.1, 0.15, -0.9, 0.3, 1.0]
    completed = [counter.update(up) for up in readings]
    assert counter.flips == 2  # 1 -> -0.6 and -0.9 -> 0.3; the wobble near edge is no flip
    assert completed.count(True) == 2


def test_the_animation_renders_headless(tmp_path):
    from diff_drive.flip_animation import render_flip

    output = tmp_path / "flip.gif"
    assert render_flip(str(output), seconds=0.8) == 10
    assert output.read_bytes()[:6] == b"GIF89a"
