"""turtle_teleop_key's keys as pure logic: a byte read from the terminal, and what the node
publishes for it. No terminal, no ROS.

As turtlesim 0.10.2's tutorials/teleop_turtle_key.cpp (ros/ros_tutorials noetic-devel,
db63288): the terminal is read one byte at a time (:47-54, :219), so an arrow key's escape
sequence (ESC [ A) counts by its last byte; ESC and [ do nothing, and the capital letters A
to D typed alone drive as the arrows do. Each byte starts from a stopped command (:227), so
a published Twist is either a drive or a turn, never both.
"""
from __future__ import annotations

from typing import Optional, Tuple

# the last byte of the arrow keys' escape sequences (teleop_turtle_key.cpp:12-15)
RIGHT, LEFT, UP, DOWN = 0x43, 0x44, 0x41, 0x42
QUIT = 0x71  # 'q' (:22, :252-254)
# byte -> (linear, angular) before scaling (:232-251)
MOVES = {UP: (1.0, 0.0), DOWN: (-1.0, 0.0), LEFT: (0.0, 1.0), RIGHT: (0.0, -1.0)}
# scale_linear and scale_angular when the parameters are not set (:172-173)
DEFAULT_SCALE = 2.0
# what the node prints before it reads (:209-211)
HELP = ("Reading from keyboard\n"
        "---------------------------\n"
        "Use arrow keys to move the turtle. 'q' to quit.")


def command(key: int, scale_linear: float = DEFAULT_SCALE,
            scale_angular: float = DEFAULT_SCALE) -> Optional[Tuple[float, float]]:
    """(linear.x, angular.z) to publish for the byte ``key``, or None: nothing is published
    for any other byte (:258-265)."""
    if key not in MOVES:
        return None
    linear, angular = MOVES[key]
    return scale_linear * linear, scale_angular * angular
