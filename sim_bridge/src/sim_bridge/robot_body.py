"""A robot from a URDF as a pybullet body, seen through its URDF names.

pybullet differs from Gazebo in ways that matter here, and this module hides them:

- a link without ``<inertial>`` gets 1 kg and unit inertia from pybullet's importer
  (Gazebo lumps it into its parent): such links get a negligible inertial before loading;
- the base pose pybullet reports is the centre of mass's, not the root link frame's:
  poses and twists here are of the URDF link frames;
- every joint gets a velocity motor that brakes it: motors are switched off, so passive
  joints (casters) turn freely; a joint's URDF ``friction`` becomes a braking motor of
  that force, which is how pybullet models joint friction;
- pybullet's URDF importer turns a collision cylinder into a convex hull of a polygon
  (a wheel with flats) padded by a 1 mm margin, unless asked for its implicit cylinder.
  The hull wheel rolled 2% too far per turn, and a flipping robot landing on two hull
  wheels yawed 10-17 degrees per flip, always the same way; implicit cylinders (exact
  size, no padding: measured) land straight within 1 degree;
- a rigid cylinder on a flat floor touches it along a line, and pybullet keeps one point
  of that line: an edge, picked by the sign of a rounding error. Both wheels of a robot
  touched on the same side (measured: 7.2 N on one wheel, 5.0 N on the other, standing
  still), and a flipping robot slid sideways at every reversal. A wheel (a collision
  cylinder turning about its own axis on a continuous or revolute joint) is therefore
  given a crown, as a real tyre has: a core as wide as the wheel and 1 mm smaller in
  radius, with a 2 mm tread at full radius around its middle. It stands on its tread
  (6.1 N on each wheel) and, tilted more than about 2 degrees, on the core's edge. Two
  shapes, not three: each one more costs about 5% of the simulator's speed. Its
  inertial is the URDF's;
- pybullet's contacts are rigid: a robot on two wheels and two casters touching exactly
  cannot share its weight among four points the way Gazebo's soft contacts do, and under
  acceleration the casters take it all and the wheels slip. Frictionless sphere casters
  (mu1 = mu2 = 0) are therefore made 1 mm smaller: the robot stands on its wheels and one
  caster, as a real one does on a floor that is not perfectly flat;
- ``package://`` and ``file://`` mesh URIs and relative paths are resolved to files
  (pybullet knows no ROS packages, and loads the URDF from a temporary file), and every
  mesh goes through :mod:`sim_bridge.mesh_files`: Collada and ASCII STL, which pybullet
  cannot read, are converted to OBJ (Collada's unit applied, as Gazebo does). A mesh that
  cannot be read does not refuse the robot, as in Gazebo: a visual is left out, and a
  collision falls back to the link's other collision shapes, else to the bounding box of
  the link's readable visual meshes, else it is dropped and the link keeps its inertial;
  each with one warning naming the link, the file and what was done;
- a root link named ``world`` fixes the robot to the world, as in Gazebo;
- pybullet's friction for a robot depends on its heading (:mod:`sim_bridge.tyre_friction`):
  the tyres' friction is computed there, and :attr:`RobotBody.tyres` lists them.
"""
from __future__ import annotations

import os
import tempfile
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from typing import Dict, List, Mapping, Optional, Sequence, Set, Tuple

import numpy as np
import pybullet as pb

from sim_bridge.gazebo_tags import GazeboTags, LinkSurface
from sim_bridge.materials import gazebo_colour
from sim_bridge.model_structure import urdf_structure
from sim_bridge.mesh_files import MeshError, bounds, collision_fallback, loadable_file
from sim_bridge.tyre_friction import Tyre
from urdf_tools.kinematics import rpy_matrix
from urdf_tools.mesh_uri import resolve_package_uri
from urdf_tools.model import RobotModel, UrdfError

# What a link without <inertial> weighs in pybullet: small against any real link, large
# enough to keep the solver well conditioned.
NEGLIGIBLE_MASS = 1e-3
NEGLIGIBLE_INERTIA = 1e-7
# how much smaller frictionless caster spheres are made (see the module's notes)
CASTER_CLEARANCE = 0.001
# a wheel's crown (see the module's notes): the tread's width at full radius, and how much
# smaller in radius the core under it is
TREAD_WIDTH = 0.002
CORE_CLEARANCE = 0.001
# the <robot name> pybullet is given (see prepare_urdf)
PYBULLET_ROBOT_NAME = "robot"

Vec3 = Tuple[float, float, float]
Quat = Tuple[float, float, float, float]


def mesh_path(uri: str, source: str) -> str:
    """The file a URDF mesh ``filename`` names: ``package://``, ``file://``, an absolute
    path, or a path relative to the URDF file's folder when ``source`` is a file, else to
    the current folder (gzserver's). Raises MeshError when a package is not found."""
    try:
        path = resolve_package_uri(uri, source)
    except UrdfError:
        package = uri[len("package://"):].partition("/")[0]
        raise MeshError(f"names ROS package '{package}', which is not found (is the "
                        "workspace sourced?)") from None
    if not path:
        raise MeshError("is empty (the <mesh> has no filename)")
    if not os.path.isabs(path):
        base = os.path.dirname(os.path.abspath(source)) if os.path.isfile(source) \
            else os.getcwd()
        path = os.path.join(base, path)
    return path


@dataclass
class _ReadableMesh:
    """A visual mesh of a link that pybullet will load."""

    uri: str
    path: str
    origin: Optional[ET.Element]
    scale: np.ndarray


def _mesh_scale(mesh: ET.Element) -> np.ndarray:
    try:
        scale = _vector(mesh.get("scale") or "1 1 1")
    except ValueError:
        scale = np.ones(3)
    return scale if scale.shape == (3,) else np.ones(3)


def _loadable(mesh: ET.Element, source: str) -> Tuple[str, str]:
    """(URI as written, the file pybullet loads) of a <mesh>; MeshError when unreadable."""
    uri = mesh.get("filename", "")
    path = mesh_path(uri, source)
    try:
        return uri, loadable_file(path)
    except MeshError as error:
        where = f" ({path})" if path != uri else ""
        raise MeshError(f"{where} {error}".strip()) from None


def _bounding_box(link: ET.Element, visual: _ReadableMesh) -> Tuple[ET.Element, np.ndarray]:
    """A <collision> box the size of ``visual``'s mesh, where the visual is."""
    lower, upper = bounds(visual.path)
    size = np.abs((upper - lower) * visual.scale)
    centre = (upper + lower) / 2 * visual.scale
    xyz = _vector(visual.origin.get("xyz") if visual.origin is not None else None)
    rpy = _vector(visual.origin.get("rpy") if visual.origin is not None else None)
    xyz = xyz + rpy_matrix(*rpy) @ centre
    collision = ET.SubElement(link, "collision")
    ET.SubElement(collision, "origin", xyz=" ".join(repr(float(v)) for v in xyz),
                  rpy=" ".join(repr(float(v)) for v in rpy))
    geometry = ET.SubElement(collision, "geometry")
    ET.SubElement(geometry, "box", size=" ".join(repr(float(max(v, 1e-6))) for v in size))
    return collision, size


def prepare_meshes(link: ET.Element, source: str, warn) -> None:
    """Points every <mesh> of ``link`` at a file pybullet reads (see the module's notes);
    leaves out visuals and replaces collisions whose mesh cannot be read, one warning each."""
    name = link.get("name", "")
    visuals: List[_ReadableMesh] = []
    for visual in link.findall("visual"):
        mesh = visual.find("geometry/mesh")
        if mesh is None:
            continue
        try:
            uri, path = _loadable(mesh, source)
        except MeshError as error:
            link.remove(visual)
            warn(f"{source}: link '{name}': visual mesh '{mesh.get('filename', '')}' "
                 f"{error}; the visual is left out, the robot is spawned without it")
            continue
        mesh.set("filename", path)
        visuals.append(_ReadableMesh(uri, path, visual.find("origin"), _mesh_scale(mesh)))
    failed: List[Tuple[str, MeshError]] = []
    for collision in link.findall("collision"):
        mesh = collision.find("geometry/mesh")
        if mesh is None:
            continue
        try:
            mesh.set("filename", _loadable(mesh, source)[1])
        except MeshError as error:
            link.remove(collision)
            failed.append((mesh.get("filename", ""), error))
    if not failed:
        return
    remaining = len(link.findall("collision"))
    boxes: List[str] = []
    if not remaining:
        for visual in visuals:
            try:
                size = _bounding_box(link, visual)[1]
            except MeshError:
                continue
            boxes.append(f"'{visual.uri}' ({' x '.join(f'{v:.3g}' for v in size)} m)")
    done = collision_fallback(remaining, boxes)
    for uri, error in failed:
        warn(f"{source}: link '{name}': collision mesh '{uri}' {error}; {done}")


@dataclass(frozen=True)
class CollisionMesh:
    """A collision mesh as pybullet loaded it: its link, its <origin> in the link's frame
    (4 x 4), the file pybullet read (converted if need be) and the URDF scale."""

    link: str
    origin: np.ndarray
    path: str
    scale: np.ndarray


def collision_meshes(prepared: str) -> List[CollisionMesh]:
    """The collision meshes of the URDF text :func:`prepare_urdf` made (those that could be
    read: the rest were replaced or dropped there)."""
    found = []
    for link in ET.fromstring(prepared).findall("link"):
        for collision in link.findall("collision"):
            mesh = collision.find("geometry/mesh")
            if mesh is None:
                continue
            origin = collision.find("origin")
            transform = np.eye(4)
            transform[:3, :3] = rpy_matrix(*_vector(origin.get("rpy") if origin is not None
                                                    else None))
            transform[:3, 3] = _vector(origin.get("xyz") if origin is not None else None)
            found.append(CollisionMesh(link.get("name", ""), transform, mesh.get("filename"),
                                       _mesh_scale(mesh)))
    return found


def _is_caster(tags: GazeboTags, link: str) -> bool:
    surface = tags.surfaces.get(link)
    return surface is not None and surface.mu1 == 0.0 and surface.mu2 == 0.0


def _rotation_axis(model: RobotModel, link: str) -> Optional[np.ndarray]:
    """The unit axis ``link`` turns about in its own frame, when its parent joint is
    continuous or revolute."""
    joint = model.parent_joint(link)
    if joint is None or joint.type not in ("continuous", "revolute"):
        return None
    axis = np.asarray(joint.axis, dtype=float)
    return axis / np.linalg.norm(axis)


def _tyre_axle(model: RobotModel, link: str) -> Optional[np.ndarray]:
    """The axis ``link`` turns about when it is a tyre: a collision cylinder turning about
    its own axis on a continuous or revolute joint (what :func:`crown_wheels` crowns)."""
    axis = _rotation_axis(model, link)
    if axis is None:
        return None
    for shape in model.links[link].collisions:
        along = rpy_matrix(*shape.origin.rpy)[:, 2]
        if shape.geometry.kind == "cylinder" and abs(float(along @ axis)) >= 0.999:
            return axis
    return None


def tyres(model: RobotModel, tags: GazeboTags, link_index: Mapping[str, int]) -> List[Tyre]:
    """The links whose contacts get :mod:`sim_bridge.tyre_friction`: the tyres, and the
    links whose ``<gazebo>`` gives ``fdir1``."""
    found = []
    for name, index in link_index.items():
        surface = tags.surfaces.get(name, LinkSurface())
        axle = _tyre_axle(model, name)
        if axle is None and surface.fdir1 is None:
            continue
        found.append(Tyre(index, surface.mu1, surface.mu2, surface.fdir1,
                          None if axle is None else tuple(float(a) for a in axle)))
    return found


def _vector(text: Optional[str]) -> np.ndarray:
    return np.array([float(v) for v in (text or "0 0 0").split()])


def crown_wheels(link: ET.Element, axis: np.ndarray) -> None:
    """Replaces each collision cylinder of ``link`` whose own axis is ``axis`` (a wheel)
    by a crowned one: a core as wide, CORE_CLEARANCE smaller in radius, and a tread at
    full radius around its middle (see the module's notes)."""
    for collision in link.findall("collision"):
        cylinder = collision.find("geometry/cylinder")
        if cylinder is None:
            continue
        origin = collision.find("origin")
        xyz = _vector(origin.get("xyz") if origin is not None else None)
        rpy = _vector(origin.get("rpy") if origin is not None else None)
        along = rpy_matrix(*rpy)[:, 2]  # a URDF cylinder's axis is its frame's z
        length, radius = float(cylinder.get("length")), float(cylinder.get("radius"))
        if abs(float(along @ axis)) < 0.999 or length <= 2 * TREAD_WIDTH \
                or radius <= 2 * CORE_CLEARANCE:
            continue
        pieces = [(TREAD_WIDTH, radius), (length, radius - CORE_CLEARANCE)]
        link.remove(collision)
        for piece_length, piece_radius in pieces:
            piece = ET.SubElement(link, "collision")
            ET.SubElement(piece, "origin", xyz=" ".join(repr(float(v)) for v in xyz),
                          rpy=" ".join(repr(float(v)) for v in rpy))
            geometry = ET.SubElement(piece, "geometry")
            ET.SubElement(geometry, "cylinder", length=repr(piece_length),
                          radius=repr(piece_radius))


def prepare_urdf(xml: str, model: RobotModel, tags: GazeboTags, warn) -> str:
    """The URDF text pybullet should load (see the module's notes)."""
    root = ET.fromstring(xml)
    for link in root.findall("link"):
        name = link.get("name", "")
        axis = _rotation_axis(model, name)
        if axis is not None:
            crown_wheels(link, axis)
        caster = _is_caster(tags, name)
        for geometry in link.findall("collision/geometry"):
            for sphere in geometry.findall("sphere") if caster else ():
                radius = float(sphere.get("radius", "0"))
                sphere.set("radius", repr(max(radius - CASTER_CLEARANCE, radius / 2)))
        if link.find("inertial") is None:
            inertial = ET.SubElement(link, "inertial")
            ET.SubElement(inertial, "mass", value=str(NEGLIGIBLE_MASS))
            ET.SubElement(inertial, "inertia", ixx=str(NEGLIGIBLE_INERTIA), ixy="0", ixz="0",
                          iyy=str(NEGLIGIBLE_INERTIA), iyz="0", izz=str(NEGLIGIBLE_INERTIA))
        prepare_meshes(link, model.source, warn)
    # pybullet's importer crashes (SIGSEGV) on a robot name of about 42,000 characters or
    # more (found by the fuzz tier); nothing reads the name pybullet keeps, the model's
    # name is the spawn request's
    root.set("name", PYBULLET_ROBOT_NAME)
    # <gazebo> and <transmission> mean nothing to pybullet's importer
    for tag in ("gazebo", "transmission"):
        for element in root.findall(tag):
            root.remove(element)
    # one element a line: pybullet's importer refuses a line longer than about 8 KB, and
    # a valid URDF may be written on one line
    ET.indent(root)
    return ET.tostring(root, encoding="unicode")


# the most joints pybullet builds in one body (beyond, it returns a body it did not build,
# which cannot even be removed without crashing it): refused before it is asked
MAX_PYBULLET_JOINTS = 127
# the longest link or joint name taken: pybullet crashed (SIGSEGV) loading a joint named by
# 5000 characters (the spawn fuzzer's), and read 1000 well
MAX_NAME_LENGTH = 1024


# A contact's stiffness (N/m) and damping (N s/m) where a link sets only the other: SDF's
# defaults, which Gazebo's URDF conversion leaves in place (sdformat sdf9 66a8c21,
# sdf/1.6/surface.sdf:188 kp, :191 kd). pybullet holds 1e12 without jitter: a 100 kg box
# rests 10 micrometres deep and still (at 1e6 it sank 0.5 mm and rocked by 14 micrometres).
DEFAULT_KP = 1e12
DEFAULT_KD = 1.0


def self_colliding_bodies(model: RobotModel, tags: GazeboTags) -> Set[str]:
    """Gazebo's links (after lumping) whose self_collide is true (sdformat sdf9 66a8c21,
    src/parser_urdf.cc). Each takes its own <selfCollide> (read at :1397-1412, written
    into the link at :2092-2096; a lumped link's goes to the link it is lumped into, the
    link's own first), else the model's: a robot-level <self_collide> is copied into the
    model (:2279-2287; sdf/1.6/model.sdf:13-15). A robot-level <selfCollide> is read into no
    link and written nowhere: no effect, as in Gazebo. Two of them collide when either is
    in the set (sdf/1.6/link.sdf:17-19)."""
    structure = urdf_structure(model)
    colliding = set()
    for body in structure.bodies:
        # the link itself first, then those lumped into it
        given = [tags.surfaces[link].self_collide for link in structure.links_of(body)
                 if link in tags.surfaces and tags.surfaces[link].self_collide is not None]
        if (given[0] if given else tags.self_collide):
            colliding.add(body)
    return colliding


class RobotBody:
    """A loaded URDF robot: link and joint access by name, in link frames."""

    def __init__(self, client: int, model: RobotModel, tags: GazeboTags, xml: str,
                 position: Sequence[float], orientation: Sequence[float], warn):
        self.client = client
        self.model = model
        prepared = prepare_urdf(xml, model, tags, warn)
        # what lasers cast against as convex hulls (World.spawn_urdf)
        self.collision_meshes = collision_meshes(prepared)
        flags = pb.URDF_USE_INERTIA_FROM_FILE | pb.URDF_USE_IMPLICIT_CYLINDER
        colliding = self_colliding_bodies(model, tags)
        if colliding:
            # parent and child never collide (a joint, or a fixed joint Gazebo lumps)
            flags |= pb.URDF_USE_SELF_COLLISION | pb.URDF_USE_SELF_COLLISION_EXCLUDE_PARENT
        if len(model.joints) > MAX_PYBULLET_JOINTS:  # it would hand back an unbuilt body
            raise UrdfError(f"{model.source}: pybullet could not build it: it has "
                            f"{len(model.links)} links and {len(model.joints)} joints, and "
                            f"pybullet builds at most {MAX_PYBULLET_JOINTS + 1} links "
                            f"({MAX_PYBULLET_JOINTS} joints) in one body")
        too_long = [name for name in (*model.links, *model.joints)
                    if len(name) > MAX_NAME_LENGTH]
        if too_long:
            raise UrdfError(f"{model.source}: a link or joint name of {len(too_long[0])} "
                            f"characters ('{too_long[0][:40]}...'); sim_bridge takes names of "
                            f"at most {MAX_NAME_LENGTH} (MAX_NAME_LENGTH): pybullet crashes on "
                            "longer ones")
        with tempfile.NamedTemporaryFile("w", suffix=".urdf", delete=False) as stream:
            stream.write(prepared)
            path = stream.name
        try:
            self.id = pb.loadURDF(path, list(position), list(orientation), flags=flags,
                                  useFixedBase=model.root() == "world", physicsClientId=client)
        except pb.error as error:
            raise UrdfError(f"{model.source}: pybullet could not load it: {error}") from None
        finally:
            os.unlink(path)

        self.link_index: Dict[str, int] = {model.root(): -1}
        self.joint_index: Dict[str, int] = {}
        for index in range(pb.getNumJoints(self.id, physicsClientId=client)):
            info = pb.getJointInfo(self.id, index, physicsClientId=client)
            self.joint_index[info[1].decode()] = index
            self.link_index[info[12].decode()] = index
        inertial = pb.getDynamicsInfo(self.id, -1, physicsClientId=client)
        # root link frame expressed in the base's centre-of-mass frame
        self._com_to_link = pb.invertTransform(inertial[3], inertial[4])
        self.weightless_links: List[Tuple[int, float]] = []
        if colliding:
            self._filter_self_collisions(colliding)
        self._apply_joint_settings()
        self._apply_surfaces(tags, warn)
        # their friction is sim_bridge.tyre_friction's, which the world applies each step
        self.tyres = tyres(model, tags, self.link_index)

    # --- set-up ---------------------------------------------------------------------
    def _filter_self_collisions(self, colliding: Set[str]) -> None:
        """Switches off the pairs of pybullet links that Gazebo does not let collide:
        parts of one Gazebo link (lumped), links a joint connects, and two links neither
        of which is in ``colliding``."""
        structure = urdf_structure(self.model)
        joined = set()
        for name in structure.joints:
            joint = self.model.joints[name]
            if joint.parent in structure.body_of:
                joined.add(frozenset((structure.body_of[joint.parent],
                                      structure.body_of[joint.child])))
        links = [(structure.body_of[link], index) for link, index in self.link_index.items()
                 if link in structure.body_of]
        for position, (body_a, index_a) in enumerate(links):
            for body_b, index_b in links[position + 1:]:
                allowed = (body_a != body_b and frozenset((body_a, body_b)) not in joined
                           and (body_a in colliding or body_b in colliding))
                if not allowed:
                    pb.setCollisionFilterPair(self.id, self.id, index_a, index_b, 0,
                                              physicsClientId=self.client)

    def _apply_joint_settings(self) -> None:
        for name, index in self.joint_index.items():
            joint = self.model.joints.get(name)
            if joint is None or not joint.movable:
                continue
            # switch pybullet's default braking motor off; keep the URDF's joint friction
            pb.setJointMotorControl2(self.id, index, pb.VELOCITY_CONTROL, targetVelocity=0.0,
                                     force=joint.friction, physicsClientId=self.client)
            pb.changeDynamics(self.id, index, jointDamping=joint.damping,
                              linearDamping=0.0, angularDamping=0.0,
                              physicsClientId=self.client)
        pb.changeDynamics(self.id, -1, linearDamping=0.0, angularDamping=0.0,
                          physicsClientId=self.client)

    def _apply_surfaces(self, tags: GazeboTags, warn) -> None:
        for link, index in self.link_index.items():
            surface = tags.surfaces.get(link)
            settings = dict(lateralFriction=1.0, rollingFriction=0.0, spinningFriction=0.0)
            if surface is not None:
                # pybullet multiplies the two surfaces' friction; the world's surfaces are
                # 1.0, so a contact gets the link's mu, as Gazebo's min(mu_a, mu_b) would
                settings["lateralFriction"] = surface.mu1
                if surface.mu2 != surface.mu1 and surface.mu1 > 0:
                    settings["anisotropicFriction"] = [1.0, surface.mu2 / surface.mu1, 1.0]
                if surface.kp is not None or surface.kd is not None:
                    settings["contactStiffness"] = \
                        surface.kp if surface.kp is not None else DEFAULT_KP
                    settings["contactDamping"] = \
                        surface.kd if surface.kd is not None else DEFAULT_KD
                if surface.material:
                    colour = gazebo_colour(surface.material)
                    if colour is None:
                        warn(f"{self.model.source}: link '{link}': unknown material "
                             f"'{surface.material}'; its URDF colour stays")
                    else:
                        self.set_colour(index, colour)
                if not surface.gravity:
                    mass = pb.getDynamicsInfo(self.id, index, physicsClientId=self.client)[0]
                    self.weightless_links.append((index, mass))
            pb.changeDynamics(self.id, index, physicsClientId=self.client, **settings)

    def set_colour(self, link_index: int, rgba: Sequence[float]) -> None:
        pb.changeVisualShape(self.id, link_index, rgbaColor=list(rgba),
                             physicsClientId=self.client)

    def apply_weightlessness(self, gravity: Sequence[float]) -> None:
        """Cancels gravity on links whose ``<gravity>`` is false (pybullet has no per-link
        switch): an opposite force at their centre of mass, each step."""
        for index, mass in self.weightless_links:
            com = (pb.getBasePositionAndOrientation(self.id, physicsClientId=self.client)[0]
                   if index == -1 else
                   pb.getLinkState(self.id, index, physicsClientId=self.client)[0])
            force = [-mass * g for g in gravity]
            pb.applyExternalForce(self.id, index, force, com, pb.WORLD_FRAME,
                                  physicsClientId=self.client)

    def set_gravity(self, indices: Sequence[int], on: bool) -> None:
        """Gravity on or off for some links (set_link_properties' gravity_mode); every
        weightless link's mass is read again, as it may have been changed."""
        weightless = {index for index, _ in self.weightless_links} - set(indices)
        if not on:
            weightless |= set(indices)
        self.weightless_links = [
            (index, pb.getDynamicsInfo(self.id, index, physicsClientId=self.client)[0])
            for index in sorted(weightless)]

    # --- reading ------------------------------------------------------------------
    def link_pose(self, link: str) -> Tuple[Vec3, Quat]:
        """World pose of a URDF link frame."""
        index = self.link_index[link]
        if index == -1:
            return self.base_pose()
        state = pb.getLinkState(self.id, index, computeForwardKinematics=1,
                                physicsClientId=self.client)
        return state[4], state[5]

    def base_pose(self) -> Tuple[Vec3, Quat]:
        com_position, com_orientation = pb.getBasePositionAndOrientation(
            self.id, physicsClientId=self.client)
        return pb.multiplyTransforms(com_position, com_orientation, *self._com_to_link)

    def base_twist(self) -> Tuple[np.ndarray, np.ndarray]:
        """Linear velocity of the root link frame's origin and angular velocity, world frame."""
        linear, angular = pb.getBaseVelocity(self.id, physicsClientId=self.client)
        com_position, com_orientation = pb.getBasePositionAndOrientation(
            self.id, physicsClientId=self.client)
        position, _ = pb.multiplyTransforms(com_position, com_orientation, *self._com_to_link)
        # v + w x r in floats (numpy's cross of two 3-vectors cost 10 us of the 20 this
        # took; the same products and sums, so the same numbers)
        rx, ry, rz = (position[0] - com_position[0], position[1] - com_position[1],
                      position[2] - com_position[2])
        wx, wy, wz = angular
        return (np.array((linear[0] + (wy * rz - wz * ry), linear[1] + (wz * rx - wx * rz),
                          linear[2] + (wx * ry - wy * rx))), np.array(angular))

    def set_base_state(self, position: Sequence[float], orientation: Sequence[float],
                       linear: Sequence[float] = (0, 0, 0),
                       angular: Sequence[float] = (0, 0, 0)) -> None:
        """Puts the root link frame at a pose with a twist (of its origin), world frame."""
        com_in_link = pb.invertTransform(*self._com_to_link)
        com_position, com_orientation = pb.multiplyTransforms(position, orientation,
                                                              *com_in_link)
        pb.resetBasePositionAndOrientation(self.id, com_position, com_orientation,
                                           physicsClientId=self.client)
        offset = np.asarray(com_position) - np.asarray(position)
        com_linear = np.asarray(linear) + np.cross(angular, offset)
        pb.resetBaseVelocity(self.id, com_linear.tolist(), list(angular),
                             physicsClientId=self.client)

    def joint_position_velocity(self, joint: str) -> Tuple[float, float]:
        state = pb.getJointState(self.id, self.joint_index[joint], physicsClientId=self.client)
        return state[0], state[1]

    def joint_states(self, joints: Sequence[str]) -> List[Tuple[float, float, float]]:
        """(position, velocity, applied effort) of each joint."""
        states = pb.getJointStates(self.id, [self.joint_index[j] for j in joints],
                                   physicsClientId=self.client)
        return [(s[0], s[1], s[3]) for s in states]

    def reset_joints(self, positions: Mapping[str, float]) -> None:
        for name, value in positions.items():
            pb.resetJointState(self.id, self.joint_index[name], value, 0.0,
                               physicsClientId=self.client)

    def movable_joints(self) -> List[str]:
        return [name for name in self.joint_index
                if name in self.model.joints and self.model.joints[name].movable]

    def remove(self) -> None:
        pb.removeBody(self.id, physicsClientId=self.client)

