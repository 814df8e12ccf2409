"""The flip routine's logic without a master: its schedule, its settings, its flip count."""
import math
import os

import pytest

from itertools import islice

from diff_drive.flip import (FlipCounter, FlipSettings, commanded_speed, load_defaults,
                             schedule, up_axis_z)

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


def test_the_schedule_reverses_exactly_at_each_legs_start():
    flip = settings()  # legs of 1.5 s at 20 Hz: every leg's start is a tick
    events = list(islice(schedule(flip), 200))
    times = [t for t, _ in events]
    assert times == pytest.approx([n / 20.0 for n in range(200)])
    reversals = [t for (t, v), (_, before) in zip(events[1:], events) if v != before]
    assert reversals == pytest.approx([1.5 * leg for leg in range(1, 7)])
    assert all(v == commanded_speed(flip, t + 1e-6) for t, v in events)


def test_a_leg_start_between_ticks_gets_its_own_command():
    flip = settings(leg_time=1.33)
    events = list(islice(schedule(flip), 120))
    times = [t for t, _ in events]
    assert times == sorted(times) and len(set(times)) == len(times)
    reversals = [t for (t, v), (_, before) in zip(events[1:], events) if v != before]
    assert reversals == pytest.approx([1.33 * leg for leg in range(1, len(reversals) + 1)])
    assert len(reversals) == 4
    ticks = [t for t in times if t not in reversals]
    assert ticks == pytest.approx([n / 20.0 for n in range(len(ticks))])


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
