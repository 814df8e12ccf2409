"""Pose arithmetic for the simulator: quaternions (x, y, z, w, as ROS and pybullet order
them), roll-pitch-yaw, and 6-number SDF poses, on tf.transformations. No pybullet, no rospy."""
from __future__ import annotations

import math
from typing import Sequence, Tuple

import numpy as np
from tf import transformations
from tf.transformations import euler_from_quaternion, quaternion_from_euler

from urdf_tools.kinematics import matrix_rpy, rpy_matrix

Vec3 = Tuple[float, float, float]
Quat = Tuple[float, float, float, float]


def quaternion_from_rpy(roll: float, pitch: float, yaw: float) -> Quat:
    return tuple(float(c) for c in quaternion_from_euler(roll, pitch, yaw))  # type: ignore[return-value]


def quaternion_matrix(q: Sequence[float]) -> np.ndarray:
    """The 3x3 rotation of a unit quaternion (x, y, z, w)."""
    return transformations.quaternion_matrix(q)[:3, :3]


def rpy_from_quaternion(q: Sequence[float]) -> Vec3:
    return euler_from_quaternion(q)


# tf.transformations' _EPS: below it a quaternion or a matrix column counts as zero
TF_EPSILON = float(np.finfo(float).eps) * 4.0


def yaw_from_quaternion(q: Sequence[float]) -> float:
    """``euler_from_quaternion(q)[2]`` (axes sxyz), tf.transformations' own steps written
    out in floats: tf builds a 4x4 matrix with numpy for it (8 us; 1 us here), and every
    odometry message needs a yaw. test_poses checks the two agree."""
    x, y, z, w = (float(c) for c in q[:4])
    norm = x * x + y * y + z * z + w * w
    if norm < TF_EPSILON:  # tf: no rotation
        return 0.0
    scale = math.sqrt(2.0 / norm)
    x, y, z, w = x * scale, y * scale, z * scale, w * scale
    m00 = 1.0 - y * y - z * z  # the rotation matrix's first column
    m10 = x * y + z * w
    if math.sqrt(m00 * m00 + m10 * m10) > TF_EPSILON:
        return math.atan2(m10, m00)
    return 0.0  # looking straight up or down: tf puts the turn into roll


def normalized(q: Sequence[float]) -> Quat:
    norm = math.sqrt(sum(c * c for c in q))
    if not math.isfinite(norm) or norm < 1e-9:
        raise ValueError(f"quaternion {tuple(q)} has no direction")
    return tuple(c / norm for c in q)  # type: ignore[return-value]


def pose6_matrix(pose: Sequence[float]) -> np.ndarray:
    transform = np.eye(4)
    transform[:3, :3] = rpy_matrix(*pose[3:6])
    transform[:3, 3] = pose[:3]
    return transform


def matrix_pose6(transform: np.ndarray) -> Tuple[float, ...]:
    return (*transform[:3, 3].tolist(), *matrix_rpy(transform[:3, :3]))


def compose6(outer: Sequence[float], inner: Sequence[float]) -> Tuple[float, ...]:
    """``inner`` (a pose in ``outer``'s frame) expressed in the frame ``outer`` is in."""
    return matrix_pose6(pose6_matrix(outer) @ pose6_matrix(inner))


def pose6_to_position_quaternion(pose: Sequence[float]) -> Tuple[Vec3, Quat]:
    return tuple(pose[:3]), quaternion_from_rpy(*pose[3:6])  # type: ignore[return-value]


def transform_point(position: Sequence[float], orientation: Sequence[float],
                    point: Sequence[float]) -> np.ndarray:
    return np.asarray(position) + quaternion_matrix(orientation) @ np.asarray(point)
