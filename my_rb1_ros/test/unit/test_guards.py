"""my_rb1_ros.guards: odometry jumps, simulated time standing still or going back, odometry
falling silent, a commanded turn making no progress; no master."""
import math

import pytest

from my_rb1_ros.guards import (MISSED_PERIODS, ClockWatch, GuardTripped, JumpDetector,
                               MotionLimits, OdometrySample, OdometryWatch, StallWatch)

LIMITS = MotionLimits(angular_speed=1.6, linear_speed=1.0, angle_margin=math.radians(5.0),
                      distance_margin=0.05)
PERIOD = 0.02  # s, the RB1's odometry at 50 Hz
TIMEOUT = 5.0


def detector_after(sample):
    detector = JumpDetector(LIMITS)
    assert detector.check(sample) is None  # the first sample has nothing to compare with
    return detector


def test_turning_at_the_fastest_speed_is_no_jump_even_across_the_seam():
    detector = detector_after(OdometrySample(0.0, -5.0, 0.0, math.pi - 0.01))
    step = LIMITS.angular_speed * PERIOD
    yaw = math.pi - 0.01
    for i in range(1, 400):  # more than a full turn, through +-pi
        yaw = math.atan2(math.sin(yaw + step), math.cos(yaw + step))
        assert detector.check(OdometrySample(i * PERIOD, -5.0, 0.0, yaw)) is None


def test_a_heading_jump_is_named_with_its_size_and_the_limit():
    detector = detector_after(OdometrySample(10.0, -5.0, 0.0, math.radians(133.0)))
    jump = detector.check(OdometrySample(10.0 + PERIOD, -5.0, 0.0, 0.0))
    assert jump is not None and "jumped" in jump and "reset" in jump
    assert "133.0 degrees" in jump
    most = math.degrees(LIMITS.angular_speed * PERIOD + LIMITS.angle_margin)
    assert f"({most:.1f} degrees)" in jump


def test_the_heading_limit_grows_with_the_time_between_messages():
    turn = LIMITS.angle_margin + LIMITS.angular_speed * 1.0 * 0.9  # possible in 1 s, not in 0.02
    assert detector_after(OdometrySample(0.0, 0.0, 0.0, 0.0)).check(
        OdometrySample(1.0, 0.0, 0.0, turn)) is None
    assert detector_after(OdometrySample(0.0, 0.0, 0.0, 0.0)).check(
        OdometrySample(PERIOD, 0.0, 0.0, turn)) is not None


def test_a_position_jump_is_named_with_its_size():
    detector = detector_after(OdometrySample(3.0, -2.0, 1.0, 0.0))
    jump = detector.check(OdometrySample(3.0 + PERIOD, -5.0, 0.0, 0.0))
    assert jump is not None and "position moved 3.162 m" in jump
    # driving at the fastest speed is no jump
    assert detector_after(OdometrySample(0.0, 0.0, 0.0, 0.0)).check(
        OdometrySample(PERIOD, LIMITS.linear_speed * PERIOD, 0.0, 0.0)) is None


def test_a_stamp_going_back_is_a_reset_or_restart():
    detector = detector_after(OdometrySample(42.0, 0.0, 0.0, 0.0))
    jump = detector.check(OdometrySample(0.5, 0.0, 0.0, 0.0))
    assert "moved backwards by 41.500 s" in jump and "reset or restarted" in jump


class Clocks:
    def __init__(self):
        self.sim, self.wall = 10.0, 1000.0


def test_clock_watch_returns_simulated_time_while_it_runs():
    clocks = Clocks()
    watch = ClockWatch(lambda: clocks.sim, lambda: clocks.wall, TIMEOUT)
    for _ in range(100):  # sim time running ten times slower than the wall: still running
        clocks.wall += 1.0
        clocks.sim += 0.1
        assert watch.check() == pytest.approx(clocks.sim)


def test_clock_watch_names_paused_physics_after_the_timeout_in_wall_time():
    clocks = Clocks()
    watch = ClockWatch(lambda: clocks.sim, lambda: clocks.wall, TIMEOUT)
    clocks.wall += TIMEOUT  # standing still exactly the timeout: not yet
    watch.check()
    clocks.wall += 0.1
    with pytest.raises(GuardTripped, match="not advanced for 5.1 s .*physics paused"):
        watch.check()


def test_clock_watch_names_a_reset_or_restart_when_time_goes_back():
    clocks = Clocks()
    watch = ClockWatch(lambda: clocks.sim, lambda: clocks.wall, TIMEOUT)
    clocks.sim = 0.25  # a new simulator's /clock
    with pytest.raises(GuardTripped, match="moved backwards by 9.750 s.*reset or restarted"):
        watch.check()


def received(watch, stamps, wall):
    for stamp in stamps:
        watch.received(stamp, wall)


def test_odometry_watch_fresh_then_silent_while_time_runs():
    watch = OdometryWatch(TIMEOUT, "/odom")
    received(watch, [1.0, 1.0 + PERIOD], wall=100.0)
    assert watch.fresh(100.0 + TIMEOUT)
    assert watch.check(100.0 + TIMEOUT, sim_now=50.0, waiting_since=100.0) is None
    cause = watch.check(100.0 + TIMEOUT + 1.0, sim_now=50.0, waiting_since=100.0)
    assert cause.startswith("no odometry on /odom for 6.0 s") and "time runs" in cause
    assert not watch.fresh(100.0 + TIMEOUT + 1.0)


def test_odometry_silent_because_time_stands_still_is_named_paused():
    watch = OdometryWatch(TIMEOUT, "/odom")
    received(watch, [1.0, 1.0 + PERIOD], wall=100.0)
    # the clock ticked a little past the last message, but no next message was due
    sim_now = 1.0 + PERIOD + MISSED_PERIODS * PERIOD * 0.9
    cause = watch.check(100.0 + TIMEOUT + 0.5, sim_now=sim_now, waiting_since=100.0)
    assert "physics paused" in cause


def test_odometry_never_received_is_named_after_the_timeout_of_the_wait():
    watch = OdometryWatch(TIMEOUT, "/odom")
    assert watch.check(104.0, sim_now=3.0, waiting_since=100.0) is None
    assert "none received" in watch.check(105.5, sim_now=3.0, waiting_since=100.0)


STALL_STEP = math.radians(2.0)  # rad closer to the goal that count as progress
STALL_SECONDS = 2.0  # simulated s without progress that are a stall


def test_a_turn_that_never_gets_closer_stalls_after_the_limit_as_blocked():
    watch = StallWatch(STALL_STEP, STALL_SECONDS)
    remaining = math.radians(90.0)
    assert watch.check(remaining, 10.0) is None
    # creeping: less than a step closer is not progress
    assert watch.check(remaining - 0.9 * STALL_STEP, 10.0 + STALL_SECONDS) is None
    assert watch.check(remaining - 0.9 * STALL_STEP, 10.0 + STALL_SECONDS + PERIOD) == \
        "the robot does not turn (blocked?)"


def test_each_step_closer_counts_from_then():
    watch = StallWatch(STALL_STEP, STALL_SECONDS)
    assert watch.check(math.radians(90.0), 10.0) is None
    assert watch.check(math.radians(88.0), 11.5) is None
    assert watch.check(math.radians(88.0), 11.5 + STALL_SECONDS) is None
    assert watch.check(math.radians(88.0), 11.5 + STALL_SECONDS + PERIOD) is not None


def test_after_a_restart_settling_at_the_goal_does_not_count():
    watch = StallWatch(STALL_STEP, STALL_SECONDS)
    assert watch.check(math.radians(1.5), 10.0) is None  # last counted 1.5 degrees short
    # stopped, it settled 0.4 degrees past the goal: counted from 10.0 s, a stall at once
    assert watch.check(math.radians(-0.4), 13.0) is not None
    watch.restart()  # what the rotation does before it turns back
    assert watch.check(math.radians(-0.4), 13.0) is None
    assert watch.check(math.radians(-0.4), 13.0 + STALL_SECONDS) is None
    assert watch.check(math.radians(-0.4), 13.0 + STALL_SECONDS + PERIOD) == \
        "the robot does not turn (blocked?)"


def test_turning_away_from_the_goal_is_no_progress_and_named():
    watch = StallWatch(STALL_STEP, STALL_SECONDS)
    assert watch.check(math.radians(90.0), 10.0) is None
    assert watch.check(math.radians(110.0), 10.0 + STALL_SECONDS) is None
    assert "turns away from the goal" in watch.check(math.radians(110.0),
                                                     10.0 + STALL_SECONDS + PERIOD)
