"""The maths of rotating in place, without ROS: yaw accumulated across the ±pi seam, and
the angular speed that brings the robot to a target and slows it near the end."""
from __future__ import annotations

import math
from dataclasses import dataclass


class YawAccumulator:
    """Turns a stream of yaw readings in (-pi, pi] into a continuous angle, so that full
    turns count: 270 degrees is 3/2 pi, not -pi/2."""

    def __init__(self):
        self.total = None
        self._last = None

    def update(self, yaw: float) -> float:
        if self._last is None:
            self.total = yaw
        else:
            self.total += math.atan2(math.sin(yaw - self._last), math.cos(yaw - self._last))
        self._last = yaw
        return self.total

    def rebase(self, yaw: float) -> None:
        """Readings go on from ``yaw`` without the change to it being counted: a teleport
        (a simulation reset) is not turning."""
        if self._last is None:
            self.total = yaw
        self._last = yaw


@dataclass
class RotationGains:
    """Proportional speed with a floor and a ceiling (rad/s and 1/s), and the tolerance
    (rad) within which the rotation is done."""

    gain: float
    max_speed: float
    min_speed: float
    tolerance: float


def angular_speed(error: float, gains: RotationGains) -> float:
    """The angular velocity command for a remaining error (rad): 0 within tolerance,
    otherwise gain x error, at least min_speed and at most max_speed, towards the target."""
    if abs(error) <= gains.tolerance:
        return 0.0
    speed = min(gains.max_speed, max(gains.min_speed, gains.gain * abs(error)))
    return math.copysign(speed, error)


def time_allowed(angle: float, gains: RotationGains, margin: float, slack: float) -> float:
    """Seconds a rotation of ``angle`` rad may take: ``slack`` times the time at full speed,
    plus ``margin`` for speeding up and slowing down."""
    return slack * abs(angle) / gains.max_speed + margin
