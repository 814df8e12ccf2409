"""Collision checking of a robot and its planning scene on FCL (python-fcl), the library
MoveIt's default collision detector uses.

Shapes as MoveIt builds them: a link's URDF collision geometry (boxes, cylinders along z,
spheres, meshes as meshes: a triangle BVH read by trimesh), a collision object's solid
primitives (box, sphere, cylinder and cone with SolidPrimitive's dimensions), triangle
meshes and planes. Which pairs are checked is the allowed collision matrix's question
(:class:`AllowedCollisions`): the SRDF's disabled pairs, an attached object's touch links,
and entries a planning scene message sets. A link mesh that cannot be read is left out of
the checks with one warning naming the link and the file (Gazebo and MoveIt load such a
robot too). No ROS here.
"""
from __future__ import annotations

import logging
import math
from dataclasses import dataclass, field
from typing import Dict, FrozenSet, Iterable, List, Optional, Sequence, Set, Tuple

import fcl
import numpy as np

from urdf_tools import Geometry, UrdfError
from urdf_tools.kinematics import origin_transform
from urdf_tools.mesh_uri import resolve_package_uri

# rospy shows the rosout.* loggers on the console and /rosout
LOG = logging.getLogger("rosout.moveit_core")


class ShapeError(ValueError):
    """A shape that cannot be built (a mesh file that cannot be read, a size that is not
    positive); the message names it."""


@dataclass
class Shape:
    """An FCL geometry placed in its body's frame (``offset``: 4x4)."""

    geometry: object
    offset: np.ndarray
    kind: str = ""


def _positive(values: Sequence[float], what: str) -> List[float]:
    values = [float(v) for v in values]
    if not all(np.isfinite(v) and v > 0 for v in values):
        raise ShapeError(f"{what} needs sizes > 0, not {values}")
    return values


class Mesh(fcl.BVHModel):
    """FCL's triangle BVH with the sphere that holds its vertices (``centre``, ``radius``
    in the mesh's frame: FCL keeps its own but does not show it to Python)."""

    centre = np.zeros(3)
    radius = math.inf


def geometry_sphere(geometry) -> Tuple[np.ndarray, float]:
    """A sphere holding the geometry (centre in its frame, radius); a half space's is
    infinite."""
    if isinstance(geometry, fcl.Box):
        return np.zeros(3), float(np.linalg.norm(geometry.side)) / 2.0
    if isinstance(geometry, fcl.Sphere):
        return np.zeros(3), float(geometry.radius)
    if isinstance(geometry, (fcl.Cylinder, fcl.Cone)):   # both centred on their middle
        return np.zeros(3), math.hypot(geometry.radius, geometry.lz / 2.0)
    if isinstance(geometry, Mesh):
        return geometry.centre, geometry.radius
    return np.zeros(3), math.inf


def mesh_geometry(vertices: np.ndarray, triangles: np.ndarray, what: str) -> fcl.BVHModel:
    vertices = np.asarray(vertices, dtype=float).reshape(-1, 3)
    triangles = np.asarray(triangles, dtype=int).reshape(-1, 3)
    if len(triangles) == 0 or not np.all(np.isfinite(vertices)):
        raise ShapeError(f"{what} has no triangles or a vertex that is not finite")
    if triangles.min() < 0 or triangles.max() >= len(vertices):
        raise ShapeError(f"{what} has a triangle naming a vertex it lacks")
    model = Mesh()
    model.beginModel(len(vertices), len(triangles))
    model.addSubModel(vertices, triangles)
    model.endModel()
    model.centre = (vertices.min(axis=0) + vertices.max(axis=0)) / 2.0
    model.radius = float(np.linalg.norm(vertices - model.centre, axis=1).max())
    return model


def mesh_file_geometry(path: str, scale: Sequence[float], what: str) -> fcl.BVHModel:
    import trimesh   # only robots and objects with meshes need it
    try:
        mesh = trimesh.load(path, force="mesh")
    except Exception as error:  # pylint: disable=broad-except
        raise ShapeError(f"{what}: mesh '{path}' cannot be read: {error}") from error
    if not hasattr(mesh, "faces") or len(mesh.faces) == 0:
        raise ShapeError(f"{what}: mesh '{path}' has no triangles")
    return mesh_geometry(np.asarray(mesh.vertices) * np.asarray(scale, dtype=float),
                         mesh.faces, f"{what}: mesh '{path}'")


def urdf_geometry(geometry: Geometry, what: str, source: str):
    """The FCL geometry of a URDF ``<geometry>``."""
    if geometry.kind == "box":
        return fcl.Box(*_positive(geometry.size, what))
    if geometry.kind == "sphere":
        return fcl.Sphere(*_positive([geometry.radius], what))
    if geometry.kind == "cylinder":
        radius, length = _positive([geometry.radius, geometry.length], what)
        return fcl.Cylinder(radius, length)
    if geometry.kind == "mesh":
        try:
            path = resolve_package_uri(geometry.filename or "", source)
        except UrdfError as error:
            raise ShapeError(str(error)) from error
        return mesh_file_geometry(path, geometry.scale, what)
    raise ShapeError(f"{what}: unknown geometry '{geometry.kind}'")


def robot_shapes(model) -> Dict[str, List[Shape]]:
    """Each link's collision shapes (links without any are left out)."""
    shapes: Dict[str, List[Shape]] = {}
    for name, link in model.urdf.links.items():
        for index, collision in enumerate(link.collisions):
            what = f"link '{name}' collision {index + 1}"
            try:
                geometry = urdf_geometry(collision.geometry, what, model.urdf.source)
            except ShapeError as error:
                LOG.warning("%s; left out of collision checks", error)
                continue
            shapes.setdefault(name, []).append(
                Shape(geometry, origin_transform(collision.origin), collision.geometry.kind))
    return shapes


class AllowedCollisions:
    """MoveIt's allowed collision matrix: pairs allowed to touch, and names allowed to touch
    everything (default entries)."""

    def __init__(self, pairs: Iterable[Tuple[str, str]] = (), everything: Iterable[str] = ()):
        self.pairs: Set[FrozenSet[str]] = {frozenset(p) for p in pairs}
        self.everything: Dict[str, bool] = {name: True for name in everything}
        self.forbidden: Set[FrozenSet[str]] = set()     # explicit "not allowed" entries
        self.version = 0       # counts the changes (the scene's list of pairs to check)

    def copy(self) -> "AllowedCollisions":
        other = AllowedCollisions()
        other.pairs, other.everything = set(self.pairs), dict(self.everything)
        other.forbidden = set(self.forbidden)
        return other

    def set(self, a: str, b: str, allowed: bool) -> None:
        pair = frozenset((a, b))
        (self.pairs.add if allowed else self.pairs.discard)(pair)
        (self.forbidden.discard if allowed else self.forbidden.add)(pair)
        self.version += 1

    def set_default(self, name: str, allowed: bool) -> None:
        self.everything[name] = allowed
        self.version += 1

    def allowed(self, a: str, b: str) -> bool:
        pair = frozenset((a, b))
        if pair in self.pairs:
            return True
        if pair in self.forbidden:
            return False
        return self.everything.get(a, False) or self.everything.get(b, False)

    def names(self) -> List[str]:
        found = {n for p in self.pairs | self.forbidden for n in p} | set(self.everything)
        return sorted(found)


@dataclass
class Body:
    """Something that collides: a link, a scene object or an object attached to a link;
    its shapes' poses in the model frame are set before each check."""

    name: str
    shapes: List[Shape]
    objects: List[fcl.CollisionObject] = field(default_factory=list)

    # the broad phase's view of the body, in its own frame: a sphere holding every shape
    # (centre, radius) and, for a body that is one box, the box (its pose, half sizes)
    centre: np.ndarray = field(init=False)
    radius: float = field(init=False)
    box: Optional[Tuple[np.ndarray, np.ndarray]] = field(init=False)

    def __post_init__(self):
        self.objects = [fcl.CollisionObject(s.geometry) for s in self.shapes]
        spheres = []
        for shape in self.shapes:
            centre, radius = geometry_sphere(shape.geometry)
            spheres.append((shape.offset[:3, :3] @ centre + shape.offset[:3, 3], radius))
        centres = np.array([c for c, _ in spheres]).reshape(-1, 3)
        self.centre = (centres.min(axis=0) + centres.max(axis=0)) / 2.0 if spheres \
            else np.zeros(3)
        self.radius = max((float(np.linalg.norm(c - self.centre)) + r for c, r in spheres),
                          default=0.0)
        self.box = None
        if len(self.shapes) == 1 and isinstance(self.shapes[0].geometry, fcl.Box):
            self.box = (self.shapes[0].offset, np.asarray(self.shapes[0].geometry.side) / 2.0)

    def place(self, pose: np.ndarray) -> None:
        for shape, obj in zip(self.shapes, self.objects):
            placed = pose @ shape.offset
            obj.setTransform(fcl.Transform(placed[:3, :3], placed[:3, 3]))

    def touches(self, other: "Body") -> bool:
        request = fcl.CollisionRequest()
        for mine in self.objects:
            for theirs in other.objects:
                if fcl.collide(mine, theirs, request, fcl.CollisionResult()):
                    return True
        return False

    def distance(self, other: "Body") -> float:
        best = np.inf
        for mine in self.objects:
            for theirs in other.objects:
                best = min(best, fcl.distance(mine, theirs, fcl.DistanceRequest(),
                                              fcl.DistanceResult()))
        return best
