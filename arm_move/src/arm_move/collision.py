"""Collision checking for the planner: the arm as spheres, the scene as boxes and a floor,
and an object the gripper carries as a box attached to the hand.

Each moving link is covered by spheres along its length (a capsule's worth, made a little
larger so that the gaps between spheres are covered too), plus ``padding``: the planner
stays that far from everything, which is what lets a dense check of the real shapes
between its states pass (see test_planner's independent check on pybullet). The base and
the turning shoulder are boxes (the shoulder's cylinder's bounding box, turning with the
waist). Self-collision is checked between every pair of link groups that are not
adjacent in the chain and do not touch in a named pose (computed from this geometry, as
MoveIt's setup assistant computes an SRDF's disabled pairs). An attached object (MoveIt's
attached collision object) moves with the hand; it is checked with its true size against
the scene, the floor and the links other than the hand (the hand holds it: its touch
links). Pure numpy: no ROS, no pybullet.
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
# the link groups in the order of the chain: neighbours are joined by a joint and always
# touch there, so they are never checked against each other
CHAIN = ("base", "shoulder", "upper_arm", "forearm", "hand")
BOXED = ("base", "shoulder")   # checked as boxes, the others as spheres
HELD_BY = "hand"               # an attached object's touch links: not checked against it


def boxes_overlap(ca, ra, ha, cb, rb, hb) -> np.ndarray:
    """Whether oriented boxes overlap (the separating axis test, 15 axes), batched over m:
    centres (m x 3), rotations (m x 3 x 3, columns the box's axes), half sizes (m x 3);
    each argument broadcasts to those shapes."""
    ca, cb = np.broadcast_arrays(np.asarray(ca, float), np.asarray(cb, float))
    m = ca.shape[0]
    ra, rb = (np.broadcast_to(r, (m, 3, 3)) for r in (ra, rb))
    ha, hb = (np.broadcast_to(h, (m, 3)) for h in (ha, hb))
    rot = np.einsum("mji,mjk->mik", ra, rb)            # b's axes in a's frame
    t = np.einsum("mji,mj->mi", ra, cb - ca)           # b's centre in a's frame
    absolute = np.abs(rot) + 1e-12                     # parallel edges: no false separation
    separated = np.any(np.abs(t) > ha + np.einsum("mik,mk->mi", absolute, hb), axis=1)
    tb = np.einsum("mik,mi->mk", rot, t)
    separated |= np.any(np.abs(tb) > hb + np.einsum("mik,mi->mk", absolute, ha), axis=1)
    for i in range(3):
        i1, i2 = (i + 1) % 3, (i + 2) % 3
        for j in range(3):
            j1, j2 = (j + 1) % 3, (j + 2) % 3
            distance = np.abs(t[:, i2] * rot[:, i1, j] - t[:, i1] * rot[:, i2, j])
            reach = (ha[:, i1] * absolute[:, i2, j] + ha[:, i2] * absolute[:, i1, j] +
                     hb[:, j1] * absolute[:, i, j2] + hb[:, j2] * absolute[:, i, j1])
            separated |= distance > reach
    return ~separated


def spheres_in_boxes(centres, radii, box_centres, rotations, halves) -> np.ndarray:
    """Whether any of each set of spheres (m x n x 3, radii n) touches its box (centres
    m x 3, rotations m x 3 x 3, half sizes 3): one bool per set."""
    local = np.einsum("mij,mni->mnj", rotations, centres - box_centres[:, None])
    outside = np.maximum(np.abs(local) - halves, 0.0)
    return np.any(np.einsum("mnj,mnj->mn", outside, outside) < radii * radii, axis=1)


@dataclass
class Attached:
    """An object the gripper holds: its box in the hand's frame (origin at the gripper
    point, x along the gripper, y across it, towards the left finger)."""

    name: str
    center: np.ndarray        # in the hand's frame
    rotation: np.ndarray      # its axes in the hand's frame (3 x 3)
    size: np.ndarray


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
    attached: Optional[Attached] = None   # what the gripper holds, if anything
    # an object the gripper (hand) may touch: the one it is about to close on (MoveIt's
    # pick allows the end effector's touch links to touch the object while approaching it)
    touch_allowed: Optional[str] = None

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

    def placement_conflict(self, box: Box, tolerance: float) -> Optional[str]:
        """What ``box`` placed in the scene would be sunk in: "floor" when any part of it is
        below the floor, else the first other box it overlaps (by name), else None. A box
        may touch what it rests on, and sink into it by up to ``tolerance`` (m)."""
        lowest = box.center[2] - float(np.abs(box.rotation[2, :]) @ (box.size / 2))
        if lowest < self.floor_z - tolerance:
            return "floor"
        half = np.maximum(box.size / 2 - tolerance, 0.0)
        for other in self.boxes.values():
            if other.name != box.name and boxes_overlap(
                    box.center[None], box.rotation, half, other.center[None], other.rotation,
                    other.size / 2)[0]:
                return other.name
        return None

    def _touches(self, centres: np.ndarray, radii: np.ndarray, fingers=None):
        """For a batch of sphere sets (m x n x 3): whether each touches the floor (m), and
        each box (one m-vector per box, in the order of ``stacked``). ``fingers`` (n bools):
        the spheres that may touch ``touch_allowed``."""
        floor = np.any(centres[..., 2] - radii < self.floor_z, axis=1)
        names, box_centres, rotations, halves = self.stacked()
        boxes = []
        for name, centre, rotation, half in zip(names, box_centres, rotations, halves):
            outside = np.maximum(np.abs((centres - centre) @ rotation) - half, 0.0)
            touching = np.einsum("mnj,mnj->mn", outside, outside) < radii * radii
            if fingers is not None and name == self.touch_allowed:
                touching &= ~fingers
            boxes.append(np.any(touching, axis=1))
        return floor, boxes

    def hits(self, centres: np.ndarray, radii: np.ndarray, fingers=None) -> np.ndarray:
        """For a batch of sphere sets (m x n x 3): whether each touches the floor or a box."""
        floor, boxes = self._touches(centres, radii, fingers)
        return np.logical_or.reduce([floor, *boxes])

    def first_hit(self, centres: np.ndarray, radii: np.ndarray, fingers=None) -> Optional[str]:
        """The name of what one set of spheres (n x 3) touches ("floor", a box), or None."""
        floor, boxes = self._touches(centres[None], radii, fingers)
        if floor[0]:
            return "floor"
        names = self.stacked()[0]
        return next((name for name, hit in zip(names, boxes) if hit[0]), None)


def fingers_around(box: Box, target: Sequence[float], finger_max: float,
                   finger_length: float) -> bool:
    """Whether a gripper point at ``target`` (pointing down) has ``box`` between its open
    fingers: its centre less than the fingers' opening away across, and the fingers
    reaching down along its sides (a grasp's approach)."""
    offset = np.asarray(target, float) - box.center
    top = box.center[2] + box.size[2] / 2
    return bool(math.hypot(offset[0], offset[1]) < finger_max and
                target[2] - finger_length / 2 < top < target[2] + finger_length / 2 + box.size[2])


class ArmCollisionModel:
    """The arm's spheres at a joint configuration, and the checks against itself and a
    scene. The spheres are laid out once (which point of the arm's plane each starts from,
    along which link direction, how far, how far sideways); a configuration only moves
    them, in a handful of numpy operations."""

    def __init__(self, kinematics: ArmKinematics, links: Mapping, finger: Mapping,
                 padding: float, self_pairs: Optional[Sequence[Sequence[str]]] = None,
                 contact_tolerance: float = 0.001):
        """``self_pairs``: the link groups to check against each other; None: computed
        (compute_self_pairs). ``contact_tolerance`` (m): how far an attached object may
        sink into what it rests on (it starts on the table when grasped)."""
        self.k = kinematics
        self.padding = padding
        self.finger_length = float(finger["length"])
        self.contact_tolerance = contact_tolerance
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
        # the touch links, among the moving spheres: the whole gripper (MoveIt's end
        # effector links), since its spheres reach past its shapes' ends
        self._fingers = self._group[self._moving] == HELD_BY
        base = links["base"]
        self.base_box = Box.upright("base", (0, 0, base["size"][2] / 2), base["size"])
        # the shoulder's cylinder as its bounding box, which turns with the waist
        diameter = 2 * shoulder["radius"]
        self._boxes = {
            "base": (self.base_box.center, np.asarray(base["size"], float) / 2),
            "shoulder": (np.array([0.0, 0.0, k.waist_z + shoulder["length"] / 2]),
                         np.array([diameter, diameter, shoulder["length"]]) / 2)}
        self._held_out = np.nonzero(~np.isin(self._group, (HELD_BY,) + BOXED))[0]
        self.self_pairs: List[Tuple[str, str]] = []
        if self_pairs is None:  # computed from the geometry
            self_pairs = self.compute_self_pairs(
                [np.asarray(q, float) for q in kinematics.named_poses.values()],
                kinematics.finger_max)
        for a, b in self_pairs:
            self._add_pair(a, b)

    # --- self-collision pairs ----------------------------------------------------------
    def _add_pair(self, a: str, b: str) -> None:
        if a not in CHAIN or b not in CHAIN or a == b:
            raise ValueError(f"self-collision pair ({a}, {b}): groups are {', '.join(CHAIN)}")
        if a in BOXED and b in BOXED:
            raise ValueError(f"self-collision pair ({a}, {b}): both stand still together")
        self.self_pairs.append((a, b))

    def _pair_hits(self, pair, centres, waists, margin) -> np.ndarray:
        """Per configuration: whether the pair of groups touch (``margin`` more than the
        padding)."""
        a, b = pair
        if b in BOXED:
            a, b = b, a
        ib = np.nonzero(self._group == b)[0]
        radii = self.radii[ib] + margin
        if a in BOXED:
            centre, half = self._boxes[a]
            rotations = self._turned(waists) if a == "shoulder" else \
                np.broadcast_to(np.eye(3), (len(centres), 3, 3))
            return spheres_in_boxes(centres[:, ib], radii, np.broadcast_to(
                centre, (len(centres), 3)), rotations, half)
        ia = np.nonzero(self._group == a)[0]
        gaps = centres[:, ia, None] - centres[:, None, ib]
        reach = (self.radii[ia, None] + margin + radii[None, :]) ** 2
        return np.any(np.einsum("mijk,mijk->mij", gaps, gaps) < reach, axis=(1, 2))

    def compute_self_pairs(self, poses, finger: float) -> List[Tuple[str, str]]:
        """The pairs of link groups that can collide and must be checked: every pair that is
        not adjacent in the chain and does not touch (true shapes: no padding) in any of
        ``poses`` (the named poses, where the arm rests by design), as MoveIt's setup
        assistant leaves out adjacent pairs and pairs in collision in the default pose.
        Pairs of standing boxes (base, shoulder) never move against each other."""
        qs = np.array(poses, float)
        centres = self.centres(qs, finger)
        pairs = []
        for i, a in enumerate(CHAIN):
            for b in CHAIN[i + 2:]:
                if a in BOXED and b in BOXED:
                    continue
                if not np.any(self._pair_hits((a, b), centres, qs[:, 0], -self.padding)):
                    pairs.append((a, b))
        return pairs

    # --- geometry ----------------------------------------------------------------------
    @staticmethod
    def _turned(waists: np.ndarray) -> np.ndarray:
        """Rotations about z by each waist angle (m x 3 x 3)."""
        c, s = np.cos(waists), np.sin(waists)
        rotations = np.zeros((len(waists), 3, 3))
        rotations[:, 0, 0], rotations[:, 0, 1], rotations[:, 1, 0], rotations[:, 1, 1] = c, -s, s, c
        rotations[:, 2, 2] = 1.0
        return rotations

    def _planar(self, qs: np.ndarray):
        """The arm's plane at each configuration: points (m x 5 x 2: shoulder joint, elbow,
        wrist, gripper point, waist) and link directions (m x 4 x 2: upper arm, forearm,
        hand, vertical), as (r, z)."""
        k = self.k
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
        return (np.stack((shoulder, elbow, wrist, grip, waist), axis=1),
                np.stack((upper, fore, hand, vertical), axis=1))

    def centres(self, qs: np.ndarray, finger: float) -> np.ndarray:
        """Every sphere's centre (base frame) for a batch of configurations: qs is m x 4,
        the result m x n x 3."""
        qs = np.atleast_2d(np.asarray(qs, dtype=float))
        points, directions = self._planar(qs)
        planar = points[:, self._origin] + self._t[None] * directions[:, self._direction]
        lateral = (self._lateral + self._opens * finger)[None, :]
        c, s = np.cos(qs[:, 0])[:, None], np.sin(qs[:, 0])[:, None]
        return np.stack((planar[..., 0] * c - lateral * s, planar[..., 0] * s + lateral * c,
                         planar[..., 1]), axis=2)

    def hand_frames(self, qs: np.ndarray):
        """The hand's frame at each configuration: origin (m x 3, the gripper point) and
        axes (m x 3 x 3, columns x along the gripper, y across it, z = x cross y), as the
        URDF's gripper link is turned: about z by the waist, then about y by the pitch."""
        qs = np.atleast_2d(np.asarray(qs, dtype=float))
        points, directions = self._planar(qs)
        grip, hand = points[:, 3], directions[:, 2]
        c, s = np.cos(qs[:, 0]), np.sin(qs[:, 0])
        origin = np.stack((grip[:, 0] * c, grip[:, 0] * s, grip[:, 1]), axis=1)
        x = np.stack((hand[:, 0] * c, hand[:, 0] * s, hand[:, 1]), axis=1)
        y = np.stack((-s, c, np.zeros_like(c)), axis=1)
        return origin, np.stack((x, y, np.cross(x, y)), axis=2)

    def attach(self, name: str, box: Box, q: Sequence[float]) -> Attached:
        """``box`` (in the scene) held by the hand at ``q``: its pose in the hand's frame."""
        origin, axes = self.hand_frames(np.asarray(q, float)[None])
        return Attached(name, axes[0].T @ (box.center - origin[0]), axes[0].T @ box.rotation,
                        np.asarray(box.size, float))

    def attached_pose(self, attached: Attached, q: Sequence[float]):
        """Where an attached object is at ``q``: centre and rotation in the scene frame."""
        origin, axes = self.hand_frames(np.asarray(q, float)[None])
        return origin[0] + axes[0] @ attached.center, axes[0] @ attached.rotation

    # --- checks ------------------------------------------------------------------------
    def _self_collisions(self, centres: np.ndarray, waists: np.ndarray,
                         margin: float = 0.0) -> List[Tuple[Tuple[str, str], np.ndarray]]:
        """Per pair: per configuration, whether the arm touches itself there."""
        return [(pair, self._pair_hits(pair, centres, waists, margin))
                for pair in self.self_pairs]

    def _attached_hits(self, qs: np.ndarray, centres: np.ndarray, scene: Scene,
                       margin: float) -> List[Tuple[str, np.ndarray]]:
        """What an attached object touches, per configuration: the scene's boxes, the floor,
        the links other than the hand. True size (no padding: it is lifted off and set down
        on a surface), ``margin`` when positive, less ``contact_tolerance``."""
        attached = scene.attached
        if attached is None:
            return []
        origin, axes = self.hand_frames(qs)
        centre = origin + np.einsum("mij,j->mi", axes, attached.center)
        rotation = np.einsum("mij,jk->mik", axes, attached.rotation)
        half = attached.size / 2 + max(margin, 0.0) - self.contact_tolerance
        corners = np.abs(rotation[:, 2, :]) @ half          # its lowest point below the centre
        hits = [("floor", centre[:, 2] - corners < scene.floor_z)]
        names, box_centres, rotations, halves = scene.stacked()
        for name, c, r, h in zip(names, box_centres, rotations, halves):
            hits.append((name, boxes_overlap(centre, rotation, half, c, r, h)))
        for group, (c, h) in self._boxes.items():
            r = self._turned(qs[:, 0]) if group == "shoulder" else np.eye(3)
            hits.append((group, boxes_overlap(centre, rotation, half, c, r, h)))
        held_out = self._held_out
        hits.append(("the arm", spheres_in_boxes(
            centres[:, held_out], self.radii[held_out] + margin, centre, rotation, half)))
        return [(f"{attached.name} (held) and {name}", hit) for name, hit in hits]

    def valid(self, qs: np.ndarray, finger: float, scene: Scene, margin: float = 0.0) -> np.ndarray:
        """Per configuration (m x 4): True where the arm (and what it holds) touches
        neither itself nor the scene (``margin``: that much more clearance than the
        padding; negative: less)."""
        qs = np.atleast_2d(np.asarray(qs, dtype=float))
        centres = self.centres(qs, finger)
        bad = scene.hits(centres[:, self._moving], self._moving_radii + margin, self._fingers)
        for _, hit in self._self_collisions(centres, qs[:, 0], margin):
            bad |= hit
        for _, hit in self._attached_hits(qs, centres, scene, margin):
            bad |= hit
        return ~bad

    def collision(self, q: Sequence[float], finger: float, scene: Scene,
                  margin: float = 0.0) -> Optional[str]:
        """What the arm at ``q`` touches: "itself (a and b)", "floor", a scene object's
        name, "<held object> (held) and <what>", or None."""
        qs = np.asarray(q, dtype=float)[None, :]
        centres = self.centres(qs, finger)
        for (a, b), hit in self._self_collisions(centres, qs[:, 0], margin):
            if hit[0]:
                return f"itself ({a} and {b})"
        for name, hit in self._attached_hits(qs, centres, scene, margin):
            if hit[0]:
                return name
        return scene.first_hit(centres[0, self._moving], self._moving_radii + margin,
                               self._fingers)
