"""Time stamps for a path of joint positions, as MoveIt's default request adapter
(AddTimeParameterization: iterative parabolic time parameterization) gives them: every
joint's speed within its limit times the velocity scaling factor, every acceleration within
its limit times the acceleration scaling factor, at rest at both ends.

Each segment first gets the time of the fastest motion along the path its limits allow
(accelerating from rest and braking to rest at the limits, corners taken slowly enough for
their change of direction); then, as IPTP does, pass after pass, a waypoint whose
acceleration (from the parabola through it and its neighbours) exceeds a limit has its two
segments stretched, until none does.
Velocities and accelerations of the waypoints are the finite differences. A joint without
a speed or acceleration limit gets MoveIt's 1 rad/s and 1 rad/s^2. No ROS here.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import List, Optional, Sequence

import numpy as np

DEFAULT_VELOCITY = 1.0          # rad/s (m/s): MoveIt's for a joint without a limit
DEFAULT_ACCELERATION = 1.0      # rad/s^2
MAX_PASSES = 1000               # stretching passes; each makes progress or ends the loop
STRETCH = 1.01                  # a stretched segment is this much longer than needed


class TimingError(ValueError):
    """A path that cannot be timed (not finite, or no limits); the message says why."""


@dataclass
class Timed:
    times: np.ndarray             # s from the start, one per waypoint
    positions: np.ndarray         # waypoints x joints
    velocities: np.ndarray
    accelerations: np.ndarray


def scaling(value: float) -> float:
    """A scaling factor as MoveIt's adapter reads it: 0 (unset) and anything outside
    (0, 1] mean 1."""
    return float(value) if 0.0 < value <= 1.0 else 1.0


def time_path(positions: Sequence[Sequence[float]], max_velocity: Sequence[Optional[float]],
              max_acceleration: Sequence[Optional[float]], velocity_scaling: float = 1.0,
              acceleration_scaling: float = 1.0) -> Timed:
    q = np.asarray(positions, dtype=float)
    if q.ndim != 2 or len(q) == 0 or not np.all(np.isfinite(q)):
        raise TimingError("a path needs at least one waypoint of finite positions")
    velocity = np.array([v if v and v > 0 else DEFAULT_VELOCITY for v in max_velocity])
    velocity = velocity * scaling(velocity_scaling)
    acceleration = np.array([a if a and a > 0 else DEFAULT_ACCELERATION
                             for a in max_acceleration]) * scaling(acceleration_scaling)
    count = len(q)
    if count == 1:
        zeros = np.zeros_like(q)
        return Timed(np.zeros(1), q, zeros, zeros.copy())
    delta = np.diff(q, axis=0)
    dt = _ramped(delta, velocity, acceleration)
    for _ in range(MAX_PASSES):
        stretched = False
        for i in range(count):
            before = dt[i - 1] if i > 0 else None
            after = dt[i] if i < count - 1 else None
            v_in = delta[i - 1] / before if before else np.zeros(q.shape[1])
            v_out = delta[i] / after if after else np.zeros(q.shape[1])
            span = (before or 0.0) + (after or 0.0)
            needed = np.max(np.abs(v_out - v_in) / acceleration) * 2.0 / span
            if needed > 1.0 + 1e-9:
                # accelerations scale as 1/t^2: stretch both neighbours by sqrt of the excess
                factor = np.sqrt(needed) * STRETCH
                if before:
                    dt[i - 1] *= factor
                if after:
                    dt[i] *= factor
                stretched = True
        if not stretched:
            break
    times = np.concatenate([[0.0], np.cumsum(dt)])
    velocities = np.zeros_like(q)
    accelerations = np.zeros_like(q)
    for i in range(1, count - 1):
        v_in, v_out = delta[i - 1] / dt[i - 1], delta[i] / dt[i]
        velocities[i] = (v_in + v_out) / 2.0
        accelerations[i] = (v_out - v_in) * 2.0 / (dt[i - 1] + dt[i])
    accelerations[0] = delta[0] / dt[0] * 2.0 / dt[0]
    accelerations[-1] = -delta[-1] / dt[-1] * 2.0 / dt[-1]
    return Timed(times, q, velocities, accelerations)


def _ramped(delta: np.ndarray, velocity: np.ndarray, acceleration: np.ndarray) -> np.ndarray:
    """Segment durations of the path at the most speed its limits allow, accelerating and
    braking at the limits along the path (forward and backward passes over the speed
    along the path, a corner taken as slowly as its joints' change of direction needs):
    the start the passes below refine, so that a long path ramps up and down instead of
    crawling at the speed its first segment may reach from rest."""
    lengths = np.linalg.norm(delta, axis=1)
    moving = lengths > 1e-12
    unit = np.zeros_like(delta)
    unit[moving] = delta[moving] / lengths[moving, None]
    with np.errstate(divide="ignore"):
        top = np.min(np.where(np.abs(unit) > 1e-12, velocity / np.abs(unit), np.inf), axis=1)
        push = np.min(np.where(np.abs(unit) > 1e-12, acceleration / np.abs(unit), np.inf),
                      axis=1)
    count = len(delta) + 1
    speed = np.full(count, np.inf)
    speed[0] = speed[-1] = 0.0
    for i in range(1, count - 1):
        turn = np.abs(unit[i] - unit[i - 1])
        reach = min(lengths[i - 1], lengths[i])
        with np.errstate(divide="ignore"):
            corner = np.min(np.where(turn > 1e-12, np.sqrt(acceleration * reach / turn), np.inf))
        speed[i] = min(top[i - 1], top[i], corner)
    for i in np.flatnonzero(moving):            # accelerating forward
        speed[i + 1] = min(speed[i + 1], math.sqrt(speed[i] ** 2 + 2 * push[i] * lengths[i]))
    for i in reversed(np.flatnonzero(moving)):  # braking backward
        speed[i] = min(speed[i], math.sqrt(speed[i + 1] ** 2 + 2 * push[i] * lengths[i]))
    dt = np.zeros(len(delta))
    for i in np.flatnonzero(moving):
        dt[i] = _segment_time(lengths[i], speed[i], speed[i + 1], top[i], push[i])
    # and never faster than the slowest joint's full speed over the segment
    return np.maximum(np.maximum(dt, np.max(np.abs(delta) / velocity, axis=1)), 1e-6)


def _segment_time(length: float, start: float, end: float, top: float, push: float) -> float:
    """The time over ``length`` from speed ``start`` to ``end``, accelerating at ``push``
    up to at most ``top`` and braking again (a trapezoid, or a triangle when the segment
    is too short for full speed). The passes above made the end speeds reachable; a
    segment from rest to rest (a two-point path) is the whole profile."""
    peak = min(top, math.sqrt(push * length + (start ** 2 + end ** 2) / 2))
    peak = max(peak, start, end)
    ramps = (peak ** 2 - start ** 2 + peak ** 2 - end ** 2) / (2 * push)
    cruise = max(length - ramps, 0.0)
    return (peak - start) / push + (peak - end) / push + (cruise / peak if peak > 0 else 0.0)


def limits_of(model, joints: Sequence[str]):
    """The joints' speed and acceleration limits in the model's bounds (None: unlimited)."""
    return ([model.bounds[j].max_velocity for j in joints],
            [model.bounds[j].max_acceleration for j in joints])


def joint_trajectory(timed: Timed, joints: List[str]):
    """A trajectory_msgs/JointTrajectory of the timed path."""
    import rospy
    from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint
    message = JointTrajectory(joint_names=list(joints))
    for t, p, v, a in zip(timed.times, timed.positions, timed.velocities, timed.accelerations):
        message.points.append(JointTrajectoryPoint(
            positions=p.tolist(), velocities=v.tolist(), accelerations=a.tolist(),
            time_from_start=rospy.Duration.from_sec(float(t))))
    return message
