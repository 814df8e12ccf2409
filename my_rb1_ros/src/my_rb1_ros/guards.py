"""What ends a rotation when its measurements stop making sense, without ROS.

A rotation is measured on odometry and paced by simulated time; both can misbehave in ways
a closed loop cannot see by itself:

- physics paused, or the simulator gone: simulated time stops, so a timeout in simulated
  time never fires. :class:`ClockWatch` and :class:`OdometryWatch` bound that in
  wall-clock time.
- a simulation reset or restart: time goes backwards (Gazebo's reset_simulation, a new
  simulator's /clock from 0), and the robot is teleported back to where it was spawned.
  :class:`ClockWatch` and :class:`JumpDetector` name both, so the teleport is not counted
  as turning.
- odometry stopping while time runs: :class:`OdometryWatch`.
- a robot that is commanded but gets no closer to its goal (blocked, or turning the wrong
  way): :class:`StallWatch`, in simulated time.

A check that trips raises :class:`GuardTripped` or returns a text; either way the text is
the cause, written for the service's answer.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable, Optional


class GuardTripped(Exception):
    """A rotation must end; the text names why."""


def time_moved_backwards(before: float, after: float, what: str) -> str:
    """The cause for ``what`` going back from ``before`` to ``after`` (seconds)."""
    return (f"{what} moved backwards by {before - after:.3f} s (from {before:.3f} to "
            f"{after:.3f} s): the simulation was reset or restarted")


def paused_cause(seconds: float, limit: float) -> str:
    """The cause when simulated time stood still for ``seconds`` of wall-clock time."""
    return (f"simulated time has not advanced for {seconds:.1f} s of wall-clock time (limit "
            f"{limit:g} s): physics paused, or the simulator stopped")


class ClockWatch:
    """Watches simulated time against the wall clock during one rotation.

    ``check()`` returns the simulated time, or raises :class:`GuardTripped` when it went
    backwards, or when it has not advanced for ``stall_timeout`` wall seconds (paused
    physics: the simulator keeps repeating the same /clock; a dead simulator: none).
    """

    def __init__(self, sim_now: Callable[[], float], wall_now: Callable[[], float],
                 stall_timeout: float):
        self._sim_now, self._wall_now = sim_now, wall_now
        self.stall_timeout = stall_timeout
        self._last_sim = sim_now()
        self._advanced_at = wall_now()

    def check(self) -> float:
        sim, wall = self._sim_now(), self._wall_now()
        if sim < self._last_sim:
            raise GuardTripped(time_moved_backwards(self._last_sim, sim, "simulated time"))
        if sim > self._last_sim:
            self._last_sim, self._advanced_at = sim, wall
        elif wall - self._advanced_at > self.stall_timeout:
            raise GuardTripped(paused_cause(wall - self._advanced_at, self.stall_timeout))
        return sim


# Odometry is missing, not merely late, once simulated time has passed this many of its
# periods since the last message; before that, silence means that time itself stood still.
MISSED_PERIODS = 2


class OdometryWatch:
    """When odometry last arrived (wall clock), its stamp and period (simulated time);
    says whether it is fresh, and why not."""

    def __init__(self, timeout: float, topic: str):
        self.timeout, self.topic = timeout, topic
        self.last_wall: Optional[float] = None
        self.last_stamp: Optional[float] = None
        self.period: Optional[float] = None

    def received(self, stamp: float, wall: float) -> None:
        if self.last_stamp is not None and stamp > self.last_stamp:
            self.period = stamp - self.last_stamp
        self.last_stamp, self.last_wall = stamp, wall

    def fresh(self, wall_now: float) -> bool:
        return self.last_wall is not None and wall_now - self.last_wall <= self.timeout

    def check(self, wall_now: float, sim_now: float, waiting_since: float) -> Optional[str]:
        """``None`` while odometry is fresh or the wait (begun at wall ``waiting_since``)
        is shorter than the timeout; otherwise the cause: paused physics when simulated
        time has not passed the next messages' stamps, no odometry when it has."""
        if self.last_wall is None:
            if wall_now - waiting_since > self.timeout:
                return (f"no odometry on {self.topic} within {self.timeout:g} s "
                        f"(none received)")
            return None
        silent = wall_now - max(self.last_wall, waiting_since)
        if silent <= self.timeout:
            return None
        if self.period is not None and sim_now <= self.last_stamp + MISSED_PERIODS * self.period:
            return paused_cause(silent, self.timeout)
        return (f"no odometry on {self.topic} for {silent:.1f} s of wall-clock time "
                f"(limit {self.timeout:g} s) while simulated time runs")


@dataclass
class MotionLimits:
    """How fast the robot can really move (rad/s, m/s), and what a single odometry message
    may add to that for noise and rounding (rad, m)."""

    angular_speed: float
    linear_speed: float
    angle_margin: float
    distance_margin: float


@dataclass
class OdometrySample:
    """One odometry message: its stamp (s, simulated), position (m) and heading (rad)."""

    stamp: float
    x: float
    y: float
    yaw: float


class JumpDetector:
    """Compares each odometry sample with the one before it. A heading or position that
    changed faster than the robot can move, or a stamp earlier than the one before, is not
    motion: it is a reset, a restart or a teleport, and ``check`` returns its description
    (``None`` for ordinary motion)."""

    def __init__(self, limits: MotionLimits):
        self.limits = limits
        self._last: Optional[OdometrySample] = None

    def check(self, sample: OdometrySample) -> Optional[str]:
        last, self._last = self._last, sample
        if last is None:
            return None
        elapsed = sample.stamp - last.stamp
        if elapsed < 0:
            return time_moved_backwards(last.stamp, sample.stamp, "odometry's time stamp")
        limits = self.limits
        # the shorter way round: a heading seen twice across the +-pi seam is no jump
        turn = abs(math.atan2(math.sin(sample.yaw - last.yaw), math.cos(sample.yaw - last.yaw)))
        most_turn = limits.angular_speed * elapsed + limits.angle_margin
        if turn > most_turn:
            return (f"odometry jumped: the heading changed by {math.degrees(turn):.1f} degrees "
                    f"in {elapsed:.3f} s, more than the robot can turn "
                    f"({math.degrees(most_turn):.1f} degrees): a simulation reset, or the "
                    f"robot was moved")
        moved = math.hypot(sample.x - last.x, sample.y - last.y)
        most_moved = limits.linear_speed * elapsed + limits.distance_margin
        if moved > most_moved:
            return (f"odometry jumped: the position moved {moved:.3f} m in {elapsed:.3f} s, "
                    f"more than the robot can drive ({most_moved:.3f} m): a simulation "
                    f"reset, or the robot was moved")
        return None


class StallWatch:
    """Whether a commanded turn gets anywhere, in simulated time.

    Progress is the remaining angle shrinking by ``step`` (rad) below where it stood when
    progress was last counted; none for more than ``seconds`` is a stall. Progress is
    measured towards the goal, not as motion: turning back after an overshoot is progress,
    turning away is not. Within ``step`` of the goal, progress is reaching it: the rotation
    then stops the robot to settle, and calls :meth:`restart` if it must turn again, so the
    time the robot stood still on purpose never counts as stalling.
    """

    def __init__(self, step: float, seconds: float):
        self.step, self.seconds = step, seconds
        self._mark: Optional[float] = None  # rad left when progress was last counted
        self._since = 0.0  # simulated s, when it was

    def restart(self) -> None:
        """The next :meth:`check` counts from where the robot stands then."""
        self._mark = None

    def check(self, remaining: float, now: float) -> Optional[str]:
        """``None`` while the turn makes progress; the cause once it has made none for
        longer than ``seconds``. ``remaining``: the angle still to turn (rad, either sign),
        ``now``: simulated time (s)."""
        remaining = abs(remaining)
        if self._mark is None or remaining <= self._mark - self.step:
            self._mark, self._since = remaining, now
            return None
        if now - self._since <= self.seconds:
            return None
        if remaining >= self._mark + self.step:
            return ("the robot turns away from the goal (cmd_vel's or odometry's sign "
                    "reversed?)")
        return "the robot does not turn (blocked?)"
