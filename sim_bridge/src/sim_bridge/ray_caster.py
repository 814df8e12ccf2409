"""Casting many rays against primitive shapes at once, with numpy.

pybullet's ``rayTestBatch`` costs grow with every object in the world (about 10 ms for
720 rays in a hall of 40 objects, whatever the collision filter), which would cap a
simulator with one laser at a few times real time. Lasers here are cast analytically
instead, against the exact shapes of the URDF and SDF (boxes, cylinders, spheres and
planes) and the convex hulls of moving bodies' collision meshes (as pybullet collides
them: :mod:`sim_bridge.convex_hulls`), all shapes and all rays in one vectorized pass
(about 1 ms for the same hall).

A :class:`Primitive` is a shape in the world: its kind, its world transform (4x4) and its
dimensions. Distances are along unit directions; a ray that starts inside a shape reads 0.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import List, Optional, Sequence

import numpy as np

KINDS = ("box", "cylinder", "sphere", "plane", "hull")
# a direction component smaller than this is treated as parallel to a face
PARALLEL = 1e-12
# a ray parallel to a face and this close outside its plane (m) touches it: a level beam at
# exactly a box's top (0.12 m up, the top at 0.1 + 0.04 / 2) lies a rounding error above or
# below it depending on the order of operations; the margin makes the answer the same
# whichever way it was worked out (the compiled kernel's too)
TOUCH = 1e-9


@dataclass
class Primitive:
    """``dims``: box (x, y, z) sizes; cylinder (radius, length) along local z; sphere
    (radius,); plane: none (the local z = 0 plane, normal +z); hull: (radius,), the
    bounding sphere's about the frame's origin, and ``planes`` (K, 4) in the shape's frame,
    n_x n_y n_z d (outward unit normal n, inside n.x <= d)."""

    kind: str
    transform: np.ndarray
    dims: Sequence[float] = ()
    planes: Optional[np.ndarray] = None


class ShapeSet:
    """Primitives stacked by kind, with bounding spheres, ready for :func:`cast`."""

    def __init__(self, primitives: Sequence[Primitive]):
        self.groups = {}
        # the hulls' planes, stacked; a hull's dims are (its first plane, how many)
        self.planes = np.zeros((0, 4))
        for kind in KINDS:
            chosen = [p for p in primitives if p.kind == kind]
            if not chosen:
                continue
            transforms = np.stack([p.transform for p in chosen])
            dims = (np.array([list(p.dims) for p in chosen], dtype=float)
                    if kind != "plane" else np.zeros((len(chosen), 1)))
            if kind == "hull":
                bound = dims[:, 0]
                counts = np.array([len(p.planes) for p in chosen])
                dims = np.column_stack([np.cumsum(counts) - counts, counts]).astype(float)
                self.planes = np.vstack([p.planes for p in chosen])
            elif kind == "box":
                bound = np.linalg.norm(dims, axis=1) / 2.0
            elif kind == "cylinder":
                bound = np.hypot(dims[:, 0], dims[:, 1] / 2.0)
            elif kind == "sphere":
                bound = dims[:, 0]
            else:
                bound = np.full(len(chosen), np.inf)  # planes are never culled
            self.groups[kind] = (transforms[:, :3, 3], transforms[:, :3, :3], dims, bound)

    def __len__(self):
        return sum(len(group[0]) for group in self.groups.values())


def _candidates(centres, bounds, origins, directions, origin_dot_direction, origin_norm2):
    """(shape, ray) index pairs whose ray passes within the shape's bounding sphere, ahead."""
    # (K, 3) x (3, N) as three broadcast products: twice as fast as matmul for this shape
    along = sum(centres[:, i, None] * directions[None, :, i] for i in range(3)) \
        - origin_dot_direction[None, :]
    centre_dot_origin = sum(centres[:, i, None] * origins[None, :, i] for i in range(3))
    centre_norm2 = (centres * centres).sum(axis=1)
    distance2 = centre_norm2[:, None] - 2.0 * centre_dot_origin + origin_norm2[None, :]
    miss2 = distance2 - along * along
    close = (miss2 <= (bounds * bounds)[:, None]) & (along >= -bounds[:, None])
    return np.nonzero(close)


def _local(centres, rotations, origins, directions):
    """Ray origins and directions in their shape's frame (one shape per ray): (M, 3) each."""
    # v_local[i] = sum_j v[j] R[j, i] (einsum: 2x faster than M tiny matmuls here)
    local_origins = np.einsum("mj,mji->mi", origins - centres, rotations)
    local_directions = np.einsum("mj,mji->mi", directions, rotations)
    return local_origins, local_directions


def _boxes(o, d, dims):
    half = dims / 2.0
    # A ray parallel to a pair of faces is between them all along, or never: dividing by a
    # stand-in for its tiny direction component instead made a ray a rounding error inside
    # a face's plane leave the slab at once (a level beam at exactly a box's top missed it,
    # one at exactly its bottom hit it).
    parallel = np.abs(d) < PARALLEL
    inverse = 1.0 / np.where(parallel, 1.0, d)
    within = np.abs(o) <= half + TOUCH
    t1 = (-half - o) * inverse
    t2 = (half - o) * inverse
    enter = np.where(parallel, np.where(within, -np.inf, np.inf), np.minimum(t1, t2))
    leave = np.where(parallel, np.where(within, np.inf, -np.inf), np.maximum(t1, t2))
    near = enter.max(axis=1)
    far = leave.min(axis=1)
    hit = (far >= near) & (far >= 0.0)
    return np.where(hit, np.maximum(near, 0.0), np.inf)


def _quadratic_entry(a, b, c):
    """Smallest t >= 0 of a t^2 + 2 b t + c = 0, 0 when inside (c <= 0), else inf."""
    disc = b * b - a * c
    root = np.sqrt(np.maximum(disc, 0.0))
    entry = (-b - root) / a
    exit_ = (-b + root) / a
    t = np.where(entry >= 0.0, entry, np.where(exit_ >= 0.0, 0.0, np.inf))
    return np.where(disc >= 0.0, t, np.inf)


def _cylinders(o, d, dims):
    radius, half = dims[:, 0], dims[:, 1] / 2.0
    ox, oy, oz = o[:, 0], o[:, 1], o[:, 2]
    dx, dy, dz = d[:, 0], d[:, 1], d[:, 2]
    a = np.maximum(dx * dx + dy * dy, PARALLEL)
    side = _quadratic_entry(a, ox * dx + oy * dy, ox * ox + oy * oy - radius * radius)
    limit = half + np.where(np.abs(dz) < PARALLEL, TOUCH, 0.0)
    best = np.where(np.abs(oz + side * dz) <= limit, side, np.inf)
    for cap in (-half, half):
        t = (cap - oz) / dz
        x, y = ox + t * dx, oy + t * dy
        best = np.minimum(best, np.where((t >= 0.0) & (x * x + y * y <= radius * radius),
                                         t, np.inf))
    inside = (ox * ox + oy * oy <= radius * radius) & (np.abs(oz) <= limit)
    return np.where(inside, 0.0, best)


def _spheres(o, d, dims):
    b = (o * d).sum(axis=1)
    c = (o * o).sum(axis=1) - dims[:, 0] ** 2
    return _quadratic_entry(np.ones_like(b), b, c)


def _planes(o, d, _dims):
    heights, rates = o[:, 2], d[:, 2]
    t = -heights / rates
    return np.where(heights <= 0.0, 0.0, np.where(t >= 0.0, t, np.inf))


def _hulls(o, d, dims, planes):
    """Each ray clipped by each plane of its hull (Cyrus-Beck), as _boxes does by slabs."""
    first, count = dims[:, 0].astype(int), dims[:, 1].astype(int)
    starts = np.cumsum(count) - count  # each ray's first entry below
    ray = np.repeat(np.arange(len(o)), count)
    plane = planes[np.repeat(first - starts, count) + np.arange(count.sum())]
    rate = (plane[:, :3] * d[ray]).sum(axis=1)
    gap = plane[:, 3] - (plane[:, :3] * o[ray]).sum(axis=1)
    parallel = np.abs(rate) < PARALLEL
    t = gap / np.where(parallel, 1.0, rate)
    within = gap >= -TOUCH
    enter = np.where(parallel, np.where(within, -np.inf, np.inf),
                     np.where(rate < 0.0, t, -np.inf))
    leave = np.where(parallel, np.where(within, np.inf, -np.inf),
                     np.where(rate > 0.0, t, np.inf))
    near = np.maximum.reduceat(enter, starts)
    far = np.minimum.reduceat(leave, starts)
    hit = (far >= near) & (far >= 0.0)
    return np.where(hit, np.maximum(near, 0.0), np.inf)


_SOLVERS = {"box": _boxes, "cylinder": _cylinders, "sphere": _spheres, "plane": _planes}


def cast(shape_sets: Sequence[ShapeSet], origins: np.ndarray,
         directions: np.ndarray) -> np.ndarray:
    """Distance along each ray to the nearest shape of any set (inf: none)."""
    origins = np.asarray(origins, dtype=float)
    directions = np.asarray(directions, dtype=float)
    distances = np.full(len(directions), np.inf)
    origin_dot_direction = (origins * directions).sum(axis=1)
    origin_norm2 = (origins * origins).sum(axis=1)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        for shapes in shape_sets:
            for kind, (centres, rotations, dims, bounds) in shapes.groups.items():
                if kind == "plane":
                    shape_index, ray_index = np.nonzero(np.ones((len(centres), len(origins)),
                                                                dtype=bool))
                else:
                    shape_index, ray_index = _candidates(centres, bounds, origins, directions,
                                                         origin_dot_direction, origin_norm2)
                if len(ray_index) == 0:
                    continue
                o, d = _local(centres[shape_index], rotations[shape_index],
                              origins[ray_index], directions[ray_index])
                if kind == "hull":
                    found = _hulls(o, d, dims[shape_index], shapes.planes)
                else:
                    found = _SOLVERS[kind](o, d, dims[shape_index])
                np.minimum.at(distances, ray_index, found)
    return distances


def primitive_for(kind: str, transform: np.ndarray, size=None, radius=None,
                  length=None, planes=None) -> Primitive:
    """A Primitive from URDF/SDF dimensions (a hull: its planes and bounding radius)."""
    if kind == "box":
        return Primitive("box", transform, tuple(size))
    if kind == "cylinder":
        return Primitive("cylinder", transform, (radius, length))
    if kind == "sphere":
        return Primitive("sphere", transform, (radius,))
    if kind == "plane":
        return Primitive("plane", transform)
    if kind == "hull":
        return Primitive("hull", transform, (radius,), np.asarray(planes, dtype=float))
    raise ValueError(f"no analytic ray casting for {kind}")


__all__: List[str] = ["Primitive", "ShapeSet", "cast", "primitive_for"]
