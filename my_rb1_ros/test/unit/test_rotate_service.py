"""my_rb1_ros.rotate_service without a master: the service's rotation run against a fake
simulator (simulated time, wall clock, a robot that turns as commanded, its odometry), in
which physics pauses, time goes back, odometry stops or jumps. Every answer ends within its
bound in wall-clock time, names its cause, and the next request succeeds."""
import math
from types import SimpleNamespace

import pytest
import rospy
from nav_msgs.msg import Odometry
from tf.transformations import quaternion_from_euler

from my_rb1_ros.rotate_service import GUARD_POLL, Config, RotateService

CONFIG = Config()
# A failure must come within the timeout, plus one poll of the guards, plus the odometry
# period by which the last message may precede the stall.
BOUND = CONFIG.odom_timeout + GUARD_POLL + 1.0 / CONFIG.control_rate


def obedient_robot(sim, _seconds):
    """The robot's yaw rate (rad/s) over the next step: the commanded one."""
    return sim.speed


class FakeSimulator:
    """Simulated and wall time advanced by the service's own waits (real time factor 1),
    a robot turning as ``robot(sim, seconds)`` says (at the commanded speed unless a test
    scripts it), odometry after every step. ``hook`` runs before each step, so a test can
    pause, rewind or teleport."""

    def __init__(self, robot=obedient_robot):
        self.sim, self.wall = 5.0, 1000.0
        self.yaw, self.speed, self.rate = 0.0, 0.0, 0.0
        self.robot = robot
        self.paused, self.odometry_on = False, True
        self.hook = None
        self.service = RotateService(CONFIG, sim_now=lambda: self.sim,
                                     wall_now=lambda: self.wall, wait=self.wait)
        self.service.command = SimpleNamespace(publish=self._command)
        self.publish_odometry()

    def _command(self, twist):
        self.speed = twist.angular.z

    def publish_odometry(self):
        message = Odometry()
        message.header.stamp = rospy.Time.from_sec(self.sim)
        message.pose.pose.position.x = -5.0
        q = quaternion_from_euler(0.0, 0.0, self.yaw)
        o = message.pose.pose.orientation
        o.x, o.y, o.z, o.w = q
        message.twist.twist.angular.z = self.rate
        self.service._on_odometry(message)

    def wait(self, seconds):
        if self.hook is not None:
            self.hook(self)
        self.wall += seconds
        if self.paused:
            return
        self.sim += seconds
        self.rate = self.robot(self, seconds)
        self.yaw = math.atan2(math.sin(self.yaw + self.rate * seconds),
                              math.cos(self.yaw + self.rate * seconds))
        if self.odometry_on:
            self.publish_odometry()

    def rotate(self, degrees):
        """(answer, true rotation in degrees, wall seconds taken)."""
        wall0, turned = self.wall, 0.0
        last = self.yaw

        def counting_hook(original):
            def hook(sim):
                nonlocal turned, last
                if original is not None:
                    original(sim)
                turned += math.atan2(math.sin(sim.yaw - last), math.cos(sim.yaw - last))
                last = sim.yaw
            return hook

        self.hook = counting_hook(self.hook)
        try:
            answer = self.service._serve(SimpleNamespace(degrees=degrees)).result
        finally:
            self.hook = None
        turned += math.atan2(math.sin(self.yaw - last), math.cos(self.yaw - last))
        return answer, math.degrees(turned), self.wall - wall0


@pytest.fixture
def sim():
    return FakeSimulator()


def assert_next_rotation_succeeds(sim):
    answer, turned, _ = sim.rotate(90)
    assert answer.startswith("success: rotated 90 degrees"), answer
    assert turned == pytest.approx(90.0, abs=CONFIG.tolerance_degrees + 0.1)


def test_a_rotation_in_the_fake_simulator_succeeds(sim):
    answer, turned, _ = sim.rotate(-270)
    assert answer.startswith("success: rotated -270 degrees"), answer
    assert turned == pytest.approx(-270.0, abs=CONFIG.tolerance_degrees + 0.1)
    assert sim.speed == 0.0


def test_physics_paused_before_the_call_fails_within_the_bound(sim):
    sim.paused = True
    answer, turned, took = sim.rotate(90)
    assert answer.startswith("failure: simulated time has not advanced"), answer
    assert "physics paused" in answer
    assert CONFIG.odom_timeout < took <= BOUND
    assert turned == 0.0 and sim.speed == 0.0
    sim.paused = False
    assert_next_rotation_succeeds(sim)


def test_physics_paused_during_the_rotation_fails_within_the_bound(sim):
    paused_at = {}

    def pause_later(s):
        if not s.paused and s.sim > 6.0:
            s.paused, paused_at["wall"] = True, s.wall

    sim.hook = pause_later
    answer, _, _ = sim.rotate(360)
    assert "physics paused" in answer and "turned" in answer, answer
    assert CONFIG.odom_timeout < sim.wall - paused_at["wall"] <= BOUND
    assert sim.speed == 0.0
    sim.paused = False
    assert_next_rotation_succeeds(sim)


def test_simulated_time_going_back_fails_naming_a_reset_or_restart(sim):
    def restart(s):
        if s.sim > 6.0:
            s.sim, s.hook = 0.1, None  # a new simulator's /clock, and its odometry

    sim.hook = restart
    answer, _, took = sim.rotate(360)
    assert answer.startswith("failure: "), answer
    assert "moved backwards" in answer and "reset or restarted" in answer
    assert took < BOUND
    assert_next_rotation_succeeds(sim)


def test_a_teleport_during_the_rotation_fails_naming_the_jump_and_is_not_counted(sim):
    def teleport(s):
        if s.yaw > math.radians(120):
            s.yaw, s.hook = 0.0, None  # reset_world: back where it was spawned

    sim.hook = teleport
    answer, _, _ = sim.rotate(360)
    assert answer.startswith("failure: odometry jumped: the heading changed by"), answer
    # turned: what odometry measured up to the jump, the jump itself not counted
    done = float(answer.split("turned ")[1].split(" of")[0])
    assert 120.0 <= done < 130.0
    assert_next_rotation_succeeds(sim)


def test_odometry_stopping_while_time_runs_is_named(sim):
    def silence(s):
        if s.sim > 6.0:
            s.odometry_on = False

    sim.hook = silence
    answer, _, took = sim.rotate(360)
    assert "no odometry on odom for" in answer and "while simulated time runs" in answer
    # found by the stall check, in simulated time, before the wall-clock timeout
    assert took < 1.0 + CONFIG.stall_seconds + GUARD_POLL
    sim.odometry_on = True
    sim.publish_odometry()
    assert_next_rotation_succeeds(sim)


def test_rospys_time_moved_backwards_is_an_answer_not_a_traceback(sim, monkeypatch):
    def raises(_degrees):
        raise rospy.exceptions.ROSTimeMovedBackwardsException(12.5)

    monkeypatch.setattr(sim.service, "_turn_by", lambda *args: raises(None))
    answer, _, _ = sim.rotate(90)
    assert answer.startswith("failure: simulated time moved backwards by 12.500 s"), answer
    assert "reset or restarted" in answer
    monkeypatch.undo()
    assert_next_rotation_succeeds(sim)


# The reported flake: rotate -180 at 5x real time, under load, ended at -180.4 and failed
# with "no progress for 2 s" although the robot was turning back to the goal.
OVERSHOOT_DEGREES = 0.4  # past the goal: more than the tolerance, less than stall_degrees
# How late (simulated s) the robot answers the command that turns it back: a node starved
# of CPU at 5x real time answers late in simulated time. Shorter than stall_seconds, so
# the robot is not blocked.
LATE_SECONDS = 0.75 * CONFIG.stall_seconds
# Simulated seconds a failure may come after its limit: the control loop's period, twice
# (the step that finds it, and the odometry that step reads).
LOOP_SLACK = 2.0 / CONFIG.control_rate


class OvershootingRobot:
    """A scripted robot for a rotation of ``goal`` degrees: it turns as commanded until the
    service first stops it, then slows down at a constant rate and comes to rest
    OVERSHOOT_DEGREES past the goal (its odometry reporting the coasting, so the service
    waits for it to settle), and answers the command that turns it back only ``late``
    simulated seconds after it came; then it turns as commanded, or never when
    ``blocked``."""

    def __init__(self, goal, late, blocked=False):
        self.stop_at = math.radians(goal + math.copysign(OVERSHOOT_DEGREES, goal))
        self.late, self.blocked = late, blocked
        self.turned, self.coasting, self.deceleration = 0.0, 0.0, 0.0  # rad, rad/s, rad/s^2
        self.phase = "approach"
        self.correction_asked = None  # simulated s

    def __call__(self, sim, seconds):
        rate = self._rate(sim, seconds)
        self.turned += rate * seconds
        return rate

    def _rate(self, sim, seconds):
        if self.phase == "approach":
            if sim.speed != 0.0 or self.turned == 0.0:
                self.coasting = sim.speed
                return sim.speed
            self.phase = "coast"
            # v^2 = 2 a d: the deceleration that stops it exactly at stop_at
            self.deceleration = self.coasting ** 2 / (2.0 * abs(self.stop_at - self.turned))
        if self.phase == "coast":
            left = self.stop_at - self.turned
            if abs(self.coasting * seconds) < abs(left):
                rate = self.coasting
                self.coasting -= math.copysign(self.deceleration * seconds, self.coasting)
                return rate
            self.phase = "stopped"
            return left / seconds
        if self.phase == "stopped":
            if sim.speed == 0.0:
                return 0.0
            self.phase, self.correction_asked = "late", sim.sim - seconds
        if self.blocked or sim.sim - self.correction_asked < self.late:
            return 0.0
        return sim.speed


# Progress once counted as 2 degrees of motion in any direction since the last 2 degrees,
# the stopped settling included: whether the overshoot, or the time before it, used up the
# 2 s depended on where that 2-degree grid fell near the goal. With these dynamics -90, 90,
# 360, -720, 30 and 60 failed so, -180 and 45 did not.
@pytest.mark.parametrize("goal", [-180, -90, 90, 360, -720, 30, 60, 45])
def test_an_overshoot_turned_back_late_is_no_stall(goal):
    robot = OvershootingRobot(goal, LATE_SECONDS)
    sim = FakeSimulator(robot)
    answer, turned, _ = sim.rotate(goal)
    assert robot.correction_asked is not None  # it did overshoot and turn back
    assert answer.startswith(f"success: rotated {goal} degrees"), answer
    assert turned == pytest.approx(goal, abs=CONFIG.tolerance_degrees + 0.1)


def test_a_robot_blocked_after_overshooting_fails_as_blocked_in_time():
    robot = OvershootingRobot(-180, LATE_SECONDS, blocked=True)
    sim = FakeSimulator(robot)
    answer, turned, _ = sim.rotate(-180)
    assert answer.startswith("failure: the robot does not turn (blocked?)"), answer
    assert f"no progress for {CONFIG.stall_seconds:g} s" in answer
    assert turned == pytest.approx(-180.0 - OVERSHOOT_DEGREES, abs=0.01)
    blocked_for = sim.sim - robot.correction_asked
    assert CONFIG.stall_seconds < blocked_for <= CONFIG.stall_seconds + LOOP_SLACK
    assert sim.speed == 0.0


def test_a_robot_blocked_from_the_start_fails_as_blocked_in_time():
    sim = FakeSimulator(robot=lambda _sim, _seconds: 0.0)
    started = sim.sim
    answer, turned, _ = sim.rotate(90)
    assert answer.startswith("failure: the robot does not turn (blocked?): 0.0 of 90 degrees"), \
        answer
    assert turned == 0.0
    assert CONFIG.stall_seconds < sim.sim - started <= CONFIG.stall_seconds + LOOP_SLACK
    assert sim.speed == 0.0


def test_a_robot_turning_the_wrong_way_fails_saying_so_in_time():
    sim = FakeSimulator(robot=lambda s, _seconds: -s.speed)
    started = sim.sim
    answer, turned, _ = sim.rotate(90)
    assert answer.startswith("failure: the robot turns away from the goal"), answer
    assert turned < 0.0
    assert CONFIG.stall_seconds < sim.sim - started <= CONFIG.stall_seconds + LOOP_SLACK
    assert sim.speed == 0.0
