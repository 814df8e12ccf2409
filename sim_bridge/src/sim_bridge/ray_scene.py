"""What lasers see, kept between scans: the scene's shapes as the ray kernel's rows.

Before, every scan of every laser re-placed every moving shape of every robot (a Python
object per shape) and cast all rays against all shapes in numpy: the placing grew with
the square of the number of robots, and the cast cost 2 ms for 720 beams. Here:

- static shapes are packed once, when the scene changes (the world drops this object);
- moving shapes (robots' and free bodies' collision shapes) are re-placed at most once
  per simulated time stamp, by the first scan that needs them; every other laser cast at
  the same stamp uses the same rows. A pose set between steps (set_state, a reset) makes
  the world call :meth:`RayScene.poses_changed`;
- one robot's shapes are placed with one pybullet call for its links' frames and a few
  array operations (:class:`sim_bridge.ray_kernel.PlacedShapes`);
- the rays are cast by the compiled kernel (:mod:`sim_bridge.ray_kernel`), or, when it was
  not built, by the numpy reference on the same rows (one warning says so).
"""
from __future__ import annotations

from typing import List, Optional, Sequence, Tuple

import numpy as np
import pybullet as pb

from sim_bridge import ray_kernel
from sim_bridge.ray_caster import ShapeSet, cast
from sim_bridge.ray_kernel import BOUND, CENTRE, DIMS, KIND, KIND_CODES, ROTATION, STRIDE

_KIND_NAMES = {code: kind for kind, code in KIND_CODES.items()}


def frames_from_poses(positions: Sequence[Sequence[float]],
                      quaternions: Sequence[Sequence[float]]) -> np.ndarray:
    """(F, 4, 4) transforms from positions (F, 3) and unit quaternions (F, 4), x y z w.
    pybullet's matrix of each quaternion (the textbook products; tf.transformations' to
    1e-15, tested) gathered in one list: numpy's cost per operation made the same on a
    robot's few frames 28 us a scan, this 8."""
    rows = []
    for (x, y, z), quaternion in zip(positions, quaternions):
        m = pb.getMatrixFromQuaternion(quaternion)
        rows.append((m[0], m[1], m[2], x, m[3], m[4], m[5], y, m[6], m[7], m[8], z,
                     0.0, 0.0, 0.0, 1.0))
    return np.array(rows, dtype=float).reshape(-1, 4, 4)


def shape_set(rows: np.ndarray, planes: np.ndarray) -> ShapeSet:
    """The numpy reference's view of kernel rows and the hulls' planes they index (for the
    fallback and for tests)."""
    shapes = ShapeSet([])
    shapes.planes = planes
    for code, kind in _KIND_NAMES.items():
        chosen = rows[rows[:, KIND] == code]
        if not len(chosen):
            continue
        dims = chosen[:, DIMS]
        if kind == "hull":
            dims = dims[:, :2]
        elif kind == "box":
            dims = 2.0 * dims
        elif kind == "cylinder":
            dims = np.stack([dims[:, 0], 2.0 * dims[:, 1]], axis=1)
        elif kind == "sphere":
            dims = dims[:, :1]
        else:
            dims = np.zeros((len(chosen), 1))
        shapes.groups[kind] = (chosen[:, CENTRE].copy(), chosen[:, ROTATION].reshape(-1, 3, 3),
                               dims, chosen[:, BOUND].copy())
    return shapes


class _Mover:
    """One moving model's shapes and how to read its frames."""

    def __init__(self, world, model, rows: slice, first_plane: int):
        self.rows = rows
        self.robot = model.robot
        if self.robot is not None:
            links = sorted({shape.link for shape in model.ray_shapes},
                           key=lambda name: self.robot.link_index[name])
            self.indices = [self.robot.link_index[name] for name in links]
            self.base_first = bool(self.indices) and self.indices[0] == -1
            self.link_indices = [i for i in self.indices if i != -1]
            frame_of = [links.index(shape.link) for shape in model.ray_shapes]
        else:
            self.name = model.name
            frame_of = [0] * len(model.ray_shapes)
        self.world = world
        self.shapes = ray_kernel.PlacedShapes(
            [s.placed(np.eye(4)) for s in model.ray_shapes],
            np.array([s.local for s in model.ray_shapes]).reshape(-1, 4, 4), frame_of,
            first_plane)

    def frames(self) -> np.ndarray:
        if self.robot is None:
            position, orientation = self.world.pose(self.name)
            return frames_from_poses([position], [orientation])
        robot = self.robot
        poses: List[Tuple[Sequence[float], Sequence[float]]] = []
        if self.base_first:
            poses.append(robot.base_pose())
        if self.link_indices:
            states = pb.getLinkStates(robot.id, self.link_indices, computeForwardKinematics=1,
                                      physicsClientId=robot.client)
            poses.extend((state[4], state[5]) for state in states)
        return frames_from_poses([p for p, _ in poses], [q for _, q in poses])

    def place(self, buffer: np.ndarray) -> None:
        if len(self.shapes):
            self.shapes.place(self.frames(), buffer[self.rows])


class RayScene:
    """The scene's shapes as kernel rows, static ones packed once, moving ones placed once
    per time stamp; :meth:`cast` one scan."""

    def __init__(self, world, kernel: Optional[ray_kernel.Kernel]):
        self.kernel = kernel
        static = [p for m in world.models.values() if m.kind == "static" for p in m.primitives]
        moving = [m for m in world.models.values()
                  if m.kind != "static" and m.ray_shapes
                  and (m.robot is not None or m.body is not None)]
        count = len(static) + sum(len(m.ray_shapes) for m in moving)
        self.rows = np.zeros((count, STRIDE))
        self.rows[:len(static)] = ray_kernel.rows(static)
        # the hulls' planes, in their shapes' frames: never re-placed
        planes = [ray_kernel.planes(static)]
        self.movers = []
        start, first_plane = len(static), len(planes[0])
        for model in moving:
            end = start + len(model.ray_shapes)
            mover = _Mover(world, model, slice(start, end), first_plane)
            self.movers.append(mover)
            planes.append(mover.shapes.planes)
            start, first_plane = end, first_plane + len(mover.shapes.planes)
        self.planes = np.ascontiguousarray(np.vstack(planes))
        self._placed_at = None
        self._static_set: Optional[ShapeSet] = None
        self._moving_set: Optional[ShapeSet] = None
        self._static_count = len(static)

    def poses_changed(self) -> None:
        """Something moved without time passing (set_state, reset): place again."""
        self._placed_at = None

    def _place(self, stamp) -> None:
        if stamp == self._placed_at:
            return
        for mover in self.movers:
            mover.place(self.rows)
        self._placed_at = stamp
        self._moving_set = None

    def cast(self, stamp, origin: np.ndarray, directions: np.ndarray, near: float,
             far: float) -> np.ndarray:
        """Distances from ``origin`` along unit ``directions`` to the first surface between
        ``near`` and ``far`` (inf where there is none), the moving shapes as at ``stamp``."""
        self._place(stamp)
        if self.kernel is not None:
            return self.kernel.cast(self.rows, origin, directions, near, far, self.planes)
        # the numpy reference on the same rows, its rays starting at near
        if self._static_set is None:
            self._static_set = shape_set(self.rows[:self._static_count], self.planes)
        if self._moving_set is None:
            self._moving_set = shape_set(self.rows[self._static_count:], self.planes)
        starts = origin + directions * near
        distances = near + cast([self._static_set, self._moving_set], starts, directions)
        return np.where(distances <= far, distances, np.inf)


__all__ = ["RayScene", "frames_from_poses", "shape_set"]
