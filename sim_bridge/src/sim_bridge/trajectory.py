"""Joint trajectories as ros_controllers' JointTrajectoryController samples them.

A trajectory starts from the joints' state when it is received and passes through its
points at their times. Each segment is interpolated per joint by what both its ends give:
positions only → linear; with velocities → cubic; with accelerations too → quintic.
Times are seconds of simulated time. Pure maths: no ROS, no pybullet.

The controller keeps, as Noetic's does, one list of :class:`Segment` per joint (ros_controllers
noetic-devel 678b92a joint_trajectory_controller/include/: joint_trajectory_controller/
joint_trajectory_segment.h, trajectory_interface/quintic_spline_segment.h ("qss"),
trajectory_interface/trajectory_interface.h ("ti")): a segment outside its time span gives
its nearer end's position with zero velocity and acceleration (qss:110-111, :393-407), and
the segment that holds a time is the last one starting at or before it (ti:70-76).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, List, Optional, Sequence, Tuple

import numpy as np


@dataclass
class Waypoint:
    time: float
    positions: np.ndarray
    velocities: Optional[np.ndarray] = None
    accelerations: Optional[np.ndarray] = None
    # the trajectory point's time_from_start, s (a state sampled from a trajectory: 0, as
    # trajectory_interface's PosVelAccState, pos_vel_acc_state.h:67)
    time_from_start: float = 0.0


def _segment(start: Waypoint, end: Waypoint, t: float) -> Tuple[np.ndarray, np.ndarray, np.ndarray]:
    duration = end.time - start.time
    if duration <= 0:
        zeros = np.zeros_like(end.positions)
        return end.positions.copy(), zeros, zeros
    s = min(max(t - start.time, 0.0), duration)
    p0, p1 = start.positions, end.positions
    if start.velocities is None or end.velocities is None:  # linear
        velocity = (p1 - p0) / duration
        return p0 + velocity * s, velocity, np.zeros_like(p0)
    v0, v1 = start.velocities, end.velocities
    if start.accelerations is None or end.accelerations is None:  # cubic
        a2 = (3 * (p1 - p0) - (2 * v0 + v1) * duration) / duration ** 2
        a3 = (2 * (p0 - p1) + (v0 + v1) * duration) / duration ** 3
        return (p0 + v0 * s + a2 * s ** 2 + a3 * s ** 3,
                v0 + 2 * a2 * s + 3 * a3 * s ** 2,
                2 * a2 + 6 * a3 * s)
    c0, c1 = start.accelerations, end.accelerations  # quintic
    T = duration
    b0, b1, b2 = p0, v0, c0 / 2
    b3 = (20 * (p1 - p0) - (8 * v1 + 12 * v0) * T - (3 * c0 - c1) * T ** 2) / (2 * T ** 3)
    b4 = (30 * (p0 - p1) + (14 * v1 + 16 * v0) * T + (3 * c0 - 2 * c1) * T ** 2) / (2 * T ** 4)
    b5 = (12 * (p1 - p0) - 6 * (v1 + v0) * T - (c0 - c1) * T ** 2) / (2 * T ** 5)
    return (b0 + b1 * s + b2 * s ** 2 + b3 * s ** 3 + b4 * s ** 4 + b5 * s ** 5,
            b1 + 2 * b2 * s + 3 * b3 * s ** 2 + 4 * b4 * s ** 3 + 5 * b5 * s ** 4,
            2 * b2 + 6 * b3 * s + 12 * b4 * s ** 2 + 20 * b5 * s ** 3)


class Trajectory:
    """Waypoints after a start state; ``sample(t)`` gives (positions, velocities, accelerations)."""

    def __init__(self, start: Waypoint, points: Sequence[Waypoint]):
        self.points: List[Waypoint] = [start] + [p for p in points if p.time >= start.time]
        # the start state takes the form of the first point (a linear first segment stays linear)
        if len(self.points) > 1:
            first = self.points[1]
            if first.velocities is None:
                start.velocities = None
            if first.accelerations is None:
                start.accelerations = None

    @property
    def end_time(self) -> float:
        return self.points[-1].time

    @property
    def goal(self) -> np.ndarray:
        return self.points[-1].positions

    def sample(self, t: float):
        if t >= self.end_time or len(self.points) == 1:
            last = self.points[-1]
            zeros = np.zeros_like(last.positions)
            return last.positions.copy(), zeros, zeros
        for start, end in zip(self.points, self.points[1:]):
            if t <= end.time:
                return _segment(start, end, t)
        raise AssertionError("unreachable: t is before the end time")


@dataclass(frozen=True)
class Tolerance:
    """StateTolerances (tolerances.h:53-67): 0 is not checked."""

    position: float = 0.0
    velocity: float = 0.0
    acceleration: float = 0.0

    def admits(self, position_error: float, velocity_error: float,
               acceleration_error: float = 0.0) -> bool:
        """checkStateTolerancePerJoint (tolerances.h:168-177)."""
        return not any(tolerance > 0.0 and abs(error) > tolerance for tolerance, error in (
            (self.position, position_error), (self.velocity, velocity_error),
            (self.acceleration, acceleration_error)))


NO_TOLERANCE = Tolerance()


@dataclass
class Segment:
    """One joint's stretch of a trajectory (JointTrajectorySegment): its two ends (scalars),
    the goal it belongs to (an action goal handle, or None) and that goal's tolerances for
    this joint: along the way (``path``), at the end (``goal``), and the time after the end
    the goal may take (``goal_time``)."""

    start: Waypoint
    end: Waypoint
    goal: Any = None
    path: Tolerance = NO_TOLERANCE
    goal_state: Tolerance = NO_TOLERANCE
    goal_time: float = 0.0

    @property
    def start_time(self) -> float:
        return self.start.time

    @property
    def end_time(self) -> float:
        return self.end.time

    def sample(self, t: float) -> Tuple[float, float, float]:
        """(position, velocity, acceleration) at ``t``; outside the span, the nearer end's
        position, still (qss:393-407)."""
        if t < self.start.time:
            return float(self.start.positions), 0.0, 0.0
        if t > self.end.time:
            return float(self.end.positions), 0.0, 0.0
        position, velocity, acceleration = _segment(self.start, self.end, t)
        return float(position), float(velocity), float(acceleration)


def find_segment(segments: Sequence[Segment], t: float) -> Optional[int]:
    """findSegment (ti:70-76): the index of the last segment starting at or before ``t``;
    None when ``t`` is before them all."""
    found = None
    for index, segment in enumerate(segments):
        if segment.start_time > t:
            break
        found = index
    return found


def sample_segments(segments: Sequence[Segment], t: float) -> Tuple[float, float, float]:
    """The state at ``t`` (trajectory_interface's sample: before every segment, the first
    one's start, still)."""
    index = find_segment(segments, t)
    return segments[0 if index is None else index].sample(t)
