"""The turtles' world as turtlesim 0.10.2's window keeps it: its size, the turtles by name,
the naming of spawned turtles, kill, reset, the update clock and the background colour.
Pure logic, no Qt and no ROS master (unit-testable).

Upstream citations are ros/ros_tutorials noetic-devel (commit db63288), folder turtlesim/.
"""
from __future__ import annotations

import math
import random
import struct
from typing import Callable, Dict, List, Optional, Tuple

import rosgraph.names
from node_params import ParameterError, between, convert

from turtle_world.turtle import Step, Turtle

# the window, pixels (turtle_frame.cpp:47, :53)
WIDTH_PX = 500
HEIGHT_PX = 500
# pixels per metre: the height of upstream's turtle images, 45 px (turtle_frame.cpp:101)
METER = 45.0
# the update timer, ms, and the fixed step every update integrates (turtle_frame.cpp:59,
# :255: 0.001 * interval)
UPDATE_MS = 16
DT = 0.001 * UPDATE_MS
# the background when ~background_r/g/b are not set (turtle_frame.cpp:38-40)
DEFAULT_BACKGROUND = (0x45, 0x56, 0xFF)
BACKGROUND_PARAMS = ("~background_r", "~background_g", "~background_b")
# how many ways the window has to draw a turtle; a spawned turtle gets one at random, as
# upstream picks one of its 14 images (turtle_frame.cpp:170)
LOOKS = 6

# upstream's log lines (turtle_frame.cpp:110, :139, :153, :197, :268, :275)
STARTING = "Starting turtlesim with node name %s"
NAME_TAKEN = "A turtled named [%s] already exists"
NO_SUCH_TURTLE = "Tried to kill turtle [%s], which does not exist"
SPAWNING = "Spawning turtle [%s] at x=[%f], y=[%f], theta=[%f]"
CLEARING = "Clearing turtlesim."
RESETTING = "Resetting turtlesim."


def f32(value: float) -> float:
    """``value`` as a C float holds it (upstream keeps sizes and spawn poses in floats)."""
    return struct.unpack("f", struct.pack("f", value))[0]


class World:
    """The turtles, by name, in the canvas frame of :mod:`turtle_world.turtle`."""

    def __init__(self, rng: Optional[random.Random] = None):
        # (500 - 1) / 45 = 11.0889 m, kept in floats (turtle_frame.cpp:112-113)
        self.width = f32((WIDTH_PX - 1) / METER)
        self.height = f32((HEIGHT_PX - 1) / METER)
        self.turtles: Dict[str, Turtle] = {}
        self.id_counter = 0
        self.started = False
        self._rng = rng or random.Random()

    def spawn(self, name: str, x: float, y: float, theta: float) -> Optional[str]:
        """A new turtle at (x, y up) facing ``theta``; its name, or None when ``name`` is
        taken. An empty name is the first free ``turtle<N>``, N counting on from the last
        one given (turtle_frame.cpp:173-199)."""
        real_name = name
        if not real_name:
            while True:
                self.id_counter += 1
                real_name = f"turtle{self.id_counter}"
                if real_name not in self.turtles:
                    break
        elif real_name in self.turtles:
            return None
        x, y, theta = f32(x), f32(y), f32(theta)
        self.turtles[real_name] = Turtle(x, f32(self.height - y), theta,
                                         look=self._rng.randrange(LOOKS))
        return real_name

    def kill(self, name: str) -> bool:
        """Removes the turtle; False when there is none of that name (turtle_frame.cpp:148-161)."""
        return self.turtles.pop(name, None) is not None

    def centre(self) -> Tuple[float, float]:
        """Where turtle1 starts: the middle of the window (turtle_frame.cpp:114, :278)."""
        return self.width / 2.0, self.height / 2.0

    def reset(self) -> str:
        """Every turtle removed, the name counter back to 0, turtle1 in the middle facing
        +x (turtle_frame.cpp:273-281); its name."""
        self.turtles.clear()
        self.id_counter = 0
        return self.spawn("", *self.centre(), 0.0)

    def tick(self, now: float) -> List[Tuple[str, Step]]:
        """One update at wall time ``now`` (s): every turtle by name order (a std::map's),
        each moved by DT. The first tick only starts the clock (turtle_frame.cpp:242-263)."""
        if not self.started:
            self.started = True
            return []
        return [(name, self.turtles[name].update(DT, now, self.width, self.height))
                for name in sorted(self.turtles)]


def to_pixels(point: Tuple[float, float]) -> Tuple[float, float]:
    """Canvas metres to pixels (turtle.cpp:141, :187, :216)."""
    return point[0] * METER, point[1] * METER


def pixel_under(point: Tuple[float, float]) -> Tuple[int, int]:
    """The pixel whose colour the sensor reads: QPointF::toPoint's rounding of the pixel
    position (turtle.cpp:187), half away from zero (positions are never negative here)."""
    x, y = to_pixels(point)
    return int(math.floor(x + 0.5)), int(math.floor(y + 0.5))


def _roscpp_int(value: float) -> int:
    """A double read as roscpp's param() reads it into an int: rounded half up."""
    return int(math.floor(value) if math.fmod(value, 1.0) < 0.5 else math.ceil(value))


def background_colour(get_param: Callable) -> Tuple[Tuple[int, int, int], List[str]]:
    """The background from ~background_r, ~background_g, ~background_b (re-read at every
    clear, turtle_frame.cpp:202-214), and a warning for each value that cannot be one: a
    channel that is not a number from 0 to 255 keeps its default (upstream keeps the
    default for text and wraps numbers beyond 255)."""
    channels, warnings = [], []
    for name, default in zip(BACKGROUND_PARAMS, DEFAULT_BACKGROUND):
        value = get_param(name, default)
        try:
            number = convert(float, value, name, "a colour channel, 0 to 255",
                             (between(0, 255),))
        except ParameterError as error:
            warnings.append(f"{error}; using {default}")
            channels.append(default)
            continue
        channels.append(_roscpp_int(number))
    return (channels[0], channels[1], channels[2]), warnings


def _finite(**values: float) -> Optional[str]:
    for name, value in values.items():
        if not math.isfinite(value):
            return f"{name} is {value}; give a finite number"
    return None


def spawn_problem(name: str, x: float, y: float, theta: float) -> Optional[str]:
    """Why a spawn request cannot be served (None when it can): a name that is no legal
    ROS name (the turtle's topics live under it) or a pose that is not finite."""
    if name and not rosgraph.names.is_legal_name(name):
        return (f"'{name}' is not a legal ROS name (its topics would be '{name}/pose' ...); "
                "use letters, digits, _ and /, starting with a letter")
    return _finite(x=x, y=y, theta=theta)


def teleport_problem(**values: float) -> Optional[str]:
    """Why a teleport request cannot be served (None when it can): a value not finite."""
    return _finite(**values)
