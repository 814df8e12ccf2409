"""``rosrun turtlesim turtle_teleop_key``: the arrow keys drive turtle1.

As turtlesim 0.10.2's tutorials/teleop_turtle_key.cpp (ros/ros_tutorials noetic-devel,
db63288): node ``teleop_turtle`` (:192), publishing geometry_msgs/Twist on
``turtle1/cmd_vel`` with a queue of 1 (:178), only when an arrow key is pressed (:261-265);
``scale_linear`` and ``scale_angular`` (default 2.0) are read relative to the node's
namespace, not as private parameters (:175-176: a public node handle), so
``_scale_linear:=`` does not reach them and ``rosparam set /scale_linear 1`` does. The
terminal stops echoing and waits for no Enter (:36-44); ``q`` or Ctrl-C quits and gives the
terminal back (:181-187, :252-254). Input that is not a terminal (a pipe) is read as it is;
at its end the node quits (upstream reads the last byte again and again).
"""
from __future__ import annotations

import os
import select
import sys
import termios

import rospy
from geometry_msgs.msg import Twist
from node_params import ParameterError, convert

from turtle_world.teleop_keys import DEFAULT_SCALE, HELP, QUIT, command

# s: how long a wait for a key lasts before the node looks whether it should stop
KEY_POLL = 0.1


def read_scale(name: str) -> float:
    """One scale parameter; a value that is not a number is named and replaced by the
    default (upstream's param() keeps the default silently)."""
    try:
        return convert(float, rospy.get_param(name, DEFAULT_SCALE), name,
                       "a number (the key's speed is 1 times this)")
    except ParameterError as error:
        rospy.logwarn("%s; using %s", error, DEFAULT_SCALE)
        return DEFAULT_SCALE


def key_mode(settings: list) -> list:
    """The terminal settings for single key presses: no line editing, no echo; Ctrl-C still
    interrupts (teleop_turtle_key.cpp:36-44)."""
    raw = [list(item) if isinstance(item, list) else item for item in settings]
    raw[3] &= ~(termios.ICANON | termios.ECHO)
    raw[6][termios.VMIN] = 1
    raw[6][termios.VTIME] = 0
    return raw


def main() -> int:
    rospy.init_node("teleop_turtle")
    scale_linear, scale_angular = read_scale("scale_linear"), read_scale("scale_angular")
    publisher = rospy.Publisher("turtle1/cmd_vel", Twist, queue_size=1)
    stdin = sys.stdin.fileno()
    saved = termios.tcgetattr(stdin) if os.isatty(stdin) else None
    print(HELP, flush=True)
    try:
        if saved is not None:
            termios.tcsetattr(stdin, termios.TCSANOW, key_mode(saved))
        while not rospy.is_shutdown():
            ready, _, _ = select.select([stdin], [], [], KEY_POLL)
            if not ready:
                continue
            data = os.read(stdin, 1)
            if not data or data[0] == QUIT:  # the end of the input, or q
                break
            move = command(data[0], scale_linear, scale_angular)
            if move is not None:
                twist = Twist()
                twist.linear.x, twist.angular.z = move
                publisher.publish(twist)
    finally:
        if saved is not None:
            termios.tcsetattr(stdin, termios.TCSANOW, saved)
    return 0
