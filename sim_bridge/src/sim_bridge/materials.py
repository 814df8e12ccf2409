"""Gazebo's named materials (``Gazebo/Black``...) as RGBA colours.

The diffuse colours of gazebo's ``gazebo.material`` script for the names course files use;
an unknown name falls back to a neutral grey (the caller warns).
"""
from typing import Optional, Tuple

RGBA = Tuple[float, float, float, float]

GAZEBO_MATERIALS = {
    "Gazebo/Black": (0.0, 0.0, 0.0, 1.0),
    "Gazebo/White": (1.0, 1.0, 1.0, 1.0),
    "Gazebo/Grey": (0.7, 0.7, 0.7, 1.0),
    "Gazebo/Gray": (0.7, 0.7, 0.7, 1.0),
    "Gazebo/DarkGrey": (0.175, 0.175, 0.175, 1.0),
    "Gazebo/LightGrey": (0.9, 0.9, 0.9, 1.0),
    "Gazebo/Red": (1.0, 0.0, 0.0, 1.0),
    "Gazebo/RedBright": (0.87, 0.26, 0.07, 1.0),
    "Gazebo/Green": (0.0, 1.0, 0.0, 1.0),
    "Gazebo/Blue": (0.0, 0.0, 1.0, 1.0),
    "Gazebo/SkyBlue": (0.53, 0.81, 0.92, 1.0),
    "Gazebo/Yellow": (1.0, 1.0, 0.0, 1.0),
    "Gazebo/Orange": (1.0, 0.5088, 0.0468, 1.0),
    "Gazebo/Purple": (1.0, 0.0, 1.0, 1.0),
    "Gazebo/Turquoise": (0.0, 1.0, 1.0, 1.0),
    "Gazebo/Gold": (0.8, 0.64, 0.0, 1.0),
    "Gazebo/Wood": (0.6, 0.4, 0.2, 1.0),
    "Gazebo/WoodPallet": (0.72, 0.56, 0.36, 1.0),
    "Gazebo/Bricks": (0.6, 0.3, 0.2, 1.0),
    "Gazebo/Road": (0.25, 0.25, 0.25, 1.0),
    "Gazebo/Residential": (0.7, 0.6, 0.5, 1.0),
    "Gazebo/Asphalt": (0.2, 0.2, 0.22, 1.0),
    "Gazebo/CeilingTiled": (0.95, 0.95, 0.95, 1.0),
    "Gazebo/PaintedWall": (0.9, 0.88, 0.82, 1.0),
    "Gazebo/ZincYellow": (0.97, 0.87, 0.19, 1.0),
    "Gazebo/DarkYellow": (0.7, 0.7, 0.0, 1.0),
    "Gazebo/FlatBlack": (0.1, 0.1, 0.1, 1.0),
    "Gazebo/Indigo": (0.33, 0.0, 0.5, 1.0),
    "Gazebo/BlueTransparent": (0.0, 0.0, 1.0, 0.5),
    "Gazebo/GreenTransparent": (0.0, 1.0, 0.0, 0.5),
    "Gazebo/RedTransparent": (1.0, 0.0, 0.0, 0.5),
}
UNKNOWN = (0.6, 0.6, 0.6, 1.0)


def gazebo_colour(name: str) -> Optional[RGBA]:
    """The RGBA of a Gazebo material name, or None when it is not known."""
    return GAZEBO_MATERIALS.get(name.strip())
