"""Differential-drive kinematics, shared by the diff-drive and skid-steer plugins.

Wheel speeds are angular (rad/s) about the wheel joints' axes, positive rolling forward;
``separation`` is the distance between the wheels' contact lines, ``radius`` half the
wheelDiameter. Pure maths: no pybullet, no ROS.
"""
from __future__ import annotations

import math
from typing import Tuple


def wheel_speeds(linear: float, angular: float, separation: float,
                 radius: float) -> Tuple[float, float]:
    """(left, right) wheel speeds for a body twist (v forward m/s, w counter-clockwise rad/s)."""
    left = (linear - angular * separation / 2.0) / radius
    right = (linear + angular * separation / 2.0) / radius
    return left, right


def body_twist(left: float, right: float, separation: float, radius: float) -> Tuple[float, float]:
    """(v, w) of the body from (left, right) wheel speeds: the inverse of wheel_speeds."""
    return (left + right) * radius / 2.0, (right - left) * radius / separation


def integrate(x: float, y: float, theta: float, linear: float, angular: float,
              dt: float) -> Tuple[float, float, float]:
    """Pose after moving with a constant twist for dt, exactly along the arc."""
    if abs(angular) < 1e-9:
        heading = theta + angular * dt / 2.0
        return x + linear * dt * math.cos(heading), y + linear * dt * math.sin(heading), \
            theta + angular * dt
    turn = angular * dt
    radius = linear / angular
    return (x + radius * (math.sin(theta + turn) - math.sin(theta)),
            y - radius * (math.cos(theta + turn) - math.cos(theta)),
            theta + turn)


def limit_change(current: float, target: float, max_change: float) -> float:
    """``target``, but at most ``max_change`` away from ``current`` (no limit when <= 0)."""
    if max_change <= 0:
        return target
    return current + max(-max_change, min(max_change, target - current))
