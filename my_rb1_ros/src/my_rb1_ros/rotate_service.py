"""The ``/rotate_robot`` service: turn the RB1 in place by a number of degrees.

Closed loop on ``odom`` (yaw accumulated, so full turns count), publishing ``cmd_vel``;
the speed falls near the goal; after stopping, the robot settles and the error is checked
again, so it ends within the tolerance. The robot is stopped on success, on every failure,
and when the node shuts down. Settings are private parameters (config/rotate_service.yaml).

Answers: ``success: rotated -90 degrees (final error 0.3 degrees)``, or ``failure: ...``
for: no odometry within ``~odom_timeout``; a robot that does not turn while commanded
(blocked); a rotation that outlasts its time (scaled to the angle); a request while
another runs (rejected; the first one goes on); more than ``~max_degrees``.

Every wait is bounded in wall-clock time as well as in simulated time, because simulated
time can stop (paused physics, a dead simulator) or go back (a reset, a restart): see
my_rb1_ros.guards. Those, and odometry jumping (a reset's teleport), end the rotation with a
failure that names them; the node goes on serving.
"""
from __future__ import annotations

import math
import sys
import threading
import time
from dataclasses import dataclass
from typing import Callable, Optional

import rospy
from node_params import ParameterError, at_least, non_negative, parameter, positive, read
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from tf.transformations import euler_from_quaternion

from my_rb1_ros.guards import (ClockWatch, GuardTripped, JumpDetector, MotionLimits,
                               OdometrySample, OdometryWatch, StallWatch,
                               time_moved_backwards)
from my_rb1_ros.rotation import RotationGains, YawAccumulator, angular_speed, time_allowed
from my_rb1_ros.srv import Rotate, RotateResponse

# The longest one wait for simulated time lasts (wall seconds) before the guards look
# again; each /clock message ends it sooner.
GUARD_POLL = 0.05


@dataclass
class Config:
    """Private parameters, read once with node_params (units in config/rotate_service.yaml).
    A value that cannot be used is a ParameterError naming it; the node then stops."""

    max_angular_speed: float = parameter(0.8, positive, expected="the fastest turn, rad/s > 0")
    min_angular_speed: float = parameter(
        0.05, positive, expected="the slowest turn near the goal, rad/s > 0 and at most "
                                 "~max_angular_speed")
    gain: float = parameter(1.5, positive, expected="1/s > 0: speed = gain x remaining angle")
    tolerance_degrees: float = parameter(0.3, positive,
                                         expected="degrees > 0 left when a rotation is done")
    control_rate: float = parameter(50.0, positive,
                                    expected="the control loop's rate, Hz (simulated) > 0")
    odom_timeout: float = parameter(
        5.0, positive, expected="wall seconds > 0 without odometry or moving time that fail")
    stall_seconds: float = parameter(
        2.0, positive, expected="seconds > 0 of commanded turning without progress that fail")
    stall_degrees: float = parameter(
        2.0, positive, expected="degrees > 0 closer to the goal that count as progress")
    settle_speed: float = parameter(0.01, positive,
                                    expected="rad/s > 0 below which the robot is still")
    settle_seconds: float = parameter(
        1.0, non_negative, expected="seconds >= 0 to wait for the robot to be still")
    time_slack: float = parameter(
        2.0, at_least(1.0), expected="a factor >= 1 on the time at full speed")
    time_margin: float = parameter(5.0, non_negative,
                                   expected="seconds >= 0 allowed on top of that time")
    max_degrees: int = parameter(3600, positive,
                                 expected="a whole number of degrees > 0, the largest request")
    jump_angular_speed: float = parameter(
        1.6, positive, expected="rad/s > 0, the fastest the robot really turns")
    jump_linear_speed: float = parameter(
        1.0, positive, expected="m/s > 0, the fastest the robot really drives")
    jump_degrees: float = parameter(5.0, non_negative,
                                    expected="degrees >= 0 allowed on top, per message")
    jump_distance: float = parameter(0.05, non_negative,
                                     expected="metres >= 0 allowed on top, per message")

    def __post_init__(self):
        if self.min_angular_speed > self.max_angular_speed:
            raise ParameterError("~min_angular_speed", self.min_angular_speed,
                                 f"is more than ~max_angular_speed ({self.max_angular_speed:g})",
                                 "the slowest turn, at most the fastest")

    @classmethod
    def from_parameters(cls, get_param: Callable = rospy.get_param) -> "Config":
        return read(cls, get_param)

    @property
    def gains(self) -> RotationGains:
        return RotationGains(self.gain, self.max_angular_speed, self.min_angular_speed,
                             math.radians(self.tolerance_degrees))

    @property
    def motion_limits(self) -> MotionLimits:
        return MotionLimits(self.jump_angular_speed, self.jump_linear_speed,
                            math.radians(self.jump_degrees), self.jump_distance)


class RotationFailed(Exception):
    """Why a rotation stopped short; the text goes into the answer."""


def _wait_for_clock(timeout: float) -> None:
    """Sleeps ``timeout`` wall seconds at most, less when /clock ticks: rospy notifies this
    condition on every /clock message (it is how rospy.sleep waits), so a loop paced in
    simulated time wakes as time moves, and still wakes when it does not."""
    condition = rospy.rostime.get_rostime_cond()
    with condition:
        condition.wait(timeout)


class RotateService:
    """The service and its odometry. The clocks and the wait are attributes so that unit
    tests can run a rotation without a master."""

    def __init__(self, config: Config, sim_now: Callable[[], float] = rospy.get_time,
                 wall_now: Callable[[], float] = time.monotonic,
                 wait: Callable[[float], None] = _wait_for_clock):
        self.config = config
        self.sim_now, self.wall_now, self.wait = sim_now, wall_now, wait
        self.yaw = YawAccumulator()
        self.yaw_rate = 0.0
        self.odometry = OdometryWatch(config.odom_timeout, "odom")
        self.jumps = JumpDetector(config.motion_limits)
        self.fault: Optional[str] = None  # a jump seen while a rotation runs
        self._rotating = False
        self._busy = threading.Lock()
        self._odom_lock = threading.Lock()
        self.command = None

    def start(self) -> None:
        self.odometry.topic = rospy.resolve_name("odom")
        self.command = rospy.Publisher("cmd_vel", Twist, queue_size=1)
        rospy.Subscriber("odom", Odometry, self._on_odometry, queue_size=10)
        rospy.on_shutdown(self.stop_robot)
        self.service = rospy.Service("/rotate_robot", Rotate, self._serve)
        rospy.loginfo("Service Ready")

    def _on_odometry(self, message: Odometry) -> None:
        p, q = message.pose.pose.position, message.pose.pose.orientation
        yaw = euler_from_quaternion((q.x, q.y, q.z, q.w))[2]
        sample = OdometrySample(message.header.stamp.to_sec(), p.x, p.y, yaw)
        with self._odom_lock:
            jump = self.jumps.check(sample)
            if jump is None:
                self.yaw.update(yaw)
            else:
                self.yaw.rebase(yaw)  # a teleport is not turning
                if self._rotating and self.fault is None:
                    self.fault = jump
            self.yaw_rate = message.twist.twist.angular.z
            self.odometry.received(sample.stamp, self.wall_now())

    def current_yaw(self):
        with self._odom_lock:
            return self.yaw.total, self.yaw_rate

    def stop_robot(self) -> None:
        self._turn(0.0)

    def _turn(self, speed: float) -> None:
        twist = Twist()
        twist.angular.z = speed
        self.command.publish(twist)

    # --- the service --------------------------------------------------------------------
    def _serve(self, request) -> RotateResponse:
        rospy.loginfo(f"Service Requested: rotate {request.degrees} degrees")
        if abs(request.degrees) > self.config.max_degrees:
            result = (f"failure: {request.degrees} degrees is beyond the limit of "
                      f"+-{self.config.max_degrees}; the robot did not move")
        elif not self._busy.acquire(blocking=False):
            result = ("failure: another rotation is running; this request is rejected "
                      "(the first one goes on)")
        else:
            try:
                result = self._rotate(request.degrees)
            except RotationFailed as failure:
                result = f"failure: {failure}"
            except rospy.exceptions.ROSTimeMovedBackwardsException as jump:
                # rospy's own waits raise it; ours name it first, this is the safety net
                now = self.sim_now()
                result = "failure: " + time_moved_backwards(now + jump.time, now,
                                                            "simulated time")
            except rospy.exceptions.ROSInterruptException:
                result = "failure: the node is shutting down"
            finally:
                with self._odom_lock:
                    self._rotating = False
                self.stop_robot()
                self._busy.release()
        rospy.loginfo(f"Service Completed: {result}")
        return RotateResponse(result)

    def _rotate(self, degrees: int) -> str:
        with self._odom_lock:
            self.fault, self._rotating = None, True
        watch = ClockWatch(self.sim_now, self.wall_now, self.config.odom_timeout)
        start = self._wait_for_odometry(watch)
        try:
            return self._turn_by(degrees, start, watch)
        except GuardTripped as cause:
            total, _ = self.current_yaw()
            raise RotationFailed(f"{cause}; turned {math.degrees(total - start):.1f} of "
                                 f"{degrees} degrees") from None

    def _guard(self, watch: ClockWatch, waiting_since: float) -> float:
        """The simulated time, once nothing says the rotation must end (GuardTripped)."""
        now = watch.check()
        with self._odom_lock:
            fault = self.fault
        if fault is not None:
            raise GuardTripped(fault)
        silence = self.odometry.check(self.wall_now(), now, waiting_since)
        if silence is not None:
            raise GuardTripped(silence)
        return now

    def _wait_until(self, watch: ClockWatch, sim_time: float, waiting_since: float) -> float:
        """Waits until simulated time reaches ``sim_time``, the guards checked on every
        wake; returns the simulated time."""
        while True:
            if rospy.is_shutdown():
                raise RotationFailed("the node is shutting down")
            now = self._guard(watch, waiting_since)
            if now >= sim_time:
                return now
            self.wait(min(sim_time - now, GUARD_POLL))

    def _wait_for_odometry(self, watch: ClockWatch) -> float:
        """The accumulated yaw once odometry is fresh; RotationFailed if none comes."""
        since = self.wall_now()
        try:
            while not self.odometry.fresh(self.wall_now()):
                if rospy.is_shutdown():
                    raise RotationFailed("the node is shutting down")
                self._guard(watch, since)
                self.wait(GUARD_POLL)
        except GuardTripped as cause:
            raise RotationFailed(f"{cause}; the robot did not move") from None
        with self._odom_lock:
            self.fault = None  # a jump before the start moved no goal
        return self.current_yaw()[0]

    def _turn_by(self, degrees: int, start: float, watch: ClockWatch) -> str:
        config, gains = self.config, self.config.gains
        if degrees == 0:
            return "success: rotated 0 degrees (final error 0.0 degrees)"
        since = self.wall_now()
        period = 1.0 / config.control_rate
        target = start + math.radians(degrees)
        began = watch.check()
        deadline = began + time_allowed(math.radians(degrees), gains, config.time_margin,
                                        config.time_slack)
        stall = StallWatch(math.radians(config.stall_degrees), config.stall_seconds)
        now = began
        while True:
            now = self._wait_until(watch, now, since)
            total, _ = self.current_yaw()
            error = target - total
            speed = angular_speed(error, gains)
            if speed == 0.0:
                final_error = self._settle(target, watch, since)
                self._guard(watch, since)  # the last reading may have been a jump
                if abs(final_error) <= gains.tolerance:
                    return (f"success: rotated {degrees} degrees (final error "
                            f"{abs(math.degrees(final_error)):.1f} degrees)")
                now = self.sim_now()
                stall.restart()  # standing still to settle was no stall: count from here
                continue  # it drifted out while stopping: turn again
            stalled = stall.check(error, now)
            if stalled is not None:
                last_odometry = self.odometry.last_stamp
                if last_odometry is not None and now - last_odometry > config.stall_seconds:
                    # no progress because nothing measures it: say so, not "blocked"
                    raise GuardTripped(
                        f"no odometry on {self.odometry.topic} for {now - last_odometry:.1f} s "
                        f"while simulated time runs (odometry stopped)")
                raise RotationFailed(
                    f"{stalled}: {math.degrees(total - start):.1f} of {degrees} degrees done, "
                    f"no progress for {config.stall_seconds:g} s")
            if now > deadline:
                raise RotationFailed(f"timed out after {now - began:.1f} s with "
                                     f"{math.degrees(error):.1f} degrees to go")
            self._turn(speed)
            now += period

    def _settle(self, target: float, watch: ClockWatch, since: float) -> float:
        """Stops, waits until the robot is still (or settle_seconds), returns the error."""
        self.stop_robot()
        now = watch.check()
        until = now + self.config.settle_seconds
        while now < until:
            _, yaw_rate = self.current_yaw()
            if abs(yaw_rate) < self.config.settle_speed:
                break
            now = self._wait_until(watch, now + 1.0 / self.config.control_rate, since)
        total, _ = self.current_yaw()
        return target - total


def main() -> None:
    rospy.init_node("rotate_service")
    try:
        config = Config.from_parameters()
    except ParameterError as error:
        rospy.logfatal("rotate_service: %s", error)
        sys.exit(1)
    service = RotateService(config)
    service.start()
    rospy.spin()
