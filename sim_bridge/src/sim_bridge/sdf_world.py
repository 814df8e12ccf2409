"""Reads the SDF that Gazebo reads: worlds and models, the subset course worlds use.

A world is ``<physics>`` (step size), ``<gravity>``, ``<include>`` of ``model://NAME``
(searched in ``GAZEBO_MODEL_PATH``, then in sim_bridge's ``models/``), and ``<model>``
with ``<static>``, ``<pose>`` and links of box, cylinder, sphere, plane and mesh geometry,
and the world's lights: its ``<light>`` elements and the lights it includes (``model://sun``),
with SDF's defaults (:class:`LightSpec`), for gazebo_ros's light services; the ``<plugin>``
elements of the world and of its models, which :mod:`sim_bridge.world` loads as Gazebo's
C++ plugins (:mod:`sim_bridge.native_plugins`). Scenes and GUI are accepted and ignored.

Meshes (``model://``, ``file://`` or relative URIs) are read as Gazebo reads them, through
:mod:`sim_bridge.mesh_files`: OBJ, STL and Collada, the last converted to OBJ for pybullet
(its ``<unit>`` applied). A mesh that cannot be read does not stop the world, as in Gazebo:
a visual is left out; a collision falls back to the link's other collision shapes, else to
the bounding box of the link's readable visual meshes (with the collision's friction), else
it is dropped and the link keeps its inertial. Each case is one warning naming the model,
the link, the file and what was done; the same case in several models (a world saved from
Gazebo's GUI inlines every copy of a model) is one warning that counts them. A free model
left with no collision shape on any link falls through the ground with gravity, as in
Gazebo (whose collision with a mesh it cannot load has no shape): no shape is made up for
it, and one more warning says so, naming the model, its links and their files. Warnings go
to the ``warn`` callable given, by default to the logger ``rosout.sim_bridge``, which is
the one ``rospy.logwarn(..., logger_name="sim_bridge")`` uses: in the node they reach the
console and /rosout, without this module importing rospy.

The result is plain data (:class:`WorldSpec`, :class:`ModelSpec`); turning it into
pybullet bodies is :mod:`sim_bridge.world`'s job. Every error names the file and the
element, and for an unknown ``model://`` the folders searched.

What cannot be simulated is refused with :class:`SdfError`, with urdf_tools' limits and
words, so that a robot and a world are judged alike: a number that is not finite (a
``<pose>`` of ``nan`` would put the model nowhere; get_model_state then reported NaN), a
box side, cylinder radius or length or sphere radius of zero or less, a negative mass, a
description larger than ``urdf_tools.model.MAX_DESCRIPTION_BYTES``, an ``<include>``
that includes itself again (directly or through other models; the chain of URIs is named)
or that nests deeper than :data:`MAX_INCLUDE_DEPTH`.
"""
from __future__ import annotations

import logging
import os
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from typing import Callable, Dict, List, Optional, Sequence, Tuple, Union

from sim_bridge.heightmap import Heightmap, HeightmapError, load_heightmap
from sim_bridge.materials import gazebo_colour
from sim_bridge.mesh_files import MeshError, bounds, collision_fallback, loadable_file
from sim_bridge.poses import compose6
from sim_bridge.sdf_articulated import ArticulationError, to_urdf
# urdf_tools' own checks and limits, so that SDF and URDF are refused alike and in the same
# words (its UrdfError is turned into SdfError by _checked)
from urdf_tools.model import MAX_DESCRIPTION_BYTES, UrdfError
from urdf_tools.model import _finite as _urdf_finite
from urdf_tools.model import _positive as _urdf_positive

Pose6 = Tuple[float, float, float, float, float, float]
ZERO_POSE: Pose6 = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
PACKAGE_MODELS = os.path.normpath(os.path.join(os.path.dirname(__file__), "..", "..", "models"))
# Gazebo's defaults when a world says nothing.
DEFAULT_STEP_SIZE = 0.001
DEFAULT_GRAVITY = (0.0, 0.0, -9.8)
# The deepest nesting of <include>s followed. The model library's deepest is 1 (a world
# including a model); sdformat has no limit and recurses until Python's stack runs out
# (a RecursionError that killed the simulator at start), so a limit far above any real
# world, and far below the stack, refuses a runaway generator with a message instead.
MAX_INCLUDE_DEPTH = 16


class SdfError(ValueError):
    """A world or model that cannot be loaded; the message names the file and the cause."""


class UnsupportedModel(SdfError):
    """A well-formed model that sim_bridge cannot build (an articulated SDF model with a
    joint type it does not build, or links no joint connects). In a world it is left out
    with one warning and the world runs; spawn_sdf_model refuses it."""


def _checked(check, values, what: str, source: str) -> Tuple[float, ...]:
    """urdf_tools' ``check`` (finite, positive) of ``values``, its refusal as SdfError."""
    try:
        return check(values, what, source)
    except UrdfError as error:
        raise SdfError(str(error)) from None


def _check_size(size: int, source: str) -> None:
    """Refuses a description over urdf_tools' limit before it is parsed."""
    if size > MAX_DESCRIPTION_BYTES:
        raise SdfError(f"{source}: the SDF is {size} bytes; sim_bridge reads at most "
                       f"{MAX_DESCRIPTION_BYTES} (urdf_tools' MAX_DESCRIPTION_BYTES, 10 MiB, "
                       "as for URDF): a description this big is a generator gone wrong or "
                       "meshes inlined")


# The models being included, outermost first: (URI as written, file it resolved to).
Chain = Tuple[Tuple[str, str], ...]


Warn = Callable[[str], None]
_LOG = logging.getLogger("rosout.sim_bridge")


def _log_warning(text: str) -> None:
    _LOG.warning(text)


class _UnreadableMesh(Exception):
    """A <mesh> whose file cannot be read: its URI and why."""

    def __init__(self, uri: str, reason: str):
        super().__init__(f"{uri}: {reason}")
        self.uri, self.reason = uri, reason


class _Warnings:
    """Collects the mesh warnings of one load, so that the same case met in several models
    is said once, with a count."""

    def __init__(self) -> None:
        self.cases: Dict[tuple, List] = {}

    def add(self, key: tuple, text: str, counted: str = "link") -> None:
        """``counted``: what the copies are, in the count (a link, a model)."""
        case = self.cases.setdefault(key, [text, set(), counted])
        case[1].add(text)

    def flush(self, warn: Optional[Warn]) -> None:
        warn = warn or _log_warning
        for text, texts, counted in self.cases.values():
            more = len(texts) - 1
            warn(text + (f" (the same for {more} more {counted}{'s' if more > 1 else ''})"
                         if more else ""))
        self.cases.clear()


@dataclass
class ShapeSpec:
    """One collision or visual: ``kind`` box | cylinder | sphere | plane | mesh |
    heightmap (a collision only: its terrain in ``heightmap``)."""

    kind: str
    pose: Pose6 = ZERO_POSE
    size: Tuple[float, float, float] = (1.0, 1.0, 1.0)
    radius: float = 0.0
    length: float = 0.0
    normal: Tuple[float, float, float] = (0.0, 0.0, 1.0)
    filename: str = ""
    scale: Tuple[float, float, float] = (1.0, 1.0, 1.0)
    rgba: Optional[Tuple[float, float, float, float]] = None
    friction: Optional[float] = None
    heightmap: Optional[Heightmap] = None


@dataclass
class LinkSpec:
    name: str
    pose: Pose6 = ZERO_POSE
    collisions: List[ShapeSpec] = field(default_factory=list)
    visuals: List[ShapeSpec] = field(default_factory=list)
    mass: float = 1.0
    inertia: Tuple[float, float, float] = (1.0, 1.0, 1.0)  # ixx, iyy, izz (SDF defaults)
    inertial_pose: Pose6 = ZERO_POSE
    # the collision meshes that could not be read and left the link with no collision shape
    lost_collisions: List[str] = field(default_factory=list)


@dataclass
class ModelSpec:
    name: str
    static: bool = False
    pose: Pose6 = ZERO_POSE
    links: List[LinkSpec] = field(default_factory=list)
    source: str = ""
    # an articulated model: the URDF robot it is built as (sim_bridge.sdf_articulated), and
    # its root link's pose in the model's frame ("" and None for a single body)
    urdf: str = ""
    urdf_root_pose: Optional[Pose6] = None
    # its <plugin> elements, which sim_bridge.world loads as Gazebo's C++ plugins
    plugins: List[ET.Element] = field(default_factory=list)
    # where the model stood when Gazebo made its <plane> collisions: a plane is fixed at its
    # collision's height then (before a world's <state> moves the model) and never moved
    # again (World._plane_placement); None: the model's pose when its bodies are first made
    plane_pose: Optional[Pose6] = None


@dataclass
class LightSpec:
    """A ``<light>``, with SDF's defaults for what it leaves out (sdformat sdf9 66a8c21,
    sdf/1.6/light.sdf: the line of each is given). Mutable: set_light_properties changes it."""

    name: str
    type: str = "point"  # :9 (point, directional, spot)
    cast_shadows: bool = False  # :13
    pose: Pose6 = ZERO_POSE  # in the world (:18)
    diffuse: Tuple[float, float, float, float] = (1.0, 1.0, 1.0, 1.0)  # :20
    specular: Tuple[float, float, float, float] = (0.1, 0.1, 0.1, 1.0)  # :23
    attenuation_range: float = 10.0  # m, :29
    attenuation_linear: float = 1.0  # :32
    attenuation_constant: float = 1.0  # :35
    attenuation_quadratic: float = 0.0  # :38
    direction: Tuple[float, float, float] = (0.0, 0.0, -1.0)  # :43 (spot and directional)


@dataclass
class WorldSpec:
    name: str = "default"
    step_size: float = DEFAULT_STEP_SIZE
    gravity: Tuple[float, float, float] = DEFAULT_GRAVITY
    models: List[ModelSpec] = field(default_factory=list)
    source: str = ""
    # the world's lights in the file's order (an included one with its <include>'s name
    # and pose, as sdformat's parser.cc gives them: sdf9 66a8c21 src/parser.cc:987-1027)
    lights: List[LightSpec] = field(default_factory=list)
    # the world's <plugin> elements (Gazebo's world plugins), in the file's order
    plugins: List[ET.Element] = field(default_factory=list)


def model_search_path() -> List[str]:
    """GAZEBO_MODEL_PATH's folders, then sim_bridge's own model library."""
    paths = [p for p in os.environ.get("GAZEBO_MODEL_PATH", "").split(os.pathsep) if p]
    return paths + [PACKAGE_MODELS]


def resolve_model_uri(uri: str, source: str, search: Optional[Sequence[str]] = None) -> str:
    """The model.sdf path of ``model://NAME`` (or of a file path / ``file://`` URI)."""
    if uri.startswith("file://"):
        uri = uri[len("file://"):]
    if not uri.startswith("model://"):
        path = uri if os.path.isabs(uri) else os.path.join(os.path.dirname(source), uri)
        if os.path.isdir(path):
            path = os.path.join(path, "model.sdf")
        if not os.path.isfile(path):
            raise SdfError(f"{source}: '{uri}' is not a file")
        return path
    name = uri[len("model://"):].strip("/")
    folders = list(search if search is not None else model_search_path())
    for folder in folders:
        candidate = os.path.join(folder, name)
        for file_name in _model_files(candidate):
            return file_name
    raise SdfError(f"{source}: cannot find '{uri}'; searched {', '.join(folders)} "
                   "(add the folder holding it to GAZEBO_MODEL_PATH)")


def _model_files(folder: str) -> List[str]:
    """The SDF of a model folder: model.config's <sdf>, else model.sdf."""
    config = os.path.join(folder, "model.config")
    if os.path.isfile(config):
        try:
            sdf = ET.parse(config).getroot().find("sdf")
        except ET.ParseError:
            sdf = None
        if sdf is not None and sdf.text and os.path.isfile(os.path.join(folder, sdf.text.strip())):
            return [os.path.join(folder, sdf.text.strip())]
    path = os.path.join(folder, "model.sdf")
    return [path] if os.path.isfile(path) else []


def _numbers(text: Optional[str], count: int, what: str, source: str) -> Tuple[float, ...]:
    parts = (text or "").split()
    try:
        values = tuple(float(p) for p in parts)
    except ValueError:
        raise SdfError(f"{source}: {what} '{text}' is not {count} numbers") from None
    if len(values) != count:
        raise SdfError(f"{source}: {what} '{text}' is not {count} numbers")
    try:
        return _urdf_finite(values, what, source)
    except UrdfError:  # urdf_tools' words, with the text as written ('1e999', not 'inf')
        raise SdfError(f"{source}: {what} '{' '.join(parts)}' is not {count} finite "
                       f"number{'s' if count > 1 else ''}") from None


def _child_number(element: ET.Element, tag: str, default: float, what: str, source: str) -> float:
    child = element.find(tag)
    if child is None:
        return default
    return _numbers(child.text, 1, f"{what} <{tag}>", source)[0]


def _pose(element: ET.Element, what: str, source: str) -> Pose6:
    pose = element.find("pose")
    if pose is None or not (pose.text or "").strip():
        return ZERO_POSE
    return _numbers(pose.text, 6, f"{what} <pose>", source)  # type: ignore[return-value]


def _material(visual: ET.Element, what: str,
              source: str) -> Optional[Tuple[float, float, float, float]]:
    material = visual.find("material")
    if material is None:
        return None
    script_name = material.find("script/name")
    if script_name is not None and script_name.text:
        colour = gazebo_colour(script_name.text)
        if colour is not None:
            return colour
    for tag in ("diffuse", "ambient"):
        colour = material.find(tag)
        if colour is not None and colour.text and colour.text.strip():
            if len(colour.text.split()) != 4:  # not a colour: as before, the next is tried
                continue
            return _numbers(colour.text, 4, f"{what} <material> <{tag}>",  # type: ignore
                            source)
    return None


# the elements SDF 1.6 allows in a <geometry> (sdformat sdf9 66a8c21 sdf/1.6/geometry.sdf)
SDF_GEOMETRIES = ("empty", "box", "cylinder", "heightmap", "image", "mesh", "plane",
                  "polyline", "sphere")


class _UnreadableHeightmap(Exception):
    """A <heightmap> Gazebo cannot build (its image missing, unreadable, of the wrong
    size): its URI and why."""

    def __init__(self, uri: str, reason: str):
        super().__init__(f"{uri}: {reason}")
        self.uri, self.reason = uri, reason


def _geometry_shape(element: ET.Element) -> Optional[ET.Element]:
    """The shape of an element's ``<geometry>`` as Gazebo takes it: the first child SDF
    knows. sdformat 9 reads the children its schema has in document order and moves any
    other (a ``<material>`` written inside the geometry, as public models do) after them
    without a word (src/parser.cc:1075-1111, a debug line only), and Gazebo builds the
    geometry's first element (gazebo 11.10.2 gazebo/physics/Link.cc:692-693,
    Collision.cc:119)."""
    geometry = element.find("geometry")
    if geometry is None:
        return None
    # none SDF knows: the first child, which Gazebo cannot build either (named in the error)
    return next((child for child in geometry if child.tag in SDF_GEOMETRIES),
                geometry[0] if len(geometry) else None)


def _shape(element: ET.Element, what: str, source: str, model_dir: str,
           notes: Optional[List[str]] = None) -> ShapeSpec:
    """``notes``: where Gazebo's errors that do not stop the shape are added."""
    shape = _geometry_shape(element)
    if shape is None:
        raise SdfError(f"{source}: {what} has no <geometry>")
    pose = _pose(element, what, source)
    kind = shape.tag
    if kind == "box":
        size = _checked(_urdf_positive,
                        _numbers(shape.findtext("size"), 3, f"{what} box <size>", source),
                        f"{what} box size", source)
        spec = ShapeSpec("box", pose, size=size)  # type: ignore[arg-type]
    elif kind == "cylinder":
        radius, length = _checked(_urdf_positive,
                                  [_child_number(shape, "radius", 0.5, what, source),
                                   _child_number(shape, "length", 1.0, what, source)],
                                  f"{what} cylinder radius and length", source)
        spec = ShapeSpec("cylinder", pose, radius=radius, length=length)
    elif kind == "sphere":
        (radius,) = _checked(_urdf_positive, [_child_number(shape, "radius", 0.5, what, source)],
                             f"{what} sphere radius", source)
        spec = ShapeSpec("sphere", pose, radius=radius)
    elif kind == "plane":
        normal = _numbers(shape.findtext("normal") or "0 0 1", 3, f"{what} plane <normal>", source)
        size = _numbers(shape.findtext("size") or "100 100", 2, f"{what} plane <size>", source)
        spec = ShapeSpec("plane", pose, normal=normal,  # type: ignore[arg-type]
                         size=(size[0], size[1], 0.0))
    elif kind == "mesh":
        uri = (shape.findtext("uri") or "").strip()
        scale = _numbers(shape.findtext("scale") or "1 1 1", 3, f"{what} mesh <scale>", source)
        spec = ShapeSpec("mesh", pose, filename=_mesh_file(uri, model_dir),
                         scale=scale)  # type: ignore[arg-type]
    elif kind == "heightmap":
        uri = (shape.findtext("uri") or "").strip()
        try:
            terrain, found = load_heightmap(shape, _resource_path(uri, model_dir))
        except (HeightmapError, OSError) as error:
            raise _UnreadableHeightmap(uri, str(error)) from None
        if notes is not None:
            notes.extend(found)
        spec = ShapeSpec("heightmap", pose, size=terrain.size, filename=terrain.image,
                         heightmap=terrain)
    else:
        raise SdfError(f"{source}: {what} has geometry <{kind}>; sim_bridge reads box, "
                       "cylinder, sphere, plane, mesh and heightmap")
    spec.friction = _friction(element, what, source)
    return spec


def _friction(element: ET.Element, what: str, source: str) -> Optional[float]:
    """A collision's ``<surface><friction><ode><mu>``; None when it gives none."""
    mu = element.find("surface/friction/ode/mu")
    if mu is None or not (mu.text or "").strip():
        return None
    return _numbers(mu.text, 1, f"{what} <surface> <friction> <ode> <mu>", source)[0]


def _mesh_file(uri: str, model_dir: str) -> str:
    """The file pybullet loads for a mesh ``<uri>`` (see :mod:`sim_bridge.mesh_files`);
    _UnreadableMesh when there is none."""
    if not uri:
        raise _UnreadableMesh(uri, "is empty (the <mesh> has no <uri>)")
    try:
        path = _resource_path(uri, model_dir)
    except OSError as error:
        raise _UnreadableMesh(uri, str(error)) from None
    try:
        return loadable_file(path)
    except MeshError as error:
        raise _UnreadableMesh(uri, f"{'(' + path + ') ' if path != uri else ''}{error}") \
            from None


def _resource_path(uri: str, model_dir: str) -> str:
    """The file a ``model://NAME/...``, ``file://`` or relative URI names (relative: to the
    model's folder); OSError naming the folders searched for a model:// one not found."""
    if uri.startswith("model://"):
        name, _, rest = uri[len("model://"):].partition("/")
        candidates = [os.path.join(folder, name, rest) for folder in model_search_path()]
        found = [c for c in candidates if os.path.exists(c)]
        if not found:
            raise OSError(f"is not found (searched {', '.join(candidates)}; "
                          "GAZEBO_MODEL_PATH, then sim_bridge's models/)")
        return found[0]
    path = uri[len("file://"):] if uri.startswith("file://") else uri
    return path if os.path.isabs(path) else os.path.join(model_dir, path)


def _bounding_box(visual: ShapeSpec, friction: Optional[float]) -> ShapeSpec:
    """A collision box the size of a visual mesh, where the visual is."""
    lower, upper = bounds(visual.filename)
    scale = [float(v) for v in visual.scale]
    size = tuple(max(abs((hi - lo) * k), 1e-6) for lo, hi, k in zip(lower, upper, scale))
    centre = tuple(float((hi + lo) / 2 * k) for lo, hi, k in zip(lower, upper, scale))
    return ShapeSpec("box", compose6(visual.pose, (*centre, 0.0, 0.0, 0.0)),
                     size=size, friction=friction)  # type: ignore[arg-type]


def _link(element: ET.Element, model: str, source: str, model_dir: str,
          warnings: _Warnings) -> LinkSpec:
    name = element.get("name", "link")
    what = f"model '{model}' link '{name}'"
    link = LinkSpec(name, _pose(element, what, source))
    visual_meshes: List[Tuple[str, ShapeSpec]] = []
    for index, visual in enumerate(element.findall("visual")):
        label = f"{what} visual '{visual.get('name', index)}'"
        if _tag(_geometry_shape(visual)) == "heightmap":
            continue  # pybullet draws the terrain's collision body (a body without a visual)
        try:
            shape = _shape(visual, label, source, model_dir)
        except _UnreadableMesh as mesh:
            warnings.add(("visual", mesh.uri, mesh.reason),
                         f"{source}: {label}: mesh '{mesh.uri}' {mesh.reason}; the visual "
                         "is left out, the model is loaded without it")
            continue
        shape.rgba = _material(visual, label, source)
        link.visuals.append(shape)
        if shape.kind == "mesh":
            visual_meshes.append(((visual.findtext("geometry/mesh/uri") or "").strip(), shape))
    failed: List[Tuple[str, _UnreadableMesh]] = []
    friction: Optional[float] = None
    for index, collision in enumerate(element.findall("collision")):
        label = f"{what} collision '{collision.get('name', index)}'"
        notes: List[str] = []
        try:
            link.collisions.append(_shape(collision, label, source, model_dir, notes))
        except _UnreadableHeightmap as terrain:
            warnings.add(("heightmap", terrain.uri, terrain.reason),
                         f"{source}: {label}: heightmap '{terrain.uri}' {terrain.reason}; the "
                         "terrain is left out, the world runs without it")
            continue
        except _UnreadableMesh as mesh:
            failed.append((label, mesh))
            friction = friction if friction is not None \
                else _friction(collision, label, source)
        for note in notes:
            warnings.add(("heightmap note", note), f"{source}: {label}: heightmap {note}")
    if failed:
        _replace_collisions(link, failed, visual_meshes, friction, source, warnings)
    inertial = element.find("inertial")
    if inertial is not None:
        link.mass = _child_number(inertial, "mass", 1.0, f"{what} inertial", source)
        if link.mass < 0:  # urdf_tools' refusal, in its words
            raise SdfError(f"{source}: {what} has a negative mass ({link.mass:g} kg); a mass "
                           "must be positive")
        link.inertial_pose = _pose(inertial, f"{what} inertial", source)
        tensor = inertial.find("inertia")
        if tensor is not None:
            link.inertia = tuple(_child_number(tensor, tag, 1.0, f"{what} inertia", source)
                                 for tag in ("ixx", "iyy", "izz"))  # type: ignore[assignment]
    return link


def _replace_collisions(link: LinkSpec, failed: List[Tuple[str, _UnreadableMesh]],
                        visual_meshes: List[Tuple[str, ShapeSpec]], friction: Optional[float],
                        source: str, warnings: _Warnings) -> None:
    """What stands in for collision meshes that cannot be read (see the module's notes)."""
    remaining = len(link.collisions)
    boxes: List[str] = []
    if not remaining:
        for uri, visual in visual_meshes:
            try:
                box = _bounding_box(visual, friction)
            except MeshError:
                continue
            link.collisions.append(box)
            boxes.append(f"'{uri}' ({' x '.join(f'{v:.3g}' for v in box.size)} m)")
    if not link.collisions:
        link.lost_collisions.extend(mesh.uri for _, mesh in failed)
    done = collision_fallback(remaining, boxes)
    for label, mesh in failed:
        warnings.add(("collision", mesh.uri, mesh.reason, done),
                     f"{source}: {label}: mesh '{mesh.uri}' {mesh.reason}; {done}")


def _colour(element: ET.Element, tag: str, default: Tuple[float, ...], what: str,
            source: str) -> Tuple[float, ...]:
    """An SDF colour: red, green, blue and, if given, alpha (1 when left out)."""
    text = element.findtext(tag)
    if text is None or not text.strip():
        return default
    count = 3 if len(text.split()) == 3 else 4
    values = _numbers(text, count, f"{what} <{tag}>", source)
    return values if count == 4 else (*values, 1.0)


def _light(element: ET.Element, source: str) -> LightSpec:
    """A ``<light>`` (see :class:`LightSpec` for the defaults)."""
    name = element.get("name", "__default__")
    what = f"light '{name}'"
    light = LightSpec(name, element.get("type", LightSpec.type))
    light.cast_shadows = (element.findtext("cast_shadows") or str(LightSpec.cast_shadows)
                          ).strip().lower() in ("1", "true")
    light.pose = _pose(element, what, source)
    light.diffuse = _colour(element, "diffuse", LightSpec.diffuse, what,  # type: ignore
                            source)
    light.specular = _colour(element, "specular", LightSpec.specular, what,  # type: ignore
                             source)
    attenuation = element.find("attenuation")
    if attenuation is not None:
        label = f"{what} <attenuation>"
        light.attenuation_range = _child_number(attenuation, "range",
                                                LightSpec.attenuation_range, label, source)
        light.attenuation_linear = _child_number(attenuation, "linear",
                                                 LightSpec.attenuation_linear, label, source)
        light.attenuation_constant = _child_number(
            attenuation, "constant", LightSpec.attenuation_constant, label, source)
        light.attenuation_quadratic = _child_number(
            attenuation, "quadratic", LightSpec.attenuation_quadratic, label, source)
    if (element.findtext("direction") or "").strip():
        light.direction = _numbers(element.findtext("direction"), 3,  # type: ignore
                                   f"{what} <direction>", source)
    return light


def _model(element: ET.Element, source: str, model_dir: str, warnings: _Warnings,
           chain: Chain = ()) -> ModelSpec:
    name = element.get("name")
    if not name:
        raise SdfError(f"{source}: a <model> has no name")
    static = (element.findtext("static") or "false").strip().lower() in ("1", "true")
    model = ModelSpec(name, static, _pose(element, f"model '{name}'", source), source=source)
    model.plugins = element.findall("plugin")
    for link in element.findall("link"):
        model.links.append(_link(link, name, source, model_dir, warnings))
    if any(shape.kind == "heightmap" for link in model.links for shape in link.collisions):
        # Gazebo makes a link with a heightmap collision static (gazebo 11.10.2
        # gazebo/physics/Link.cc:695-696); a terrain model has that one link
        model.static = static = True
    for nested in element.findall("include"):
        inner = _include(nested, source, warnings, chain)
        if isinstance(inner, ModelSpec):  # a light in a model is not read
            model.links.extend(_offset_links(inner))
    if element.find("joint") is not None and not static:
        try:
            model.urdf, model.urdf_root_pose = to_urdf(element, model)
        except ArticulationError as error:
            raise UnsupportedModel(f"{source}: model '{name}' cannot be built: {error}") \
                from None
    return model


def _tag(element: Optional[ET.Element]) -> Optional[str]:
    return None if element is None else element.tag


def _offset_links(model: ModelSpec) -> List[LinkSpec]:
    return [LinkSpec(l.name, compose6(model.pose, l.pose), l.collisions, l.visuals, l.mass,
                     l.inertia, l.inertial_pose, l.lost_collisions) for l in model.links]


def _check_shapeless(model: ModelSpec, source: str, warnings: _Warnings) -> None:
    """The warning for a free model that unreadable collision meshes left with no collision
    shape at all (see the module's notes); called once the model is final (an
    ``<include>`` may make it static)."""
    lost = [(link.name, link.lost_collisions) for link in model.links if link.lost_collisions]
    if model.static or not lost or any(link.collisions for link in model.links):
        return
    files = "; ".join(f"link '{name}': mesh " + ", ".join(f"'{uri}'" for uri in uris)
                      for name, uris in lost)
    warnings.add(("no collision shape", tuple((n, tuple(u)) for n, u in lost)),
                 f"{source}: model '{model.name}' is free (not <static>) and has no collision "
                 f"shape left ({files} cannot be read): it keeps its mass and falls through "
                 "the ground with gravity, as in Gazebo, where a collision whose mesh cannot "
                 "be loaded has no shape; make the mesh findable (GAZEBO_MODEL_PATH, the "
                 "path) or give the link a <box>, <cylinder> or <sphere> collision",
                 counted="model")


def load_model_file(path: str, warn: Optional[Warn] = None) -> Optional[ModelSpec]:
    """The first model of an SDF file (a model.sdf); None for a light (model://sun).
    Meshes that cannot be read are warned about through ``warn`` (see the module's notes)."""
    warnings = _Warnings()
    model = _load_model_file(path, warnings)
    if isinstance(model, ModelSpec):
        _check_shapeless(model, path, warnings)
    warnings.flush(warn)
    return model if isinstance(model, ModelSpec) else None


def _load_model_file(path: str, warnings: _Warnings,
                     chain: Chain = ()) -> Union[ModelSpec, LightSpec]:
    """The model of a model file, or its light (model://sun is one)."""
    root = _parse(path)
    element = root if root.tag == "model" else root.find("model")
    if element is None:
        light = root if root.tag == "light" else root.find("light")
        if light is not None:
            return _light(light, path)
        raise SdfError(f"{path}: no <model> in it")
    return _model(element, path, os.path.dirname(path), warnings, chain)


def parse_model(text: str, source: str = "<sdf>", warn: Optional[Warn] = None) -> ModelSpec:
    """A model from SDF text (spawn_sdf_model's model_xml). Meshes that cannot be read are
    warned about through ``warn`` (see the module's notes)."""
    warnings = _Warnings()
    model = _parse_model(text, source, warnings)
    _check_shapeless(model, source, warnings)
    warnings.flush(warn)
    return model


def parse_light(text: str, source: str = "<sdf>") -> Optional[LightSpec]:
    """The light of spawn_sdf_model's model_xml when its root's first element is a
    ``<light>`` (gazebo_ros spawns it as a light then, gazebo_ros_api_plugin.cpp:2654-2658,
    :2697-2705), else None (a model: :func:`parse_model`)."""
    try:
        root = ET.fromstring(text)
    except ET.ParseError:
        return None  # parse_model names the error
    if root.tag == "light":
        return _light(root, source)
    first = root[0] if len(root) else None
    return _light(first, source) if first is not None and first.tag == "light" else None


def _parse_model(text: str, source: str, warnings: _Warnings) -> ModelSpec:
    # a text longer in characters than the limit is longer in bytes: no need to encode it
    _check_size(len(text) if len(text) > MAX_DESCRIPTION_BYTES else len(text.encode("utf-8")),
                source)
    try:
        root = ET.fromstring(text)
    except ET.ParseError as error:
        raise SdfError(f"{source}: not well-formed XML: {error}") from None
    element = root if root.tag == "model" else root.find("model")
    if element is None:
        # spawn_model -database NAME sends a world that includes model://NAME
        include = root.find(".//include")
        model = _include(include, source, warnings) if include is not None else None
        if not isinstance(model, ModelSpec):
            raise SdfError(f"{source}: no <model> in it")
        if include.find("pose") is None:
            # gazebo_ros writes the spawn's pose into the <include> (the included model's
            # own <pose> gives way to it), composed with the include's pose, none here
            # (gazebo_ros_pkgs noetic-devel f9e1a46,
            # gazebo_ros/src/gazebo_ros_api_plugin.cpp:2459-2475, updateSDFAttributes)
            model.pose = ZERO_POSE
        return model
    return _model(element, source, os.getcwd(), warnings)


def _include(element: ET.Element, source: str, warnings: _Warnings,
             chain: Chain = ()) -> Union[ModelSpec, LightSpec]:
    """The model or light an ``<include>`` names, with the include's ``<name>`` and
    ``<pose>`` (and, for a model, ``<static>``); ``chain``: the includes being followed
    around it (see :data:`MAX_INCLUDE_DEPTH`)."""
    uri = (element.findtext("uri") or "").strip()
    if not uri:
        raise SdfError(f"{source}: an <include> has no <uri>")
    path = resolve_model_uri(uri, source)
    real = os.path.realpath(path)
    files = [file for _, file in chain]
    if real in files:
        cycle = [u for u, _ in chain[files.index(real):]] + [uri]
        raise SdfError(f"{source}: <include> of '{uri}' includes itself again: "
                       f"{' -> '.join(cycle)} ({real}); an include cycle never ends "
                       "(remove the <include> that closes it)")
    if len(chain) >= MAX_INCLUDE_DEPTH:
        raise SdfError(f"{source}: <include> of '{uri}' is nested {len(chain) + 1} deep "
                       f"({' -> '.join([u for u, _ in chain] + [uri])}); sim_bridge follows "
                       f"at most {MAX_INCLUDE_DEPTH} (MAX_INCLUDE_DEPTH)")
    model = _load_model_file(path, warnings, chain + ((uri, real),))
    if element.find("name") is not None:
        model.name = element.findtext("name").strip()
    if element.find("pose") is not None:
        model.pose = _pose(element, f"<include> of {uri}", source)
    if isinstance(model, ModelSpec) and element.find("static") is not None:
        model.static = element.findtext("static").strip().lower() in ("1", "true")
    return model


def _parse(path: str) -> ET.Element:
    try:
        _check_size(os.path.getsize(path), path)  # before reading a file of any size
        with open(path, "rb") as stream:
            # Gazebo reads a file whose <?xml ...?> declaration follows blank lines
            # (Interbotix's xsarm_gazebo.world starts with one); expat does not
            return ET.fromstring(stream.read().lstrip())
    except ET.ParseError as error:
        raise SdfError(f"{path}: not well-formed XML: {error}") from None
    except OSError as error:
        raise SdfError(f"{path}: cannot be read: {error.strerror}") from None


def resolve_world_name(name: str) -> str:
    """A world file as gzserver finds it: an absolute path or one relative to the current
    folder as it is, else relative to a folder of GAZEBO_RESOURCE_PATH (gazebo_ros's
    default, ``worlds/empty.world``, is found this way)."""
    if os.path.isabs(name) or os.path.isfile(name):
        return name
    folders = [p for p in os.environ.get("GAZEBO_RESOURCE_PATH", "").split(os.pathsep) if p]
    for folder in folders:
        candidate = os.path.join(folder, name)
        if os.path.isfile(candidate):
            return candidate
    raise SdfError(f"world '{name}' is not a file, here or in GAZEBO_RESOURCE_PATH "
                   f"({os.pathsep.join(folders) or 'unset'})")


def load_world(path: str, warn: Optional[Warn] = None) -> WorldSpec:
    """Reads a .world file (``path`` as :func:`resolve_world_name` resolves it). Meshes that
    cannot be read are warned about through ``warn`` (see the module's notes)."""
    warnings = _Warnings()
    try:
        return _load_world(path, warnings)
    finally:
        warnings.flush(warn)


def _load_world(path: str, warnings: _Warnings) -> WorldSpec:
    path = resolve_world_name(path)
    root = _parse(path)
    world = root.find("world") if root.tag == "sdf" else root
    if world is None or world.tag != "world":
        raise SdfError(f"{path}: no <world> in it")
    spec = WorldSpec(world.get("name", "default"), source=path)
    spec.plugins = world.findall("plugin")
    physics = world.find("physics")
    if physics is not None:
        spec.step_size = _child_number(physics, "max_step_size", DEFAULT_STEP_SIZE,
                                       "<physics>", path)
        if spec.step_size <= 0:
            raise SdfError(f"{path}: <physics> <max_step_size> must be positive")
    if world.find("gravity") is not None:
        spec.gravity = _numbers(world.findtext("gravity"), 3, "<gravity>", path)  # type: ignore
    names = set()
    for element in world:
        try:
            if element.tag == "include":
                model = _include(element, path, warnings)
            elif element.tag == "model":
                model = _model(element, path, os.path.dirname(path), warnings)
            elif element.tag == "light":
                model = _light(element, path)
            else:
                continue
        except UnsupportedModel as error:
            # one model must not take the world down (students add Gazebo's robots to theirs)
            warnings.add(("unsupported", str(error)), f"{error}: left out of the world, which "
                         "runs without it", counted="model")
            continue
        if isinstance(model, LightSpec):
            spec.lights.append(model)
            continue
        if model.name in names:
            raise SdfError(f"{path}: two models are named '{model.name}'")
        names.add(model.name)
        _check_shapeless(model, path, warnings)
        spec.models.append(model)
    _apply_state(world, spec, path)
    return spec


def _apply_state(world: ET.Element, spec: WorldSpec, source: str) -> None:
    """A world saved from Gazebo keeps where its models are in ``<state>``, which Gazebo
    applies when it loads the world (Husky's playpen turns a barrier there: without it
    the robot spawned on top of it): each ``<state><model name><pose>`` places the model
    of that name, each ``<state><light name><pose>`` the light. Links' poses and velocities in
    the state are not applied. Gazebo 11 makes
    the world's collisions before it applies the state, so a model's planes stay where its
    own ``<pose>`` put them (``ModelSpec.plane_pose``): inferred, not read in gazebo-classic's
    source, from worlds that run there (Neobotix's workshop stands decals on their edges
    at 1.25 m by its state; planes made there would lift every robot onto a floor at 1.25 m)."""
    models = {model.name: model for model in spec.models}
    for state in world.findall("state"):
        for element in state.findall("model"):
            model = models.get(element.get("name", ""))
            if model is not None and element.find("pose") is not None:
                if model.plane_pose is None:
                    model.plane_pose = model.pose
                model.pose = _pose(element, f"<state> model '{model.name}'", source)
        # a light's pose likewise (Gazebo 11's world state carries its lights' poses:
        # gazebo-classic's LightState, unverified here)
        for element in state.findall("light"):
            for light in spec.lights:
                if light.name == element.get("name", "") and element.find("pose") is not None:
                    light.pose = _pose(element, f"<state> light '{light.name}'", source)
