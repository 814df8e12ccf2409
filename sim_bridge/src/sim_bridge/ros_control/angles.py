"""The angle functions ros_controllers' PID position controllers compute their error with,
as ROS's ``angles`` package defines them (ros/angles, angles/include/angles/angles.h,
commit 0042845; Noetic's ros_controllers includes it as ``<angles/angles.h>``):

- :func:`normalize_angle` into (-pi, pi];
- :func:`shortest_angular_distance`: ``normalize_angle(to - from)``;
- :func:`two_pi_complement`: the same turn the other way round the circle;
- :func:`shortest_angular_distance_with_large_limits`: the shorter of the two turns that
  keeps ``from + turn`` within [left, right], limits that may lie beyond ±pi (a revolute
  joint with limits of ±2 pi): the shorter turn when neither or both do;
- :func:`shortest_angular_distance_with_limits`: the turn that stays within the valid arc
  [left, right] of the unit circle (DefaultRobotHWSim's position PID error for revolute
  joints), through :func:`find_min_max_delta`.

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


def find_min_max_delta(start: float, left: float, right: float):
    """angles::find_min_max_delta: (within, min_delta, max_delta), how far ``start`` may turn
    either way before the arc's ends, and whether it lies on the arc at all."""
    delta = [shortest_angular_distance(start, left), shortest_angular_distance(start, right)]
    delta += [two_pi_complement(delta[0]), two_pi_complement(delta[1])]
    if delta[0] == 0:
        return True, delta[0], max(delta[1], delta[3])
    if delta[1] == 0:
        return True, min(delta[0], delta[2]), delta[1]
    delta_min, delta_min_2pi = delta[0], delta[2]
    if delta[2] < delta_min:
        delta_min, delta_min_2pi = delta[2], delta[0]
    delta_max, delta_max_2pi = delta[1], delta[3]
    if delta[3] > delta_max:
        delta_max, delta_max_2pi = delta[3], delta[1]
    if delta_min <= delta_max_2pi or delta_max >= delta_min_2pi:
        return left == -math.pi and right == math.pi, delta_max_2pi, delta_min_2pi
    return True, delta_min, delta_max


def shortest_angular_distance_with_limits(start: float, end: float, left: float,
                                          right: float) -> float:
    """angles::shortest_angular_distance_with_limits(from, to, left, right, result): the turn
    it writes to ``result``: the shorter turn or its complement, whichever keeps within the
    arc; when ``end`` (or ``start``) lies off the arc, the turn toward the nearer end."""
    within, min_delta, max_delta = find_min_max_delta(start, left, right)
    delta = shortest_angular_distance(start, end)
    delta_mod_2pi = two_pi_complement(delta)
    if within:
        if min_delta <= delta <= max_delta:
            return delta
        if min_delta <= delta_mod_2pi <= max_delta:
            return delta_mod_2pi
        _, min_delta_to, max_delta_to = find_min_max_delta(end, left, right)
        if abs(min_delta_to) < abs(max_delta_to):
            return max(delta, delta_mod_2pi)
        if abs(min_delta_to) > abs(max_delta_to):
            return min(delta, delta_mod_2pi)
        return delta if abs(delta) < abs(delta_mod_2pi) else delta_mod_2pi
    if abs(min_delta) < abs(max_delta):
        return min(delta, delta_mod_2pi)
    if abs(min_delta) > abs(max_delta):
        return max(delta, delta_mod_2pi)
    return delta if abs(delta) < abs(delta_mod_2pi) else delta_mod_2pi
