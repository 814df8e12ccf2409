"""Collision checking for the planner: the arm as spheres, the scene as boxes and a floor.

Each moving link is covered by spheres along its length (a capsule's worth, made a little
larger so that the gaps between spheres are covered too), plus ``padding``: the planner
stays that far from everything, which is what lets a dense check of the real shapes
between its states pass (see test_planner's independent check on pybullet). The base and
the turning shoulder are boxes/spheres too but only count against the links that can
reach them. Pure numpy: no ROS, no pybullet.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Dict, List, Mapping, Optional, Sequence, Tuple

import numpy as np

from arm_move.kinematics import ArmKinematics
from sim_bridge.poses import quaternion_from_rpy, quaternion_matrix

# links checked against the scene (the base and the shoulder never move off the table)
MOVING = ("upper_arm", "forearm", "hand")


@dataclass
class Box:
    """An oriented box: ``center`` (m), ``orientation`` (a unit quaternion x, y, z, w, in
    the scene frame), ``size`` (full edge lengths); ``rotation`` (its axes as a 3x3 matrix)
    follows from the orientation."""

    name: str
    center: np.ndarray
    orientation: Tuple[float, float, float, float]
    size: np.ndarray
    rotation: np.ndarray = field(init=False)

    def __post_init__(self):
        self.center = np.asarray(self.center, float)
        self.size = np.asarray(self.size, float)
        self.rotation = quaternion_matrix(self.orientation)

    @classmethod
    def upright(cls, name: str, center: Sequence[float], size: Sequence[float],
                yaw: float = 0.0) -> "Box":
        """A box standing upright, turned by ``yaw`` about z."""
        return cls(name, center, quaternion_from_rpy(0.0, 0.0, yaw), size)


@dataclass
class Scene:
    """What the arm must not touch: boxes by name and a floor height (base frame)."""

    floor_z: float
    boxes: Dict[str, Box] = field(default_factory=dict)

    def __post_init__(self):
        self._stacked = None

    def add(self, box: Box) -> None:
        self.boxes[box.name] = box
        self._stacked = None

    def remove(self, name: str) -> None:
        self.boxes.pop(name, None)
        self._stacked = None

    def stacked(self):
        """The boxes as arrays (names, centres, rotations, half sizes), for one batched test."""
        if self._stacked is None:
            boxes = list(self.boxes.values())
            self._stacked = ([b.name for b in boxes],
                             np.array([b.center for b in boxes]).reshape(-1, 3),
                             np.array([b.rotation for b in boxes]).reshape(-1, 3, 3),
                             np.array([b.size / 2 for b in boxes]).reshape(-1, 3))
        return self._stacked

    def containing(self, point: Sequence[float]) -> Optional[str]:
        """The name of the box a point is inside, or None."""
        names, box_centres, rotations, halves = self.stacked()
        for name, centre, rotation, half in zip(names, box_centres, rotations, halves):
            if np.all(np.abs((np.asarray(point, float) - centre) @ rotation) <= half):
                return name
        return None

    def _touches(self, centres: np.ndarray, radii: np.ndarray):
        """For a batch of sphere sets (m x n x 3): whether each touches the floor (m), and
        each box (one m-vector per box, in the order of ``stacked``)."""
        floor = np.any(centres[..., 2] - radii < self.floor_z, axis=1)
        _, box_centres, rotations, halves = self.stacked()
        boxes = []
        for centre, rotation, half in zip(box_centres, rotations, halves):
            outside = np.maximum(np.abs((centres - centre) @ rotation) - half, 0.0)
            boxes.append(np.any(np.einsum("mnj,mnj->mn", outside, outside) < radii * radii,
                                axis=1))
        return floor, boxes

    def hits(self, centres: np.ndarray, radii: np.ndarray) -> np.ndarray:
        """For a batch of sphere sets (m x n x 3): whether each touches the floor or a box."""
        floor, boxes = self._touches(centres, radii)
        return np.logical_or.reduce([floor, *boxes])

    def first_hit(self, centres: np.ndarray, radii: np.ndarray) -> Optional[str]:
        """The name of what one set of spheres (n x 3) touches ("floor", a box), or None."""
        floor, boxes = self._touches(centres[None], radii)
        if floor[0]:
            return "floor"
        names = self.stacked()[0]
        return next((name for name, hit in zip(names, boxes) if hit[0]), None)


class ArmCollisionModel:
    """The arm's spheres at a joint configuration, and the checks against itself and a
    scene. The spheres are laid out once (which point of the arm's plane each starts from,
    along which link direction, how far, how far sideways); a configuration only moves
    them, in a handful of numpy operations."""

    def __init__(self, kinematics: ArmKinematics, links: Mapping, finger: Mapping,
                 padding: float, self_pairs: Sequence[Sequence[str]]):
        self.k = kinematics
        self.padding = padding
        k = kinematics

        def cover(width: float, height: float) -> float:  # the capsule around a box section
            return 0.5 * math.hypot(width, height)

        rows: List[Tuple[str, int, int, float, float, float, float]] = []

        def capsule(group, origin, direction, start, end, radius, lateral=0.0, opens=0.0):
            """Spheres one radius apart from ``start`` to ``end`` along a direction, each
            enlarged by sqrt(1.25) so that the waist between two still has the radius."""
            count = max(2, int(math.ceil(abs(end - start) / radius)) + 1)
            for t in np.linspace(start, end, count):
                rows.append((group, origin, direction, t, lateral, opens,
                             radius * math.sqrt(1.25) + padding))

        # planar points: 0 shoulder joint, 1 elbow, 2 wrist, 3 gripper point, 4 waist;
        # directions: 0 upper arm, 1 forearm, 2 hand, 3 vertical
        a1, _ = k.upper_arm
        capsule("upper_arm", 0, 0, 0.0, a1, cover(links["upper_arm"]["width"],
                                                  links["upper_arm"]["height"]))
        capsule("forearm", 1, 1, 0.0, k.wrist_x, cover(links["forearm"]["width"],
                                                      links["forearm"]["height"]))
        bar_x = k.ee_arm_x + k.gripper_bar_x
        capsule("hand", 2, 2, 0.0, bar_x, cover(links["gripper"]["width"],
                                                links["gripper"]["height"]))
        bar = links["gripper_bar"]
        bar_radius = cover(bar["length"], bar["height"])
        for lateral in np.linspace(-bar["width"] / 2, bar["width"] / 2,
                                   max(2, int(math.ceil(bar["width"] / bar_radius)) + 1)):
            rows.append(("hand", 2, 2, bar_x, float(lateral), 0.0,
                         bar_radius * math.sqrt(1.25) + padding))
        finger_radius = cover(finger["thickness"], finger["height"])
        for side in (1.0, -1.0):
            capsule("hand", 3, 2, -finger["length"] / 2, finger["length"] / 2, finger_radius,
                    lateral=side * finger["thickness"] / 2, opens=side)
        shoulder = links["shoulder"]
        capsule("shoulder", 4, 3, 0.0, shoulder["length"], shoulder["radius"])

        self.groups = sorted({row[0] for row in rows})
        self._group = np.array([row[0] for row in rows])
        self._origin = np.array([row[1] for row in rows])
        self._direction = np.array([row[2] for row in rows])
        self._t = np.array([row[3] for row in rows])[:, None]
        self._lateral = np.array([row[4] for row in rows])
        self._opens = np.array([row[5] for row in rows])
        self.radii = np.array([row[6] for row in rows])
        self._moving = np.nonzero(np.isin(self._group, MOVING))[0]
        self._moving_radii = self.radii[self._moving]
        base = links["base"]
        self.base_box = Box.upright("base", (0, 0, base["size"][2] / 2), base["size"])
        pairs_i, pairs_j, self._base_checked = [], [], np.zeros(len(rows), bool)
        for a, b in self_pairs:
            if "base" in (a, b):
                self._base_checked |= self._group == (b if a == "base" else a)
                continue
            ia, ib = np.nonzero(self._group == a)[0], np.nonzero(self._group == b)[0]
            pairs_i.extend(np.repeat(ia, len(ib)))
            pairs_j.extend(np.tile(ib, len(ia)))
        self._pi, self._pj = np.array(pairs_i, int), np.array(pairs_j, int)
        self._base_checked = np.nonzero(self._base_checked)[0]
        self._base_radii = self.radii[self._base_checked]

    def centres(self, qs: np.ndarray, finger: float) -> np.ndarray:
        """Every sphere's centre (base frame) for a batch of configurations: qs is m x 4,
        the result m x n x 3."""
        k = self.k
        qs = np.atleast_2d(np.asarray(qs, dtype=float))
        a1, e10 = k.upper_arm
        q1, q12 = qs[:, 1], qs[:, 1] + qs[:, 2]
        q123 = q12 + qs[:, 3]
        upper = np.stack((np.cos(e10 - q1), np.sin(e10 - q1)), axis=1)
        fore = np.stack((np.cos(q12), -np.sin(q12)), axis=1)
        hand = np.stack((np.cos(q123), -np.sin(q123)), axis=1)
        shoulder = np.broadcast_to((0.0, k.shoulder_height), upper.shape)
        elbow = shoulder + a1 * upper
        wrist = elbow + k.wrist_x * fore
        grip = wrist + k.hand_length * hand
        waist = np.broadcast_to((0.0, k.waist_z), upper.shape)
        vertical = np.broadcast_to((0.0, 1.0), upper.shape)
        points = np.stack((shoulder, elbow, wrist, grip, waist), axis=1)       # m x 5 x 2
        directions = np.stack((upper, fore, hand, vertical), axis=1)          # m x 4 x 2
        planar = points[:, self._origin] + self._t[None] * directions[:, self._direction]
        lateral = (self._lateral + self._opens * finger)[None, :]
        c, s = np.cos(qs[:, 0])[:, None], np.sin(qs[:, 0])[:, None]
        return np.stack((planar[..., 0] * c - lateral * s, planar[..., 0] * s + lateral * c,
                         planar[..., 1]), axis=2)

    def _self_collisions(self, centres: np.ndarray, margin: float = 0.0) -> np.ndarray:
        """Per configuration: whether the arm touches itself."""
        hit = np.zeros(len(centres), bool)
        if len(self._pi):
            gaps = centres[:, self._pi] - centres[:, self._pj]
            reach = (self.radii[self._pi] + self.radii[self._pj] + 2 * margin) ** 2
            hit |= np.any(np.einsum("mij,mij->mi", gaps, gaps) < reach, axis=1)
        box = self.base_box
        local = centres[:, self._base_checked] - box.center
        outside = np.maximum(np.abs(local) - box.size / 2, 0.0)
        hit |= np.any(np.einsum("mij,mij->mi", outside, outside) <
                      (self._base_radii + margin) ** 2, axis=1)
        return hit

    def valid(self, qs: np.ndarray, finger: float, scene: Scene, margin: float = 0.0) -> np.ndarray:
        """Per configuration (m x 4): True where the arm touches neither itself nor the scene
        (``margin``: that much more clearance than the padding; negative: less)."""
        centres = self.centres(qs, finger)
        bad = self._self_collisions(centres, margin)
        bad |= scene.hits(centres[:, self._moving], self._moving_radii + margin)
        return ~bad

    def collision(self, q: Sequence[float], finger: float, scene: Scene,
                  margin: float = 0.0) -> Optional[str]:
        """What the arm at ``q`` touches: "self", "floor", a scene object's name, or None."""
        centres = self.centres(np.asarray(q, dtype=float)[None, :], finger)
        if self._self_collisions(centres, margin)[0]:
            return "self"
        return scene.first_hit(centres[0, self._moving], self._moving_radii + margin)
