"""Whether a rotate service turns by odometry or by the clock, judged by what it does, as a
teaching assistant reading its code would judge it.

Subscribing to /odom is not using it: a node can subscribe and still turn for the time the
angle takes at its speed. The probe therefore asks for one more turn of a robot geared
down (``gear_down``): the same robot respawned with its drive plugin's ``wheelDiameter``
multiplied by a factor, so that every wheel turns that factor slower for the same
``/cmd_vel`` (Noetic's drive plugins turn a wheel at ``v / (wheelDiameter / 2)``:
gazebo_ros_pkgs noetic-devel f9e1a46 gazebo_plugins/src/gazebo_ros_diff_drive.cpp:288-289,
:304-305; gazebo_ros_skid_steer_drive.cpp:369-377 divides by the same radius). The robot
then turns that factor slower than commanded. Odometry taken from the world
(``odometrySource`` ``world``, the diff drive's default, gazebo_ros_diff_drive.cpp:107; the
skid steer's only kind, its pose from WorldPose, gazebo_ros_skid_steer_drive.cpp:425-437)
still reports the true heading, so a node that turns by it still turns the angle asked,
taking longer; a node that turns by the clock stops after the same time, short by the
factor (``judge``).

Encoder odometry (``odometrySource`` ``encoder``) counts the wheels with the plugin's own
diameter, so it is fooled by the same gearing as the clock is: such a robot is not geared
down, and the item is judged by the subscription alone, marked for review."""
from __future__ import annotations

import os
import xml.etree.ElementTree as ElementTree
from dataclasses import dataclass
from typing import Tuple

from course_grader.measures import Rotation

# the drive plugins whose wheel speed is v / (wheelDiameter / 2), by file name, and their
# default wheelDiameter (gazebo_ros_diff_drive.cpp:100; gazebo_ros_skid_steer_drive.cpp:152)
GEARED_PLUGINS = {"libgazebo_ros_diff_drive.so": 0.15, "libgazebo_ros_skid_steer_drive.so": 0.15}
# the diff drive's odometrySource when not written, or not one of its two names
# (gazebo_ros_diff_drive.cpp:105-107)
DEFAULT_ODOMETRY_SOURCE = "world"


class CannotGearDown(ValueError):
    """The robot cannot be slowed this way; the message says why."""


@dataclass
class GearedRobot:
    """A robot description whose drive turns its wheels ``factor`` times slower."""

    xml: str
    plugin: str                  # the drive plugin's file name
    diameter: float              # its wheelDiameter as the robot has it (m)
    geared: float                # the one written into ``xml`` (m)

    def describe(self) -> str:
        return (f"{self.plugin}'s wheelDiameter {self.diameter:g} m made {self.geared:g} m: "
                f"its wheels turn {self.geared / self.diameter:g} times slower for the same "
                f"/cmd_vel")


def gear_down(urdf_xml: str, factor: float) -> GearedRobot:
    """``urdf_xml`` with its drive plugin's wheelDiameter times ``factor`` (written in when
    the plugin relies on the default). Raises CannotGearDown when the robot has no such
    plugin, more than one, or counts odometry from its wheels."""
    if not factor > 1.0:
        raise ValueError(f"a gearing factor must be above 1, not {factor!r}")
    try:
        root = ElementTree.fromstring(urdf_xml)
    except ElementTree.ParseError as error:
        raise CannotGearDown(f"robot_description does not parse: {error}") from None
    drives = [p for p in root.iter("plugin")
              if os.path.basename(p.get("filename", "")) in GEARED_PLUGINS]
    if len(drives) != 1:
        found = ", ".join(sorted({os.path.basename(p.get("filename", ""))
                                  for p in root.iter("plugin")})) or "none"
        raise CannotGearDown(
            f"{'no' if not drives else 'more than one'} drive plugin of "
            f"{' or '.join(sorted(GEARED_PLUGINS))} in robot_description (plugins: {found})")
    drive = drives[0]
    plugin = os.path.basename(drive.get("filename"))
    source = (drive.findtext("odometrySource") or DEFAULT_ODOMETRY_SOURCE).strip().lower()
    if source == "encoder":
        raise CannotGearDown(
            f"{plugin} counts odometry from its wheels (odometrySource {source}): geared "
            "down, it would report the commanded turn, as the clock does")
    element = drive.find("wheelDiameter")
    if element is None:
        element = ElementTree.SubElement(drive, "wheelDiameter")
        diameter = GEARED_PLUGINS[plugin]
    else:
        try:
            diameter = float(element.text)
        except (TypeError, ValueError):
            raise CannotGearDown(f"{plugin}'s wheelDiameter {element.text!r} is not a "
                                 "number") from None
    geared = diameter * factor
    element.text = repr(geared)
    return GearedRobot(ElementTree.tostring(root, encoding="unicode"), plugin, diameter, geared)


def judge(free: Rotation, free_seconds: float, slowed: Rotation, slowed_seconds: float,
          factor: float, tolerance: float) -> Tuple[bool, str]:
    """(turned by odometry, evidence) from a turn of the robot as it is (``free``) and one
    of the robot geared down ``factor`` times (``slowed``), each with its duration in
    simulated seconds from the request until the robot stopped. The free turn says how the
    node turns (an overshoot of 7% included): by odometry, the slowed turn is the same
    share of its request, taking longer; by the clock, that share over ``factor``. Within
    ``tolerance`` degrees of the first passes."""
    share = free.turned / free.requested
    by_odometry = slowed.requested * share
    by_clock = by_odometry / factor
    turns = (f"free: asked {free.requested:+.0f}, turned {free.turned:+.1f} deg in truth in "
             f"{free_seconds:.1f} s; geared down {factor:g} times: asked "
             f"{slowed.requested:+.0f}, turned {slowed.turned:+.1f} in {slowed_seconds:.1f} s, "
             f"where the free turn's {share:.3f} of the request gives {by_odometry:+.1f} by "
             f"odometry, {by_clock:+.1f} by the clock")
    if abs(slowed.turned - by_odometry) <= tolerance:
        return True, f"turns by odometry: the slowed robot still turned the angle ({turns})"
    if abs(slowed.turned - by_clock) <= tolerance:
        return False, (f"turns by the clock: the slowed robot stopped near 1/{factor:g} of "
                       f"the angle ({turns})")
    return False, (f"the slowed robot turned neither as by odometry nor as by the clock "
                   f"({slowed.turned - by_odometry:+.1f} deg from odometry's; {turns})")
