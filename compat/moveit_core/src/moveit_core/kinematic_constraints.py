"""MoveIt's kinematic constraints (moveit_core/kinematic_constraints/src/kinematic_constraint.cpp
on noetic-devel, "kc" below): a moveit_msgs/Constraints message turned into a set that
decides whether a state satisfies it, with upstream's formulas and tolerances.

- JointConstraint (kc:264-295): ``position - tolerance_below <= value <= position +
  tolerance_above`` with 2 machine epsilons of slack; a continuous joint compares the
  shortest signed angle between the wrapped value and the wrapped target.
- PositionConstraint (kc:493-527): the link's ``target_point_offset`` (in the link's frame)
  must lie inside one of the ``constraint_region``'s primitives (box, sphere, cylinder at
  their poses, as geometric_shapes' bodies containsPoint without padding) or convex meshes,
  the region placed in ``header.frame_id``.
- OrientationConstraint (kc:666-727): the link's rotation relative to the target,
  ``R_target^T * R_link``, as intrinsic XYZ Euler angles (CalcEulerAngles, kc:78-111, with
  its gimbal-lock rule, kc:698-705) wrapped to [0, pi] (normalizeAbsoluteAngle, kc:63-67),
  or as a rotation vector's absolute components (parameterization ROTATION_VECTOR); each
  strictly below its absolute tolerance plus one machine epsilon (kc:724-726).

A constraint that cannot be configured (an unknown joint or link, a region without
shapes) is left out of the set with a warning, as upstream's ``configure`` returning false
disables it (KinematicConstraintSet::add). VisibilityConstraints are not provided: a set
holding one says so (:class:`ConstraintSet` raises). Frames resolve through the scene
(:meth:`PlanningScene.frame_pose`): the model frame, a link (moving with the state), or a
collision object. No ROS here."""
from __future__ import annotations

import logging
import math
import sys
from dataclasses import dataclass
from typing import List, Mapping, Optional

import numpy as np
from geometry_msgs.msg import Pose
from moveit_msgs.msg import Constraints, MoveItErrorCodes, OrientationConstraint as OrientationMsg
from shape_msgs.msg import SolidPrimitive

from moveit_core.planning_scene import PlanningScene, SceneError, pose_matrix

LOG = logging.getLogger("rosout.kinematic_constraints")

EPSILON = sys.float_info.epsilon   # std::numeric_limits<double>::epsilon(), kc:286-287, 724-726
# CalcEulerAngles' test for cos(pitch) == 0 (kc:92): 4 epsilons
GIMBAL_LOCK = 4 * EPSILON


class ConstraintError(ValueError):
    """A constraint message that cannot be evaluated: ``code`` is MoveIt's error code."""

    def __init__(self, message: str, code: int = MoveItErrorCodes.FAILURE):
        super().__init__(message)
        self.code = code


def normalize_angle(angle: float) -> float:
    """An angle in [-pi, pi] (kc:48-59, normalizeAngle)."""
    value = math.fmod(angle, 2.0 * math.pi)
    if value < -math.pi:
        value += 2.0 * math.pi
    elif value > math.pi:
        value -= 2.0 * math.pi
    return value


def normalize_absolute_angle(angle: float) -> float:
    """|angle| folded into [0, pi] (kc:63-67)."""
    folded = math.fmod(abs(angle), 2.0 * math.pi)
    return min(2.0 * math.pi - folded, folded)


def intrinsic_xyz(rotation: np.ndarray):
    """(roll, pitch, yaw) with R = Rx(roll) Ry(pitch) Rz(yaw), and False at gimbal lock,
    where roll carries roll + yaw (or roll - yaw) and yaw is 0 (kc:78-111)."""
    r = rotation
    rsum = math.sqrt((r[0, 0] ** 2 + r[0, 1] ** 2 + r[1, 2] ** 2 + r[2, 2] ** 2) / 2.0)
    pitch = math.atan2(r[0, 2], rsum)
    if rsum > GIMBAL_LOCK:
        return np.array([math.atan2(-r[1, 2], r[2, 2]), pitch, math.atan2(-r[0, 1], r[0, 0])]), True
    if r[0, 2] > 0:
        return np.array([math.atan2(r[1, 0] + r[2, 1], r[1, 1] - r[2, 0]), pitch, 0.0]), False
    return np.array([math.atan2(r[2, 1] - r[1, 0], r[1, 1] + r[2, 0]), pitch, 0.0]), False


def rotation_vector(rotation: np.ndarray) -> np.ndarray:
    """The rotation's axis times its angle (angle in [0, pi]), as Eigen::AngleAxisd."""
    cosine = max(-1.0, min(1.0, (np.trace(rotation) - 1.0) / 2.0))
    angle = math.acos(cosine)
    if angle < 1e-12:
        return np.zeros(3)
    if math.pi - angle < 1e-6:   # near a half turn the skew part vanishes: the axis from R + I
        symmetric = (rotation + np.eye(3)) / 2.0
        axis = np.sqrt(np.clip(np.diag(symmetric), 0.0, None))
        pivot = int(np.argmax(axis))
        for i in range(3):
            if i != pivot and symmetric[pivot, i] < 0:
                axis[i] = -axis[i]
        return axis / np.linalg.norm(axis) * angle
    axis = np.array([rotation[2, 1] - rotation[1, 2], rotation[0, 2] - rotation[2, 0],
                     rotation[1, 0] - rotation[0, 1]]) / (2.0 * math.sin(angle))
    return axis * angle


def orientation_error(relative: np.ndarray, parameterization: int,
                      z_tolerance: float) -> np.ndarray:
    """The three non-negative angles an OrientationConstraint compares with its tolerances,
    for the link's rotation relative to the target (kc:686-716)."""
    if parameterization == OrientationMsg.ROTATION_VECTOR:
        return np.abs(rotation_vector(relative))
    angles, regular = intrinsic_xyz(relative)
    if not regular and normalize_absolute_angle(angles[0]) > z_tolerance + EPSILON:
        # at gimbal lock the yaw hides in the roll: read it as a yaw (kc:698-705)
        angles[2], angles[0] = angles[0], 0.0
    return np.array([normalize_absolute_angle(a) for a in angles])


@dataclass
class Region:
    """One shape of a PositionConstraint's region: a primitive or a convex mesh's facets."""

    pose: np.ndarray                       # in the constraint's frame
    kind: str                              # box, sphere, cylinder, mesh
    dimensions: np.ndarray
    facets: Optional[np.ndarray] = None    # mesh: rows (normal, offset), inside when <= 0

    def contains(self, local: np.ndarray) -> bool:
        if self.kind == "box":
            return bool(np.all(np.abs(local) <= self.dimensions / 2.0))
        if self.kind == "sphere":
            return float(local @ local) <= self.dimensions[0] ** 2
        if self.kind == "cylinder":
            return abs(local[2]) <= self.dimensions[0] / 2.0 and \
                float(local[:2] @ local[:2]) <= self.dimensions[1] ** 2
        return bool(np.all(self.facets[:, :3] @ local + self.facets[:, 3] <= 1e-12))

    def sample(self, rng: np.random.Generator, tries: int) -> Optional[np.ndarray]:
        """A point inside, in the region's own frame (rejection in its bounding box)."""
        if self.kind == "box":
            return rng.uniform(-self.dimensions / 2.0, self.dimensions / 2.0)
        if self.kind == "sphere":
            half = np.full(3, self.dimensions[0])
        elif self.kind == "cylinder":
            half = np.array([self.dimensions[1], self.dimensions[1], self.dimensions[0] / 2.0])
        else:
            half = None
        low, high = (-half, half) if half is not None else (self.dimensions[0], self.dimensions[1])
        for _ in range(tries):
            point = rng.uniform(low, high)
            if self.contains(point):
                return point
        return None


def _regions(message) -> List[Region]:
    region = message.constraint_region
    found = []
    for primitive, pose in zip(region.primitives, region.primitive_poses):
        dims = np.array(primitive.dimensions, dtype=float)
        kind = {SolidPrimitive.BOX: "box", SolidPrimitive.SPHERE: "sphere",
                SolidPrimitive.CYLINDER: "cylinder"}.get(primitive.type)
        needed = {"box": 3, "sphere": 1, "cylinder": 2}.get(kind, 0)
        if kind is None or len(dims) < needed:
            LOG.warning("position constraint on '%s': a primitive of type %d with %d "
                        "dimensions is left out of its region", message.link_name,
                        primitive.type, len(dims))
            continue
        found.append(Region(pose_matrix(pose, "constraint region pose"), kind, dims[:needed]))
    for mesh, pose in zip(region.meshes, region.mesh_poses):
        points = np.array([[v.x, v.y, v.z] for v in mesh.vertices], dtype=float)
        facets = _convex_facets(points)
        if facets is None:
            LOG.warning("position constraint on '%s': a mesh of %d vertices encloses no "
                        "volume and is left out of its region", message.link_name, len(points))
            continue
        found.append(Region(pose_matrix(pose, "constraint region mesh pose"), "mesh",
                            np.array([points.min(axis=0), points.max(axis=0)]), facets))
    return found


def _convex_facets(points: np.ndarray) -> Optional[np.ndarray]:
    """The convex hull's half-spaces of a mesh's vertices (geometric_shapes' ConvexMesh
    body is the mesh's convex hull)."""
    if len(points) < 4:
        return None
    try:
        from scipy.spatial import ConvexHull, QhullError
    except ImportError as error:
        raise ConstraintError("a mesh in a position constraint's region needs scipy "
                              "(python3-scipy)") from error
    try:
        return ConvexHull(points).equations
    except QhullError:
        return None


class ConstraintSet:
    """A Constraints message ready to decide states of ``scene``'s robot (its frames)."""

    def __init__(self, scene: PlanningScene, message: Constraints):
        if message.visibility_constraints:
            raise ConstraintError("visibility constraints are not provided here (only joint, "
                                  "position and orientation constraints)")
        self.scene = scene
        model = scene.model
        self.joints = []
        for joint in message.joint_constraints:
            bounds = model.bounds.get(joint.joint_name)
            if bounds is None:
                LOG.warning("joint constraint on '%s', which the robot lacks: left out",
                            joint.joint_name)
                continue
            continuous = not bounds.bounded
            target = normalize_angle(joint.position) if continuous else joint.position
            self.joints.append((joint.joint_name, target, abs(joint.tolerance_below),
                                abs(joint.tolerance_above), continuous))
        links = set(model.urdf.links)
        self.positions = []
        for constraint in message.position_constraints:
            regions = _regions(constraint) if constraint.link_name in links else []
            if constraint.link_name not in links:
                LOG.warning("position constraint on '%s', which the robot lacks: left out",
                            constraint.link_name)
                continue
            if not regions:
                LOG.warning("position constraint on '%s' has no region: left out",
                            constraint.link_name)
                continue
            offset = constraint.target_point_offset
            self.positions.append((constraint.link_name, constraint.header.frame_id,
                                   np.array([offset.x, offset.y, offset.z, 1.0]), regions))
        self.orientations = []
        for constraint in message.orientation_constraints:
            if constraint.link_name not in links:
                LOG.warning("orientation constraint on '%s', which the robot lacks: left out",
                            constraint.link_name)
                continue
            if constraint.parameterization not in (OrientationMsg.XYZ_EULER_ANGLES,
                                                   OrientationMsg.ROTATION_VECTOR):
                LOG.warning("orientation constraint on '%s': unknown parameterization %d: "
                            "left out", constraint.link_name, constraint.parameterization)
                continue
            rotation = pose_matrix(Pose(orientation=constraint.orientation),
                                   "orientation constraint")[:3, :3]
            tolerances = np.abs([constraint.absolute_x_axis_tolerance,
                                 constraint.absolute_y_axis_tolerance,
                                 constraint.absolute_z_axis_tolerance])
            self.orientations.append((constraint.link_name, constraint.header.frame_id,
                                      rotation, tolerances, constraint.parameterization))

        # an unknown frame is refused now rather than at the first state decided
        poses = model.link_poses(scene.positions)
        for _link, frame, *_rest in self.positions + self.orientations:
            self.frame(frame, poses)

    @property
    def empty(self) -> bool:
        return not (self.joints or self.positions or self.orientations)

    @property
    def needs_poses(self) -> bool:
        return bool(self.positions or self.orientations)

    def frame(self, frame: str, poses) -> np.ndarray:
        try:
            return self.scene.frame_pose(frame, poses)
        except SceneError as error:
            raise ConstraintError(str(error), MoveItErrorCodes.FRAME_TRANSFORM_FAILURE) from error

    def decide(self, positions: Mapping[str, float], poses=None) -> Optional[str]:
        """None when the state satisfies every constraint; else which one it breaks."""
        for name, target, below, above, continuous in self.joints:
            value = positions.get(name)
            if value is None:
                return f"joint '{name}' has no position"
            if continuous:
                difference = normalize_angle(value) - target
                if difference > math.pi:
                    difference = 2.0 * math.pi - difference
                elif difference < -math.pi:
                    difference += 2.0 * math.pi
            else:
                difference = value - target
            if not (-below - 2 * EPSILON <= difference <= above + 2 * EPSILON):
                return (f"joint '{name}' at {value:.4f} (wanted {target:.4f} -{below:g} "
                        f"+{above:g})")
        if not self.needs_poses:
            return None
        poses = poses if poses is not None else self.scene.model.link_poses(positions)
        for link, frame, offset, regions in self.positions:
            point = poses[link] @ offset
            local_frame = self.frame(frame, poses)
            inside = any(region.contains((np.linalg.inv(local_frame @ region.pose) @ point)[:3])
                         for region in regions)
            if not inside:
                return f"'{link}' at {np.round(point[:3], 4).tolist()} outside its region"
        for link, frame, rotation, tolerances, parameterization in self.orientations:
            target = self.frame(frame, poses)[:3, :3] @ rotation
            error = orientation_error(target.T @ poses[link][:3, :3], parameterization,
                                      tolerances[2])
            if not np.all(error < tolerances + EPSILON):
                return (f"'{link}' turned {np.round(error, 4).tolist()} rad from its target "
                        f"(tolerances {np.round(tolerances, 4).tolist()})")
        return None
