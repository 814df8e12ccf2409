"""Pose arithmetic for the simulator: quaternions (x, y, z, w, as ROS and pybullet order
them), roll-pitch-yaw, and 6-number SDF poses. No pybullet, no rospy."""
from __future__ import annotations

import math
from typing import Sequence, Tuple

import numpy as np

from urdf_tools.kinematics import matrix_rpy, rpy_matrix

Vec3 = Tuple[float, float, float]
Quat = Tuple[float, float, float, float]


def quaternion_from_rpy(roll: float, pitch: float, yaw: float) -> Quat:
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return (sr * cp * cy - cr * sp * sy,
            cr * sp * cy + sr * cp * sy,
            cr * cp * sy - sr * sp * cy,
            cr * cp * cy + sr * sp * sy)


def quaternion_matrix(q: Sequence[float]) -> np.ndarray:
    x, y, z, w = q
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
    ])


def rpy_from_quaternion(q: Sequence[float]) -> Vec3:
    return matrix_rpy(quaternion_matrix(q))


def yaw_from_quaternion(q: Sequence[float]) -> float:
    x, y, z, w = q
    return math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))


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
