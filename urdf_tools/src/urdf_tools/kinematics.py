"""Homogeneous transforms along a URDF's kinematic tree (REP 103 roll-pitch-yaw).

Used to say where a link is relative to another for given joint positions: the
description tests compare this with what robot_state_publisher broadcasts, and the arm
planner uses it as forward kinematics.
"""
from __future__ import annotations

from typing import Mapping, Optional, Sequence, Tuple

import numpy as np
from tf.transformations import euler_from_matrix, euler_matrix, rotation_matrix

from urdf_tools.model import Joint, Origin, RobotModel


def rpy_matrix(roll: float, pitch: float, yaw: float) -> np.ndarray:
    """Rotation of URDF's fixed-axis roll-pitch-yaw: R = Rz(yaw) Ry(pitch) Rx(roll)."""
    return euler_matrix(roll, pitch, yaw)[:3, :3]


def matrix_rpy(rotation: np.ndarray) -> Tuple[float, float, float]:
    """Roll, pitch, yaw of a rotation matrix (inverse of :func:`rpy_matrix`)."""
    return euler_from_matrix(rotation)


def axis_angle_matrix(axis: Sequence[float], angle: float) -> np.ndarray:
    """Rotation by ``angle`` about ``axis`` (any length but zero)."""
    return rotation_matrix(angle, axis)[:3, :3]


def origin_transform(origin: Origin) -> np.ndarray:
    transform = np.eye(4)
    transform[:3, :3] = rpy_matrix(*origin.rpy)
    transform[:3, 3] = origin.xyz
    return transform


def joint_transform(joint: Joint, position: float = 0.0) -> np.ndarray:
    """Parent link frame to child link frame with the joint at ``position`` (rad or m)."""
    transform = origin_transform(joint.origin)
    motion = np.eye(4)
    if joint.type in ("revolute", "continuous"):
        motion[:3, :3] = axis_angle_matrix(joint.axis, position)
    elif joint.type == "prismatic":
        motion[:3, 3] = np.asarray(joint.axis, dtype=float) * position
    return transform @ motion


def link_transform(model: RobotModel, base: str, tip: str,
                   positions: Optional[Mapping[str, float]] = None) -> np.ndarray:
    """Pose of ``tip`` in the frame of ``base`` (an ancestor), joints at ``positions``
    (by joint name; missing joints at 0)."""
    positions = positions or {}
    transform = np.eye(4)
    for joint in model.chain(base, tip):
        transform = transform @ joint_transform(joint, positions.get(joint.name, 0.0))
    return transform
