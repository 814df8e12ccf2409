"""Inertia tensors of solid shapes about their centre of mass (principal axes).

Each returns (ixx, iyy, izz) in kg m^2. The formulas are the standard ones for uniform
density; descriptions use them to write ``<inertia>`` and tests to check it.
"""
from __future__ import annotations

from typing import Tuple

Principal = Tuple[float, float, float]


def solid_box(mass: float, x: float, y: float, z: float) -> Principal:
    """Cuboid with edges x, y, z: ixx = m (y^2 + z^2) / 12, and so on."""
    return (mass * (y * y + z * z) / 12.0,
            mass * (x * x + z * z) / 12.0,
            mass * (x * x + y * y) / 12.0)


def solid_cylinder(mass: float, radius: float, length: float, axis: str = "z") -> Principal:
    """Cylinder: m (3 r^2 + h^2) / 12 across the axis, m r^2 / 2 about it."""
    across = mass * (3.0 * radius * radius + length * length) / 12.0
    about = mass * radius * radius / 2.0
    if axis == "x":
        return (about, across, across)
    if axis == "y":
        return (across, about, across)
    if axis == "z":
        return (across, across, about)
    raise ValueError(f"axis must be x, y or z, not {axis!r}")


def solid_sphere(mass: float, radius: float) -> Principal:
    """Sphere: 2 m r^2 / 5 about every axis."""
    moment = 2.0 * mass * radius * radius / 5.0
    return (moment, moment, moment)
