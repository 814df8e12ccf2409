"""The angle functions ros_controllers' PID position controllers compute their error with,
as ROS's ``angles`` package defines them (ros/angles, angles/include/angles/angles.h,
commit 0042845; Noetic's ros_controllers includes it as ``<angles/angles.h>``):

- :func:`normalize_angle` into (-pi, pi];
- :func:`shortest_angular_distance`: ``normalize_angle(to - from)``;
- :func:`two_pi_complement`: the same turn the other way round the circle;
- :func:`shortest_angular_distance_with_large_limits`: the shorter of the two turns that
  keeps ``from + turn`` within [left, right], limits that may lie beyond ±pi (a revolute
  joint with limits of ±2 pi): the shorter turn when neither or both do.

Scalars only; the trajectory controller has its own vectorised shortest distance.
"""
from __future__ import annotations

import math

TWO_PI = 2.0 * math.pi


def normalize_angle(angle: float) -> float:
    """angles::normalize_angle: the same angle in (-pi, pi] (fmod, then shifted)."""
    result = math.fmod(angle + math.pi, TWO_PI)
    return result + math.pi if result <= 0.0 else result - math.pi


def shortest_angular_distance(start: float, end: float) -> float:
    """angles::shortest_angular_distance(from, to)."""
    return normalize_angle(end - start)


def two_pi_complement(angle: float) -> float:
    """angles::two_pi_complement: ``angle`` (within ±2 pi) turned the other way round."""
    if angle > TWO_PI or angle < -TWO_PI:
        angle = math.fmod(angle, TWO_PI)
    if angle < 0.0:
        return TWO_PI + angle
    if angle > 0.0:
        return -TWO_PI + angle
    return TWO_PI


def shortest_angular_distance_with_large_limits(start: float, end: float, left: float,
                                                right: float) -> float:
    """angles::shortest_angular_distance_with_large_limits(from, to, left, right, result):
    the turn it writes to ``result`` (its boolean, whether ``start`` was within the limits,
    is not used by the controllers)."""
    delta = shortest_angular_distance(start, end)
    other = two_pi_complement(delta)
    if abs(delta) > abs(other):  # try the shorter turn first
        delta, other = other, delta
    if left > right:
        return delta
    for turn in (delta, other):
        if left <= start + turn <= right:
            return turn
    return delta
