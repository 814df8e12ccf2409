"""The arm's table scene from config/scene.yaml: the collision objects the mover gives
MoveIt's planning scene, and where the RealSense box may be put.

The same numbers place the objects in the simulation (worlds/arm_box.world: the arm stands
at the world's origin on the table top, so the world's frame and the arm's base frame
coincide; a test compares the two files)."""
from __future__ import annotations

from typing import Mapping, Optional, Sequence, Tuple

import numpy as np
import tf.transformations as tft
from geometry_msgs.msg import PoseStamped

TABLE = "table"
REALSENSE_BOX = "realsense_box"
PICK_OBJECT = "pick_object"


def pose_stamped(frame: str, position: Sequence[float],
                 orientation: Sequence[float] = (0.0, 0.0, 0.0, 1.0)) -> PoseStamped:
    """A PoseStamped; ``orientation`` as x, y, z, w."""
    pose = PoseStamped()
    pose.header.frame_id = frame
    pose.pose.position.x, pose.pose.position.y, pose.pose.position.z = map(float, position)
    o = pose.pose.orientation
    o.x, o.y, o.z, o.w = map(float, orientation)
    return pose


def yaw_quaternion(yaw: float) -> Tuple[float, ...]:
    return tuple(tft.quaternion_from_euler(0.0, 0.0, yaw))


def unit_quaternion(x: float, y: float, z: float, w: float) -> Tuple[float, ...]:
    """The quaternion made unit length; ValueError when it is not finite or has (nearly)
    no length."""
    q = np.array([x, y, z, w], dtype=float)
    if not np.all(np.isfinite(q)):
        raise ValueError(f"orientation {q.tolist()} is not finite")
    norm = float(np.linalg.norm(q))
    if norm < 1e-6:
        raise ValueError(f"orientation {q.tolist()} is a zero-length quaternion")
    return tuple(float(c) for c in q / norm)


def half_extents(size: Sequence[float], orientation: Sequence[float]) -> np.ndarray:
    """Half the size of the axis-aligned box around a box of ``size`` turned by
    ``orientation``."""
    rotation = tft.quaternion_matrix(orientation)[:3, :3]
    return np.abs(rotation) @ (np.asarray(size, dtype=float) / 2)


def floor_height(config: Mapping) -> float:
    """The floor's height in the arm's frame: the table's height below its top."""
    return -float(config["table_height"])


def placement_problem(config: Mapping, position: Sequence[float],
                      orientation: Sequence[float],
                      others: Mapping[str, Tuple[Sequence[float], Sequence[float]]]
                      ) -> Optional[str]:
    """What a RealSense box at this pose would be in: "floor" (it reaches below it),
    "table" (it sinks into its top by more than ``contact_tolerance``) or the name of one of
    ``others`` (name -> (centre, size) of upright boxes) whose space it shares; None when it
    is free. Resting on the table is free. Boxes are compared by the upright boxes around
    them (a turned box near another is refused a little early)."""
    tolerance = float(config["contact_tolerance"])
    centre = np.asarray(position, dtype=float)
    half = half_extents(config[REALSENSE_BOX]["size"], orientation)
    low, high = centre - half, centre + half
    if low[2] < floor_height(config) - tolerance:
        return "floor"
    table = config[TABLE]
    table_half = np.asarray(table["size"], dtype=float) / 2
    table_centre = np.asarray(table["center"], dtype=float)
    if _overlap(low, high, table_centre - table_half, table_centre + table_half, tolerance):
        return "table"
    for name, (other_centre, other_size) in others.items():
        other_half = np.asarray(other_size, dtype=float) / 2
        other_centre = np.asarray(other_centre, dtype=float)
        if _overlap(low, high, other_centre - other_half, other_centre + other_half, tolerance):
            return name
    return None


def _overlap(low_a, high_a, low_b, high_b, tolerance: float) -> bool:
    """Whether two axis-aligned boxes share more than ``tolerance`` along every axis."""
    return bool(np.all(np.minimum(high_a, high_b) - np.maximum(low_a, low_b) > tolerance))
