"""The flip routine: drive back and forth along a line by flipping over, never turning.

Both wheels always get the same speed (``angular.z`` is always zero). The robot drives a
leg at ``speed``, then the command reverses sign at once: the wheels' sudden reversal
throws the body over its axle, it lands on its top caster and, because a pitch flip keeps
the axle where it was, the reversed wheels now drive it back the way it came, wheels
leading. Every leg ends in the next reversal and the next flip.

Settings are private parameters (``~speed``, ``~leg_time``, ``~rate``); what is not set
comes from the package's ``config/flip.yaml``, the one place the defaults live. The node
starts once the robot's odometry (``diff/odom``) arrives, and counts the flips it sees
there (the body's up axis changing sign) in its log.

The routine is a schedule in simulated time (:func:`schedule`): a command every ``1/rate``
s and one at each leg's exact start, each published when its time comes. A reversal is the
flip's whole cause, so it must not wait for the next periodic sample: a loop that samples
the clock at ``rate`` and asks which leg it is in reverses up to a whole period late (and
at random, as its samples drift against the legs' boundaries), and a late reversal can
fail to throw the robot over.
"""
from __future__ import annotations

import dataclasses
import math
import os
import sys
from dataclasses import dataclass, fields
from typing import Iterator, Mapping, Optional, Tuple

import rospkg
import rospy
import yaml
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from node_params import given_from, parameter, positive, read

SAME_INSTANT = 1e-9  # s: a tick and a leg's start closer than this are one command


@dataclass(frozen=True)
class FlipSettings:
    """How the routine drives: speed (m/s), leg_time (s), rate (Hz). No defaults here:
    they live in config/flip.yaml."""

    speed: float = parameter(dataclasses.MISSING, positive, expected="the wheels' ground speed, m/s > 0")
    leg_time: float = parameter(dataclasses.MISSING, positive, expected="seconds > 0 (simulated) of each leg")
    rate: float = parameter(dataclasses.MISSING, positive, expected="how often the command is published, Hz > 0")

    @classmethod
    def from_mapping(cls, values: Mapping[str, object], source: str) -> "FlipSettings":
        """Settings from ``values`` (names without ``~``); node_params.ParameterError (a
        ValueError) naming ``source`` and the setting when one is missing or is not a
        positive finite number."""
        return read(cls, values, prefix=f"{source}: ")


def load_defaults(path: str) -> dict:
    """The yaml of defaults as a dict (an empty or missing file: ValueError naming it)."""
    try:
        with open(path) as stream:
            values = yaml.safe_load(stream)
    except OSError as error:
        raise ValueError(f"{path}: cannot read the flip defaults: {error.strerror}") from None
    if not isinstance(values, dict):
        raise ValueError(f"{path}: expected a mapping of flip settings")
    return values


def packaged_settings_path() -> str:
    """The package's config/flip.yaml: the one place the defaults live."""
    return os.path.join(rospkg.RosPack().get_path("diff_drive"), "config", "flip.yaml")


def commanded_speed(settings: FlipSettings, elapsed: float) -> float:
    """The wheels' ground speed ``elapsed`` seconds into the routine: +speed on even legs,
    -speed on odd ones."""
    return leg_speed(settings, int(max(elapsed, 0.0) // settings.leg_time))


def leg_speed(settings: FlipSettings, leg: int) -> float:
    """The wheels' ground speed on leg number ``leg`` (0 first): +speed on even legs."""
    return settings.speed if leg % 2 == 0 else -settings.speed


def schedule(settings: FlipSettings) -> Iterator[Tuple[float, float]]:
    """The routine's commands, endless and in order, as (seconds into the routine, speed):
    one every ``1/rate`` s, and one at the exact start of every leg. Times are counted as
    multiples (tick / rate, leg * leg_time), never summed, so they do not drift; a tick
    that falls on a leg's start is that leg's command."""
    tick, leg = 0, 0
    while True:
        tick_time, leg_start = tick / settings.rate, leg * settings.leg_time
        if math.isclose(leg_start, tick_time, abs_tol=SAME_INSTANT):
            yield leg_start, leg_speed(settings, leg)
            tick, leg = tick + 1, leg + 1
        elif leg_start < tick_time:
            yield leg_start, leg_speed(settings, leg)
            leg += 1
        else:
            yield tick_time, leg_speed(settings, leg - 1)
            tick += 1


def up_axis_z(x: float, y: float, z: float, w: float) -> float:
    """The world z component of the body's z axis, from its orientation quaternion:
    positive upright, negative upside down."""
    return 1.0 - 2.0 * (x * x + y * y)


class FlipCounter:
    """Counts sign changes of the body's up axis (readings near zero, on edge, are skipped)."""

    def __init__(self, dead_band: float = 0.2):
        self.dead_band = dead_band
        self.flips = 0
        self._side: Optional[bool] = None

    def update(self, up_z: float) -> bool:
        """Takes one reading; True when it completes a flip."""
        if abs(up_z) < self.dead_band:
            return False
        side = up_z > 0
        flipped = self._side is not None and side != self._side
        self._side = side
        self.flips += flipped
        return flipped


class FlipNode:
    """Publishes the routine on ``diff/cmd_vel`` and counts flips on ``diff/odom``.
    Nothing here talks to the master before :meth:`run`."""

    def __init__(self, settings: FlipSettings):
        self.settings = settings
        self.counter = FlipCounter()
        self._odometry_seen = False

    def run(self) -> None:
        self._command = rospy.Publisher("diff/cmd_vel", Twist, queue_size=1)
        rospy.Subscriber("diff/odom", Odometry, self._on_odometry, queue_size=10)
        rospy.on_shutdown(self._stop)
        rospy.loginfo("flip: %.2f m/s legs of %.2f s, reversing at once, never turning",
                      self.settings.speed, self.settings.leg_time)
        rospy.loginfo("flip: waiting for the robot's odometry on %s",
                      rospy.resolve_name("diff/odom"))
        try:
            while not rospy.is_shutdown():
                self._wait_for_odometry()
                try:
                    self._drive()
                except rospy.exceptions.ROSTimeMovedBackwardsException:
                    rospy.loginfo("flip: the clock went back (world reset): starting again")
        except rospy.exceptions.ROSInterruptException:
            pass

    def _wait_for_odometry(self) -> None:
        """Returns once the robot's odometry has arrived (polled at the routine's rate)."""
        while not self._odometry_seen:
            rospy.sleep(1.0 / self.settings.rate)

    def _drive(self) -> None:
        """Publishes the schedule from now on, each command when its time comes (simulated
        time); ends only by an exception (shutdown, the clock going back)."""
        start = rospy.get_time()
        for elapsed, speed in schedule(self.settings):
            due = start + elapsed - rospy.get_time()
            if due > 0.0:
                rospy.sleep(due)
            twist = Twist()
            twist.linear.x = speed
            self._command.publish(twist)

    def _on_odometry(self, message: Odometry) -> None:
        self._odometry_seen = True
        q = message.pose.pose.orientation
        if self.counter.update(up_axis_z(q.x, q.y, q.z, q.w)):
            rospy.loginfo("flip: flipped over (%d so far)", self.counter.flips)

    def _stop(self) -> None:
        self._command.publish(Twist())


def main(argv=None) -> None:
    rospy.init_node("flip", argv=argv)
    try:
        path = packaged_settings_path()
        known = {field.name for field in fields(FlipSettings)}
        defaults = {name: value for name, value in load_defaults(path).items() if name in known}
        # a private parameter wins; what is unset comes from the yaml, named as its file's
        settings = read(FlipSettings, rospy.get_param, "~", defaults=given_from(defaults, path))
    except ValueError as error:
        rospy.logfatal("flip: %s", error)
        sys.exit(2)
    FlipNode(settings).run()
