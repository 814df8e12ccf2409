"""The steering window's logic, free of Qt and of a master (unit-testable).

The facts follow rqt_robot_steering 0.5.12 (ROS noetic):

- sliders count in thousandths: position 1000 is 1 m/s (linear) or 1 rad/s (angular);
  the arrow keys and the +/- buttons move a slider by 10 (0.01), Shift and Page Up/Down by
  100 (0.1);
- the ranges start at -1.0 .. 1.0 m/s and -3.0 .. 3.0 rad/s; a maximum can be set between
  0 and 10, a minimum between -10 and 0, in steps of 0.1 with two decimals;
- the topic starts as ``/cmd_vel``; an empty topic publishes nothing;
- private parameters ``~default_topic``, ``~default_vx_max``, ``~default_vx_min``,
  ``~default_vw_max``, ``~default_vw_min`` override those starting values;
- every 100 ms and at every slider change the current command is published, a zero command
  only once (so that another node can take over the robot), except that the stop button
  sends a zero command again when both sliders are already at zero.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, List, Optional, Tuple

import rosgraph.names
from geometry_msgs.msg import Twist
from node_params import ParameterError, convert

SLIDER_FACTOR = 1000
SINGLE_STEP = 10
PAGE_STEP = 100
PUBLISH_PERIOD = 0.1  # s, the repeat period of the command
RANGE_LIMIT = 10.0  # a maximum lies in [0, RANGE_LIMIT], a minimum in [-RANGE_LIMIT, 0]
RANGE_STEP = 0.1
RANGE_DECIMALS = 2
DEFAULT_TOPIC = "/cmd_vel"


@dataclass(frozen=True)
class Settings:
    """The window's starting values: the topic and the sliders' ranges (m/s, rad/s)."""
    topic: str = DEFAULT_TOPIC
    vx_max: float = 1.0
    vx_min: float = -1.0
    vw_max: float = 3.0
    vw_min: float = -3.0


# private parameter -> (Settings field, lowest, highest)
RANGE_PARAMETERS = {
    "default_vx_max": ("vx_max", 0.0, RANGE_LIMIT),
    "default_vx_min": ("vx_min", -RANGE_LIMIT, 0.0),
    "default_vw_max": ("vw_max", 0.0, RANGE_LIMIT),
    "default_vw_min": ("vw_min", -RANGE_LIMIT, 0.0),
}
TOPIC_PARAMETER = "default_topic"


def clamp_range(value: float, low: float, high: float) -> float:
    """A range bound as its spin box holds it: within [low, high], two decimals."""
    return round(min(max(value, low), high), RANGE_DECIMALS)


def read_settings(get_param: Callable[[str, object], object]) -> Tuple[Settings, List[str]]:
    """Reads the private parameters with ``get_param(name, default)`` (``rospy.get_param``
    with ``~`` names). Returns the settings and one warning per parameter that could not be
    used as given: it is then left at its default or clamped into its spin box's range."""
    defaults = Settings()
    warnings: List[str] = []
    values = {}

    label = "~" + TOPIC_PARAMETER
    topic = get_param(label, defaults.topic)
    if not isinstance(topic, str):  # a number or a list: no topic was meant; the default
        warnings.append(f"{ParameterError(label, topic, 'is not text', 'a topic name')}; "
                        f"using {defaults.topic}")
        topic = defaults.topic
    else:
        problem = topic_problem(topic)
        if problem and topic:
            warnings.append(f"~{TOPIC_PARAMETER}: {problem}")
    values["topic"] = topic

    for parameter, (field, low, high) in RANGE_PARAMETERS.items():
        default = getattr(defaults, field)
        raw = get_param("~" + parameter, default)
        try:  # node_params converts what roslaunch hands over; a bad value only warns here
            number = convert(float, raw, "~" + parameter,
                             f"a number between {low} and {high}")
        except ParameterError as error:
            warnings.append(f"{error}; using {default}")
            number = default
        clamped = clamp_range(number, low, high)
        if abs(clamped - number) > 10 ** -RANGE_DECIMALS / 2:
            warnings.append(f"~{parameter} must lie between {low} and {high}; "
                            f"{number} becomes {clamped}")
        values[field] = clamped
    return Settings(**values), warnings


def topic_problem(topic: str) -> Optional[str]:
    """Why nothing can be published on ``topic``, or None when it is a legal name."""
    if topic == "":
        return "no topic: type the name of the topic to publish on"
    if topic == "/":
        return "'/' is the global namespace, not a topic: type a topic name after it"
    if not rosgraph.names.is_legal_name(topic):
        return (f"'{topic}' is not a legal topic name: use letters, digits, '_' and '/', "
                "starting with a letter, '/' or '~'")
    return None


def slider_position(velocity: float) -> int:
    """The slider position (an integer) that stands for ``velocity``."""
    return int(round(velocity * SLIDER_FACTOR))


def slider_velocity(position: int) -> float:
    """The velocity a slider ``position`` stands for."""
    return position / SLIDER_FACTOR


def linear_label(velocity: float) -> str:
    return f"{velocity:0.2f} m/s"


def angular_label(velocity: float) -> str:
    return f"{velocity:0.2f} rad/s"


def make_twist(linear_x: float, angular_z: float) -> Twist:
    """A Twist driving forward at ``linear_x`` m/s and turning at ``angular_z`` rad/s
    (counter-clockwise positive); every other component zero."""
    twist = Twist()
    twist.linear.x = float(linear_x)
    twist.angular.z = float(angular_z)
    return twist


class CommandGate:
    """Decides which commands are published, as rqt_robot_steering does: a non-zero command
    every time it is offered, a zero command only the first time after a non-zero one (so
    that another node can take control); :meth:`stop_pressed` lets one more zero through."""

    def __init__(self) -> None:
        self.zero_sent = False
        self.published = 0

    def offer(self, linear_x: float, angular_z: float) -> Optional[Twist]:
        """The Twist to publish for this command, or None."""
        if linear_x == 0 and angular_z == 0:
            if self.zero_sent:
                return None
            self.zero_sent = True
        else:
            self.zero_sent = False
        self.published += 1
        return make_twist(linear_x, angular_z)

    def stop_pressed(self) -> None:
        """The stop button with both sliders at zero: the next zero command goes out."""
        self.zero_sent = False
