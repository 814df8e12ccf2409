"""The teleop node: reads keys from the terminal, publishes ``cmd_vel`` (remap it to drive
another topic). The terminal goes to raw mode for single key presses and is restored on
exit, also after Ctrl-C or an error. Private parameters: ``~speed`` (0.5 m/s), ``~turn``
(1.0 rad/s), ``~repeat_rate`` (10 Hz: the command is republished this often)."""
from __future__ import annotations

import os
import select
import sys
import termios
import tty

from dataclasses import dataclass

import rospy
from geometry_msgs.msg import Twist
from node_params import ParameterError, parameter, positive, read

from keyboard_teleop.keys import HELP, Teleop

CTRL_C = "\x03"


@dataclass(frozen=True)
class TeleopSettings:
    """The private parameters, read with node_params (a bad one stops the node, named)."""

    speed: float = parameter(0.5, positive, expected="the starting linear speed, m/s > 0")
    turn: float = parameter(1.0, positive, expected="the starting turning speed, rad/s > 0")
    repeat_rate: float = parameter(
        10.0, positive, expected="how often the command is republished, Hz > 0")


def read_key(stream, timeout: float) -> str:
    """One key, or "" after ``timeout`` seconds. Read from the descriptor, not through
    Python's buffered stream: keys typed together (``k`` then Ctrl-C) would otherwise wait
    in the stream's buffer while select() sees nothing more to read."""
    ready, _, _ = select.select([stream], [], [], timeout)
    return os.read(stream.fileno(), 1).decode("utf-8", "replace") if ready else ""


def main() -> None:
    rospy.init_node("teleop_twist_keyboard")
    try:
        settings = read(TeleopSettings)
    except ParameterError as error:
        rospy.logfatal("teleop_twist_keyboard: %s", error)
        sys.exit(1)
    teleop = Teleop(settings.speed, settings.turn)
    period = 1.0 / settings.repeat_rate
    publisher = rospy.Publisher("cmd_vel", Twist, queue_size=1)
    stdin = sys.stdin
    if not stdin.isatty():
        sys.exit("teleop_twist_keyboard: needs a terminal (run it with rosrun, or launch-prefix='xterm -e')")
    saved = termios.tcgetattr(stdin)

    def publish():
        twist = Twist()
        twist.linear.x, twist.angular.z = teleop.command
        publisher.publish(twist)

    print(HELP)
    print(teleop.status(), flush=True)
    try:
        tty.setraw(stdin.fileno())
        while not rospy.is_shutdown():
            key = read_key(stdin, period)
            if key == CTRL_C:
                break
            if key:
                teleop.press(key)
                sys.stdout.write("\r" + teleop.status() + "\r\n")
                sys.stdout.flush()
            publish()
    finally:
        teleop.press("k")
        publish()
        termios.tcsetattr(stdin, termios.TCSADRAIN, saved)
        print("teleop_twist_keyboard: stopped; terminal restored", flush=True)
