"""MoveIt's planning scene: the robot's state, the collision objects of the world, objects
attached to links and the allowed collision matrix, changed by moveit_msgs messages
(CollisionObject with ADD, REMOVE, APPEND and MOVE; AttachedCollisionObject; PlanningScene
diffs and full scenes) and asked whether a state collides (FCL, :mod:`moveit_core.collision`).

As MoveIt: an object's ``pose`` places it in its header's frame (a link of the robot or the
model frame), each shape's pose is relative to it, and a pose whose quaternion is all zeros
is the identity (older scripts leave ``pose`` unset); attaching an object with only its id
moves the world object onto the link; detaching puts it back into the world where it is;
only the links a group moves are checked when a group is named. A message that cannot be
applied raises SceneError naming the object and why, and changes nothing.
"""
from __future__ import annotations

import copy
import logging
from dataclasses import dataclass
from typing import Dict, List, Mapping, Optional, Sequence, Set, Tuple

import numpy as np
from geometry_msgs.msg import Pose
from moveit_msgs.msg import (AllowedCollisionEntry, AllowedCollisionMatrix,
                             AttachedCollisionObject, CollisionObject,
                             PlanningScene as PlanningSceneMsg, PlanningSceneComponents)
from shape_msgs.msg import SolidPrimitive
from tf.transformations import quaternion_from_matrix, quaternion_matrix

from moveit_core.collision import (AllowedCollisions, Body, Shape, ShapeError, fcl,
                                   mesh_geometry, robot_shapes)
from moveit_core.robot_model import RobotModel

# rospy shows the rosout.* loggers on the console and /rosout
LOG = logging.getLogger("rosout.moveit_core")
# m: a pair whose bounding volumes are farther apart than this is not handed to FCL (a
# margin over rounding: FCL counts touching as contact)
NEAR = 1e-4


class SceneError(ValueError):
    """A scene message that cannot be applied; the message names the object and why."""


def pose_matrix(pose: Pose, what: str) -> np.ndarray:
    """A Pose as a 4x4 matrix; an all-zero quaternion is the identity, as MoveIt reads it."""
    q = np.array([pose.orientation.x, pose.orientation.y, pose.orientation.z,
                  pose.orientation.w], dtype=float)
    p = np.array([pose.position.x, pose.position.y, pose.position.z], dtype=float)
    if not (np.all(np.isfinite(q)) and np.all(np.isfinite(p))):
        raise SceneError(f"{what} holds a value that is not finite")
    norm = np.linalg.norm(q)
    matrix = quaternion_matrix(q / norm) if norm > 1e-9 else np.eye(4)
    matrix[:3, 3] = p
    return matrix


def matrix_pose(matrix: np.ndarray) -> Pose:
    pose = Pose()
    pose.position.x, pose.position.y, pose.position.z = (float(v) for v in matrix[:3, 3])
    rotation = np.eye(4)
    rotation[:3, :3] = matrix[:3, :3]
    q = quaternion_from_matrix(rotation)
    pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w = \
        (float(v) for v in q)
    return pose


def primitive_geometry(primitive: SolidPrimitive, what: str):
    dims = [float(d) for d in primitive.dimensions]
    needed = {SolidPrimitive.BOX: 3, SolidPrimitive.SPHERE: 1, SolidPrimitive.CYLINDER: 2,
              SolidPrimitive.CONE: 2}
    if primitive.type not in needed:
        raise SceneError(f"{what}: solid primitive type {primitive.type} is not one of "
                         "BOX (1), SPHERE (2), CYLINDER (3), CONE (4)")
    if len(dims) < needed[primitive.type] or not all(
            np.isfinite(d) and d > 0 for d in dims[:needed[primitive.type]]):
        raise SceneError(f"{what}: dimensions {dims} (needs {needed[primitive.type]} sizes "
                         "> 0)")
    if primitive.type == SolidPrimitive.BOX:
        return fcl.Box(*dims[:3]), "box"
    if primitive.type == SolidPrimitive.SPHERE:
        return fcl.Sphere(dims[0]), "sphere"
    if primitive.type == SolidPrimitive.CYLINDER:
        return fcl.Cylinder(dims[SolidPrimitive.CYLINDER_RADIUS],
                            dims[SolidPrimitive.CYLINDER_HEIGHT]), "cylinder"
    return fcl.Cone(dims[SolidPrimitive.CONE_RADIUS], dims[SolidPrimitive.CONE_HEIGHT]), "cone"


def object_shapes(message: CollisionObject) -> List[Shape]:
    """The shapes of a CollisionObject message, each relative to the object's pose."""
    what = f"collision object '{message.id}'"
    for kind, shapes, poses in (("primitives", message.primitives, message.primitive_poses),
                                ("meshes", message.meshes, message.mesh_poses),
                                ("planes", message.planes, message.plane_poses)):
        if len(shapes) != len(poses):
            raise SceneError(f"{what} has {len(shapes)} {kind} and {len(poses)} poses of them")
    found: List[Shape] = []
    for index, (primitive, pose) in enumerate(zip(message.primitives, message.primitive_poses)):
        geometry, kind = primitive_geometry(primitive, f"{what} primitive {index + 1}")
        found.append(Shape(geometry, pose_matrix(pose, f"{what} primitive pose"), kind))
    for index, (mesh, pose) in enumerate(zip(message.meshes, message.mesh_poses)):
        vertices = np.array([[v.x, v.y, v.z] for v in mesh.vertices], dtype=float)
        triangles = np.array([list(t.vertex_indices) for t in mesh.triangles], dtype=int)
        try:
            geometry = mesh_geometry(vertices, triangles, f"{what} mesh {index + 1}")
        except ShapeError as error:
            raise SceneError(str(error)) from error
        found.append(Shape(geometry, pose_matrix(pose, f"{what} mesh pose"), "mesh"))
    for index, (plane, pose) in enumerate(zip(message.planes, message.plane_poses)):
        a, b, c, d = plane.coef
        normal = np.array([a, b, c], dtype=float)
        if not np.all(np.isfinite(plane.coef)) or np.linalg.norm(normal) < 1e-9:
            raise SceneError(f"{what} plane {index + 1}: coefficients {list(plane.coef)}")
        # ax + by + cz + d = 0: FCL's plane n.x = offset, the half space below it
        scale = np.linalg.norm(normal)
        found.append(Shape(fcl.Halfspace(normal / scale, -d / scale),
                           pose_matrix(pose, f"{what} plane pose"), "plane"))
    return found


@dataclass
class SceneObject:
    """A collision object of the world: its pose in the model frame, its shapes."""

    message: CollisionObject            # as given, its pose re-expressed in the model frame
    pose: np.ndarray
    body: Body


@dataclass
class AttachedObject:
    message: AttachedCollisionObject    # the object's pose relative to the link
    link: str
    offset: np.ndarray                  # the object's pose in the link's frame
    touch_links: Set[str]
    body: Body


class PlanningScene:
    """One robot's scene; ``positions`` the robot's state (every variable)."""

    def __init__(self, model: RobotModel, name: str = "(noname)+"):
        self.model, self.name = model, name
        self.positions: Dict[str, float] = model.default_positions()
        self.links = {link: Body(link, shapes) for link, shapes in robot_shapes(model).items()}
        self.acm = AllowedCollisions(
            [(d.link1, d.link2) for d in model.srdf.disabled_collisions],
            model.srdf.disabled_default_collisions)
        for a, b in model.srdf.enabled_collisions:
            self.acm.set(a, b, False)
        self.objects: Dict[str, SceneObject] = {}
        self.attached: Dict[str, AttachedObject] = {}
        self._moved_by: Dict[Optional[str], Set[str]] = {}
        self._pairs: Dict[tuple, _Checks] = {}      # see _pairs_to_check

    def copy(self) -> "PlanningScene":
        """An independent scene (a planning request's, or another thread's): the same
        shapes, collision objects of its own (FCL objects are moved for every check)."""
        other = copy.copy(self)
        other.positions = dict(self.positions)
        other.links = {name: Body(name, body.shapes) for name, body in self.links.items()}
        other.objects = {name: SceneObject(o.message, o.pose, Body(name, o.body.shapes))
                         for name, o in self.objects.items()}
        other.attached = {name: AttachedObject(a.message, a.link, a.offset, set(a.touch_links),
                                               Body(name, a.body.shapes))
                          for name, a in self.attached.items()}
        other.acm = self.acm.copy()
        other._moved_by = dict(self._moved_by)
        other._pairs = {}       # they name this scene's bodies
        return other

    # --- frames ------------------------------------------------------------------------

    def frame_pose(self, frame: str, poses: Optional[Mapping[str, np.ndarray]] = None
                   ) -> np.ndarray:
        if frame in ("", self.model.model_frame, self.model.root_link):
            return np.eye(4)
        poses = poses if poses is not None else self.model.link_poses(self.positions)
        if frame in poses:
            return poses[frame]
        if frame in self.objects:
            return self.objects[frame].pose
        raise SceneError(f"frame '{frame}' is neither a link of the robot, its model frame "
                         f"'{self.model.model_frame}' nor an object of the scene")

    # --- changes -----------------------------------------------------------------------

    def apply_collision_object(self, message: CollisionObject) -> None:
        op, name = message.operation, message.id
        if op == CollisionObject.REMOVE:
            if not name:
                self.objects.clear()
            elif self.objects.pop(name, None) is None:
                raise SceneError(f"cannot remove collision object '{name}': the scene has none "
                                 "of that name")
            return
        if not name:
            raise SceneError("a collision object without an id")
        frame = self.frame_pose(message.header.frame_id)
        pose = frame @ pose_matrix(message.pose, f"collision object '{name}' pose")
        if op == CollisionObject.MOVE:
            if name not in self.objects:
                raise SceneError(f"cannot move collision object '{name}': the scene has none "
                                 "of that name")
            self.objects[name].pose = pose
            self.objects[name].message.pose = matrix_pose(pose)
            return
        if op not in (CollisionObject.ADD, CollisionObject.APPEND):
            raise SceneError(f"collision object '{name}': unknown operation {op}")
        shapes = object_shapes(message)
        kept = copy.deepcopy(message)
        kept.header.frame_id, kept.pose = self.model.model_frame, matrix_pose(pose)
        if op == CollisionObject.APPEND and name in self.objects:
            old = self.objects[name]
            shapes = old.body.shapes + [Shape(s.geometry, np.linalg.inv(old.pose) @ pose @
                                              s.offset, s.kind) for s in shapes]
            kept = _appended(old.message, message, np.linalg.inv(old.pose) @ pose)
            pose = old.pose
        if not shapes:
            raise SceneError(f"collision object '{name}' has no shape (ADD needs at least one "
                             "primitive, mesh or plane)")
        self.objects[name] = SceneObject(kept, pose, Body(name, shapes))

    def apply_attached_object(self, message: AttachedCollisionObject) -> None:
        obj, link = message.object, message.link_name
        if obj.operation == CollisionObject.REMOVE:
            names = [obj.id] if obj.id else [n for n, a in self.attached.items()
                                             if not link or a.link == link]
            for name in names:
                self._detach(name)
            return
        if obj.operation != CollisionObject.ADD:
            raise SceneError(f"attached object '{obj.id}': operation {obj.operation} (ADD or "
                             "REMOVE)")
        if link not in self.model.urdf.links:
            raise SceneError(f"cannot attach '{obj.id}' to '{link}': the robot has no such link")
        poses = self.model.link_poses(self.positions)
        to_link = np.linalg.inv(poses[link])
        if obj.primitives or obj.meshes or obj.planes:
            frame = self.frame_pose(obj.header.frame_id or link, poses)
            pose = frame @ pose_matrix(obj.pose, f"attached object '{obj.id}' pose")
            shapes = object_shapes(obj)
            self.objects.pop(obj.id, None)
        elif obj.id in self.objects:
            world = self.objects.pop(obj.id)
            pose, shapes = world.pose, world.body.shapes
            obj = world.message
        elif obj.id in self.attached:
            return      # already attached, nothing new
        else:
            raise SceneError(f"cannot attach '{obj.id}': no shapes given and no world object "
                             "of that name")
        offset = to_link @ pose
        kept = copy.deepcopy(message)
        kept.object = copy.deepcopy(obj)
        kept.object.header.frame_id, kept.object.pose = link, matrix_pose(offset)
        kept.object.operation = CollisionObject.ADD
        touch = set(message.touch_links) | {link}
        self.attached[obj.id] = AttachedObject(kept, link, offset, touch, Body(obj.id, shapes))

    def _detach(self, name: str) -> None:
        attached = self.attached.pop(name, None)
        if attached is None:
            raise SceneError(f"cannot detach '{name}': no object of that name is attached")
        pose = self.model.link_poses(self.positions)[attached.link] @ attached.offset
        message = copy.deepcopy(attached.message.object)
        message.header.frame_id, message.pose = self.model.model_frame, matrix_pose(pose)
        self.objects[name] = SceneObject(message, pose, attached.body)

    def set_state(self, positions: Mapping[str, float]) -> None:
        self.positions.update({j: float(v) for j, v in positions.items()
                               if j in self.model.bounds})

    def apply(self, scene: PlanningSceneMsg) -> None:
        """A PlanningScene message: a diff (``is_diff``) applied, or the whole scene replaced
        (world objects and attached objects; the robot state's joints set). All or nothing."""
        trial = self.copy()
        if not scene.is_diff:
            trial.objects.clear()
            trial.attached.clear()
        # in MoveIt's order (PlanningScene::setPlanningSceneDiffMsg, planning_scene.cpp:1286-1310
        # on noetic-devel): the robot state with its attached objects, then the world's objects,
        # so that an object a diff detaches (back into the world) is removed by the same diff's
        # world REMOVE, as PlanningSceneInterface::clear() relies on
        state = scene.robot_state.joint_state
        trial.set_state(dict(zip(state.name, state.position)))
        for message in scene.robot_state.attached_collision_objects:
            trial.apply_attached_object(message)
        _apply_matrix(trial.acm, scene.allowed_collision_matrix)
        for message in scene.world.collision_objects:
            trial.apply_collision_object(message)
        self.objects, self.attached, self.acm, self.positions = \
            trial.objects, trial.attached, trial.acm, trial.positions

    # --- questions ---------------------------------------------------------------------

    def moved_links(self, group: Optional[str]) -> Set[str]:
        """Links whose pose the group's variables change (every link without a group)."""
        if group not in self._moved_by:
            if group is None:
                self._moved_by[group] = set(self.model.urdf.links)
            else:
                moved: Set[str] = set()
                for joint in self.model.group(group).joints:
                    stack = [self.model.urdf.joints[joint].child]
                    while stack:
                        link = stack.pop()
                        moved.add(link)
                        stack.extend(j.child for j in self.model.urdf.joints.values()
                                     if j.parent == link)
                self._moved_by[group] = moved
        return self._moved_by[group]

    def _pairs_to_check(self, group: Optional[str]) -> "_Checks":
        """The bodies to place and the pairs to check: pairs of which one moves with the
        group, not allowed by the matrix. Kept until the scene's objects, attached objects
        or matrix change (planning checks thousands of states of one scene)."""
        key = (group, tuple((n, id(o.body)) for n, o in self.objects.items()),
               tuple((n, id(a.body)) for n, a in self.attached.items()), id(self.acm),
               self.acm.version)
        if key in self._pairs:
            return self._pairs[key]
        moving = self.moved_links(group)
        links = list(self.links.values())
        candidates = []
        for i, a in enumerate(links):
            candidates += [(a, b) for b in links[i + 1:] if a.name in moving or b.name in moving]
            if a.name in moving:
                candidates += [(a, obj.body) for obj in self.objects.values()]
        for attached in self.attached.values():
            if attached.link in moving:
                candidates += [(attached.body, obj.body) for obj in self.objects.values()]
                candidates += [(attached.body, link) for link in links
                               if link.name not in attached.touch_links]
        pairs = [(a, b) for a, b in candidates if not self.acm.allowed(a.name, b.name)]
        self._pairs = {key: _Checks(pairs)}
        return self._pairs[key]

    def _world_poses(self, checks: "_Checks", poses: Mapping[str, np.ndarray],
                     count: int) -> np.ndarray:
        """Each checked body's pose in the model frame in each state (bodies x N x 4 x 4),
        from the links' poses (N x 4 x 4 each)."""
        placed = []
        for body in checks.bodies:
            if body.name in self.links:
                placed.append(poses[body.name])
            elif body.name in self.attached:
                attached = self.attached[body.name]
                placed.append(poses[attached.link] @ attached.offset)
            else:
                placed.append(np.broadcast_to(self.objects[body.name].pose, (count, 4, 4)))
        return np.stack(placed) if placed else np.zeros((0, count, 4, 4))

    @staticmethod
    def _touching(checks: "_Checks", world: np.ndarray, pairs: Sequence[int], state: int,
                  first_only: bool) -> List[Tuple[str, str]]:
        """FCL's answer for some of the pairs (their indices) in one state."""
        for index in np.unique(np.concatenate((checks.first[pairs], checks.second[pairs]))):
            checks.bodies[index].place(world[index, state])
        found: List[Tuple[str, str]] = []
        for pair in pairs:
            a, b = checks.pairs[pair]
            if a.touches(b):
                found.append((a.name, b.name))
                if first_only:
                    break
        return found

    def contacts(self, positions: Optional[Mapping[str, float]] = None,
                 group: Optional[str] = None, first_only: bool = True) -> List[Tuple[str, str]]:
        """The pairs in collision at ``positions`` (over the scene's state); with ``group``,
        only pairs of which one moves with the group."""
        state = dict(self.positions)
        if positions:
            state.update(positions)
        poses = self.model.link_poses(state)
        checks = self._pairs_to_check(group)
        world = self._world_poses(checks, {k: v[None] for k, v in poses.items()}, 1)
        # every pair: for one state the broad phase costs about what FCL does
        return self._touching(checks, world, np.arange(len(checks.pairs)), 0, first_only)

    def first_collision(self, positions: Mapping[str, float], variables: Sequence[str],
                        values: np.ndarray, group: Optional[str], order: Sequence[int]
                        ) -> Optional[int]:
        """The first state of ``values`` (N x len(variables), over ``positions`` over the
        scene's state) in ``order`` that collides, or None: a motion's states, kinematics and
        broad phase for all of them at once, FCL for the pairs found near."""
        values = np.asarray(values, dtype=float).reshape(-1, len(variables))
        poses = self.model.link_poses_many(dict(self.positions, **positions), variables,
                                           values)
        checks = self._pairs_to_check(group)
        world = self._world_poses(checks, poses, len(values))
        near = checks.near(world)
        wanted = near.any(axis=0)
        for state in order:
            if wanted[state] and self._touching(checks, world, np.flatnonzero(near[:, state]),
                                                state, True):
                return state
        return None

    def in_collision(self, positions: Optional[Mapping[str, float]] = None,
                     group: Optional[str] = None) -> bool:
        return bool(self.contacts(positions, group))

    # --- messages ----------------------------------------------------------------------

    def to_msg(self, components: int = 0) -> PlanningSceneMsg:
        """The scene as get_planning_scene answers (``components`` 0: everything)."""
        c = PlanningSceneComponents
        wanted = components or 0xFFFF
        scene = PlanningSceneMsg(name=self.name, robot_model_name=self.model.name,
                                 is_diff=False)
        if wanted & c.ROBOT_STATE:
            names = [j for j in self.model.joint_order if j in self.model.bounds]
            full = self.model.complete(self.positions)
            scene.robot_state.joint_state.name = names
            scene.robot_state.joint_state.position = [full[j] for j in names]
        if wanted & (c.ROBOT_STATE | c.ROBOT_STATE_ATTACHED_OBJECTS):
            scene.robot_state.attached_collision_objects = [
                copy.deepcopy(a.message) for a in self.attached.values()]
        if wanted & (c.WORLD_OBJECT_NAMES | c.WORLD_OBJECT_GEOMETRY):
            for obj in self.objects.values():
                if wanted & c.WORLD_OBJECT_GEOMETRY:
                    scene.world.collision_objects.append(copy.deepcopy(obj.message))
                else:
                    scene.world.collision_objects.append(CollisionObject(
                        id=obj.message.id, type=obj.message.type))
        if wanted & c.ALLOWED_COLLISION_MATRIX:
            scene.allowed_collision_matrix = _matrix_msg(
                self.acm, list(self.links) + list(self.objects) + list(self.attached))
        return scene


class _Checks:
    """The pairs a scene checks for one group, with their broad phase: each body's bounding
    sphere (and box, for a body that is one box) tested for all pairs and states at once;
    only pairs within NEAR of touching go to FCL."""

    def __init__(self, pairs: Sequence[Tuple[Body, Body]]):
        self.pairs = list(pairs)
        index: Dict[int, int] = {}
        self.bodies: List[Body] = []
        for body in (body for pair in self.pairs for body in pair):
            if id(body) not in index:
                index[id(body)] = len(self.bodies)
                self.bodies.append(body)
        self.first = np.array([index[id(a)] for a, _ in self.pairs], dtype=int)
        self.second = np.array([index[id(b)] for _, b in self.pairs], dtype=int)
        self.centres = np.array([b.centre for b in self.bodies]).reshape(-1, 3)
        self.radii = np.array([b.radius for b in self.bodies])
        # a pair with a box: the other body's sphere against the box (tighter than two
        # spheres around a table); ``sphere`` and ``boxed`` are the pair's bodies so ordered
        first_box = np.array([a.box is not None for a, _ in self.pairs], dtype=bool)
        second_box = np.array([b.box is not None for _, b in self.pairs], dtype=bool)
        self.with_box, self.two_boxes = first_box | second_box, first_box & second_box
        self.sphere = np.where(second_box, self.first, self.second)
        self.boxed = np.where(second_box, self.second, self.first)
        self.box_poses = np.array([b.box[0] if b.box is not None else np.eye(4)
                                   for b in self.bodies]).reshape(-1, 4, 4)
        self.half_sizes = np.array([b.box[1] if b.box is not None else np.zeros(3)
                                    for b in self.bodies]).reshape(-1, 3)

    def near(self, world: np.ndarray) -> np.ndarray:
        """Pairs x states: True where the pair's bounds are within NEAR of each other, with
        the bodies at ``world`` (bodies x N x 4 x 4). Spheres first, for all; a sphere
        against a box, then box against box, only where the spheres meet."""
        centres = (world[:, :, :3, :3] @ self.centres[:, None, :, None])[..., 0] + \
            world[:, :, :3, 3]
        with np.errstate(invalid="ignore"):     # infinite radii (planes) are always near
            gap = np.linalg.norm(centres[self.first] - centres[self.second], axis=-1) - \
                self.radii[self.first][:, None] - self.radii[self.second][:, None]
        near = ~(gap > NEAR)
        pairs, states = np.nonzero(near & self.with_box[:, None])
        if len(pairs):
            sphere, boxed = self.sphere[pairs], self.boxed[pairs]
            frames = world[boxed, states] @ self.box_poses[boxed]
            offset = centres[sphere, states] - frames[:, :3, 3]
            local = (offset[:, None, :] @ frames[:, :3, :3])[:, 0, :]
            outside = np.clip(np.abs(local) - self.half_sizes[boxed], 0.0, None)
            apart = np.linalg.norm(outside, axis=-1) - self.radii[sphere] > NEAR
            near[pairs[apart], states[apart]] = False
        pairs, states = np.nonzero(near & self.two_boxes[:, None])
        if len(pairs):
            first, second = self.first[pairs], self.second[pairs]
            apart = _boxes_apart(world[first, states] @ self.box_poses[first],
                                 self.half_sizes[first],
                                 world[second, states] @ self.box_poses[second],
                                 self.half_sizes[second])
            near[pairs[apart], states[apart]] = False
        return near


# added to the rotation's entries in the separating-axis test, so that two nearly parallel
# edges (whose cross product is almost zero) never seem to separate the boxes
PARALLEL_EDGES = 1e-6


def _boxes_apart(a: np.ndarray, half_a: np.ndarray, b: np.ndarray, half_b: np.ndarray
                 ) -> np.ndarray:
    """For M pairs of boxes (poses M x 4 x 4, half sizes M x 3): True where they are more
    than NEAR apart along one of their 15 separating axes (Gottschalk's OBB test, in a's
    frame: its 3 face normals, b's 3, the 9 edge cross products)."""
    rotation = np.swapaxes(a[:, :3, :3], -1, -2) @ b[:, :3, :3]
    offset = ((b[:, :3, 3] - a[:, :3, 3])[:, None, :] @ a[:, :3, :3])[:, 0, :]
    size = np.abs(rotation) + PARALLEL_EDGES
    apart = np.any(np.abs(offset) > half_a + (size @ half_b[:, :, None])[:, :, 0] + NEAR,
                   axis=-1)
    along_b = (offset[:, None, :] @ rotation)[:, 0, :]
    apart |= np.any(np.abs(along_b) > (half_a[:, None, :] @ size)[:, 0, :] + half_b + NEAR,
                    axis=-1)
    for i in range(3):
        i1, i2 = (i + 1) % 3, (i + 2) % 3
        for j in range(3):
            j1, j2 = (j + 1) % 3, (j + 2) % 3
            reach = half_a[:, i1] * size[:, i2, j] + half_a[:, i2] * size[:, i1, j] + \
                half_b[:, j1] * size[:, i, j2] + half_b[:, j2] * size[:, i, j1]
            distance = np.abs(offset[:, i2] * rotation[:, i1, j] -
                              offset[:, i1] * rotation[:, i2, j])
            apart |= distance > reach + NEAR
    return apart


def _appended(old: CollisionObject, new: CollisionObject, relative: np.ndarray
              ) -> CollisionObject:
    """``old`` with ``new``'s shapes added, their poses re-expressed relative to old's."""
    merged = copy.deepcopy(old)
    for shapes, poses, target, target_poses in (
            (new.primitives, new.primitive_poses, merged.primitives, merged.primitive_poses),
            (new.meshes, new.mesh_poses, merged.meshes, merged.mesh_poses),
            (new.planes, new.plane_poses, merged.planes, merged.plane_poses)):
        for shape, pose in zip(shapes, poses):
            target.append(shape)
            target_poses.append(matrix_pose(relative @ pose_matrix(pose, "pose")))
    return merged


def _apply_matrix(acm: AllowedCollisions, message: AllowedCollisionMatrix) -> None:
    names = list(message.entry_names)
    if len(message.entry_values) != len(names):
        if names or message.entry_values:
            raise SceneError(f"allowed collision matrix: {len(names)} names and "
                             f"{len(message.entry_values)} rows")
    for i, row in enumerate(message.entry_values):
        if len(row.enabled) != len(names):
            raise SceneError(f"allowed collision matrix: row '{names[i]}' has "
                             f"{len(row.enabled)} values for {len(names)} names")
        for j, allowed in enumerate(row.enabled):
            if i != j:
                acm.set(names[i], names[j], bool(allowed))
    for name, allowed in zip(message.default_entry_names, message.default_entry_values):
        acm.set_default(name, bool(allowed))


def _matrix_msg(acm: AllowedCollisions, names: Sequence[str]) -> AllowedCollisionMatrix:
    names = sorted(set(names) | set(acm.names()))
    message = AllowedCollisionMatrix(entry_names=names)
    for a in names:
        message.entry_values.append(AllowedCollisionEntry(
            enabled=[a != b and acm.allowed(a, b) for b in names]))
    message.default_entry_names = [n for n, v in acm.everything.items() if v]
    message.default_entry_values = [True] * len(message.default_entry_names)
    return message
