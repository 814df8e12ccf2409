"""A URDF document read into plain Python objects.

Everything that reads a robot description in this workspace goes through here: the
simulator (links, joints, ``<gazebo>`` blocks, transmissions), the arm planner (the
kinematic chain) and the description tests (sizes, masses, inertias).

The parsing is ``urdf_parser_py``'s (PyPI ``urdfdom-py``), the reader ROS's own Python
tools use; its objects are converted into the frozen dataclasses below. What it does not
keep or does not check is done here:

- ``<gazebo>`` blocks (it drops them) and ``<transmission>`` elements are read with
  ElementTree from the same text. Transmissions are ros_control's, not urdfdom's: C++
  urdfdom ignores them and gazebo_ros_control skips a bad one, whereas urdf_parser_py
  refuses the whole robot over, say, a transmission without ``<actuator>``.
- What it prints to stderr (unknown elements, an element given twice) becomes a warning
  naming the source, logged and kept in :attr:`RobotModel.warnings`.
- What URDF requires and it lets through (a known joint type, joint ends that exist, one
  root, unique names, finite numbers) and what is physically impossible (a negative mass,
  a moving link of 0 kg, a shape of no size) raise :class:`UrdfError` naming the source,
  the link or joint and the value, so that a broken file is reported, not half-loaded.
- The size limits below keep a runaway generator from taking the simulator down.
"""
from __future__ import annotations

import contextlib
import dataclasses
import logging
import math
import os
import re
import threading
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from typing import Dict, Iterable, Iterator, List, Optional, Sequence, Tuple

import numpy
from lxml import etree as lxml_etree

try:
    from urdf_parser_py import urdf as upp
    from urdf_parser_py import xml_reflection as upp_reflection
    from urdf_parser_py.xml_reflection import core as upp_core
except ImportError as _error:  # pragma: no cover - an installation fault, named for the user
    raise ImportError("urdf_tools needs urdf_parser_py (PyPI urdfdom-py 1.2.1, listed in "
                      "tools/requirements.txt): run 'make' in the workspace, which installs "
                      "it into .venv, then 'source tools/env.bash'") from _error

Vector3 = Tuple[float, float, float]

LOG = logging.getLogger(__name__)

# The most links, and joints, a description may have. pybullet crashes (segfault) loading a
# body of about 7000 links (5000 still load); the biggest robot of the courses has 14. A
# thousand leaves room for any real robot and refuses a runaway xacro loop first.
MAX_LINKS = 1000
MAX_JOINTS = 1000
# The largest description accepted, in bytes of UTF-8 text. The workspace's biggest is
# about 13 kB: one of 10 MiB is a generator gone wrong or meshes inlined, and is refused
# before it is parsed (twice: ElementTree and lxml) and held in memory as objects.
MAX_DESCRIPTION_BYTES = 10 * 1024 * 1024


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
    # its name attribute, "" for none (URDF allows one; sdformat names a collision after it)
    name: str = ""


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
class SafetyController:
    """A ``<safety_controller>``: soft position limits and the gains that keep a joint
    inside them (urdfdom's JointSafety; ros_control reads it as SoftJointLimits)."""

    k_velocity: float
    k_position: float = 0.0
    soft_lower_limit: float = 0.0
    soft_upper_limit: float = 0.0


@dataclass(frozen=True)
class Mimic:
    """A ``<mimic>``: the joint's position is ``multiplier`` * ``joint``'s + ``offset``."""

    joint: str
    multiplier: float = 1.0
    offset: float = 0.0


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
    mimic: Optional[Mimic] = None
    safety: Optional[SafetyController] = None

    @property
    def movable(self) -> bool:
        return self.type not in ("fixed", "floating", "planar")


@dataclass(frozen=True)
class Transmission:
    """A ros_control ``<transmission>``: which joints, and through which interface.
    ``type`` is the ``<type>`` text (None without the element, "" when empty),
    ``joint_interfaces`` each joint's own ``<hardwareInterface>`` texts and ``actuators`` the
    ``<actuator>`` elements' names (None without the attribute), for ros_control's
    transmission parser, which skips a transmission lacking them."""

    name: str
    joints: Tuple[str, ...]
    hardware_interfaces: Tuple[str, ...]
    type: Optional[str] = None
    joint_interfaces: Tuple[Tuple[str, ...], ...] = ()
    actuators: Tuple[Optional[str], ...] = ()


@dataclass
class RobotModel:
    """A parsed URDF. ``gazebo`` keeps each ``<gazebo>`` element (an ElementTree element)
    for the simulator to read: a list of (reference or None, element)."""

    name: str
    links: Dict[str, Link]
    joints: Dict[str, Joint]
    materials: Dict[str, Tuple[float, float, float, float]] = field(default_factory=dict)
    gazebo: List[Tuple[Optional[str], ET.Element]] = field(default_factory=list)
    transmissions: List[Transmission] = field(default_factory=list)
    source: str = "<string>"
    # What was accepted but looks wrong (an unknown element, an inertia tensor that is not
    # positive definite), one sentence each naming the source; also logged.
    warnings: List[str] = field(default_factory=list)

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



_JOINT_TYPES = ("revolute", "continuous", "prismatic", "fixed", "floating", "planar")
_SHAPES = ("box", "cylinder", "sphere", "mesh")

# --- urdf_parser_py: its chatter captured, its refusals explained -----------------------

# urdf_parser_py reports through a module-level function (xml_reflection.on_error, bound
# in two modules) that writes to stderr; it is swapped for a collector while we parse. The
# lock keeps two threads (a simulator's service callbacks) from swapping it at once.
_PARSER_LOCK = threading.Lock()


@contextlib.contextmanager
def _captured_chatter() -> Iterator[List[str]]:
    messages: List[str] = []
    with _PARSER_LOCK:
        saved = upp_reflection.on_error, upp_core.on_error
        upp_reflection.on_error = upp_core.on_error = messages.append
        try:
            yield messages
        finally:
            upp_reflection.on_error, upp_core.on_error = saved


# urdf_parser_py's reasons, said the way the rest of our messages say things.
_REASONS = (
    (re.compile(r"Required attribute not set in XML: (\w+)"), r"has no '\1' attribute"),
    (re.compile(r"Required element not set in XML: (\w+)"), r"has no <\1>"),
    (re.compile(r"Invalid vector length"), "has the wrong number of values"),
    (re.compile(r"Invalid joint type: (.*)"),
     r"has type '\1'; URDF knows " + ", ".join(_JOINT_TYPES)),
    (re.compile(r"One element only for geometric"),
     "needs exactly one shape: " + ", ".join(_SHAPES)),
    (re.compile(r"Invalid geometric tag: (\w+)"),
     r"has an unknown shape <\1>; URDF knows " + ", ".join(_SHAPES)),
    (re.compile(r"could not convert string to float: (.*)"), r"\1 is not a number"),
    (re.compile(r"float\(\) argument must be .*'NoneType'"), "has no value"),
)
_CHATTER = (
    (re.compile(r'Unknown tag "(.+)" in (.*)'), r"\2: unknown element <\1>, ignored"),
    (re.compile(r'Unknown attribute "(.+)" in (.*)'), r"\2: unknown attribute '\1', ignored"),
    (re.compile(r"Scalar element defined multiple times: (.*)"),
     r"an element has <\1> more than once; the first is used"),
)
_PATH_STEP = re.compile(r"/([^/\[]+)((?:\[[^\]]*\])*)")


def _reason(error: BaseException) -> str:
    text = str(error).strip()
    for pattern, replacement in _REASONS:
        if pattern.search(text):
            return pattern.sub(replacement, text, count=1)
    return text


def _words(tag: str, name: Optional[str], index: Optional[int]) -> str:
    """``link 'base'``, ``visual 0`` or ``inertial``: how our messages name an element."""
    if name is not None:
        return f"{tag} '{name}'"
    return tag if index is None else f"{tag} {index}"


def _path_words(path: str) -> str:
    """urdf_parser_py's XPath-like location (``/robot[@name='r']/link[@name='a']/visual[1]``)
    in our words (``link 'a' visual 0``)."""
    words = []
    for tag, suffix in _PATH_STEP.findall(path):
        if tag == "robot":
            continue
        name = re.search(r"\[@name='([^']*)'\]", suffix)
        index = re.search(r"\[(\d+)\]", suffix)
        words.append(_words(tag, name.group(1) if name else None,
                            int(index.group(1)) - 1 if index else None))
    return " ".join(words) or "robot"


def _chatter_warning(message: str) -> str:
    for pattern, replacement in _CHATTER:
        match = pattern.fullmatch(message.strip())
        if match:
            text = match.expand(replacement)
            if pattern.groups == 2:  # the location comes first: put it in our words
                location, _, rest = text.partition(": ")
                text = f"{_path_words(location)}: {rest}"
            return text
    return message.strip()


def _locate(cls, node, words: List[str]):
    """Where urdf_parser_py's refusal of ``node`` (read as ``cls``) lies: each child element
    is read again on its own, and the deepest one it refuses is returned as
    (words naming it, element, exception, attribute or None); None when every child reads."""
    seen: Dict[str, int] = {}
    for child in node:
        param = cls.XML_REFL.element_map.get(child.tag)
        if param is None:
            continue
        index = seen[child.tag] = seen.get(child.tag, -1) + 1
        here = words + [_words(child.tag, child.get("name") if param.is_aggregate else None,
                               index if param.is_aggregate else None)]
        value_type = param.value_type
        try:
            value_type.from_xml(child, upp_core.Path(child.tag))
            continue
        except Exception as error:  # urdf_parser_py raises many kinds; all mean "refused"
            failure = error
        if isinstance(value_type, upp_core.ObjectType):
            return _locate(value_type.type, child, here) or (here, child, failure, None)
        if isinstance(value_type, upp_core.SimpleElementType):
            return here, child, failure, value_type.attribute
        shapes = list(child)
        if isinstance(value_type, upp.GeometricType) and len(shapes) == 1:
            return here + [shapes[0].tag], shapes[0], failure, None
        return here, child, failure, None
    return None


def _refusal(error: Exception, root, source: str) -> UrdfError:
    """urdf_parser_py's ``error`` for the document ``root`` as our UrdfError: which element,
    which attribute and its text, and why."""
    words, element, failure, attribute = (_locate(upp.URDF, root, [])
                                          or (["robot"], root, error, None))
    if isinstance(failure, upp_core.ParseError):
        named = re.search(r"\[@(\w+)\]$", str(failure.path))
        attribute = named.group(1) if named else attribute
        failure = failure.e
    where = " ".join(words)
    if attribute is not None and element.get(attribute) is not None:
        where += f" {attribute} '{element.get(attribute)}'"
    return UrdfError(f"{source}: {where}: {_reason(failure)}")


def _read(text: str, source: str):
    """The document read by urdf_parser_py, and its chatter as our warnings."""
    # Comments and processing instructions are not elements; urdf_parser_py would take a
    # processing instruction for an unknown tag. The text has passed ElementTree, which
    # refuses external entities, so lxml expands only internal ones, as ElementTree does.
    parser = lxml_etree.XMLParser(encoding="utf-8", remove_comments=True, remove_pis=True)
    try:
        root = lxml_etree.fromstring(text.encode("utf-8"), parser)
    except lxml_etree.XMLSyntaxError as error:
        raise UrdfError(f"{source}: not well-formed XML: {error}") from None
    for tag in ("gazebo", "transmission"):  # read with ElementTree (see the module's doc)
        for element in root.findall(tag):
            root.remove(element)
    ignored = _first_shape_only(root, source)
    with _captured_chatter() as chatter:
        try:
            robot = upp.URDF.from_xml(root, upp_core.Path(upp.URDF.XML_REFL.tag))
        except Exception as error:  # urdf_parser_py raises many kinds; all mean "refused"
            raise _refusal(error, root, source) from None
    return robot, ignored + [f"{source}: {_chatter_warning(message)}" for message in chatter]


def _first_shape_only(root, source: str) -> List[str]:
    """Each ``<geometry>`` read as urdfdom reads it (the parser behind Gazebo's URDF
    import, sdformat sdf9 66a8c21 src/urdf/urdf_parser/link.cpp:229-275, and robot_state_
    publisher's and rviz's): its first child element is the shape, whatever follows it is
    not looked at. Public descriptions put a ``<material>`` inside a mesh's geometry, which
    Gazebo loads without a word; urdf_parser_py refuses the robot for it ("One element only
    for geometric"). The elements after the shape are removed here, each named in a
    warning. A first element that is not a shape is refused, as urdfdom refuses it
    ("Unknown geometry type") and Gazebo then spawns nothing."""
    warnings = []
    for link in root.iterfind("link"):
        for kind in ("visual", "collision"):
            for index, holder in enumerate(link.iterfind(kind)):
                geometry = holder.find("geometry")
                children = [] if geometry is None else \
                    [child for child in geometry if isinstance(child.tag, str)]
                if len(children) < 2:
                    continue  # urdf_parser_py reads one element as urdfdom does
                where = f"{source}: link '{link.get('name')}' {kind} {index} geometry"
                if children[0].tag not in _SHAPES:
                    raise UrdfError(
                        f"{where}: its first element is <{children[0].tag}>, not a shape ("
                        f"{', '.join(_SHAPES)}); Gazebo's URDF reader (urdfdom) takes the "
                        "first element as the shape and refuses the robot ('Unknown geometry "
                        "type'): put the shape first")
                for child in children[1:]:
                    geometry.remove(child)
                names = ", ".join(f"<{child.tag}>" for child in children[1:])
                warnings.append(
                    f"{where}: {names} after the <{children[0].tag}> ignored; the shape is "
                    "the geometry's first element, as Gazebo's URDF reader (urdfdom) takes it")
    return warnings


# --- conversion into the dataclasses, with the checks urdf_parser_py does not make ------

def _finite(values: Sequence[float], what: str, source: str) -> Tuple[float, ...]:
    numbers = tuple(float(v) for v in values)
    if not all(math.isfinite(v) for v in numbers):
        raise UrdfError(f"{source}: {what} '{' '.join(f'{v:g}' for v in numbers)}' is not "
                        f"{len(numbers)} finite number{'s' if len(numbers) > 1 else ''}")
    return numbers


def _positive(values: Sequence[float], what: str, source: str) -> Tuple[float, ...]:
    numbers = _finite(values, what, source)
    if not all(v > 0 for v in numbers):
        raise UrdfError(f"{source}: {what} '{' '.join(f'{v:g}' for v in numbers)}' must be "
                        "positive: a shape without size cannot collide or be drawn")
    return numbers


def _origin(pose, what: str, source: str) -> Origin:
    if pose is None:
        return Origin()
    return Origin(_finite(pose.xyz or (0, 0, 0), f"{what} origin xyz", source),
                  _finite(pose.rpy or (0, 0, 0), f"{what} origin rpy", source))


def _geometry(shape, what: str, source: str) -> Geometry:
    if isinstance(shape, upp.Box):
        return Geometry("box", size=_positive(shape.size, f"{what} box size", source))
    if isinstance(shape, upp.Cylinder):
        return Geometry("cylinder",
                        radius=_positive([shape.radius], f"{what} cylinder radius", source)[0],
                        length=_positive([shape.length], f"{what} cylinder length", source)[0])
    if isinstance(shape, upp.Sphere):
        return Geometry("sphere",
                        radius=_positive([shape.radius], f"{what} sphere radius", source)[0])
    if isinstance(shape, upp.Mesh):
        if not shape.filename:
            raise UrdfError(f"{source}: {what} mesh has no filename")
        scale = _finite(shape.scale, f"{what} mesh scale", source) \
            if shape.scale is not None else (1.0, 1.0, 1.0)
        return Geometry("mesh", filename=shape.filename, scale=scale)
    raise UrdfError(f"{source}: {what} has no <geometry>")


def _remember_colour(material, materials: Dict, source: str) -> None:
    if material is not None and material.color is not None:
        materials[material.name] = _finite(material.color.rgba,
                                           f"material '{material.name}' rgba", source)


def _link(link, materials: Dict, source: str) -> Link:
    name = link.name
    if not name:
        raise UrdfError(f"{source}: a <link> has no name")
    visuals = []
    for index, visual in enumerate(link.visuals):
        what = f"link '{name}' visual {index}"
        _remember_colour(visual.material, materials, source)
        visuals.append(Shape(_geometry(visual.geometry, what, source),
                             _origin(visual.origin, what, source),
                             visual.material.name if visual.material is not None else None))
    collisions = []
    for index, collision in enumerate(link.collisions):
        what = f"link '{name}' collision {index}"
        collisions.append(Shape(_geometry(collision.geometry, what, source),
                                _origin(collision.origin, what, source)))
    inertial = None
    if link.inertial is not None:
        what = f"link '{name}' inertial"
        tensor = link.inertial.inertia
        if tensor is None:
            raise UrdfError(f"{source}: {what} needs <mass> and <inertia>")
        mass = _finite([link.inertial.mass], f"{what} mass", source)[0]
        if mass < 0:
            raise UrdfError(f"{source}: link '{name}' has a negative mass ({mass:g} kg); "
                            "a mass must be positive")
        moments = _finite([getattr(tensor, key) for key in upp.Inertia.KEYS],
                          f"{what} inertia", source)
        inertial = Inertial(mass, *moments, origin=_origin(link.inertial.origin, what, source))
    return Link(name, tuple(visuals), tuple(collisions), inertial)


def _joint(joint, source: str) -> Joint:
    name = joint.name
    if not name:
        raise UrdfError(f"{source}: a <joint> has no name")
    if joint.type not in _JOINT_TYPES:
        raise UrdfError(f"{source}: joint '{name}' has type '{joint.type}'; "
                        f"URDF knows {', '.join(_JOINT_TYPES)}")
    if not joint.parent or not joint.child:
        raise UrdfError(f"{source}: joint '{name}' needs <parent link=...> and <child link=...>")
    axis = _finite(joint.axis, f"joint '{name}' axis", source) \
        if joint.axis is not None else (1.0, 0.0, 0.0)
    limit = None
    if joint.limit is not None:
        limit = Limit(*_finite([joint.limit.lower or 0.0, joint.limit.upper or 0.0,
                                joint.limit.effort, joint.limit.velocity],
                               f"joint '{name}' limit (lower upper effort velocity)", source))
    elif joint.type in ("revolute", "prismatic"):
        raise UrdfError(f"{source}: {joint.type} joint '{name}' needs a <limit>")
    damping = friction = 0.0
    if joint.dynamics is not None:
        damping, friction = _finite([joint.dynamics.damping or 0.0,
                                     joint.dynamics.friction or 0.0],
                                    f"joint '{name}' dynamics (damping friction)", source)
    mimic = None
    if joint.mimic is not None and joint.mimic.joint:
        multiplier, offset = _finite(
            [1.0 if joint.mimic.multiplier is None else joint.mimic.multiplier,
             joint.mimic.offset or 0.0], f"joint '{name}' mimic (multiplier offset)", source)
        mimic = Mimic(joint.mimic.joint, multiplier, offset)
    safety = None
    if joint.safety_controller is not None:
        controller = joint.safety_controller
        safety = SafetyController(*_finite(
            [controller.k_velocity, controller.k_position or 0.0,
             controller.soft_lower_limit or 0.0, controller.soft_upper_limit or 0.0],
            f"joint '{name}' safety_controller (k_velocity k_position soft_lower_limit "
            "soft_upper_limit)", source))
    return Joint(name, joint.type, joint.parent, joint.child,
                 _origin(joint.origin, f"joint '{name}'", source), axis, limit, damping,
                 friction, mimic, safety)


def _transmission(element: ET.Element) -> Transmission:
    joints, interfaces, per_joint = [], [], []
    for joint in element.findall("joint"):
        joints.append(joint.get("name", ""))
        own = tuple(h.text.strip() for h in joint.findall("hardwareInterface") if h.text)
        interfaces.extend(own)
        per_joint.append(own)
    kind = element.find("type")
    return Transmission(element.get("name", ""), tuple(joints), tuple(interfaces),
                        None if kind is None else (kind.text or "").strip(), tuple(per_joint),
                        tuple(a.get("name") for a in element.findall("actuator")))


def _tree(links: Dict[str, Link], joint_list: Iterable[Joint], source: str) -> Dict[str, Joint]:
    """The joints by name, once each is known to join two defined links into one tree."""
    joints: Dict[str, Joint] = {}
    children = set()
    for joint in joint_list:
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
    return joints


def _check_masses(model: RobotModel, warnings: List[str]) -> None:
    """A link that moves on its own joint with nothing weighing anything in it is refused;
    odd inertias are warned about (Gazebo simulates them too)."""
    source = model.source
    fixed_children: Dict[str, List[str]] = {}
    for joint in model.joints.values():
        if joint.type == "fixed":
            fixed_children.setdefault(joint.parent, []).append(joint.child)

    def body_mass(link: str) -> float:
        # Gazebo lumps links on fixed joints into their parent before it drops the
        # links of no mass: the body is the link and all that is fixed to it (walked
        # without recursion: a fixed chain may be MAX_LINKS long).
        mass, pending = 0.0, [link]
        while pending:
            name = pending.pop()
            inertial = model.links[name].inertial
            mass += inertial.mass if inertial is not None else 0.0
            pending.extend(fixed_children.get(name, ()))
        return mass

    for name, link in model.links.items():
        if link.inertial is None or link.inertial.mass != 0 or body_mass(name) > 0:
            continue
        joint = model.parent_joint(name)
        if joint is None:
            warnings.append(f"{source}: root link '{name}' weighs 0 kg: Gazebo leaves a "
                            "root of no mass, and so the whole robot, out; pybullet fixes it "
                            "in place")
        elif joint.type != "fixed":
            raise UrdfError(f"{source}: link '{name}' has a mass of 0 kg but moves on "
                            f"{joint.type} joint '{joint.name}': a body that moves needs a "
                            "positive mass (Gazebo leaves it and all below it out); give "
                            "the link its mass, or fix it to its parent")
    for name, link in model.links.items():
        if link.inertial is None or link.inertial.mass <= 0:
            continue
        moments = numpy.linalg.eigvalsh(numpy.array(link.inertial.tensor))
        if moments.min() <= 0:
            # ODE (Gazebo) and pybullet warn and simulate it; real robots' exported
            # descriptions often carry such tensors, so it is not refused.
            values = " ".join(f"{key}={getattr(link.inertial, key):g}" for key in upp.Inertia.KEYS)
            warnings.append(f"{source}: link '{name}' inertia ({values}) is not positive "
                            "definite (principal moments "
                            f"{', '.join(f'{m:g}' for m in moments)}); it may spin or jitter")


def _check_size(size: int, source: str) -> None:
    if size > MAX_DESCRIPTION_BYTES:
        raise UrdfError(f"{source}: the description is {size} bytes; urdf_tools reads at most "
                        f"{MAX_DESCRIPTION_BYTES} (MAX_DESCRIPTION_BYTES, 10 MiB): a robot "
                        "description this big is a generator gone wrong or meshes inlined")


def _check_structure(root: ET.Element, source: str) -> None:
    """What is cheaper or only possible to check on the XML: the counts, before the slow
    read, and joint ends without a link (urdf_parser_py reads ``<parent/>`` as 'None')."""
    for tag, limit, name in (("link", MAX_LINKS, "MAX_LINKS"), ("joint", MAX_JOINTS, "MAX_JOINTS")):
        count = len(root.findall(tag))
        if count > limit:
            raise UrdfError(f"{source}: the robot has {count} {tag}s; urdf_tools accepts at most "
                            f"{limit} ({name}): pybullet crashes loading a body of about 7000 "
                            "links; a robot this big is a generator (a xacro loop) gone wrong")
    for joint in root.findall("joint"):
        ends = [joint.find(end) for end in ("parent", "child")]
        if any(end is not None and not end.get("link") for end in ends):
            raise UrdfError(f"{source}: joint '{joint.get('name')}' needs <parent link=...> "
                            "and <child link=...>")


def parse_urdf(text: str, source: str = "<string>") -> RobotModel:
    """Parses URDF text; ``source`` (a file name) is named in every error and warning."""
    # A text longer in characters than the limit is longer in bytes: no need to encode it.
    _check_size(len(text) if len(text) > MAX_DESCRIPTION_BYTES else len(text.encode("utf-8")),
                source)
    try:
        root = ET.fromstring(text)
    except ET.ParseError as error:
        raise UrdfError(f"{source}: not well-formed XML: {error}") from None
    if root.tag != "robot":
        raise UrdfError(f"{source}: the top element is <{root.tag}>, not <robot>")
    _check_structure(root, source)
    robot, warnings = _read(text, source)
    # urdf_parser_py knows no name of a visual or collision, which URDF allows (urdfdom
    # reads it): not a fault of the file; the names are read below
    warnings = [w for w in warnings if not _SHAPE_NAME_CHATTER.search(w)]
    materials: Dict[str, Tuple[float, float, float, float]] = {}
    for material in robot.materials:
        _remember_colour(material, materials, source)
    links: Dict[str, Link] = {}
    for element in robot.links:
        link = _link(element, materials, source)
        if link.name in links:
            raise UrdfError(f"{source}: link '{link.name}' is defined twice")
        links[link.name] = link
    if not links:
        raise UrdfError(f"{source}: the robot has no links")
    _name_collisions(root, links)
    joints = _tree(links, (_joint(joint, source) for joint in robot.joints), source)
    gazebo = [(element.get("reference"), element) for element in root.findall("gazebo")]
    transmissions = [_transmission(t) for t in root.findall("transmission")]
    model = RobotModel(robot.name, links, joints, materials, gazebo, transmissions, source)
    _check_masses(model, warnings)
    for warning in warnings:
        LOG.warning("%s", warning)
    model.warnings = warnings
    return model


_SHAPE_NAME_CHATTER = re.compile(r"(visual|collision) \d+: unknown attribute 'name', ignored$")


def _name_collisions(root: ET.Element, links: Dict[str, Link]) -> None:
    """Each link's collisions get their name attributes (document order, as urdf_parser_py
    reads them)."""
    for element in root.findall("link"):
        link = links.get(element.get("name", ""))
        names = [c.get("name", "") for c in element.findall("collision")]
        if link is None or len(names) != len(link.collisions) or not any(names):
            continue
        links[link.name] = dataclasses.replace(link, collisions=tuple(
            dataclasses.replace(shape, name=name) for shape, name in zip(link.collisions, names)))


def load_urdf(path: str) -> RobotModel:
    """Reads and parses a URDF file (plain URDF; see :mod:`urdf_tools.xacro_loader`)."""
    _check_size(os.path.getsize(path), path)  # before reading a file of any size
    with open(path, encoding="utf-8") as stream:
        return parse_urdf(stream.read(), source=path)
