"""The table scene from config/scene.yaml, as planning-scene boxes, and pose helpers.
The same numbers place the objects in the simulation (worlds/arm_box.world is checked
against them by a description test)."""
from __future__ import annotations

import math
from typing import Mapping, Sequence

import numpy as np

from arm_move.collision import Box, Scene

TABLE = "table"
REALSENSE_BOX = "realsense_box"


def table_box(config: Mapping) -> Box:
    table = config["table"]
    return Box.upright(TABLE, table["center"], table["size"])


def empty_scene(config: Mapping) -> Scene:
    """The scene before anything is added: only the floor, below the table top."""
    return Scene(floor_z=-float(config["table_height"]))


def quaternion_rotation(x: float, y: float, z: float, w: float) -> np.ndarray:
    """The rotation matrix of a quaternion; ValueError when it is not finite or has (nearly)
    no length."""
    q = np.array([x, y, z, w], dtype=float)
    if not np.all(np.isfinite(q)):
        raise ValueError(f"orientation {q.tolist()} is not finite")
    norm = float(np.linalg.norm(q))
    if norm < 1e-6:
        raise ValueError(f"orientation {q.tolist()} is a zero-length quaternion")
    x, y, z, w = q / norm
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def yaw_quaternion(yaw: float) -> Sequence[float]:
    return (0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2))
