"""The simulated world: pybullet underneath, Gazebo's notions on top. No rospy here.

It holds the models (static scenery, free bodies from SDF, robots from URDF with their
plugins), steps the physics with a fixed step, keeps simulated time as an integer number
of nanoseconds (monotonic, also across resets), and answers Gazebo's questions: spawn,
delete, get and set a model's state, pause, reset.

Static scenery is batched into a few multi-link bodies (at most ``STATIC_LINKS_PER_BODY``
links each), one link per collision or visual shape: pybullet casts rays through one such
body about three times faster than through one body per object, and it silently keeps
only 16 shapes of a compound and 127 links of a body.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable, Dict, List, Mapping, Optional, Sequence, Tuple

import numpy as np
import pybullet as pb

from sim_bridge.gazebo_tags import GazeboTags, read_gazebo_tags
from sim_bridge.plugins import create_plugins
from sim_bridge.plugins.base import Bus, Plugin, PluginContext
from sim_bridge.poses import (compose6, normalized, pose6_to_position_quaternion,
                              quaternion_from_rpy)
from sim_bridge.robot_body import RobotBody
from sim_bridge.sdf_world import ModelSpec, ShapeSpec, WorldSpec
from urdf_tools.model import UrdfError, parse_urdf

STATIC_LINKS_PER_BODY = 100
# pybullet multiplies the friction of the two surfaces in contact: world surfaces are 1.0
# so that a contact gets the robot link's own mu (Gazebo takes the smaller of the two).
WORLD_FRICTION = 1.0

Vec3 = Tuple[float, float, float]
Quat = Tuple[float, float, float, float]


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
    # for static models: where they are (they never move)
    position: Vec3 = (0.0, 0.0, 0.0)
    orientation: Quat = (0.0, 0.0, 0.0, 1.0)


def _finite(values: Sequence[float], what: str) -> None:
    if not all(math.isfinite(v) for v in values):
        raise SimError(f"{what} {tuple(values)} is not finite")


class World:
    def __init__(self, bus: Bus, step_size: float = 0.001,
                 gravity: Sequence[float] = (0.0, 0.0, -9.8), gui: bool = False, seed: int = 0,
                 ray_threads: int = 0):
        self.bus = bus
        self.gui = gui
        self.client = pb.connect(pb.GUI if gui else pb.DIRECT)
        self.seed = seed
        self.rng = np.random.default_rng(seed)
        self.ray_threads = ray_threads
        self.models: Dict[str, Model] = {}
        self._static_bodies: List[int] = []
        self.now_ns = 0
        self.paused = False
        self.step_size = step_size
        self.gravity = tuple(gravity)
        self._configure_physics()

    # --- physics settings --------------------------------------------------------------
    def _configure_physics(self) -> None:
        pb.setGravity(*self.gravity, physicsClientId=self.client)
        pb.setTimeStep(self.step_size, physicsClientId=self.client)
        pb.setPhysicsEngineParameter(deterministicOverlappingPairs=1,
                                     physicsClientId=self.client)

    @property
    def step_ns(self) -> int:
        return int(round(self.step_size * 1e9))

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
        if spec.static:
            self.models[spec.name] = model
            self._rebuild_static()
        else:
            model.body = self._free_body(spec)
            self.models[spec.name] = model
        return model

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

    def _make_shape(self, shape: ShapeSpec, collision: bool) -> int:
        create = pb.createCollisionShape if collision else pb.createVisualShape
        return create(physicsClientId=self.client, **self._shape_arguments(shape, collision))

    def _rebuild_static(self) -> None:
        """Rebuilds the static scenery's bodies from the static models' specs."""
        for body in self._static_bodies:
            pb.removeBody(body, physicsClientId=self.client)
        self._static_bodies = []
        entries: List[Tuple[int, int, Tuple[float, ...], Optional[float]]] = []
        for model in self.models.values():
            if model.kind != "static":
                continue
            for link in model.spec.links:
                link_pose = compose6(model.spec.pose, link.pose)
                for shape in link.collisions:
                    pose = compose6(link_pose, shape.pose)
                    entries.append((self._make_shape(shape, True), -1, pose, shape.friction))
                for shape in link.visuals:
                    pose = compose6(link_pose, shape.pose)
                    entries.append((-1, self._make_shape(shape, False), pose, None))
        for start in range(0, len(entries), STATIC_LINKS_PER_BODY):
            chunk = entries[start:start + STATIC_LINKS_PER_BODY]
            count = len(chunk)
            body = pb.createMultiBody(
                baseMass=0, baseCollisionShapeIndex=-1, baseVisualShapeIndex=-1,
                linkMasses=[0] * count,
                linkCollisionShapeIndices=[e[0] for e in chunk],
                linkVisualShapeIndices=[e[1] for e in chunk],
                linkPositions=[list(e[2][:3]) for e in chunk],
                linkOrientations=[list(quaternion_from_rpy(*e[2][3:6])) for e in chunk],
                linkInertialFramePositions=[[0, 0, 0]] * count,
                linkInertialFrameOrientations=[[0, 0, 0, 1]] * count,
                linkParentIndices=[0] * count, linkJointTypes=[pb.JOINT_FIXED] * count,
                linkJointAxis=[[0, 0, 1]] * count, physicsClientId=self.client)
            for index, entry in enumerate(chunk):
                # min(mu, 1): see WORLD_FRICTION
                friction = WORLD_FRICTION if entry[3] is None else min(entry[3], WORLD_FRICTION)
                pb.changeDynamics(body, index, lateralFriction=friction,
                                  physicsClientId=self.client)
            self._static_bodies.append(body)

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
                   joints: Optional[Mapping[str, float]] = None, source: str = "") -> Model:
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
                                self.step_size, self.gravity, self.cast_rays)
        try:
            model.plugins = create_plugins(context, tags)
        except Exception:
            robot.remove()
            raise
        self.models[name] = model
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
        if model.kind == "static":
            self._rebuild_static()
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
            self._rebuild_static()
        elif model.robot is not None:
            model.robot.set_base_state(position, orientation, linear, angular)
        else:
            pb.resetBasePositionAndOrientation(model.body, list(position), list(orientation),
                                               physicsClientId=self.client)
            pb.resetBaseVelocity(model.body, list(linear), list(angular),
                                 physicsClientId=self.client)

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
        plugins = [p for m in self.models.values() for p in m.plugins]
        for plugin in plugins:
            plugin.before_step(self.now_ns)
        for model in self.models.values():
            if model.robot is not None and model.robot._weightless:
                model.robot.apply_weightlessness(self.gravity)
        pb.stepSimulation(physicsClientId=self.client)
        self.now_ns += self.step_ns
        for plugin in plugins:
            plugin.after_step(self.now_ns)
        return True

    def cast_rays(self, starts: np.ndarray, ends: np.ndarray) -> List[tuple]:
        return pb.rayTestBatch(starts.tolist(), ends.tolist(), numThreads=self.ray_threads,
                               physicsClientId=self.client)

    def close(self) -> None:
        for name in list(self.models):
            for plugin in self.models[name].plugins:
                plugin.close()
        pb.disconnect(physicsClientId=self.client)


__all__ = ["World", "Model", "SimError", "UrdfError"]
