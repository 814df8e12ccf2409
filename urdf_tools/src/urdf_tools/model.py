"""A URDF document read into plain Python objects.

Everything that reads a robot description in this workspace goes through here: the
simulator (links, joints, ``<gazebo>`` blocks, transmissions), the arm planner (the
kinematic chain) and the description tests (sizes, masses, inertias). The parser checks
what URDF requires (names, parents, a single root) and raises :class:`UrdfError` naming
the source and the problem, so that a broken file is reported, not half-loaded.
"""
from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Tuple

Vector3 = Tuple[float, float, float]


class UrdfError(ValueError):
    """A robot description that cannot be used; the message names the source and why."""


@dataclass(frozen=True)
class Origin:
    """An ``<origin>``: translation in metres, roll-pitch-yaw in radians."""

    xyz: Vector3 = (0.0, 0.0, 0.0)
    rpy: Vector3 = (0.0, 0.0, 0.0)


@dataclass(frozen=True)
class Geometry:
    """One ``<geometry>``. ``kind`` is box, cylinder, sphere or mesh.

    box: ``size`` (x, y, z); cylinder: ``radius``, ``length`` (along z); sphere: ``radius``;
    mesh: ``filename``, ``scale``.
    """

    kind: str
    size: Optional[Vector3] = None
    radius: Optional[float] = None
    length: Optional[float] = None
    filename: Optional[str] = None
    scale: Vector3 = (1.0, 1.0, 1.0)


@dataclass(frozen=True)
class Shape:
    """A ``<visual>`` or ``<collision>``: a geometry placed in its link's frame."""

    geometry: Geometry
    origin: Origin = Origin()
    material: Optional[str] = None


@dataclass(frozen=True)
class Inertial:
    """Mass in kg; inertia tensor (kg m^2) about the centre of mass, in the ``origin`` frame."""

    mass: float
    ixx: float
    ixy: float
    ixz: float
    iyy: float
    iyz: float
    izz: float
    origin: Origin = Origin()

    @property
    def tensor(self) -> Tuple[Vector3, Vector3, Vector3]:
        return ((self.ixx, self.ixy, self.ixz),
                (self.ixy, self.iyy, self.iyz),
                (self.ixz, self.iyz, self.izz))


@dataclass(frozen=True)
class Link:
    name: str
    visuals: Tuple[Shape, ...] = ()
    collisions: Tuple[Shape, ...] = ()
    inertial: Optional[Inertial] = None


@dataclass(frozen=True)
class Limit:
    lower: float = 0.0
    upper: float = 0.0
    effort: float = 0.0
    velocity: float = 0.0


@dataclass(frozen=True)
class Joint:
    name: str
    type: str
    parent: str
    child: str
    origin: Origin = Origin()
    axis: Vector3 = (1.0, 0.0, 0.0)
    limit: Optional[Limit] = None
    damping: float = 0.0
    friction: float = 0.0

    @property
    def movable(self) -> bool:
        return self.type not in ("fixed", "floating", "planar")


@dataclass(frozen=True)
class Transmission:
    """A ros_control ``<transmission>``: which joints, and through which interface."""

    name: str
    joints: Tuple[str, ...]
    hardware_interfaces: Tuple[str, ...]


@dataclass
class RobotModel:
    """A parsed URDF. ``gazebo`` keeps each ``<gazebo>`` element for the simulator to read:
    a list of (reference or None, element)."""

    name: str
    links: Dict[str, Link]
    joints: Dict[str, Joint]
    materials: Dict[str, Tuple[float, float, float, float]] = field(default_factory=dict)
    gazebo: List[Tuple[Optional[str], ET.Element]] = field(default_factory=list)
    transmissions: List[Transmission] = field(default_factory=list)
    source: str = "<string>"

    def root(self) -> str:
        children = {j.child for j in self.joints.values()}
        roots = [name for name in self.links if name not in children]
        return roots[0]

    def parent_joint(self, link: str) -> Optional[Joint]:
        for joint in self.joints.values():
            if joint.child == link:
                return joint
        return None

    def chain(self, base: str, tip: str) -> List[Joint]:
        """The joints from ``base`` down to ``tip`` (``base`` must be an ancestor of ``tip``)."""
        joints: List[Joint] = []
        link = tip
        while link != base:
            joint = self.parent_joint(link)
            if joint is None:
                raise UrdfError(f"{self.source}: link '{base}' is not an ancestor of '{tip}'")
            joints.append(joint)
            link = joint.parent
        return list(reversed(joints))

    def total_mass(self) -> float:
        return sum(link.inertial.mass for link in self.links.values() if link.inertial)

    def gazebo_properties(self, reference: str) -> Dict[str, str]:
        """The simple ``<gazebo reference=...>`` children (material, mu1, kp...) as text."""
        props: Dict[str, str] = {}
        for ref, element in self.gazebo:
            if ref == reference:
                for child in element:
                    if len(child) == 0 and child.text is not None:
                        props[child.tag] = child.text.strip()
        return props


def _floats(text: Optional[str], count: int, what: str, source: str) -> Tuple[float, ...]:
    if text is None:
        return tuple([0.0] * count)
    parts = text.split()
    try:
        values = tuple(float(p) for p in parts)
    except ValueError:
        raise UrdfError(f"{source}: {what} '{text}' is not {count} numbers") from None
    if len(values) != count or not all(math.isfinite(v) for v in values):
        raise UrdfError(f"{source}: {what} '{text}' is not {count} finite numbers")
    return values


def _number(element: ET.Element, attribute: str, what: str, source: str,
            default: Optional[float] = None) -> float:
    text = element.get(attribute)
    if text is None:
        if default is None:
            raise UrdfError(f"{source}: {what} has no '{attribute}' attribute")
        return default
    return _floats(text, 1, f"{what} {attribute}", source)[0]


def _origin(element: Optional[ET.Element], what: str, source: str) -> Origin:
    if element is None:
        return Origin()
    return Origin(_floats(element.get("xyz"), 3, f"{what} origin xyz", source),
                  _floats(element.get("rpy"), 3, f"{what} origin rpy", source))


def _geometry(element: Optional[ET.Element], what: str, source: str) -> Geometry:
    if element is None or len(element) == 0:
        raise UrdfError(f"{source}: {what} has no <geometry>")
    shape = element[0]
    if shape.tag == "box":
        return Geometry("box", size=_floats(shape.get("size"), 3, f"{what} box size", source))
    if shape.tag == "cylinder":
        return Geometry("cylinder", radius=_number(shape, "radius", f"{what} cylinder", source),
                        length=_number(shape, "length", f"{what} cylinder", source))
    if shape.tag == "sphere":
        return Geometry("sphere", radius=_number(shape, "radius", f"{what} sphere", source))
    if shape.tag == "mesh":
        filename = shape.get("filename")
        if not filename:
            raise UrdfError(f"{source}: {what} mesh has no filename")
        scale = _floats(shape.get("scale"), 3, f"{what} mesh scale", source) \
            if shape.get("scale") else (1.0, 1.0, 1.0)
        return Geometry("mesh", filename=filename, scale=scale)
    raise UrdfError(f"{source}: {what} has an unknown geometry <{shape.tag}>")


def _material_name(element: ET.Element, materials: Dict, source: str) -> Optional[str]:
    material = element.find("material")
    if material is None:
        return None
    name = material.get("name", "")
    color = material.find("color")
    if color is not None:
        materials[name] = _floats(color.get("rgba"), 4, f"material '{name}' rgba", source)
    return name


def _link(element: ET.Element, materials: Dict, source: str) -> Link:
    name = element.get("name")
    if not name:
        raise UrdfError(f"{source}: a <link> has no name")
    visuals = []
    for index, visual in enumerate(element.findall("visual")):
        what = f"link '{name}' visual {index}"
        visuals.append(Shape(_geometry(visual.find("geometry"), what, source),
                             _origin(visual.find("origin"), what, source),
                             _material_name(visual, materials, source)))
    collisions = []
    for index, collision in enumerate(element.findall("collision")):
        what = f"link '{name}' collision {index}"
        collisions.append(Shape(_geometry(collision.find("geometry"), what, source),
                                _origin(collision.find("origin"), what, source)))
    inertial = None
    inertial_element = element.find("inertial")
    if inertial_element is not None:
        what = f"link '{name}' inertial"
        mass_element = inertial_element.find("mass")
        tensor = inertial_element.find("inertia")
        if mass_element is None or tensor is None:
            raise UrdfError(f"{source}: {what} needs <mass> and <inertia>")
        inertial = Inertial(
            mass=_number(mass_element, "value", f"{what} mass", source),
            **{key: _number(tensor, key, f"{what} inertia", source)
               for key in ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")},
            origin=_origin(inertial_element.find("origin"), what, source))
    return Link(name, tuple(visuals), tuple(collisions), inertial)


_JOINT_TYPES = ("revolute", "continuous", "prismatic", "fixed", "floating", "planar")


def _joint(element: ET.Element, source: str) -> Joint:
    name = element.get("name")
    if not name:
        raise UrdfError(f"{source}: a <joint> has no name")
    joint_type = element.get("type")
    if joint_type not in _JOINT_TYPES:
        raise UrdfError(f"{source}: joint '{name}' has type '{joint_type}'; "
                        f"URDF knows {', '.join(_JOINT_TYPES)}")
    parent, child = element.find("parent"), element.find("child")
    if parent is None or child is None or not parent.get("link") or not child.get("link"):
        raise UrdfError(f"{source}: joint '{name}' needs <parent link=...> and <child link=...>")
    axis_element = element.find("axis")
    axis = _floats(axis_element.get("xyz"), 3, f"joint '{name}' axis", source) \
        if axis_element is not None else (1.0, 0.0, 0.0)
    limit = None
    limit_element = element.find("limit")
    if limit_element is not None:
        what = f"joint '{name}' limit"
        limit = Limit(lower=_number(limit_element, "lower", what, source, 0.0),
                      upper=_number(limit_element, "upper", what, source, 0.0),
                      effort=_number(limit_element, "effort", what, source, 0.0),
                      velocity=_number(limit_element, "velocity", what, source, 0.0))
    elif joint_type in ("revolute", "prismatic"):
        raise UrdfError(f"{source}: {joint_type} joint '{name}' needs a <limit>")
    dynamics = element.find("dynamics")
    damping = friction = 0.0
    if dynamics is not None:
        damping = _number(dynamics, "damping", f"joint '{name}' dynamics", source, 0.0)
        friction = _number(dynamics, "friction", f"joint '{name}' dynamics", source, 0.0)
    return Joint(name, joint_type, parent.get("link"), child.get("link"),
                 _origin(element.find("origin"), f"joint '{name}'", source),
                 axis, limit, damping, friction)


def _transmission(element: ET.Element) -> Transmission:
    joints, interfaces = [], []
    for joint in element.findall("joint"):
        joints.append(joint.get("name", ""))
        interfaces.extend(h.text.strip() for h in joint.findall("hardwareInterface") if h.text)
    return Transmission(element.get("name", ""), tuple(joints), tuple(interfaces))


def parse_urdf(text: str, source: str = "<string>") -> RobotModel:
    """Parses URDF text; ``source`` (a file name) is named in every error."""
    try:
        root = ET.fromstring(text)
    except ET.ParseError as error:
        raise UrdfError(f"{source}: not well-formed XML: {error}") from None
    if root.tag != "robot":
        raise UrdfError(f"{source}: the top element is <{root.tag}>, not <robot>")
    materials: Dict[str, Tuple[float, float, float, float]] = {}
    for material in root.findall("material"):
        color = material.find("color")
        if color is not None:
            materials[material.get("name", "")] = _floats(
                color.get("rgba"), 4, f"material '{material.get('name')}' rgba", source)
    links: Dict[str, Link] = {}
    for element in root.findall("link"):
        link = _link(element, materials, source)
        if link.name in links:
            raise UrdfError(f"{source}: link '{link.name}' is defined twice")
        links[link.name] = link
    if not links:
        raise UrdfError(f"{source}: the robot has no links")
    joints: Dict[str, Joint] = {}
    children = set()
    for element in root.findall("joint"):
        joint = _joint(element, source)
        if joint.name in joints:
            raise UrdfError(f"{source}: joint '{joint.name}' is defined twice")
        for end in (joint.parent, joint.child):
            if end not in links:
                raise UrdfError(f"{source}: joint '{joint.name}' names link '{end}', "
                                "which is not defined")
        if joint.child in children:
            raise UrdfError(f"{source}: link '{joint.child}' has two parent joints")
        children.add(joint.child)
        joints[joint.name] = joint
    roots = [name for name in links if name not in children]
    if len(roots) != 1:
        raise UrdfError(f"{source}: the links must form one tree; roots found: {roots}")
    gazebo = [(element.get("reference"), element) for element in root.findall("gazebo")]
    transmissions = [_transmission(t) for t in root.findall("transmission")]
    return RobotModel(root.get("name", ""), links, joints, materials, gazebo, transmissions,
                      source)


def load_urdf(path: str) -> RobotModel:
    """Reads and parses a URDF file (plain URDF; see :mod:`urdf_tools.xacro_loader`)."""
    with open(path, encoding="utf-8") as stream:
        return parse_urdf(stream.read(), source=path)
