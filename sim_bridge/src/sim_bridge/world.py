"""The simulated world: pybullet underneath, Gazebo's notions on top. No rospy here.

It holds the models (static scenery, free bodies from SDF, robots from URDF with their
plugins), steps the physics with a fixed step, keeps simulated time as an integer number
of nanoseconds (monotonic, also across resets), and answers Gazebo's questions: spawn,
delete, get and set a model's state, pause, reset.

Static scenery is one fixed rigid body per shape (``useMaximalCoordinates``): a fixed
multi-link body would have all its links re-posed every step (four times the step cost
in a 40-object hall). Lasers do not ask pybullet: see :mod:`sim_bridge.ray_caster`.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Dict, List, Mapping, Optional, Sequence, Tuple

import numpy as np
import pybullet as pb

from sim_bridge.gazebo_tags import GazeboTags, read_gazebo_tags
from sim_bridge.plugins import create_plugins
from sim_bridge.plugins.base import Bus, Plugin, PluginContext
from sim_bridge.poses import (compose6, normalized, pose6_matrix, pose6_to_position_quaternion,
                              quaternion_from_rpy, quaternion_matrix)
from sim_bridge.ray_caster import Primitive, ShapeSet, cast, primitive_for
from sim_bridge.robot_body import RobotBody
from sim_bridge.sdf_world import ModelSpec, ShapeSpec, WorldSpec
from urdf_tools.kinematics import matrix_rpy, origin_transform
from urdf_tools.model import UrdfError, parse_urdf

# pybullet multiplies the friction of the two surfaces in contact: world surfaces are 1.0
# so that a contact gets the robot link's own mu (Gazebo takes the smaller of the two).
WORLD_FRICTION = 1.0

Vec3 = Tuple[float, float, float]
Quat = Tuple[float, float, float, float]


@dataclass(frozen=True)
class RayShape:
    """A moving model's collision shape as lasers see it: ``local`` places it in its link's
    frame (``link`` None: the free body's frame)."""

    link: Optional[str]
    local: np.ndarray
    kind: str
    size: Optional[Sequence[float]] = None
    radius: Optional[float] = None
    length: Optional[float] = None

    def placed(self, frame: np.ndarray) -> Primitive:
        return primitive_for(self.kind, frame @ self.local, size=self.size, radius=self.radius,
                             length=self.length)


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
    initial_joints: Dict[str, float] = field(default_factory=dict)
    # for static models: where they are (they never move), their bodies and shapes
    position: Vec3 = (0.0, 0.0, 0.0)
    orientation: Quat = (0.0, 0.0, 0.0, 1.0)
    static_bodies: List[int] = field(default_factory=list)
    primitives: List[Primitive] = field(default_factory=list)  # static: placed in the world
    # moving models: their shapes for lasers, placed each scan from the bodies' poses
    ray_shapes: List[RayShape] = field(default_factory=list)
    has_mesh: bool = False


def _finite(values: Sequence[float], what: str) -> None:
    if not all(math.isfinite(v) for v in values):
        raise SimError(f"{what} {tuple(values)} is not finite")


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
        self._weightless: List[RobotBody] = []
        self.now_ns = 0
        self.paused = False
        self.step_size = step_size
        self.gravity = tuple(gravity)
        self._configure_physics()

    # --- physics settings --------------------------------------------------------------
    def _configure_physics(self) -> None:
        pb.setGravity(*self.gravity, physicsClientId=self.client)
        pb.setTimeStep(self.step_size, physicsClientId=self.client)
        self._step_ns = int(round(self.step_size * 1e9))
        # Friction as a pyramid, as Gazebo's ODE. A robot's (multibody's) contacts get a
        # pyramid on the world's axes whatever this says (README, "pybullet facts").
        pb.setPhysicsEngineParameter(deterministicOverlappingPairs=1, enableConeFriction=0,
                                     physicsClientId=self.client)

    @property
    def step_ns(self) -> int:
        return self._step_ns

    @property
    def now(self) -> float:
        return self.now_ns / 1e9

    def load_world(self, spec: WorldSpec) -> None:
        self.step_size = spec.step_size
        self.gravity = spec.gravity
        self._configure_physics()
        for model in spec.models:
            self.add_sdf_model(model)

    # --- models from SDF ------------------------------------------------------------------
    def add_sdf_model(self, spec: ModelSpec, position: Optional[Sequence[float]] = None,
                      orientation: Optional[Sequence[float]] = None, namespace: str = "") -> Model:
        if spec.name in self.models:
            raise SimError(f"a model named '{spec.name}' exists already; delete it or pick "
                           "another name")
        if position is not None:
            roll_pitch_yaw = pb.getEulerFromQuaternion(list(orientation or (0, 0, 0, 1)))
            spec.pose = (*position, *roll_pitch_yaw)
        pos, orn = pose6_to_position_quaternion(spec.pose)
        model = Model(spec.name, "static" if spec.static else "body", pos, orn, namespace, spec,
                      position=pos, orientation=orn)
        model.has_mesh = any(s.kind == "mesh" for link in spec.links for s in link.collisions)
        if spec.static:
            self._create_static_bodies(model)
        else:
            model.body = self._free_body(spec)
            model.ray_shapes = [
                RayShape(None, pose6_matrix(link.pose) @ pose6_matrix(shape.pose), shape.kind,
                         shape.size, shape.radius, shape.length)
                for link in spec.links for shape in link.collisions if shape.kind != "mesh"]
        self.models[spec.name] = model
        self._scene_changed()
        return model

    def _scene_changed(self) -> None:
        """Models came, went or moved: what is derived from them is rebuilt when next used."""
        self._plugins = None
        self._static_shapes = None
        self._has_meshes = None

    def _shape_arguments(self, shape: ShapeSpec, collision: bool) -> dict:
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
        elif shape.kind == "plane":
            if collision:
                arguments = dict(shapeType=pb.GEOM_PLANE, planeNormal=list(shape.normal))
            else:  # a thin box shows a plane of the size the SDF gives
                arguments = dict(shapeType=pb.GEOM_BOX,
                                 halfExtents=[shape.size[0] / 2, shape.size[1] / 2, 0.0005])
        if not collision:
            arguments["rgbaColor"] = list(shape.rgba or (0.7, 0.7, 0.7, 1.0))
        return arguments

    def _make_shape(self, shape: ShapeSpec, collision: bool, relative_to=None) -> int:
        """A pybullet shape; ``relative_to`` = (link pose, body pose) places a visual on a
        body that is not at the visual's own pose."""
        arguments = self._shape_arguments(shape, collision)
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
        for link in model.spec.links:
            link_pose = compose6(model.spec.pose, link.pose)
            visuals = list(link.visuals)
            for shape in link.collisions:
                pose = compose6(link_pose, shape.pose)
                # a link's only visual rides on its first collision body: half the bodies
                visual = -1
                if len(link.visuals) == 1 and visuals:
                    visual = self._make_shape(visuals.pop(), False,
                                              relative_to=(link_pose, pose))
                body = self._fixed_body(self._make_shape(shape, True), visual, pose)
                # min(mu, 1): see WORLD_FRICTION
                friction = WORLD_FRICTION if shape.friction is None \
                    else min(shape.friction, WORLD_FRICTION)
                pb.changeDynamics(body, -1, lateralFriction=friction, physicsClientId=self.client)
                model.static_bodies.append(body)
                if shape.kind != "mesh":  # meshes: lasers ask pybullet (see cast_rays)
                    model.primitives.append(primitive_for(
                        shape.kind, pose6_matrix(pose), size=shape.size, radius=shape.radius,
                        length=shape.length))
            for shape in visuals:
                pose = compose6(link_pose, shape.pose)
                model.static_bodies.append(self._fixed_body(-1, self._make_shape(shape, False),
                                                            pose))

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
        pb.changeDynamics(body, -1, localInertiaDiagonal=list(link.inertia),
                          lateralFriction=WORLD_FRICTION, linearDamping=0.0, angularDamping=0.0,
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
                   orientation: Sequence[float] = (0, 0, 0, 1), namespace: str = "",
                   joints: Optional[Mapping[str, float]] = None, source: str = "",
                   tf_prefix: str = "") -> Model:
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
        joints = dict(joints or {})
        unknown = [j for j in joints if j not in description.joints]
        if unknown:
            raise SimError(f"model '{name}' has no joint(s) {', '.join(unknown)}")
        robot = RobotBody(self.client, description, tags, xml, position, orientation,
                          self.bus.warn)
        model = Model(name, "robot", tuple(position), tuple(orientation), namespace.strip("/"),
                      robot=robot, tags=tags, body=robot.id, initial_joints=joints)
        robot.reset_joints(joints)
        context = PluginContext(self.client, robot, name, model.namespace, self.bus,
                                np.random.default_rng([self.seed, len(self.models)]),
                                self.step_size, self.gravity, self.cast_rays, tf_prefix)
        try:
            model.plugins = create_plugins(context, tags)
        except Exception:
            robot.remove()
            raise
        model.has_mesh = any(s.geometry.kind == "mesh" for link in description.links.values()
                             for s in link.collisions)
        model.ray_shapes = [
            RayShape(link.name, origin_transform(shape.origin), shape.geometry.kind,
                     shape.geometry.size, shape.geometry.radius, shape.geometry.length)
            for link in description.links.values() for shape in link.collisions
            if shape.geometry.kind != "mesh"]
        self.models[name] = model
        self._scene_changed()
        return model

    # --- requests ------------------------------------------------------------------------
    def model(self, name: str) -> Model:
        try:
            return self.models[name]
        except KeyError:
            known = ", ".join(sorted(self.models)) or "none"
            raise SimError(f"there is no model named '{name}' (models: {known})") from None

    def delete(self, name: str) -> None:
        model = self.model(name)
        for plugin in model.plugins:
            plugin.close()
        del self.models[name]
        self._scene_changed()
        if model.kind == "static":
            self._remove_static_bodies(model)
        elif model.robot is not None:
            model.robot.remove()
        elif model.body is not None:
            pb.removeBody(model.body, physicsClientId=self.client)

    def pose(self, name: str) -> Tuple[Vec3, Quat]:
        model = self.model(name)
        if model.kind == "static":
            return model.position, model.orientation
        if model.robot is not None:
            return model.robot.base_pose()
        return pb.getBasePositionAndOrientation(model.body, physicsClientId=self.client)

    def twist(self, name: str) -> Tuple[np.ndarray, np.ndarray]:
        model = self.model(name)
        if model.kind == "static":
            return np.zeros(3), np.zeros(3)
        if model.robot is not None:
            return model.robot.base_twist()
        linear, angular = pb.getBaseVelocity(model.body, physicsClientId=self.client)
        return np.asarray(linear), np.asarray(angular)

    def set_state(self, name: str, position: Sequence[float], orientation: Sequence[float],
                  linear: Sequence[float] = (0, 0, 0), angular: Sequence[float] = (0, 0, 0)) -> None:
        model = self.model(name)
        _finite(position, "the position")
        _finite(linear, "the linear velocity")
        _finite(angular, "the angular velocity")
        try:
            orientation = normalized(orientation)
        except ValueError as error:
            raise SimError(f"the orientation: {error}") from None
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
            pb.resetBasePositionAndOrientation(model.body, list(position), list(orientation),
                                               physicsClientId=self.client)
            pb.resetBaseVelocity(model.body, list(linear), list(angular),
                                 physicsClientId=self.client)

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
        model.initial_joints.update(positions)
        for plugin in model.plugins:
            plugin.reset(self.now_ns)

    def reset(self) -> None:
        """Every model back where it was spawned, at rest; time goes on (never backwards)."""
        for model in self.models.values():
            if model.kind == "static":
                continue
            self.set_state(model.name, model.initial_position, model.initial_orientation)
            if model.robot is not None:
                model.robot.reset_joints({j: model.initial_joints.get(j, 0.0)
                                          for j in model.robot.movable_joints()})
            for plugin in model.plugins:
                plugin.reset(self.now_ns)

    # --- stepping -------------------------------------------------------------------------
    def step(self) -> bool:
        """One physics step; False (and nothing happens) while paused."""
        if self.paused:
            return False
        if self._plugins is None:  # the models changed since the last step
            self._plugins = [p for m in self.models.values() for p in m.plugins]
            self._weightless = [m.robot for m in self.models.values()
                                if m.robot is not None and m.robot.weightless_links]
        for plugin in self._plugins:
            plugin.before_step(self.now_ns)
        for robot in self._weightless:
            robot.apply_weightlessness(self.gravity)
        pb.stepSimulation(physicsClientId=self.client)
        self.now_ns += self._step_ns
        for plugin in self._plugins:
            plugin.after_step(self.now_ns)
        return True

    # --- ray casting (lasers) -------------------------------------------------------------
    def cast_rays(self, origin: Sequence[float], directions: np.ndarray, near: float,
                  far: float) -> np.ndarray:
        """Distances from ``origin`` along unit ``directions`` to the first surface between
        ``near`` and ``far`` (inf where there is none). Analytic against the scene's
        primitive shapes; through pybullet when a mesh is in the scene."""
        origin = np.asarray(origin, dtype=float)
        starts = origin + directions * near
        if self._has_meshes is None:
            self._has_meshes = any(m.has_mesh for m in self.models.values())
        if self._has_meshes:
            ends = origin + directions * far
            results = pb.rayTestBatch(starts.tolist(), ends.tolist(),
                                      numThreads=self.ray_threads, physicsClientId=self.client)
            fractions = np.array([r[2] if r[0] >= 0 else np.inf for r in results])
            return near + fractions * (far - near)
        if self._static_shapes is None:
            self._static_shapes = ShapeSet([p for m in self.models.values()
                                            if m.kind == "static" for p in m.primitives])
        distances = near + cast([self._static_shapes, ShapeSet(self._moving_primitives())],
                                starts, directions)
        return np.where(distances <= far, distances, np.inf)

    def _moving_primitives(self) -> List[Primitive]:
        primitives: List[Primitive] = []
        for model in self.models.values():
            if model.robot is not None:
                frames = {name: pose_matrix(*model.robot.link_pose(name))
                          for name in {shape.link for shape in model.ray_shapes}}
                primitives.extend(shape.placed(frames[shape.link]) for shape in model.ray_shapes)
            elif model.body is not None:
                frame = pose_matrix(*pb.getBasePositionAndOrientation(
                    model.body, physicsClientId=self.client))
                primitives.extend(shape.placed(frame) for shape in model.ray_shapes)
        return primitives

    def close(self) -> None:
        for name in list(self.models):
            for plugin in self.models[name].plugins:
                plugin.close()
        pb.disconnect(physicsClientId=self.client)


__all__ = ["World", "Model", "SimError", "UrdfError"]
