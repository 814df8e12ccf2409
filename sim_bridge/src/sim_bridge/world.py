"""The simulated world: pybullet underneath, Gazebo's notions on top. No rospy here.

It holds the models (static scenery, free bodies from SDF, robots from URDF with their
plugins), steps the physics with a fixed step, keeps simulated time as an integer number
of nanoseconds (monotonic, also across resets), and answers Gazebo's questions: spawn,
delete, get and set a model's or a link's state, a model's, a joint's and a link's
properties (a link's mass and inertia: its lumped pybullet links together), the physics
properties (step size, update rate, gravity), wrenches and joint efforts for a while of
simulated time (:mod:`sim_bridge.external_forces`), the world file's lights, pause, reset.

Names are Gazebo's: a link is ``model::link`` or its plain name (the first model having
it, as Gazebo's ``EntityByName``), and a model's links and joints are those Gazebo shows,
after sdformat's lumping of fixed joints (:mod:`sim_bridge.model_structure`). Poses are of
link frames (URDF's, SDF's), never of pybullet's centres of mass; a model's pose is its
frame's (a robot's root link, an SDF model's ``<pose>``).

Static scenery is one fixed rigid body per shape (``useMaximalCoordinates``): a fixed
multi-link body would have all its links re-posed every step (four times the step cost
in a 40-object hall). Lasers do not ask pybullet: see :mod:`sim_bridge.ray_caster` (a
moving body's collision mesh: its convex hulls, :mod:`sim_bridge.convex_hulls`), except
for static scenery's meshes, which collide as their triangles.
"""
from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from typing import Any, Dict, List, Mapping, Optional, Sequence, Set, Tuple, Union

import numpy as np
import pybullet as pb

from sim_bridge.convex_hulls import mesh_hulls
from sim_bridge.external_forces import (BodyWrench, ExternalForces, JointEffort, LinkMasses,
                                        Window, centre_of_mass)
from sim_bridge.gazebo_tags import GazeboTags, read_gazebo_tags
from sim_bridge.model_structure import Structure, sdf_structure, urdf_structure
from sim_bridge.native_plugins import NativePlugins
from sim_bridge.plugins import MODEL_PLUGINS, SENSOR_PLUGINS, create_plugins
from sim_bridge.plugins.base import NEVER, Bus, Plugin, PluginContext
from sim_bridge.poses import (compose6, normalized, pose6_matrix, pose6_to_position_quaternion,
                              quaternion_from_rpy, quaternion_matrix)
from sim_bridge import ray_kernel
from sim_bridge.ray_caster import Primitive, ShapeSet, cast, primitive_for
from sim_bridge.ray_scene import RayScene
from sim_bridge.robot_body import RobotBody
from sim_bridge.sdf_world import LightSpec, ModelSpec, ShapeSpec, WorldSpec
from sim_bridge.tyre_friction import TyreFriction
from urdf_tools.kinematics import link_transform, matrix_rpy, origin_transform, rpy_matrix
from urdf_tools.model import UrdfError, parse_urdf

# pybullet multiplies the friction of the two surfaces in contact: world surfaces are 1.0
# so that a contact gets the robot link's own mu (Gazebo takes the smaller of the two).
WORLD_FRICTION = 1.0

Vec3 = Tuple[float, float, float]
Quat = Tuple[float, float, float, float]
Transform = Tuple[Vec3, Quat]
IDENTITY: Transform = ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))
# A robot spawned into the scenery is raised out of what lies under it: contacts deeper than
# this (m) whose normal points up at least this much (cos of 60 degrees), a few rounds at most
# (each round clears the deepest contact; a slope may uncover another).
PENETRATION_TOLERANCE = 0.001
MIN_FLOOR_NORMAL_Z = 0.5
MAX_LIFTS = 5
# reference frames that mean the world (gazebo_ros: "", world, map, /map)
WORLD_FRAMES = frozenset(("", "world", "/world", "map", "/map"))
# ODE's settings as Gazebo's worlds have them, reported by get_physics_properties (the
# solver is pybullet's, not ODE: see World.physics_properties)
ODE_DEFAULTS = dict(auto_disable_bodies=False, sor_pgs_precon_iters=0, sor_pgs_iters=50,
                    sor_pgs_w=1.3, sor_pgs_rms_error_tol=0.0, contact_surface_layer=0.001,
                    contact_max_correcting_vel=100.0, cfm=0.0, erp=0.2, max_contacts=20)
# What set_physics_properties takes beyond Gazebo's own checks (it has none: a rate of
# 1e-9 Hz makes Gazebo's world thread sleep 1e9 s before its next step). The simulator
# serves requests and Ctrl-C between steps and, paced, sleeps 1/max_update_rate wall
# seconds a step, so a rate other than 0 (as fast as possible) must be at least this many
# steps per wall second: the node then answers within a second (the same floor as
# real_time_factor's 0.001 at the default 1 ms step).
MIN_UPDATE_RATE = 1.0
# Simulated time counts whole nanoseconds: a step under half of one rounds to 0 and time
# would stand still. ROS time's seconds are unsigned 32-bit: a longer step than this (s)
# cannot be put on /clock even once.
MAX_TIME_STEP = float(2 ** 32 - 1)
# The longest step pybullet takes: a world's longer <max_step_size> (Gazebo's step: plugins,
# controllers and the clock keep it) is stepped by pybullet in equal parts no longer than
# this, the step's forces and motor targets held through them, as ODE holds them through
# its step. Above about 5 ms pybullet's joint motors let go under load where ODE's hold:
# AgileX LIMO (ugv_gazebo_sim, a 10 ms world), its wheels held at speed by its drive
# plugin's motors against gazebo_ros_control's velocity PID, got 3.7 of the 6.7 N m its
# motors had to give at 10 ms and flipped over; all of it at 5 ms, in pybullet alone too.
MAX_PHYSICS_STEP = 0.005
# at most this many parts (a step of 0.5 s; a longer one is stepped in parts this many)
MAX_PHYSICS_PARTS = 100


@dataclass(frozen=True)
class RayShape:
    """A moving model's collision shape as lasers see it: ``local`` places it in its link's
    frame (``link`` None: the free body's frame). A hull (one object of a collision mesh):
    ``planes`` in its own frame, ``radius`` its bounding sphere's about that frame's origin."""

    link: Optional[str]
    local: np.ndarray
    kind: str
    size: Optional[Sequence[float]] = None
    radius: Optional[float] = None
    length: Optional[float] = None
    planes: Optional[np.ndarray] = None

    def placed(self, frame: np.ndarray) -> Primitive:
        return primitive_for(self.kind, frame @ self.local, size=self.size, radius=self.radius,
                             length=self.length, planes=self.planes)


def hull_ray_shapes(link: Optional[str], local: np.ndarray, path: str,
                    scale: Sequence[float]) -> Tuple[List[RayShape], bool]:
    """The convex hulls pybullet collides a moving mesh as (one per object of the file it
    loads, ``path``, scaled), as lasers' shapes placed by ``local`` in the link's frame; and
    whether some of it has no hull here (an object with no volume, an unreadable file),
    which pybullet must then answer for."""
    try:
        hulls, flat = mesh_hulls(path, scale)
    except (OSError, ValueError):
        return [], True
    shapes = []
    for hull in hulls:
        centred = np.eye(4)
        centred[:3, 3] = hull.centre
        shapes.append(RayShape(link, local @ centred, "hull", radius=hull.radius,
                               planes=hull.planes))
    return shapes, flat > 0


class SimError(ValueError):
    """A request the world cannot carry out; the message says why."""


@dataclass
class Model:
    name: str
    kind: str  # "static", "body" (free SDF body) or "robot" (URDF)
    initial_position: Vec3
    initial_orientation: Quat
    namespace: str = ""
    spec: Optional[ModelSpec] = None
    body: Optional[int] = None
    robot: Optional[RobotBody] = None
    tags: Optional[GazeboTags] = None
    plugins: List[Plugin] = field(default_factory=list)
    # robots with tyres: their friction, applied before each step
    friction: Optional[TyreFriction] = None
    initial_joints: Dict[str, float] = field(default_factory=dict)
    # for static models: where they are (they never move), their bodies and shapes
    position: Vec3 = (0.0, 0.0, 0.0)
    orientation: Quat = (0.0, 0.0, 0.0, 1.0)
    static_bodies: List[int] = field(default_factory=list)
    primitives: List[Primitive] = field(default_factory=list)  # static: placed in the world
    # moving models: their shapes for lasers, placed each scan from the bodies' poses
    ray_shapes: List[RayShape] = field(default_factory=list)
    has_mesh: bool = False
    # the pybullet (body, link) pairs holding collision meshes that lasers cast through
    # pybullet: static scenery's (concave: their triangles) and what has no hull in
    # ray_shapes (a flat object, a link whose mesh was replaced by a box)
    mesh_holders: List[Tuple[int, int]] = field(default_factory=list)
    # the links, joints and collisions Gazebo shows (see sim_bridge.model_structure)
    structure: Structure = field(default_factory=lambda: Structure(()))
    # free SDF bodies: the link's frame and pybullet's base (its centre of mass) in the
    # model's frame
    link_in_model: Transform = IDENTITY
    com_in_model: Transform = IDENTITY
    # robots: what their plugins were made with (Gazebo C++ plugins' sensors read through it)
    context: Optional[PluginContext] = None
    # what set_joint_properties changed: joint → damping (N m s/rad), (lower, upper) stops
    joint_damping: Dict[str, float] = field(default_factory=dict)
    joint_stops: Dict[str, Tuple[float, float]] = field(default_factory=dict)
    # a free SDF body whose gravity set_link_properties switched off (a robot's links:
    # RobotBody.weightless_links)
    weightless: bool = False


@dataclass(frozen=True)
class LinkRef:
    """One of Gazebo's links: a model's name and the link's (plain) name."""

    model: str
    link: str

    @property
    def scoped(self) -> str:
        return f"{self.model}::{self.link}"


@dataclass(frozen=True)
class ModelProperties:
    """gazebo_msgs/GetModelProperties' answer."""

    parent_model_name: str
    canonical_body_name: str
    body_names: Tuple[str, ...]
    geom_names: Tuple[str, ...]
    joint_names: Tuple[str, ...]
    child_model_names: Tuple[str, ...]
    is_static: bool


@dataclass(frozen=True)
class JointProperties:
    """gazebo_msgs/GetJointProperties' answer: the type's name, one value per axis."""

    type: str
    damping: Tuple[float, ...]
    position: Tuple[float, ...]
    rate: Tuple[float, ...]


@dataclass(frozen=True)
class LinkProperties:
    """gazebo_msgs/GetLinkProperties' answer for one of Gazebo's links (its lumped parts
    together): the centre of mass in the link's frame, the mass, and the inertia tensor
    about the centre of mass in the axes of the link's inertial frame, as Gazebo's
    ``Inertial`` holds it (``ixx, ixy, ixz, iyy, iyz, izz``)."""

    com: Vec3
    gravity_mode: bool
    mass: float
    inertia: Tuple[float, float, float, float, float, float]


@dataclass(frozen=True)
class _MassPart:
    """One pybullet link (or a static link's SDF inertial) of a Gazebo link: its mass, its
    principal moments, its principal axes and its centre of mass in the Gazebo link's
    frame. ``index``: pybullet's link index (-1 the base), None for a static model."""

    index: Optional[int]
    mass: float
    moments: np.ndarray
    axes: np.ndarray
    centre: np.ndarray

    def tensor(self, scale: float = 1.0) -> np.ndarray:
        """Its inertia about its own centre of mass, in the Gazebo link's axes."""
        return self.axes @ np.diag(self.moments * scale) @ self.axes.T


def _combined(parts: Sequence[_MassPart]) -> Tuple[float, np.ndarray, np.ndarray]:
    """Mass, centre of mass and inertia about it (the link's axes) of lumped parts: the
    parallel-axis theorem, as sdformat lumps a fixed joint's child into its parent."""
    mass = sum(part.mass for part in parts)
    centre = sum(part.mass * part.centre for part in parts) / mass
    tensor = np.zeros((3, 3))
    for part in parts:
        offset = part.centre - centre
        tensor += part.tensor() + part.mass * (offset @ offset * np.eye(3)
                                               - np.outer(offset, offset))
    return mass, centre, tensor


@dataclass(frozen=True)
class SensorRate:
    """A sensor as performance_metrics names it (``model::link::sensor``, the link
    Gazebo's, after lumping), its type and its update rate in Hz of simulated time."""

    name: str
    type: str
    rate: float


@dataclass(frozen=True)
class PhysicsProperties:
    """gazebo_msgs/GetPhysicsProperties' answer; ``ode`` holds ODEPhysics' fields."""

    time_step: float
    paused: bool
    max_update_rate: float
    gravity: Vec3
    ode: Dict[str, Any]


# The largest coordinate pybullet's transform functions carry: they compute in single
# precision, so a position of 1e300 sent to set_model_state came back (inf, nan, nan).
MAX_COORDINATE = float(np.finfo(np.float32).max)
# set_link_properties: how far (m) a centre of mass asked for may be from the link's and
# still be its own (get_link_properties' figures come back exactly; this allows for a
# client's rounding), and the share of the largest moment a product of inertia may reach
# in a part's principal axes and still be zero (the rounding of the rotations)
COM_TOLERANCE = 1e-6
INERTIA_TOLERANCE = 1e-6


def _finite(values: Sequence[float], what: str) -> None:
    """Refuses numbers that are not finite or beyond MAX_COORDINATE, naming them as given."""
    given = tuple(float(v) for v in values)
    if not all(math.isfinite(v) for v in given):
        raise SimError(f"{what} {given} is not finite")
    if any(abs(v) > MAX_COORDINATE for v in given):
        raise SimError(f"{what} {given} is beyond +-{MAX_COORDINATE:.3g}, the largest number "
                       "pybullet's transforms carry (single precision)")


def _checked_state(position: Sequence[float], orientation: Sequence[float],
                   linear: Sequence[float], angular: Sequence[float]) -> Quat:
    """The orientation normalised, once every number of a requested state is checked."""
    _finite(position, "the position")
    _finite(linear, "the linear velocity")
    _finite(angular, "the angular velocity")
    try:
        return normalized(orientation)
    except ValueError as error:
        raise SimError(f"the orientation: {error}") from None


def _compose(outer: Transform, inner: Transform) -> Transform:
    return pb.multiplyTransforms(outer[0], outer[1], inner[0], inner[1])


def _inverse(transform: Transform) -> Transform:
    return pb.invertTransform(transform[0], transform[1])


def _moved(linear: Sequence[float], angular: Sequence[float], origin: Sequence[float],
           point: Sequence[float]) -> np.ndarray:
    """The velocity of ``point`` on a rigid body whose ``origin`` moves at ``linear`` while
    it turns at ``angular``."""
    return np.asarray(_moved_floats(linear, angular, origin, point))


def _moved_floats(linear: Sequence[float], angular: Sequence[float], origin: Sequence[float],
                  point: Sequence[float]) -> List[float]:
    """:func:`_moved` in floats, for the per-step callers (numpy's small arrays cost µs)."""
    turned = _cross(angular, (point[0] - origin[0], point[1] - origin[1], point[2] - origin[2]))
    return [linear[0] + turned[0], linear[1] + turned[1], linear[2] + turned[2]]


def _cross(a: Sequence[float], b: Sequence[float]) -> Tuple[float, float, float]:
    """a × b of two 3-vectors, in floats: numpy's cross takes ~19 µs on 3-vectors here, and a
    Gazebo plugin's SetLinearVel reaches here once a step."""
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def pose_matrix(position: Sequence[float], orientation: Sequence[float]) -> np.ndarray:
    transform = np.eye(4)
    transform[:3, :3] = quaternion_matrix(orientation)
    transform[:3, 3] = position
    return transform


class World:
    def __init__(self, bus: Bus, step_size: float = 0.001,
                 gravity: Sequence[float] = (0.0, 0.0, -9.8), gui: bool = False, seed: int = 0,
                 ray_threads: int = 0):
        self.bus = bus
        self.gui = gui
        self.client = pb.connect(pb.GUI if gui else pb.DIRECT)
        if gui:  # the world alone: no debug panels, no camera previews
            pb.configureDebugVisualizer(pb.COV_ENABLE_GUI, 0, physicsClientId=self.client)
        self.seed = seed
        self.rng = np.random.default_rng(seed)
        self.ray_threads = ray_threads
        self.models: Dict[str, Model] = {}
        # derived from the models, rebuilt when they change (see _scene_changed)
        self._static_shapes: Optional[ShapeSet] = None
        self._plugins: Optional[List[Plugin]] = None  # what step() calls
        self._has_meshes: Optional[bool] = None
        # what lasers see (sim_bridge.ray_scene), rebuilt after the scene changes
        self._ray_scene: Optional[RayScene] = None
        # counts the changes of the scene (models added, deleted, static ones moved)
        self.scene_version = 0
        self._weightless: List[RobotBody] = []
        self._frictions: List[TyreFriction] = []
        # (body, link) of every robot's tyres (sim_bridge.tyre_friction)
        self._tyres: Set[Tuple[int, int]] = set()
        self.now_ns = 0
        self.paused = False
        self.step_size = step_size
        self.gravity = tuple(gravity)
        # Gazebo's real_time_update_rate: steps per wall second the simulator aims at
        # (0: as many as it can); the world does not pace itself, its owner does
        self.max_update_rate = 1.0 / step_size
        self.forces = ExternalForces(self.client)
        # the world file's lights (gazebo_ros's light services), in its order
        self.lights: List[LightSpec] = []
        # free SDF bodies without gravity: (pybullet body, mass)
        self._weightless_bodies: List[Tuple[int, float]] = []
        self.world_name = "default"
        # Gazebo's C++ plugins (sim_bridge.native_plugins) and the joint efforts they set for
        # the next step: (body, joint index) → N or N m
        self.native = NativePlugins(self)
        self._native_efforts: Dict[Tuple[int, int], float] = {}
        self._configure_physics()

    # --- physics settings --------------------------------------------------------------
    def _configure_physics(self) -> None:
        pb.setGravity(*self.gravity, physicsClientId=self.client)
        pb.setTimeStep(self.step_size, physicsClientId=self.client)
        # (numSubSteps 0 and 1 are both one step)
        parts = min(math.ceil(self.step_size / MAX_PHYSICS_STEP - 1e-9), MAX_PHYSICS_PARTS)
        pb.setPhysicsEngineParameter(numSubSteps=parts if parts > 1 else 0,
                                     physicsClientId=self.client)
        self._step_ns = int(round(self.step_size * 1e9))
        # Friction as a pyramid, as Gazebo's ODE. A robot's (multibody's) contacts get it
        # on the world's axes whatever this says, so tyres get theirs from
        # sim_bridge.tyre_friction, whose slip scale follows the step.
        pb.setPhysicsEngineParameter(deterministicOverlappingPairs=1, enableConeFriction=0,
                                     physicsClientId=self.client)
        for model in self.models.values():
            if model.friction is not None:
                model.friction.set_physics(self.step_size, self.gravity)

    @property
    def step_ns(self) -> int:
        return self._step_ns

    @property
    def now(self) -> float:
        return self.now_ns / 1e9

    @property
    def real_time_factor(self) -> float:
        """Simulated seconds per wall second aimed at: max_update_rate × step size (0: as
        fast as possible), as Gazebo derives it."""
        return self.max_update_rate * self.step_size

    @real_time_factor.setter
    def real_time_factor(self, factor: float) -> None:
        if not math.isfinite(factor) or factor < 0:
            raise SimError(f"the real time factor must be 0 (as fast as possible) or "
                           f"positive, not {factor}")
        self.max_update_rate = factor / self.step_size

    def physics_properties(self) -> PhysicsProperties:
        """Gazebo's physics properties. pybullet's solver is not ODE: ``ode`` reports
        pybullet's solver iterations as ``sor_pgs_iters`` and, for the rest, the values of
        Gazebo's ODE that pybullet's defaults correspond to (erp 0.2, cfm 0)."""
        ode = dict(ODE_DEFAULTS)
        ode["sor_pgs_iters"] = int(pb.getPhysicsEngineParameters(
            physicsClientId=self.client)["numSolverIterations"])
        return PhysicsProperties(self.step_size, self.paused, self.max_update_rate,
                                 tuple(self.gravity), ode)

    def set_physics(self, time_step: float, max_update_rate: float,
                    gravity: Sequence[float]) -> None:
        """gazebo_ros's set_physics_properties: the step size (s), the update rate (steps
        per wall second, 0: as fast as possible) and gravity (m/s²). Plugins see the new
        step size and gravity from the next step on; rates they fixed when spawned stay."""
        now = (f"(it is {self.step_size:g} now; get_physics_properties gives every current "
               "value)")
        if not math.isfinite(time_step) or time_step <= 0:
            raise SimError(f"time_step {time_step} must be a positive number of seconds {now}")
        if time_step > MAX_TIME_STEP:
            raise SimError(f"time_step {time_step} is longer than ROS time can carry "
                           f"({MAX_TIME_STEP:.0f} s) {now}")
        if round(time_step * 1e9) < 1:
            raise SimError(f"time_step {time_step} is below a nanosecond, the resolution of "
                           f"simulated time: the clock would not advance {now}")
        if not math.isfinite(max_update_rate) or max_update_rate < 0:
            raise SimError(f"max_update_rate {max_update_rate} must be 0 (as fast as "
                           "possible) or a positive number of steps per second")
        if 0 < max_update_rate < MIN_UPDATE_RATE:
            raise SimError(f"max_update_rate {max_update_rate} is too slow: each step would "
                           f"wait {1 / max_update_rate:.3g} s of wall time, during which the "
                           "simulator answers no request; give 0 (as fast as possible) or "
                           f"at least {MIN_UPDATE_RATE:g} step per second")
        _finite(gravity, "gravity")
        self.step_size = float(time_step)
        self.max_update_rate = float(max_update_rate)
        self.gravity = tuple(float(g) for g in gravity)
        self._configure_physics()
        for model in self.models.values():
            for plugin in model.plugins:
                context = getattr(plugin, "context", None)
                if context is not None:
                    context.step_size = self.step_size
                    context.gravity = self.gravity

    def load_world(self, spec: WorldSpec) -> None:
        factor = self.real_time_factor
        self.step_size = spec.step_size
        self.gravity = spec.gravity
        self.max_update_rate = factor / self.step_size
        self.world_name = spec.name
        self._configure_physics()
        for model in spec.models:
            self.add_sdf_model(model)
        self.lights.extend(spec.lights)
        # Events::worldCreated once the models are in, before the world's plugins load
        # (gazebo 11 physics/World.cc:414, in World::Load; the plugins in World::Init)
        self.native.world_created()
        for element in spec.plugins:  # after the models, as Gazebo loads them
            self.native.load_world_plugin(spec.name, element)

    # --- models from SDF ------------------------------------------------------------------
    def add_sdf_model(self, spec: ModelSpec, position: Optional[Sequence[float]] = None,
                      orientation: Optional[Sequence[float]] = None, namespace: str = "") -> Model:
        if spec.name in self.models:
            raise SimError(f"a model named '{spec.name}' exists already; delete it or pick "
                           "another name")
        if position is not None:
            # gazebo_ros's spawn composes the model's own <pose> with the request's
            # initial_pose: initial_pose * <pose> (gazebo_ros_pkgs noetic-devel f9e1a46,
            # gazebo_ros/src/gazebo_ros_api_plugin.cpp:761, :2459-2475, updateSDFAttributes)
            orientation = _checked_state(position, orientation or (0, 0, 0, 1), (0, 0, 0),
                                         (0, 0, 0))
            roll_pitch_yaw = pb.getEulerFromQuaternion(list(orientation))
            spec.pose = compose6((*position, *roll_pitch_yaw), spec.pose)
        if spec.urdf:  # articulated: built as the URDF robot it converts to, as Gazebo would
            root = compose6(spec.pose, spec.urdf_root_pose)
            # its <plugin>s travel in the URDF's <gazebo> blocks (sim_bridge.sdf_articulated)
            return self.spawn_urdf(spec.name, spec.urdf, *pose6_to_position_quaternion(root),
                                   namespace=namespace, source=spec.source)
        pos, orn = pose6_to_position_quaternion(spec.pose)
        model = Model(spec.name, "static" if spec.static else "body", pos, orn, namespace, spec,
                      position=pos, orientation=orn)
        model.has_mesh = any(s.kind == "mesh" for link in spec.links for s in link.collisions)
        model.structure = sdf_structure(spec)
        if spec.static:
            self._create_static_bodies(model)
        else:
            model.body = self._free_body(spec)
            # pybullet's base is the link's centre of mass
            link_pose = pose6_to_position_quaternion(spec.links[0].pose)
            inertial = pb.getDynamicsInfo(model.body, -1, physicsClientId=self.client)
            model.link_in_model = link_pose
            model.com_in_model = _compose(link_pose, (inertial[3], inertial[4]))
            model.ray_shapes = [
                RayShape(None, pose6_matrix(link.pose) @ pose6_matrix(shape.pose), shape.kind,
                         shape.size, shape.radius, shape.length)
                for link in spec.links for shape in link.collisions if shape.kind != "mesh"]
            for link in spec.links:
                for shape in link.collisions:
                    if shape.kind != "mesh":
                        continue
                    hulls, unmatched = hull_ray_shapes(
                        None, pose6_matrix(link.pose) @ pose6_matrix(shape.pose),
                        shape.filename, shape.scale)
                    model.ray_shapes.extend(hulls)
                    if unmatched:
                        model.mesh_holders = [(model.body, -1)]
        self.models[spec.name] = model
        self._scene_changed()
        self._load_native_plugins(spec.name, spec.plugins, namespace)
        return model

    def _load_native_plugins(self, name: str, elements: Sequence[Any], namespace: str) -> None:
        """The model's plugins that sim_bridge does not emulate, loaded as Gazebo's C++
        plugins once the model is in the world (sim_bridge.native_plugins); one that cannot
        be is a warning, and the model stays."""
        for element in elements:
            if element.get("filename", "") not in MODEL_PLUGINS:
                self.native.load_model_plugin(name, element, namespace)

    def _scene_changed(self) -> None:
        """Models came, went or moved: what is derived from them is rebuilt when next used."""
        self.scene_version += 1
        self._plugins = None
        self._static_shapes = None
        self._has_meshes = None
        self._ray_scene = None

    def _shape_arguments(self, shape: ShapeSpec, collision: bool, concave: bool = False) -> dict:
        """pybullet's createCollisionShape/createVisualShape arguments. ``concave``: a mesh
        collides as its triangles (static scenery only: pybullet moves no concave shape),
        not as its convex hull, which fills a ring wall or a room in."""
        arguments: dict = {}
        if shape.kind == "box":
            arguments = dict(shapeType=pb.GEOM_BOX, halfExtents=[s / 2 for s in shape.size])
        elif shape.kind == "cylinder":
            key = "height" if collision else "length"
            arguments = {"shapeType": pb.GEOM_CYLINDER, "radius": shape.radius,
                         key: shape.length}
        elif shape.kind == "sphere":
            arguments = dict(shapeType=pb.GEOM_SPHERE, radius=shape.radius)
        elif shape.kind == "mesh":
            arguments = dict(shapeType=pb.GEOM_MESH, fileName=shape.filename,
                             meshScale=list(shape.scale))
            if collision and concave:
                arguments["flags"] = pb.GEOM_FORCE_CONCAVE_TRIMESH
        elif shape.kind == "heightmap":  # a collision only (sdf_world leaves its visual out)
            arguments = dict(shapeType=pb.GEOM_HEIGHTFIELD,
                             **shape.heightmap.shape_arguments())
        elif shape.kind == "plane":
            if collision:
                arguments = dict(shapeType=pb.GEOM_PLANE, planeNormal=list(shape.normal))
            else:  # a thin box shows a plane of the size the SDF gives
                arguments = dict(shapeType=pb.GEOM_BOX,
                                 halfExtents=[shape.size[0] / 2, shape.size[1] / 2, 0.0005])
        if not collision:
            arguments["rgbaColor"] = list(shape.rgba or (0.7, 0.7, 0.7, 1.0))
        return arguments

    def _make_shape(self, shape: ShapeSpec, collision: bool, relative_to=None,
                    concave: bool = False) -> int:
        """A pybullet shape; ``relative_to`` = (link pose, body pose) places a visual on a
        body that is not at the visual's own pose; ``concave``: see _shape_arguments."""
        arguments = self._shape_arguments(shape, collision, concave)
        if relative_to is not None:
            link_pose, body_pose = relative_to
            offset = np.linalg.inv(pose6_matrix(body_pose)) @ pose6_matrix(
                compose6(link_pose, shape.pose))
            arguments["visualFramePosition"] = offset[:3, 3].tolist()
            arguments["visualFrameOrientation"] = list(
                quaternion_from_rpy(*matrix_rpy(offset[:3, :3])))
        create = pb.createCollisionShape if collision else pb.createVisualShape
        return create(physicsClientId=self.client, **arguments)

    def _create_static_bodies(self, model: Model) -> None:
        """One fixed rigid body per collision shape and one per visual: pybullet does not
        touch them between steps (a multi-link body's links are re-posed every step)."""
        model.static_bodies = []
        model.primitives = []
        if model.spec.plane_pose is None:
            model.spec.plane_pose = model.spec.pose
        for link in model.spec.links:
            link_pose = compose6(model.spec.pose, link.pose)
            visuals = list(link.visuals)
            for shape in link.collisions:
                pose = compose6(link_pose, shape.pose)
                if shape.kind == "plane":  # its body's z axis is the normal
                    made_at = compose6(compose6(model.spec.plane_pose, link.pose), shape.pose)
                    pose = self._plane_placement(made_at, shape.normal)
                    shape = dataclasses.replace(shape, normal=(0.0, 0.0, 1.0))
                if shape.kind == "heightmap":  # pybullet centres it between its extremes
                    pose = compose6(pose, (0.0, 0.0, shape.heightmap.centre_height(),
                                           0.0, 0.0, 0.0))
                # a link's only visual rides on its first collision body: half the bodies
                visual = -1
                if len(link.visuals) == 1 and visuals:
                    visual = self._make_shape(visuals.pop(), False,
                                              relative_to=(link_pose, pose))
                body = self._fixed_body(self._make_shape(shape, True, concave=True), visual,
                                        pose)
                # min(mu, 1): see WORLD_FRICTION
                friction = WORLD_FRICTION if shape.friction is None \
                    else min(shape.friction, WORLD_FRICTION)
                pb.changeDynamics(body, -1, lateralFriction=friction, physicsClientId=self.client)
                model.static_bodies.append(body)
                if shape.kind in ("mesh", "heightmap"):
                    model.mesh_holders.append((body, -1))
                else:  # meshes and terrain: lasers ask pybullet (see cast_rays)
                    model.primitives.append(primitive_for(
                        shape.kind, pose6_matrix(pose), size=shape.size, radius=shape.radius,
                        length=shape.length))
            for shape in visuals:
                pose = compose6(link_pose, shape.pose)
                model.static_bodies.append(self._fixed_body(-1, self._make_shape(shape, False),
                                                            pose))

    @staticmethod
    def _plane_placement(pose: Sequence[float], normal: Sequence[float]) -> Tuple[float, ...]:
        """Where a plane collision lies, as Gazebo 11's ODE makes it (gazebo-classic
        0c6796e gazebo/physics/ode/ODEPlaneShape.cc:33-47, CreatePlane): the SDF's
        ``<normal>`` taken in world axes, whatever the pose's rotation, at the collision's
        world height (``dCreatePlane(n, z)``, the plane n.x = z/|n| once ODE makes n a unit
        vector), and never moved after (ODE's planes cannot be placed). The SDF spec puts
        the normal in the collision's frame (sdformat sdf9 66a8c21 sdf/1.6/plane_shape.sdf:3-7);
        Gazebo does not, and the worlds that run there rely on it (gazebo-classic issue
        2274): a wall decal, a plane stood on its edge, is a second floor there, not a
        half-space that throws out what stands in front of it. The pose returned: the
        plane's point nearest the origin, turned so that its z axis is the normal (the
        frame pybullet's plane and the lasers' plane primitive take)."""
        direction = np.asarray(normal, dtype=float)
        length = float(np.linalg.norm(direction))
        direction = direction / length
        origin = direction * (pose[2] / length)
        # any frame whose z axis is the normal: x from the world axis least along it
        helper = np.eye(3)[int(np.argmin(np.abs(direction)))]
        x_axis = np.cross(helper, direction)
        x_axis /= np.linalg.norm(x_axis)
        rotation = np.column_stack([x_axis, np.cross(direction, x_axis), direction])
        return (*origin.tolist(), *matrix_rpy(rotation))

    def _fixed_body(self, collision: int, visual: int, pose: Sequence[float]) -> int:
        position, orientation = pose6_to_position_quaternion(pose)
        return pb.createMultiBody(baseMass=0, baseCollisionShapeIndex=collision,
                                  baseVisualShapeIndex=visual, basePosition=list(position),
                                  baseOrientation=list(orientation), useMaximalCoordinates=True,
                                  physicsClientId=self.client)

    def _remove_static_bodies(self, model: Model) -> None:
        for body in model.static_bodies:
            pb.removeBody(body, physicsClientId=self.client)
        model.static_bodies = []

    def _free_body(self, spec: ModelSpec) -> int:
        if len(spec.links) != 1:
            raise SimError(f"model '{spec.name}': a free (non-static) SDF model must have one "
                           f"link; it has {len(spec.links)}")
        link = spec.links[0]
        if len(link.collisions) > 16 or len(link.visuals) > 16:
            raise SimError(f"model '{spec.name}': at most 16 collisions and 16 visuals per link")
        collision = self._compound(link.collisions, True)
        visual = self._compound(link.visuals, False)
        pose = compose6(spec.pose, link.pose)
        position, orientation = pose6_to_position_quaternion(pose)
        inertial_position, inertial_orientation = pose6_to_position_quaternion(link.inertial_pose)
        body = pb.createMultiBody(baseMass=link.mass, baseCollisionShapeIndex=collision,
                                  baseVisualShapeIndex=visual, basePosition=list(position),
                                  baseOrientation=list(orientation),
                                  baseInertialFramePosition=list(inertial_position),
                                  baseInertialFrameOrientation=list(inertial_orientation),
                                  physicsClientId=self.client)
        # the collision's <mu> where it gives one (the first that does), as Gazebo reads it
        friction = next((shape.friction for shape in link.collisions
                         if shape.friction is not None), WORLD_FRICTION)
        pb.changeDynamics(body, -1, localInertiaDiagonal=list(link.inertia),
                          lateralFriction=friction, linearDamping=0.0, angularDamping=0.0,
                          physicsClientId=self.client)
        return body

    def _compound(self, shapes: Sequence[ShapeSpec], collision: bool) -> int:
        if not shapes:
            return -1
        if len(shapes) == 1 and shapes[0].pose == (0.0,) * 6:
            return self._make_shape(shapes[0], collision)
        types, extents, radii, lengths, files, scales, normals, positions, orientations, colours = \
            [], [], [], [], [], [], [], [], [], []
        for shape in shapes:
            arguments = self._shape_arguments(shape, collision)
            types.append(arguments["shapeType"])
            extents.append(arguments.get("halfExtents", [0, 0, 0]))
            radii.append(arguments.get("radius", 0.0))
            lengths.append(arguments.get("height", arguments.get("length", 0.0)))
            files.append(arguments.get("fileName", ""))
            scales.append(arguments.get("meshScale", [1, 1, 1]))
            normals.append(arguments.get("planeNormal", [0, 0, 1]))
            positions.append(list(shape.pose[:3]))
            orientations.append(list(quaternion_from_rpy(*shape.pose[3:6])))
            colours.append(arguments.get("rgbaColor"))
        common = dict(shapeTypes=types, halfExtents=extents, radii=radii, lengths=lengths,
                      fileNames=files, meshScales=scales, planeNormals=normals,
                      physicsClientId=self.client)
        if collision:
            return pb.createCollisionShapeArray(collisionFramePositions=positions,
                                                collisionFrameOrientations=orientations,
                                                **common)
        return pb.createVisualShapeArray(visualFramePositions=positions,
                                         visualFrameOrientations=orientations, **common)

    # --- robots from URDF ---------------------------------------------------------------
    def spawn_urdf(self, name: str, xml: str, position: Sequence[float] = (0, 0, 0),
                   orientation: Sequence[float] = (0, 0, 0, 1), namespace: str = "/",
                   joints: Optional[Mapping[str, float]] = None, source: str = "",
                   tf_prefix: str = "") -> Model:
        """Spawns a URDF robot. ``namespace`` is the spawn request's robot_namespace: "/"
        (spawn_model's at the top level) or another goes to the plugins naming none; ""
        (a request naming none, a model of a world file) leaves them their own defaults."""
        if not name:
            raise SimError("the model needs a name")
        if name in self.models:
            raise SimError(f"a model named '{name}' exists already; delete it or pick "
                           "another name")
        _finite(position, "the initial position")
        try:
            orientation = normalized(orientation)
        except ValueError as error:
            raise SimError(f"the initial orientation: {error}") from None
        description = parse_urdf(xml, source or f"model '{name}'")
        tags = read_gazebo_tags(description)
        for tag, where in tags.not_emulated.items():
            self.bus.warn(f"model '{name}': <{tag}> in {where} is not emulated by sim_bridge; "
                          "ignored")
        for reference, held in tags.unknown_references.items():
            self.bus.warn(f"model '{name}': <gazebo reference='{reference}'> names no link or "
                          f"joint of the model; its block ({', '.join(held) or 'empty'}) is "
                          "ignored and the model loads without it, as in Gazebo")
        joints = dict(joints or {})
        unknown = [j for j in joints if j not in description.joints]
        if unknown:
            raise SimError(f"model '{name}' has no joint(s) {', '.join(unknown)}")
        robot = RobotBody(self.client, description, tags, xml, position, orientation,
                          self.bus.warn)
        robot.reset_joints(joints)
        position = self._lifted_out_of_scenery(robot, position, orientation, name)
        model = Model(name, "robot", tuple(position), tuple(orientation), namespace.strip("/"),
                      robot=robot, tags=tags, body=robot.id, initial_joints=joints,
                      structure=urdf_structure(description))
        if robot.tyres:
            model.friction = TyreFriction(self.client, robot.id, robot.tyres, self.step_size,
                                          self._tyres, self.gravity)
        context = PluginContext(self.client, robot, name, model.namespace, self.bus,
                                np.random.default_rng([self.seed, len(self.models)]),
                                self.step_size, self.gravity, self.cast_rays, tf_prefix,
                                self.model_of_body, model.structure,
                                lambda body, name=name: self.applied_wrench(name, body),
                                namespace_given=bool(namespace))
        model.context = context
        try:
            model.plugins = create_plugins(context, tags)
        except Exception:
            if model.friction is not None:
                model.friction.remove()
            robot.remove()
            raise
        model.has_mesh = any(s.geometry.kind == "mesh" for link in description.links.values()
                             for s in link.collisions)
        model.ray_shapes = [
            RayShape(link.name, origin_transform(shape.origin), shape.geometry.kind,
                     shape.geometry.size, shape.geometry.radius, shape.geometry.length)
            for link in description.links.values() for shape in link.collisions
            if shape.geometry.kind != "mesh"]
        # collision meshes as pybullet loaded them: their hulls; a link whose mesh could not
        # be read (a box of its visual stands in) or has no hull here stays pybullet's
        held = {link.name for link in description.links.values()
                if sum(s.geometry.kind == "mesh" for s in link.collisions)
                > sum(m.link == link.name for m in robot.collision_meshes)}
        for mesh in robot.collision_meshes:
            hulls, unmatched = hull_ray_shapes(mesh.link, mesh.origin, mesh.path, mesh.scale)
            model.ray_shapes.extend(hulls)
            if unmatched:
                held.add(mesh.link)
        model.mesh_holders = [(robot.id, robot.link_index[link]) for link in sorted(held)
                              if link in robot.link_index]
        self.models[name] = model
        self._scene_changed()
        self._load_native_plugins(name, [spec.element for spec in tags.plugins], namespace)
        # and its sensors' plugins that are not emulated (Gazebo's sensor plugins)
        for sensor in tags.sensors:
            for spec in sensor.plugins:
                if spec.filename not in SENSOR_PLUGINS:
                    self.native.load_sensor_plugin(name, sensor.name, spec.element, namespace)
        return model

    def _lifted_out_of_scenery(self, robot: RobotBody, position: Sequence[float],
                               orientation: Sequence[float], name: str) -> Vec3:
        """The spawn position raised until no collision shape is sunk in static scenery below
        it. Many packages spawn at -z 0 with their wheels under the base link: Gazebo lifts
        such a robot gently (ODE's correcting velocity is capped); pybullet's correction of
        a deep penetration would throw it metres into the air. The robot is moved before its
        first step, and the raised pose is the one reset returns to."""
        scenery = [body for model in self.models.values() if model.kind == "static"
                   for body in model.static_bodies]
        lifted = np.asarray(position, dtype=float)
        for _ in range(MAX_LIFTS):
            sunk = 0.0
            for body in scenery:
                for point in pb.getClosestPoints(robot.id, body, 0.0,
                                                 physicsClientId=self.client):
                    depth, normal_z = -point[8], point[7][2]
                    if depth > PENETRATION_TOLERANCE and normal_z > MIN_FLOOR_NORMAL_Z:
                        sunk = max(sunk, depth / normal_z)
            if sunk == 0.0:
                break
            lifted[2] += sunk
            robot.set_base_state(lifted, orientation)
        if lifted[2] != position[2]:
            self.bus.info(f"model '{name}': spawned {lifted[2] - position[2]:.3f} m into the "
                          f"ground; set on it (z {lifted[2]:.3f})")
        return (float(lifted[0]), float(lifted[1]), float(lifted[2]))

    # --- requests ------------------------------------------------------------------------
    def model_of_body(self, body: int) -> Optional[str]:
        """The name of the model whose pybullet body ``body`` is, or None."""
        for name, model in self.models.items():
            if model.body == body or body in model.static_bodies:
                return name
        return None

    def model(self, name: str) -> Model:
        try:
            return self.models[name]
        except KeyError:
            known = ", ".join(sorted(self.models)) or "none"
            raise SimError(f"there is no model named '{name}' (models: {known})") from None

    def delete(self, name: str) -> None:
        model = self.model(name)
        self.native.remove_model(name)
        for plugin in model.plugins:
            plugin.close()
        del self.models[name]
        self.forces.forget_model(name)
        self._scene_changed()
        if model.kind == "static":
            self._remove_static_bodies(model)
        elif model.robot is not None:
            if model.friction is not None:
                model.friction.remove()
            model.robot.remove()
        elif model.body is not None:
            pb.removeBody(model.body, physicsClientId=self.client)

    def pose(self, name: str) -> Tuple[Vec3, Quat]:
        model = self.model(name)
        if model.kind == "static":
            return model.position, model.orientation
        if model.robot is not None:
            return model.robot.base_pose()
        com = pb.getBasePositionAndOrientation(model.body, physicsClientId=self.client)
        return _compose(com, _inverse(model.com_in_model))

    def twist(self, name: str) -> Tuple[np.ndarray, np.ndarray]:
        model = self.model(name)
        if model.kind == "static":
            return np.zeros(3), np.zeros(3)
        if model.robot is not None:
            return model.robot.base_twist()
        # the velocity of the model frame's origin (pybullet gives its centre of mass's)
        linear, angular = pb.getBaseVelocity(model.body, physicsClientId=self.client)
        com, _ = pb.getBasePositionAndOrientation(model.body, physicsClientId=self.client)
        return _moved(linear, angular, com, self.pose(name)[0]), np.asarray(angular)

    def set_state(self, name: str, position: Sequence[float], orientation: Sequence[float],
                  linear: Sequence[float] = (0, 0, 0), angular: Sequence[float] = (0, 0, 0)) -> None:
        model = self.model(name)
        orientation = _checked_state(position, orientation, linear, angular)
        self._poses_moved()
        if model.kind == "static":
            model.position, model.orientation = tuple(position), orientation
            roll_pitch_yaw = pb.getEulerFromQuaternion(list(orientation))
            model.spec.pose = (*position, *roll_pitch_yaw)
            self._remove_static_bodies(model)
            self._create_static_bodies(model)
            self._scene_changed()
        elif model.robot is not None:
            model.robot.set_base_state(position, orientation, linear, angular)
        else:
            com_position, com_orientation = _compose((position, orientation),
                                                     model.com_in_model)
            pb.resetBasePositionAndOrientation(model.body, list(com_position),
                                               list(com_orientation),
                                               physicsClientId=self.client)
            pb.resetBaseVelocity(model.body, _moved(linear, angular, position,
                                                    com_position).tolist(),
                                 list(angular), physicsClientId=self.client)

    def set_joint_positions(self, name: str, positions: Mapping[str, float]) -> None:
        """Puts a robot's joints at positions (they become its reset positions too); its
        plugins start over from there (position controllers hold the new pose)."""
        model = self.model(name)
        if model.robot is None:
            raise SimError(f"model '{name}' has no joints")
        unknown = [j for j in positions if j not in model.robot.joint_index]
        if unknown:
            raise SimError(f"model '{name}' has no joint(s) {', '.join(unknown)}")
        for joint, value in positions.items():
            if not math.isfinite(value):
                raise SimError(f"joint '{joint}': position {value} is not finite")
        model.robot.reset_joints(positions)
        self._poses_moved()
        model.initial_joints.update(positions)
        for plugin in model.plugins:
            plugin.reset(self.now_ns)

    # --- Gazebo's entities: models, links, joints ---------------------------------------
    def find_entity(self, name: str) -> Union[Model, LinkRef, None]:
        """What Gazebo's ``EntityByName`` finds: the models in order, each before its
        links; a link by ``model::link`` or by its plain name (the first model's)."""
        for model in self.models.values():
            if name == model.name:
                return model
            for body in model.structure.bodies:
                if name == body or name == f"{model.name}::{body}":
                    return LinkRef(model.name, body)
        return None

    def find_link(self, name: str) -> LinkRef:
        found = self.find_entity(name)
        if isinstance(found, LinkRef):
            return found
        raise SimError(self._not_a_link(name, found))

    @staticmethod
    def _scoped(model: Model, names: Sequence[str]) -> str:
        return ", ".join(f"{model.name}::{name}" for name in names) or "none"

    def _not_a_link(self, name: str, found: Optional[Model]) -> str:
        if found is not None:
            return (f"'{name}' is a model, not a link; its links: "
                    f"{self._scoped(found, found.structure.bodies)}")
        model_name, _, link = name.rpartition("::")
        if model_name and model_name not in self.models:
            return (f"there is no link named '{name}': there is no model named "
                    f"'{model_name}' (models: {', '.join(self.models) or 'none'})")
        for model in [self.models[model_name]] if model_name else self.models.values():
            joint = model.structure.lumped_by.get(link)
            if joint is not None:
                body = model.structure.body_of[link]
                return (f"model '{model.name}' has no link '{link}': Gazebo lumps it into "
                        f"'{body}' (fixed joint '{joint}'); ask for '{model.name}::{body}', "
                        f"or keep the link with <gazebo reference=\"{joint}\">"
                        "<preserveFixedJoint>true</preserveFixedJoint></gazebo>")
        if model_name:
            model = self.models[model_name]
            return (f"model '{model_name}' has no link '{link}' (its links: "
                    f"{self._scoped(model, model.structure.bodies)})")
        return (f"there is no link named '{name}' (name a link as model::link; models: "
                f"{', '.join(self.models) or 'none'})")

    def state_in_world(self, reference_frame: str, position: Sequence[float],
                       orientation: Sequence[float], linear: Sequence[float],
                       angular: Sequence[float]) -> Tuple[Vec3, Quat, np.ndarray, np.ndarray]:
        """A state requested in ``reference_frame`` (set_model_state's: pose in the frame,
        twist in its axes) in the world, once every number is checked as it was sent: a
        value that is not finite, or beyond MAX_COORDINATE, is refused naming it (turned
        by pybullet first, 1e300 became (inf, nan, nan)). Turned in double precision."""
        orientation = _checked_state(position, orientation, linear, angular)
        frame_position, frame_orientation = self.frame_state(reference_frame)[:2]
        frame = pose_matrix(frame_position, frame_orientation)
        placed = frame @ pose_matrix(position, orientation)
        rotation = frame[:3, :3]
        return (tuple(float(v) for v in placed[:3, 3]),
                quaternion_from_rpy(*matrix_rpy(placed[:3, :3])),
                rotation @ np.asarray(linear, float), rotation @ np.asarray(angular, float))

    def frame_state(self, name: str) -> Tuple[Vec3, Quat, np.ndarray, np.ndarray]:
        """Pose and twist (world axes; the velocity of the frame's origin) of a reference
        frame: the world ('', 'world', 'map'), a model or a link."""
        if name in WORLD_FRAMES:
            return (0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0), np.zeros(3), np.zeros(3)
        found = self.find_entity(name)
        if isinstance(found, Model):
            return (*self.pose(found.name), *self.twist(found.name))
        if isinstance(found, LinkRef):
            return (*self.link_pose(found), *self.link_twist(found))
        raise SimError(f"reference frame '{name}' is not the world ('' or 'world'), a model "
                       f"or a link: {self._not_a_link(name, None)}")

    def link_pose(self, ref: LinkRef) -> Transform:
        """World pose of a link's frame."""
        model = self.model(ref.model)
        if model.robot is not None:
            return model.robot.link_pose(ref.link)
        if model.kind == "static":
            link = next(l for l in model.spec.links if l.name == ref.link)
            return _compose((model.position, model.orientation),
                            pose6_to_position_quaternion(link.pose))
        return _compose(self.pose(model.name), model.link_in_model)

    def link_twist(self, ref: LinkRef) -> Tuple[np.ndarray, np.ndarray]:
        """Velocity of a link frame's origin and the link's angular velocity, world axes
        (pybullet gives its centre of mass's)."""
        model = self.model(ref.model)
        if model.kind == "static":
            return np.zeros(3), np.zeros(3)
        if model.robot is not None:
            index = model.robot.link_index[ref.link]
            if index == -1:
                return model.robot.base_twist()
            state = pb.getLinkState(model.robot.id, index, computeLinkVelocity=1,
                                    computeForwardKinematics=1, physicsClientId=self.client)
            return _moved(state[6], state[7], state[0], state[4]), np.asarray(state[7])
        linear, angular = pb.getBaseVelocity(model.body, physicsClientId=self.client)
        com, _ = pb.getBasePositionAndOrientation(model.body, physicsClientId=self.client)
        return _moved(linear, angular, com, self.link_pose(ref)[0]), np.asarray(angular)

    def link_states(self) -> List[Tuple[str, Vec3, Quat, np.ndarray, np.ndarray]]:
        """(``model::link``, position, orientation, linear, angular) of every link of every
        model, in the world: gazebo_msgs/LinkStates."""
        states = []
        for model in self.models.values():
            for body in model.structure.bodies:
                ref = LinkRef(model.name, body)
                position, orientation = self.link_pose(ref)
                linear, angular = self.link_twist(ref)
                states.append((ref.scoped, position, orientation, linear, angular))
        return states

    def set_link_state(self, ref: LinkRef, position: Sequence[float],
                       orientation: Sequence[float], linear: Sequence[float] = (0, 0, 0),
                       angular: Sequence[float] = (0, 0, 0)) -> None:
        """Puts a model's canonical link at a pose with a twist (of its frame's origin,
        world axes); the model moves with it, as in Gazebo. Other links are refused:
        pybullet keeps a robot's links on their joints (reduced coordinates), so one link
        cannot be placed apart from the rest."""
        model = self.model(ref.model)
        canonical = model.structure.canonical
        if ref.link != canonical:
            if model.robot is not None:
                joint = model.robot.model.parent_joint(ref.link)
                raise SimError(
                    f"link '{ref.scoped}' hangs on joint '{joint.name}': pybullet keeps a "
                    "robot's links on their joints, so set_link_state places only the "
                    f"canonical link '{model.name}::{canonical}', which carries the whole "
                    "model; turn joints with set_model_configuration")
            raise SimError(f"link '{ref.scoped}' is not the canonical link of model "
                           f"'{model.name}', '{model.name}::{canonical}', the only one "
                           "set_link_state places (the model moves with it)")
        orientation = _checked_state(position, orientation, linear, angular)
        link_in_model = _compose(_inverse(self.pose(model.name)), self.link_pose(ref))
        model_position, model_orientation = _compose((tuple(position), orientation),
                                                     _inverse(link_in_model))
        self.set_state(model.name, model_position, model_orientation,
                       _moved(linear, angular, position, model_position), angular)

    def model_properties(self, name: str) -> ModelProperties:
        """What gazebo_ros's get_model_properties says of a model (nested SDF models are
        merged into their parent here: no child models)."""
        model = self.model(name)
        structure = model.structure
        return ModelProperties("", structure.canonical, structure.bodies, structure.geoms,
                               structure.joints, (), model.kind == "static")

    def joint_properties(self, name: str) -> JointProperties:
        """gazebo_ros's get_joint_properties: the joint's type, damping, position and
        rate (one axis), from pybullet's joint."""
        model, joint = self.find_joint(name)
        described = model.robot.model.joints[joint]
        position, rate = model.robot.joint_position_velocity(joint)
        return JointProperties(described.type,
                               (model.joint_damping.get(joint, described.damping),),
                               (position,), (rate,))

    def set_joint_properties(self, name: str, damping: Sequence[float] = (),
                             lo_stop: Sequence[float] = (), hi_stop: Sequence[float] = (),
                             fmax: Sequence[float] = (), vel: Sequence[float] = ()) -> None:
        """gazebo_ros's set_joint_properties, the parts of ODE's joint settings pybullet
        has: damping (its joint damping), the stops (its joint limits) and the joint motor
        (fmax, vel: pybullet's velocity motor, which also carries the URDF friction, as
        ODE's motor does in Gazebo). Each list holds a value per axis; the joints here
        have one. An empty list changes nothing."""
        model, joint = self.find_joint(name)
        described = model.robot.model.joints[joint]
        if not described.movable:
            raise SimError(f"joint '{model.name}::{joint}' is {described.type}: it has no "
                           "axis to set")
        given = dict(damping=damping, lo_stop=lo_stop, hi_stop=hi_stop, fmax=fmax, vel=vel)
        for what, values in given.items():
            if len(values) > 1:
                raise SimError(f"{what} has {len(values)} values; joint '{model.name}::"
                               f"{joint}' has one axis")
            _finite(values, what)
        if damping and damping[0] < 0:
            raise SimError(f"damping {damping[0]} is negative")
        if fmax and fmax[0] < 0:
            raise SimError(f"fmax {fmax[0]} is negative")
        limit = described.limit
        lower, upper = model.joint_stops.get(
            joint, (limit.lower, limit.upper) if limit and described.type != "continuous"
            else (-math.inf, math.inf))
        lower = lo_stop[0] if lo_stop else lower
        upper = hi_stop[0] if hi_stop else upper
        if (lo_stop or hi_stop) and lower > upper:
            raise SimError(f"loStop {lower} is above hiStop {upper}")
        robot, index = model.robot, model.robot.joint_index[joint]
        if damping:
            model.joint_damping[joint] = float(damping[0])
            pb.changeDynamics(robot.id, index, jointDamping=float(damping[0]),
                              physicsClientId=self.client)
        if lo_stop or hi_stop:
            model.joint_stops[joint] = (float(lower), float(upper))
            # pybullet takes finite limits: an open side is as far as it carries
            pb.changeDynamics(robot.id, index,
                              jointLowerLimit=max(float(lower), -MAX_COORDINATE),
                              jointUpperLimit=min(float(upper), MAX_COORDINATE),
                              physicsClientId=self.client)
        if fmax or vel:
            force = float(fmax[0]) if fmax else described.friction
            pb.setJointMotorControl2(robot.id, index, pb.VELOCITY_CONTROL,
                                     targetVelocity=float(vel[0]) if vel else 0.0,
                                     force=force, physicsClientId=self.client)

    # --- link properties (gazebo_ros's get_ and set_link_properties) ----------------------
    def _mass_parts(self, model: Model, body: str) -> List[_MassPart]:
        """The parts of one of Gazebo's links as pybullet has them now (a robot's: the link
        and those lumped into it, the link first), placed in the link's frame."""
        if model.robot is not None:
            robot, parts = model.robot, []
            for link in model.structure.links_of(body):
                index = robot.link_index[link]
                info = pb.getDynamicsInfo(robot.id, index, physicsClientId=self.client)
                # fixed joints only: where the part is in the link does not change
                placed = link_transform(robot.model, body, link)
                parts.append(_MassPart(
                    index, info[0], np.asarray(info[2], dtype=float),
                    placed[:3, :3] @ quaternion_matrix(info[4]),
                    placed[:3, :3] @ np.asarray(info[3], dtype=float) + placed[:3, 3]))
            return parts
        if model.kind == "static":  # no pybullet dynamics: the SDF's inertial
            link = next(l for l in model.spec.links if l.name == body)
            frame = pose6_matrix(link.inertial_pose)
            return [_MassPart(None, link.mass, np.asarray(link.inertia, dtype=float),
                              frame[:3, :3], frame[:3, 3])]
        info = pb.getDynamicsInfo(model.body, -1, physicsClientId=self.client)
        return [_MassPart(-1, info[0], np.asarray(info[2], dtype=float),
                          quaternion_matrix(info[4]), np.asarray(info[3], dtype=float))]

    @staticmethod
    def _inertial_axes(model: Model, body: str) -> np.ndarray:
        """The axes Gazebo's ``Inertial`` of the link holds its moments in: the link's own
        inertial frame's (a URDF link's ``<inertial><origin rpy>``, kept when sdformat lumps
        children into it, sdf9 66a8c21 src/parser_urdf.cc:887-892; none: the link's axes)."""
        if model.robot is not None:
            inertial = model.robot.model.links[body].inertial
            return rpy_matrix(*inertial.origin.rpy) if inertial is not None else np.eye(3)
        link = next(l for l in model.spec.links if l.name == body)
        return pose6_matrix(link.inertial_pose)[:3, :3]

    def _gravity_mode(self, model: Model, body: str) -> bool:
        """Whether gravity pulls the link: not when a part of it is weightless (sdformat
        writes a lumped child's <gravity> into the link it joins, parser_urdf.cc:2071-2079)."""
        if model.robot is not None:
            weightless = {index for index, _ in model.robot.weightless_links}
            return not any(model.robot.link_index[link] in weightless
                           for link in model.structure.links_of(body))
        return not model.weightless

    def link_properties(self, name: str) -> LinkProperties:
        """gazebo_ros's get_link_properties: the link's mass, its centre of mass in its
        frame and its inertia about that centre, its lumped parts together (their masses
        and tensors as pybullet has them, combined by the parallel-axis theorem), in the
        axes of the link's inertial frame (see _inertial_axes), and its gravity mode."""
        ref = self.find_link(name)
        model = self.model(ref.model)
        mass, centre, tensor = _combined(self._mass_parts(model, ref.link))
        axes = self._inertial_axes(model, ref.link)
        held = axes.T @ tensor @ axes
        return LinkProperties(
            tuple(float(v) for v in centre), self._gravity_mode(model, ref.link), float(mass),
            (float(held[0, 0]), float(held[0, 1]), float(held[0, 2]), float(held[1, 1]),
             float(held[1, 2]), float(held[2, 2])))

    def set_link_properties(self, name: str, com: Sequence[float], gravity_mode: bool,
                            mass: float, inertia: Sequence[float]) -> None:
        """gazebo_ros's set_link_properties, what pybullet can do from the next step on: the
        mass (every part of the link scaled alike, so its centre of mass stays), the
        moments of inertia about the centre of mass (``inertia``: ixx, ixy, ixz, iyy, iyz,
        izz in the axes get_link_properties gives them in; the change goes to the link's
        own part, along its principal axes) and gravity (pybullet has no switch per link:
        a weightless link is held up by a force of m g at its centre of mass each step).
        Refused, with the reason: a centre of mass other than the link's own (pybullet
        fixes a link's inertial frame when it builds the body), products of inertia that
        would turn the principal axes, a moment that is not positive, a mass that is not
        positive, a number that is not finite, a static model's link."""
        ref = self.find_link(name)
        model = self.model(ref.model)
        if model.kind == "static":
            raise SimError(f"link '{ref.scoped}' belongs to static model '{model.name}': "
                           "it does not move, so its mass and inertia change nothing")
        _finite(com, "the centre of mass")
        _finite((mass,), "the mass")
        _finite(inertia, "the inertia (ixx, ixy, ixz, iyy, iyz, izz)")
        if mass <= 0:
            raise SimError(f"the mass {mass:g} kg must be positive")
        parts = self._mass_parts(model, ref.link)
        total, centre, tensor = _combined(parts)
        if np.linalg.norm(np.asarray(com, dtype=float) - centre) > COM_TOLERANCE:
            raise SimError(
                f"the centre of mass ({', '.join(f'{v:g}' for v in com)}) is not link "
                f"'{ref.scoped}''s own ({', '.join(f'{v:g}' for v in centre)}, in its "
                "frame): pybullet fixes a link's inertial frame when it builds the body and "
                "cannot move it; send the link's own (get_link_properties gives it)")
        scale = float(mass) / total
        ixx, ixy, ixz, iyy, iyz, izz = (float(v) for v in inertia)
        axes = self._inertial_axes(model, ref.link)
        wanted = axes @ np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]]) @ axes.T
        # the link's own part takes the change, in its principal axes
        own = parts[0]
        change = own.axes.T @ (wanted - scale * tensor) @ own.axes
        moments = own.moments * scale + np.diag(change)
        products = change - np.diag(np.diag(change))
        if np.abs(products).max() > INERTIA_TOLERANCE * max(np.abs(moments).max(),
                                                            np.abs(wanted).max()):
            held = axes.T @ (scale * tensor) @ axes
            raise SimError(
                f"the products of inertia (ixy {ixy:g}, ixz {ixz:g}, iyz {iyz:g}) would turn "
                f"link '{ref.scoped}''s principal axes, which pybullet fixes when it builds "
                "the body (it takes the moments along them only); at this mass they are "
                f"ixy {held[0, 1]:g}, ixz {held[0, 2]:g}, iyz {held[1, 2]:g}")
        if np.any(moments <= 0):
            raise SimError(f"the inertia asked for leaves link '{ref.scoped}''s own part "
                           f"with principal moments {', '.join(f'{v:g}' for v in moments)} "
                           "kg m^2: each must be positive")
        body = model.body
        for number, part in enumerate(parts):
            # mass and moments in one call: pybullet recomputes a link's inertia from its
            # collision shapes when its mass alone is changed
            pb.changeDynamics(body, part.index, mass=part.mass * scale,
                              localInertiaDiagonal=list(moments if number == 0
                                                        else part.moments * scale),
                              physicsClientId=self.client)
        if model.robot is not None:
            model.robot.set_gravity([part.index for part in parts], gravity_mode)
            if model.friction is not None:  # the tyres' slip stiffness follows the mass
                model.friction.mass += (scale - 1.0) * total
                model.friction.set_physics(self.step_size, self.gravity)
        else:
            model.weightless = not gravity_mode
        self._refresh_weightless()

    # --- lights (gazebo_ros's light services) -----------------------------------------------
    def light(self, name: str) -> LightSpec:
        """A light of the world by its name (the first of that name, as Gazebo's
        ``LightByName``)."""
        for light in self.lights:
            if light.name == name:
                return light
        known = ", ".join(light.name for light in self.lights) or "none"
        raise SimError(f"there is no light named '{name}' (lights: {known})")

    def set_light(self, name: str, cast_shadows: bool, diffuse: Sequence[float],
                  specular: Sequence[float], attenuation_constant: float,
                  attenuation_linear: float, attenuation_quadratic: float,
                  direction: Sequence[float], position: Sequence[float],
                  orientation: Sequence[float]) -> None:
        """gazebo_ros's set_light_properties: every one of these is the request's, as
        Noetic writes them all into the light (gazebo_ros_api_plugin.cpp:1366-1392); an
        orientation (0, 0, 0, 0) is the identity (as set_model_state's)."""
        light = self.light(name)
        for what, values in (("diffuse", diffuse), ("specular", specular),
                             ("the attenuation", (attenuation_constant, attenuation_linear,
                                                  attenuation_quadratic)),
                             ("the direction", direction)):
            _finite(values, what)
        _finite(position, "the position")
        if not any(orientation):
            orientation = (0.0, 0.0, 0.0, 1.0)
        try:
            turned = quaternion_matrix(normalized(orientation))
        except ValueError as error:
            raise SimError(f"the orientation: {error}") from None
        light.cast_shadows = bool(cast_shadows)
        light.diffuse = tuple(float(v) for v in diffuse)  # type: ignore[assignment]
        light.specular = tuple(float(v) for v in specular)  # type: ignore[assignment]
        light.attenuation_constant = float(attenuation_constant)
        light.attenuation_linear = float(attenuation_linear)
        light.attenuation_quadratic = float(attenuation_quadratic)
        light.direction = tuple(float(v) for v in direction)  # type: ignore[assignment]
        light.pose = (*(float(v) for v in position), *matrix_rpy(turned))  # type: ignore

    def add_light(self, light: LightSpec) -> None:
        """A light spawned (spawn_sdf_model): refused when a light or a model has its name,
        as gazebo_ros refuses it (gazebo_ros_api_plugin.cpp:2683-2694)."""
        if light.name in self.models or any(l.name == light.name for l in self.lights):
            raise SimError(f"a light or model named '{light.name}' exists already; delete "
                           "it or pick another name")
        self.lights.append(light)

    def delete_light(self, name: str) -> None:
        self.lights.remove(self.light(name))

    def sensors(self) -> List[SensorRate]:
        """Every robot's sensors with the rate they update at in simulated time: their
        ``<update_rate>`` (Hz), or every step when it is 0, absent or unreadable (Gazebo's
        sensors update at every world update then)."""
        found = []
        for model in self.models.values():
            if model.tags is None:
                continue
            for sensor in model.tags.sensors:
                try:
                    rate = float((sensor.element.findtext("update_rate") or "0").strip())
                except ValueError:
                    rate = 0.0
                if not math.isfinite(rate) or rate <= 0:
                    rate = 1.0 / self.step_size
                link = model.structure.body_of.get(sensor.link, sensor.link)
                found.append(SensorRate(f"{model.name}::{link}::{sensor.name}", sensor.type,
                                        rate))
        return found

    def find_joint(self, name: str) -> Tuple[Model, str]:
        """A joint by ``model::joint`` or its plain name (the first model's), among the
        joints Gazebo shows."""
        for model in self.models.values():
            for joint in model.structure.joints:
                if name == joint or name == f"{model.name}::{joint}":
                    return model, joint
        model_name, _, joint = name.rpartition("::")
        for model in self.models.values():
            if model.robot is None or (model_name and model.name != model_name):
                continue
            described = model.robot.model.joints.get(joint)
            if described is not None:  # in the URDF, not in Gazebo: lumped
                body = model.structure.body_of.get(described.child, described.child)
                raise SimError(
                    f"joint '{name}' of model '{model.name}' is a fixed joint Gazebo lumps "
                    f"away (link '{described.child}' becomes part of '{body}'); keep it with "
                    f"<gazebo reference=\"{joint}\"><preserveFixedJoint>true"
                    "</preserveFixedJoint></gazebo>")
        joints = ", ".join(f"{m.name}::{j}" for m in self.models.values()
                           for j in m.structure.joints) or "none"
        raise SimError(f"there is no joint named '{name}' (joints: {joints})")

    # --- forces from outside (see sim_bridge.external_forces) ----------------------------
    def _link_masses(self, model: Model, body: str) -> LinkMasses:
        """The pybullet links making up one of Gazebo's links, the link itself first."""
        if model.robot is None:
            return [(-1, pb.getDynamicsInfo(model.body, -1, physicsClientId=self.client)[0])]
        return [(model.robot.link_index[link],
                 pb.getDynamicsInfo(model.robot.id, model.robot.link_index[link],
                                    physicsClientId=self.client)[0])
                for link in model.structure.links_of(body)]

    def apply_wrench(self, body_name: str, force: Sequence[float], torque: Sequence[float],
                     reference_frame: str = "", reference_point: Sequence[float] = (0, 0, 0),
                     start_ns: int = 0, duration_ns: int = -1) -> LinkRef:
        """gazebo_ros's apply_body_wrench. ``force`` and ``torque`` are in the axes of
        ``reference_frame`` (the world for '', 'world', 'map'; else a model's or a link's
        frame). The force acts at ``reference_point``: a point in the reference frame, or,
        in the world frame, an offset from the body's centre of mass (gazebo_ros reads it
        so: 0 pushes through the centre of mass). The wrench is turned into world axes now
        and stays so, as Gazebo's; it acts from ``start_ns`` (now, if past) for
        ``duration_ns`` of simulated time, or until cleared when that is negative."""
        ref = self.find_link(body_name)
        model = self.model(ref.model)
        _finite(force, "the force")
        _finite(torque, "the torque")
        _finite(reference_point, "the reference point")
        if model.kind == "static":
            raise SimError(f"link '{ref.scoped}' belongs to static model '{model.name}': "
                           "forces move nothing")
        links = self._link_masses(model, ref.link)
        com = centre_of_mass(self.client, model.body, links)
        world_force = np.asarray(force, dtype=float)
        world_torque = np.asarray(torque, dtype=float)
        point = np.asarray(reference_point, dtype=float)
        if reference_frame in WORLD_FRAMES:
            lever = point
        else:
            frame_position, frame_orientation, _, _ = self.frame_state(reference_frame)
            rotation = quaternion_matrix(frame_orientation)
            world_force, world_torque = rotation @ world_force, rotation @ world_torque
            lever = np.asarray(frame_position) + rotation @ point - com
        self.forces.wrenches.append(BodyWrench(
            model.name, ref.link, model.body, links, world_force,
            world_torque + np.cross(lever, world_force),
            Window.starting(self.now_ns, start_ns, duration_ns)))
        return ref

    def applied_wrench(self, model_name: str, body: str) -> Tuple[np.ndarray, np.ndarray]:
        """(force, torque) that the wrenches on a model's link apply on the step starting
        now: world axes, the torque about the link's centre of mass."""
        force, torque = np.zeros(3), np.zeros(3)
        for wrench in self.forces.wrenches:
            if (wrench.model, wrench.body) == (model_name, body) and \
                    wrench.window.holds(self.now_ns):
                force += wrench.force
                torque += wrench.torque
        return force, torque

    def clear_wrenches(self, body_name: str) -> int:
        """Ends the wrenches on a link; how many there were."""
        ref = self.find_link(body_name)
        return self.forces.clear_wrenches(lambda w: (w.model, w.body) == (ref.model, ref.link))

    def apply_joint_effort(self, joint_name: str, effort: float, start_ns: int = 0,
                           duration_ns: int = -1) -> Tuple[str, str]:
        """gazebo_ros's apply_joint_effort: a torque (N m; a force in N for a prismatic
        joint) added to whatever drives the joint, from ``start_ns`` (now, if past) for
        ``duration_ns``, or until cleared when that is negative. (model, joint)."""
        model, joint = self.find_joint(joint_name)
        if not math.isfinite(effort):
            raise SimError(f"the effort {effort} is not finite")
        described = model.robot.model.joints[joint]
        if not described.movable:
            raise SimError(f"joint '{model.name}::{joint}' is {described.type}: an effort "
                           "moves nothing")
        self.forces.efforts.append(JointEffort(
            model.name, joint, model.robot.id, model.robot.joint_index[joint], float(effort),
            Window.starting(self.now_ns, start_ns, duration_ns)))
        return model.name, joint

    def clear_joint_efforts(self, joint_name: str) -> int:
        """Ends the efforts on a joint; how many there were."""
        model, joint = self.find_joint(joint_name)
        return self.forces.clear_efforts(lambda e: (e.model, e.joint) == (model.name, joint))

    def reset(self) -> None:
        """Every model back where it was spawned, at rest; time goes on (never backwards)."""
        self._poses_moved()
        for model in self.models.values():
            if model.kind == "static":
                continue
            self.set_state(model.name, model.initial_position, model.initial_orientation)
            if model.robot is not None:
                model.robot.reset_joints({j: model.initial_joints.get(j, 0.0)
                                          for j in model.robot.movable_joints()})
            for plugin in model.plugins:
                plugin.reset(self.now_ns)
        self.native.reset()

    # --- stepping -------------------------------------------------------------------------
    def step(self) -> bool:
        """One physics step with the plugins around it; False (and nothing happens) while
        paused."""
        if self.paused:
            return False
        self._refresh_step_lists()
        # Gazebo's order: WorldUpdateBegin with the time of the step to come, the physics,
        # WorldUpdateEnd (sim_bridge.native_plugins); the host is called only when it
        # holds plugins (this runs every step)
        native = self.native if self.native.count else None
        if native is not None:
            native.begin(self.now_ns + self._step_ns)
        for plugin in self._plugins:
            plugin.before_step(self.now_ns)
        self._apply_native_efforts()
        self.step_physics()
        for plugin in self._plugins:
            plugin.after_step(self.now_ns)
        if native is not None:
            native.end()
        return True

    def advance(self, max_steps: int) -> int:
        """Up to ``max_steps`` steps (at least one), as :meth:`step` makes them; returns how
        many were made (0 while paused). The steps that end before any plugin's
        :meth:`~sim_bridge.plugins.base.Plugin.quiet_until_ns` are made by the physics
        alone: the plugins would have returned at once there, so pybullet sees the same
        calls in the same order and the world ends in the same state, bit for bit
        (test_world_advance.py). What a plugin does at its update rate then costs nothing
        on the steps between (a drive plugin at 50 Hz and a laser at 20 Hz leave 19 steps
        in 20 to the physics). Gazebo's C++ plugins are called at every step."""
        if self.paused:
            return 0
        self._refresh_step_lists()
        if self.native.count or self._native_efforts:
            self.step()
            return 1
        now_ns, step_ns = self.now_ns, self._step_ns
        quiet_ns = NEVER
        for plugin in self._plugins:
            until = plugin.quiet_until_ns(now_ns, step_ns)
            if until < quiet_ns:
                quiet_ns = until
        made = 0
        step_physics = self.step_physics
        while made < max_steps and self.now_ns + step_ns < quiet_ns:
            step_physics()
            made += 1
        if made < max_steps or made == 0:
            self.step()
            made += 1
        return made

    # --- what Gazebo's C++ plugins set (sim_bridge.native_plugins) --------------------------
    def set_twist(self, name: str, linear: Sequence[float], angular: Sequence[float]) -> None:
        """A free model's velocity (of its frame's origin, world axes), its pose kept; a NaN
        component keeps the one the model has (Model::SetLinearVel keeps the angular)."""
        model = self.model(name)
        body = model.robot.id if model.robot is not None else model.body
        if body is None:
            return
        com = pb.getBasePositionAndOrientation(body, physicsClientId=self.client)[0]
        origin = self.pose(name)[0]
        if any(map(math.isnan, (*linear, *angular))):
            had_linear, had_angular = pb.getBaseVelocity(body, physicsClientId=self.client)
            angular = [o if math.isnan(n) else n for n, o in zip(angular, had_angular)]
            had_linear = _moved_floats(had_linear, had_angular, com, origin)
            linear = [o if math.isnan(n) else n for n, o in zip(linear, had_linear)]
        com_linear = _moved_floats(linear, angular, origin, com)
        pb.resetBaseVelocity(body, com_linear, list(angular),
                             physicsClientId=self.client)

    def add_link_wrench(self, model_name: str, link: str, force: Sequence[float],
                        torque: Sequence[float], in_link_frame: bool) -> None:
        """A force at a link's centre of mass and a torque, for the next step only (pybullet
        clears them after each, as ODE does); in the link's axes when ``in_link_frame``."""
        model = self.model(model_name)
        if model.robot is not None:
            body, index = model.robot.id, model.robot.link_index[link]
        elif model.body is not None:
            body, index = model.body, -1
        else:
            return
        if index == -1:
            com, rotation = pb.getBasePositionAndOrientation(body, physicsClientId=self.client)
        else:
            state = pb.getLinkState(body, index, computeForwardKinematics=1,
                                    physicsClientId=self.client)
            com, rotation = state[0], state[1]
        force, torque = np.asarray(force, float), np.asarray(torque, float)
        if in_link_frame:
            turn = np.asarray(pb.getMatrixFromQuaternion(rotation)).reshape(3, 3)
            force, torque = turn @ force, turn @ torque
        if force.any():
            pb.applyExternalForce(body, index, force.tolist(), list(com), pb.WORLD_FRAME,
                                  physicsClientId=self.client)
        if torque.any():
            pb.applyExternalTorque(body, index, torque.tolist(), pb.WORLD_FRAME,
                                   physicsClientId=self.client)

    def set_model_gravity(self, name: str, on: bool) -> None:
        """Gravity on or off for all of a model's links."""
        model = self.model(name)
        if model.robot is not None:
            model.robot.set_gravity(list(model.robot.link_index.values()), on)
        elif model.kind == "body":
            model.weightless = not on
        self._refresh_weightless()

    def set_step_joint_force(self, model_name: str, joint: str, force: float) -> None:
        """A joint's effort for the next step (N or N m)."""
        robot = self.model(model_name).robot
        self._native_efforts[(robot.id, robot.joint_index[joint])] = float(force)

    def _apply_native_efforts(self) -> None:
        if not self._native_efforts:
            return
        for (body, index), force in self._native_efforts.items():
            pb.setJointMotorControl2(body, index, pb.TORQUE_CONTROL, force=force,
                                     physicsClientId=self.client)
        self._native_efforts = {}

    def step_physics(self) -> None:
        """The physics of one step alone (forces, tyres, pybullet's step), no plugins: what
        the benchmark compares the whole simulator with."""
        self._refresh_step_lists()
        for robot in self._weightless:
            robot.apply_weightlessness(self.gravity)
        for body, mass in self._weightless_bodies:
            # pybullet's base is its centre of mass: gravity cancelled there
            com = pb.getBasePositionAndOrientation(body, physicsClientId=self.client)[0]
            pb.applyExternalForce(body, -1, [-mass * g for g in self.gravity], com,
                                  pb.WORLD_FRAME, physicsClientId=self.client)
        if self.forces:
            self.forces.apply(self.now_ns)
        for friction in self._frictions:
            friction.apply()
        pb.stepSimulation(physicsClientId=self.client)
        self.now_ns += self._step_ns

    def _refresh_step_lists(self) -> None:
        if self._plugins is None:  # the models changed since the last step
            self._plugins = [p for m in self.models.values() for p in m.plugins]
            self._refresh_weightless()
            self._frictions = [m.friction for m in self.models.values() if m.friction]
            for friction in self._frictions:
                friction.forget()

    def _refresh_weightless(self) -> None:
        """The bodies whose gravity is cancelled each step, as their links say now."""
        self._weightless = [m.robot for m in self.models.values()
                            if m.robot is not None and m.robot.weightless_links]
        self._weightless_bodies = [
            (m.body, pb.getDynamicsInfo(m.body, -1, physicsClientId=self.client)[0])
            for m in self.models.values() if m.kind == "body" and m.weightless]

    # --- ray casting (lasers) -------------------------------------------------------------
    def cast_rays(self, origin: Sequence[float], directions: np.ndarray, near: float,
                  far: float, reference: bool = False) -> np.ndarray:
        """Distances from ``origin`` along unit ``directions`` to the first surface between
        ``near`` and ``far`` (inf where there is none). Analytic against the scene's
        primitive shapes and moving meshes' convex hulls (:mod:`sim_bridge.ray_scene`: the
        compiled kernel, moving shapes placed once per time stamp); through pybullet for the
        rays that pass by a static mesh (see :attr:`Model.mesh_holders`).
        ``reference``: the numpy reference, every shape placed anew (what tests check the
        fast path against); pybullet alone when a mesh is pybullet's."""
        origin = np.asarray(origin, dtype=float)
        directions = np.asarray(directions, dtype=float)
        if self._has_meshes is None:
            self._has_meshes = any(m.mesh_holders for m in self.models.values())
        if self._has_meshes and reference:
            return self._cast_through_pybullet(origin, directions, near, far)
        if reference:
            return self._cast_reference(origin, directions, near, far)
        if self._ray_scene is None:
            kernel, where = ray_kernel.load()
            if kernel is None and not self._kernel_warned:
                self._kernel_warned = True  # once, not at every change of the scene
                self.bus.warn(f"lasers are cast by numpy, slower: {where}")
            self._ray_scene = RayScene(self, kernel)
        distances = self._ray_scene.cast(self.now_ns, origin, directions, near, far)
        if self._has_meshes:
            # the rays that pass through a static mesh's bounding box: pybullet's answer for
            # them (it knows every shape); the kernel's elsewhere, where no such mesh can be
            # hit (tools/bench and README, "Lasers")
            through = self._rays_through_mesh_bounds(origin, directions, near, far)
            if through.any():
                distances = distances.copy()
                distances[through] = self._cast_through_pybullet(origin, directions[through],
                                                                 near, far)
        return distances

    def _cast_through_pybullet(self, origin: np.ndarray, directions: np.ndarray, near: float,
                               far: float) -> np.ndarray:
        starts = origin + directions * near
        ends = origin + directions * far
        results = pb.rayTestBatch(starts.tolist(), ends.tolist(),
                                  numThreads=self.ray_threads, physicsClientId=self.client)
        fractions = np.array([r[2] if r[0] >= 0 else np.inf for r in results])
        return near + fractions * (far - near)

    def _rays_through_mesh_bounds(self, origin: np.ndarray, directions: np.ndarray,
                                  near: float, far: float) -> np.ndarray:
        """Which rays pass through the axis-aligned bounding box of a collision mesh
        between ``near`` and ``far`` (the slab test; pybullet's boxes, margins included)."""
        boxes = np.array([pb.getAABB(body, link, physicsClientId=self.client)
                          for model in self.models.values() for body, link in model.mesh_holders])
        if len(boxes) == 0:
            return np.zeros(len(directions), dtype=bool)
        lower, upper = boxes[:, 0, :][None], boxes[:, 1, :][None]  # (1, boxes, 3)
        with np.errstate(divide="ignore", invalid="ignore"):
            inverse = 1.0 / directions[:, None, :]  # (rays, 1, 3)
            t_lower = (lower - origin) * inverse
            t_upper = (upper - origin) * inverse
        # a ray parallel to a slab: inside it for all t (nan from 0 * inf) or never
        parallel = directions[:, None, :] == 0.0
        inside = (origin >= lower) & (origin <= upper)
        t_near = np.where(parallel, np.where(inside, -np.inf, np.inf),
                          np.minimum(t_lower, t_upper))
        t_far = np.where(parallel, np.where(inside, np.inf, -np.inf),
                         np.maximum(t_lower, t_upper))
        entry, leave = t_near.max(axis=2), t_far.min(axis=2)  # (rays, boxes)
        return ((entry <= leave) & (leave >= near) & (entry <= far)).any(axis=1)

    # set when the missing ray kernel has been warned about (per world)
    _kernel_warned = False

    def _poses_moved(self) -> None:
        """Models were placed without time passing: lasers place their shapes again."""
        if self._ray_scene is not None:
            self._ray_scene.poses_changed()

    def _cast_reference(self, origin: np.ndarray, directions: np.ndarray, near: float,
                        far: float) -> np.ndarray:
        """The numpy reference (ray_caster), every moving shape placed for this call."""
        if self._static_shapes is None:
            self._static_shapes = ShapeSet([p for m in self.models.values()
                                            if m.kind == "static" for p in m.primitives])
        starts = origin + directions * near
        distances = near + cast([self._static_shapes, ShapeSet(self._moving_primitives())],
                                starts, directions)
        return np.where(distances <= far, distances, np.inf)

    def _moving_primitives(self) -> List[Primitive]:
        """Every moving shape placed where its body is now (the reference's way)."""
        primitives: List[Primitive] = []
        for model in self.models.values():
            if model.robot is not None:
                frames = {name: pose_matrix(*model.robot.link_pose(name))
                          for name in {shape.link for shape in model.ray_shapes}}
                primitives.extend(shape.placed(frames[shape.link]) for shape in model.ray_shapes)
            elif model.body is not None:  # ray shapes are placed in the model's frame
                frame = pose_matrix(*self.pose(model.name))
                primitives.extend(shape.placed(frame) for shape in model.ray_shapes)
        return primitives

    def close(self) -> None:
        self.native.close()  # C++ plugins first: they may still read the world
        for name in list(self.models):
            for plugin in self.models[name].plugins:
                plugin.close()
        pb.disconnect(physicsClientId=self.client)


__all__ = ["World", "Model", "LinkRef", "ModelProperties", "PhysicsProperties", "SimError",
           "UrdfError", "WORLD_FRAMES"]
