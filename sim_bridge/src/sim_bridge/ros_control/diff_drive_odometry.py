"""diff_drive_controller's odometry and speed limiter, as ros_controllers noetic-devel
(678b92a) computes them: ``diff_drive_controller/src/odometry.cpp`` and
``src/speed_limiter.cpp``. Pure maths: no pybullet, no ROS.

The odometry integrates the wheels' *position* changes since the last update (not their
velocities), and publishes as its twist the rolling mean of the last
``velocity_rolling_window_size`` per-update estimates (boost's rolling_mean: the mean of the
samples there are while fewer than the window). Open loop, it integrates the commands
instead.
"""
from __future__ import annotations

import math
from collections import deque
from dataclasses import dataclass
from typing import Deque

# odometry.cpp:155: below this turn (rad per update) the arc is taken as a straight step
STRAIGHT_TURN = 1e-6
# odometry.cpp:96-98: an interval shorter than this gives no velocity estimate
MIN_VELOCITY_INTERVAL = 0.0001
# diff_drive_controller.cpp:229 (and odometry.h:72)
DEFAULT_ROLLING_WINDOW = 10


class RollingMean:
    """boost::accumulators' rolling_mean over a window: the mean of the last ``size``
    samples, or of all of them while there are fewer."""

    def __init__(self, size: int):
        self.samples: Deque[float] = deque(maxlen=max(int(size), 1))

    def add(self, value: float) -> float:
        self.samples.append(value)
        return sum(self.samples) / len(self.samples)


class Odometry:
    """odometry.cpp's Odometry. Its pose, and the wheels' previous positions, start at 0 when
    it is made and are kept by :meth:`init` (odometry.cpp:48-72): a controller restarted goes
    on from where it was, and wheels not at 0 on the first update count as travelled."""

    def __init__(self, window: int = DEFAULT_ROLLING_WINDOW):
        self.window = window
        self.x = self.y = self.heading = 0.0
        self.linear = self.angular = 0.0
        self.separation = self.left_radius = self.right_radius = 0.0
        self._left_old = self._right_old = 0.0
        self._stamp_ns = 0  # ros::Time(0) until init
        self._reset_means()

    def _reset_means(self) -> None:
        self._linear_mean = RollingMean(self.window)
        self._angular_mean = RollingMean(self.window)

    def init(self, now_ns: int) -> None:
        """odometry.cpp:67-72: the means start over, the time is now."""
        self._reset_means()
        self._stamp_ns = now_ns

    def set_wheel_params(self, separation: float, left_radius: float,
                         right_radius: float) -> None:
        self.separation, self.left_radius, self.right_radius = \
            separation, left_radius, right_radius

    def update(self, left_position: float, right_position: float, now_ns: int) -> bool:
        """odometry.cpp:74-110: from the wheels' positions (rad, each side's mean)."""
        left = left_position * self.left_radius
        right = right_position * self.right_radius
        left_step, right_step = left - self._left_old, right - self._right_old
        self._left_old, self._right_old = left, right
        linear = (right_step + left_step) * 0.5
        angular = (right_step - left_step) / self.separation
        return self._advance(linear, angular, now_ns)

    def _advance(self, linear: float, angular: float, now_ns: int) -> bool:
        """A step's travel (m) and turn (rad) integrated first; then a velocity estimate
        into the rolling means, only when at least 0.1 ms has passed (odometry.cpp:80-99)."""
        self._integrate(linear, angular)
        dt = (now_ns - self._stamp_ns) * 1e-9
        if dt < MIN_VELOCITY_INTERVAL:
            return False
        self._stamp_ns = now_ns
        self.linear = self._linear_mean.add(linear / dt)
        self.angular = self._angular_mean.add(angular / dt)
        return True

    def update_open_loop(self, linear: float, angular: float, now_ns: int) -> None:
        """odometry.cpp:112-122: the command (m/s, rad/s) is the twist, integrated over the
        time since the last update."""
        self.linear, self.angular = linear, angular
        dt = (now_ns - self._stamp_ns) * 1e-9
        self._stamp_ns = now_ns
        self._integrate(linear * dt, angular * dt)

    def _integrate(self, linear: float, angular: float) -> None:
        """integrateExact (odometry.cpp:153-166), a displacement (m, rad): along the arc, or
        second-order Runge-Kutta (:138-146) when the turn is too small for the arc."""
        if abs(angular) < STRAIGHT_TURN:
            direction = self.heading + angular * 0.5
            self.x += linear * math.cos(direction)
            self.y += linear * math.sin(direction)
            self.heading += angular
            return
        old = self.heading
        radius = linear / angular
        self.heading += angular
        self.x += radius * (math.sin(self.heading) - math.sin(old))
        self.y -= radius * (math.cos(self.heading) - math.cos(old))


@dataclass
class SpeedLimiter:
    """speed_limiter.cpp (speed_limiter.h:61-71 for the defaults: every limit off, every
    bound 0). ``limit`` applies jerk, then acceleration, then velocity (:75-84)."""

    has_velocity_limits: bool = False
    has_acceleration_limits: bool = False
    has_jerk_limits: bool = False
    min_velocity: float = 0.0
    max_velocity: float = 0.0
    min_acceleration: float = 0.0
    max_acceleration: float = 0.0
    min_jerk: float = 0.0
    max_jerk: float = 0.0

    def limit(self, v: float, v0: float, v1: float, dt: float) -> float:
        """``v`` limited, given the two limited commands before it (``v0`` the last) and the
        control period ``dt``."""
        if self.has_jerk_limits:  # :115-135
            dv0 = v0 - v1
            reach = 2.0 * dt * dt
            v = v0 + dv0 + _clamp((v - v0) - dv0, self.min_jerk * reach, self.max_jerk * reach)
        if self.has_acceleration_limits:  # :98-113
            v = v0 + _clamp(v - v0, self.min_acceleration * dt, self.max_acceleration * dt)
        if self.has_velocity_limits:  # :86-96
            v = _clamp(v, self.min_velocity, self.max_velocity)
        return v


def _clamp(value: float, low: float, high: float) -> float:
    """speed_limiter.cpp:43-47: min(max(low, value), high)."""
    return min(max(low, value), high)
