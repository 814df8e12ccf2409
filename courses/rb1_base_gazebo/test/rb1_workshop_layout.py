"""The RB1 warehouse as rb1_base_gazebo's tests see it: where the course puts the robot, the
taped start square, and the world read with sim_bridge's loader, its models found as
gazebo_ros finds them (the folders packages export as gazebo_model_path)."""
from __future__ import annotations

import math
import os
import subprocess
from dataclasses import dataclass
from typing import Dict, List, Tuple

import numpy as np

PACKAGE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
WORLD = os.path.join(PACKAGE, "worlds", "ros2_online_workshop.world")
MODELS = os.path.join(PACKAGE, "models")

# Where the course's launch files spawn the robot (students' my_rb1_robot_warehouse.launch:
# x -0.5 to -0.3, y -1.5 to -1.3), heading +x.
START = (-0.4, -1.35)
# The taped start square's inside (the tape's inner edges; the west side is the wall's face).
SQUARE = {"x_min": -0.896, "x_max": 0.028, "y_min": -1.712, "y_max": -0.933}
# The RB1 is a cylinder 0.5 m across; sim_bridge's test robot (diff_bot) a 0.4 x 0.3 m box
# with its wheels inside that box's half-diagonal: turning in place, each sweeps a disc.
RB1_RADIUS = 0.25
DIFF_BOT_HALF_DIAGONAL = math.hypot(0.4 / 2, 0.3 / 2)
SWEEP_RADIUS = max(RB1_RADIUS, DIFF_BOT_HALF_DIAGONAL)
# Heights a robot on the floor occupies or scans at (m): lasers at 0.16 (diff_bot) to about
# 0.3 (the RB1's, on top of its 0.3 m body).
ROBOT_HEIGHT = 0.4


def exported_model_folders() -> List[str]:
    """gazebo_model_path as packages export it to gazebo_ros (what gzserver adds to
    GAZEBO_MODEL_PATH), by rospack."""
    listed = subprocess.run(["rospack", "plugins", "--attrib=gazebo_model_path", "gazebo_ros"],
                            capture_output=True, text=True, timeout=60, check=False)
    folders = []
    for line in listed.stdout.splitlines():
        _package, _, folder = line.partition(" ")
        folders.extend(f for f in folder.strip().split(os.pathsep) if f)
    return folders


def load():
    """The world as sim_bridge loads it under gazebo_ros (sim_bridge.sdf_world.load_world)."""
    from sim_bridge.sdf_world import load_world
    previous = os.environ.get("GAZEBO_MODEL_PATH")
    os.environ["GAZEBO_MODEL_PATH"] = os.pathsep.join(
        [p for p in (previous or "").split(os.pathsep) if p] + exported_model_folders())
    try:
        return load_world(WORLD)
    finally:
        if previous is None:
            del os.environ["GAZEBO_MODEL_PATH"]
        else:
            os.environ["GAZEBO_MODEL_PATH"] = previous


@dataclass
class Solid:
    """A collision shape seen from above: a box (half sizes, yaw) or an upright cylinder."""

    model: str
    kind: str
    centre: Tuple[float, float]
    half: Tuple[float, float]  # box: half sizes along its axes; cylinder: (radius, radius)
    yaw: float
    z_min: float
    z_max: float

    def distance(self, x: float, y: float) -> float:
        """From the point to the footprint (0 inside)."""
        dx, dy = x - self.centre[0], y - self.centre[1]
        if self.kind == "cylinder":
            return max(math.hypot(dx, dy) - self.half[0], 0.0)
        c, s = math.cos(self.yaw), math.sin(self.yaw)
        u, v = c * dx + s * dy, -s * dx + c * dy
        return math.hypot(max(abs(u) - self.half[0], 0.0), max(abs(v) - self.half[1], 0.0))


def placed(model, link, shape) -> np.ndarray:
    from sim_bridge.poses import compose6, pose6_matrix
    return pose6_matrix(compose6(compose6(model.pose, link.pose), shape.pose))


def solids(world) -> List[Solid]:
    """Every collision shape but the ground plane, as footprints. Refuses what it cannot
    see exactly from above (a mesh, a tilted shape), so that no obstacle goes unchecked."""
    found = []
    for model in world.models:
        for link in model.links:
            for shape in link.collisions:
                if shape.kind == "plane":
                    continue
                matrix = placed(model, link, shape)
                assert shape.kind in ("box", "cylinder"), \
                    f"{model.name}: a {shape.kind} collision; these checks read boxes and cylinders"
                assert abs(matrix[2, 2] - 1.0) < 1e-9, f"{model.name}: a tilted {shape.kind}"
                x, y, z = matrix[:3, 3]
                yaw = math.atan2(matrix[1, 0], matrix[0, 0])
                if shape.kind == "box":
                    half, height = (shape.size[0] / 2, shape.size[1] / 2), shape.size[2]
                else:
                    half, height = (shape.radius, shape.radius), shape.length
                found.append(Solid(model.name, shape.kind, (x, y), half, yaw,
                                   z - height / 2, z + height / 2))
    return found


def in_robot_band(solid: Solid) -> bool:
    return solid.z_max > 0.005 and solid.z_min < ROBOT_HEIGHT


def clearance(solid_list: List[Solid], points) -> Dict[str, float]:
    """The least distance from the points to each model's footprints (robot-height band)."""
    nearest: Dict[str, float] = {}
    for solid in solid_list:
        if not in_robot_band(solid):
            continue
        d = min(solid.distance(x, y) for x, y in points)
        nearest[solid.model] = min(d, nearest.get(solid.model, math.inf))
    return nearest
