"""The table scene from config/scene.yaml, as planning-scene boxes, and pose helpers.
The same numbers place the objects in the simulation (worlds/arm_box.world is checked
against them by a description test)."""
from __future__ import annotations

from typing import Mapping, Tuple

import numpy as np

from arm_move.collision import Box, Scene

TABLE = "table"
REALSENSE_BOX = "realsense_box"
PICK_OBJECT = "pick_object"


def table_box(config: Mapping) -> Box:
    table = config["table"]
    return Box.upright(TABLE, table["center"], table["size"])


def pick_box(config: Mapping) -> Box:
    """The block the gripper picks up, standing on the table where the yaml puts it."""
    block = config[PICK_OBJECT]
    return Box.upright(PICK_OBJECT, block["position"], block["size"], block.get("yaw", 0.0))


def empty_scene(config: Mapping) -> Scene:
    """The scene before anything is added: only the floor, below the table top."""
    return Scene(floor_z=-float(config["table_height"]))


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


def world_scene(config: Mapping) -> Scene:
    """The scene as the world starts: the table, the block, and the RealSense box where the
    yaml puts it (the mover itself starts with the table and the block, and places the box
    on reset)."""
    scene = empty_scene(config)
    scene.add(table_box(config))
    scene.add(pick_box(config))
    box = config[REALSENSE_BOX]
    scene.add(Box.upright(REALSENSE_BOX, box["position"], box["size"], box["yaw"]))
    return scene
