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
- :func:`hull_planes`: the planes of a point cloud's hull: an incremental hull over the
  points (numpy; no qhull in the environment: trimesh's hull needs scipy), coplanar
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

# Points this far (relative to the cloud's extent) off a face's plane count as on it: the
# float rounding of the OBJ's 9 digits, far below what a laser resolves (1e-9 of a 1 m
# mesh: a nanometre).
RELATIVE_TOLERANCE = 1e-9
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
    (N, 3), coplanar faces merged; None when the hull has no volume."""
    points = np.unique(np.asarray(points, dtype=float).reshape(-1, 3), axis=0)
    if len(points) < 4:
        return None
    extent = float(np.max(points.max(axis=0) - points.min(axis=0)))
    tolerance = RELATIVE_TOLERANCE * max(extent, 1.0)
    simplex = _initial_simplex(points, tolerance)
    if simplex is None:
        return None
    faces = _hull_faces(points, simplex, tolerance)
    corners = points[np.unique(np.array(faces))]
    normals = _merged(np.array([_plane(points, face)[0] for face in faces]))
    return np.column_stack([normals, _support(corners, normals)])


def _initial_simplex(points: np.ndarray, tolerance: float) -> Optional[List[int]]:
    """Four points spanning a volume (extremes of the cloud), or None when it is flat."""
    first = int(np.argmin(points[:, 0]))
    distances = np.linalg.norm(points - points[first], axis=1)
    second = int(np.argmax(distances))
    if distances[second] <= tolerance:
        return None
    axis = (points[second] - points[first]) / distances[second]
    relative = points - points[first]
    off_line = np.linalg.norm(relative - np.outer(relative @ axis, axis), axis=1)
    third = int(np.argmax(off_line))
    if off_line[third] <= tolerance:
        return None
    normal = np.cross(points[second] - points[first], points[third] - points[first])
    normal /= np.linalg.norm(normal)
    heights = relative @ normal
    fourth = int(np.argmax(np.abs(heights)))
    if abs(heights[fourth]) <= tolerance:
        return None
    return [first, second, third, fourth]


def _plane(points: np.ndarray, face: Tuple[int, int, int]) -> Tuple[np.ndarray, float]:
    a, b, c = (points[i] for i in face)
    normal = np.cross(b - a, c - a)
    normal /= np.linalg.norm(normal)
    return normal, float(normal @ a)


def _hull_faces(points: np.ndarray, simplex: List[int],
                tolerance: float) -> List[Tuple[int, int, int]]:
    """The hull's triangles, each wound outward: the tetrahedron, then every point outside
    the current hull replaces the faces it sees by a fan from the horizon to itself. Points
    are taken farthest from the centre first, so that most of the rest fall inside early."""
    inside_point = points[simplex].mean(axis=0)
    faces: List[Tuple[int, int, int]] = []
    for a, b, c in ((0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3)):
        face = (simplex[a], simplex[b], simplex[c])
        normal, offset = _plane(points, face)
        if normal @ inside_point > offset:  # wound inward: turn it
            face = (face[0], face[2], face[1])
        faces.append(face)
    normals = np.array([_plane(points, f)[0] for f in faces])
    offsets = np.array([_plane(points, f)[1] for f in faces])
    alive = np.ones(len(faces), dtype=bool)
    order = np.argsort(-np.linalg.norm(points - inside_point, axis=1), kind="stable")
    order = order[~np.isin(order, simplex)]
    for start in range(0, len(order), BATCH):
        batch = order[start:start + BATCH]
        # the batch's points inside the hull so far, in one product, are passed over
        live = np.nonzero(alive)[0]
        outside = ((points[batch] @ normals[live].T - offsets[live]) > tolerance).any(axis=1)
        for index in batch[outside]:
            point = points[index]
            live = np.nonzero(alive)[0]
            visible = live[normals[live] @ point - offsets[live] > tolerance]
            if not len(visible):
                continue
            edges = set()
            for face_index in visible:
                a, b, c = faces[face_index]
                edges.update(((a, b), (b, c), (c, a)))
            horizon = [edge for edge in edges if (edge[1], edge[0]) not in edges]
            alive[visible] = False
            new = [(a, b, int(index)) for a, b in horizon]
            planes = [_plane(points, face) for face in new]
            faces.extend(new)
            normals = np.vstack([normals, [n for n, _ in planes]])
            offsets = np.concatenate([offsets, [d for _, d in planes]])
            alive = np.concatenate([alive, np.ones(len(new), dtype=bool)])
    return [face for face, kept in zip(faces, alive) if kept]


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
