"""What a URDF's ``<gazebo>`` blocks ask of the simulator.

- ``<gazebo reference="link">`` with simple children: surface and look of that link
  (:class:`LinkSurface`);
- ``<gazebo>`` (or with a reference) holding ``<plugin>``: a model plugin (:class:`PluginSpec`);
- ``<gazebo reference="link">`` holding ``<sensor>``: a sensor on that link, with its own
  plugin (:class:`SensorSpec`).

Parameter values stay as text here; each plugin reads its own with its defaults. A value may
be written as text or, as some robot files do, as an attribute: ``<mu1 value="0.5"/>`` is
read like ``<mu1>0.5</mu1>`` (Gazebo's URDF reader takes both).

Tags that Gazebo knows but sim_bridge does not emulate are collected in
:attr:`GazeboTags.not_emulated` (tag → where it was first seen), so that the simulator warns
once per tag, naming it, instead of ignoring it silently.
"""
from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Set, Tuple

from urdf_tools.model import RobotModel, UrdfError

# Gazebo's ODE defaults: mu = mu2 = 1; no self collision; gravity on.
DEFAULT_MU = 1.0
# Plugin parameters every gazebo_ros plugin takes and that change nothing here: the plugin
# always runs and logs at the node's level.
READ_BY_EVERY_PLUGIN = frozenset(("alwaysOn", "rosDebugLevel", "robotNamespace"))
# <gazebo reference="joint"> tags with no effect here (pybullet's joints are exact);
# reported once each. preserveFixedJoint and disableFixedJointLumping are honoured by
# sim_bridge.model_structure (the links Gazebo shows), so they are not in this list.
JOINT_TAGS_NOT_EMULATED = ("stopCfm", "stopErp", "fudgeFactor", "provideFeedback",
                           "implicitSpringDamper", "cfmDamping", "springStiffness",
                           "springReference")


@dataclass
class LinkSurface:
    mu1: float = DEFAULT_MU
    mu2: float = DEFAULT_MU
    kp: Optional[float] = None
    kd: Optional[float] = None
    min_depth: Optional[float] = None
    # Gazebo's first friction direction, in the link's frame (sim_bridge.tyre_friction)
    fdir1: Optional[Tuple[float, float, float]] = None
    material: Optional[str] = None
    # <selfCollide> as given (None: not given, the model's <self_collide> decides)
    self_collide: Optional[bool] = None
    gravity: bool = True


@dataclass
class PluginSpec:
    """A ``<plugin name filename>``: its parameters as {tag: text}; ``element`` keeps nested ones."""

    name: str
    filename: str
    params: Dict[str, str]
    element: ET.Element
    reference: Optional[str] = None
    # the tags the plugin asked for: what is left was written but means nothing to it
    read: Set[str] = field(default_factory=set)
    # tag → the value the plugin runs with, "(default)" marked: what --verbose prints
    used: Dict[str, str] = field(default_factory=dict)

    def text(self, tag: str, default: Optional[str] = None) -> Optional[str]:
        self.read.add(tag)
        value = self.params.get(tag)
        if value is None:
            self.use_default(tag, default)
            return default
        self.used[tag] = value
        return value

    def use_default(self, tag: str, default) -> None:
        """Records that the plugin runs with its default for ``tag``."""
        self.used[tag] = "(default)" if default is None else f"{default} (default)"

    def summary(self) -> str:
        """The parameters the plugin runs with, in the order it read them."""
        return ", ".join(f"<{tag}> {value or repr('')}" for tag, value in self.used.items())

    def unread(self) -> List[str]:
        """Parameters written in the plugin that it never asked for, in file order."""
        return [tag for tag in self.params
                if tag not in self.read and tag not in READ_BY_EVERY_PLUGIN]


@dataclass
class SensorSpec:
    """A ``<sensor>`` on a link; ``element`` is the whole sensor (ray, imu, update_rate...)."""

    name: str
    type: str
    link: str
    element: ET.Element
    plugins: List[PluginSpec] = field(default_factory=list)


@dataclass
class GazeboTags:
    surfaces: Dict[str, LinkSurface]
    plugins: List[PluginSpec]
    sensors: List[SensorSpec]
    self_collide: bool = False
    # tag → where it was first seen, for tags read but not emulated
    not_emulated: Dict[str, str] = field(default_factory=dict)
    # reference → what its block held (tags), for <gazebo reference> naming nothing the
    # model has: Gazebo's URDF-to-SDF conversion finds no element to put them in and the
    # model loads without them (robots comment a link out and leave its block)
    unknown_references: Dict[str, List[str]] = field(default_factory=dict)


def _float(text: str, what: str, source: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise UrdfError(f"{source}: {what} '{text}' is not a number") from None
    if not math.isfinite(value):  # a friction or stiffness of nan/inf breaks the physics
        raise UrdfError(f"{source}: {what} '{text}' is not a finite number")
    return value


def _direction(text: str, what: str, source: str) -> Optional[Tuple[float, float, float]]:
    """Three numbers; None for Gazebo's "0 0 0" (no direction given)."""
    parts = text.split()
    if len(parts) != 3:
        raise UrdfError(f"{source}: {what} '{text}' is not three numbers")
    vector = tuple(_float(p, what, source) for p in parts)
    if not all(math.isfinite(v) for v in vector):
        raise UrdfError(f"{source}: {what} '{text}' is not three finite numbers")
    return vector if any(vector) else None


def _bool(text: str) -> bool:
    return text.strip().lower() in ("1", "true")


def value_of(element: ET.Element) -> str:
    """An element's value: its text, or its ``value`` attribute (``<mu1 value="0.5"/>``)."""
    text = (element.text or "").strip()
    if not text and element.get("value") is not None:
        return element.get("value", "").strip()
    return text


def _plugin(element: ET.Element, reference: Optional[str], source: str) -> PluginSpec:
    filename = element.get("filename", "")
    if not filename:
        raise UrdfError(f"{source}: a <plugin> has no filename")
    params = {child.tag: value_of(child) for child in element}
    return PluginSpec(element.get("name", filename), filename, params, element, reference)


def read_gazebo_tags(model: RobotModel) -> GazeboTags:
    source = model.source
    surfaces: Dict[str, LinkSurface] = {}
    plugins: List[PluginSpec] = []
    sensors: List[SensorSpec] = []
    robot_self_collide = False
    not_emulated: Dict[str, str] = {}
    unknown_references: Dict[str, List[str]] = {}
    for reference, block in model.gazebo:
        if reference is not None and reference not in model.links:
            if reference in model.joints:
                for child in block:
                    if child.tag in JOINT_TAGS_NOT_EMULATED:
                        not_emulated.setdefault(child.tag, f"joint '{reference}'")
                continue
            unknown_references.setdefault(reference, []).extend(
                f"<{child.tag}{' ' + repr(child.get('name')) if child.get('name') else ''}>"
                for child in block)
            continue
        for child in block:
            tag = child.tag
            text = value_of(child)
            if tag == "plugin":
                plugins.append(_plugin(child, reference, source))
            elif tag == "sensor":
                if reference is None:
                    raise UrdfError(f"{source}: <sensor '{child.get('name')}'> needs "
                                    "<gazebo reference='link'>")
                sensors.append(SensorSpec(child.get("name", ""), child.get("type", ""),
                                          reference, child,
                                          [_plugin(p, reference, source)
                                           for p in child.findall("plugin")]))
            elif reference is None:
                if tag == "self_collide":
                    robot_self_collide = _bool(text)
                else:  # static, enable_wind, ...
                    not_emulated.setdefault(tag, "the robot's <gazebo>")
            else:
                surface = surfaces.setdefault(reference, LinkSurface())
                what = f"<gazebo reference='{reference}'> <{tag}>"
                if tag == "mu1":
                    surface.mu1 = _float(text, what, source)
                elif tag == "mu2":
                    surface.mu2 = _float(text, what, source)
                elif tag == "kp":
                    surface.kp = _float(text, what, source)
                elif tag == "kd":
                    surface.kd = _float(text, what, source)
                elif tag == "minDepth":
                    surface.min_depth = _float(text, what, source)
                elif tag == "fdir1":
                    surface.fdir1 = _direction(text, what, source)
                elif tag == "material":
                    surface.material = text
                elif tag == "selfCollide":
                    surface.self_collide = _bool(text)
                elif tag in ("gravity", "turnGravityOff"):
                    surface.gravity = _bool(text) if tag == "gravity" else not _bool(text)
                else:  # maxVel, maxContacts, dampingFactor, laserRetro, ...
                    not_emulated.setdefault(tag, f"link '{reference}'")
    return GazeboTags(surfaces, plugins, sensors, robot_self_collide, not_emulated,
                      unknown_references)


def plugin_joint_names(spec: PluginSpec, tags: Tuple[str, ...]) -> List[str]:
    return [spec.params[tag] for tag in tags if tag in spec.params]
