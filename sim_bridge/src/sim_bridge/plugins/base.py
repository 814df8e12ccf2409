"""What every plugin gets and does.

A plugin is built with a :class:`PluginContext` (the pybullet client, the robot body, the
namespace, a :class:`Bus` to ROS, a seeded random generator) and its spec from the URDF.
Each physics step the world calls ``before_step`` (apply commands) and ``after_step``
(sense and publish) with the simulated time in nanoseconds. Plugins read all their
parameters in the constructor; a missing required one raises :class:`PluginError`.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, Optional, Sequence, Tuple

import genpy
import numpy as np
import pybullet as pb
from geometry_msgs.msg import Vector3, WrenchStamped

from sim_bridge.gazebo_tags import PluginSpec
from sim_bridge.poses import pose6_to_position_quaternion

# a simulated time no step reaches (2^63 - 1 ns, about 292 years): "never", for
# Plugin.quiet_until_ns
NEVER = 2 ** 63 - 1
# UpdateSlots: how many nanoseconds past its period it looks for where Gazebo's float
# comparison turns (one or two at any period below a million years)
BRANCH_SEARCH_NS = 1000


class PluginError(ValueError):
    """A plugin that cannot run as written; the message names the plugin and the cause."""


class Bus:
    """The plugins' way to ROS. The ROS adapter implements it with rospy; unit tests with a
    recorder. Topic names given here are already resolved (absolute)."""

    def publisher(self, topic: str, msg_class, queue_size: int = 10, latch: bool = False):
        raise NotImplementedError

    def subscriber(self, topic: str, msg_class, callback: Callable[[Any], None]):
        raise NotImplementedError

    def send_transforms(self, transforms: Sequence[Any]) -> None:
        raise NotImplementedError

    def listened(self, publisher=None) -> bool:
        """Whether anyone would receive a message on ``publisher`` (one from this bus), or
        on /tf when None. A plugin may skip building a message nobody would receive: what
        nobody receives cannot differ. True unless the bus knows otherwise."""
        return True

    def service(self, name: str, srv_class, handler: Callable[[Any], Any]):
        """Offers a service; ``handler`` runs in the physics thread. Returns a handle with
        ``shutdown()``."""
        raise NotImplementedError

    def action_server(self, name: str, action_class, on_goal: Callable[[Any], None],
                      on_cancel: Callable[[Any], None]):
        """Offers an actionlib action; the callbacks get actionlib goal handles and run in
        the physics thread."""
        raise NotImplementedError

    def info(self, text: str) -> None:
        raise NotImplementedError

    def warn(self, text: str) -> None:
        raise NotImplementedError

    def warn_throttled(self, key: str, period: float, text: str) -> None:
        raise NotImplementedError

    def debug(self, text: str) -> None:
        """A note for whoever runs with verbose:=true; nothing by default."""

    def get_param(self, name: str, default: Any = None) -> Any:
        return default


class TrackingBus(Bus):
    """A bus that keeps what a plugin opened through it, so that a plugin that fails while
    it is being built can be taken out without leaving a publisher, a subscriber or a
    service behind (Gazebo loads the robot without that plugin; nothing of it stays)."""

    def __init__(self, bus: Bus):
        self.bus = bus
        self.opened: list = []

    def _keep(self, handle):
        self.opened.append(handle)
        return handle

    def publisher(self, topic, msg_class, queue_size=10, latch=False):
        return self._keep(self.bus.publisher(topic, msg_class, queue_size, latch))

    def subscriber(self, topic, msg_class, callback):
        return self._keep(self.bus.subscriber(topic, msg_class, callback))

    def service(self, name, srv_class, handler):
        return self._keep(self.bus.service(name, srv_class, handler))

    def action_server(self, name, action_class, on_goal, on_cancel):
        return self._keep(self.bus.action_server(name, action_class, on_goal, on_cancel))

    def send_transforms(self, transforms):
        self.bus.send_transforms(transforms)

    def listened(self, publisher=None):
        return self.bus.listened(publisher)

    def info(self, text):
        self.bus.info(text)

    def debug(self, text):
        self.bus.debug(text)

    def warn(self, text):
        self.bus.warn(text)

    def warn_throttled(self, key, period, text):
        self.bus.warn_throttled(key, period, text)

    def get_param(self, name, default=None):
        return self.bus.get_param(name, default)

    def close_all(self) -> None:
        """Unregisters / shuts down everything opened through this bus."""
        for handle in reversed(self.opened):
            close = getattr(handle, "shutdown", None) or getattr(handle, "unregister", None)
            if close is not None:
                close()
        self.opened.clear()


@dataclass
class PluginContext:
    client: int
    robot: Any  # RobotBody
    model_name: str
    namespace: str  # robotNamespace from spawn_model, "" for none
    bus: Bus
    rng: np.random.Generator
    step_size: float
    gravity: Sequence[float] = (0.0, 0.0, -9.8)
    # cast_rays(origin, unit directions (N, 3), near, far) -> distances (N,), inf: nothing
    cast_rays: Optional[Callable[..., np.ndarray]] = None
    # prefix of the frames the plugins name (the namespace's tf_prefix parameter), "" none
    tf_prefix: str = ""
    # the name of the model a pybullet body is (for contacts' names), or None
    model_of_body: Callable[[int], Optional[str]] = lambda body: None
    # the model as Gazebo's interface shows it (model_structure.Structure), None unknown
    structure: Any = None
    # (force, torque) applied from outside to one of the model's links for the step that
    # starts now: world axes, the torque about its centre of mass (external_forces)
    applied_wrench: Callable[[str], Tuple[np.ndarray, np.ndarray]] = \
        lambda body: (np.zeros(3), np.zeros(3))
    # the spawn request named a namespace, "/" included (spawn_model sends its own, "/" at
    # the top level; gazebo_ros then gives it to every plugin that names none)
    namespace_given: bool = False


def resolve_topic(namespace: str, topic: str) -> str:
    """Gazebo's rule: an absolute topic stays; a relative one goes under the namespace."""
    if topic.startswith("/"):
        return topic
    namespace = namespace.strip("/")
    return f"/{namespace}/{topic}" if namespace else f"/{topic}"


def stamp(now_ns: int) -> genpy.Time:
    return genpy.Time(now_ns // 1_000_000_000, now_ns % 1_000_000_000)


def wrench_stamped(now_ns: int, frame_id: str, force, torque) -> WrenchStamped:
    """A geometry_msgs/WrenchStamped of two 3-vectors, stamped with simulated time."""
    message = WrenchStamped()
    message.header.stamp, message.header.frame_id = stamp(now_ns), frame_id
    message.wrench.force = Vector3(*(float(v) for v in force))
    message.wrench.torque = Vector3(*(float(v) for v in torque))
    return message


class Plugin:
    """Base of model plugins and sensor plugins."""

    # Where a plugin's topics go when <robotNamespace> does not say (gazebo_plugins differ):
    # the diff drive and joint state publisher (the GazeboRos class) take the model's name
    # for an absent or empty tag; the laser and cameras (the GetRobotNamespace helper) for an
    # empty one; gazebo_ros_control and the IMU sensor for an absent one; every other plugin
    # reads both as the top level.
    ABSENT_NAMESPACE_IS_MODEL = False
    EMPTY_NAMESPACE_IS_MODEL = False

    def __init__(self, context: PluginContext, spec: PluginSpec):
        self.context = context
        self.spec = spec
        self.namespace = self._namespace(spec.text("robotNamespace"))

    def _namespace(self, own: Optional[str]) -> str:
        """The plugin's namespace, without slashes at its ends ("" the top level). As
        gazebo_ros's spawn service (walkChildAddRobotNamespace): a request naming a namespace
        ("/" included, spawn_model's at the top level) gives it to the plugins that name
        none; a plugin's own tag is kept."""
        model = self.context.model_name.strip("/")
        if own is None:
            if self.context.namespace_given:
                return self.context.namespace.strip("/")
            return model if self.ABSENT_NAMESPACE_IS_MODEL else ""
        if not own.strip():
            return model if self.EMPTY_NAMESPACE_IS_MODEL else ""
        return own.strip().strip("/")

    # --- parameters -------------------------------------------------------------------
    def param(self, tag: str, default: Optional[str] = None) -> Optional[str]:
        return self.spec.text(tag, default)

    def number(self, tag: str, default: float, false_value: Optional[float] = None) -> float:
        """The tag's number; ``false_value`` is what the word ``false`` means where Gazebo
        reads it as a number (e.g. ``<wheelAcceleration>false</wheelAcceleration>`` is 0)."""
        text = self.spec.text(tag)
        if text is None or text == "":
            self.spec.use_default(tag, default)
            return default
        if false_value is not None and text.strip().lower() == "false":
            return false_value
        try:
            value = float(text)
        except ValueError:
            return self.unreadable(tag, text, "a number", default)
        if not np.isfinite(value):
            return self.unreadable(tag, text, "a finite number", default)
        return value

    def unreadable(self, tag: str, text: str, expected: str, default):
        """A value written that the plugin cannot read: Gazebo's plugins log an error and
        run with their default (``<wheelAcceleration>true</wheelAcceleration>`` is read as
        0), so the plugin runs; the line names the tag, the text and the default used."""
        self.spec.used[tag] = f"{default} (default; '{text}' unreadable)"
        shown = " ".join(f"{v:g}" for v in default) if isinstance(default, (tuple, list)) \
            else default
        self.context.bus.warn(
            f"model '{self.context.model_name}': plugin '{self.spec.name}' "
            f"({self.spec.filename}): <{tag}> '{text}' is not {expected}; the plugin runs "
            f"with its default, {shown}")
        return default

    def flag(self, tag: str, default: bool) -> bool:
        """A boolean as sdformat's ``Element::Get<bool>`` reads one (sdformat 9,
        include/sdf/Param.hh, Param::Get): ``true`` or ``1``, any case, is true; any other
        text false."""
        text = self.spec.text(tag)
        if text is None or text == "":
            self.spec.use_default(tag, default)
            return default
        return text.strip().lower() in ("1", "true")

    def gazebo_ros_flag(self, tag: str, default: bool) -> bool:
        """A boolean as gazebo_plugins' ``GazeboRos::getParameterBoolean`` reads one
        (gazebo_ros_pkgs noetic-devel f9e1a46, gazebo_plugins/src/gazebo_ros_utils.cpp:92-123):
        absent, the default; ``true`` or ``1`` true and ``false`` or ``0`` false, any case;
        any other text, an empty tag included, warns and keeps the default."""
        text = self.spec.text(tag)
        if text is None:
            self.spec.use_default(tag, default)
            return default
        word = text.strip().lower()
        if word in ("true", "1"):
            return True
        if word in ("false", "0"):
            return False
        return self.unreadable(tag, text, "true, false, 1 or 0 (any case)", default)

    def joint(self, tag: str, default: Optional[str] = None) -> str:
        name = self.spec.text(tag, default)
        if not name:
            raise PluginError(f"plugin '{self.spec.name}' ({self.spec.filename}) needs "
                              f"<{tag}>, the name of a joint")
        if name not in self.context.robot.joint_index:
            raise PluginError(f"plugin '{self.spec.name}' ({self.spec.filename}): <{tag}> "
                              f"names joint '{name}', which model '{self.context.model_name}' "
                              "does not have")
        return name

    def topic(self, name: str) -> str:
        return resolve_topic(self.namespace, name)

    def frame(self, name: str, prefix: Optional[str] = None) -> str:
        """A frame name with the model's tf_prefix (or ``prefix`` when given), as
        tf::resolve makes it (ros/geometry noetic-devel fe344b6, tf/src/tf.cpp:159-185): a
        name that starts with '/' is absolute, its slash dropped and no prefix added
        (``/world`` stays ``world``); any other gets the prefix."""
        if name.startswith("/"):
            return name.lstrip("/")
        prefix = (self.context.tf_prefix if prefix is None else prefix).strip("/")
        return f"{prefix}/{name}" if prefix else name

    def own_tf_prefix(self) -> str:
        """The ``tf_prefix`` parameter in the plugin's own namespace and nowhere above it:
        what a plugin gets that reads it with ``getParam`` on a node handle in its
        robotNamespace (f3d and ft_sensor, gazebo_ros_pkgs noetic-devel f9e1a46,
        gazebo_plugins/src/gazebo_ros_f3d.cpp:112-115, gazebo_ros_ft_sensor.cpp:123-126),
        unlike tf::getPrefixParam's search, which the model's ``tf_prefix`` follows. A
        value that is not a string is not read, as getParam into a std::string fails."""
        value = self.context.bus.get_param(self.topic("tf_prefix"), "")
        return value if isinstance(value, str) else ""

    # --- the step ---------------------------------------------------------------------
    def quiet_until_ns(self, now_ns: int, step_ns: int) -> int:
        """The end of the first step, of the steps of ``step_ns`` from ``now_ns``, in which
        :meth:`before_step` (given the step's start) or :meth:`after_step` (given its end)
        may do anything: in every step that ends earlier, both return at once, changing
        nothing and calling nothing. The world makes those steps by the physics alone
        (:meth:`World.advance <sim_bridge.world.World.advance>`), which is what calling the
        plugin there would have done. A plugin that overrides either method may act at
        every step unless it says otherwise (rate-gated plugins answer from their
        :class:`Rate`, an end's time, or :class:`UpdateSlots`, a start's, which is one step
        before its end); one that overrides neither never acts."""
        cls = type(self)
        if cls.before_step is Plugin.before_step and cls.after_step is Plugin.after_step:
            return NEVER
        return now_ns

    def before_step(self, now_ns: int) -> None:
        """Applies commands to the bodies before a physics step."""

    def after_step(self, now_ns: int) -> None:
        """Reads the result of a physics step and publishes."""

    def reset(self, now_ns: int) -> None:
        """The world was reset: forget integrated state."""

    def close(self) -> None:
        """The model is deleted: everything the plugin opened on ROS (publishers,
        subscribers, services, actions) is closed. Plugins are built on a
        :class:`TrackingBus`, which keeps what they open, so no plugin lists its own."""
        close_all = getattr(self.context.bus, "close_all", None)
        if close_all is not None:
            close_all()


def element_pose(element, what: str):
    """(position, quaternion) of an element's ``<pose>`` (x y z roll pitch yaw; none: the
    identity); ``what`` names the element in the error."""
    text = element.findtext("pose")
    try:
        pose = tuple(float(v) for v in text.split()) if text else (0.0,) * 6
    except ValueError:
        pose = ()
    if len(pose) != 6:
        raise PluginError(f"{what}: <pose> '{text}' needs 6 numbers")
    return pose6_to_position_quaternion(pose)


class SensorPlugin(Plugin):
    """A sensor's plugin: the sensor's link and its ``<pose>`` in the link's frame, and where
    that is in the world now (from the link's true pose, rotation included)."""

    def __init__(self, context: PluginContext, spec: PluginSpec, sensor):
        super().__init__(context, spec)
        self.link = sensor.link
        if self.link not in context.robot.link_index:
            raise PluginError(f"sensor '{sensor.name}' is on link '{self.link}', which the "
                              "model does not have")
        self.sensor_position, self.sensor_orientation = element_pose(
            sensor.element, f"sensor '{sensor.name}'")

    def sensor_pose(self):
        """(position, quaternion) of the sensor in the world."""
        link_position, link_orientation = self.context.robot.link_pose(self.link)
        return pb.multiplyTransforms(link_position, link_orientation, self.sensor_position,
                                     self.sensor_orientation,
                                     physicsClientId=self.context.client)


class Rate:
    """Fires once per period of simulated time (period 0: every step), like Gazebo's
    updateRate."""

    def __init__(self, rate_hz: float):
        self.period_ns = int(round(1e9 / rate_hz)) if rate_hz > 0 else 0
        self.next_ns = 0

    def quiet_until_ns(self) -> int:
        """The first time :meth:`due` may say yes (and change anything): the next slot."""
        return self.next_ns

    def due(self, now_ns: int) -> bool:
        if now_ns < self.next_ns:
            return False
        if self.period_ns:
            self.next_ns += self.period_ns
            if self.next_ns <= now_ns:  # fell behind (time jumped): keep the period from now
                self.next_ns = now_ns + self.period_ns
        return True

    def reset(self, now_ns: int) -> None:
        self.next_ns = now_ns


def gazebo_seconds(ns: int) -> float:
    """A time difference as Gazebo's ``common::Time::Double()`` makes it (whole seconds plus
    nanoseconds times 1e-9), for comparisons with a period in seconds as the plugins make
    them."""
    return ns // 1_000_000_000 + (ns % 1_000_000_000) * 1e-9


class Throttle:
    """gazebo_plugins' own rate check on top of whatever calls it: ``ready(now)`` when at
    least 1/rate seconds (``common::Time::Double()``) have passed since the last message,
    ``mark(now)`` when one went out (``last_update_time_ = now``). The last message's time
    starts at ``last_ns`` (Gazebo's ``common::Time()``, 0, unless the plugin sets it at
    load). A rate of 0 or less: always ready."""

    def __init__(self, rate_hz: float, last_ns: int = 0):
        self.period = 1.0 / rate_hz if rate_hz > 0 else 0.0
        self.last_ns = last_ns

    def ready(self, now_ns: int) -> bool:
        return self.period == 0.0 or gazebo_seconds(now_ns - self.last_ns) >= self.period

    def mark(self, now_ns: int) -> None:
        self.last_ns = now_ns


class UpdateSlots:
    """The rate branch of gazebo_plugins' drive plugins' UpdateChild, where they read the
    last cmd_vel and set the wheels (gazebo_ros_pkgs noetic-devel f9e1a46,
    gazebo_plugins/src/gazebo_ros_diff_drive.cpp:269-271, :307;
    gazebo_ros_skid_steer_drive.cpp:350-352, :382): it runs once more than the period
    (``common::Time::Double()``) has passed since ``last_update_time_``, which starts at the
    load's time and then moves on by exactly one period (``common::Time(period)``, whole
    nanoseconds), not to now. So a command waits up to a period for its slot; at 100 Hz on
    1 ms steps the slots are 10 ms apart and each sees 11 ms since the last. A rate of 0 or
    less: every step. The load's time here is the first step's (nothing moves between a
    spawn and its first step)."""

    def __init__(self, rate_hz: float):
        self.period = 1.0 / rate_hz if rate_hz > 0 else 0.0
        self.period_ns = int(round(self.period * 1e9))
        self.last_ns: Optional[int] = None
        # the fewest nanoseconds since the last update whose common::Time::Double() is more
        # than the period (Double() grows with the nanoseconds, so the branch runs exactly
        # from there on): within a nanosecond or two of the period (the search is bounded
        # for periods of thousands of years, where a nanosecond is below a double's step)
        self.branch_ns = max(self.period_ns - 1, 0)
        for _ in range(BRANCH_SEARCH_NS):
            if gazebo_seconds(self.branch_ns) > self.period:
                break
            self.branch_ns += 1

    def quiet_until_ns(self, now_ns: int) -> int:
        """The first time :meth:`due` runs the branch (or, before its first call, changes
        anything)."""
        if self.last_ns is None:
            return now_ns
        return self.last_ns + self.branch_ns

    def due(self, now_ns: int) -> Optional[float]:
        """The seconds since the last update when the branch runs now, else None."""
        if self.last_ns is None:
            self.last_ns = now_ns
        # Gazebo's float comparison, decided once for all in whole nanoseconds (branch_ns)
        if now_ns - self.last_ns < self.branch_ns:
            return None
        seconds = gazebo_seconds(now_ns - self.last_ns)
        self.last_ns += self.period_ns
        return seconds

    def restart(self, now_ns: int) -> None:
        """``last_update_time_ = SimTime()`` (the diff drive's Reset)."""
        self.last_ns = now_ns
