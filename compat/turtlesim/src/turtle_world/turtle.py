"""One turtle's motion and pen, step for step as turtlesim 0.10.2 moves and draws it: pure
logic, no Qt and no ROS (unit-testable).

Upstream citations are ros/ros_tutorials noetic-devel (commit db63288), folder turtlesim/.

Coordinates are the canvas frame that turtlesim keeps inside: metres from the window's top
left corner, x to the right, y DOWN (so a heading turns counter-clockwise on the screen
while y shrinks). The published Pose has y up: ``y_up = canvas_height - y``
(turtle.cpp:177-178). One metre is 45 pixels (the height of upstream's turtle images,
turtle_frame.cpp:101).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import List, Optional, Tuple

# turtle.h:51: turtlesim's own pi (3.6e-9 short of math.pi), which the heading wrap uses:
# headings stay within [-PI, PI) of this PI
PI = 3.14159265
# a command older than this (wall clock, s) stops the turtle (turtle.cpp:148-153)
COMMAND_TIMEOUT = 1.0
# what Turtle.update warns when it clamps (turtle.cpp:169): the canvas-frame position
WALL_WARNING = "Oh no! I hit the wall! (Clamping from [x=%f, y=%f])"
# the width of a new QPen(QColor) in Qt 5: set_pen with width 0 leaves it there
# (turtle.cpp:83-87 set only a non-zero width)
NEW_PEN_WIDTH = 1

Point = Tuple[float, float]


@dataclass(frozen=True)
class Pen:
    """A pen colour (0..255 each) and width in pixels."""

    r: int
    g: int
    b: int
    width: int


# turtle.cpp:35-37 (0xb3, 0xb8, 0xff) and :51-53 (width 3)
DEFAULT_PEN = Pen(0xB3, 0xB8, 0xFF, 3)


@dataclass(frozen=True)
class Segment:
    """A line the pen draws: from ``start`` (where the turtle is now) to ``end`` (where it
    was), canvas metres (turtle.cpp:141, :206 draw in that order)."""

    pen: Pen
    start: Point
    end: Point


@dataclass(frozen=True)
class Step:
    """What one update did, in the order upstream does it: the teleports' lines are drawn,
    the colour is read at ``sensor`` (canvas metres), then ``motion_line`` is drawn
    (turtle.cpp:138-142, :185-192, :201-209)."""

    teleport_lines: Tuple[Segment, ...]
    motion_line: Optional[Segment]
    # the Pose to publish: x, y (up), theta, linear_velocity, angular_velocity
    pose: Tuple[float, float, float, float, float]
    sensor: Point
    # the canvas-frame position before clamping, when the turtle hit the wall
    clamped_from: Optional[Point]
    # the picture changed: the window is repainted (turtle.cpp:196-211)
    modified: bool


@dataclass(frozen=True)
class Teleport:
    """A queued teleport (turtle.h:96-111): absolute (x, y up, theta) or relative (turn
    by ``theta``, then ``linear`` metres along the new heading)."""

    x: float
    y: float
    theta: float
    linear: float
    relative: bool


def wrap(orient: float) -> float:
    """The heading kept within [-PI, PI), as turtle.cpp:158-159 keeps it."""
    return orient - 2 * PI * math.floor((orient + PI) / (2 * PI))


@dataclass(eq=False)  # a turtle is itself, not any turtle at the same place
class Turtle:
    """A turtle at canvas position (``x``, ``y``), heading ``orient`` (radians,
    counter-clockwise from +x). ``look`` picks how the window draws it."""

    x: float
    y: float
    orient: float
    look: int = 0
    lin_vel_x: float = 0.0
    lin_vel_y: float = 0.0
    ang_vel: float = 0.0
    # never commanded: the first update finds the command stale (turtle.cpp:148, the
    # command time starts at zero)
    last_command: float = -math.inf
    pen_on: bool = True
    pen: Pen = DEFAULT_PEN
    teleports: List[Teleport] = field(default_factory=list)

    # --- requests (turtle.cpp:67-103) ----------------------------------------------------

    def command(self, linear_x: float, linear_y: float, angular_z: float, now: float) -> None:
        """A cmd_vel Twist received at wall time ``now`` (s): linear.x, linear.y, angular.z
        (turtle.cpp:67-73)."""
        self.last_command = now
        self.lin_vel_x, self.lin_vel_y, self.ang_vel = linear_x, linear_y, angular_z

    def set_pen(self, r: int, g: int, b: int, width: int, off: int) -> None:
        """set_pen (turtle.cpp:75-91): any non-zero ``off`` lifts the pen and keeps its
        colour and width; otherwise a new pen of this colour, ``width`` pixels wide (0: a
        new pen's width, one pixel)."""
        self.pen_on = not off
        if off:
            return
        self.pen = Pen(r, g, b, width if width != 0 else NEW_PEN_WIDTH)

    def teleport_absolute(self, x: float, y: float, theta: float) -> None:
        """Queued; done at the next update (turtle.cpp:99-103)."""
        self.teleports.append(Teleport(x, y, theta, 0.0, False))

    def teleport_relative(self, linear: float, angular: float) -> None:
        """Queued; done at the next update (turtle.cpp:93-97)."""
        self.teleports.append(Teleport(0.0, 0.0, angular, linear, True))

    # --- one update (turtle.cpp:112-212) --------------------------------------------------

    def update(self, dt: float, now: float, canvas_width: float,
               canvas_height: float) -> Step:
        """Moves the turtle by one update of ``dt`` seconds at wall time ``now``."""
        old_orient = self.orient
        modified = False
        teleport_lines = []
        # the queued teleports first, in order, each drawn (turtle.cpp:117-146)
        for request in self.teleports:
            old = (self.x, self.y)
            if request.relative:
                self.orient += request.theta
                self.x += math.cos(self.orient) * request.linear
                self.y += -math.sin(self.orient) * request.linear
            else:
                # y flipped and kept >= 0 here; x and the top are clamped by the motion
                # step below, with its warning (turtle.cpp:133-135)
                self.x = request.x
                self.y = max(0.0, canvas_height - request.y)
                self.orient = request.theta
            if self.pen_on:
                teleport_lines.append(Segment(self.pen, (self.x, self.y), old))
            modified = True
        self.teleports.clear()

        if now - self.last_command > COMMAND_TIMEOUT:  # turtle.cpp:148-153
            self.lin_vel_x = self.lin_vel_y = self.ang_vel = 0.0

        old = (self.x, self.y)
        # the heading first, then the position along the new heading (turtle.cpp:157-163)
        self.orient = wrap(self.orient + self.ang_vel * dt)
        cos, sin = math.cos(self.orient), math.sin(self.orient)
        self.x += cos * self.lin_vel_x * dt - sin * self.lin_vel_y * dt
        self.y -= cos * self.lin_vel_y * dt + sin * self.lin_vel_x * dt

        clamped_from = None  # turtle.cpp:166-173
        if self.x < 0 or self.x > canvas_width or self.y < 0 or self.y > canvas_height:
            clamped_from = (self.x, self.y)
        self.x = min(max(self.x, 0.0), canvas_width)
        self.y = min(max(self.y, 0.0), canvas_height)

        pose = (self.x, canvas_height - self.y, self.orient,
                math.hypot(self.lin_vel_x, self.lin_vel_y), self.ang_vel)  # turtle.cpp:176-181
        motion_line = None
        if self.orient != old_orient:
            modified = True
        if (self.x, self.y) != old:
            if self.pen_on:
                motion_line = Segment(self.pen, (self.x, self.y), old)
            modified = True
        return Step(tuple(teleport_lines), motion_line, pose, (self.x, self.y), clamped_from,
                    modified)
