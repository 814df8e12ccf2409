"""Figures computed from ground-truth samples, without ROS: heading unwrapped across ±180°,
when a turn stopped, whether the robot is still, tilt, and whether a point lies in a
rectangle; samples thinned for a plot. The probes feed them what the simulator reports."""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import List, Optional, Sequence, Tuple

from course_grader.answer_words import claims_success

Sample = Tuple[float, float]   # (simulated time s, yaw rad)


def yaw_of(x: float, y: float, z: float, w: float) -> float:
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


def tilt_degrees(x: float, y: float, z: float, w: float) -> float:
    """Angle between the body's z axis and the vertical."""
    cos_tilt = max(-1.0, min(1.0, 1.0 - 2.0 * (x * x + y * y)))
    return math.degrees(math.acos(cos_tilt))


def unwrap(previous: Optional[float], yaw: float) -> float:
    """``yaw`` shifted by whole turns to lie within half a turn of ``previous``."""
    if previous is None:
        return yaw
    return previous + math.remainder(yaw - previous, 2.0 * math.pi)


def inside(value: float, bounds: Sequence[float]) -> bool:
    return bounds[0] <= value <= bounds[1]


def distance_outside(x: float, y: float, bounds_x: Sequence[float],
                     bounds_y: Sequence[float]) -> float:
    """How far the point (x, y) is from the rectangle; 0 inside it."""
    dx = max(bounds_x[0] - x, 0.0, x - bounds_x[1])
    dy = max(bounds_y[0] - y, 0.0, y - bounds_y[1])
    return math.hypot(dx, dy)


def thin(samples: Sequence, most: int) -> List:
    """At most ``most`` of ``samples``, evenly spread by index, the first and the last kept
    (a plot needs no more points than it is wide)."""
    samples = list(samples)
    if most < 2:
        raise ValueError(f"cannot thin samples to {most} (at least 2)")
    if len(samples) <= most:
        return samples
    chosen = sorted({round(i * (len(samples) - 1) / (most - 1)) for i in range(most)})
    return [samples[i] for i in chosen]


def is_still(samples: List[Sample], window: float, speed: float) -> bool:
    """The yaw changed by less than ``speed`` x ``window`` over the last ``window`` seconds
    (and the samples span that long)."""
    if not samples or samples[-1][0] - samples[0][0] < window:
        return False
    end = samples[-1][0]
    recent = [yaw for t, yaw in samples if t >= end - window]
    return max(recent) - min(recent) <= speed * window


def stop_time(samples: List[Sample], band: float) -> float:
    """The first time from which the yaw stays within ``band`` (rad) of its last value."""
    final = samples[-1][1]
    stopped = samples[-1][0]
    for t, yaw in reversed(samples):
        if abs(yaw - final) > band:
            break
        stopped = t
    return stopped


@dataclass
class Rotation:
    """One /rotate_robot call as measured in ground truth."""

    requested: float          # degrees
    turned: float             # degrees, true yaw change (counter-clockwise positive)
    answer: str
    answered_at: float        # simulated s
    stopped_at: float         # simulated s, when the true yaw stopped changing

    def error(self) -> float:
        return self.turned - self.requested

    def turned_ok(self, tolerance: float) -> bool:
        return abs(self.error()) <= tolerance

    def says_success(self) -> bool:
        return claims_success(self.answer)

    def answered_when_done(self, lag: float, done_within: float) -> bool:
        """Success claimed once the turn was done: the robot turned within ``done_within``
        degrees of the request (how close is the other item's to score) and had stopped,
        or stopped no more than ``lag`` s after the answer."""
        return (self.says_success() and abs(self.error()) < done_within
                and self.answered_at >= self.stopped_at - lag)
