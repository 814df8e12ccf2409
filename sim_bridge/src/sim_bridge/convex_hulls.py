"""Convex hulls of collision meshes as sets of planes, for the lasers' kernel.

A moving body's collision mesh collides in pybullet as the convex hull of each of its
objects (see :mod:`sim_bridge.mesh_files`). pybullet's ray test against such a hull runs
its GJK solver, about 18 us a ray (a 720-beam scan beside two construction cones: 0.7 ms,
0.07 without them). A convex polyhedron is the intersection of the half-spaces of its
faces, so a ray against it is a few multiplications a face (Cyrus-Beck clipping, in
``ray_kernel.c`` and the numpy reference :mod:`sim_bridge.ray_caster`): here each hull is
turned into those planes once, when its body spawns.

- :func:`mesh_hulls`: the hulls of a mesh file pybullet loads (an OBJ: one per object,
  ``o`` or ``g``, of the vertices its faces use, as pybullet's OBJ reader groups them; a
  binary STL: one), scaled, each as outward unit normals n and offsets d (inside: n.x <= d)
  about the centre of its bounding sphere; cached per file and scale;
- :func:`hull_planes`: the planes of a point cloud's hull: qhull's (scipy), coplanar
  triangles merged into one plane.

A hull with no volume (the points on a plane or a line) gives no planes: the caller keeps
such a mesh in pybullet's hands.
"""
from __future__ import annotations

import os
from dataclasses import dataclass
from typing import Dict, List, Optional, Sequence, Tuple

import numpy as np

from sim_bridge.mesh_files import stl_vertices

# Two triangles whose unit normals differ by less than this (rad) are one face: a cube's 12
# triangles become its 6 planes, a cone's frustum's 96 its 50 (the OBJ's 9 digits turn
# the normals of a flat quad's two triangles up to about 1e-8 apart). The plane is put
# through the farthest vertex along the kept normal, so the hull grows by at most this
# times its size (a micrometre on a metre).
COPLANAR_NORMAL = 1e-6
# points tested against the hull in one product (bounds the memory: BATCH x faces)
BATCH = 256


@dataclass(frozen=True)
class Hull:
    """One convex hull in the mesh's frame: ``planes`` (K, 4) rows n_x n_y n_z d about
    ``centre`` (inside: n.(x - centre) <= d), every vertex within ``radius`` of it."""

    centre: np.ndarray
    planes: np.ndarray
    radius: float


def hull_planes(points: np.ndarray) -> Optional[np.ndarray]:
    """The planes (K, 4: unit outward normal, offset) of the convex hull of ``points``
    (N, 3), coplanar faces merged; None when the hull has no volume. The hull is qhull's
    (scipy.spatial.ConvexHull), whose facets' ``equations`` are the outward unit normals
    and the offsets' negatives."""
    from scipy.spatial import ConvexHull, QhullError
    points = np.unique(np.asarray(points, dtype=float).reshape(-1, 3), axis=0)
    if len(points) < 4:
        return None
    try:
        hull = ConvexHull(points)
    except QhullError:  # flat or on a line: no volume
        return None
    corners = points[hull.vertices]
    normals = _merged(hull.equations[:, :3])
    return np.column_stack([normals, _support(corners, normals)])


def _merged(normals: np.ndarray) -> np.ndarray:
    """One normal for each set of faces whose normals agree to COPLANAR_NORMAL (a convex
    hull has one face a direction; two faces that round apart stay two planes, which costs
    the cast a few multiplications, not a wrong answer)."""
    _, first = np.unique(np.round(normals / COPLANAR_NORMAL), axis=0, return_index=True)
    return normals[np.sort(first)]


def _support(corners: np.ndarray, normals: np.ndarray) -> np.ndarray:
    """Each plane's offset, through the farthest corner along its normal: no vertex lies
    outside its plane, whatever the rounding of a sliver triangle's normal or the merging."""
    offsets = np.full(len(normals), -np.inf)
    for start in range(0, len(corners), BATCH):
        offsets = np.maximum(offsets, (corners[start:start + BATCH] @ normals.T).max(axis=0))
    return offsets


def object_points(path: str) -> List[np.ndarray]:
    """The vertex sets pybullet makes one hull each of: an OBJ file's objects (``o`` and
    ``g`` start one; the vertices its faces use), a binary STL's vertices."""
    if path.lower().endswith(".stl"):
        return [stl_vertices(path)]
    vertices: List[List[float]] = []
    groups: List[List[int]] = [[]]
    with open(path, "rb") as stream:
        for line in stream:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == b"v" and len(parts) >= 4:
                vertices.append([float(v) for v in parts[1:4]])
            elif parts[0] in (b"o", b"g"):
                if groups[-1]:
                    groups.append([])
            elif parts[0] == b"f":
                for corner in parts[1:]:
                    number = int(corner.split(b"/")[0])
                    # OBJ counts from 1; negative: back from the last vertex read
                    groups[-1].append(number - 1 if number > 0 else len(vertices) + number)
    table = np.asarray(vertices, dtype=float).reshape(-1, 3)
    return [table[np.unique(group)] for group in groups if group]


_cache: Dict[Tuple[str, int, int, Tuple[float, ...]], Tuple[List[Hull], int]] = {}


def mesh_hulls(path: str, scale: Sequence[float] = (1.0, 1.0, 1.0)) -> Tuple[List[Hull], int]:
    """(the hulls of the mesh file ``path`` pybullet loads, scaled by ``scale``; how many of
    its objects have no volume and no hull here). Cached per file (path, size, time) and
    scale: a robot's links spawn many times."""
    status = os.stat(path)
    key = (os.path.realpath(path), status.st_size, status.st_mtime_ns,
           tuple(float(s) for s in scale))
    if key not in _cache:
        hulls, flat = [], 0
        for points in object_points(path):
            points = points * np.asarray(scale, dtype=float)
            planes = hull_planes(points)
            if planes is None:
                flat += 1
                continue
            centre = (points.min(axis=0) + points.max(axis=0)) / 2.0
            radius = float(np.linalg.norm(points - centre, axis=1).max())
            planes = planes.copy()
            planes[:, 3] -= planes[:, :3] @ centre
            hulls.append(Hull(centre, planes, radius))
        _cache[key] = (hulls, flat)
    return _cache[key]


__all__ = ["Hull", "hull_planes", "mesh_hulls", "object_points"]
