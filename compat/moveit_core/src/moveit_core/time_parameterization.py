"""Time stamps for a path of joint positions as Noetic's MoveIt gives them: the default
request adapter ``AddTimeParameterization`` (moveit noetic-devel 7c0343f0,
moveit_ros/planning/planning_request_adapter_plugins/src/add_time_parameterization.cpp:68,80)
runs ``IterativeParabolicTimeParameterization`` with its defaults (100 iterations, 0.01 s of
change per iteration, iterative_time_parameterization.h:50), step for step as
moveit_core/trajectory_processing/src/iterative_time_parameterization.cpp ("iptp" below):

- each segment first takes the time its slowest joint needs at its speed limit times the
  velocity scaling factor (iptp:101-142, applyVelocityConstraints);
- then, per joint, a forward and a backward pass over the waypoints, repeated while a pass
  changed something and at most 100 times: a waypoint whose acceleration (the parabola
  through it and its neighbours; at the first and last waypoint the mirrored neighbour)
  exceeds the limit times the acceleration scaling factor by more than 0.01 (iptp's
  ROUNDING_THRESHOLD) has one segment lengthened, the one after it going forward and the one
  before it going backward, to the time ``findT1``/``findT2`` find by steps of 1 % but by at
  most 0.01 s per visit (iptp:298-456, 148-184);
- velocities and accelerations of the waypoints from the finite differences, zero speed at
  both ends (iptp:188-294, updateTrajectory).

So, as in Noetic, a path is not time-optimal and its accelerations may exceed a limit where
100 iterations did not suffice; what bounds it is that no segment grows by more than
0.01 s per visit. A joint without a speed or acceleration limit gets IPTP's 1 rad/s and
1 rad/s^2 (iptp:43-44). A first waypoint with a known velocity (``start_velocity``, as a
start state read from joint_states has) starts from it (iptp:277-285, 407-417). No ROS here.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import List, Optional, Sequence

import numpy as np

DEFAULT_VELOCITY = 1.0          # rad/s (m/s): iptp's DEFAULT_VEL_MAX, a joint without a limit
DEFAULT_ACCELERATION = 1.0      # rad/s^2: iptp's DEFAULT_ACCEL_MAX
ROUNDING_THRESHOLD = 0.01       # iptp:45: an acceleration this far beyond its limit is tolerated
MAX_ITERATIONS = 100            # iterative_time_parameterization.h:50, the adapter's default
MAX_TIME_CHANGE_PER_IT = 0.01   # s, the same line
MULT_FACTOR = 1.01              # iptp:151, 170: findT1/findT2's step


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
    (0, 1] mean 1 (iptp:113-122, 327-336)."""
    return float(value) if 0.0 < value <= 1.0 else 1.0


def time_path(positions: Sequence[Sequence[float]], max_velocity: Sequence[Optional[float]],
              max_acceleration: Sequence[Optional[float]], velocity_scaling: float = 1.0,
              acceleration_scaling: float = 1.0,
              start_velocity: Optional[Sequence[float]] = None) -> Timed:
    q = np.asarray(positions, dtype=float)
    if q.ndim != 2 or len(q) == 0 or not np.all(np.isfinite(q)):
        raise TimingError("a path needs at least one waypoint of finite positions")
    # the scaling factors scale a joint's own limits, not the defaults (iptp:131-135, 363-367)
    velocity = np.array([abs(v) * scaling(velocity_scaling) if v else DEFAULT_VELOCITY
                         for v in max_velocity], dtype=float)
    acceleration = np.array([abs(a) * scaling(acceleration_scaling) if a
                             else DEFAULT_ACCELERATION for a in max_acceleration], dtype=float)
    start = None if start_velocity is None else [float(v) for v in start_velocity]
    count = len(q)
    if count == 1:
        zeros = np.zeros_like(q)
        return Timed(np.zeros(1), q, zeros, zeros.copy())
    # iptp:121-136: each segment as long as its slowest joint needs
    dt = np.max(np.abs(np.diff(q, axis=0)) / velocity, axis=1).tolist()
    _apply_acceleration_limits(q.T.tolist(), dt, acceleration.tolist(), start)
    return _timed(q, np.asarray(dt), start)


def _visit_time(dq1: float, dq2: float, dt1: float, dt2: float, a_max: float,
                first: bool) -> float:
    """The segment's new time at one visit: iptp's findT1 (``first``: dt1 grows) or findT2
    (dt2 grows), the time times 1.01 until the acceleration is within ``a_max``, and once
    more (the loop's last step, iptp:156-162, 175-181), kept to at most 0.01 s more than it
    was (iptp:426, :431). The steps stop once past that, which changes nothing kept."""
    def accel(t1, t2):
        return 2.0 * (dq2 / t2 - dq1 / t1) / (t1 + t2)
    cap = (dt1 if first else dt2) + MAX_TIME_CHANGE_PER_IT
    a = accel(dt1, dt2)
    while abs(a) > a_max:
        a = accel(dt1, dt2)
        if first:
            dt1 *= MULT_FACTOR
        else:
            dt2 *= MULT_FACTOR
        if (dt1 if first else dt2) > cap:
            break
    return min(cap, dt1 if first else dt2)


def _apply_acceleration_limits(q: List[List[float]], dt: List[float], a_max: List[float],
                               start: Optional[List[float]]) -> None:
    """iptp:298-456 (applyAccelerationConstraints) on ``dt`` in place; ``q`` joint-major."""
    count = len(q[0])
    backwards = False
    for _ in range(MAX_ITERATIONS):
        updates = 0
        for j, qj in enumerate(q):
            limit = a_max[j] + ROUNDING_THRESHOLD
            for _pass in range(2):
                for i in range(count - 1):
                    index = count - 1 - i if backwards else i
                    if index == 0:
                        q1, q2, q3 = qj[1], qj[0], qj[1]
                        dt1 = dt2 = dt[0]
                    elif index < count - 1:
                        q1, q2, q3 = qj[index - 1], qj[index], qj[index + 1]
                        dt1, dt2 = dt[index - 1], dt[index]
                    else:
                        q1, q2, q3 = qj[index - 1], qj[index], qj[index - 1]
                        dt1 = dt2 = dt[index - 1]
                    if dt1 == 0.0 or dt2 == 0.0:
                        continue            # iptp:400-405: a = 0
                    v1 = start[j] if index == 0 and start is not None else (q2 - q1) / dt1
                    a = 2.0 * ((q3 - q2) / dt2 - v1) / (dt1 + dt2)
                    if abs(a) <= limit:
                        continue
                    # findT1/findT2 take their v1 from the positions, not the start velocity
                    if backwards:
                        dt[index - 1] = _visit_time(q2 - q1, q3 - q2, dt1, dt2, a_max[j], True)
                    else:
                        dt[index] = _visit_time(q2 - q1, q3 - q2, dt1, dt2, a_max[j], False)
                    updates += 1
                backwards = not backwards
        if updates == 0:
            break


def _timed(q: np.ndarray, dt: np.ndarray, start: Optional[List[float]]) -> Timed:
    """iptp:188-294 (updateTrajectory): times, and each waypoint's velocity (the mean of the
    segments either side; zero at the ends, whose mirrored neighbour is the one they have)
    and acceleration."""
    count = len(q)
    times = np.concatenate([[0.0], np.cumsum(dt)])
    velocities = np.zeros_like(q)
    accelerations = np.zeros_like(q)
    for i in range(count):
        if i == 0:
            q1, q2, q3, dt1, dt2 = q[1], q[0], q[1], dt[0], dt[0]
        elif i < count - 1:
            q1, q2, q3, dt1, dt2 = q[i - 1], q[i], q[i + 1], dt[i - 1], dt[i]
        else:
            q1, q2, q3, dt1, dt2 = q[i - 1], q[i], q[i - 1], dt[i - 1], dt[i - 1]
        if dt1 == 0.0 or dt2 == 0.0:
            continue
        if i == 0 and start is not None:
            v1 = v2 = np.asarray(start)     # iptp:284-286
        else:
            v1, v2 = (q2 - q1) / dt1, (q3 - q2) / dt2
        velocities[i] = (v1 + v2) / 2.0
        accelerations[i] = 2.0 * (v2 - v1) / (dt1 + dt2)
    return Timed(times, q, velocities, accelerations)


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
